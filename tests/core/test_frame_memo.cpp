// geo::FrameMemo: LocalFrame's to_geodetic, to_ecef, to_dis_euler and jacobian through the kept
// series terms, inverses, sines and convergences give the bits of the plain functions, for runs of
// points that share coordinates (p, p + v, p + z, p + x, p + y) and runs that share only some of
// them (one coordinate, a latitude but not a longitude, +0 against -0).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "core/geodesy.hpp"
#include "world/random.hpp"

using namespace npsnet;
using namespace npsnet::geo;

namespace {
using world::Rng;  // splitmix64, header only

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }
bool same_bits(const Geodetic& a, const Geodetic& b) {
  return std::memcmp(&a.lat_deg, &b.lat_deg, 8) == 0 && std::memcmp(&a.lon_deg, &b.lon_deg, 8) == 0 &&
         std::memcmp(&a.h_m, &b.h_m, 8) == 0;
}

// Every point of `run` through one memo, in order, against the plain frame, bit for bit.
void expect_same_as_frame(const LocalFrame& f, FrameMemo& m, const std::vector<Vec3>& run, double h, double p,
                          double r) {
  for (const Vec3& q : run) {
    const Geodetic g = f.to_geodetic(q), gm = m.to_geodetic(q);
    ASSERT_TRUE(same_bits(g, gm)) << q.transpose();
    ASSERT_TRUE(same_bits(f.to_ecef(q), m.to_ecef(q))) << q.transpose();
    ASSERT_TRUE(same_bits(geodetic_to_ecef(g), m.geodetic_to_ecef(g))) << q.transpose();
    ASSERT_TRUE(same_bits(f.to_dis_euler(g, h, p, r), m.to_dis_euler(g, h, p, r))) << q.transpose();
    const Mat3 j = f.jacobian(g), jm = m.jacobian(g);
    ASSERT_EQ(std::memcmp(j.data(), jm.data(), sizeof(double) * 9), 0) << q.transpose();
  }
}
}  // namespace

TEST(FrameMemo, KeptTermsGiveTheBitsOfTheFrame) {
  const LocalFrame f({35.98, -121.25, 0}, 50000, 50000);
  Rng rng(13);
  int inverses = 0, terms = 0, points = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 p(rng.uniform(0, 50000), rng.uniform(0, 50000), rng.uniform(0, 1500));
    const double h = rng.uniform(0, 360), pi = rng.uniform(-30, 30), ro = rng.uniform(-30, 30);
    // Parked (zero velocity), driving, or along an axis: velocity sharing one of p's coordinates.
    const int kind = i % 4;
    const Vec3 v = kind == 0   ? Vec3::Zero()
                   : kind == 1 ? Vec3(rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-2, 2))
                   : kind == 2 ? Vec3(rng.uniform(-20, 20), 0, 0)
                               : Vec3(0, rng.uniform(-20, 20), 0);
    FrameMemo m(f);
    const std::vector<Vec3> run = {p, p + v, p + Vec3::UnitZ(), p + Vec3::UnitX(), p + Vec3::UnitY()};
    expect_same_as_frame(f, m, run, h, pi, ro);
    inverses += m.inverses_computed(), terms += m.terms_computed(), points += static_cast<int>(run.size());
  }
  // The memo is used: p + z is p's inverse; p + x and p + y take one coordinate's terms from p.
  EXPECT_LT(inverses, points * 4 / 5);
  EXPECT_LT(terms, 2 * inverses);
}

TEST(FrameMemo, PointsSharingOneCoordinateOrASignedZero) {
  const LocalFrame f({35.98, -121.25, 0}, 50000, 50000);
  Rng rng(14);
  // One memo over a long run: points that share x, or y, with one of the last few, points whose
  // latitude matches an earlier one but not their longitude, signed zeros, repeats.
  FrameMemo m(f);
  std::vector<Vec3> run;
  Vec3 q(rng.uniform(0, 50000), rng.uniform(0, 50000), 10);
  for (int i = 0; i < 20000; ++i) {
    switch (rng.next() % 6) {
      case 0: q.x() = rng.uniform(0, 50000); break;                         // same northing
      case 1: q.y() = rng.uniform(0, 50000); break;                         // same easting
      case 2: q.z() = rng.uniform(0, 1000); break;                          // same inverse
      case 3: q = Vec3(rng.uniform(0, 50000), rng.uniform(0, 50000), 0); break;
      case 4: q.x() = (rng.next() & 1) ? 0.0 : -0.0; break;                 // +0 / -0
      default: if (!run.empty()) q = run[run.size() - 1 - rng.next() % std::min<size_t>(run.size(), 4)];
    }
    run.push_back(q);
  }
  expect_same_as_frame(f, m, run, 45, 3, -2);
  EXPECT_LT(m.inverses_computed(), static_cast<int>(run.size()));
}
