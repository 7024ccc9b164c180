#include "world/pose.hpp"

namespace npsnet::world {

Mat3 pose_rotation(double heading_deg, double pitch_deg, double roll_deg) {
  // Compass heading turns clockwise seen from above: a rotation of -heading about z.
  const Eigen::AngleAxisd yaw(-deg2rad(heading_deg), Vec3::UnitZ());
  const Eigen::AngleAxisd pitch(deg2rad(pitch_deg), Vec3::UnitX());  // nose (+y) up
  const Eigen::AngleAxisd roll(deg2rad(roll_deg), Vec3::UnitY());     // right side (+x) down
  return (yaw * pitch * roll).toRotationMatrix();
}

}  // namespace npsnet::world
