#version 330 core
// Colour by height (relative to the map's range) and slope, sun lighting, exponential haze.
// u_water = 1 draws the water plane instead (translucent blue).
in vec3 v_world;
in vec3 v_normal;
in float v_scorch;
in float v_dist;
uniform vec3 u_sun;          // unit vector towards the sun
uniform vec2 u_hrange;       // terrain min, max height (m)
uniform float u_water_level; // m
uniform int u_water;
uniform float u_fog_density; // 1/m, 0 = no fog
uniform vec3 u_fog_color;
out vec4 frag;

vec3 ground_color(float h, float up) {
  float span = max(u_hrange.y - u_hrange.x, 1.0);
  float t = clamp((h - u_hrange.x) / span, 0.0, 1.0);
  vec3 low = vec3(0.40, 0.50, 0.24);
  vec3 mid = vec3(0.55, 0.53, 0.33);
  vec3 high = vec3(0.52, 0.45, 0.36);
  vec3 top = vec3(0.80, 0.79, 0.77);
  vec3 c = mix(low, mid, smoothstep(0.15, 0.45, t));
  c = mix(c, high, smoothstep(0.5, 0.8, t));
  c = mix(c, top, smoothstep(0.88, 0.97, t));
  vec3 rock = vec3(0.46, 0.43, 0.40);
  c = mix(rock, c, smoothstep(0.72, 0.88, up));
  float above = h - u_water_level;
  c = mix(vec3(0.76, 0.70, 0.52), c, smoothstep(0.5, 3.0, above));
  return c;
}

void main() {
  vec3 n = normalize(v_normal);
  vec3 c;
  float alpha = 1.0;
  if (u_water == 1) {
    c = vec3(0.16, 0.32, 0.48);
    alpha = 0.82;
  } else {
    c = ground_color(v_world.z, n.z);
    c = mix(c, vec3(0.10, 0.08, 0.07), clamp(v_scorch, 0.0, 1.0));
  }
  float diffuse = max(dot(n, u_sun), 0.0);
  vec3 lit = c * (0.38 + 0.72 * diffuse);
  float f = exp(-pow(v_dist * u_fog_density, 2.0));
  frag = vec4(mix(u_fog_color, lit, f), alpha);
}
