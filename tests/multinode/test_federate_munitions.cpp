// Munitions of other simulators (issue 10, defect 3), through the real path: a peer (application
// 50) sends Detonation PDUs of each warhead class and result into a running node on loopback
// multicast. On the old node every one of them was our HE round: a 6 m crater and damage.
// Now (models/munitions.toml, node/munition_codes.hpp): smoke, illumination, practice and
// small-arms kinetic rounds make no crater and no damage, a dud nothing, an airburst no crater
// (but its blast), an HE ground impact its crater.
#include <gtest/gtest.h>

#include <map>

#include "peer_support.hpp"

using nlohmann::json;

namespace {

struct Shot {
  const char* what;
  double at_s;                 // scenario time it is sent
  net::EntityType type;
  std::uint16_t warhead, fuse, quantity;
  std::uint8_t result;
  double x, y, agl;
  bool on_t1;                  // entity impact on our t1
  const char* munition;        // expected event fields
  const char* result_name;
};

}  // namespace

TEST(FederateMunitions, EachWarheadClassAndResultHasItsEffect) {
  fed::Federate f("fed_munitions", "federate.toml", 4.5);
  const auto& node = f.node;
  auto& peer = f.peer;
  const net::EntityType he_type = fed::kHeRound;
  const net::EntityType smoke_type{2, 9, 225, 2, 5, 4, 0};  // battlefield support, 60 mm: not in any table
  const net::EntityType rifle_type{2, 8, 225, 2, 1, 0, 0};  // a ballistic anti-personnel round
  // t1 (ours) is parked at (200, 200); he_round: blast 30 m (inner third destroys), crater 6 m.
  const std::vector<Shot> shots{
      {"smoke", 0.5, smoke_type, 2000, 1000, 1, 3, 205, 200, 0.2, false, "smoke", "ground_impact"},
      {"illumination", 0.8, smoke_type, 3000, 2000, 1, 5, 200, 200, 300, false, "illumination", "airburst"},
      {"practice", 1.1, he_type, 4000, 1000, 1, 1, 200, 200, 1.0, true, "practice", "entity_impact"},
      {"kinetic", 1.4, rifle_type, 5000, 1000, 30, 1, 200, 200, 1.0, true, "kinetic", "entity_impact"},
      {"dud", 1.7, he_type, 1000, 1000, 1, 6, 203, 200, 0.2, false, "he_round", "dud"},
      {"airburst", 2.2, he_type, 1000, 3000, 1, 25, 200, 200, 8.0, false, "he_round", "airburst"},
      {"he", 2.8, he_type, 1000, 1000, 1, 3, 320, 320, 0.2, false, "he_round", "ground_impact"},
  };
  size_t next = 0;
  while (next < shots.size() && lan::unix_now() < node.start + 4.0) {
    const Shot& s = shots[next];
    fed::sleep_until(node.start + s.at_s);
    peer.send(fed::detonation(peer, static_cast<std::uint16_t>(next), s.type, s.warhead, s.fuse, s.quantity, s.result,
                              f.ecef(s.x, s.y, s.agl), s.on_t1 ? net::EntityId{1, 1, 1} : net::EntityId{}));
    ++next;
  }
  ASSERT_EQ(next, shots.size()) << "the peer fell behind its schedule";
  ASSERT_TRUE(f.finished());
  const auto ev = f.events();

  const auto dets = fed::of_type(ev, "detonation");
  ASSERT_EQ(dets.size(), shots.size());
  double airburst_t = -1;
  for (size_t i = 0; i < shots.size(); ++i) {
    SCOPED_TRACE(shots[i].what);
    EXPECT_EQ(dets[i]["round"], "rd1:50:" + std::to_string(100 + i)) << "in the order sent";
    EXPECT_EQ(dets[i]["munition"], shots[i].munition);
    EXPECT_EQ(dets[i]["result"], shots[i].result_name);
    EXPECT_EQ(dets[i]["quantity"], shots[i].quantity);
    EXPECT_EQ(dets[i]["target"], shots[i].on_t1 ? "t1" : "");
    if (std::string(shots[i].what) == "airburst") airburst_t = dets[i]["t"];
  }
  EXPECT_EQ(dets[0]["warhead"], "smoke");
  EXPECT_EQ(dets[1]["fuse"], "timed");
  EXPECT_EQ(dets[3]["warhead"], "kinetic");

  // One crater: the HE ground impact's, where it landed.
  const auto craters = fed::of_type(ev, "crater");
  ASSERT_EQ(craters.size(), 1u) << "smoke, illumination, practice, kinetic, dud and airburst make none";
  EXPECT_NEAR(craters[0]["point"][0].get<double>(), 320, 0.5);
  EXPECT_NEAR(craters[0]["point"][1].get<double>(), 320, 0.5);
  EXPECT_EQ(craters[0]["radius_m"], 6.0);

  // t1 is damaged once: by the HE airburst 8 m above it (blast), not by the rounds before.
  std::vector<json> t1_damage;
  for (const auto& d : fed::of_type(ev, "damage"))
    if (d["object"] == "t1") t1_damage.push_back(d);
  ASSERT_EQ(t1_damage.size(), 1u) << "only the airburst's blast damages t1";
  EXPECT_EQ(t1_damage[0]["to_state"], "wreck");
  EXPECT_EQ(t1_damage[0]["t"], airburst_t);
}

// A burst (issue 10, defect 3: quantity), through the real path. A peer's Fire and Detonation
// of `quantity` rounds at one point: each round adds its blast levels (world/changes.hpp
// DetonationRecord::quantity, collision::detonate): a vehicle in blast reach outside the inner
// third goes `quantity` states on (inner third: destroyed), a fixed object `quantity` times the
// levels of its distance; one crater whatever the quantity; the Fire is logged with its quantity
// (its effect comes with its Detonation). HE rounds (blast 30 m) land 18 m from two of our
// tanks: 2 rounds beside t1 wreck it (intact -> wreck), 1 round beside tank2 damages it; a burst
// of 3 small-arms rounds (kinetic) on tank2 changes nothing. The old node (or one that ignores
// the quantity) left t1 only damaged.
TEST(FederateMunitions, BurstOfQuantityRoundsAddsEachRoundsBlast) {
  fed::Federate f("fed_burst", "federate.toml", 3.5);
  auto& node = f.node;
  auto& peer = f.peer;
  const net::EntityType he_type = fed::kHeRound;
  const net::EntityType rifle_type{2, 8, 225, 2, 1, 0, 0};  // a ballistic anti-personnel round
  std::uint16_t event = 0;
  auto fire_and_detonate = [&](net::EntityType type, std::uint16_t warhead, std::uint16_t quantity, double x, double y,
                               std::uint8_t result, net::EntityId target) {  // the rounds leave and land at once
    const auto d = fed::detonation(peer, ++event, type, warhead, 1000, quantity, result, f.ecef(x, y, 0.2), target);
    net::FirePdu fire;
    fire.firing_entity_id = d.firing_entity_id;
    fire.target_entity_id = target;
    fire.munition_id = d.exploding_entity_id;
    fire.event_id = d.event_id;
    fire.location = f.ecef(20, 20, 2.0);  // the peer's gun, off in a corner
    fire.descriptor = d.descriptor;
    peer.send(fire);
    peer.send(d);
  };
  // tank2 drives east from (40, 360) at 10 m/s: at 1.0 s it is at x = 50.
  fed::sleep_until(node.start + 0.5);
  fire_and_detonate(he_type, 1000, 2, 218, 200, 3, {});  // 2 HE rounds 18 m east of t1
  fed::sleep_until(node.start + 1.0);
  const double t2_x = 40 + 10 * (lan::unix_now() - node.start);
  fire_and_detonate(he_type, 1000, 1, t2_x, 378, 3, {});  // 1 HE round 18 m north of tank2
  fed::sleep_until(node.start + 2.0);
  fire_and_detonate(rifle_type, 5000, 3, 40 + 10 * (lan::unix_now() - node.start), 360, 1, {1, 1, 2});
  ASSERT_LT(lan::unix_now(), node.start + 2.5) << "the peer fell behind its schedule";
  ASSERT_TRUE(f.finished());
  const auto ev = f.events();

  const auto fires = fed::of_type(ev, "fire");
  ASSERT_EQ(fires.size(), 3u);
  EXPECT_EQ(fires[0]["quantity"], 2);
  EXPECT_EQ(fires[0]["munition"], "he_round");
  EXPECT_EQ(fires[2]["quantity"], 3);
  EXPECT_EQ(fires[2]["warhead"], "kinetic");
  const auto dets = fed::of_type(ev, "detonation");
  ASSERT_EQ(dets.size(), 3u);
  EXPECT_EQ(dets[0]["quantity"], 2);
  EXPECT_EQ(dets[2]["quantity"], 3);
  EXPECT_EQ(dets[2]["target"], "tank2");
  EXPECT_EQ(fed::of_type(ev, "crater").size(), 2u) << "one crater per HE burst, none for the small arms";

  std::map<std::string, std::vector<std::string>> states;
  for (const auto& d : fed::of_type(ev, "damage")) states[d["object"].get<std::string>()].push_back(d["to_state"]);
  EXPECT_EQ(states["t1"], (std::vector<std::string>{"wreck"})) << "2 rounds: two levels at once";
  EXPECT_EQ(states["tank2"], (std::vector<std::string>{"damaged"})) << "1 round: one level; small arms: none";
}
