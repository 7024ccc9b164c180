// geo::FrameMemo: LocalFrame's to_geodetic, to_ecef, to_dis_euler and jacobian through the kept
// series terms, inverses, sines and convergences give the bits of the plain functions, for runs of
// points that share coordinates (p, p + v, p + z, p + x, p + y) and runs that share only some of
// them (one coordinate, a latitude but not a longitude, +0 against -0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
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

TEST(FrameMemo, InverseGivesTheForwardConvergenceAndScale) {
  // The Grid forms (the exact dead-reckoning test's): the convergence and scale from the inverse's
  // own series against the forward projection's (LocalFrame), on the default world's 50 km frame
  // and on one 600 km wide (300 km off its meridian), and the DIS angles and Jacobian made from
  // them. The inverse's latitude and longitude are the plain frame's bits either way.
  Rng rng(29);
  for (const double size : {50000.0, 600000.0}) {
    const LocalFrame f({35.98, -121.25, 0}, size, size);
    double worst_gamma = 0, worst_k = 0, worst_euler = 0, worst_jac = 0;
    for (int i = 0; i < 20000; ++i) {
      const Vec3 p(rng.uniform(0, size), rng.uniform(0, size), rng.uniform(0, 1500));
      FrameMemo m(f);
      FrameMemo::Grid grid;
      const Geodetic g = m.to_geodetic(p, grid);
      ASSERT_TRUE(same_bits(g, f.to_geodetic(p))) << p.transpose();
      worst_gamma = std::max(worst_gamma, std::abs(grid.gamma - deg2rad(f.convergence_deg(g))));
      const Mat3 j = f.jacobian(g), jg = m.jacobian(g, grid);
      // the scale: |local +y| in ECEF is 1 / k at height 0 (a grid metre is 1 / k ellipsoid metres)
      const Geodetic g0{g.lat_deg, g.lon_deg, 0};
      const double k_fwd = 1.0 / f.jacobian(g0).col(1).norm(), k_inv = 1.0 / m.jacobian(g0, grid).col(1).norm();
      worst_k = std::max(worst_k, std::abs(k_inv - k_fwd));
      worst_jac = std::max(worst_jac, (jg - j).cwiseAbs().maxCoeff());
      const double h = rng.uniform(0, 360), pi = rng.uniform(-30, 30), ro = rng.uniform(-30, 30);
      const Vec3 e = f.to_dis_euler(g, h, pi, ro), eg = m.to_dis_euler(g, grid, h, pi, ro);
      for (int c = 0; c < 3; ++c) worst_euler = std::max(worst_euler, std::abs(std::remainder(eg[c] - e[c], 2 * kPi)));
    }
    EXPECT_LT(worst_gamma, 2e-15) << size;  // rad
    EXPECT_LT(worst_k, 2e-15) << size;
    EXPECT_LT(worst_jac, 4e-15) << size;
    EXPECT_LT(worst_euler, 2e-14) << size;  // rad: the angles themselves round to a few 1e-16
    std::printf("frame %.0f km: worst convergence %.2e rad, scale %.2e, Jacobian %.2e, DIS angles %.2e rad\n",
                size / 1000, worst_gamma, worst_k, worst_jac, worst_euler);
  }
}
