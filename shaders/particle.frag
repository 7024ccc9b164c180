#version 330 core
in vec2 v_uv;
in vec4 v_color;
out vec4 frag;
void main() {
  float r2 = dot(v_uv, v_uv);
  if (r2 > 1.0) discard;
  float soft = 1.0 - smoothstep(0.35, 1.0, r2);
  frag = v_color * soft;  // premultiplied: blend ONE, ONE_MINUS_SRC_ALPHA
}
