#version 330 core
// Full-screen triangle at the far plane (depth 1): drawn after the opaque scene with the depth
// test on, so only pixels nothing covers are shaded. The fragment shader turns each pixel into a
// view direction.
out vec2 v_ndc;
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
  v_ndc = p;
  gl_Position = vec4(p, 1.0, 1.0);
}
