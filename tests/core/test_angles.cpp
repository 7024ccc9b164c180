// Angle helpers: wrap360 and wrap180 (core/math.hpp) and atan2_deg_float (core/atan_float.hpp) give the bits
// of the libm expressions they stand for; sincos_small, sincos_deg and atan2_rad
// (core/trig.hpp) are within 1-2.5 ulp of long double; their two-at-once forms give the same bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "core/atan_float.hpp"
#include "core/math.hpp"
#include "core/trig.hpp"

using namespace npsnet;

namespace {
double wrap360_fmod(double deg) {  // wrap360 as written before its shortcut
  double r = std::fmod(deg, 360.0);
  return r < 0 ? r + 360.0 : r;
}
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
}  // namespace

TEST(Angles, Wrap360GivesTheBitsOfFmodInAndOutOfRange) {
  std::vector<double> xs = {0.0, -0.0, 1e-300, -1e-300, 359.99999999999994, 360.0, -360.0, 720.0, 180.0,
                            -180.0, 540.25, -0.5, std::nextafter(360.0, 0.0), 1e9, -1e9,
                            std::nextafter(-360.0, 0.0), std::nextafter(720.0, 0.0), std::nextafter(360.0, 720.0),
                            -359.99999999999994, -1e-17, 719.9, -720.0, 1080.0};
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> any(-1000.0, 1000.0);
  for (int i = 0; i < 100000; ++i) xs.push_back(any(rng));
  for (double x : xs) EXPECT_TRUE(same_bits(wrap360(x), wrap360_fmod(x))) << x;
  EXPECT_TRUE(std::isnan(wrap360(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_TRUE(std::signbit(wrap360(-0.0)));  // fmod keeps the sign of a zero
}

// wrap180 is std::remainder(deg, 360) (exact, the short way round), bit for bit, its shortcut
// included; and |wrap180| is the wrapped magnitude the dead-reckoning bound took before, by fmod.
TEST(Angles, Wrap180GivesTheBitsOfRemainderInAndOutOfRange) {
  std::vector<double> xs = {0.0, -0.0, 1e-300, -1e-300, 179.99999999999997, 180.0, -180.0, 181.0, -181.0,
                            359.99999999999994, 360.0, -360.0, 540.0, -540.0, 720.0, 1e9, -1e9, 1e300, -1e300,
                            std::nextafter(180.0, 0.0), std::nextafter(-180.0, 0.0), std::nextafter(180.0, 360.0)};
  std::mt19937_64 rng(180);
  std::uniform_real_distribution<double> any(-1000.0, 1000.0);
  for (int i = 0; i < 100000; ++i) xs.push_back(any(rng));
  auto abs_by_fmod = [](double d) {  // node/dr_bound.cpp's wrapped |d| before wrap180
    d = std::fabs(d);
    if (d >= 360.0) d = std::fmod(d, 360.0);
    return d > 180.0 ? 360.0 - d : d;
  };
  for (double x : xs) {
    EXPECT_TRUE(same_bits(wrap180(x), std::remainder(x, 360.0))) << x;
    EXPECT_TRUE(same_bits(std::fabs(wrap180(x)), abs_by_fmod(x))) << x;
    EXPECT_LE(std::fabs(wrap180(x)), 180.0) << x;
  }
  EXPECT_TRUE(std::isnan(wrap180(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_TRUE(std::isnan(wrap180(std::numeric_limits<double>::infinity())));
  EXPECT_EQ(wrap180(359.0), -1.0);
  EXPECT_EQ(wrap180(-270.0), 90.0);
}

TEST(Angles, Atan2DegFloatGivesTheBitsOfTheLibmExpression) {
  auto libm = [](double y, double x) { return static_cast<float>(rad2deg(std::atan2(y, x))); };
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> rise(-30.0, 30.0), run(1.0, 12.0), any(-1.0, 1.0), e10(-20.0, 20.0);
  std::uniform_int_distribution<int> scale(0, 8);
  int checked = 0;
  double py = 0.25, px = 3.0;  // the last slope: paired with this one (atan2_deg_float2)
  double hy[4] = {0.1, -0.02, 0.3, 0}, hx[4] = {2.0, 4.0, 1.5, 1};  // the last three, then this one
  auto check = [&](double y, double x) {
    hy[3] = y, hx[3] = x;
    const float a = atan2_deg_float(y, x), b = libm(y, x);
    ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << y << " " << x;
    float p0, p1;
    atan2_deg_float2(py, px, y, x, p0, p1);
    const float b0 = libm(py, px);
    ASSERT_TRUE(std::memcmp(&p0, &b0, sizeof p0) == 0 && std::memcmp(&p1, &b, sizeof p1) == 0)
        << "pair " << py << " " << px << ", " << y << " " << x;
    float q[4];  // the last three slopes and this one (atan2_deg_float4)
    atan2_deg_float4(hy, hx, q);
    for (int k = 0; k < 4; ++k) {
      const float want = libm(hy[k], hx[k]);
      ASSERT_EQ(std::memcmp(&q[k], &want, sizeof want), 0) << "four, lane " << k << ": " << hy[k] << " " << hx[k];
    }
    py = y, px = x;
    for (int k = 0; k < 3; ++k) hy[k] = hy[k + 1], hx[k] = hx[k + 1];
    ++checked;
  };
  // Terrain slopes (rise over a footprint of 1-12 m, down to 1e-8 m) and any ratio over 40 decades.
  for (int i = 0; i < 2000000; ++i) check(rise(rng) * std::pow(10.0, -scale(rng)), run(rng));
  for (int i = 0; i < 1000000; ++i) check(std::copysign(std::pow(10.0, e10(rng)), any(rng)), 1.0 + 1e3 * (any(rng) + 1));
  for (double y : {0.0, -0.0, 1e-300, -1e-300, 0.66, 2.41421356237309504880, 1e300, -1e300,
                   std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()})
    check(y, 1.0);
  EXPECT_EQ(checked, 3000010);
  EXPECT_TRUE(std::signbit(atan2_deg_float(-0.0, 2.0)));
  EXPECT_TRUE(std::isnan(atan2_deg_float(std::numeric_limits<double>::quiet_NaN(), 2.0)));
}

TEST(Angles, AtanRationalIsWithinTwoUlpsOfLongDouble) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> any(-1.0, 1.0), e10(-20.0, 20.0);
  double worst = 0;
  for (int i = 0; i < 1000000; ++i) {
    for (const double v : {any(rng), std::copysign(std::pow(10.0, e10(rng)), any(rng))}) {
      const long double ref = std::atan(static_cast<long double>(v));
      worst = std::max(worst, static_cast<double>(std::fabs((detail::atan_rational(v) - ref) / ref)));
    }
  }
  EXPECT_LT(worst, 4.5e-16);  // the 1e-12 tolerance of atan2_deg_float is thousands of times this
}

TEST(Angles, AtanSeriesIsWithinOneUlpOfLongDouble) {
  // atan2_deg_float2's d for slopes within kAtanSeriesMax (both lanes of the vector form too).
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> any(-detail::kAtanSeriesMax, detail::kAtanSeriesMax), e(-30.0, 0.0);
  double worst = 0;
  for (int i = 0; i < 1000000; ++i) {
    const double v0 = any(rng), v1 = std::copysign(std::pow(10.0, e(rng)) * detail::kAtanSeriesMax, any(rng));
    const detail::Double2 r = detail::atan_series(detail::Double2{v0, v1});
    ASSERT_EQ(r[0], detail::atan_series(v0));
    ASSERT_EQ(r[1], detail::atan_series(v1));
    for (const double v : {v0, v1}) {
      const long double ref = std::atan(static_cast<long double>(v));
      const double ulp = std::nextafter(std::abs(static_cast<double>(ref)), HUGE_VAL) - std::abs(static_cast<double>(ref));
      worst = std::max(worst, static_cast<double>(std::fabs(detail::atan_series(v) - ref) / ulp));
    }
  }
  for (const double v : {detail::kAtanSeriesMax, -detail::kAtanSeriesMax}) {
    const long double ref = std::atan(static_cast<long double>(v));
    EXPECT_LT(static_cast<double>(std::fabs((detail::atan_series(v) - ref) / ref)), 2.3e-16) << v;
  }
  EXPECT_LE(worst, 1.0);
}

TEST(Angles, SinCosSmallIsWithinOneUlpOfLongDouble) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> any(-kSinCosSmallMax, kSinCosSmallMax), e(-30.0, 0.0);
  auto ulps = [](double got, long double ref) {
    const double r = static_cast<double>(ref);
    const double ulp = std::nextafter(std::abs(r), HUGE_VAL) - std::abs(r);
    return static_cast<double>(std::fabs(got - ref)) / ulp;
  };
  double worst_s = 0, worst_c = 0;
  int differ = 0;  // from libm: it is not libm's bits, only as close
  const std::vector<double> edges = {0.0, -0.0, kSinCosSmallMax, -kSinCosSmallMax, 1e-300, -5e-324, 1e-8, 0.5};
  for (int i = 0; i < 2000000; ++i) {
    const double x = i < static_cast<int>(edges.size()) ? edges[i]
                     : i % 2               ? any(rng)
                                           : std::copysign(std::pow(10.0, e(rng)) * kSinCosSmallMax, any(rng));
    const SinCos v = sincos_small(x);
    worst_s = std::max(worst_s, x == 0 ? 0.0 : ulps(v.s, std::sin(static_cast<long double>(x))));
    worst_c = std::max(worst_c, ulps(v.c, std::cos(static_cast<long double>(x))));
    differ += v.s != std::sin(x) || v.c != std::cos(x);
  }
  EXPECT_LE(worst_s, 1.0);
  EXPECT_LE(worst_c, 1.0);
  EXPECT_GT(differ, 0);  // (so the test above is of this function, not of libm)
  EXPECT_TRUE(same_bits(sincos_small(0.0).s, 0.0) && same_bits(sincos_small(-0.0).s, -0.0));
  EXPECT_EQ(sincos_small(0.0).c, 1.0);
}

// Two angles at once (a vehicle's pitch and roll, world::pose_rotation): the bits of one at a time.
TEST(Angles, SinCosDeg2GivesTheBitsOfSinCosDegForEachAngle) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> small(-44.0, 44.0), any(-1000.0, 1000.0);
  const std::vector<double> edges = {0.0, -0.0, 43.999999999999993, -44.0, 44.0, 90.0, -180.0, 1e-300, 1e20,
                                     std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()};
  int paired = 0;
  for (int i = 0; i < 400000; ++i) {
    const size_t ne = edges.size();
    const double d0 = i < static_cast<int>(ne * ne) ? edges[i % ne] : i % 5 ? small(rng) : any(rng);
    const double d1 = i < static_cast<int>(ne * ne) ? edges[i / ne] : i % 7 ? small(rng) : any(rng);
    SinCos a, b;
    sincos_deg2(d0, d1, a, b);
    const SinCos ra = sincos_deg(d0), rb = sincos_deg(d1);
    ASSERT_TRUE(same_bits(a.s, ra.s) && same_bits(a.c, ra.c)) << d0 << " beside " << d1;
    ASSERT_TRUE(same_bits(b.s, rb.s) && same_bits(b.c, rb.c)) << d1 << " beside " << d0;
    paired += std::abs(d0) < 44 && std::abs(d1) < 44;
  }
  EXPECT_GT(paired, 200000);  // most went through the two-lane series
}

TEST(Angles, SinCosDegAndAtan2RadAreWithinTwoAndTwoAndAHalfUlpsOfLongDouble) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> deg(-720.0, 720.0), any(-1.0, 1.0), e(-12.0, 12.0);
  constexpr long double kDeg = 3.14159265358979323846264338327950288L / 180;
  // Error in ulps of the result, or of 1 for a result near 0 (sin of a multiple of 180 degrees
  // is 0 exactly here; libm's sin(pi) is 1.2e-16).
  auto ulps = [](double got, long double ref) {
    const double r = std::max(std::abs(static_cast<double>(ref)), 0.25);
    return static_cast<double>(std::fabs(got - ref)) / (std::nextafter(r, HUGE_VAL) - r);
  };
  double worst_sc = 0, worst_at = 0;
  const std::vector<double> edges = {0,   -0.0, 45, 90, 135, 180, 270, 360, -90, 1e-300, 44.999999999999, 1e15,
                                     44, -44, 43.99999999999999, -43.99999999999999, 1e-20, -5e-324};
  for (int i = 0; i < 1000000; ++i) {
    const double d = i < static_cast<int>(edges.size()) ? edges[i] : deg(rng);
    const SinCos v = sincos_deg(d);
    const long double rad = std::fmod(static_cast<long double>(d), 360.0L) * kDeg;  // (fmod is exact)
    worst_sc = std::max({worst_sc, ulps(v.s, std::sin(rad)), ulps(v.c, std::cos(rad))});
    const double y = i % 3 ? any(rng) : std::copysign(std::pow(10.0, e(rng)), any(rng)), x = any(rng);
    const long double ref = std::atan2(static_cast<long double>(y), static_cast<long double>(x));
    const double at = atan2_rad(y, x);
    worst_at = std::max(worst_at, static_cast<double>(std::fabs(at - ref) / std::fabs(ref)) / 0x1p-53);
  }
  EXPECT_LE(worst_sc, 2.0);
  EXPECT_LE(worst_at, 5.0);  // relative error in units of 2^-53 (2.5 ulp at worst)
  // The right angles are exact, and so is their quadrant.
  for (int q = -8; q <= 8; ++q) {
    const SinCos v = sincos_deg(90.0 * q);
    const int m = ((q % 4) + 4) % 4;
    EXPECT_EQ(v.s, m == 1 ? 1.0 : m == 3 ? -1.0 : 0.0) << q;
    EXPECT_EQ(v.c, m == 0 ? 1.0 : m == 2 ? -1.0 : 0.0) << q;
  }
  // atan2's special cases and signs: libm's.
  for (double y : {0.0, -0.0, 1.0, -1.0})
    for (double x : {0.0, -0.0, 2.0, -2.0})
      EXPECT_TRUE(same_bits(atan2_rad(y, x), std::atan2(y, x))) << y << " " << x;
  EXPECT_TRUE(std::isnan(sincos_deg(NAN).s) && std::isnan(atan2_rad(NAN, 1.0)));
  EXPECT_EQ(atan2_rad(1.0, 1.0), std::atan2(1.0, 1.0));
}
