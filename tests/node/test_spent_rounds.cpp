// Spent rounds are reclaimed: a tank firing round after round does not grow the entity arrays
// (the slot of a round spent two ticks ago takes the next one), and every round keeps a name of
// its own in the event log.
#include <gtest/gtest.h>

#include <set>

#include "node/simulation.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

TEST(SpentRounds, AreReclaimedAndKeepTheirOwnNames) {
  auto w = test::flat_world();
  const int tank = test::add_vehicle(w, "tank", "m1a1", 500, 1000, 90, 0);
  w.index_fixed();
  const size_t vehicles = w.ents.size();
  world::Scenario sc;
  node::EventLog log;
  log.keep(true);
  node::Simulation sim(std::move(w), sc, log, 0.1);
  const int he = sim.world().kinds.find("he_round");
  const int shots = 30;
  size_t most = 0;
  for (int i = 0; i < shots * 30; ++i) {
    if (i % 30 == 0) { ASSERT_GE(sim.fire(tank, he, Vec3(900, 1000, 100), -1, ""), 0); }
    sim.tick();
    most = std::max(most, sim.world().ents.size());
  }
  std::set<std::string> rounds;
  int detonations = 0;
  for (const auto& e : log.kept()) {
    if (e["event"] == "fire") rounds.insert(e["round"].get<std::string>());
    if (e["event"] == "detonation") ++detonations;
  }
  EXPECT_EQ(rounds.size(), static_cast<size_t>(shots));  // a name per round
  EXPECT_EQ(detonations, shots);
  EXPECT_LE(most, vehicles + 2);  // without reclaiming: vehicles + 30
  EXPECT_TRUE(sim.world().valid());
}
