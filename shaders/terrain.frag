#version 330 core
// Colour, light and haze come from terrain.vert.
in vec4 v_color;
out vec4 frag;
void main() { frag = v_color; }
