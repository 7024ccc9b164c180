// Poses: model space (x right, y forward, z up, origin at the ground-contact centre) to the
// local frame, and bounding-sphere centres of entities and fixed objects in their current state.
#pragma once
#include "core/trig.hpp"
#include "world/world.hpp"

namespace npsnet::world {

// Compass heading (deg, clockwise from north), pitch (deg, nose up), roll (deg, right side down).
Mat3 pose_rotation(double heading_deg, double pitch_deg, double roll_deg);
// The same from the heading's direction, heading_to_dir(h), for a caller that keeps it while the
// heading stays the same (collision, from tick to tick): pose_rotation(heading_to_dir(h), p, r)
// is pose_rotation(h, p, r) bit for bit. Sines and cosines from core/trig.hpp.
// (Inline: the collision entity pass makes one for every entity every tick.)
inline Mat3 pose_rotation(const Vec2& heading_dir, double pitch_deg, double roll_deg) {
  // Rz(-heading) Rx(pitch) Ry(roll): compass heading turns clockwise seen from above (a rotation
  // of -heading about z); pitch about x, nose (+y) up; roll about y, right side (+x) down. The
  // products written out: Rx Ry first, then the heading's rows.
  SinCos p, r;
  sincos_deg2(pitch_deg, roll_deg, p, r);
  const double sh = heading_dir.x(), ch = heading_dir.y();  // sin and cos of the heading
  const double a0 = r.c, a2 = r.s;                                    // Rx Ry, row 0 (a1 = 0)
  const double b0 = p.s * r.s, b1 = p.c, b2 = -(p.s * r.c);           // row 1
  Mat3 m;
  m << ch * a0 + sh * b0, sh * b1, ch * a2 + sh * b2,  //
      ch * b0 - sh * a0, ch * b1, ch * b2 - sh * a2,   //
      -(p.c * r.s), p.s, p.c * r.c;
  return m;
}

inline Vec3 entity_centre(const World& w, size_t e) {
  const Kind& k = w.kinds[w.ents.kind[e]];
  const auto& ents = w.ents;
  return ents.pos[e] + pose_rotation(ents.heading_deg[e], ents.pitch_deg[e], ents.roll_deg[e]) *
                           k.centre_by_state[ents.state[e]].cast<double>();
}
inline double entity_radius(const World& w, size_t e) {
  return w.kinds[w.ents.kind[e]].radius_by_state[w.ents.state[e]];
}
// Fixed objects keep their intact sphere whatever their state (the thesis's one radius per
// object, p. 9), so a vehicle driving on through a damaged tree stays in one contact episode.
inline Vec3 fixed_centre(const World& w, size_t o) {
  const Kind& k = w.kinds[w.fixed.kind[o]];
  const Vec3f& c = k.centre_by_state[0];
  return w.fixed.pos[o] + pose_rotation(w.fixed.heading_deg[o], 0, 0) * c.cast<double>();
}
inline double fixed_radius(const World& w, size_t o) {
  return w.fixed.radius_m[o];
}

}  // namespace npsnet::world
