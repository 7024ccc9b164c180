// Angle helpers: wrap360 (core/math.hpp) and atan2_deg_float (core/atan_float.hpp) give the bits
// of the libm expressions they stand for.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "core/atan_float.hpp"
#include "core/math.hpp"

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

TEST(Angles, Atan2DegFloatGivesTheBitsOfTheLibmExpression) {
  auto libm = [](double y, double x) { return static_cast<float>(rad2deg(std::atan2(y, x))); };
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> rise(-30.0, 30.0), run(1.0, 12.0), any(-1.0, 1.0), e10(-20.0, 20.0);
  std::uniform_int_distribution<int> scale(0, 8);
  int checked = 0;
  auto check = [&](double y, double x) {
    const float a = atan2_deg_float(y, x), b = libm(y, x);
    ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << y << " " << x;
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
