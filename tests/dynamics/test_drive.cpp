// Driving a vehicle by its controls, per domain: acceleration, braking, reverse, turn radius,
// speed limits (Table 2), terrain following, shores, climb and dive, fuel, crashes into the ground.
#include <gtest/gtest.h>

#include "dynamics/drive.hpp"
#include "dynamics/dynamics.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

namespace {
constexpr double kDt = 0.1;

struct Driven {
  world::World w = test::flat_world();
  int e = -1;
  std::vector<dynamics::Crash> crashes;
  Driven(const std::string& kind, double x, double y, double heading, double z = -1) {
    e = test::add_vehicle(w, "v", kind, x, y, heading, 0);
    if (z >= 0) w.ents.pos[e].z() = z;
    w.ents.fuel_l[e] = static_cast<float>(w.kinds[w.ents.kind[e]].fuel_l);
    w.ents.driven[e] = 1;
  }
  void run(const dynamics::Controls& c, double seconds) {
    for (int i = 0; i < static_cast<int>(std::lround(seconds / kDt)); ++i) dynamics::drive(w, e, c, kDt, crashes);
  }
  double speed() const { return w.ents.vel[e].head<2>().norm(); }
  const world::Kind& kind() const { return w.kinds[w.ents.kind[e]]; }
};
}  // namespace

TEST(DriveGround, AcceleratesAtItsRateUpToTheTable2Limit) {
  Driven d("m1a1", 200, 1000, 90);
  d.run({1, 0, 0}, 2.0);
  EXPECT_NEAR(d.speed(), d.kind().accel_mps2 * 2.0, 1e-6);  // 1.3 m/s^2 for 2 s
  EXPECT_GT(d.w.ents.pos[d.e].x(), 200.0);
  EXPECT_NEAR(d.w.ents.pos[d.e].y(), 1000.0, 1e-6);
  d.run({1, 0, 0}, 60.0);
  EXPECT_NEAR(d.speed(), kmh2mps(thesis::kTable2GroundKmh), 1e-6);  // never above 60 km/h
  d.w.ents.max_mps[d.e] = static_cast<float>(kmh2mps(30));          // a scenario override holds too
  d.run({1, 0, 0}, 1.0);
  EXPECT_LE(d.speed(), kmh2mps(30) + 1e-6);
}

TEST(DriveGround, BrakesToAStopThenReverses) {
  Driven d("m1a1", 1000, 1000, 90);
  d.w.ents.vel[d.e] = Vec3(10, 0, 0);
  d.run({-1, 0, 0}, 1.0);
  EXPECT_NEAR(d.w.ents.vel[d.e].x(), 10 - d.kind().brake_mps2 * 1.0, 1e-6);  // brakes at 4 m/s^2
  d.run({-1, 0, 0}, 1.5);
  EXPECT_NEAR(d.w.ents.vel[d.e].x(), 0.0, 1e-9);  // stopped (it does not overshoot into reverse)
  d.run({-1, 0, 0}, 30.0);
  EXPECT_NEAR(d.w.ents.vel[d.e].x(), -dynamics::kReverseFraction * kmh2mps(60), 1e-6);  // reverse limit
  EXPECT_NEAR(d.w.ents.heading_deg[d.e], 90.0, 1e-6);  // backing up, still facing east
}

TEST(DriveGround, CoastsToAStopWithoutThrottle) {
  Driven d("hmmwv", 1000, 1000, 0);
  d.w.ents.vel[d.e] = Vec3(0, 6, 0);
  d.run({0, 0, 0}, 5.0);
  EXPECT_NEAR(d.speed(), 6 - dynamics::kCoastMps2 * 5, 1e-6);
  d.run({0, 0, 0}, 10.0);
  EXPECT_EQ(d.speed(), 0.0);
}

TEST(DriveGround, FullSteerTurnsOnItsTurnRadius) {
  // At 5 m/s with full right steer the m1a1 (radius 8 m) turns 5/8 rad/s: a circle of 8 m.
  Driven d("m1a1", 1000, 1000, 0);
  const double v = 5.0, r = d.kind().turn_radius_m;
  d.w.ents.vel[d.e] = Vec3(0, v, 0);
  d.w.kinds = d.w.kinds;  // (handling from models/kinds.toml)
  d.w.ents.max_mps[d.e] = static_cast<float>(v);  // hold the speed at v
  double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
  const double period = 2 * kPi * r / v;
  for (int i = 0; i < static_cast<int>(period / kDt); ++i) {
    d.run({1, 1, 0}, kDt);
    const Vec3& p = d.w.ents.pos[d.e];
    min_x = std::min(min_x, p.x()), max_x = std::max(max_x, p.x());
    min_y = std::min(min_y, p.y()), max_y = std::max(max_y, p.y());
  }
  EXPECT_NEAR(max_x - min_x, 2 * r, 0.3);  // the circle's diameter
  EXPECT_NEAR(max_y - min_y, 2 * r, 0.3);
  EXPECT_GT(min_x, 999.0);  // turning right (east) of the start
  EXPECT_LT(std::abs(wrap360(d.w.ents.heading_deg[d.e] + 180) - 180), 10.0);  // about once around
}

TEST(DriveGround, FollowsTheTerrainAndStopsAtTheShore) {
  auto w = test::flat_world(100.0, 0.1);  // rising 0.1 m per m eastward
  Driven d("m1a1", 500, 1000, 90);
  d.w = std::move(w);
  d.e = test::add_vehicle(d.w, "v", "m1a1", 500, 1000, 90, 0);
  d.w.ents.driven[d.e] = 1;
  d.run({1, 0, 0}, 5.0);
  EXPECT_NEAR(d.w.ents.pos[d.e].z(), d.w.terrain.height(d.w.ents.pos[d.e].x(), 1000), 0.05);
  EXPECT_NEAR(d.w.ents.pitch_deg[d.e], rad2deg(std::atan(0.1)), 0.05);
  d.w.water_level_m = d.w.terrain.height(d.w.ents.pos[d.e].x() - 3, 1000);  // a lake from 3 m behind it
  d.w.ents.heading_deg[d.e] = 270;
  d.w.ents.vel[d.e] = Vec3(-5, 0, 0);
  const double x0 = d.w.ents.pos[d.e].x();
  d.run({1, 0, 0}, 3.0);
  EXPECT_GE(d.w.ents.pos[d.e].x(), x0 - 5.0);  // it did not drive into the lake
  EXPECT_FALSE(d.w.is_water(d.w.ents.pos[d.e].x(), 1000));
}

TEST(DriveShip, StaysOnTheWaterAtItsLimit) {
  Driven d("patrol_ship", 100, 1000, 90);
  d.w.water_level_m = 200;  // the whole flat world (height 100) is lake
  d.run({1, 0, 0}, 60.0);
  EXPECT_NEAR(d.speed(), kmh2mps(thesis::kTable2ShipKmh), 1e-6);
  EXPECT_NEAR(d.w.ents.pos[d.e].z(), 200.0, 1e-9);
  d.w.water_level_m = -1000;  // now dry land all round: it cannot move
  const Vec3 p = d.w.ents.pos[d.e];
  d.run({1, 0.5, 0}, 2.0);
  EXPECT_NEAR((d.w.ents.pos[d.e] - p).head<2>().norm(), 0.0, 1e-9);
}

TEST(DriveAir, ClimbsDivesAndBanks) {
  Driven d("ah64", 1000, 200, 0, 300.0);
  d.run({1, 0, 1}, 5.0);
  const double climb = d.kind().climb_mps;
  EXPECT_NEAR(d.w.ents.pos[d.e].z(), 300.0 + climb * 5.0, 1e-6);
  EXPECT_GT(d.w.ents.pitch_deg[d.e], 0.0);
  d.run({0, 0, -1}, 2.0);
  EXPECT_NEAR(d.w.ents.pos[d.e].z(), 300.0 + climb * 3.0, 1e-6);
  EXPECT_LT(d.w.ents.pitch_deg[d.e], 0.0);
  const double h0 = d.w.ents.heading_deg[d.e];
  d.run({0, 1, 0}, 1.0);
  EXPECT_NEAR(d.w.ents.roll_deg[d.e], dynamics::kMaxBankDeg, 1e-6);  // banked right
  EXPECT_GT(wrap360(d.w.ents.heading_deg[d.e] - h0), 1.0);            // and turning right
  d.run({1, 0, 0}, 25.0);
  EXPECT_NEAR(d.w.ents.vel[d.e].norm(), kmh2mps(d.kind().max_speed_kmh), 1e-3);  // its limit (290 km/h)
}

TEST(DriveAir, DivingIntoTheGroundIsACrashRestingIsNot) {
  Driven d("ah64", 1000, 200, 0, 150.0);
  d.w.ents.vel[d.e] = Vec3(0, 50, 0);
  d.run({0, 0, -1}, 3.0);
  EXPECT_TRUE(d.crashes.empty());
  d.run({0, 0, -1}, 10.0);
  ASSERT_EQ(d.crashes.size(), 1u);  // one contact: afterwards it rests on the ground
  EXPECT_NEAR(d.crashes[0].point.z(), 100.0, 1e-6);
  EXPECT_GT(d.crashes[0].speed_mps, thesis::kQuickSpeedMps);
  EXPECT_NEAR(d.w.ents.pos[d.e].z(), 100.0, 1e-6);
}

TEST(DriveFuel, BurnsWithSpeedAndAnEmptyTankStops) {
  Driven d("hmmwv", 200, 1000, 90);
  const double full = d.w.ents.fuel_l[d.e];
  d.run({0, 0, 0}, 10.0);
  EXPECT_EQ(d.w.ents.fuel_l[d.e], full);  // standing still burns nothing
  d.w.ents.vel[d.e] = Vec3(kmh2mps(60), 0, 0);
  d.run({1, 0, 0}, 36.0);  // at the limit: fuel_lph x 36 s / 3600 s
  EXPECT_NEAR(full - d.w.ents.fuel_l[d.e], d.kind().fuel_lph * 0.01, 1e-3);
  d.w.ents.fuel_l[d.e] = 0.001f;
  d.run({1, 0, 0}, 30.0);
  EXPECT_EQ(d.w.ents.fuel_l[d.e], 0.0f);
  EXPECT_EQ(d.speed(), 0.0);  // empty: it coasted to a stop and full throttle does nothing
}

TEST(DriveFuel, AWaypointVehicleStopsWhenDry) {
  Driven d("hmmwv", 200, 1000, 90);
  d.w.ents.driven[d.e] = 0;
  d.w.ents.cruise_mps[d.e] = 10;
  d.w.ents.max_mps[d.e] = 20;
  d.w.ents.fuel_l[d.e] = 0;
  std::vector<dynamics::GroundImpact> imp;
  dynamics::step(d.w, kDt, imp);
  EXPECT_EQ(d.speed(), 0.0);
}

TEST(DriveAim, PointsAtTheVehicleAheadElseTheGround) {
  Driven d("m1a1", 500, 1000, 90);
  const int t = test::add_vehicle(d.w, "target", "bmp", 1200, 1010, 0, 0);  // 0.8 deg off the nose
  test::add_vehicle(d.w, "side", "bmp", 600, 1200, 0, 0);                   // far off the nose
  auto a = dynamics::aim_from(d.w, d.e);
  EXPECT_EQ(a.target, t);
  d.w.ents.heading_deg[d.e] = 270;  // nothing that way: the ground 3 km out (flat: never met)
  a = dynamics::aim_from(d.w, d.e);
  EXPECT_EQ(a.target, -1);
  EXPECT_NEAR(a.point.z(), 100.0, 1e-6);
  EXPECT_LT(a.point.x(), 500.0);
}
