// A run of the default scenario yields each of the thesis's Appendix A outcomes in its event log,
// with the default (continuous) method and with the thesis's own method.
#include <gtest/gtest.h>

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
  const int ticks = static_cast<int>(sc.duration_s / 0.1);
  for (int i = 0; i < ticks; ++i) sim.tick();
  r.events = log.kept();
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
  EXPECT_TRUE(has("damage", "object", "tree1"));
  for (const auto& e : default_run().events) {
    if (e["event"] == "damage" && e["object"] == "tree1") {
      EXPECT_EQ(e["to_state"], "damaged");
    } else if (e["event"] == "damage" && e["object"] == "tree2") {
      EXPECT_EQ(e["to_state"], "stump");
    }
  }
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
  bool crater = false, det = false;
  for (const auto& e : default_run().events) {
    if (e["event"] == "detonation" && e["shooter"] == "arty1") det = e["result"] == "ground_impact";
    if (e["event"] == "crater" && std::abs(e["point"][0].get<double>() - 5062.5) < 5) crater = true;
  }
  EXPECT_TRUE(det);
  EXPECT_TRUE(crater);
  EXPECT_TRUE(has("damage", "object", "tree3"));  // within the blast
}

TEST_P(AppendixA, MissileHitsTank) {
  bool hit = false;
  for (const auto& e : default_run().events)
    if (e["event"] == "detonation" && e["munition"] == "missile" && e["target"] == "tank8") hit = e["result"] == "entity_impact";
  EXPECT_TRUE(hit);
  for (const auto& e : default_run().events) {
    if (e["event"] == "damage" && e["object"] == "tank8") {
      EXPECT_EQ(e["to_state"], "wreck");
    }
  }
  // the ground under it is untouched: no crater near tank8
  for (const auto& e : default_run().events) {
    if (e["event"] == "crater") {
      EXPECT_GT(std::abs(e["point"][0].get<double>() - 9062.5), 100);
    }
  }
}

TEST_P(AppendixA, AutonomousVehiclesReact) {
  EXPECT_TRUE(has("autonomous", "id", "apc3"));
  EXPECT_TRUE(has("fire", "shooter", "apc3"));  // returned fire
  bool fled = false;
  for (const auto& e : default_run().events)
    if (e["event"] == "autonomous" && e["id"] == "jeep2") fled = e["reaction"] == "flee";
  EXPECT_TRUE(fled);
}

TEST_P(AppendixA, BackgroundTrafficRuns) {
  int bg = 0;
  for (const auto& e : default_run().events)
    if (e["event"] == "collision" && e["a"].get<std::string>().rfind("bg", 0) == 0) ++bg;
  EXPECT_GT(bg, 0);
}

INSTANTIATE_TEST_SUITE_P(Methods, AppendixA, ::testing::Values("continuous", "thesis"));
