#version 330 core
// Colour, light and haze come from object.vert (flat faces); u_alpha < 1 for a see-through vehicle.
in vec3 v_color;
uniform float u_alpha;
out vec4 frag;
void main() { frag = vec4(v_color, u_alpha); }
