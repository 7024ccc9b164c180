// core/math.hpp angle helpers: wrap360's in-range shortcut gives the bits fmod gives.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

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
                            -180.0, 540.25, -0.5, std::nextafter(360.0, 0.0), 1e9, -1e9};
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> any(-1000.0, 1000.0);
  for (int i = 0; i < 100000; ++i) xs.push_back(any(rng));
  for (double x : xs) EXPECT_TRUE(same_bits(wrap360(x), wrap360_fmod(x))) << x;
  EXPECT_TRUE(std::isnan(wrap360(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_TRUE(std::signbit(wrap360(-0.0)));  // fmod keeps the sign of a zero
}
