#version 330 core
in vec3 v_normal;
in vec3 v_color;
in float v_dist;
uniform vec3 u_sun;
uniform float u_fog_density;
uniform vec3 u_fog_color;
out vec4 frag;
void main() {
  vec3 n = normalize(v_normal);
  float diffuse = max(dot(n, u_sun), 0.0);
  float sky = 0.5 + 0.5 * n.z;  // hemisphere ambient: faces turned up get more sky light
  vec3 lit = v_color * (0.28 + 0.18 * sky + 0.70 * diffuse);
  float f = exp(-pow(v_dist * u_fog_density, 2.0));
  frag = vec4(mix(u_fog_color, lit, f), 1.0);
}
