// Swept-sphere time of impact, analytic (issue 6). Two spheres move linearly over one tick:
// a from a0 to a1, b from b0 to b1 (local frame, m). The first time |d(t)| = ra + rb, with
// d(t) = (b0 - a0) + t ((b1 - b0) - (a1 - a0)) and t the fraction of the tick in [0, 1], is the
// smaller root of |v|^2 t^2 + 2 (d0.v) t + |d0|^2 - R^2 = 0. A fixed sphere has b0 = b1.
// The answer is a Trace (trace.hpp): fraction = first touch, exit_fraction = last touch, point
// midway between the two surfaces on the line of centres, normal from a towards b.
#pragma once
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

}  // namespace npsnet::collision
