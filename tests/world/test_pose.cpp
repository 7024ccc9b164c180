// pose_rotation from a kept yaw quaternion (world/pose.hpp; collision keeps one per entity while
// its heading stays the same float) gives the bits of the three-AngleAxis form it stands for.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "world/pose.hpp"

using namespace npsnet;

namespace {
Mat3 three_angle_axes(double heading_deg, double pitch_deg, double roll_deg) {  // pose_rotation as written before
  const Eigen::AngleAxisd yaw(-deg2rad(heading_deg), Vec3::UnitZ());
  const Eigen::AngleAxisd pitch(deg2rad(pitch_deg), Vec3::UnitX());
  const Eigen::AngleAxisd roll(deg2rad(roll_deg), Vec3::UnitY());
  return (yaw * pitch * roll).toRotationMatrix();
}
bool same_bits(const Mat3& a, const Mat3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 9) == 0; }
}  // namespace

TEST(Pose, KeptYawQuaternionGivesTheBitsOfTheThreeAngleForm) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> heading(-720.f, 720.f), tilt(-60.f, 60.f);
  const std::vector<float> special = {0.f, -0.f, 90.f, 180.f, 270.f, 359.99997f, 1e-30f, -1e-30f, 360.f};
  for (int i = 0; i < 200000; ++i) {
    const float h = i < static_cast<int>(special.size()) ? special[i] : heading(rng);
    const float p = i % 7 == 0 ? 0.f : tilt(rng), r = i % 5 == 0 ? -0.f : tilt(rng);
    const Mat3 ref = three_angle_axes(h, p, r);
    ASSERT_TRUE(same_bits(world::pose_rotation(world::yaw_quaternion(h), p, r), ref)) << h << " " << p << " " << r;
    ASSERT_TRUE(same_bits(world::pose_rotation(h, p, r), ref)) << h << " " << p << " " << r;
  }
}
