#version 330 core
// Instanced models. Model space: x right, y forward, z up, origin at the ground contact centre.
// Instance: world position, heading (compass, rad: 0 = +y north, pi/2 = +x east), pitch (nose up,
// rad), roll (right side down, rad), uniform scale. Flat faces: light and haze per vertex.
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
layout(location = 3) in vec4 i_pos_heading;
layout(location = 4) in vec4 i_pitch_roll_scale;
uniform mat4 u_vp;
uniform vec3 u_eye;
uniform vec3 u_sun;
uniform float u_fog_density;
uniform vec3 u_fog_color;
out vec3 v_color;
void main() {
  float h = i_pos_heading.w, p = i_pitch_roll_scale.x, r = i_pitch_roll_scale.y;
  float ch = cos(h), sh = sin(h), cp = cos(p), sp = sin(p), cr = cos(r), sr = sin(r);
  // R = Rz(-heading) * Rx(pitch) * Ry(roll)   (column-major mat3 constructors)
  mat3 rz = mat3(ch, -sh, 0.0, sh, ch, 0.0, 0.0, 0.0, 1.0);
  mat3 rx = mat3(1.0, 0.0, 0.0, 0.0, cp, sp, 0.0, -sp, cp);
  mat3 ry = mat3(cr, 0.0, -sr, 0.0, 1.0, 0.0, sr, 0.0, cr);
  mat3 rot = rz * rx * ry;
  vec3 rel = (i_pos_heading.xyz - u_eye) + rot * (a_pos * i_pitch_roll_scale.z);
  vec3 n = rot * a_normal;
  float sky = 0.5 + 0.5 * n.z;  // hemisphere ambient: faces turned up get more sky light
  vec3 lit = a_color * (0.28 + 0.18 * sky + 0.70 * max(dot(n, u_sun), 0.0));
  float f = exp(-pow(length(rel) * u_fog_density, 2.0));
  v_color = mix(u_fog_color, lit, f);
  gl_Position = u_vp * vec4(rel, 1.0);
}
