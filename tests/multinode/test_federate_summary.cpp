// Remote entities in the summaries (issue 10, defect 7), through the real path: a peer's two
// vehicles (one Latin-1 marking, one with a control character) and a soldier in a running node;
// SIGUSR1 in the middle of the run and the end-of-run summary each list them (id, marking made
// safe, type and kind, owner site/application, last update age, damage; the soldier, tracked and
// not in the world, as "lifeform" with its damage bits' name, was "none" and "unknown"). The old
// node printed only a count.
#include <gtest/gtest.h>
#include <signal.h>

#include <map>

#include "peer_support.hpp"

namespace {
size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST(FederateSummary, Usr1AndEndOfRunListRemoteEntities) {
  fed::Federate f("fed_summary", "federate.toml", 3.0);
  const auto& node = f.node;
  auto& peer = f.peer;
  auto r1 = fed::entity_state(peer, 1, fed::kM1a1, "", f.ecef(300, 300));
  fed::set_marking_bytes(r1, {'T', 0xC4, 'N', 'K'});  // Latin-1
  r1.appearance = 1u << 3;  // slight damage
  // an aircraft no kind has: generic_air
  auto r2 = fed::entity_state(peer, 2, {1, 2, 225, 1, 9, 9, 0}, "", f.ecef(100, 300, 500));
  fed::set_marking_bytes(r2, {'a', 0x01, 'b'});
  // a soldier (tracked, not in the world), moderately damaged: listed as what it is and its damage
  auto s3 = fed::entity_state(peer, 3, {3, 1, 225, 1, 0, 0, 0}, "inf3", f.ecef(120, 100));
  s3.appearance = 2u << 3;
  fed::sleep_until(node.start + 0.3);
  peer.send(r1), peer.send(r2), peer.send(s3);
  fed::sleep_until(node.start + 1.5);
  ASSERT_EQ(::kill(node.pid, SIGUSR1), 0);
  fed::sleep_until(node.start + 2.0);
  peer.send(r1);
  ASSERT_TRUE(f.finished());
  const std::string out = lan::read_text(node.out);
  EXPECT_EQ(count_of(out, "remote 1:50:1 \"T\xC3\x84NK\" type 1:1:225:1:1:3:0 (m1a1) owner site 1 app 50 last update "), 2u)
      << "once on SIGUSR1, once at the end:\n" << out;
  EXPECT_EQ(count_of(out, "damage damaged (appearance damage 1)"), 2u) << out;
  EXPECT_EQ(count_of(out, "remote 1:50:2 "), 2u) << out;
  EXPECT_EQ(out.find('\x01'), std::string::npos) << "no control character reaches the terminal";
  EXPECT_NE(out.find("type 1:2:225:1:9:9:0 (generic_air)"), std::string::npos) << out;
  EXPECT_EQ(count_of(out, "remote 1:50:3 \"inf3\" type 3:1:225:1:0:0:0 (lifeform) owner site 1 app 50"), 2u) << out;
  EXPECT_EQ(count_of(out, "damage moderate (appearance damage 2)"), 2u) << out;
}

// Every remote entity's damage changes and departures are logged (issue 10, defect 7), also for
// entities tracked but not put into the world (life forms, foreign cultural features) and for
// the Entity State Update form of a state. A peer (NPSNET_DIS_TIMEOUT_S=1.2) sends:
//  * inf1, a soldier: slightly damaged at 1.0 s, deactivated (Entity State) at 2.2 s;
//  * r1, an M1A1: destroyed at 1.5 s and deactivated at 2.6 s, both in Entity State Updates;
//  * bldg (a foreign building) and j2 (a jeep: a generic ground vehicle) twice, then silent:
//    they time out at about 1.8 s;
//  * inf2, a soldier heard throughout, unchanged: nothing is logged of it but its join.
// The old node logged nothing of inf1 and bldg after their joins, and nothing of r1's updates
// (its world entity even stayed active after the Update deactivated it).
TEST(FederateSummary, EveryRemoteEntitysDamageAndDepartureIsLogged) {
  fed::Federate f("fed_departures", "federate.toml", 4.0, {}, {"NPSNET_DIS_TIMEOUT_S=1.2"});
  auto& node = f.node;
  auto& peer = f.peer;
  const net::EntityType soldier{3, 1, 225, 1, 0, 0, 0};
  auto inf1 = fed::entity_state(peer, 1, soldier, "inf1", f.ecef(100, 100));
  const auto inf2 = fed::entity_state(peer, 2, soldier, "inf2", f.ecef(110, 100));
  const auto r1 = fed::entity_state(peer, 3, fed::kM1a1, "r1", f.ecef(300, 300));
  const auto bldg = fed::entity_state(peer, 4, {5, 1, 225, 3, 1, 0, 0}, "bldg", f.ecef(250, 250));
  const auto j2 = fed::entity_state(peer, 5, {1, 1, 222, 6, 1, 0, 0}, "j2", f.ecef(320, 300));
  net::EntityStateUpdatePdu r1u;
  r1u.entity_id = r1.entity_id;
  r1u.location = r1.location;
  bool inf1_gone = false, r1_gone = false;
  for (int i = 0; i < 40 && lan::unix_now() < node.start + 3.5; ++i) {
    fed::sleep_until(node.start + 0.3 + 0.1 * i);
    const double t = lan::unix_now() - node.start;
    if (i % 3 == 0) {
      peer.send(inf2);
      if (i < 6) peer.send(bldg), peer.send(j2);
      if (t < 2.2) {
        inf1.appearance = t >= 1.0 ? 1u << 3 : 0u;  // slight
        peer.send(inf1);
      }
      if (t < 1.5) peer.send(r1);
      else if (t < 2.6) r1u.appearance = 3u << 3, peer.send(r1u);  // destroyed
    }
    if (t >= 2.2 && !inf1_gone) inf1_gone = true, inf1.appearance |= net::kAppearanceDeactivated, peer.send(inf1);
    if (t >= 2.6 && !r1_gone) r1_gone = true, r1u.appearance |= net::kAppearanceDeactivated, peer.send(r1u);
  }
  ASSERT_TRUE(inf1_gone && r1_gone) << "the peer fell behind its schedule";
  ASSERT_TRUE(f.finished());
  const auto ev = f.events();
  std::map<std::string, std::vector<nlohmann::json>> of;  // id -> its events after the join
  for (const auto& e : ev) {
    const std::string type = e.value("event", "");
    if (type == "damage") of[e["object"].get<std::string>()].push_back(e);
    if (type == "entity_timeout" || type == "entity_removed") of[e["id"].get<std::string>()].push_back(e);
  }
  ASSERT_EQ(of["inf1"].size(), 2u) << "damage, then removal";
  EXPECT_EQ(of["inf1"][0]["event"], "damage");
  EXPECT_EQ(of["inf1"][0]["from_state"], "none");
  EXPECT_EQ(of["inf1"][0]["to_state"], "slight");
  EXPECT_EQ(of["inf1"][0]["tracked_as"], "lifeform");
  EXPECT_EQ(of["inf1"][0]["remote"], true);
  EXPECT_NEAR(of["inf1"][0]["t"].get<double>(), 1.0, 0.5);
  EXPECT_EQ(of["inf1"][1]["event"], "entity_removed");
  EXPECT_EQ(of["inf1"][1]["entity"], "1:50:1");
  EXPECT_EQ(of["inf1"][1]["state"], "slight");
  EXPECT_EQ(of["inf1"][1]["tracked_as"], "lifeform");
  EXPECT_NEAR(of["inf1"][1]["t"].get<double>(), 2.2, 0.5);

  ASSERT_EQ(of["r1"].size(), 2u) << "its Entity State Updates: destroyed, then deactivated";
  EXPECT_EQ(of["r1"][0]["event"], "damage");
  EXPECT_EQ(of["r1"][0]["to_state"], "wreck");
  EXPECT_EQ(of["r1"][0]["remote"], true);
  EXPECT_EQ(of["r1"][1]["event"], "entity_removed");
  EXPECT_EQ(of["r1"][1]["state"], "wreck");
  EXPECT_NEAR(of["r1"][1]["t"].get<double>(), 2.6, 0.5);

  for (const char* id : {"bldg", "j2"}) {
    SCOPED_TRACE(id);
    ASSERT_EQ(of[id].size(), 1u);
    EXPECT_EQ(of[id][0]["event"], "entity_timeout");
    EXPECT_NEAR(of[id][0]["t"].get<double>(), 0.6 + 1.2, 0.5) << "1.2 s after its last Entity State";
  }
  EXPECT_EQ(of["bldg"][0]["tracked_as"], "cultural_feature");
  EXPECT_EQ(of["bldg"][0]["kind"], "5:1:225:3:1:0:0");
  EXPECT_EQ(of["j2"][0]["kind"], "generic_ground");
  EXPECT_TRUE(of["inf2"].empty()) << of["inf2"].size();
}
