// Kinematics fidelity (issue 10, defect 5), through the real path: a running node on loopback
// multicast and a peer (application 50).
//  * What we send: tank2 drives east at 10 m/s from x = 40 m until a peer's HE round hits it
//    (wreck: stopped, its Entity State goes out at once). Each Entity State's timestamp is the
//    time of the state it carries (the old node stamped the tick before: 1 m behind at 10 m/s),
//    and its acceleration is filtered (the old node sent |a| = 100 m/s^2 for the tick tank2
//    stopped in).
//  * What we receive: the peer's bmp turns right at 0.4 rad/s and 20 m/s under RPB (body-axis
//    velocity, Annex E): a circle of 50 m from (150, 150) heading north, through our parked t1
//    at (200, 200) after a quarter turn (3.93 s), from its one Entity State. The old node went
//    straight north and never met t1.
#include <gtest/gtest.h>

#include <cmath>

#include "peer_support.hpp"

TEST(FederateKinematics, SentStatesAreStampedWithTheirTimeAndFilteredAcceleration) {
  const auto w = fed::world_of("federate.toml");
  lan::Procs procs;
  // Heartbeat 0.5 s (timeout 1.2 s): tank2 sends about twice a second while it drives.
  auto node = fed::start_node(procs, "fed_sent", "federate.toml", 4.0, {}, {"NPSNET_DIS_TIMEOUT_S=1.2"});
  net::Session peer(fed::peer_config(node.port));
  std::vector<net::EntityStatePdu> tank2;
  auto visit = net::Overloaded{[&](const net::EntityStatePdu& p) {
    if (p.entity_id.site == 1 && p.entity_id.application == 1 && p.entity_id.entity == 2) tank2.push_back(p);
  }};
  fed::poll_until(peer, node.start + 2.5, visit);
  const auto t2 = tank2.empty() ? net::Vec3d{} : tank2.back().location;
  net::DetonationPdu hit;  // our he_round's type on tank2 (entity 2): it is wrecked and stops
  hit.firing_entity_id = peer.entity_id(1);
  hit.target_entity_id = {1, 1, 2};
  hit.exploding_entity_id = peer.entity_id(100);
  hit.location = t2;
  hit.descriptor = {{2, 8, 225, 2, 14, 1, 0}, 1000, 1000, 1, 0};
  hit.detonation_result = 1;
  peer.send(hit);
  fed::poll_until(peer, node.start + 4.5, visit);
  ASSERT_EQ(procs.wait(node.pid, 30.0), 0) << lan::read_text(node.out);
  bool wrecked = false;
  for (const auto& d : fed::of_type(lan::read_events(node.events), "damage"))
    if (d["object"] == "tank2" && d["to_state"] == "wreck") wrecked = true;
  EXPECT_TRUE(wrecked) << "the peer's round stops tank2";

  ASSERT_GE(tank2.size(), 3u);
  int moving = 0;
  double worst_a = 0, worst_x = 0;
  for (const auto& p : tank2) {
    const double T = net::decode_timestamp(p.header.timestamp).seconds_past_hour;
    const auto l = fed::local(w, p.location);
    const auto& a = p.dead_reckoning.linear_acceleration;
    worst_a = std::max(worst_a, std::sqrt(double(a.x) * a.x + double(a.y) * a.y + double(a.z) * a.z));
    if (T > 0 && T < 2.4) {
      ++moving;
      worst_x = std::max(worst_x, std::abs(l.x() - (40.0 + 10.0 * T)));
    }
  }
  EXPECT_GE(moving, 2) << "tank2 sends while it drives";
  EXPECT_LT(worst_x, 0.05) << "a state stamped with another time is off by 1 m at 10 m/s (one 0.1 s tick)";
  EXPECT_LT(worst_a, 20.0) << "stopping in one tick is not sent as 100 m/s^2";
  for (const auto& p : tank2) EXPECT_EQ(p.force_id, 2) << "force = \"opposing\" in the scenario";
  std::filesystem::remove_all(node.dir);
}

TEST(FederateKinematics, ReceivedRpbFollowsItsCircle) {
  const auto w = fed::world_of("federate.toml");
  const auto& frame = w.terrain.frame();
  lan::Procs procs;
  auto node = fed::start_node(procs, "fed_rpb", "federate.toml", 6.0);
  net::Session peer(fed::peer_config(node.port));
  net::EntityStatePdu bmp;
  bmp.entity_id = peer.entity_id(3);
  bmp.entity_type = {1, 1, 222, 2, 1, 0, 0};
  bmp.marking = net::make_marking("r3").value();
  bmp.location = fed::ecef(w, 150, 150);
  const auto eu = frame.to_dis_euler(npsnet::Vec3(150, 150, 0), 0.0, 0, 0);  // heading north
  bmp.orientation = {static_cast<float>(eu.x()), static_cast<float>(eu.y()), static_cast<float>(eu.z())};
  bmp.linear_velocity = {20, 0, 0};                    // body axes: forward
  bmp.dead_reckoning.algorithm = 7;                    // RPB
  bmp.dead_reckoning.angular_velocity = {0, 0, 0.4f};  // about body z (down): turning right
  fed::sleep_until(node.start + 1.0);
  const double sent = lan::unix_now() - node.start;
  peer.send(bmp);  // one Entity State: the node dead-reckons the rest (timeout 12 s)
  ASSERT_EQ(procs.wait(node.pid, 30.0), 0) << lan::read_text(node.out);
  const auto ev = lan::read_events(node.events);

  const double quarter_s = (3.14159265358979 / 2) / 0.4;
  std::vector<nlohmann::json> met;
  for (const auto& c : fed::of_type(ev, "collision"))
    if ((c["a"] == "t1" && c["b"] == "r3") || (c["a"] == "r3" && c["b"] == "t1")) met.push_back(c);
  ASSERT_FALSE(met.empty()) << "r3 under RPB must follow its circle through t1";
  const double at = met[0]["t"];
  EXPECT_GT(at, sent + quarter_s - 1.0);
  EXPECT_LT(at, sent + quarter_s + 0.3);
  EXPECT_NEAR(met[0]["point"][0].get<double>(), 200, 8.0);
  EXPECT_NEAR(met[0]["point"][1].get<double>(), 200, 8.0) << met[0].dump();
  // Its velocity at the contact is the dead-reckoned one turned out of body axes (20 m/s along
  // the circle, about east, towards t1), not (20, 0, 0) read as ECEF axes.
  EXPECT_GT(met[0]["closing_speed_mps"].get<double>(), 12.0) << met[0].dump();
  EXPECT_LT(met[0]["closing_speed_mps"].get<double>(), 20.5) << met[0].dump();
  std::filesystem::remove_all(node.dir);
}
