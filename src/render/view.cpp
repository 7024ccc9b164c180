#include "render/view.hpp"

#include <algorithm>
#include <cmath>

namespace npsnet::render {

ViewMath make_view(const Vec3& eye, const Vec3& target, double fov_y_deg, int width, int height, const Vec3& up) {
  ViewMath v;
  v.eye = eye;
  v.width = std::max(1, width);
  v.height = std::max(1, height);
  Vec3 f = target - eye;
  if (!(f.norm() > 1e-9) || !f.allFinite()) f = Vec3(0, 1, 0);
  f.normalize();
  Vec3 r = f.cross(up.allFinite() ? up : Vec3(0, 0, 1));
  if (r.norm() < 1e-6) r = f.cross(Vec3(0, 0, 1));
  if (r.norm() < 1e-6) r = f.cross(Vec3(0, 1, 0));  // looking straight up or down
  r.normalize();
  const Vec3 u = r.cross(f);
  v.forward = f.cast<float>();
  v.right = r.cast<float>();
  v.up = u.cast<float>();
  Mat4f view = Mat4f::Identity();
  view.block<1, 3>(0, 0) = v.right.transpose();
  view.block<1, 3>(1, 0) = v.up.transpose();
  view.block<1, 3>(2, 0) = -v.forward.transpose();
  v.view = view;
  const double fov = std::clamp(std::isfinite(fov_y_deg) ? fov_y_deg : 50.0, 1.0, 170.0);
  v.tan_half_fov_y = static_cast<float>(std::tan(deg2rad(fov) / 2));
  v.aspect = static_cast<float>(v.width) / static_cast<float>(v.height);
  const float n = kNearM, fa = kFarM;
  Mat4f p = Mat4f::Zero();
  p(0, 0) = 1.0f / (v.aspect * v.tan_half_fov_y);
  p(1, 1) = 1.0f / v.tan_half_fov_y;
  p(2, 2) = -(fa + n) / (fa - n);
  p(2, 3) = -2.0f * fa * n / (fa - n);
  p(3, 2) = -1.0f;
  v.proj = p;
  v.vp = p * view;
  // Gribb-Hartmann plane extraction from the combined matrix.
  const Mat4f& m = v.vp;
  const Vec4f r0 = m.row(0), r1 = m.row(1), r2 = m.row(2), r3 = m.row(3);
  v.planes = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
  for (auto& pl : v.planes) pl /= pl.head<3>().norm();
  return v;
}

bool ViewMath::box_visible(const Vec3& lo, const Vec3& hi) const {
  const Vec3f l = (lo - eye).cast<float>(), h = (hi - eye).cast<float>();
  for (const auto& pl : planes) {
    // the box corner farthest along the plane normal
    const float x = pl.x() >= 0 ? h.x() : l.x();
    const float y = pl.y() >= 0 ? h.y() : l.y();
    const float z = pl.z() >= 0 ? h.z() : l.z();
    if (pl.x() * x + pl.y() * y + pl.z() * z + pl.w() < 0) return false;
  }
  return true;
}

bool ViewMath::sphere_visible(const Vec3& c, float r) const {
  const Vec3f p = (c - eye).cast<float>();
  for (const auto& pl : planes)
    if (pl.head<3>().dot(p) + pl.w() < -r) return false;
  return true;
}

bool project_to_pixel(const ViewMath& v, const Vec3& p, double& px, double& py) {
  const Vec3f rel = (p - v.eye).cast<float>();
  const Vec4f c = v.vp * Vec4f(rel.x(), rel.y(), rel.z(), 1.0f);
  if (c.w() <= 1e-6f) return false;
  const double nx = c.x() / c.w(), ny = c.y() / c.w();
  px = (nx * 0.5 + 0.5) * v.width;
  py = (1.0 - (ny * 0.5 + 0.5)) * v.height;
  return true;
}

}  // namespace npsnet::render
