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

namespace detail {
// The float d rounds to when its tolerance does not matter, else the libm expression's.
inline float atan2_deg_float_of(double y, double x, double atan_yx) {
  if (y == 0) return static_cast<float>(y);
  const double d = rad2deg(atan_yx);
  const double tol = 1e-12 * std::abs(d);
  const float lo = static_cast<float>(d - tol), hi = static_cast<float>(d + tol);
  if (lo == hi) return lo;
  return static_cast<float>(rad2deg(std::atan2(y, x)));
}
}  // namespace detail

// static_cast<float>(rad2deg(std::atan2(y, x))), x > 0 and finite.
inline float atan2_deg_float(double y, double x) {
  return detail::atan2_deg_float_of(y, x, detail::atan_rational(y / x));
}

// The same of two slopes at once (terrain following's pitch and roll), bit for bit.
inline void atan2_deg_float2(double y0, double x0, double y1, double x1, float& a, float& b) {
  double r0, r1;
  detail::atan_rational2(y0 / x0, y1 / x1, r0, r1);
  a = detail::atan2_deg_float_of(y0, x0, r0), b = detail::atan2_deg_float_of(y1, x1, r1);
}

}  // namespace npsnet
