#version 330 core
// 2D overlay quads in pixels (top-left origin): HUD panels, bitmap-font glyphs, the map inset.
layout(location = 0) in vec4 i_rect;   // x, y, w, h (px)
layout(location = 1) in vec4 i_uv;     // u0, v0, u1, v1
layout(location = 2) in vec4 i_color;  // rgba
layout(location = 3) in float i_mode;  // 0 solid, 1 font glyph, 2 map texture
uniform vec2 u_screen;                 // frame size (px)
out vec2 v_uv;
out vec4 v_color;
flat out int v_mode;
void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1));
  vec2 px = i_rect.xy + corner * i_rect.zw;
  v_uv = mix(i_uv.xy, i_uv.zw, corner);
  v_color = i_color;
  v_mode = int(i_mode + 0.5);
  gl_Position = vec4(px.x / u_screen.x * 2.0 - 1.0, 1.0 - px.y / u_screen.y * 2.0, 0.0, 1.0);
}
