// Analytic swept-sphere time of impact (sweep.hpp).
#include "collision/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace npsnet::collision {
Trace sphere_sweep(const Vec3& a0, const Vec3& a1, double ra, const Vec3& b0, const Vec3& b1, double rb,
                   bool hit_only) {
  if (!finite(a0) || !finite(a1) || !finite(b0) || !finite(b1) || !std::isfinite(ra) || !std::isfinite(rb))
    throw std::invalid_argument("sphere_sweep: position or radius is not finite (NaN or infinite input)");
  if (ra < 0 || rb < 0) throw std::invalid_argument("sphere_sweep: negative radius");
  return sphere_sweep_checked(a0, a1, ra, b0, b1, rb, hit_only);
}

namespace detail {

void sweep_overflows() {
  throw std::invalid_argument("sphere_sweep: motion overflows (infinite relative displacement)");
}

Trace sweep_contact(Trace h, const Vec3& a0, const Vec3& a1, double ra, const Vec3& b0, const Vec3& b1, double rb,
                    const Vec3& v, double A, double B, double C, double s) {
  const double R = ra + rb;
  if (h.started_inside) h.exit_fraction = A > 0 ? std::min(1.0, (-B + std::sqrt(B * B - A * C)) / A) : 1.0;
  else h.exit_fraction = std::min(1.0, (-B + s) / A);
  const Vec3 ca = a0 + h.fraction * (a1 - a0), cb = b0 + h.fraction * (b1 - b0);
  const Vec3 d = cb - ca;
  const double n = d.norm();
  if (n > 1e-12 * std::max(1.0, R)) h.normal = d / n;
  else if (A > 0) h.normal = v.normalized();  // b moves away from a along v a moment later
  else h.normal = Vec3::UnitX();
  // Midway between a's surface point and b's surface point on the line of centres.
  h.point = 0.5 * ((ca + ra * h.normal) + (cb - rb * h.normal));
  return h;
}

}  // namespace detail

}  // namespace npsnet::collision
