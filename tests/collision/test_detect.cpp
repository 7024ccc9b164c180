// Thesis detection levels: L1 (100 m window), L2 (spheres), L3 (rays + Haines); fixed objects
// from the gridsquare list below the threshold height; one event per contact episode; bounce.
#include <gtest/gtest.h>

#include "collision/collision.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

namespace {
std::vector<collision::Contact> detect_once(const world::World& w, collision::Detector& d) {
  std::vector<collision::Contact> out;
  d.detect(w, out);
  return out;
}
}  // namespace

TEST(L1, RejectsPairsOutsideTheWindow) {
  auto w = test::flat_world();
  test::add_vehicle(w, "a", "m1a1", 500, 500, 0, 0);
  test::add_vehicle(w, "b", "m1a1", 500 + thesis::kFirstLevelWindowM + 1, 500, 0, 0);
  test::add_vehicle(w, "c", "m1a1", 500, 500 + thesis::kFirstLevelWindowM + 1, 0, 0);
  test::index_fixed(w);
  collision::Detector d(collision::Options{collision::Method::Thesis});
  EXPECT_TRUE(detect_once(w, d).empty());
  EXPECT_EQ(d.stats().l1_pairs, 0);
}

TEST(L2, RejectsWithinWindowButApart) {
  auto w = test::flat_world();
  test::add_vehicle(w, "a", "m1a1", 500, 500, 0, 0);
  test::add_vehicle(w, "b", "m1a1", 550, 550, 0, 0);
  test::index_fixed(w);
  collision::Detector d(collision::Options{collision::Method::Thesis});
  EXPECT_TRUE(detect_once(w, d).empty());
  EXPECT_EQ(d.stats().l1_pairs, 1);
  EXPECT_EQ(d.stats().l2_pairs, 0);
}

TEST(L3, RejectsSpheresThatTouchWithoutTheSurfaces) {
  // Two tanks side by side, nose to tail diagonal: spheres overlap, hulls do not.
  auto w = test::flat_world();
  const int a = test::add_vehicle(w, "a", "m1a1", 500, 500, 0, 0);
  const double r = world::entity_radius(w, a);
  test::add_vehicle(w, "b", "m1a1", 500 + 1.6 * r * 0.7071, 500 + 1.6 * r * 0.7071, 0, 0);
  test::index_fixed(w);
  collision::Detector d(collision::Options{collision::Method::Thesis});
  EXPECT_TRUE(detect_once(w, d).empty());
  EXPECT_EQ(d.stats().l2_pairs, 1);
  EXPECT_EQ(d.stats().l3_rejects, 1);
}

TEST(L3, AcceptsWhenHullsMeet) {
  auto w = test::flat_world();
  test::add_vehicle(w, "a", "m1a1", 500, 500, 90, 0);
  test::add_vehicle(w, "b", "m1a1", 500, 503.0, 90, 0);  // side by side, 3 m apart: hulls overlap
  test::index_fixed(w);
  collision::Detector d(collision::Options{collision::Method::Thesis});
  const auto c = detect_once(w, d);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_STREQ(c[0].method, "L3-haines");
}

TEST(Episodes, OneEventPerContactEpisode) {
  auto w = test::flat_world();
  test::add_vehicle(w, "a", "m1a1", 500, 500, 90, 0);
  const int b = test::add_vehicle(w, "b", "m1a1", 500, 503.0, 90, 0);
  test::index_fixed(w);
  collision::Detector d(collision::Options{collision::Method::Thesis});
  EXPECT_EQ(detect_once(w, d).size(), 1u);
  EXPECT_EQ(detect_once(w, d).size(), 0u);  // still touching: same episode
  w.ents.pos[b].y() = 600;                  // separate
  EXPECT_EQ(detect_once(w, d).size(), 0u);
  w.ents.pos[b].y() = 503;                  // touch again: a new episode
  EXPECT_EQ(detect_once(w, d).size(), 1u);
}

TEST(Fixed, CheckedOnlyBelowThresholdHeight) {
  auto w = test::flat_world();
  test::add_fixed(w, "t", "tree", 562.5, 562.5);
  test::index_fixed(w);
  const int e = test::add_vehicle(w, "a", "ah64", 560, 562.5, 90, 0);
  collision::Detector d(collision::Options{collision::Method::Thesis});
  EXPECT_EQ(detect_once(w, d).size(), 1u);
  w.ents.pos[e].z() += thesis::kFixedCheckThresholdHeightM + 1;
  collision::Detector d2(collision::Options{collision::Method::Thesis});
  EXPECT_TRUE(detect_once(w, d2).empty());
  EXPECT_EQ(d2.stats().fixed_tests, 0);
}

TEST(Fixed, ThesisGridMissesAcrossTheBorder) {
  // The thesis's own limitation (Figure 9): an object in the next gridsquare, touching a vehicle
  // across the border, is not in the vehicle's list.
  auto w = test::flat_world();
  const double border = thesis::kGridsquareM * 4;
  test::add_fixed(w, "t", "tree", border + 1.0, 562.5);
  test::index_fixed(w);
  test::add_vehicle(w, "a", "m1a1", border - 3.0, 562.5, 90, 0);
  collision::Detector d(collision::Options{collision::Method::Thesis});
  EXPECT_TRUE(detect_once(w, d).empty());
}

TEST(Bounce, SeparatesAndConservesMomentum) {
  auto w = test::flat_world();
  const int a = test::add_vehicle(w, "a", "m1a1", 500, 500, 90, 10);
  const int b = test::add_vehicle(w, "b", "bmp", 500, 503.5, 120, 10);  // closing at 30 degrees
  test::index_fixed(w);
  collision::Detector d(collision::Options{collision::Method::Thesis});
  auto contacts = detect_once(w, d);
  ASSERT_EQ(contacts.size(), 1u);
  world::Changes ch;
  collision::respond(w, contacts, ch);
  ASSERT_EQ(ch.collisions[0].result_a, world::Result::Bounce);
  const double ma = w.kinds[w.ents.kind[a]].mass_kg, mb = w.kinds[w.ents.kind[b]].mass_kg;
  const Vec3 p0 = ma * w.ents.vel[a] + mb * w.ents.vel[b];
  const double speed_a = w.ents.vel[a].norm(), speed_b = w.ents.vel[b].norm();
  world::Applied ap;
  world::apply(w, ch, ap);
  const Vec3 p1 = ma * w.ents.vel[a] + mb * w.ents.vel[b];
  EXPECT_NEAR((p1 - p0).norm(), 0.0, 1e-6 * p0.norm());
  // both speeds diminished? the heavier one at least; the pair's kinetic energy falls
  const double ke0 = 0.5 * ma * speed_a * speed_a + 0.5 * mb * speed_b * speed_b;
  const double ke1 = 0.5 * ma * w.ents.vel[a].squaredNorm() + 0.5 * mb * w.ents.vel[b].squaredNorm();
  EXPECT_LT(ke1, ke0);
  // separated: they no longer touch, so next tick finds nothing
  const double dist = (world::entity_centre(w, b) - world::entity_centre(w, a)).norm();
  EXPECT_GE(dist, world::entity_radius(w, a) + world::entity_radius(w, b));
  collision::Detector d2(collision::Options{collision::Method::Thesis});
  EXPECT_TRUE(detect_once(w, d2).empty());
}

TEST(Detonation, CraterChangesHeightAndBlastFallsWithDistance) {
  auto w = test::flat_world();
  const int near = test::add_fixed(w, "n", "tree", 1005, 1000);
  const int mid = test::add_fixed(w, "m", "tree", 1015, 1000);
  const int far = test::add_fixed(w, "f", "tree", 1025, 1000);
  const int out = test::add_fixed(w, "o", "tree", 1100, 1000);
  test::index_fixed(w);
  const int shooter = test::add_vehicle(w, "s", "m1a1", 500, 500, 0, 0);
  const int m = test::add_vehicle(w, "r", "he_round", 1000, 1000, 0, 0);
  w.ents.owner[m] = shooter;
  const double h0 = w.terrain.height(1000, 1000);
  world::Changes ch;
  collision::detonate(w, m, Vec3(1000, 1000, h0), -1, ch);
  world::Applied ap;
  world::apply(w, ch, ap);
  EXPECT_NEAR(w.terrain.height(1000, 1000), h0 - w.kinds[w.kinds.find("he_round")].crater_depth_m, 0.05);
  EXPECT_EQ(ap.terrain_patches.size(), 1u);
  EXPECT_EQ(w.fixed.state[near], 2);  // stump
  EXPECT_EQ(w.fixed.state[mid], 2);   // two levels
  EXPECT_EQ(w.fixed.state[far], 1);   // one level
  EXPECT_EQ(w.fixed.state[out], 0);   // beyond the blast
  EXPECT_FALSE(w.ents.active[m]);
}
