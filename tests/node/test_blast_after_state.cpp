// Issue 11, observed: "Blast damage is added on top of a tree state already received, so a tree
// ends a stump on every node instead of damaged." Two nodes in one process (wire_support.hpp) run
// cultural.toml: node 1's tank shells the ground 25 m from tree tr1 at t = 0.5 s (one level:
// damaged); a round at 1.5 s lands by building b2, far from tr1; the next round near tr1 is at
// 2.5 s, so the run stops at 2 s. Node 2 receives the
// tree's cultural-feature state (damaged) and the Detonation in either order and must end with the
// tree damaged, as node 1: a received Detonation leaves fixed objects to the firing node's
// published states (node/warfare_receive.cpp, decides_fixed = false). A regression test: it passes
// on main since 4a1286e; the default order (Detonation first) and the reverse (state first).
#include <gtest/gtest.h>

#include "support/dirs.hpp"
#include "wire_support.hpp"

using namespace npsnet;

TEST(BlastAfterState, ATreeStateReceivedBeforeOrAfterTheBlastIsNotDamagedTwice) {
  const std::string file = std::string(npsnet::dirs::source()) + "/tests/multinode/data/cultural.toml";
  for (const bool state_first : {false, true}) {
    SCOPED_TRACE(state_first ? "cultural state first" : "detonation first");
    std::vector<std::vector<std::uint8_t>> later;
    int held = 0;
    test::Wire wire(file, 2, state_first ? "blast_state_first" : "blast_det_first", 2.4,
                    [&](int from, int, const std::vector<std::uint8_t>& d) {
                      if (state_first && from == 1 && test::pdu_type(d) == 3) {  // Detonation: a tick late
                        later.push_back(d);
                        ++held;
                        return 0;
                      }
                      return 1;
                    });
    for (int i = 0; i < 20; ++i) {  // 2 s
      wire.run(1);
      for (auto& d : later) wire.node(2).inbox.push_back(std::move(d));
      later.clear();
    }
    if (state_first) { ASSERT_GT(held, 0); }
    auto& n1 = wire.node(1);
    auto& n2 = wire.node(2);
    int tr1 = -1;
    for (size_t o = 0; o < n1.world().fixed.size(); ++o)
      if (n1.world().fixed.id[o] == "tr1") tr1 = static_cast<int>(o);
    ASSERT_GE(tr1, 0);
    EXPECT_EQ(n1.world().fixed.state[tr1], 1) << "node 1: damaged";
    EXPECT_EQ(n2.world().fixed.state[tr1], 1) << "node 2: damaged, as node 1 (2 = stump)";
    int craters = 0, tree_damage = 0;
    for (const auto& e : wire.events(2)) {
      if (e["event"] == "crater") ++craters;
      if (e["event"] == "damage" && e["object"] == "tr1") ++tree_damage;
    }
    EXPECT_EQ(craters, 2) << "node 2 applied the rounds of 0.5 s and 1.5 s (b2)";
    EXPECT_EQ(tree_damage, 1) << "one damage event for the tree on node 2";
  }
}
