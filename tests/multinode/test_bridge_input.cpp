// A node fed hostile and unusual network input while it runs (loopback multicast, random port):
// unknown entity types get the generic model of their domain, PDUs with non-finite or off-map
// positions, Collision PDUs naming entities nobody has, cultural features of objects that do not
// exist, and garbage datagrams change nothing and crash nothing; a Detonation of an unknown
// munition type still leaves an he_round crater. The node exits 0 and counts the rejects.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <thread>

#include "peer_support.hpp"

TEST(BridgeInput, HostileAndUnknownPdusAreHandled) {
  fed::Federate f("bridge_input", "rejoin.toml", 4);
  const auto& node = f.node;
  const double start = node.start;
  auto& peer = f.peer;
  auto ecef = [&](double x, double y) { return f.ecef(x, y); };
  auto es_of = [&](std::uint16_t entity, net::EntityType type, const char* marking, net::Vec3d at) {
    auto p = fed::entity_state(peer, entity, type, marking, at);
    p.dead_reckoning.algorithm = 2;
    return p;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto ground = es_of(1, {1, 1, 99, 9, 9, 9, 0}, "x9", ecef(200, 200));
  const auto air = es_of(2, {1, 2, 99, 9, 9, 9, 0}, "air9", ecef(250, 250));
  const auto bad = es_of(3, {1, 1, 225, 1, 1, 3, 0}, "bad", {nan, 0, 0});
  auto cultural = es_of(9999, {5, 1, 0, 1, 1, 0, 0}, "tree", ecef(10, 10));
  cultural.entity_id.application = 0x8000 | 50;
  cultural.appearance = 77;
  net::CollisionPdu ghost;  // names entities nobody has
  ghost.issuing_entity_id = {9, 9, 9};
  ghost.colliding_entity_id = {1, 1, 1};
  net::CollisionPdu ghost2;
  ghost2.issuing_entity_id = peer.entity_id(1);
  ghost2.colliding_entity_id = {1, 1, 999};
  net::DetonationPdu off_map;
  off_map.exploding_entity_id = peer.entity_id(100);
  off_map.location = {0, 0, 0};
  off_map.detonation_result = 3;
  net::DetonationPdu nan_det = off_map;
  nan_det.location = {nan, nan, nan};
  net::DetonationPdu unknown_round = off_map;
  unknown_round.exploding_entity_id = peer.entity_id(101);
  unknown_round.location = ecef(300, 300);
  unknown_round.descriptor.munition_type = {2, 9, 99, 9, 9, 9, 9};
  const std::uint8_t garbage[] = {7, 1, 1, 1, 0, 0, 0, 0, 0xff, 0xff, 0, 0, 1, 2, 3};
  const std::uint8_t short_header[] = {7, 1, 1};

  // Send for 3 s from the start (the node runs 4 s): entities every 0.2 s, the rest once.
  bool once = false;
  for (int i = 0; i < 60 && lan::unix_now() < start + 3.5; ++i) {
    if (lan::unix_now() >= start + 0.2) {
      peer.send(ground), peer.send(air), peer.send(bad), peer.send(cultural);
      if (!once) {
        once = true;
        peer.send(ghost), peer.send(ghost2), peer.send(off_map), peer.send(nan_det), peer.send(unknown_round);
        peer.transport().send(garbage);
        peer.transport().send(short_header);
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(f.finished());
  const auto ev = f.events();
  int craters = 0, detonations = 0;
  std::map<std::string, nlohmann::json> joined;
  for (const auto& e : ev) {
    if (e["event"] == "entity_joined") joined[e["id"].get<std::string>()] = e;
    if (e["event"] == "crater") ++craters;
    if (e["event"] == "detonation") {
      ++detonations;
      EXPECT_EQ(e["munition"], "he_round");
    }
    if (e["event"] == "collision") ADD_FAILURE() << "no collision may come of ghost Collision PDUs: " << e.dump();
    if (e["event"] == "damage") ADD_FAILURE() << "nothing is damaged: " << e.dump();
  }
  ASSERT_TRUE(joined.count("x9"));
  EXPECT_EQ(joined["x9"]["kind"], "1:1:99:9:9:9:0");
  EXPECT_EQ(joined["x9"]["model"], "generic_ground");
  EXPECT_EQ(joined["x9"]["entity"], "1:50:1");
  ASSERT_TRUE(joined.count("air9"));
  EXPECT_EQ(joined["air9"]["model"], "generic_air");
  EXPECT_FALSE(joined.count("bad")) << "a non-finite position never enters the world";
  EXPECT_EQ(detonations, 1) << "only the on-map detonation with finite position";
  EXPECT_EQ(craters, 1);
  const std::string out = lan::read_text(node.out);
  EXPECT_NE(out.find("length_exceeds_data=1"), std::string::npos) << out;
  EXPECT_NE(out.find("truncated_header=1"), std::string::npos) << out;
}
