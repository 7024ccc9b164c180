#version 330 core
// Camera-facing particle quads (explosions, fire, smoke). Instance: world centre + size (m),
// premultiplied colour + alpha. The quad's corners come from gl_VertexID (triangle strip).
layout(location = 0) in vec4 i_pos_size;
layout(location = 1) in vec4 i_color;
uniform mat4 u_vp;
uniform vec3 u_eye;
uniform vec3 u_right;
uniform vec3 u_up;
uniform float u_fog_density;
out vec2 v_uv;
out vec4 v_color;
void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1)) * 2.0 - 1.0;
  vec3 rel = (i_pos_size.xyz - u_eye) + (u_right * corner.x + u_up * corner.y) * (0.5 * i_pos_size.w);
  v_uv = corner;
  float f = exp(-pow(length(rel) * u_fog_density, 2.0));
  v_color = i_color * f;
  gl_Position = u_vp * vec4(rel, 1.0);
}
