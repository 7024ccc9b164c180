#version 330 core
// Terrain posts: world position (m), unit normal, scorch (0..1, crater floors). Drawn eye-relative.
// Colour by height (relative to the map's range) and slope, sun lighting and exponential haze are
// computed here per post (llvmpipe is bound by per-pixel work); u_water = 1 draws the water plane.
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_scorch;
uniform mat4 u_vp;           // projection * rotation-only view
uniform vec3 u_eye;          // camera position, world m
uniform vec3 u_sun;          // unit vector towards the sun
uniform vec2 u_hrange;       // terrain min, max height (m)
uniform float u_water_level; // m
uniform int u_water;
uniform float u_fog_density; // 1/m, 0 = no haze
uniform vec3 u_fog_color;
out vec4 v_color;

vec3 ground_color(float h, float up) {  // keep in step with terrain_color() in overlay.cpp
  float span = max(u_hrange.y - u_hrange.x, 1.0);
  float t = clamp((h - u_hrange.x) / span, 0.0, 1.0);
  vec3 c = mix(vec3(0.40, 0.50, 0.24), vec3(0.55, 0.53, 0.33), smoothstep(0.15, 0.45, t));
  c = mix(c, vec3(0.52, 0.45, 0.36), smoothstep(0.5, 0.8, t));
  c = mix(c, vec3(0.80, 0.79, 0.77), smoothstep(0.88, 0.97, t));
  c = mix(vec3(0.46, 0.43, 0.40), c, smoothstep(0.72, 0.88, up));
  c = mix(vec3(0.76, 0.70, 0.52), c, smoothstep(0.5, 3.0, h - u_water_level));
  return c;
}

void main() {
  vec3 rel = a_pos - u_eye;
  vec3 n = normalize(a_normal);
  vec3 c;
  float alpha = 1.0;
  if (u_water == 1) {
    c = vec3(0.16, 0.32, 0.48);
    alpha = 0.82;
  } else {
    c = mix(ground_color(a_pos.z, n.z), vec3(0.10, 0.08, 0.07), clamp(a_scorch, 0.0, 1.0));
  }
  vec3 lit = c * (0.38 + 0.72 * max(dot(n, u_sun), 0.0));
  float f = exp(-pow(length(rel) * u_fog_density, 2.0));
  v_color = vec4(mix(u_fog_color, lit, f), alpha);
  gl_Position = u_vp * vec4(rel, 1.0);
}
