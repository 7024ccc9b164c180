// The float of rad2deg(atan2(y, x)) for x > 0 (a slope angle in degrees, stored as float) with
// the same bits as the libm expression, usually without calling it: a rational approximation of
// atan (Cephes atan.c: relative error 2.0e-16 measured against long double over 40 million
// arguments, tests/core/test_angles.cpp) gives d; when every value within 1e-12 |d| of d rounds
// to the same float, the libm result (within a few 1e-16 |d| of d) rounds to it too, so that
// float is returned; otherwise (about 2 in 100,000 slopes) the libm expression is evaluated.
// y = +-0 gives +-0 (what atan2 gives for x > 0); NaN and infinite y go the same way as libm's.
#pragma once
#include <cmath>

#include "core/math.hpp"

namespace npsnet {

namespace detail {
// atan(v), relative error about 1 ulp (Cephes: three ranges, a 4/5 rational in v^2).
inline double atan_rational(double v) {
  constexpr double P[] = {-8.750608600031904122785E-1, -1.615753718733365076637E1, -7.500855792314704667340E1,
                          -1.228866684490136173410E2, -6.485021904942025371773E1};
  constexpr double Q[] = {2.485846490142306297962E1, 1.650270098316988542046E2, 4.328810604912902668951E2,
                          4.853903996359136964868E2, 1.945506571482613964425E2};
  constexpr double kTan3Pi8 = 2.41421356237309504880, kMoreBits = 6.123233995736765886130E-17;
  const bool neg = v < 0;
  double t = neg ? -v : v, base = 0, more = 0;
  if (t > kTan3Pi8) base = kPi / 2, more = kMoreBits, t = -1.0 / t;
  else if (t > 0.66) base = kPi / 4, more = 0.5 * kMoreBits, t = (t - 1.0) / (t + 1.0);
  const double z = t * t;
  const double p = (((P[0] * z + P[1]) * z + P[2]) * z + P[3]) * z + P[4];
  const double q = ((((z + Q[0]) * z + Q[1]) * z + Q[2]) * z + Q[3]) * z + Q[4];
  const double r = base + ((t * (z * p / q) + t) + more);
  return neg ? -r : r;
}
}  // namespace detail

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
