// Trigonometry of the hot loops without libm: every vehicle's heading direction, its heading to a
// waypoint and the half angles of its pose are a few of these a tick (a libm sincos or atan2 is
// about 110-150 instructions; these 30-60), with the same bits on every libm. Within 1 ulp of
// the exact value (sincos_small), 2 ulp (sincos_deg: the degrees' conversion rounds too) and
// 2.5 ulp (atan2_rad), measured against long double in tests/core/test_angles.cpp; not libm's bits.
//  sincos_small(x): |x| <= pi/4, the Taylor series to x^17 and x^16 (the first terms left out,
//    x^19/19! and x^18/18!, are below 1e-19 and 2e-18 there: under 0.02 ulp), in Estrin's form.
//  sincos_deg(deg): any finite angle in degrees: reduced by a multiple of 90 degrees in degrees
//    (exact below 2^52), so 90, 180, 270 give exact 0 and +-1. NaN, infinite and huge: libm.
//  atan2_rad(y, x): atan2 from a rational atan (Cephes atan.c), with atan2's quadrants.
//  sincos_small2, sincos_deg2, detail::atan_rational2: two angles at once (a vehicle's pitch and
//    roll) in one SSE2 register, the same bits as one at a time (the series are shared templates).
#pragma once
#include <cmath>
#include <numbers>

namespace npsnet {

struct SinCos {
  double s, c;
};

inline constexpr double kSinCosSmallMax = std::numbers::pi / 4;

namespace detail {
// The series of sincos_small on T: a double, or two doubles in one SSE2 register (sincos_small2):
// the same operations in the same order on each lane, so the same bits.
template <class T>
inline void sincos_series(T x, T& s, T& c) {
  // (-1)^k / (2k+1)! and (-1)^k / (2k)!, rounded to double.
  constexpr double S3 = -1.66666666666666657415e-01, S5 = 8.33333333333333321769e-03,
                   S7 = -1.98412698412698412526e-04, S9 = 2.75573192239858925110e-06,
                   S11 = -2.50521083854417202239e-08, S13 = 1.60590438368216133409e-10,
                   S15 = -7.64716373181981640551e-13, S17 = 2.81145725434552059811e-15;
  constexpr double C4 = 4.16666666666666643537e-02, C6 = -1.38888888888888894189e-03,
                   C8 = 2.48015873015873015658e-05, C10 = -2.75573192239858882758e-07,
                   C12 = 2.08767569878681001866e-09, C14 = -1.14707455977297245073e-11,
                   C16 = 4.77947733238738525345e-14;
  // Estrin's scheme (pairs, then powers z^2 and z^4): a third of Horner's chain of dependent
  // multiply-adds, so that a vehicle's few of these overlap instead of waiting on each other.
  const T z = x * x, z2 = z * z, z4 = z2 * z2;
  const T ps = (S3 + S5 * z) + z2 * (S7 + S9 * z) + z4 * ((S11 + S13 * z) + z2 * (S15 + S17 * z));
  const T pc = (C4 + C6 * z) + z2 * (C8 + C10 * z) + z4 * ((C12 + C14 * z) + z2 * C16);
  // The small corrections first, the leading terms last: one rounding of the leading sum.
  const T hz = 0.5 * z;
  s = x + x * z * ps;
  c = (1.0 - hz) + ((1.0 - (1.0 - hz)) - hz + z * z * pc);
}
using Double2 = double __attribute__((vector_size(16)));
}  // namespace detail

// sin and cos of x for |x| <= kSinCosSmallMax (a larger x loses accuracy: the caller checks).
inline SinCos sincos_small(double x) {
  double s, c;
  detail::sincos_series(x, s, c);
  return {x == 0 ? x : s, c};  // (sin(-0) is -0)
}

// sincos_small of two angles at once, bit for bit (a vehicle's pitch and roll: one chain of
// multiplies for both).
inline void sincos_small2(double x0, double x1, SinCos& a, SinCos& b) {
  detail::Double2 s, c;
  detail::sincos_series(detail::Double2{x0, x1}, s, c);
  a = {x0 == 0 ? x0 : s[0], c[0]};
  b = {x1 == 0 ? x1 : s[1], c[1]};
}

// sin and cos of an angle in degrees.
inline SinCos sincos_deg(double deg) {
  if (!(std::abs(deg) < 0x1p52)) {  // NaN, infinite, or too large to reduce exactly here
    const double r = deg * (std::numbers::pi / 180);
    return {std::sin(r), std::cos(r)};
  }
  // Within 44 degrees q below is 0 and r is deg: the series at once (a vehicle's pitch and roll).
  if (std::abs(deg) < 44.0) return sincos_small(deg * (std::numbers::pi / 180));
  // q: the nearest multiple of 90 degrees (or one that leaves r a hair past 45: the series holds
  // there), without libm or a division.
  const long long q = static_cast<long long>(deg * (1.0 / 90.0) + (deg < 0 ? -0.5 : 0.5));
  const double r = deg - 90.0 * static_cast<double>(q);  // exact: 90 q is an integer, a multiple of deg's ulp
  const SinCos v = sincos_small(r * (std::numbers::pi / 180));
  switch (q & 3) {  // sin(r + 90) = cos r, cos(r + 90) = -sin r
    case 0: return v;
    case 1: return {v.c, -v.s};
    case 2: return {-v.s, -v.c};
    default: return {-v.c, v.s};
  }
}

// sincos_deg of two angles, bit for bit: both within 44 degrees (a vehicle's pitch and roll) as
// one sincos_small2, else one by one.
inline void sincos_deg2(double d0, double d1, SinCos& a, SinCos& b) {
  if (std::abs(d0) < 44.0 && std::abs(d1) < 44.0) {
    sincos_small2(d0 * (std::numbers::pi / 180), d1 * (std::numbers::pi / 180), a, b);
    return;
  }
  a = sincos_deg(d0), b = sincos_deg(d1);
}

namespace detail {
// Cephes' atan after its range reduction, on T (a double, or two in one register: atan_rational2):
// base + atan(t) + more, t in [-0.42, 0.66].
template <class T>
inline T atan_reduced(T t, T base, T more) {
  constexpr double P[] = {-8.750608600031904122785E-1, -1.615753718733365076637E1, -7.500855792314704667340E1,
                          -1.228866684490136173410E2, -6.485021904942025371773E1};
  constexpr double Q[] = {2.485846490142306297962E1, 1.650270098316988542046E2, 4.328810604912902668951E2,
                          4.853903996359136964868E2, 1.945506571482613964425E2};
  const T z = t * t;
  const T p = (((P[0] * z + P[1]) * z + P[2]) * z + P[3]) * z + P[4];
  const T q = ((((z + Q[0]) * z + Q[1]) * z + Q[2]) * z + Q[3]) * z + Q[4];
  return base + ((t * (z * p / q) + t) + more);
}
// The range reduction: |v| -> t, base, more (three ranges); neg: v < 0.
inline void atan_reduce(double v, bool& neg, double& t, double& base, double& more) {
  constexpr double kTan3Pi8 = 2.41421356237309504880, kMoreBits = 6.123233995736765886130E-17;
  neg = v < 0;
  t = neg ? -v : v, base = 0, more = 0;
  if (t > kTan3Pi8) base = std::numbers::pi / 2, more = kMoreBits, t = -1.0 / t;
  else if (t > 0.66) base = std::numbers::pi / 4, more = 0.5 * kMoreBits, t = (t - 1.0) / (t + 1.0);
}
// atan(v), relative error about 1 ulp (Cephes: three ranges, a 4/5 rational in v^2).
inline double atan_rational(double v) {
  bool neg;
  double t, base, more;
  atan_reduce(v, neg, t, base, more);
  const double r = atan_reduced(t, base, more);
  return neg ? -r : r;
}
// atan_rational of two values at once, bit for bit (a vehicle's pitch and roll slopes).
inline void atan_rational2(double v0, double v1, double& r0, double& r1) {
  bool n0, n1;
  double t0, b0, m0, t1, b1, m1;
  atan_reduce(v0, n0, t0, b0, m0);
  atan_reduce(v1, n1, t1, b1, m1);
  const Double2 r = atan_reduced(Double2{t0, t1}, Double2{b0, b1}, Double2{m0, m1});
  r0 = n0 ? -r[0] : r[0], r1 = n1 ? -r[1] : r[1];
}
}  // namespace detail

// atan2(y, x) for finite y, x (either infinite or NaN: libm's): the angle of (x, y) in radians,
// in [-pi, pi]; the signs of zeros as atan2 gives them.
inline double atan2_rad(double y, double x) {
  if (!std::isfinite(y) || !std::isfinite(x) || x == 0 || y == 0) return std::atan2(y, x);
  const double ax = std::abs(x), ay = std::abs(y);
  // The smaller over the larger, so the quotient rounds once: pi/2 - atan(x/y) beyond 45 degrees.
  double a = ay <= ax ? detail::atan_rational(ay / ax) : std::numbers::pi / 2 - detail::atan_rational(ax / ay);
  if (x < 0) a = std::numbers::pi - a;
  return y < 0 ? -a : a;
}

}  // namespace npsnet
