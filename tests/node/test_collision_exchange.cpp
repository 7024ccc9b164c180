// Collisions across nodes under a faulty network (issue 11; node/collision_outcome.hpp,
// node/repeat_ledger.hpp): two nodes in one process (wire_support.hpp) run lan.toml, where node
// 1's tank t1 meets node 2's APC a2 in a kill band at 11 m/s (kill) and t1b meets a2b at 30 deg
// (bounce). Node 1 decides both (lower entity ids) and issues the Collision PDUs.
//  * The Collision PDU carries the outcome: a kill is a kill on node 2 even when every Entity
//    State of node 1 saying "destroyed" is lost (before: "stop", the issuer's last appearance).
//  * A lost Collision PDU heals: node 1 repeats it every heartbeat (before: lost for good).
//  * A duplicated one applies once: every Collision PDU delivered twice at once and a third time
//    a tick later gives the same collision events and the same velocities on node 2 as every one
//    delivered once.
#include <gtest/gtest.h>

#include <map>

#include "support/dirs.hpp"
#include "node/collision_outcome.hpp"
#include "node/dis_mapping.hpp"
#include "wire_support.hpp"

using namespace npsnet;

namespace {

const std::string kLan = std::string(npsnet::dirs::source()) + "/tests/multinode/data/lan.toml";
constexpr double kTimeoutS = 2.4;  // heartbeat 1 s (Annex C ratio 5:12)
constexpr int kTicks = 70;         // 7 s: the kill at ~3 s, then 4 heartbeats

// The collision events of a log by pair "a/b" (ids sorted).
std::multimap<std::string, nlohmann::json> collisions(const std::vector<nlohmann::json>& ev) {
  std::multimap<std::string, nlohmann::json> out;
  for (const auto& e : ev)
    if (e["event"] == "collision") {
      std::string a = e["a"], b = e["b"];
      if (b < a) std::swap(a, b);
      out.emplace(a + "/" + b, e);
    }
  return out;
}

int last_state(const test::WiredNode& n, int e) {
  return static_cast<int>(n.world().kinds[n.world().ents.kind[e]].states.size()) - 1;
}

}  // namespace

TEST(CollisionExchange, OutcomeTravelsInOctet31AndOtherSimulatorsFallBack) {
  net::CollisionPdu p;
  node::set_outcome(p, world::Result::Kill);
  EXPECT_EQ(p.collision_type, node::dis::kCollisionInelastic);
  EXPECT_EQ(p.padding, node::kOutcomeKill);
  EXPECT_EQ(node::outcome_of(p, 0), world::Result::Kill) << "stated: the issuer's appearance does not matter";
  node::set_outcome(p, world::Result::Stop);
  EXPECT_EQ(node::outcome_of(p, node::dis::kDamageMask), world::Result::Stop);
  node::set_outcome(p, world::Result::Bounce);
  EXPECT_EQ(p.collision_type, node::dis::kCollisionElastic);
  EXPECT_EQ(node::outcome_of(p, node::dis::kDamageMask), world::Result::Bounce);
  // Another simulator (octet 31 zero) or an outcome that contradicts the collision type: the
  // collision type and the issuer's appearance decide, as before.
  net::CollisionPdu other;
  other.collision_type = node::dis::kCollisionInelastic;
  EXPECT_EQ(node::outcome_of(other, 0), world::Result::Stop);
  EXPECT_EQ(node::outcome_of(other, node::dis::kDamageMask), world::Result::Kill);
  other.padding = node::kOutcomeBounce;  // bounce with inelastic: not believed
  EXPECT_EQ(node::outcome_of(other, 0), world::Result::Stop);
  other.collision_type = node::dis::kCollisionElastic;
  other.padding = node::kOutcomeKill;  // kill with elastic: not believed
  EXPECT_EQ(node::outcome_of(other, node::dis::kDamageMask), world::Result::Bounce);
  other.padding = 200;
  EXPECT_EQ(node::outcome_of(other, 0), world::Result::Bounce);
}

TEST(CollisionExchange, AKillIsAKillWithoutTheIssuersDestroyedEntityState) {
  int dropped = 0;
  // Every Entity State of node 1 whose appearance says destroyed is lost.
  test::Wire wire(kLan, 2, "kill", kTimeoutS, [&](int from, int, const std::vector<std::uint8_t>& d) {
    if (from == 1 && test::pdu_type(d) == 1 && test::es_damage(d) == 3) return ++dropped, 0;
    return 1;
  });
  wire.run(kTicks);
  ASSERT_GT(dropped, 0) << "node 1's tank was destroyed and said so";
  const auto c1 = collisions(wire.events(1));
  const auto c2 = collisions(wire.events(2));
  ASSERT_EQ(c1.count("a2/t1"), 1u);
  EXPECT_EQ(c1.find("a2/t1")->second["outcome_a"], "kill");
  ASSERT_EQ(c2.count("a2/t1"), 1u) << "node 2 records the collision node 1 decided";
  EXPECT_EQ(c2.find("a2/t1")->second["outcome_a"], "kill");
  EXPECT_EQ(c2.find("a2/t1")->second["outcome_b"], "kill");
  auto& n2 = wire.node(2);
  const int a2 = n2.index("a2");
  EXPECT_EQ(n2.world().ents.state[a2], last_state(n2, a2)) << "node 2's APC is a wreck";
}

TEST(CollisionExchange, ALostCollisionPduHealsByTheIssuersRepeat) {
  int lost = 0;
  test::Wire wire(kLan, 2, "lost", kTimeoutS, [&](int from, int, const std::vector<std::uint8_t>& d) {
    if (from == 1 && test::pdu_type(d) == 4 && lost < 2) return ++lost, 0;  // both first Collision PDUs
    return 1;
  });
  wire.run(kTicks);
  ASSERT_EQ(lost, 2) << "node 1 announced two collisions";
  const auto c2 = collisions(wire.events(2));
  ASSERT_EQ(c2.count("a2/t1"), 1u) << "the kill reached node 2 by a repeat";
  EXPECT_EQ(c2.find("a2/t1")->second["outcome_b"], "kill");
  ASSERT_EQ(c2.count("a2b/t1b"), 1u) << "the bounce reached node 2 by a repeat";
  EXPECT_EQ(c2.find("a2b/t1b")->second["outcome_a"], "bounce");
  auto& n2 = wire.node(2);
  const int a2 = n2.index("a2");
  EXPECT_EQ(n2.world().ents.state[a2], last_state(n2, a2));
}

TEST(CollisionExchange, ADuplicatedCollisionPduAppliesOnce) {
  // copies of each Collision PDU at once, and once more a tick later when `late`.
  auto run = [](int copies, bool late, const std::string& tag, Vec3& a2b_vel, float& a2b_cruise) {
    std::vector<std::vector<std::uint8_t>> again;
    test::Wire wire(kLan, 2, tag, kTimeoutS, [&](int from, int, const std::vector<std::uint8_t>& d) {
      if (test::pdu_type(d) != 4) return 1;
      if (late && from == 1) again.push_back(d);
      return copies;
    });
    for (int i = 0; i < kTicks; ++i) {
      wire.run(1);
      for (auto& d : again) wire.node(2).inbox.push_back(std::move(d));
      again.clear();
    }
    auto& n2 = wire.node(2);
    a2b_vel = n2.world().ents.vel[n2.index("a2b")];
    a2b_cruise = n2.world().ents.cruise_mps[n2.index("a2b")];
    return collisions(wire.events(2));
  };
  Vec3 once_vel, twice_vel;
  float once_cruise = 0, twice_cruise = 0;
  const auto once = run(1, false, "once", once_vel, once_cruise);
  const auto twice = run(2, true, "twice", twice_vel, twice_cruise);
  EXPECT_EQ(once.count("a2/t1"), 1u);
  EXPECT_EQ(once.count("a2b/t1b"), 1u);
  EXPECT_EQ(twice.count("a2/t1"), 1u) << "a duplicated Collision PDU is one collision";
  EXPECT_EQ(twice.count("a2b/t1b"), 1u) << "a duplicated Collision PDU is one collision";
  EXPECT_EQ(twice_vel, once_vel) << "the bounce is applied to node 2's APC once";
  EXPECT_EQ(twice_cruise, once_cruise);
}
