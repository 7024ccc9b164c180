// The float of rad2deg(atan2(y, x)) for x > 0 (a slope angle in degrees, stored as float) with
// the same bits as the libm expression, usually without calling it: a rational approximation of
// atan (detail::atan_rational in core/trig.hpp, from Cephes atan.c: relative error 2.0e-16
// measured against long double over 40 million arguments, tests/core/test_angles.cpp) gives d;
// when every value within 1e-12 |d| of d rounds to the same float, the libm result (within a few
// 1e-16 |d| of d) rounds to it too, so that float is returned; otherwise (about 2 in 100,000
// slopes) the libm expression is evaluated.
// y = +-0 gives +-0 (what atan2 gives for x > 0); NaN and infinite y go the same way as libm's.
#pragma once
#include <cmath>

#include "core/math.hpp"
#include "core/trig.hpp"

namespace npsnet {

// static_cast<float>(rad2deg(std::atan2(y, x))), x > 0 and finite.
inline float atan2_deg_float(double y, double x) {
  if (y == 0) return static_cast<float>(y);
  const double d = rad2deg(detail::atan_rational(y / x));
  const double tol = 1e-12 * std::abs(d);
  const float lo = static_cast<float>(d - tol), hi = static_cast<float>(d + tol);
  if (lo == hi) return lo;
  return static_cast<float>(rad2deg(std::atan2(y, x)));
}

}  // namespace npsnet
