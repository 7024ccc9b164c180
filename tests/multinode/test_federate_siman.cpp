// Simulation management (issue 10, defect 4), through the real path: an exercise-control peer
// (application 50) freezes the node, resumes it at a given simulation time and removes one of
// its vehicles; every request is answered with an Acknowledge carrying its request id
// (IEEE 1278.1-2012 5.6.5, 7.5). A freeze whose frozen behaviour has "run simulation clock"
// (bit 0) resumes at the time the clock ran to; the time frozen is never counted as a tick's.
#include <gtest/gtest.h>

#include <map>
#include <regex>

#include "peer_support.hpp"

TEST(FederateSiman, FreezeResumeRemoveEachAcknowledged) {
  // Heartbeat 0.5 s (timeout 1.2 s): the node would send an Entity State at least every 0.5 s.
  fed::Federate f("fed_siman", "federate.toml", 4, {}, {"NPSNET_DIS_TIMEOUT_S=1.2"});
  const auto& node = f.node;
  auto& peer = f.peer;
  const net::EntityId all{net::kAllSites, net::kAllApplications, 0};
  const net::EntityId control = peer.entity_id(0);

  struct Heard {
    double at;
    net::EntityStatePdu es;
  };
  std::vector<Heard> es;
  std::map<std::uint32_t, std::pair<double, net::AcknowledgePdu>> acks;
  auto visit = net::Overloaded{
      [&](const net::EntityStatePdu& p) {
        if (p.entity_id.site == 1 && p.entity_id.application == 1) es.push_back({lan::unix_now() - node.start, p});
      },
      [&](const net::AcknowledgePdu& p) {
        if (p.originating_id.site == 1 && p.originating_id.application == 1)
          acks[p.request_id] = {lan::unix_now() - node.start, p};
      }};
  fed::poll_until(peer, node.start + 1.0, visit);
  net::StopFreezePdu stop;
  stop.originating_id = control;
  stop.receiving_id = all;
  stop.reason = 1;  // recess
  stop.frozen_behavior = 0;
  stop.request_id = 77;
  peer.send(stop);
  fed::poll_until(peer, node.start + 3.0, visit);
  net::StartResumePdu start;
  start.originating_id = control;
  start.receiving_id = {1, 1, 0};
  start.simulation_time = {0, net::relative_timestamp(20.0)};  // resume at scenario time 20 s
  start.request_id = 78;
  peer.send(start);
  fed::poll_until(peer, node.start + 3.5, visit);
  net::RemoveEntityPdu remove;
  remove.originating_id = control;
  remove.receiving_id = {1, 1, 1};  // t1 (entity number = index + 1)
  remove.request_id = 79;
  peer.send(remove);
  net::RemoveEntityPdu nobody = remove;
  nobody.receiving_id = {1, 1, 999};
  nobody.request_id = 80;
  peer.send(nobody);
  fed::poll_until(peer, node.start + 7.0, visit);
  ASSERT_TRUE(f.finished());

  ASSERT_TRUE(acks.count(77) && acks.count(78) && acks.count(79) && acks.count(80)) << "an Acknowledge for every request";
  EXPECT_EQ(acks[77].second.acknowledge_flag, 4);
  EXPECT_EQ(acks[78].second.acknowledge_flag, 3);
  EXPECT_EQ(acks[79].second.acknowledge_flag, 2);
  for (std::uint32_t r : {77u, 78u, 79u}) EXPECT_EQ(acks[r].second.response_flag, 1) << r;
  EXPECT_EQ(acks[80].second.response_flag, 2) << "no entity 999: unable to comply";
  EXPECT_EQ(acks[77].second.receiving_id, control);
  // Frozen (behaviour 0: nothing transmitted) between the two acknowledgements.
  const double frozen_from = acks[77].first + 0.15, frozen_to = acks[78].first - 0.05;
  int during = 0, after = 0;
  bool t1_deactivated = false;
  for (const auto& h : es) {
    if (h.at > frozen_from && h.at < frozen_to) ++during;
    if (h.at > acks[78].first + 0.05) {
      ++after;
      if (h.es.entity_id.entity == 2) {  // tank2, after the resume: its clock restarted at 20 s
        EXPECT_GE(net::decode_timestamp(h.es.header.timestamp).seconds_past_hour, 19.9);
      }
    }
    if (h.es.entity_id.entity == 1 && (h.es.appearance & net::kAppearanceDeactivated) && h.at < 5.0) t1_deactivated = true;
  }
  EXPECT_EQ(during, 0) << "no Entity State while frozen";
  EXPECT_GT(after, 0);
  EXPECT_TRUE(t1_deactivated) << "Remove Entity: t1 leaves with a deactivation Entity State";
  const auto ev = f.events();
  bool removed = false;
  double last_t = 0;
  for (const auto& e : ev) {
    if (e["event"] == "entity_removed" && e["id"] == "t1") removed = true;
    last_t = std::max(last_t, e.value("t", 0.0));
  }
  EXPECT_TRUE(removed);
  EXPECT_GE(last_t, 20.0) << "events after the resume carry the resumed scenario time";
}

// The longest tick (s) the node's "paced:" summary names; -1 without one.
static double longest_tick_s(const std::string& out) {
  std::smatch m;
  if (!std::regex_search(out, m, std::regex(R"(longest tick ([0-9.]+) ms)"))) return -1;
  return std::stod(m[1].str()) / 1000;
}

TEST(FederateSiman, RunSimulationClockBitMovesTheClockOnWhileFrozen) {
  fed::Federate f("fed_runclock", "federate.toml", 4);
  const auto& node = f.node;
  auto& peer = f.peer;
  const net::EntityId control = peer.entity_id(0);
  std::map<std::uint32_t, double> acked;  // request id -> when its Acknowledge was heard (UNIX s)
  auto visit = net::Overloaded{[&](const net::AcknowledgePdu& p) {
    if (p.originating_id.site == 1 && p.originating_id.application == 1) acked[p.request_id] = lan::unix_now();
  }};
  auto freeze = [&](std::uint8_t behaviour, std::uint32_t request) {
    net::StopFreezePdu stop;
    stop.originating_id = control;
    stop.receiving_id = {1, 1, 0};
    stop.reason = 1;  // recess
    stop.frozen_behavior = behaviour;
    stop.request_id = request;
    peer.send(stop);
  };
  auto resume = [&](std::uint32_t request) {  // simulation time zero: keep the scenario clock
    net::StartResumePdu start;
    start.originating_id = control;
    start.receiving_id = {1, 1, 0};
    start.request_id = request;
    peer.send(start);
  };
  fed::poll_until(peer, node.start + 0.8, visit);
  freeze(1, 1);  // run simulation clock
  fed::poll_until(peer, node.start + 2.3, visit);
  resume(2);
  fed::poll_until(peer, node.start + 2.8, visit);
  freeze(0, 3);  // the clock stops
  fed::poll_until(peer, node.start + 3.8, visit);
  resume(4);
  fed::poll_until(peer, node.start + 7.0, visit);
  ASSERT_TRUE(f.finished());
  ASSERT_TRUE(acked.count(1) && acked.count(2) && acked.count(3) && acked.count(4)) << "an Acknowledge for every request";
  const auto ev = f.events();
  const auto frozen = fed::of_type(ev, "frozen"), resumed = fed::of_type(ev, "resumed");
  ASSERT_EQ(frozen.size(), 2u);
  ASSERT_EQ(resumed.size(), 2u);
  const double ran = resumed[0]["t"].get<double>() - frozen[0]["t"].get<double>();
  EXPECT_NEAR(ran, acked[2] - acked[1], 0.3) << "bit 0: the scenario clock ran on while frozen (1.5 s)";
  EXPECT_EQ(resumed[1]["t"].get<double>(), frozen[1]["t"].get<double>()) << "bit 0 clear: the clock stood still";
  const std::string out = lan::read_text(node.out);
  const double longest = longest_tick_s(out);
  EXPECT_GE(longest, 0) << out;
  EXPECT_LT(longest, 0.9) << "the second (1 s) and first (1.5 s) freezes are no tick's time: " << out;
}
