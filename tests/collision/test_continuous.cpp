// The continuous method at the places where the thesis's fails (ch. V): tunnelling at speed,
// jets closing at 2,000 m/s, border objects (Figure 9), objects larger than a gridsquare.
#include <gtest/gtest.h>

#include <cmath>

#include "collision/collision.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

namespace {

collision::Options continuous(double dt, collision::Tier tier = collision::Tier::Auto) {
  return collision::Options{collision::Method::Continuous, tier, dt};
}

std::vector<collision::Contact> run_ticks(world::World& w, collision::Detector& d, double dt, int ticks,
                                          int* tick_of_first = nullptr) {
  std::vector<collision::Contact> all;
  for (int k = 0; k < ticks; ++k) {
    for (size_t e = 0; e < w.ents.size(); ++e) w.ents.pos[e] += w.ents.vel[e] * dt;
    const size_t before = all.size();
    d.detect(w, all);
    if (tick_of_first && before == 0 && !all.empty()) *tick_of_first = k;
  }
  return all;
}

// Two jets head-on along x at `alt` m, closing at `closing` m/s; their noses are `gap` m apart
// at the start of the tick; positions set to the end of the tick (as after dynamics::step).
struct Jets {
  world::World w;
  double nose = 0;  // nose ahead of the model origin (m)
};
Jets head_on_jets(double gap, double closing, double dt) {
  Jets j{test::flat_world(), 0};
  const int k = j.w.kinds.find("f16");
  j.nose = j.w.models[j.w.kinds[k].models[0]].bbox_max.y();
  const double x0 = 500, alt = 1000;
  const int a = test::add_vehicle(j.w, "jet-a", "f16", x0, 1000, 90, closing / 2);
  const int b = test::add_vehicle(j.w, "jet-b", "f16", x0 + 2 * j.nose + gap, 1000, 270, closing / 2);
  for (int e : {a, b}) {
    j.w.ents.pos[e].z() = alt;
    j.w.ents.pos[e] += j.w.ents.vel[e] * dt;  // end of the tick
  }
  test::index_fixed(j.w);
  return j;
}

}  // namespace

TEST(Continuous, TanksFasterThanTheThesisLimitPassThroughWithThesisCollideWithContinuous) {
  // Thesis p. 23: two tanks closing fast enough to move past each other within one frame are
  // never seen touching. Speed chosen from the tanks' own spheres: they close 2 R + 4 m a tick.
  const double dt = thesis::kDefaultDtS;
  auto make = [&](double& speed_mps) {
    auto w = test::flat_world();
    const int k = w.kinds.find("m1a1");
    // Sum of the true radii (the meshes, barrel included, lie within; the thesis spheres are 0.9x).
    const double R = 2 * w.models[w.kinds[k].models[0]].true_radius;
    speed_mps = (2 * R + 4) / dt / 2;
    // Centres start 2.5 ticks of closing apart: at the end of ticks 2 and 3 they are +-Delta/2.
    const double delta = 2 * speed_mps * dt;
    const int a = test::add_vehicle(w, "tank-a", "m1a1", 1000 - 1.25 * delta, 1000, 90, speed_mps);
    const int b = test::add_vehicle(w, "tank-b", "m1a1", 1000 + 1.25 * delta, 1000, 270, speed_mps);
    w.ents.max_mps[a] = w.ents.max_mps[b] = static_cast<float>(speed_mps);  // max_speed_kmh raised
    test::index_fixed(w);
    return w;
  };
  double v = 0;
  auto w1 = make(v);
  EXPECT_GT(mps2kmh(v), thesis::kTunnellingSpeedKmh);
  collision::Detector thesis_d(collision::Options{collision::Method::Thesis});
  EXPECT_TRUE(run_ticks(w1, thesis_d, dt, 6).empty()) << "the thesis method should miss this";
  EXPECT_GT(w1.ents.pos[0].x(), w1.ents.pos[1].x()) << "...and the tanks are past each other";

  auto w2 = make(v);
  collision::Detector cont(continuous(dt));
  int tick = -1;
  const auto c = run_ticks(w2, cont, dt, 6, &tick);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(tick, 2);  // the tick in which they pass
  EXPECT_GT(c[0].fraction, 0.0);
  EXPECT_LT(c[0].fraction, 1.0);
  EXPECT_STREQ(c[0].method, "continuous-mesh");
  // Head-on, on the line y = 1000, meeting where they cross (x = 1000 by symmetry).
  EXPECT_NEAR(c[0].point.y(), 1000, 0.5);
  EXPECT_NEAR(c[0].point.x(), 1000, 0.5);
  // Figure 8: angle 180 with closing speed above the constant: both killed.
  world::Changes ch;
  collision::respond(w2, c, ch);
  ASSERT_EQ(ch.collisions.size(), 1u);
  EXPECT_EQ(ch.collisions[0].result_a, world::Result::Kill);
}

TEST(Continuous, JetsClosingAt2000MpsCollideAtTheAnalyticTimeAndPoint) {
  for (double dt : {0.1, 1.0}) {
    for (double frac : {0.1, 0.5, 0.9}) {
      const double closing = 2000, gap = frac * closing * dt;
      // Sphere tier: the analytic swept-sphere time.
      {
        auto j = head_on_jets(gap, closing, dt);
        const double R = 2 * world::entity_radius(j.w, 0);
        const Vec3 ca1 = world::entity_centre(j.w, 0), cb1 = world::entity_centre(j.w, 1);
        const double centres0 = (cb1 - ca1).x() + closing * dt;  // signed, at the start
        collision::Detector d(continuous(dt, collision::Tier::Sphere));
        std::vector<collision::Contact> c;
        d.detect(j.w, c);
        ASSERT_EQ(c.size(), 1u) << "dt " << dt << " frac " << frac;
        const double t = std::max(0.0, (centres0 - R) / (closing * dt));
        EXPECT_NEAR(c[0].fraction, t, 1e-9);
        const double xa = ca1.x() - closing / 2 * dt * (1 - t), xb = cb1.x() + closing / 2 * dt * (1 - t);
        EXPECT_NEAR(c[0].point.x(), 0.5 * (xa + xb), 1e-6);
      }
      // Mesh tier: the noses meet after the gap closes.
      {
        auto j = head_on_jets(gap, closing, dt);
        collision::Detector d(continuous(dt));
        std::vector<collision::Contact> c;
        d.detect(j.w, c);
        ASSERT_EQ(c.size(), 1u) << "dt " << dt << " frac " << frac;
        EXPECT_STREQ(c[0].method, "continuous-mesh");
        EXPECT_NEAR(c[0].fraction, frac, 2e-3);
        const double x_meet = 500 + j.nose + gap / 2;  // midway between the two noses at the start
        EXPECT_NEAR(c[0].point.x(), x_meet, 0.3);
        EXPECT_NEAR(c[0].point.y(), 1000, 0.5);
      }
    }
  }
}

TEST(Continuous, JetsThatWouldMeetNextTickAreNotReportedEarly) {
  const double dt = 0.1, closing = 2000;
  auto j = head_on_jets(1.05 * closing * dt + 50, closing, dt);  // spheres and noses still apart
  collision::Detector d(continuous(dt));
  std::vector<collision::Contact> c;
  d.detect(j.w, c);
  EXPECT_TRUE(c.empty());
}

TEST(BorderObjects, Figure9LargeObjectAtAGridsquareCornerTouchedFromTheNeighbour) {
  // A building whose centre lies just inside a gridsquare corner; a tank in the diagonal
  // neighbour gridsquare touches its sphere. The thesis lists the building only in its home
  // gridsquare and the tank checks only its own: missed. The continuous method lists the
  // building in every gridsquare its sphere overlaps and queries every gridsquare the tank's
  // swept sphere overlaps: found.
  auto make = [] {
    auto w = test::flat_world();
    const double g = thesis::kGridsquareM;
    const int o = test::add_fixed(w, "bldg", "building", 4 * g - 1.0, 4 * g - 1.0);
    const double rb = world::fixed_radius(w, o);
    const int k = w.kinds.find("m1a1");
    const double rt = w.kinds[k].radius_by_state[0];
    const double d = (rb + rt) * 0.8 / std::sqrt(2.0);  // diagonal offset: spheres overlap
    const int e = test::add_vehicle(w, "tank", "m1a1", 4 * g - 1.0 + d, 4 * g - 1.0 + d, 45, 0);
    EXPECT_NE(w.grid.cols(), -1);
    test::index_fixed(w);  // the thesis's lists
    EXPECT_NE(w.grid.cell_of(w.ents.pos[e].x(), w.ents.pos[e].y()), w.grid.cell_of(w.fixed.pos[o].x(), w.fixed.pos[o].y()));
    return w;
  };
  auto w1 = make();
  collision::Detector thesis_d(collision::Options{collision::Method::Thesis});
  std::vector<collision::Contact> c1;
  thesis_d.detect(w1, c1);
  EXPECT_TRUE(c1.empty());
  auto w2 = make();
  collision::Detector cont(continuous(0.1));
  std::vector<collision::Contact> c2;
  cont.detect(w2, c2);
  ASSERT_EQ(c2.size(), 1u);
  EXPECT_TRUE(c2[0].b_fixed);
  EXPECT_EQ(c2[0].b, 0);
  EXPECT_EQ(c2[0].fraction, 0.0);  // overlapping from the start of the tick
}

TEST(BorderObjects, ObjectLargerThanAGridsquareIsFoundFromEveryGridsquareItCovers) {
  auto w = test::flat_world();
  const double g = thesis::kGridsquareM;
  const int k = w.kinds.find("rock");
  w.fixed.add("mesa", k, Vec3(6.5 * g, 6.5 * g, 100), 0, static_cast<float>(1.6 * g));  // 200 m radius
  // Tanks two gridsquares away in x, in y, and diagonally, each just inside the sphere.
  const double r = 1.6 * g;
  test::add_vehicle(w, "east", "m1a1", 6.5 * g + r - 2, 6.5 * g, 0, 0);
  test::add_vehicle(w, "north", "m1a1", 6.5 * g, 6.5 * g + r - 2, 0, 0);
  test::add_vehicle(w, "diag", "m1a1", 6.5 * g + (r - 2) / std::sqrt(2.0), 6.5 * g - (r - 2) / std::sqrt(2.0), 0, 0);
  test::add_vehicle(w, "outside", "m1a1", 6.5 * g - r - 20, 6.5 * g, 0, 0);
  test::index_fixed(w);
  collision::Detector thesis_d(collision::Options{collision::Method::Thesis});
  std::vector<collision::Contact> c1;
  thesis_d.detect(w, c1);
  EXPECT_TRUE(c1.empty());
  collision::Detector cont(continuous(0.1));
  std::vector<collision::Contact> c2;
  cont.detect(w, c2);
  ASSERT_EQ(c2.size(), 3u);
  for (const auto& c : c2) EXPECT_NE(w.ents.id[c.a], "outside");
}

TEST(Continuous, EpisodeReportedOnceWhileTouching) {
  auto w = test::flat_world();
  test::add_vehicle(w, "a", "m1a1", 500, 500, 90, 0);
  test::add_vehicle(w, "b", "m1a1", 500, 503.0, 90, 0);  // side by side: hulls overlap
  test::index_fixed(w);
  collision::Detector d(continuous(0.1));
  std::vector<collision::Contact> c;
  d.detect(w, c);
  d.detect(w, c);
  d.detect(w, c);
  EXPECT_EQ(c.size(), 1u);
}

// Thousands of episodes at once: past kEpisodeIndexMin keys the detector finds last tick's
// episodes through each entity's bucket (a counting sort by lower index), and the fixed
// contacts' in the sorted keys after the buckets. Each is still reported once; those of bodies
// moved away end, and begin again (one contact each) when they come back.
TEST(Continuous, ThousandsOfEpisodesEachReportedOnce) {
  auto w = test::flat_world();
  const int side = 40;  // a 40 x 40 lattice, 4 m apart: each tank's sphere meets a score of others
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) test::add_vehicle(w, test::numbered("v", side * i + j), "m1a1", 400 + 4.0 * i, 400 + 4.0 * j, 0, 0);
  for (int i = 0; i < 10; ++i)  // trees among them: fixed contacts among the indexed keys
    for (int j = 0; j < 10; ++j) test::add_fixed(w, test::numbered("t", 10 * i + j), "tree", 402 + 16.0 * i, 402 + 16.0 * j);
  test::index_fixed(w);
  collision::Detector d(continuous(0.1, collision::Tier::Sphere));
  std::vector<collision::Contact> first, c;
  d.detect(w, first);
  ASSERT_GE(first.size(), 4096u);  // enough episodes for the indexed look-up
  size_t with_trees = 0;
  for (const auto& k : first) with_trees += k.b_fixed;
  ASSERT_GT(with_trees, 100u);
  d.detect(w, c);
  EXPECT_EQ(c.size(), 0u);  // all still touching
  // Every 7th tank driven off, each alone on a 40 m lattice: their episodes end.
  std::vector<Vec3> home(w.ents.pos.begin(), w.ents.pos.end());
  std::vector<bool> moved(w.ents.size(), false);
  for (size_t e = 0, k = 0; e < w.ents.size(); e += 7, ++k) {
    moved[e] = true;
    const double x = 1000 + 40.0 * static_cast<double>(k % 20), y = 1000 + 40.0 * static_cast<double>(k / 20);
    w.ents.pos[e] = Vec3(x, y, w.terrain.height(x, y));
  }
  d.detect(w, c);
  EXPECT_EQ(c.size(), 0u);
  for (size_t e = 0; e < w.ents.size(); ++e) w.ents.pos[e] = home[e];
  c.clear();
  d.detect(w, c);
  size_t again = 0, again_trees = 0;  // the first tick's contacts with a moved tank
  for (const auto& k : first) again += moved[k.a] || (!k.b_fixed && moved[k.b]), again_trees += k.b_fixed && moved[k.a];
  EXPECT_GT(again_trees, 0u);
  EXPECT_EQ(c.size(), again);
  for (const auto& k : c) EXPECT_TRUE(moved[k.a] || (!k.b_fixed && moved[k.b])) << k.a << " " << k.b;
}

TEST(Tiers, CheapestTierDecidesAndAForcedTierIsObeyed) {
  // Spheres overlap, hulls do not (the thesis L3 reject case): the sphere tier reports a
  // contact, auto (mesh for two tanks) and hull do not.
  auto make = [] {
    auto w = test::flat_world();
    const int a = test::add_vehicle(w, "a", "m1a1", 500, 500, 0, 0);
    const double r = world::entity_radius(w, a);
    test::add_vehicle(w, "b", "m1a1", 500 + 1.6 * r * 0.7071, 500 + 1.6 * r * 0.7071, 0, 0);
    test::index_fixed(w);
    return w;
  };
  for (auto [tier, expect] : {std::pair{collision::Tier::Sphere, 1u}, std::pair{collision::Tier::Hull, 0u},
                              std::pair{collision::Tier::Mesh, 0u}, std::pair{collision::Tier::Auto, 0u}}) {
    auto w = make();
    collision::Detector d(continuous(0.1, tier));
    std::vector<collision::Contact> c;
    d.detect(w, c);
    EXPECT_EQ(c.size(), expect) << collision::tier_name(tier);
  }
  // Auto: a tank and a rock stay spheres (the rock declares only its sphere).
  auto w = test::flat_world();
  test::add_fixed(w, "r", "rock", 500, 504);
  test::add_vehicle(w, "a", "m1a1", 500, 500, 0, 0);
  test::index_fixed(w);
  collision::Detector d(continuous(0.1));
  std::vector<collision::Contact> c;
  d.detect(w, c);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_STREQ(c[0].method, "continuous-sphere-fixed");
}

TEST(Method, ParsesNamesAndRejectsOthers) {
  EXPECT_EQ(collision::parse_method("thesis"), collision::Method::Thesis);
  EXPECT_EQ(collision::parse_method("continuous"), collision::Method::Continuous);
  EXPECT_THROW(collision::parse_method("swept"), std::invalid_argument);
  EXPECT_EQ(collision::parse_tier("capsule"), collision::Tier::Box);
  EXPECT_EQ(collision::parse_tier("mesh"), collision::Tier::Mesh);
  EXPECT_THROW(collision::parse_tier("voxel"), std::invalid_argument);
  EXPECT_THROW(collision::options_from("continuous", "auto", 0.0), std::invalid_argument);
  EXPECT_THROW(collision::options_from("continuous", "auto", NAN), std::invalid_argument);
}

TEST(Tiers, KindsDeclareTheirTiersInKindsToml) {
  auto w = test::flat_world();
  EXPECT_EQ(w.kinds[w.kinds.find("m1a1")].top_tier, world::ShapeTier::Mesh);
  EXPECT_EQ(collision::top_tier(w.kinds[w.kinds.find("m1a1")]), collision::Tier::Mesh);
  EXPECT_EQ(collision::top_tier(w.kinds[w.kinds.find("tree")]), collision::Tier::Hull);  // its trunk
  EXPECT_EQ(collision::top_tier(w.kinds[w.kinds.find("building")]), collision::Tier::Box);
  EXPECT_EQ(collision::top_tier(w.kinds[w.kinds.find("rock")]), collision::Tier::Sphere);
  EXPECT_EQ(collision::top_tier(w.kinds[w.kinds.find("he_round")]), collision::Tier::Sphere);
  const auto bad = test::write_file("kinds_bad_tiers.toml",
                                    "[thing]\nmobility = \"ground\"\nmass_kg = 1.0\nstates = [\"intact\"]\n"
                                    "models = [\"" + test::source("models/hmmwv.obj").string() + "\"]\n"
                                    "dis_type = [1, 1, 0, 0, 0, 0, 0]\ntiers = [\"sphere\", \"voxel\"]\n");
  world::ModelLibrary lib;
  try {
    world::KindTable::load(bad, lib);
    ADD_FAILURE() << "a bad tier name must be an error";
  } catch (const std::exception& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("thing.tiers"), std::string::npos) << msg;
    EXPECT_NE(msg.find("voxel"), std::string::npos) << msg;
  }
}

TEST(Method, ScenarioSelectsMethodAndTierAndRejectsUnknownOnes) {
  const std::string world = "[world]\nterrain = \"" + test::source("terrain/default.tif").string() + "\"\n";
  const auto def = world::load_scenario(test::write_file("method_default.toml", world));
  EXPECT_EQ(def.collision_method, "continuous");  // the default
  EXPECT_EQ(def.collision_tier, "auto");
  const auto th = world::load_scenario(
      test::write_file("method_thesis.toml", "collision_method = \"thesis\"\ncollision_tier = \"hull\"\n" + world));
  EXPECT_EQ(th.collision_method, "thesis");
  EXPECT_EQ(collision::options_from(th.collision_method, th.collision_tier, 0.1).tier, collision::Tier::Hull);
  for (const char* bad : {"collision_method = \"fast\"\n", "collision_tier = \"voxel\"\n"}) {
    try {
      world::load_scenario(test::write_file("method_bad.toml", std::string(bad) + world));
      ADD_FAILURE() << bad;
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(bad).substr(0, 14)), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("method_bad.toml:1"), std::string::npos) << e.what();
    }
  }
}

// A round leaves its shooter's hull in its first tick: the two never meet (the pair loop asks
// world.ents.owner only of a body whose tags say it has one), while the round meets the tank it
// flies into. Either way round in storage (the round's slot before or after the shooter's); with
// no owner set, the shooter's contact is reported, so the test can tell.
TEST(Continuous, ARoundNeverMeetsItsShooterButMeetsItsTarget) {
  for (const bool round_first : {false, true}) {
    for (const bool owned : {true, false}) {
      SCOPED_TRACE(std::string(round_first ? "round stored first" : "shooter stored first") + (owned ? ", owned" : ", no owner"));
      auto w = test::flat_world();
      test::index_fixed(w);
      int shooter = -1, round = -1;
      if (!round_first) shooter = test::add_vehicle(w, "shooter", "m1a1", 1000, 1000, 0, 0);
      round = test::add_vehicle(w, "round", "he_round", 1000, 1043, 0, 0);  // the tick's end
      if (round_first) shooter = test::add_vehicle(w, "shooter", "m1a1", 1000, 1000, 0, 0);
      const int target = test::add_vehicle(w, "target", "m1a1", 1000, 1040, 0, 0);
      w.ents.vel[shooter] = w.ents.vel[target] = Vec3::Zero();
      w.ents.vel[round] = Vec3(0, 400, 0);  // from 1003 m, in the shooter's sphere, through the target's
      if (owned) w.ents.owner[round] = shooter;
      collision::Detector d(continuous(0.1));
      std::vector<collision::Contact> out;
      d.detect(w, out);
      bool with_shooter = false, with_target = false;
      for (const auto& c : out) {
        ASSERT_FALSE(c.b_fixed);
        const int other = c.a == round ? c.b : c.b == round ? c.a : -1;
        with_shooter |= other == shooter;
        with_target |= other == target;
      }
      EXPECT_EQ(with_shooter, !owned);
      EXPECT_TRUE(with_target);
    }
  }
}
