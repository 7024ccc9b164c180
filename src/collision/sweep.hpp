// Swept-sphere time of impact, analytic (issue 6). Two spheres move linearly over one tick:
// a from a0 to a1, b from b0 to b1 (local frame, m). The first time |d(t)| = ra + rb, with
// d(t) = (b0 - a0) + t ((b1 - b0) - (a1 - a0)) and t the fraction of the tick in [0, 1], is the
// smaller root of |v|^2 t^2 + 2 (d0.v) t + |d0|^2 - R^2 = 0. A fixed sphere has b0 = b1.
// The answer is a Trace (trace.hpp): fraction = first touch, exit_fraction = last touch, point
// midway between the two surfaces on the line of centres, normal from a towards b.
#pragma once
#include <cmath>

#include "collision/trace.hpp"
#include "core/math.hpp"

namespace npsnet::collision {

// Throws std::invalid_argument when an input is NaN or infinite, or a radius is negative.
// Touching exactly (grazing, |d| = R at one instant) is a hit with exit_fraction = fraction. With no relative
// motion the spheres either overlap for the whole tick (started_inside) or never meet. When the
// centres coincide the normal is the relative velocity's direction, or +x without one.
// hit_only: the same hit, started_inside and fraction, the rest left at Trace's defaults (a
// running episode asks only whether its bounds still meet).
Trace sphere_sweep(const Vec3& a0, const Vec3& a1, double ra, const Vec3& b0, const Vec3& b1, double rb,
                   bool hit_only = false);

// b's travel over the tick relative to a's: the motion v of d(t) = (b0 - a0) + t v.
inline Vec3 relative_motion(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  return (b1 - b0) - (a1 - a0);
}

namespace detail {
// The hit's exit, normal and point (sphere_sweep_checked, once the first touch is known).
Trace sweep_contact(Trace h, const Vec3& a0, const Vec3& a1, double ra, const Vec3& b0, const Vec3& b1, double rb,
                    const Vec3& v, double A, double B, double C, double s);
[[noreturn]] void sweep_overflows();
}  // namespace detail

// The same answer, bit for bit, for radii the caller knows are finite and not negative (the
// detector's, from the kinds it loaded), without sphere_sweep's checks of each input: a NaN or
// infinite coordinate or radius still throws std::invalid_argument, by way of the motion's
// terms (|v|^2, d0.v, |d0|^2 - R^2), whatever they came from. Inline, its miss and its running
// episode's answer (hit_only) ahead of the rest: the continuous method's pair loop asks it of
// about 100,000 pairs a tick in the 100,000-vehicle crowd.
inline Trace sphere_sweep_checked(const Vec3& a0, const Vec3& a1, double ra, const Vec3& b0, const Vec3& b1, double rb,
                                  bool hit_only = false) {
  Trace h;
  const Vec3 d0 = b0 - a0;
  const Vec3 v = relative_motion(a0, a1, b0, b1);
  const double R = ra + rb;
  const double A = v.squaredNorm();
  const double B = d0.dot(v);
  const double C = d0.squaredNorm() - R * R;
  if (!std::isfinite(A) || !std::isfinite(B) || !std::isfinite(C)) detail::sweep_overflows();
  if (C < 0) {  // overlapping at the start
    h.hit = h.started_inside = true;
    h.fraction = 0;
    return hit_only ? h : detail::sweep_contact(h, a0, a1, ra, b0, b1, rb, v, A, B, C, 0);
  }
  if (A <= 0 || B >= 0) return h;  // no relative motion, or moving apart (or tangent at t=0)
  const double disc = B * B - A * C;
  if (disc < 0) return h;
  const double s = std::sqrt(disc);
  // Smaller root, in the form that does not cancel: -B > 0, so -B + s > 0.
  const double t = C / (-B + s);
  if (t > 1) return h;
  h.hit = true;
  h.fraction = t;
  return hit_only ? h : detail::sweep_contact(h, a0, a1, ra, b0, b1, rb, v, A, B, C, s);
}

}  // namespace npsnet::collision
