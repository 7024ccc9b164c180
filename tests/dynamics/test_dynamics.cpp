// Dynamics: speed limits, waypoints, terrain following, ballistic and guided munitions, dt range.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <random>
#include <string>

#include "dynamics/autonomous.hpp"
#include "dynamics/dynamics.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

TEST(TerrainFollowing, PitchOnASlope) {
  // Terrain rising 0.2 m per m eastward: a tank heading east pitches nose-up atan(0.2), no roll;
  // heading north it rolls (right side, east, up: negative roll) and does not pitch.
  auto w = test::flat_world(100.0, 0.2);
  const int e = test::add_vehicle(w, "t", "m1a1", 1000, 1000, 90, 0);
  dynamics::follow_terrain(w, e);
  EXPECT_NEAR(w.ents.pitch_deg[e], rad2deg(std::atan(0.2)), 0.01);
  EXPECT_NEAR(w.ents.roll_deg[e], 0.0, 0.01);
  EXPECT_NEAR(w.ents.pos[e].z(), w.terrain.height(1000, 1000), 0.01);
  w.ents.heading_deg[e] = 0;
  dynamics::follow_terrain(w, e);
  EXPECT_NEAR(w.ents.pitch_deg[e], 0.0, 0.01);
  EXPECT_NEAR(w.ents.roll_deg[e], -rad2deg(std::atan(0.2)), 0.01);
}

TEST(TerrainFollowing, FeelsACrater) {
  auto w = test::flat_world();
  const int e = test::add_vehicle(w, "t", "m1a1", 1000, 1000, 90, 0);
  w.terrain.crater(1000, 1000, 8, 2);
  dynamics::follow_terrain(w, e);
  EXPECT_LT(w.ents.pos[e].z(), 100.0 - 0.5);
}

TEST(TerrainFollowing, SteppedTogetherEachVehicleGetsItsOwnPose) {
  // dynamics::step follows the terrain for a few vehicles at once, after their moves: each must
  // get the pose of its own terrain following (the bits of follow_terrain on its own), whatever
  // its place in the batch, with ships and aircraft between them. Rough ground: every post random.
  auto w = test::flat_world();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<float> h(static_cast<size_t>(w.terrain.cols()) * w.terrain.rows());
  for (float& v : h) v = static_cast<float>(100.0 + 8.0 * u(rng));
  w.terrain = world::Terrain(w.terrain.cols(), w.terrain.rows(), w.terrain.spacing_m(), std::move(h), w.terrain.origin());
  std::vector<int> ground;
  for (int i = 0; i < 37; ++i) {
    const char* kind = i % 11 == 5 ? "f16" : i % 13 == 7 ? "patrol_ship" : i % 2 ? "m1a1" : "hmmwv";
    const int e = test::add_vehicle(w, "v" + std::to_string(i), kind, 100 + 1800 * u(rng), 100 + 1800 * u(rng),
                                    360 * u(rng), 5 + 10 * u(rng));
    w.ents.cruise_mps[e] = w.ents.max_mps[e] = static_cast<float>(5 + 10 * u(rng));
    if (w.kinds[w.ents.kind[e]].mobility == world::Mobility::Ground) ground.push_back(e);
  }
  ASSERT_GT(ground.size(), 20u);
  std::vector<dynamics::GroundImpact> imp;
  for (int tick = 0; tick < 3; ++tick) {
    dynamics::step(w, 1.0 / 60, imp);
    for (int e : ground) {
      const double z = w.ents.pos[e].z();
      const float pitch = w.ents.pitch_deg[e], roll = w.ents.roll_deg[e];
      dynamics::follow_terrain(w, e);
      EXPECT_EQ(std::bit_cast<uint64_t>(z), std::bit_cast<uint64_t>(w.ents.pos[e].z())) << w.ents.id[e];
      EXPECT_EQ(std::bit_cast<uint32_t>(pitch), std::bit_cast<uint32_t>(w.ents.pitch_deg[e])) << w.ents.id[e];
      EXPECT_EQ(std::bit_cast<uint32_t>(roll), std::bit_cast<uint32_t>(w.ents.roll_deg[e])) << w.ents.id[e];
    }
  }
}

TEST(Vehicles, SpeedNeverAboveTheLimit) {
  auto w = test::flat_world();
  const int e = test::add_vehicle(w, "t", "m1a1", 200, 1000, 90, 0);
  w.ents.cruise_mps[e] = 100;  // asks for 360 km/h
  w.ents.max_mps[e] = static_cast<float>(kmh2mps(thesis::kTable2GroundKmh));
  std::vector<dynamics::GroundImpact> imp;
  for (int i = 0; i < 10; ++i) dynamics::step(w, 0.1, imp);
  EXPECT_NEAR(w.ents.pos[e].x() - 200, kmh2mps(thesis::kTable2GroundKmh) * 1.0, 1e-6);
  EXPECT_LE(w.ents.vel[e].norm(), kmh2mps(thesis::kTable2GroundKmh) + 1e-9);
}

TEST(Vehicles, SteersToWaypointsForAnyDt) {
  for (double dt : {0.01, 0.1, 0.5, 1.0}) {
    auto w = test::flat_world();
    const int e = test::add_vehicle(w, "t", "hmmwv", 500, 500, 90, 10);
    w.ents.max_mps[e] = 20;
    w.ents.route[e] = {Vec2(1500, 500), Vec2(1500, 1500)};
    std::vector<dynamics::GroundImpact> imp;
    const int n = static_cast<int>(std::round(300.0 / dt));
    for (int i = 0; i < n; ++i) dynamics::step(w, dt, imp);
    EXPECT_NEAR(w.ents.pos[e].x(), 1500, 20) << "dt " << dt;
    EXPECT_GT(w.ents.pos[e].y(), 1400) << "dt " << dt;
  }
}

TEST(Vehicles, HoldTheirCourseWithinAHundredthOfADegreeAndCorrectBeyondIt) {
  // Heading 90 (east), the waypoint 1.8 km on (the map is 2 km), off the course by 0.005 and by
  // 0.02 degrees.
  for (double off_deg : {0.005, 0.02}) {
    auto w = test::flat_world();
    const int e = test::add_vehicle(w, "t", "hmmwv", 100, 500, 90, 10);
    const Vec2 wp(1900, 500 + 1800 * std::tan(deg2rad(off_deg)));
    w.ents.route[e] = {wp};
    std::vector<dynamics::GroundImpact> imp;
    core::HeadingMemo memo;
    dynamics::step(w, 1.0 / 60, imp, nullptr, &memo);
    if (off_deg < 0.01) EXPECT_EQ(w.ents.heading_deg[e], 90.0f) << "within the band the course is held";
    else EXPECT_LT(w.ents.heading_deg[e], 90.0f) << "beyond it the vehicle turns to the waypoint";
    // Either way the vehicle reaches its waypoint: the band's drift is corrected as it nears.
    for (int i = 0; i < 60 * 200 && w.ents.leg[e] == 0; ++i) dynamics::step(w, 1.0 / 60, imp, nullptr, &memo);
    EXPECT_EQ(w.ents.leg[e], 1) << off_deg;
    EXPECT_LT((Vec2(w.ents.pos[e].x(), w.ents.pos[e].y()) - wp).norm(), 15.5) << off_deg;
  }
}

TEST(Munitions, BallisticRoundMeetsTheTerrainAtTheTarget) {
  auto w = test::flat_world();
  const int s = test::add_vehicle(w, "s", "m1a1", 200, 1000, 90, 0);
  const int he = w.kinds.find("he_round");
  const Vec3 target(1700, 1000, w.terrain.height(1700, 1000));
  const int m = test::fire(w, s, he, target, -1);
  ASSERT_GE(m, 0);
  std::vector<dynamics::GroundImpact> imp;
  for (int i = 0; i < 200 && imp.empty(); ++i) dynamics::step(w, 0.1, imp);
  ASSERT_EQ(imp.size(), 1u);
  EXPECT_LT((imp[0].point - target).head<2>().norm(), 3.0);  // within a post of the aim point
  EXPECT_NEAR(imp[0].point.z(), w.terrain.height(imp[0].point.x(), imp[0].point.y()), 1e-3);
  EXPECT_FALSE(w.ents.active[m]);
  EXPECT_EQ(w.ents.rounds[s], w.kinds[w.ents.kind[s]].rounds - 1);
}

TEST(Munitions, MissileIsGuidedToAMovingTarget) {
  auto w = test::flat_world();
  const int h = test::add_vehicle(w, "h", "ah64", 200, 200, 90, 0);
  w.ents.pos[h].z() += 300;
  const int t = test::add_vehicle(w, "t", "m1a1", 1500, 1500, 0, 10);
  const int m = test::fire(w, h, w.kinds.find("missile"), w.ents.pos[t], t);
  std::vector<dynamics::GroundImpact> imp;
  double best = 1e9;
  for (int i = 0; i < 100; ++i) {
    dynamics::step(w, 0.1, imp);
    best = std::min(best, (w.ents.pos[m] - world::entity_centre(w, t)).norm());
  }
  EXPECT_TRUE(imp.empty());
  EXPECT_LT(best, world::entity_radius(w, t));
}

TEST(Autonomous, ReturnsFireOrFlees) {
  auto w = test::flat_world();
  const int shooter = test::add_vehicle(w, "s", "m1a1", 200, 200, 0, 0);
  const int a = test::add_vehicle(w, "a", "bmp", 800, 200, 0, 0);
  const int b = test::add_vehicle(w, "b", "hmmwv", 200, 800, 0, 0);  // no rounds
  w.ents.autonomous[a] = w.ents.autonomous[b] = 1;
  w.ents.max_mps[b] = 20;
  world::Changes c;
  world::EntityChange ch;
  EXPECT_EQ(dynamics::react_to_fire(w, a, shooter, ch), dynamics::Reaction::ReturnFire);
  c.entities.push_back(ch);
  EXPECT_EQ(dynamics::react_to_fire(w, b, shooter, ch), dynamics::Reaction::Flee);
  c.entities.push_back(ch);
  EXPECT_NEAR(ch.heading_deg, 0.0, 1e-3);  // directly away from the shooter (north)
  EXPECT_EQ(dynamics::react_to_fire(w, shooter, a, ch), dynamics::Reaction::None);  // not autonomous
  EXPECT_EQ(w.ents.calm_until[a], -1.0f);  // deciding changes nothing: apply does
  world::Applied applied;
  world::apply(w, c, applied);
  EXPECT_EQ(dynamics::react_to_fire(w, a, shooter, ch), dynamics::Reaction::None);  // calm for a while
  EXPECT_NEAR(w.ents.heading_deg[b], 0.0, 1e-3);
  std::vector<dynamics::GroundImpact> imp;
  for (int i = 0; i < 10; ++i) dynamics::step(w, 0.1, imp);
  EXPECT_GT(w.ents.pos[b].y(), 800 + 15);
}

TEST(Vehicles, ShipsStayOnWater) {
  // Terrain rising eastward: water (level 150) only where x < 500.
  auto w = test::flat_world(100.0, 0.1);
  w.water_level_m = 150.0;
  const int s = test::add_vehicle(w, "s", "patrol_ship", 300, 1000, 90, 10);
  w.ents.pos[s].z() = w.water_level_m;
  std::vector<dynamics::GroundImpact> imp;
  for (int i = 0; i < 2000; ++i) {
    dynamics::step(w, 0.1, imp);
    ASSERT_TRUE(w.is_water(w.ents.pos[s].x(), w.ents.pos[s].y())) << "tick " << i;
    ASSERT_DOUBLE_EQ(w.ents.pos[s].z(), w.water_level_m);
  }
}

TEST(Vehicles, AircraftHoldAltitudeAboveTerrain) {
  auto w = test::flat_world(100.0, 0.05);
  const int a = test::add_vehicle(w, "a", "f16", 100, 1000, 90, 200);
  w.ents.pos[a].z() = 300;
  std::vector<dynamics::GroundImpact> imp;
  for (int i = 0; i < 80; ++i) dynamics::step(w, 0.1, imp);  // 1.6 km east: ground rises 80 m
  EXPECT_DOUBLE_EQ(w.ents.pos[a].z(), 300.0);
  EXPECT_GT(w.ents.pos[a].x(), 1500);
}

namespace {
// A hilly world (posts vary in both directions: vehicles pitch and roll) with a crowd of ground
// vehicles on looping routes, some on none (a fixed heading), some parked; seeded.
world::World hilly_crowd(uint32_t seed) {
  auto w = test::flat_world();
  const int n = w.terrain.cols();
  std::vector<float> h(static_cast<size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      h[static_cast<size_t>(j) * n + i] = static_cast<float>(100 + 8 * std::sin(i * 0.37) * std::cos(j * 0.23) + 0.05 * i);
  w.terrain = world::Terrain(n, n, 10.0, std::move(h), {35.98, -121.25, 0});
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> xy(100, 1900), hd(0, 360), sp(0, 15);
  const char* kinds[] = {"m1a1", "bmp", "hmmwv"};
  for (int v = 0; v < 60; ++v) {
    const double heading = v % 7 == 0 ? 0.0 : v % 11 == 0 ? 270.0 : hd(rng);
    const int e = test::add_vehicle(w, test::numbered("v", v), kinds[v % 3], xy(rng), xy(rng), heading, v % 13 == 0 ? 0.0 : sp(rng));
    if (v % 5 != 0) {  // a looping route of 3 to 5 waypoints; every fifth vehicle holds its heading
      for (int k = 0; k < 3 + v % 3; ++k) w.ents.route[e].push_back(Vec2(xy(rng), xy(rng)));
      w.ents.loop_route[e] = 1;
    }
  }
  return w;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}
void expect_same_state(const world::World& a, const world::World& b, int tick) {
  ASSERT_TRUE(same_bits(a.ents.pos, b.ents.pos)) << "tick " << tick;
  ASSERT_TRUE(same_bits(a.ents.vel, b.ents.vel)) << "tick " << tick;
  ASSERT_TRUE(same_bits(a.ents.heading_deg, b.ents.heading_deg)) << "tick " << tick;
  ASSERT_TRUE(same_bits(a.ents.pitch_deg, b.ents.pitch_deg)) << "tick " << tick;
  ASSERT_TRUE(same_bits(a.ents.roll_deg, b.ents.roll_deg)) << "tick " << tick;
  ASSERT_TRUE(same_bits(a.ents.leg, b.ents.leg)) << "tick " << tick;
}
}  // namespace

TEST(HeadingMemo, KeptDirectionsGiveTheBitsOfTheSinAndCos) {
  // The same crowd stepped without and with the memo: the same bits every tick; then the memo,
  // full of the first crowd's entries, serves another crowd in the same slots: still the same.
  core::HeadingMemo memo;
  for (uint32_t seed : {7u, 8u}) {
    auto plain = hilly_crowd(seed), kept = hilly_crowd(seed);
    std::vector<dynamics::GroundImpact> imp;
    for (int t = 0; t < 600; ++t) {
      dynamics::step(plain, 1.0 / 60, imp);
      dynamics::step(kept, 1.0 / 60, imp, nullptr, &memo);
      expect_same_state(plain, kept, t);
      if (HasFatalFailure()) return;
    }
    // The memo holds the stored heading's direction of every moving ground vehicle, bit for bit.
    for (size_t e = 0; e < kept.ents.size(); ++e) {
      ASSERT_EQ(memo.key(e), (uint64_t{1} << 32) | std::bit_cast<uint32_t>(kept.ents.heading_deg[e])) << e;
      const Vec2 d = heading_to_dir(kept.ents.heading_deg[e]);
      EXPECT_EQ(std::bit_cast<uint64_t>(memo.kept_dir(e).x()), std::bit_cast<uint64_t>(d.x())) << e;
      EXPECT_EQ(std::bit_cast<uint64_t>(memo.kept_dir(e).y()), std::bit_cast<uint64_t>(d.y())) << e;
    }
  }
}
