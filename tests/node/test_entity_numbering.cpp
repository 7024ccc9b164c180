// A node owning more than 32,767 entities (issue 13): entity numbers 1-32767 under each of its
// applications, application + k * 4096 (node/ownership.hpp, net::kEntitiesPerApplication):
// ids round-trip, every block is ours on receive (echo filter, Remove Entity), and a node of
// 40,000 vehicles publishes them all.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "support/dirs.hpp"
#include "net/codec.hpp"
#include "node/net_bridge.hpp"
#include "node/ownership.hpp"
#include "node/simulation.hpp"
#include "support/scratch.hpp"

using namespace npsnet;

TEST(EntityNumbering, OwnIdsRunAcrossApplicationsPast32767) {
  node::Ownership o(net::EntityId{1, 5, 0});
  o.set_application_blocks(4);
  EXPECT_EQ(o.own_id(0), (net::EntityId{1, 5, 1}));
  EXPECT_EQ(o.own_id(32766), (net::EntityId{1, 5, 32767}));
  EXPECT_EQ(o.own_id(32767), (net::EntityId{1, 5 + 4096, 1}));
  EXPECT_EQ(o.own_id(99999), (net::EntityId{1, 5 + 3 * 4096, 99999 - 3 * 32767 + 1}));
  for (int e : {0, 1, 32766, 32767, 32768, 65533, 65534, 65535, 99999, 131067})
    EXPECT_EQ(o.own_index(o.own_id(e)), e) << e;
  EXPECT_EQ(o.own_index({1, 5 + 4 * 4096, 1}), -1);  // a fifth block is not ours
  EXPECT_EQ(o.own_index({1, 6, 1}), -1);
  EXPECT_EQ(o.own_index({2, 5, 1}), -1);
  EXPECT_EQ(o.own_index({1, 5, 0}), -1);
  EXPECT_EQ(o.own_index({1, 5, 32768}), -1);
  // The receive filter: PDUs of every block are ours (echo or clash), the next application not.
  net::ReceiveFilter f;
  f.application = 5;
  f.application_blocks = 4;
  EXPECT_TRUE(f.own_application(5));
  EXPECT_TRUE(f.own_application(5 + 3 * 4096));
  EXPECT_FALSE(f.own_application(5 + 4 * 4096));
  EXPECT_FALSE(f.own_application(6));
  EXPECT_FALSE(f.own_application(4));
}

TEST(EntityNumbering, ANodeOf40000VehiclesPublishesThemAllAndIsAddressedInItsSecondApplication) {
  world::Scenario sc = world::load_scenario(std::string(npsnet::dirs::source()).append("/scenarios/default.toml"));
  sc.background_vehicles = 40000;
  const world::World w = world::build_world(sc);
  ASSERT_GT(w.ents.size(), 32767u);
  const auto file = test::scratch_dir() / "numbering.jsonl";
  {
    node::EventLog log(file);
    node::Simulation sim(w, sc, log, 0.1);
    node::BridgeOptions bo;
    bo.offline = true;
    ::setenv("NPSNET_DIS_PACK", "1", 1);  // every first Entity State in the first tick
    node::NetBridge bridge(bo, sim, log);  // threw "entity numbers go up to 32767" before
    ::unsetenv("NPSNET_DIS_PACK");
    bridge.attach();
    sim.tick();
    EXPECT_GE(bridge.ground_es_sent(), 40000u);
    // Remove Entity to (site 1, application 1 + 4096, entity 5): entity index 32767 + 4.
    net::RemoveEntityPdu p;
    p.originating_id = {7, 7, 0};
    p.receiving_id = {1, 1 + 4096, 5};
    p.request_id = 42;
    std::array<std::uint8_t, 256> buf{};
    auto n = net::encode(p, std::span<std::uint8_t>(buf));
    ASSERT_TRUE(n);
    bridge.receive(std::span<const std::uint8_t>(buf.data(), n.value()), bridge.clock_s());
    sim.tick();
  }
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const std::string removed = "\"entity\":\"1:4097:5\"";
  ASSERT_NE(text.find("entity_removed"), std::string::npos) << "no removal";
  EXPECT_NE(text.find(removed), std::string::npos) << text.substr(text.find("entity_removed") - 20, 300);
  EXPECT_NE(text.find("\"id\":\"" + w.ents.id[32767 + 4] + "\""), std::string::npos);
  EXPECT_EQ(text.find("entity_removed", text.find("entity_removed") + 1), std::string::npos) << "one removal only";
}
