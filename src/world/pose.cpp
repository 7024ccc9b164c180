#include "world/pose.hpp"

namespace npsnet::world {

Mat3 pose_rotation(double heading_deg, double pitch_deg, double roll_deg) {
  return pose_rotation(heading_to_dir(heading_deg), pitch_deg, roll_deg);
}

}  // namespace npsnet::world
