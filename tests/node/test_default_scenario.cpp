// A run of the default scenario yields each of the thesis's Appendix A outcomes in its event log,
// with the default (continuous) method and with the thesis's own method.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>

#include "node/simulation.hpp"
#include "support/fixture.hpp"

using namespace npsnet;
using nlohmann::json;

namespace {

struct Run {
  std::vector<json> events;
  int background = 0, background_moved = 0;  // background vehicles; those 100 m or more from their start
};

std::string g_method = "continuous";  // set by the fixture for each parameter

const Run& default_run() {
  static std::map<std::string, Run> runs;
  auto it = runs.find(g_method);
  if (it != runs.end()) return it->second;
  Run r;
  auto sc = world::load_scenario(test::source("scenarios/default.toml"));
  sc.collision_method = g_method;
  node::EventLog log;
  log.keep(true);
  node::Simulation sim(world::build_world(sc), sc, log, 0.1);
  const world::Entities start = sim.world().ents;
  const int ticks = static_cast<int>(sc.duration_s / 0.1);
  for (int i = 0; i < ticks; ++i) sim.tick();
  r.events = log.kept();
  EXPECT_TRUE(sim.world().valid());
  for (size_t e = 0; e < start.size(); ++e) {
    if (!start.loop_route[e]) continue;  // background traffic drives looping routes
    ++r.background;
    if ((sim.world().ents.pos[e] - start.pos[e]).head<2>().norm() >= 100) ++r.background_moved;
  }
  return runs[g_method] = std::move(r);
}

const json* find_collision(const std::string& a, const std::string& b) {
  for (const auto& e : default_run().events)
    if (e["event"] == "collision" && ((e["a"] == a && e["b"] == b) || (e["a"] == b && e["b"] == a))) return &e;
  return nullptr;
}

std::string outcome_of(const json& e, const std::string& id) { return e["a"] == id ? e["outcome_a"] : e["outcome_b"]; }

bool has(const std::string& type, const std::string& key, const std::string& value) {
  for (const auto& e : default_run().events)
    if (e["event"] == type && e.contains(key) && e[key] == value) return true;
  return false;
}

// The states `object` was moved to, in the order of its damage events.
std::vector<std::string> damage_states(const std::string& object) {
  std::vector<std::string> to;
  for (const auto& e : default_run().events)
    if (e["event"] == "damage" && e["object"] == object) to.push_back(e["to_state"]);
  return to;
}

// The first event of `type` whose `key` is `value`, or nullptr.
const json* first(const std::string& type, const std::string& key, const std::string& value) {
  for (const auto& e : default_run().events)
    if (e["event"] == type && e.contains(key) && e[key] == value) return &e;
  return nullptr;
}

double distance_2d(const json& p, const json& q) {
  return std::hypot(p[0].get<double>() - q[0].get<double>(), p[1].get<double>() - q[1].get<double>());
}

class AppendixA : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { g_method = GetParam(); }
};

}  // namespace

TEST_P(AppendixA, BroadsideKillsBoth) {
  const json* c = find_collision("tank1", "apc1");
  ASSERT_TRUE(c);
  EXPECT_EQ(outcome_of(*c, "tank1"), "kill");
  EXPECT_EQ(outcome_of(*c, "apc1"), "kill");
  EXPECT_EQ((*c)["method"], g_method == "thesis" ? "L3-haines" : "continuous-mesh");
}

TEST_P(AppendixA, ShallowAngleBounces) {
  const json* c = find_collision("tank2", "apc2");
  ASSERT_TRUE(c);
  EXPECT_EQ(outcome_of(*c, "tank2"), "bounce");
  EXPECT_EQ(outcome_of(*c, "apc2"), "bounce");
}

TEST_P(AppendixA, SlowAndFastTree) {
  const json* slow = find_collision("tank3", "tree1");
  const json* fast = find_collision("tank4", "tree2");
  ASSERT_TRUE(slow && fast);
  EXPECT_EQ(outcome_of(*slow, "tree1"), "damage_fixed");
  EXPECT_EQ(outcome_of(*fast, "tree2"), "destroy_fixed");
  // The slow tank leaves tree1 damaged, the fast one knocks tree2 down to a stump (each once).
  EXPECT_EQ(damage_states("tree1"), std::vector<std::string>{"damaged"});
  EXPECT_EQ(damage_states("tree2"), std::vector<std::string>{"stump"});
}

TEST_P(AppendixA, SlowAndFastWatertower) {
  const json* slow = find_collision("tank5", "tower1");
  const json* fast = find_collision("tank6", "tower2");
  ASSERT_TRUE(slow && fast);
  EXPECT_EQ(outcome_of(*slow, "tower1"), "damage_fixed");
  EXPECT_EQ(outcome_of(*slow, "tank5"), "stop");
  EXPECT_EQ(outcome_of(*fast, "tower2"), "destroy_fixed");
  EXPECT_EQ(outcome_of(*fast, "tank6"), "kill");
}

TEST_P(AppendixA, JeepOverBushNoDamage) {
  const json* c = find_collision("jeep1", "bush1");
  ASSERT_TRUE(c);
  EXPECT_EQ(outcome_of(*c, "jeep1"), "none");
  EXPECT_EQ(outcome_of(*c, "bush1"), "none");
  EXPECT_FALSE(has("damage", "object", "bush1"));
  EXPECT_FALSE(has("damage", "object", "jeep1"));
}

TEST_P(AppendixA, TankIntoBuilding) {
  const json* c = find_collision("tank7", "house1");
  ASSERT_TRUE(c);
  EXPECT_EQ(outcome_of(*c, "house1"), "damage_fixed");
  EXPECT_TRUE(has("damage", "object", "house1"));
  EXPECT_TRUE(has("damage", "object", "tank7"));
}

TEST_P(AppendixA, ArtilleryRoundCraters) {
  const json* det = first("detonation", "shooter", "arty1");
  ASSERT_TRUE(det);
  EXPECT_EQ((*det)["result"], "ground_impact");
  // A crater where the round came down (x and y), logged in the detonation's tick.
  int craters = 0;
  for (const auto& e : default_run().events)
    if (e["event"] == "crater" && e["frame"] == (*det)["frame"] && distance_2d(e["point"], (*det)["point"]) < 0.01) ++craters;
  EXPECT_EQ(craters, 1);
  const json* fired = first("fire", "shooter", "arty1");  // aimed at a point on the ground
  ASSERT_TRUE(fired);
  EXPECT_LT(distance_2d((*det)["point"], (*fired)["point"]), 1.0);
  EXPECT_FALSE(damage_states("tree3").empty());  // within the blast
}

TEST_P(AppendixA, MissileHitsTank) {
  const json* hit = nullptr;
  for (const auto& e : default_run().events)
    if (e["event"] == "detonation" && e["munition"] == "missile" && e["target"] == "tank8") hit = &e;
  ASSERT_TRUE(hit);
  EXPECT_EQ((*hit)["result"], "entity_impact");
  EXPECT_EQ(damage_states("tank8"), std::vector<std::string>{"wreck"});  // killed at once
  // The ground under it is untouched: no crater within 100 m of the impact (x and y).
  for (const auto& e : default_run().events) {
    if (e["event"] == "crater") { EXPECT_GT(distance_2d(e["point"], (*hit)["point"]), 100) << e.dump(); }
  }
}

TEST_P(AppendixA, AutonomousVehiclesReact) {
  auto reacted = [](const std::string& id, const std::string& reaction) {
    for (const auto& e : default_run().events)
      if (e["event"] == "autonomous" && e["id"] == id && e["reaction"] == reaction) return true;
    return false;
  };
  EXPECT_TRUE(reacted("apc3", "return_fire"));
  EXPECT_TRUE(has("fire", "shooter", "apc3"));  // returned fire
  EXPECT_TRUE(reacted("jeep2", "flee"));
}

TEST_P(AppendixA, BackgroundTrafficRuns) {
  // The 500 background vehicles drive their looping routes for the whole run: nearly all are
  // 100 m or more from where they started (a few stop against a building or a wreck).
  EXPECT_EQ(default_run().background, 500);
  EXPECT_GE(default_run().background_moved, 450);
}

INSTANTIATE_TEST_SUITE_P(Methods, AppendixA, ::testing::Values("continuous", "thesis"));

// The start frame 0000-view-player1-driver.png is the thesis's Figure A.1 scene (issue 9): the
// player's tank looks over forest to hills. Checked on the world, not the pixels: trees stand
// within 3 km inside the driver camera's 60 degree field of view, and the terrain beyond 2.5 km
// rises above the driver's eye somewhere along the view (a horizon of hills, not a plain's).
TEST(DefaultScenario, StartViewLooksOverForestToHills) {
  const auto sc = world::load_scenario(test::source("scenarios/default.toml"));
  const world::World w = world::build_world(sc);
  int p = -1;
  for (size_t e = 0; e < w.ents.size(); ++e)
    if (w.ents.id[e] == "player1") p = static_cast<int>(e);
  ASSERT_GE(p, 0);
  const Vec3 at = w.ents.pos[p];
  const Vec2 fwd = heading_to_dir(w.ents.heading_deg[p]);
  int trees_in_view = 0;
  for (size_t o = 0; o < w.fixed.size(); ++o) {
    if (w.kinds[w.fixed.kind[o]].name != "tree") continue;
    const Vec2 d = (w.fixed.pos[o] - at).head<2>();
    const double r = d.norm();
    if (r < 20 || r > 3000) continue;
    if (d.dot(fwd) / r >= std::cos(30.0 * M_PI / 180.0)) ++trees_in_view;
  }
  EXPECT_GE(trees_in_view, 200) << "the start view should look over forest";
  const double eye = at.z() + 2.5;
  double best_deg = -90;
  for (int a = -30; a <= 30; a += 5) {
    const double h = (w.ents.heading_deg[p] + a) * M_PI / 180.0;
    for (double r = 2500; r <= 8000; r += 100) {
      const double x = at.x() + std::sin(h) * r, y = at.y() + std::cos(h) * r;
      if (x < 0 || y < 0 || x > 50000 || y > 50000) break;
      best_deg = std::max(best_deg, std::atan2(w.terrain.height(x, y) - eye, r) * 180.0 / M_PI);
    }
  }
  EXPECT_GT(best_deg, 0.3) << "no hill rises above the driver's eye beyond 2.5 km";
}
