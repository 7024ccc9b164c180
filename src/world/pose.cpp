#include "world/pose.hpp"

#include "core/trig.hpp"

namespace npsnet::world {
namespace {

// sin and cos of half of an angle in degrees (core/trig.hpp).
SinCos half_angle(double deg) { return sincos_deg(0.5 * deg); }

}  // namespace

Eigen::Quaterniond yaw_quaternion(double heading_deg) {
  // Compass heading turns clockwise seen from above: a rotation of -heading about z.
  const SinCos y = half_angle(-heading_deg);
  return Eigen::Quaterniond(y.c, 0, 0, y.s);
}

Mat3 pose_rotation(const Eigen::Quaterniond& yaw, double pitch_deg, double roll_deg) {
  // yaw * pitch * roll as quaternions (pitch about x, nose (+y) up; roll about y, right side (+x)
  // down), written out: the yaw has only w and z, pitch only w and x, roll only w and y.
  const SinCos p = half_angle(pitch_deg), r = half_angle(roll_deg);
  const double pw = p.c * r.c, px = p.s * r.c, py = p.c * r.s, pz = p.s * r.s;  // pitch * roll
  const double a = yaw.w(), d = yaw.z();
  const double w = a * pw - d * pz, x = a * px - d * py, y = a * py + d * px, z = a * pz + d * pw;
  // The rotation matrix of the unit quaternion (w, x, y, z): Eigen's toRotationMatrix, in scalars.
  const double tx = 2 * x, ty = 2 * y, tz = 2 * z;
  const double twx = tx * w, twy = ty * w, twz = tz * w, txx = tx * x, txy = ty * x, txz = tz * x;
  const double tyy = ty * y, tyz = tz * y, tzz = tz * z;
  Mat3 m;
  m << 1 - (tyy + tzz), txy - twz, txz + twy,  //
      txy + twz, 1 - (txx + tzz), tyz - twx,   //
      txz - twy, tyz + twx, 1 - (txx + tyy);
  return m;
}

Mat3 pose_rotation(double heading_deg, double pitch_deg, double roll_deg) {
  return pose_rotation(yaw_quaternion(heading_deg), pitch_deg, roll_deg);
}

}  // namespace npsnet::world
