// Figure 8 (thesis p. 22): every branch, every angle-band edge, each damage transition.
#include <gtest/gtest.h>

#include "collision/collision.hpp"
#include "support/fixture.hpp"

using namespace npsnet;
using world::Result;

TEST(AngleBands, EdgesAsFigure8) {
  // In a band: <= 5, [85, 95], [175, 185], [265, 275], >= 355 (edges included).
  EXPECT_TRUE(collision::in_kill_band(4.9));
  EXPECT_TRUE(collision::in_kill_band(5.0));
  EXPECT_FALSE(collision::in_kill_band(5.1));
  EXPECT_FALSE(collision::in_kill_band(84.9));
  EXPECT_TRUE(collision::in_kill_band(85.0));
  EXPECT_TRUE(collision::in_kill_band(95.0));
  EXPECT_FALSE(collision::in_kill_band(95.1));
  EXPECT_FALSE(collision::in_kill_band(174.9));
  EXPECT_TRUE(collision::in_kill_band(175.0));
  EXPECT_TRUE(collision::in_kill_band(185.0));
  EXPECT_FALSE(collision::in_kill_band(185.1));
  EXPECT_FALSE(collision::in_kill_band(264.9));
  EXPECT_TRUE(collision::in_kill_band(265.0));
  EXPECT_TRUE(collision::in_kill_band(275.0));
  EXPECT_FALSE(collision::in_kill_band(275.1));
  EXPECT_FALSE(collision::in_kill_band(354.9));
  EXPECT_TRUE(collision::in_kill_band(355.0));
  EXPECT_FALSE(collision::in_kill_band(30.0));
}

TEST(AngleBands, AngleFromTwoHeadings) {
  EXPECT_DOUBLE_EQ(collision::impact_angle_deg(90, 0), 270);
  EXPECT_DOUBLE_EQ(collision::impact_angle_deg(0, 90), 90);
  EXPECT_DOUBLE_EQ(collision::impact_angle_deg(350, 10), 20);
  EXPECT_DOUBLE_EQ(collision::impact_angle_deg(10, 350), 340);
}

TEST(FixedDamage, MomentumAgainstConstants) {
  EXPECT_EQ(collision::fixed_damage_level(thesis::kFixedMomentumHi, 1), 3);
  EXPECT_EQ(collision::fixed_damage_level(thesis::kFixedMomentumHi - 1, 1), 2);
  EXPECT_EQ(collision::fixed_damage_level(thesis::kFixedMomentumMed, 1), 2);
  EXPECT_EQ(collision::fixed_damage_level(thesis::kFixedMomentumMed - 1, 1), 1);
  EXPECT_EQ(collision::fixed_damage_level(thesis::kFixedMomentumLow, 1), 1);
  EXPECT_EQ(collision::fixed_damage_level(thesis::kFixedMomentumLow - 1, 1), 0);
  // Resistance scales what an object withstands.
  EXPECT_EQ(collision::fixed_damage_level(thesis::kFixedMomentumHi, 2), 2);
}

namespace {

// Two vehicles whose centres are placed to touch; returns the response to a forced contact.
// a (entity 0) moves +x at `speed`, b (entity 1) -x at `speed`: closing at 2 x speed along the
// contact normal (+x), whatever the headings say.
world::Changes mobile_pair(double heading_a, double heading_b, double speed, const char* ka = "m1a1",
                           const char* kb = "m1a1") {
  auto w = test::flat_world();
  const int a = test::add_vehicle(w, "a", ka, 1000, 1000, heading_a, speed);
  const int b = test::add_vehicle(w, "b", kb, 1006, 1000, heading_b, speed);
  w.ents.vel[a] = Vec3(speed, 0, 0);
  w.ents.vel[b] = Vec3(-speed, 0, 0);
  collision::Contact c;
  c.a = a, c.b = b, c.point = Vec3(1003, 1000, 101), c.normal = Vec3(1, 0, 0), c.method = "test";
  world::Changes out;
  collision::respond(w, {c}, out);
  return out;
}

world::Changes fixed_hit(const char* vehicle, double speed, const char* fixed_kind, int& fixed_state_to) {
  auto w = test::flat_world();
  const int a = test::add_vehicle(w, "v", vehicle, 1000, 1000, 90, speed);
  const int o = test::add_fixed(w, "f", fixed_kind, 1005, 1000);
  test::index_fixed(w);
  collision::Contact c;
  c.a = a, c.b = o, c.b_fixed = true, c.point = Vec3(1003, 1000, 101), c.normal = Vec3(1, 0, 0), c.method = "test";
  world::Changes out;
  collision::respond(w, {c}, out);
  EXPECT_LE(out.fixed.size(), 1u);
  fixed_state_to = out.fixed.empty() ? 0 : out.fixed[0].to_state;
  return out;
}

}  // namespace

TEST(Figure8Mobile, InBandFastKillsBoth) {
  const auto out = mobile_pair(90, 0, 10.0);  // angle 270
  ASSERT_EQ(out.collisions.size(), 1u);
  ASSERT_EQ(out.entities.size(), 2u);
  EXPECT_DOUBLE_EQ(out.collisions[0].closing_speed_mps, 20.0);
  EXPECT_EQ(out.collisions[0].result_a, Result::Kill);
  EXPECT_EQ(out.collisions[0].result_b, Result::Kill);
  EXPECT_EQ(out.entities[0].to_state, 2);
  EXPECT_EQ(out.entities[1].to_state, 2);
}

TEST(Figure8Mobile, InBandSlowStopsBoth) {
  const auto out = mobile_pair(90, 270, thesis::kKillClosingSpeedMps * 0.25);  // head-on, 180; closing at half
  ASSERT_EQ(out.collisions.size(), 1u);
  ASSERT_EQ(out.entities.size(), 2u);
  EXPECT_EQ(out.collisions[0].result_a, Result::Stop);
  EXPECT_EQ(out.collisions[0].result_b, Result::Stop);
  for (const auto& ch : out.entities) {
    EXPECT_EQ(ch.to_state, -1);
    EXPECT_TRUE(ch.set_vel);
    EXPECT_TRUE(ch.vel.isZero());
  }
}

TEST(Figure8Mobile, SameDirectionBandIsStopOrKill) {
  const auto in = mobile_pair(90, 94.9, 10), out = mobile_pair(90, 95.1, 10);  // angles 4.9, 5.1
  ASSERT_EQ(in.collisions.size(), 1u);
  ASSERT_EQ(out.collisions.size(), 1u);
  EXPECT_EQ(in.collisions[0].result_a, Result::Kill);
  EXPECT_EQ(out.collisions[0].result_a, Result::Bounce);
}

TEST(Figure8Mobile, OutsideBandsBounceAndDiminish) {
  const auto out = mobile_pair(90, 60, 10.0);  // angle 330
  ASSERT_EQ(out.collisions.size(), 1u);
  EXPECT_EQ(out.collisions[0].result_a, Result::Bounce);
  EXPECT_EQ(out.collisions[0].result_b, Result::Bounce);
  ASSERT_EQ(out.entities.size(), 2u);
  const world::EntityChange& a = out.entities[0].entity == 0 ? out.entities[0] : out.entities[1];
  const world::EntityChange& b = out.entities[0].entity == 0 ? out.entities[1] : out.entities[0];
  ASSERT_TRUE(a.set_vel && b.set_vel);
  // A bounce, not a stop: each turns back along the normal, slower than it came (Figure 7),
  // separating at the restitution times the closing speed; equal masses keep zero momentum.
  EXPECT_LT(a.vel.x(), 0.0);
  EXPECT_GT(b.vel.x(), 0.0);
  EXPECT_LT(a.vel.norm(), 10.0);
  EXPECT_LT(b.vel.norm(), 10.0);
  EXPECT_NEAR((b.vel - a.vel).x(), thesis::kBounceRestitution * 20.0, 1e-9);
  EXPECT_NEAR((a.vel + b.vel).norm(), 0.0, 1e-9);
}

TEST(Figure8Fixed, SlowTankDamagesTreeAndIsSlowed) {
  int to = -1;
  const auto out = fixed_hit("m1a1", kmh2mps(5), "tree", to);  // 8.75e4 kg m/s: low
  ASSERT_EQ(out.collisions.size(), 1u);
  EXPECT_EQ(to, 1);
  EXPECT_EQ(out.collisions[0].result_b, Result::DamageFixed);
  EXPECT_EQ(out.collisions[0].result_a, Result::Slowed);
}

TEST(Figure8Fixed, FastTankLeavesAStump) {
  int to = -1;
  const auto out = fixed_hit("m1a1", kmh2mps(50), "tree", to);  // 8.75e5: high
  ASSERT_EQ(out.collisions.size(), 1u);
  EXPECT_EQ(to, 2);
  EXPECT_EQ(out.collisions[0].result_b, Result::DestroyFixed);
  EXPECT_EQ(out.collisions[0].result_a, Result::Slowed);
}

TEST(Figure8Fixed, JeepOverBushNoDamage) {
  int to = -1;
  const auto out = fixed_hit("hmmwv", kmh2mps(40), "bush", to);
  ASSERT_EQ(out.collisions.size(), 1u);
  EXPECT_TRUE(out.fixed.empty());
  EXPECT_EQ(out.collisions[0].result_a, Result::None);
  EXPECT_EQ(out.collisions[0].result_b, Result::None);
}

TEST(Figure8Fixed, LargeObjectFastKillsVehicle) {
  int to = -1;
  const auto out = fixed_hit("m1a1", kmh2mps(60), "watertower", to);
  ASSERT_EQ(out.collisions.size(), 1u);
  EXPECT_EQ(out.collisions[0].result_a, Result::Kill);
  EXPECT_EQ(out.collisions[0].result_b, Result::DestroyFixed);
  EXPECT_EQ(to, 2);
}

TEST(Figure8Fixed, LargeObjectSlowStopsVehicleAndDamagesObject) {
  int to = -1;
  const auto out = fixed_hit("m1a1", kmh2mps(5), "watertower", to);
  ASSERT_EQ(out.collisions.size(), 1u);
  EXPECT_EQ(out.collisions[0].result_a, Result::Stop);
  EXPECT_EQ(out.collisions[0].result_b, Result::DamageFixed);
  EXPECT_EQ(to, 1);
}

TEST(Figure8Fixed, TankIntoBuildingDamagesBoth) {
  int to = -1;
  const auto out = fixed_hit("m1a1", kmh2mps(25), "building", to);
  ASSERT_EQ(out.collisions.size(), 1u);
  EXPECT_EQ(to, 2);  // damaged_med
  EXPECT_EQ(out.collisions[0].result_a, Result::Stop);
  ASSERT_FALSE(out.entities.empty());
  EXPECT_EQ(out.entities[0].to_state, 1);  // the tank is damaged
}

TEST(Figure8Munition, OnlyResponseIsExplosion) {
  auto w = test::flat_world();
  const int t = test::add_vehicle(w, "t", "m1a1", 1000, 1000, 0, 0);
  const int m = test::add_vehicle(w, "m", "missile", 995, 1000, 90, 400);
  test::index_fixed(w);
  collision::Contact c;
  c.a = t, c.b = m, c.point = Vec3(998, 1000, 101), c.normal = Vec3(-1, 0, 0), c.method = "test";
  world::Changes out;
  collision::respond(w, {c}, out);
  ASSERT_EQ(out.collisions.size(), 1u);
  EXPECT_EQ(out.collisions[0].result_a, Result::Kill);
  EXPECT_EQ(out.collisions[0].result_b, Result::Explode);
  ASSERT_EQ(out.detonations.size(), 1u);
  EXPECT_EQ(out.detonations[0].target, t);
  EXPECT_TRUE(out.craters.empty());  // a round that hits a vehicle leaves the ground untouched
}

TEST(DamageTransitions, ApplyMovesStatesForwardOnly) {
  auto w = test::flat_world();
  const int o = test::add_fixed(w, "b", "building", 1000, 1000);
  const int e = test::add_vehicle(w, "t", "m1a1", 900, 900, 0, 5);
  test::index_fixed(w);
  world::Applied applied;
  const char* expect[] = {"damaged_low", "damaged_med", "destroyed"};
  for (int s = 1; s <= 3; ++s) {
    world::Changes c;
    c.fixed.push_back({o, s});
    applied.clear();
    world::apply(w, c, applied);
    ASSERT_EQ(applied.damage.size(), 1u);
    EXPECT_EQ(w.kinds[w.fixed.kind[o]].states[w.fixed.state[o]], expect[s - 1]);
  }
  world::Changes back;
  back.fixed.push_back({o, 1});
  applied.clear();
  world::apply(w, back, applied);
  EXPECT_TRUE(applied.damage.empty());
  EXPECT_EQ(w.fixed.state[o], 3);
  // vehicle: intact -> damaged -> wreck, and a wreck stops
  for (const char* st : {"damaged", "wreck"}) {
    world::Changes c;
    world::EntityChange ch;
    ch.entity = e;
    ch.to_state = w.ents.state[e] + 1;
    c.entities.push_back(ch);
    applied.clear();
    world::apply(w, c, applied);
    EXPECT_EQ(w.kinds[w.ents.kind[e]].states[w.ents.state[e]], st);
  }
  EXPECT_EQ(applied.killed.size(), 1u);
  EXPECT_EQ(w.ents.cruise_mps[e], 0.0f);
}
