// A standing trunk as a collision shape (shapes.hpp: make_trunk).
#include <cmath>

#include "collision/shapes.hpp"

namespace npsnet::collision {

Shape make_trunk(const world::Model& m, double r) {
  Shape s;
  const double z0 = m.bbox_min.z(), z1 = std::max<double>(m.bbox_max.z(), z0 + 1e-3);
  s.box_centre = Vec3(0, 0, 0.5 * (z0 + z1));
  s.box_half = Vec3(r, r, 0.5 * (z1 - z0)).cwiseMax(Vec3::Constant(1e-3));
  s.min_half = s.box_half.minCoeff();
  s.sphere_centre = m.centre.cast<double>();
  // The cylinder as a prism of kTrunkSides sides circumscribing it (never smaller than the trunk).
  const double rc = r / std::cos(kPi / kTrunkSides);
  for (int k = 0; k < kTrunkSides; ++k) {
    const double a = 2 * kPi * k / kTrunkSides;
    for (double z : {z0, z1}) s.hull.emplace_back(rc * std::cos(a), rc * std::sin(a), z);
  }
  for (const Vec3& v : s.hull) {
    s.bound_radius = std::max(s.bound_radius, (v - s.sphere_centre).norm());
    s.pivot_radius = std::max(s.pivot_radius, v.norm());
  }
  for (int k = 0; k < kTrunkSides; ++k) {  // the sides, two triangles each, and the two caps
    const Vec3 &a0 = s.hull[2 * k], &a1 = s.hull[2 * k + 1];
    const Vec3 &b0 = s.hull[2 * ((k + 1) % kTrunkSides)], &b1 = s.hull[2 * ((k + 1) % kTrunkSides) + 1];
    s.tris.push_back({a0, b0, b1});
    s.tris.push_back({a0, b1, a1});
    if (k > 0 && k + 1 < kTrunkSides) {
      s.tris.push_back({s.hull[0], b0, a0});
      s.tris.push_back({s.hull[1], a1, b1});
    }
  }
  return s;
}

}  // namespace npsnet::collision
