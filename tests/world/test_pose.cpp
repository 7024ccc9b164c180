// pose_rotation (world/pose.hpp): within a few 1e-16 of the three-AngleAxis form it stands for
// (its half angles are core/trig.hpp's sincos_deg, not libm's), and from a kept
// yaw quaternion (collision keeps one per entity while its heading stays the same float) the
// same bits as from the heading.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "world/pose.hpp"

using namespace npsnet;

namespace {
// pose_rotation as it was first written (three AngleAxis), in long double, the heading reduced
// to a turn in degrees first (exactly, by fmod), so that the reference is within 1e-18.
Mat3 three_angle_axes(double heading_deg, double pitch_deg, double roll_deg) {
  using AA = Eigen::AngleAxis<long double>;
  using V = Eigen::Matrix<long double, 3, 1>;
  constexpr long double kDeg = 3.14159265358979323846264338327950288L / 180;
  const AA yaw(-std::fmod(static_cast<long double>(heading_deg), 360.0L) * kDeg, V::UnitZ());
  const AA pitch(pitch_deg * kDeg, V::UnitX()), roll(roll_deg * kDeg, V::UnitY());
  return (yaw * pitch * roll).toRotationMatrix().cast<double>();
}
bool same_bits(const Mat3& a, const Mat3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 9) == 0; }
}  // namespace

TEST(Pose, KeptYawQuaternionGivesTheSameBitsAndBothAreTheThreeAngleForm) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> heading(-720.f, 720.f), tilt(-60.f, 60.f);
  const std::vector<float> special = {0.f, -0.f, 90.f, 180.f, 270.f, 359.99997f, 1e-30f, -1e-30f, 360.f};
  double worst = 0, worst_libm = 0, ortho = 0, ortho_ref = 0;  // (orthogonality: |M M^T - I|)
  for (int i = 0; i < 200000; ++i) {
    const float h = i < static_cast<int>(special.size()) ? special[i] : heading(rng);
    const float p = i % 7 == 0 ? 0.f : tilt(rng), r = i % 5 == 0 ? -0.f : tilt(rng);
    const Mat3 ref = three_angle_axes(h, p, r);
    const Mat3 m = world::pose_rotation(h, p, r);
    const Mat3 libm = (Eigen::AngleAxisd(-deg2rad(h), Vec3::UnitZ()) * Eigen::AngleAxisd(deg2rad(p), Vec3::UnitX()) *
                       Eigen::AngleAxisd(deg2rad(r), Vec3::UnitY())).toRotationMatrix();  // the old one, in double
    ASSERT_TRUE(same_bits(world::pose_rotation(heading_to_dir(h), p, r), m)) << h << " " << p << " " << r;
    worst = std::max(worst, (m - ref).cwiseAbs().maxCoeff());
    worst_libm = std::max(worst_libm, (libm - ref).cwiseAbs().maxCoeff());
    ortho = std::max(ortho, (m * m.transpose() - Mat3::Identity()).cwiseAbs().maxCoeff());
    ortho_ref = std::max(ortho_ref, (libm * libm.transpose() - Mat3::Identity()).cwiseAbs().maxCoeff());
  }
  // A different sincos at all (a wrong term, a sign) would be off by far more than this.
  EXPECT_GT(worst, 0.0);
  // No less accurate than the old one (libm's sin and cos of radians, Eigen's products).
  EXPECT_LE(worst, worst_libm) << worst << " against " << worst_libm;
  EXPECT_LT(worst, 2e-15);
  EXPECT_LT(ortho, 2 * ortho_ref) << ortho << " against the old (libm and Eigen) product's " << ortho_ref;
}
