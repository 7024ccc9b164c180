// The float of rad2deg(atan2(y, x)) for x > 0 (a slope angle in degrees, stored as float) with
// the same bits as the libm expression, usually without calling it: a rational approximation of
// atan (detail::atan_rational in core/trig.hpp, from Cephes atan.c: relative error 2.0e-16
// measured against long double over 40 million arguments, tests/core/test_angles.cpp) gives d;
// when every value within 1e-12 |d| of d rounds to the same float, the libm result (within a few
// 1e-16 |d| of d) rounds to it too, so that float is returned; otherwise (about 2 in 100,000
// slopes) the libm expression is evaluated.
// y = +-0 gives +-0 (what atan2 gives for x > 0); NaN and infinite y go the same way as libm's.
// atan2_deg_float2 (terrain following's pitch and roll): the two slopes in one vector division,
// and when both are within kAtanSeriesMax, d from atan's Taylor series to t^17 (no division:
// within 1 ulp of long double there, tests/core/test_angles.cpp) instead of the rational one;
// atan2_deg_float4 the same for two vehicles at once. Every form gives the libm expression's
// float: which of atan's two forms picked d does not change it.
#pragma once
#include <cmath>

#include "core/math.hpp"
#include "core/trig.hpp"

namespace npsnet {

namespace detail {
inline constexpr double kAtanSeriesMax = 0.125;
// atan(t) for |t| <= kAtanSeriesMax: t - t^3/3 + ... + t^17/17 in Estrin's form, on T (a double
// or two in one register). z = t^2 <= 1/64, so the first term left out, t^19/19, is below
// 3.5e-18 |t|: under 0.02 ulp.
template <class T>
inline T atan_series(T t) {
  constexpr double A1 = -1.0 / 3, A2 = 1.0 / 5, A3 = -1.0 / 7, A4 = 1.0 / 9, A5 = -1.0 / 11, A6 = 1.0 / 13,
                   A7 = -1.0 / 15, A8 = 1.0 / 17;
  const T z = t * t, z2 = z * z, z4 = z2 * z2;
  const T p = (A1 + A2 * z) + z2 * (A3 + A4 * z) + z4 * ((A5 + A6 * z) + z2 * (A7 + A8 * z));
  return t + t * z * p;
}
// The float d rounds to when its tolerance does not matter, else the libm expression's.
inline float atan2_deg_float_of(double y, double x, double atan_yx) {
  if (y == 0) return static_cast<float>(y);
  const double d = atan_yx * (180.0 / kPi);  // (not rad2deg's division: d only picks the float)
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
  const detail::Double2 v = detail::Double2{y0, y1} / detail::Double2{x0, x1};  // the bits of y0 / x0, y1 / x1
  double r0, r1;
  if (std::abs(v[0]) <= detail::kAtanSeriesMax && std::abs(v[1]) <= detail::kAtanSeriesMax) {
    const detail::Double2 r = detail::atan_series(v);
    r0 = r[0], r1 = r[1];
  } else {
    detail::atan_rational2(v[0], v[1], r0, r1);
  }
  a = detail::atan2_deg_float_of(y0, x0, r0), b = detail::atan2_deg_float_of(y1, x1, r1);
}

// The same of four slopes at once (two vehicles' pitch and roll side by side), bit for bit: one
// vector division and, when all four are within kAtanSeriesMax, one series; else two pairs.
inline void atan2_deg_float4(const double (&y)[4], const double (&x)[4], float (&out)[4]) {
  using Double4 = double __attribute__((vector_size(32)));
  const Double4 v = Double4{y[0], y[1], y[2], y[3]} / Double4{x[0], x[1], x[2], x[3]};
  bool series = true;
  for (int k = 0; k < 4; ++k) series &= std::abs(v[k]) <= detail::kAtanSeriesMax;
  if (!series) {
    atan2_deg_float2(y[0], x[0], y[1], x[1], out[0], out[1]);
    atan2_deg_float2(y[2], x[2], y[3], x[3], out[2], out[3]);
    return;
  }
  const Double4 r = detail::atan_series(v);
  for (int k = 0; k < 4; ++k) out[k] = detail::atan2_deg_float_of(y[k], x[k], r[k]);
}

}  // namespace npsnet
