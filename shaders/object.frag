#version 330 core
// Colour, light and haze come from object.vert (flat faces).
in vec3 v_color;
out vec4 frag;
void main() { frag = vec4(v_color, 1.0); }
