#version 330 core
in vec2 v_ndc;
uniform mat4 u_inv_vp;      // inverse of projection * rotation-only view
uniform vec3 u_horizon;
uniform vec3 u_zenith;
out vec4 frag;
void main() {
  vec4 far = u_inv_vp * vec4(v_ndc, 1.0, 1.0);
  vec3 dir = normalize(far.xyz / far.w);
  float e = clamp(dir.z, 0.0, 1.0);
  frag = vec4(mix(u_horizon, u_zenith, pow(e, 0.6)), 1.0);
}
