// WGS84 geodesy: exact published points, round trips, transverse Mercator, DIS Euler angles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/geodesy.hpp"

using namespace npsnet;
using namespace npsnet::geo;

namespace {
// Small deterministic generator for test points (splitmix64).
struct Rng {
  uint64_t s;
  uint64_t next() {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * ((next() >> 11) * 0x1.0p-53); }
};

double ecef_distance(const Geodetic& a, const Geodetic& b) {
  return (geodetic_to_ecef(a) - geodetic_to_ecef(b)).norm();
}
}  // namespace

TEST(Geodesy, PublishedExactPoints) {
  const Vec3 p0 = geodetic_to_ecef({0, 0, 0});
  EXPECT_NEAR(p0.x(), 6378137.0, 1e-9);
  EXPECT_NEAR(p0.y(), 0.0, 1e-9);
  EXPECT_NEAR(p0.z(), 0.0, 1e-9);
  const Vec3 np = geodetic_to_ecef({90, 0, 0});
  EXPECT_NEAR(np.x(), 0.0, 1e-6);
  EXPECT_NEAR(np.y(), 0.0, 1e-6);
  EXPECT_NEAR(np.z(), 6356752.314245, 1e-6);  // b of WGS84 (NIMA TR8350.2)
  const Vec3 p90 = geodetic_to_ecef({0, 90, 0});
  EXPECT_NEAR(p90.x(), 0.0, 1e-6);
  EXPECT_NEAR(p90.y(), 6378137.0, 1e-9);
  EXPECT_NEAR(p90.z(), 0.0, 1e-9);
  const Vec3 sp = geodetic_to_ecef({-90, 0, 100});
  EXPECT_NEAR(sp.z(), -6356852.314245, 1e-6);

  const Geodetic g0 = ecef_to_geodetic({6378137.0, 0, 0});
  EXPECT_NEAR(g0.lat_deg, 0, 1e-12);
  EXPECT_NEAR(g0.lon_deg, 0, 1e-12);
  EXPECT_NEAR(g0.h_m, 0, 1e-6);
  const Geodetic gp = ecef_to_geodetic({0, 0, 6356752.314245 + 1000});
  EXPECT_NEAR(gp.lat_deg, 90, 1e-12);
  EXPECT_NEAR(gp.h_m, 1000, 1e-6);
  const Geodetic gs = ecef_to_geodetic({0, 0, -6356752.314245});
  EXPECT_NEAR(gs.lat_deg, -90, 1e-12);
  EXPECT_NEAR(gs.h_m, 0, 1e-6);
}

TEST(Geodesy, EcefRoundTripEverywhere) {
  Rng rng{1};
  double worst = 0;
  for (int i = 0; i < 20000; ++i) {
    Geodetic g;
    // A third of the points within 1 degree of a pole.
    if (i % 3 == 0) {
      g.lat_deg = rng.uniform(89.0, 90.0) * (i % 2 ? 1 : -1);
    } else {
      g.lat_deg = rng.uniform(-90, 90);
    }
    g.lon_deg = rng.uniform(-180, 180);
    g.h_m = (i % 5 == 0) ? rng.uniform(1e5, 4e7) : rng.uniform(-500, 20000);
    const Geodetic back = ecef_to_geodetic(geodetic_to_ecef(g));
    const double d = ecef_distance(g, back);
    worst = std::max(worst, d);
    ASSERT_LT(d, 1e-3) << g.lat_deg << " " << g.lon_deg << " " << g.h_m;
    ASSERT_NEAR(back.h_m, g.h_m, 1e-3);
  }
  EXPECT_LT(worst, 1e-6);  // the iteration reaches machine precision, far below 0.1 mm
}

TEST(Geodesy, EnuAxes) {
  const Geodetic o{35.98, -121.25, 100};
  const Mat3 r = enu_rotation(o.lat_deg, o.lon_deg);
  EXPECT_NEAR((r * r.transpose() - Mat3::Identity()).norm(), 0, 1e-14);
  // Up is along the ellipsoid normal: a point 10 m higher is (0, 0, 10) in ENU.
  const Vec3 up = ecef_to_enu(geodetic_to_ecef({o.lat_deg, o.lon_deg, o.h_m + 10}), o);
  EXPECT_NEAR(up.x(), 0, 1e-6);
  EXPECT_NEAR(up.y(), 0, 1e-6);
  EXPECT_NEAR(up.z(), 10, 1e-6);
  // A point slightly north has positive north and ~zero east.
  const Vec3 n = ecef_to_enu(geodetic_to_ecef({o.lat_deg + 1e-4, o.lon_deg, o.h_m}), o);
  EXPECT_GT(n.y(), 11.0);
  EXPECT_NEAR(n.x(), 0, 1e-6);
  const Vec3 e = ecef_to_enu(geodetic_to_ecef({o.lat_deg, o.lon_deg + 1e-4, o.h_m}), o);
  EXPECT_GT(e.x(), 9.0);
  EXPECT_NEAR(e.y(), 0, 1e-3);
  const Vec3 v(12.5, -40.25, 7.0);
  EXPECT_LT((ecef_to_enu(enu_to_ecef(v, o), o) - v).norm(), 1e-8);
}

TEST(Geodesy, TransverseMercatorRoundTrip50km) {
  const TransverseMercator tm(35.98, -121.25, 25000.0, 25000.0);
  const Vec2 c = tm.forward(35.98, -121.25);
  EXPECT_NEAR(c.x(), 25000.0, 1e-9);
  EXPECT_NEAR(c.y(), 25000.0, 1e-9);
  Rng rng{2};
  for (int i = 0; i < 5000; ++i) {
    const double x = rng.uniform(-25000, 75000), y = rng.uniform(-25000, 75000);
    const Geodetic g = tm.inverse(x, y);
    const Vec2 back = tm.forward(g.lat_deg, g.lon_deg);
    ASSERT_LT((back - Vec2(x, y)).norm(), 1e-3) << x << " " << y;
  }
  // Geodetic -> TM -> geodetic, measured on the ground.
  for (int i = 0; i < 5000; ++i) {
    const Geodetic g{rng.uniform(35.5, 36.5), rng.uniform(-121.8, -120.7), 0};
    const Vec2 xy = tm.forward(g.lat_deg, g.lon_deg);
    const Geodetic back = tm.inverse(xy.x(), xy.y());
    ASSERT_LT(ecef_distance(g, back), 1e-3);
  }
}

// The series' terms come from those of the first order by the angle-sum formulas (geodesy.cpp,
// xi_series / eta_series): they keep the projection's nanometres, far from the meridian too.
TEST(Geodesy, TransverseMercatorRoundTripWithinNanometres) {
  Rng rng{21};
  double worst = 0;
  for (double lat0 : {-60.0, 0.0, 35.98, 70.0}) {
    const TransverseMercator tm(lat0, 10.0, 500000.0, 0.0);
    for (int i = 0; i < 2000; ++i) {
      const Geodetic g{std::clamp(lat0 + rng.uniform(-5, 5), -84.0, 84.0), 10.0 + rng.uniform(-3, 3), 0};
      const Vec2 xy = tm.forward(g.lat_deg, g.lon_deg);
      const double d = ecef_distance(g, tm.inverse(xy.x(), xy.y()));
      worst = std::max(worst, d);
      ASSERT_LT(d, 1e-8) << g.lat_deg << " " << g.lon_deg;
    }
  }
  RecordProperty("worst_nm", std::to_string(worst * 1e9));
}

TEST(Geodesy, TransverseMercatorScaleOnCentralMeridian) {
  // k0 = 1: along the central meridian, TM northing differences equal meridian arc lengths,
  // which for 1 arc-minute near 36 N is ~1849.6 m; a short step east has scale ~1.
  const TransverseMercator tm(0, -121.25);
  const Vec2 a = tm.forward(36.0, -121.25), b = tm.forward(36.0 + 1e-5, -121.25);
  const double dist = ecef_distance({36.0, -121.25, 0}, {36.0 + 1e-5, -121.25, 0});
  EXPECT_NEAR((b - a).norm() / dist, 1.0, 1e-7);
  EXPECT_NEAR(a.x(), 0.0, 1e-9);
}

TEST(Geodesy, LocalFrameCornersAndCentre) {
  const Geodetic sw{35.98, -121.25, 0};
  const LocalFrame f(sw, 50000, 40000);
  const Vec3 o = f.to_local(sw);
  EXPECT_NEAR(o.x(), 0, 1e-6);
  EXPECT_NEAR(o.y(), 0, 1e-6);
  const Geodetic back = f.to_geodetic({0, 0, 12});
  EXPECT_NEAR(back.lat_deg, sw.lat_deg, 1e-11);
  EXPECT_NEAR(back.lon_deg, sw.lon_deg, 1e-11);
  EXPECT_DOUBLE_EQ(back.h_m, 12);
  // The TM is centred on the terrain: its origin (lat0, lon0) is the local centre.
  const Geodetic c{f.projection().lat0(), f.projection().lon0(), 0};
  const Vec3 cl = f.to_local(c);
  EXPECT_NEAR(cl.x(), 25000, 1e-6);
  EXPECT_NEAR(cl.y(), 20000, 1e-6);
  // The frame is metric: 50 km east along the south edge is ~50 km on the ellipsoid.
  const double d = ecef_distance(f.to_geodetic({0, 0, 0}), f.to_geodetic({50000, 0, 0}));
  EXPECT_NEAR(d, 50000, 2.0);  // chord vs arc and scale <= 1.00002 at 25 km off the meridian
  // Round trip of local points.
  Rng rng{3};
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p(rng.uniform(-1000, 51000), rng.uniform(-1000, 41000), rng.uniform(-100, 3000));
    ASSERT_LT((f.from_ecef(f.to_ecef(p)) - p).norm(), 1e-3);
  }
}

TEST(Geodesy, ConvergenceMatchesGridNorth) {
  const LocalFrame f({35.98, -121.25, 0}, 50000, 50000);
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(50000, 50000, 0), Vec3(25000, 25000, 0),
                       Vec3(3000, 47000, 0)}) {
    // Azimuth of a 1 m step along local +y, measured in ENU at p.
    const Geodetic g = f.to_geodetic(p);
    const Vec3 step = ecef_to_enu(f.to_ecef(p + Vec3(0, 1, 0)), g) -
                      ecef_to_enu(f.to_ecef(p - Vec3(0, 1, 0)), g);
    const double az = rad2deg(std::atan2(step.x(), step.y()));
    EXPECT_NEAR(f.convergence_deg(g), az, 1e-6) << p.transpose();
  }
  // West of the central meridian in the northern hemisphere, grid north is west of true north.
  EXPECT_LT(f.convergence_deg(f.to_geodetic({0, 25000, 0})), -0.1);
  EXPECT_GT(f.convergence_deg(f.to_geodetic({50000, 25000, 0})), 0.1);
}

// LocalFrame::jacobian (from the convergence and the TM point scale) is the derivative of
// to_ecef: central differences over +-1 m agree to rounding (their own error, the third
// derivative, is ~1e-14 m per m), over the map, at heights to 3 km and off the map's edges.
// A wrong sign of the convergence or the scale's series would be off by ~1e-3 (the convergence
// reaches 0.15 deg at the map's edges, the scale 1 + 8e-6).
TEST(Geodesy, JacobianIsTheDerivativeOfToEcef) {
  const LocalFrame f({35.98, -121.25, 0}, 50000, 50000);
  Rng rng{21};
  double worst = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 p(rng.uniform(-5000, 55000), rng.uniform(-5000, 55000), rng.uniform(-100, 3000));
    const Mat3 j = f.jacobian(f.to_geodetic(p));
    for (int c = 0; c < 3; ++c) {
      const Vec3 d = (f.to_ecef(p + Vec3::Unit(c)) - f.to_ecef(p - Vec3::Unit(c))) / 2;
      worst = std::max(worst, (j.col(c) - d).norm());
      ASSERT_LT((j.col(c) - d).norm(), 1e-8) << "column " << c << " at " << p.transpose();
    }
    // On the ellipsoid (h = 0) columns x and y are at right angles and alike long (1 / k: the
    // projection is conformal); above it the north and east radii grow apart. z: a unit normal.
    const Mat3 j0 = f.jacobian(f.to_geodetic(Vec3(p.x(), p.y(), 0)));
    EXPECT_LT(std::abs(j0.col(0).dot(j0.col(1))), 1e-13);
    EXPECT_NEAR(j0.col(0).norm(), j0.col(1).norm(), 1e-13);
    EXPECT_NEAR(j.col(2).norm(), 1.0, 1e-15);
  }
  std::printf("worst |J - central difference| %.3g m per m\n", worst);
  // On the central meridian at the ellipsoid the scale is 1.
  const Geodetic c{f.projection().lat0(), f.projection().lon0(), 0};
  const Mat3 jc = f.jacobian(c);
  EXPECT_NEAR(jc.col(0).norm(), 1.0, 1e-12);
  EXPECT_NEAR(jc.col(1).norm(), 1.0, 1e-12);
}

TEST(Geodesy, DisEulerRoundTrip) {
  const LocalFrame f({35.98, -121.25, 0}, 50000, 50000);
  Rng rng{4};
  for (int i = 0; i < 5000; ++i) {
    const Vec3 pos(rng.uniform(0, 50000), rng.uniform(0, 50000), rng.uniform(0, 3000));
    const double h = rng.uniform(0, 360), p = rng.uniform(-89, 89), r = rng.uniform(-179, 179);
    const Vec3 e = f.to_dis_euler(pos, h, p, r);
    const Vec3 back = f.from_dis_euler(pos, e);
    ASSERT_NEAR(std::remainder(back.x() - h, 360.0), 0, 1e-8) << h << " " << p << " " << r;
    ASSERT_NEAR(back.y(), p, 1e-8);
    ASSERT_NEAR(back.z(), r, 1e-8);
  }
}

namespace {
// Body axes of DIS Euler angles in ECEF: columns x (forward), y (right), z (down).
Mat3 dis_body_axes(const Vec3& e) {
  return (Eigen::AngleAxisd(e.x(), Vec3::UnitZ()) * Eigen::AngleAxisd(e.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(e.z(), Vec3::UnitX()))
      .toRotationMatrix();
}
}  // namespace

TEST(Geodesy, LevelVehicleHeadingNorthPointsNorth) {
  const LocalFrame f({35.98, -121.25, 0}, 50000, 50000);
  // At the centre (on the central meridian) grid north is true north.
  const Vec3 c(25000, 25000, 300);
  const Geodetic g = f.to_geodetic(c);
  const Mat3 enu = enu_rotation(g.lat_deg, g.lon_deg);
  const Mat3 axes = enu * dis_body_axes(f.to_dis_euler(c, 0, 0, 0));
  EXPECT_LT((axes.col(0) - Vec3(0, 1, 0)).norm(), 1e-9);  // forward = north
  EXPECT_LT((axes.col(1) - Vec3(1, 0, 0)).norm(), 1e-9);  // right = east
  EXPECT_LT((axes.col(2) - Vec3(0, 0, -1)).norm(), 1e-9); // down = -up
  // Heading east, pitched 10 deg nose up, rolled 20 deg right wing down.
  const Mat3 a2 = enu * dis_body_axes(f.to_dis_euler(c, 90, 10, 20));
  const double p = deg2rad(10), r = deg2rad(20);
  EXPECT_LT((a2.col(0) - Vec3(std::cos(p), 0, std::sin(p))).norm(), 1e-9);
  EXPECT_NEAR(a2.col(1).z(), -std::sin(r) * std::cos(p), 1e-9);  // right wing goes down
  // Off the central meridian, heading 0 follows local +y (grid north), not true north.
  const Vec3 w(1000, 45000, 0);
  const Geodetic gw = f.to_geodetic(w);
  const Vec3 grid_north = (ecef_to_enu(f.to_ecef(w + Vec3(0, 1, 0)), gw) -
                           ecef_to_enu(f.to_ecef(w - Vec3(0, 1, 0)), gw))
                              .normalized();
  const Mat3 aw = enu_rotation(gw.lat_deg, gw.lon_deg) * dis_body_axes(f.to_dis_euler(w, 0, 0, 0));
  EXPECT_LT((aw.col(0) - grid_north).norm(), 1e-8);
  EXPECT_GT(std::abs(grid_north.x()), 1e-3);  // and that differs from true north here
}
