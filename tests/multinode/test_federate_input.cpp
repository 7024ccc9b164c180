// A node and a foreign DIS peer (issue 10, defects 1, 2, 3, 7), through the real path: PDUs sent
// by a net::Session into a running `npsnet run --net` on loopback multicast.
#include <gtest/gtest.h>

#include <random>

#include "peer_support.hpp"

namespace {

using nlohmann::json;

// An M1A1, as our kinds file has it, standing at `at`.
net::EntityStatePdu vehicle_es(const net::Session& peer, std::uint16_t entity, const char* marking, net::Vec3d at) {
  return fed::entity_state(peer, entity, fed::kM1a1, marking, at);
}

// Every line of the log is JSON (read_events throws otherwise) and valid UTF-8 (dump throws).
std::vector<json> read_valid_log(const std::filesystem::path& f) {
  std::vector<json> ev;
  EXPECT_NO_THROW(ev = lan::read_events(f));
  for (const auto& e : ev) EXPECT_NO_THROW((void)e.dump());
  return ev;
}

}  // namespace

// Defect 1: a Latin-1 marking ("TÄNK", byte 0xC4) killed the node with a JSON UTF-8 error; any
// other bytes (control characters, no NUL, unknown character sets) and randomly corrupted PDUs
// of every type must leave it running. Markings are decoded by their character set.
TEST(FederateInput, AnyMarkingAndAnyBytesLeaveTheNodeRunning) {
  fed::Federate f("fed_bytes", "federate.toml", 4);
  const auto& node = f.node;
  auto& peer = f.peer;

  auto latin = vehicle_es(peer, 1, "x", f.ecef(300, 300));
  fed::set_marking_bytes(latin, {'T', 0xC4, 'N', 'K'});
  auto controls = vehicle_es(peer, 2, "x", f.ecef(320, 300));
  fed::set_marking_bytes(controls, {0x01, 'A', 0x7F, 0x9B, '"', '\\', 0xFF, 0x0A, 0xC3, 0x28, 0x80});  // no NUL
  auto chevron = vehicle_es(peer, 3, "12", f.ecef(340, 300));
  chevron.marking.character_set = 3;
  auto unknown_set = vehicle_es(peer, 4, "x", f.ecef(360, 300));
  unknown_set.marking.character_set = 200;
  unknown_set.marking.characters[0] = static_cast<char>(0xE9);

  // Corrupted copies of valid PDUs of each type (fixed seed: the same bytes every run).
  std::vector<std::vector<std::uint8_t>> seeds;
  auto bytes = [](const auto& pdu) {
    std::vector<std::uint8_t> b(net::encoded_size(pdu));
    (void)net::encode(pdu, std::span<std::uint8_t>(b));
    return b;
  };
  net::FirePdu fire;
  fire.firing_entity_id = peer.entity_id(1);
  fire.location = f.ecef(300, 300);
  net::DetonationPdu det;
  det.firing_entity_id = peer.entity_id(1);
  det.location = f.ecef(200, 100);
  det.detonation_result = 3;
  net::CollisionPdu col;
  col.issuing_entity_id = peer.entity_id(1);
  col.colliding_entity_id = {1, 1, 1};
  net::EntityStateUpdatePdu esu;
  esu.entity_id = peer.entity_id(1);
  esu.location = f.ecef(300, 300);
  seeds = {bytes(latin), bytes(fire), bytes(det), bytes(col), bytes(esu)};
  std::mt19937 rng(1278);
  std::vector<std::vector<std::uint8_t>> corrupt;
  for (int i = 0; i < 1500; ++i) {
    auto b = seeds[i % seeds.size()];
    const int flips = 1 + static_cast<int>(rng() % 8);
    for (int k = 0; k < flips; ++k) {
      const size_t at = 12 + rng() % (b.size() - 12);  // keep the header, so the PDU gets decoded
      b[at] = static_cast<std::uint8_t>(rng());
    }
    corrupt.push_back(std::move(b));
  }

  fed::sleep_until(node.start + 0.3);
  size_t next = 0;
  for (int round = 0; round < 25 && lan::unix_now() < node.start + 3.0; ++round) {
    peer.send(latin), peer.send(controls), peer.send(chevron), peer.send(unknown_set);
    for (int k = 0; k < 60 && next < corrupt.size(); ++k) peer.transport().send(corrupt[next++]);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(f.finished());
  const auto ev = read_valid_log(node.events);
  std::map<std::string, json> joined;
  for (const auto& e : fed::of_type(ev, "entity_joined")) joined[e["entity"].get<std::string>()] = e;
  ASSERT_TRUE(joined.count("1:50:1"));
  EXPECT_EQ(joined["1:50:1"]["marking"], "T\xC3\x84NK") << "Latin-1 0xC4 is U+00C4";
  EXPECT_EQ(joined["1:50:1"]["id"], "T\xC3\x84NK");
  ASSERT_TRUE(joined.count("1:50:2"));
  const std::string m2 = joined["1:50:2"]["marking"];
  EXPECT_EQ(m2.find('\x01'), std::string::npos) << "control characters never reach the log";
  EXPECT_NE(m2.find("A"), std::string::npos);
  ASSERT_TRUE(joined.count("1:50:3"));
  EXPECT_EQ(joined["1:50:3"]["marking"], "12");
  ASSERT_TRUE(joined.count("1:50:4"));
  EXPECT_EQ(joined["1:50:4"]["marking"], "\xC3\xA9");
}

// Defect 2 (and 7): the node decided damage for entities it does not own. A peer's tank r1 sits
// at (300, 300) and keeps saying "damage 0" while HE rounds land beside it and on it, and its
// bmp r2 runs broadside into our parked t1 (we decide that contact: our id is the lower). Only
// the owner's appearance changes r1 (destroyed, then repaired: a state may go back), and the
// peer's round beside treeA leaves treeA to the firing node. Removals are logged.
TEST(FederateInput, RemoteDamageIsDecidedByItsOwner) {
  fed::Federate f("fed_owner", "federate.toml", 5.5);
  const auto& node = f.node;
  auto& peer = f.peer;

  auto r1 = vehicle_es(peer, 1, "r1", f.ecef(300, 300));
  auto r2 = vehicle_es(peer, 2, "r2", f.ecef(170, 200));
  r2.entity_type = {1, 1, 222, 2, 1, 0, 0};                            // bmp
  r2.dead_reckoning.algorithm = 2;                                     // FPW, 10 m/s east (ECEF axes)
  r2.linear_velocity = fed::ecef_velocity(f.world, 170, 200, 10, 0);
  r2.orientation = fed::orientation(f.world, 170, 200, 90.0);
  auto he = [&](double x, double y, std::uint8_t result, net::EntityId target, std::uint16_t n) {
    return fed::detonation(peer, n, fed::kHeRound, 1000, 1000, 1, result, f.ecef(x, y, 0.5), target);
  };
  const double t0 = node.start;
  bool sent_beside = false, sent_on = false, sent_tree = false;
  double r2_sent_from = -1;
  while (lan::unix_now() < t0 + 4.8) {
    const double t = lan::unix_now() - t0;
    r1.appearance = (t > 2.5 && t < 3.5) ? (3u << 3) : 0u;  // destroyed from 2.5 s, repaired at 3.5 s
    if (t > 0.2) peer.send(r1);
    if (t > 0.5 && t < 4.0) {  // r2 drives east from x = 170 from t = 0.5 s
      if (r2_sent_from < 0) r2_sent_from = t;
      const double x = 170 + 10 * (t - r2_sent_from);
      r2.location = f.ecef(x, 200);
      peer.send(r2);
    }
    if (t > 1.0 && !sent_beside) sent_beside = true, peer.send(he(305, 300, 3, {}, 1));
    if (t > 1.2 && !sent_tree) sent_tree = true, peer.send(he(312, 110, 3, {}, 2));
    if (t > 1.5 && !sent_on) sent_on = true, peer.send(he(300, 300, 1, r1.entity_id, 3));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  auto gone = r1;
  gone.appearance = net::kAppearanceDeactivated;
  peer.send(gone);
  ASSERT_TRUE(f.finished());
  const auto ev = read_valid_log(node.events);
  EXPECT_EQ(fed::of_type(ev, "detonation").size(), 3u);
  std::vector<std::string> r1_states;
  for (const auto& d : fed::of_type(ev, "damage")) {
    EXPECT_NE(d["object"], "r2") << "r2's owner never said it was damaged: " << d.dump();
    EXPECT_NE(d["object"], "treeA") << "a peer's round: the firing node publishes what it changed: " << d.dump();
    if (d["object"] == "r1") {
      r1_states.push_back(d["to_state"]);
      EXPECT_EQ(d.value("remote", false), true);
    }
  }
  EXPECT_EQ(r1_states, (std::vector<std::string>{"wreck", "intact"})) << "as r1's owner said, in order";
  bool t1_hit = false;
  for (const auto& c : fed::of_type(ev, "collision"))
    if ((c["a"] == "t1" && c["b"] == "r2") || (c["a"] == "r2" && c["b"] == "t1")) t1_hit = true;
  EXPECT_TRUE(t1_hit) << "r2 runs into t1";
  const auto removed = fed::of_type(ev, "entity_removed");
  ASSERT_EQ(removed.size(), 1u);
  EXPECT_EQ(removed[0]["id"], "r1");
}
