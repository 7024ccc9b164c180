// Camera math for the renderer, in floats, eye-relative: the view matrix holds only the rotation
// and every position is drawn as (world - eye), so 50 km coordinates keep millimetre precision.
// Local frame: x east, y north, z up, metres. Pixels: (0, 0) = top-left.
#pragma once
#include <Eigen/Core>
#include <array>

#include "core/math.hpp"

namespace npsnet::render {

using Mat4f = Eigen::Matrix4f;
using Vec4f = Eigen::Vector4f;

inline constexpr float kNearM = 1.0f;     // near plane, m
inline constexpr float kFarM = 75000.0f;  // far plane, m (the 50 km square's diagonal)

struct ViewMath {
  Vec3 eye{0, 0, 0};
  Vec3f forward{0, 1, 0}, right{1, 0, 0}, up{0, 0, 1};
  Mat4f view = Mat4f::Identity();  // rotation only
  Mat4f proj = Mat4f::Identity();
  Mat4f vp = Mat4f::Identity();    // proj * view, applied to (world - eye)
  std::array<Vec4f, 6> planes{};   // frustum planes in eye-relative coordinates, inside >= 0
  float tan_half_fov_y = 0.5f, aspect = 1;
  int width = 1, height = 1;

  // Axis-aligned box [lo, hi] in world coordinates: false when wholly outside a plane.
  bool box_visible(const Vec3& lo, const Vec3& hi) const;
  bool sphere_visible(const Vec3& c, float r) const;
};

// eye == target or a degenerate fov are corrected (forward defaults to +y, fov clamped 1..170 deg).
// `up`: the frame's up direction before it is made square to the line of sight (a rolled
// vehicle's roof); along the line of sight or not finite, +z is used.
ViewMath make_view(const Vec3& eye, const Vec3& target, double fov_y_deg, int width, int height,
                   const Vec3& up = Vec3(0, 0, 1));

// Window pixel of a world point (x right, y down, top-left origin); false when behind the camera.
bool project_to_pixel(const ViewMath& v, const Vec3& p, double& px, double& py);

}  // namespace npsnet::render
