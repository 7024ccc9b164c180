#version 330 core
in vec2 v_uv;
in vec4 v_color;
flat in int v_mode;
uniform sampler2D u_font;  // R8 glyph atlas
uniform sampler2D u_map;   // RGBA terrain map
out vec4 frag;
void main() {
  if (v_mode == 1) {
    float a = texture(u_font, v_uv).r;
    frag = vec4(v_color.rgb, v_color.a * a);
  } else if (v_mode == 2) {
    frag = vec4(texture(u_map, v_uv).rgb * v_color.rgb, v_color.a);
  } else {
    frag = v_color;
  }
}
