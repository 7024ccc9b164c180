// What a node killed and restarted gets back (issue 11, README "Faults": joining a running
// exercise): two nodes in one process (wire_support.hpp) run lan.toml, where node 1's tank t1 and
// node 2's APC a2 kill each other at about t = 3 s (node 1 decides: it issues the Collision PDU,
// issuing t1, colliding a2, outcome kill) and t1b bounces off a2b. One node is killed at 4 s and
// started again at 8 s: it catches its scenario up headless (no network), so its vehicle is
// intact at its scripted place, and the past comes from the network.
//  * Node 1 restarted: node 2 adopted node 1's Collision PDUs (repeat_ledger.hpp) and repeats
//    them; their issuing entity is node 1's own t1. They are no identity clash: delivered, the
//    kill applies to t1 once, and the echo filter still counts a clash for other PDU types.
//  * Node 2 restarted: node 1 repeats its Collision PDU naming a2 as the colliding entity: a2
//    comes back destroyed (this healed before: the repeat waits for t1's Entity State).
//  * Node 2 restarted while node 1 is dead too (three nodes; node 3 adopted node 1's PDU): t1
//    is never heard again, so the PDU waited for it for ever and a2 came back intact. A
//    collision of ours dated before the join waits one DIS timeout for the other entity, then
//    applies without it.
//  * restart.toml: node 1's round hits node 2's v2 at t ~ 1.3 s; node 2 restarts at 8 s while its
//    m2 passes within the blast radius of that point (it was 90 m away when the round fell). The
//    firer's repeat destroys v2 again (the direct hit the PDU names; this healed before), and
//    blasts none of node 2's vehicles: before, m2 was damaged by a round that fell 7 s earlier.
//  * With --checkpoint (node/checkpoint.hpp; Wire::keep_checkpoint): the catch-up puts the own
//    vehicles back as the checkpoint has them. lan.toml, node 2 restarted: a2 comes back a wreck
//    where it was killed (without it: more than 50 m on, where its route took it). restart_blast.toml:
//    node 2's parked d2 was damaged by the blast of the round that hit v2; it comes back damaged
//    (without it: intact, the Detonation names only v2). Each test runs the same exercise
//    without the checkpoint too and asserts the old answer, so it fails if the restore does not
//    happen. restart_round.toml: node 2's round (fired at 1 s, falls at 7 s) is in flight when
//    node 2 is killed; the checkpoint holds it, the restart flies it on and its Detonation goes
//    out under the Fire PDU's event id and munition id: node 1 gets the crater once, whether the
//    round fell while node 2 was catching up (sent at the join) or after (sent live). Without
//    the checkpoint no node ever gets that Detonation (its Fire went out, nobody holds the round).
#include <gtest/gtest.h>

#include <algorithm>

#include "support/dirs.hpp"
#include "wire_support.hpp"

using namespace npsnet;

namespace {

const std::string kLan = std::string(npsnet::dirs::source()) + "/tests/multinode/data/lan.toml";
const std::string kRestart = std::string(npsnet::dirs::source()) + "/tests/multinode/data/restart.toml";
const std::string kRestartBlast = std::string(npsnet::dirs::source()) + "/tests/multinode/data/restart_blast.toml";
const std::string kRestartRound = std::string(npsnet::dirs::source()) + "/tests/multinode/data/restart_round.toml";
constexpr double kTimeoutS = 2.4;  // heartbeat 1 s (Annex C ratio 5:12)
constexpr int kKillAt = 40, kDeadFor = 40, kAfter = 40;  // ticks of 0.1 s

int count(const std::vector<nlohmann::json>& ev, const std::string& type, const std::string& pair = "") {
  int n = 0;
  for (const auto& e : ev)
    if (e["event"] == type && (pair.empty() || e.value("a", "") + "/" + e.value("b", "") == pair ||
                               e.value("b", "") + "/" + e.value("a", "") == pair))
      ++n;
  return n;
}

// Node k (run kKillAt ticks) killed, kDeadFor ticks on, restarted, kAfter ticks on.
void kill_restart(test::Wire& wire, int k) {
  wire.kill(k);
  wire.run(kDeadFor);
  wire.restart(k, kKillAt + kDeadFor);
  wire.run(kAfter);
}

// Runs lan.toml with node `restarted` killed at kKillAt and restarted kDeadFor ticks later.
void kill_and_restart(test::Wire& wire, int restarted) {
  wire.run(kKillAt);
  ASSERT_EQ(count(wire.events(restarted), "collision", "t1/a2"), 1) << "t1 and a2 collided before the kill";
  kill_restart(wire, restarted);
}

}  // namespace

TEST(RestartedNode, AnAdoptedCollisionOfItsOwnVehicleIsDeliveredAndApplied) {
  test::Wire wire(kLan, 2, "own_adopted", kTimeoutS, [](int, int, const std::vector<std::uint8_t>&) { return 1; });
  kill_and_restart(wire, 1);
  auto& n1 = wire.node(1);
  const auto ev = wire.events(1);
  EXPECT_EQ(n1.bridge->counters().own_id_clash, 0u) << "node 2's adopted repeat of our Collision PDU is no clash";
  EXPECT_EQ(count(ev, "id_clash"), 0);
  const int t1 = n1.index("t1");
  EXPECT_EQ(n1.world().ents.state[t1], test::destroyed(n1, "t1")) << "t1 was killed in that collision before the restart";
  EXPECT_EQ(n1.world().ents.vel[t1], Vec3::Zero());
  EXPECT_EQ(count(ev, "collision", "t1/a2"), 1) << "applied once, though node 2 repeats it every heartbeat";
  EXPECT_EQ(count(ev, "collision", "t1b/a2b"), 1) << "the bounce of t1b is recorded once";
  // Node 2 sees t1 destroyed again (the restarted node's Entity States).
  auto& n2 = wire.node(2);
  EXPECT_EQ(n2.world().ents.state[n2.index("t1")], test::destroyed(n2, "t1"));
}

TEST(RestartedNode, ItsVehicleKilledInAnotherNodesCollisionComesBackKilled) {
  test::Wire wire(kLan, 2, "other_issued", kTimeoutS, [](int, int, const std::vector<std::uint8_t>&) { return 1; });
  kill_and_restart(wire, 2);
  auto& n2 = wire.node(2);
  const auto ev = wire.events(2);
  const int a2 = n2.index("a2");
  EXPECT_EQ(n2.world().ents.state[a2], test::destroyed(n2, "a2")) << "a2 was killed by node 1's collision before the restart";
  EXPECT_EQ(n2.world().ents.vel[a2], Vec3::Zero());
  EXPECT_EQ(count(ev, "collision", "t1/a2"), 1) << "applied once, though node 1 repeats it every heartbeat";
  auto& n1 = wire.node(1);
  EXPECT_EQ(n1.world().ents.state[n1.index("a2")], test::destroyed(n1, "a2"));
}

TEST(RestartedNode, ItsVehicleKilledByADeadNodesAdoptedCollisionComesBackKilled) {
  test::Wire wire(kLan, 3, "issuer_dead", kTimeoutS, [](int, int, const std::vector<std::uint8_t>&) { return 1; });
  wire.run(kKillAt);
  ASSERT_EQ(count(wire.events(3), "collision", "t1/a2"), 1) << "node 3 recorded node 1's collision";
  wire.kill(1);
  kill_restart(wire, 2);
  auto& n2 = wire.node(2);
  const int a2 = n2.index("a2");
  EXPECT_EQ(n2.world().ents.state[a2], test::destroyed(n2, "a2")) << "node 3's adopted repeat names a2 killed";
  EXPECT_EQ(n2.world().ents.vel[a2], Vec3::Zero());
  auto& n3 = wire.node(3);
  EXPECT_EQ(n3.world().ents.state[n3.index("a2")], test::destroyed(n3, "a2")) << "node 3 sees a2 destroyed again";
}

TEST(RestartedNode, APastRoundDestroysTheVehicleItHitAndBlastsNoneOfOurs) {
  test::Wire wire(kRestart, 2, "past_round", kTimeoutS, [](int, int, const std::vector<std::uint8_t>&) { return 1; });
  wire.run(kKillAt);
  {
    auto& n2 = wire.node(2);
    ASSERT_EQ(n2.world().ents.state[n2.index("v2")], test::destroyed(n2, "v2")) << "g1's round hit v2";
    ASSERT_EQ(n2.world().ents.state[n2.index("m2")], 0) << "m2 was out of the blast";
  }
  kill_restart(wire, 2);
  auto& n2 = wire.node(2);
  EXPECT_EQ(n2.world().ents.state[n2.index("v2")], test::destroyed(n2, "v2")) << "the repeated Detonation names v2 hit";
  EXPECT_EQ(n2.world().ents.state[n2.index("m2")], 0) << "m2 was 90 m away when the round fell";
  EXPECT_EQ(count(wire.events(2), "detonation"), 1) << "applied once";
}

TEST(RestartedNode, WithACheckpointItsKilledVehicleComesBackWhereItStood) {
  Vec3 wreck[2];
  for (const bool keep : {false, true}) {
    test::Wire wire(kLan, 2, keep ? "ckpt_wreck" : "ckpt_wreck_none", kTimeoutS,
                    [](int, int, const std::vector<std::uint8_t>&) { return 1; });
    if (keep) wire.keep_checkpoint(2);
    wire.run(kKillAt);
    {
      auto& n2 = wire.node(2);
      const int a2 = n2.index("a2");
      ASSERT_EQ(n2.world().ents.state[a2], test::destroyed(n2, "a2")) << "t1 and a2 killed each other at ~3 s";
      wreck[keep] = n2.world().ents.pos[a2];
    }
    kill_restart(wire, 2);
    auto& n2 = wire.node(2);
    const int a2 = n2.index("a2");
    EXPECT_EQ(n2.world().ents.state[a2], test::destroyed(n2, "a2"));
    EXPECT_EQ(n2.world().ents.vel[a2], Vec3::Zero());
    const Vec3 here = n2.world().ents.pos[a2];
    auto& n1 = wire.node(1);
    const Vec3 copy = n1.world().ents.pos[n1.index("a2")];
    if (keep) {
      EXPECT_EQ(here, wreck[keep]) << "the wreck is back where it was killed, to the bit";
      EXPECT_LT((copy - wreck[keep]).norm(), 0.5) << "node 1 sees it there too";
      EXPECT_EQ(count(wire.events(2), "collision", "t1/a2"), 1) << "and the collision is not applied twice";
    } else {
      EXPECT_GT((here - wreck[keep]).norm(), 50.0) << "without the checkpoint the catch-up drove a2 on along its route";
    }
  }
  EXPECT_EQ(wreck[0], wreck[1]) << "both runs are the same exercise until the kill";
}

TEST(RestartedNode, WithACheckpointItsBlastDamagedVehicleComesBackDamaged) {
  for (const bool keep : {false, true}) {
    test::Wire wire(kRestartBlast, 2, keep ? "ckpt_blast" : "ckpt_blast_none", kTimeoutS,
                    [](int, int, const std::vector<std::uint8_t>&) { return 1; });
    if (keep) wire.keep_checkpoint(2);
    wire.run(kKillAt);
    {
      auto& n2 = wire.node(2);
      ASSERT_EQ(n2.world().ents.state[n2.index("v2")], test::destroyed(n2, "v2")) << "g1's round hit v2";
      ASSERT_EQ(n2.world().ents.state[n2.index("d2")], 1) << "its blast damaged d2, 25 m away";
    }
    kill_restart(wire, 2);
    auto& n2 = wire.node(2);
    auto& n1 = wire.node(1);
    EXPECT_EQ(n2.world().ents.state[n2.index("v2")], test::destroyed(n2, "v2"));
    EXPECT_EQ(n2.world().ents.state[n2.index("d2")], keep ? 1 : 0)
        << (keep ? "the checkpoint keeps d2's blast damage" : "without it the restart forgets it (the old answer)");
    EXPECT_EQ(n1.world().ents.state[n1.index("d2")], keep ? 1 : 0) << "node 1 sees what node 2 now says";
    EXPECT_EQ(count(wire.events(2), "detonation"), 1) << "the repeated Detonation is applied once";
  }
}

namespace {
// restart_round.toml with node 2 killed at tick `kill` and restarted at tick `back`, with or without
// its checkpoint. Node 1's world and events, and node 2's Fire and Detonation identities (octets
// 24-35: munition entity id and event id, the same place in both PDUs).
struct RoundRun {
  int detonations = 0, craters = 0;
  Vec3 crater = Vec3::Zero();
  std::vector<std::vector<std::uint8_t>> fire_ids, detonation_ids;  // node 2's, as sent
  int round_lines = -1;  // rounds in node 2's checkpoint at the kill
};
RoundRun round_run(bool keep, int kill, int back, const std::string& tag) {
  RoundRun out;
  test::Wire wire(kRestartRound, 2, tag, kTimeoutS, [&out](int from, int to, const std::vector<std::uint8_t>& d) {
    if (from == 2 && to == 1 && d.size() >= 36 && (test::pdu_type(d) == 2 || test::pdu_type(d) == 3)) {
      auto& ids = test::pdu_type(d) == 2 ? out.fire_ids : out.detonation_ids;
      const std::vector<std::uint8_t> id(d.begin() + 24, d.begin() + 36);
      if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
    }
    return 1;
  });
  if (keep) wire.keep_checkpoint(2);
  wire.run(kill);
  if (keep) {
    wire.node(2).checkpoint->flush();  // its thread writes it
    const auto c = node::read_checkpoint(wire.node(2).checkpoint_file);
    out.round_lines = c ? static_cast<int>(c->rounds.size()) : -1;
  }
  wire.kill(2);
  wire.run(back - kill);
  wire.restart(2, back);
  wire.run(200 - back);
  for (const auto& e : wire.events(1)) {
    if (e["event"] == "detonation") ++out.detonations;
    if (e["event"] == "crater") ++out.craters, out.crater = Vec3(e["point"][0], e["point"][1], e["point"][2]);
  }
  return out;
}
}  // namespace

TEST(RestartedNode, WithACheckpointItsRoundInFlightAtTheKillStillFalls) {
  struct Case {
    int kill, back;
    const char* when;
  };
  for (const Case c : {Case{40, 80, "falls while node 2 catches up"}, Case{25, 45, "falls after node 2 joined"}}) {
    SCOPED_TRACE(c.when);
    const RoundRun none = round_run(false, c.kill, c.back, std::string("round_none_") + std::to_string(c.kill));
    EXPECT_EQ(none.fire_ids.size(), 1u) << "the Fire PDU went out before the kill";
    EXPECT_EQ(none.detonations, 0) << "without the checkpoint the round is lost for good (the old answer)";
    const RoundRun kept = round_run(true, c.kill, c.back, std::string("round_kept_") + std::to_string(c.kill));
    EXPECT_EQ(kept.round_lines, 1) << "the checkpoint at the kill holds the round in flight";
    EXPECT_EQ(kept.detonations, 1) << "node 1 gets the Detonation, once, repeats and all";
    EXPECT_EQ(kept.craters, 1);
    EXPECT_LT((kept.crater - Vec3(3999.926, 1000.0, 100.0)).norm(), 0.01) << "where the round would have fallen";
    ASSERT_EQ(kept.fire_ids.size(), 1u);
    ASSERT_EQ(kept.detonation_ids.size(), 1u) << "every copy of the Detonation is the same";
    EXPECT_EQ(kept.detonation_ids[0], kept.fire_ids[0]) << "the Fire's munition id and event id";
  }
}

// Relative DIS timestamps wrap at the hour: node 1's repeat of its t1/a2 Collision PDU (dated
// t ~ 3 s) reached node 2, restarted 40 min into the exercise, dated "20 min after the join", and
// was applied as a new collision (a bounce of then pushed on now). A PDU of a new event is dated
// within seconds of now (the nodes share the scenario clock); one dated further from now, either
// way, repeats the past.
TEST(RestartedNode, ACollisionMoreThanHalfAnHourBeforeTheJoinIsStillThePast) {
  test::Wire wire(kLan, 2, "past_wrap", kTimeoutS, [](int, int, const std::vector<std::uint8_t>&) { return 1; });
  wire.run(kKillAt);
  ASSERT_EQ(count(wire.events(2), "collision", "t1/a2"), 1);
  wire.kill(2);
  constexpr int kBack = 24000;  // 2,400 s: 40 min
  wire.run(kBack - kKillAt);
  wire.restart(2, kBack);
  wire.run(kAfter);
  auto& n2 = wire.node(2);
  const auto ev = wire.events(2);
  ASSERT_EQ(count(ev, "collision", "t1/a2"), 1) << "node 1's repeat is applied once";
  for (const auto& e : ev) {  // (t1b and a2b, parked in the map's corner by then, may touch anew after the join)
    if (e["event"] == "collision" && e["a"] == "t1" && e["b"] == "a2") {
      EXPECT_EQ(e.value("method", ""), "network_past") << e.dump();
    }
  }
  EXPECT_EQ(n2.world().ents.state[n2.index("a2")], test::destroyed(n2, "a2"));
}
