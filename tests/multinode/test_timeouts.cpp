// Heartbeats and timeouts (issue 11; node/remote_entities.hpp, node/net_bridge.hpp): node 1 of
// tests/multinode/data/federate.toml beside a DIS peer (peer_support.hpp, loopback multicast).
//  * A parked entity sends only its heartbeat, so two lost heartbeats time it out (DIS: 2.4
//    heartbeats) though it never left. The peer's tank p1 stands in contact with node 1's parked
//    t1, falls silent past the timeout (NPSNET_DIS_TIMEOUT_S=1.5 here) and comes back with the
//    same id at the same place: it is the same entity (entity_joined "rejoin": true) and the
//    same contact episode, not a second collision (main logged and decided it again).
//  * A lost first Entity State hid a parked vehicle until its next heartbeat (5 s): the first one
//    is now repeated twice, 0.5 s apart. The peer drops the first it hears of t1 (a lost
//    datagram) and must hear t1 again well before the heartbeat.
#include <gtest/gtest.h>

#include "peer_support.hpp"

namespace {
bool pair_is(const nlohmann::json& c, const char* a, const char* b) {
  return (c["a"] == a && c["b"] == b) || (c["a"] == b && c["b"] == a);
}
}  // namespace

TEST(Timeouts, RejoinAfterASpuriousTimeoutIsTheSameEntityAndNoSecondCollision) {
  fed::Federate f("rejoin_contact", "federate.toml", 8, {}, {"NPSNET_DIS_TIMEOUT_S=1.5"});
  const double start = f.node.start;
  auto p1 = fed::entity_state(f.peer, 1, fed::kM1a1, "p1", f.ecef(202.5, 200));  // beside t1 at (200, 200)
  p1.orientation = fed::orientation(f.world, 202.5, 200, 0);
  // Heard 0.3 s - 2 s, silent (timed out at ~3.5 s), heard again 4.5 s - 7 s; every 0.2 s.
  for (int i = 0; i < 100 && lan::unix_now() < start + 7.0; ++i) {
    const double t = lan::unix_now() - start;
    if ((t >= 0.3 && t < 2.0) || t >= 4.5) f.peer.send(p1);
    fed::sleep_until(lan::unix_now() + 0.2);
  }
  ASSERT_TRUE(f.finished());
  const auto ev = f.events();
  std::vector<nlohmann::json> joins, timeouts, collisions;
  for (const auto& e : ev) {
    if (e.value("id", "") == "p1" && e["event"] == "entity_joined") joins.push_back(e);
    if (e.value("id", "") == "p1" && e["event"] == "entity_timeout") timeouts.push_back(e);
    if (e["event"] == "collision" && pair_is(e, "t1", "p1")) collisions.push_back(e);
  }
  ASSERT_EQ(timeouts.size(), 1u) << "the silence timed p1 out";
  ASSERT_EQ(joins.size(), 2u);
  EXPECT_FALSE(joins[0].value("rejoin", false));
  EXPECT_TRUE(joins[1].value("rejoin", false)) << joins[1].dump();
  ASSERT_EQ(collisions.size(), 1u) << "one contact episode: the rejoin resumes it";
  EXPECT_LT(collisions[0]["t"].get<double>(), 2.0);
}

TEST(Timeouts, ALostFirstEntityStateIsRepeatedBeforeTheHeartbeat) {
  fed::Federate f("announce", "federate.toml", 4);
  const double start = f.node.start;
  std::vector<double> heard;  // node time of each Entity State of t1 (1:1:1), parked
  fed::poll_until(f.peer, start + 3.0, net::Overloaded{[&](const net::EntityStatePdu& p) {
                    if (p.entity_id == net::EntityId{1, 1, 1}) heard.push_back(lan::unix_now() - start);
                  }});
  ASSERT_TRUE(f.finished());
  ASSERT_GE(heard.size(), 2u) << "only one Entity State of parked t1 in 3 s: lose it and t1 is hidden until 5 s";
  // The first one lost: t1 is heard again within a second, not at its heartbeat.
  EXPECT_LT(heard[1] - heard[0], 1.0);
  EXPECT_LE(heard.size(), 4u) << "a few repeats, not a stream";
}
