#version 330 core
// Terrain posts: world position (m), unit normal, scorch (0..1, crater floors). Drawn eye-relative.
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_scorch;
uniform mat4 u_vp;        // projection * rotation-only view
uniform vec3 u_eye;       // camera position, world m
out vec3 v_world;
out vec3 v_normal;
out float v_scorch;
out float v_dist;
void main() {
  vec3 rel = a_pos - u_eye;
  v_world = a_pos;
  v_normal = a_normal;
  v_scorch = a_scorch;
  v_dist = length(rel);
  gl_Position = u_vp * vec4(rel, 1.0);
}
