#include "world/pose.hpp"

#include "core/trig.hpp"

namespace npsnet::world {

Mat3 pose_rotation(const Vec2& heading_dir, double pitch_deg, double roll_deg) {
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

Mat3 pose_rotation(double heading_deg, double pitch_deg, double roll_deg) {
  return pose_rotation(heading_to_dir(heading_deg), pitch_deg, roll_deg);
}

}  // namespace npsnet::world
