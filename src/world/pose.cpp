#include "world/pose.hpp"

namespace npsnet::world {

Eigen::Quaterniond yaw_quaternion(double heading_deg) {
  // Compass heading turns clockwise seen from above: a rotation of -heading about z.
  return Eigen::Quaterniond(Eigen::AngleAxisd(-deg2rad(heading_deg), Vec3::UnitZ()));
}

Mat3 pose_rotation(const Eigen::Quaterniond& yaw, double pitch_deg, double roll_deg) {
  const Eigen::AngleAxisd pitch(deg2rad(pitch_deg), Vec3::UnitX());  // nose (+y) up
  const Eigen::AngleAxisd roll(deg2rad(roll_deg), Vec3::UnitY());     // right side (+x) down
  // Eigen: AngleAxis * AngleAxis is Quaternion(a) * Quaternion(b); Quaternion * AngleAxis is
  // q * Quaternion(b): the products of the three-AngleAxis form, in its order.
  return (yaw * pitch * roll).toRotationMatrix();
}

Mat3 pose_rotation(double heading_deg, double pitch_deg, double roll_deg) {
  return pose_rotation(yaw_quaternion(heading_deg), pitch_deg, roll_deg);
}

}  // namespace npsnet::world
