// Multi-node LAN exercise on loopback multicast (239.1.2.3, a random port, --iface 127.0.0.1):
// three `npsnet run` processes on tests/multinode/data/lan.toml. Node 1's tank t1 and node 2's
// APC a2 collide broadside (kill), t1b and a2b at a shallow angle (bounce); node 2's hmmwv h2 runs
// into tree2; node 3's tank s3 fires a round that lands.
// Every event log must hold that collision once with the same pair and outcomes, the damage of
// each side once, the crater at the same place, and tree2 in the same state. A second test kills
// a node (SIGKILL) and restarts it: the other logs entity_timeout, then entity_joined again.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <thread>

#include "support/dirs.hpp"
#include "lan_support.hpp"

namespace {

using nlohmann::json;
const std::filesystem::path kData = std::filesystem::path(npsnet::dirs::source()) / "tests" / "multinode" / "data";

using lan::node_args;
using lan::of_type;

std::set<std::string> pair_of(const json& c) { return {c.value("a", ""), c.value("b", "")}; }

}  // namespace

TEST(LanExercise, CollisionAndCraterAgreeOnThreeNodes) {
  const auto dir = lan::fresh_dir("lan");
  const int port = lan::random_port();
  const double start = lan::unix_now() + 2.0;
  lan::Procs procs;
  std::vector<int> pids;
  for (int n = 1; n <= 3; ++n) {
    auto args = node_args("lan.toml", port, n, start, 8, dir, std::to_string(n));
    pids.push_back(procs.start(args, dir / ("out_" + std::to_string(n) + ".txt")));
  }
  for (int n = 1; n <= 3; ++n)
    ASSERT_EQ(procs.wait(pids[n - 1], 40.0), 0) << lan::read_text(dir / ("out_" + std::to_string(n) + ".txt"));

  std::vector<std::vector<json>> logs;
  for (int n = 1; n <= 3; ++n) logs.push_back(lan::read_events(dir / ("events_" + std::to_string(n) + ".jsonl")));

  const std::set<std::string> pair{"t1", "a2"};
  std::vector<json> hits;
  for (int n = 0; n < 3; ++n) {
    SCOPED_TRACE("node " + std::to_string(n + 1));
    const auto& ev = logs[n];
    std::vector<json> c;
    for (const auto& e : of_type(ev, "collision"))
      if (pair_of(e) == pair) c.push_back(e);
    ASSERT_EQ(c.size(), 1u) << "the t1/a2 collision is decided once and logged once on every node";
    hits.push_back(c[0]);
    // Damage applied once per entity per node.
    int dt1 = 0, da2 = 0;
    for (const auto& d : of_type(ev, "damage")) {
      if (d["object"] == "t1") ++dt1;
      if (d["object"] == "a2") ++da2;
    }
    const bool kill = c[0]["outcome_a"] == "kill";
    EXPECT_EQ(dt1, kill ? 1 : 0);
    EXPECT_EQ(da2, kill ? 1 : 0);
    // The round of node 3 lands once, with its crater, on every node.
    ASSERT_EQ(of_type(ev, "detonation").size(), 1u);
    ASSERT_EQ(of_type(ev, "crater").size(), 1u);
    EXPECT_EQ(of_type(ev, "fire").size(), 1u) << "only node 3 fires s3's round";
    EXPECT_EQ(of_type(ev, "detonation")[0]["shooter"], "s3");
  }
  // Same outcomes everywhere (the decider is node 1: t1 has the lower DIS entity id).
  for (int n = 1; n < 3; ++n) {
    EXPECT_EQ(hits[n]["outcome_a"], hits[0]["outcome_a"]);
    EXPECT_EQ(hits[n]["outcome_b"], hits[0]["outcome_b"]);
  }
  EXPECT_NE(hits[0]["method"], "network") << "node 1 decided it";
  EXPECT_EQ(hits[1]["method"], "network");
  EXPECT_EQ(hits[2]["method"], "network");
  EXPECT_EQ(hits[0]["outcome_a"], "kill") << "broadside at 40 km/h each is in the kill band";
  // The shallow-angle pair bounces, decided once by node 1 (t1b's id is the lower), logged once
  // with the same outcomes everywhere.
  for (int n = 0; n < 3; ++n) {
    SCOPED_TRACE("node " + std::to_string(n + 1));
    std::vector<json> b;
    for (const auto& e : of_type(logs[n], "collision"))
      if (pair_of(e) == std::set<std::string>{"t1b", "a2b"}) b.push_back(e);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(b[0]["outcome_a"], "bounce");
    EXPECT_EQ(b[0]["outcome_b"], "bounce");
    EXPECT_EQ(b[0]["method"] == "network", n != 0);
  }
  // Crater at the same place (metres).
  const auto c3 = of_type(logs[2], "crater")[0]["point"];
  for (int n = 0; n < 2; ++n) {
    const auto c = of_type(logs[n], "crater")[0];
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(c["point"][k].get<double>(), c3[k].get<double>(), 0.05);
    EXPECT_EQ(c["radius_m"], of_type(logs[2], "crater")[0]["radius_m"]);
  }
  // Remote entities joined, named by marking.
  auto joined = [&](int n) {
    std::set<std::string> s;
    for (const auto& e : of_type(logs[n], "entity_joined")) s.insert(e["id"].get<std::string>());
    return s;
  };
  EXPECT_EQ(joined(0), (std::set<std::string>{"a2", "a2b", "h2", "s3"}));
  EXPECT_EQ(joined(1), (std::set<std::string>{"t1", "t1b", "s3"}));
  EXPECT_EQ(joined(2), (std::set<std::string>{"t1", "t1b", "a2", "a2b", "h2"}));
  // tree2 (run down by node 2's hmmwv) ends in the same state everywhere: cultural feature.
  std::string tree_state[3];
  for (int n = 0; n < 3; ++n)
    for (const auto& d : of_type(logs[n], "damage"))
      if (d["object"] == "tree2") tree_state[n] = d["to_state"].get<std::string>();
  EXPECT_FALSE(tree_state[1].empty()) << "node 2's hmmwv damages tree2";
  EXPECT_EQ(tree_state[0], tree_state[1]);
  EXPECT_EQ(tree_state[2], tree_state[1]);
  // Counters are printed at the end of a run.
  for (int n = 1; n <= 3; ++n) {
    const std::string out = lan::read_text(dir / ("out_" + std::to_string(n) + ".txt"));
    EXPECT_NE(out.find("net: datagrams"), std::string::npos) << out;
    EXPECT_NE(out.find("rejected none"), std::string::npos) << out;
  }
  std::filesystem::remove_all(dir);
}

TEST(LanExercise, KilledNodeTimesOutAndRejoins) {
  const auto dir = lan::fresh_dir("rejoin");
  const int port = lan::random_port();
  const std::vector<std::string> env{"NPSNET_DIS_TIMEOUT_S=1.5"};
  const double start = lan::unix_now() + 1.5;
  lan::Procs procs;
  auto a1 = node_args("rejoin.toml", port, 1, start, 11, dir, "1");
  auto a2 = node_args("rejoin.toml", port, 2, start, 11, dir, "2a");
  const int p1 = procs.start(a1, dir / "out_1.txt", env);
  const int p2 = procs.start(a2, dir / "out_2a.txt", env);
  // Kill node 2 three seconds into the exercise, restart it three seconds later.
  while (lan::unix_now() < start + 3.0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  procs.kill_now(p2);
  const double killed_at = lan::unix_now() - start;
  while (lan::unix_now() < start + 6.0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  auto b2 = node_args("rejoin.toml", port, 2, lan::unix_now() + 0.5, 4, dir, "2b");
  // The restarted node packs its Entity States several to a datagram (NPSNET_DIS_PACK=1).
  const int p2b = procs.start(b2, dir / "out_2b.txt", {"NPSNET_DIS_TIMEOUT_S=1.5", "NPSNET_DIS_PACK=1"});
  ASSERT_EQ(procs.wait(p2b, 30.0), 0) << lan::read_text(dir / "out_2b.txt");
  ASSERT_EQ(procs.wait(p1, 30.0), 0) << lan::read_text(dir / "out_1.txt");

  const auto ev = lan::read_events(dir / "events_1.jsonl");
  std::vector<std::pair<double, std::string>> seq;  // a2's joins and timeouts on node 1, in order
  for (const auto& e : ev)
    if ((e["event"] == "entity_joined" || e["event"] == "entity_timeout") && e["id"] == "a2")
      seq.emplace_back(e["t"].get<double>(), e["event"].get<std::string>());
  std::string seq_text;
  for (const auto& [t, e] : seq) seq_text += e + " at " + std::to_string(t) + "; ";
  ASSERT_EQ(seq.size(), 3u) << "joined, timed out, joined again: " << seq_text;
  EXPECT_EQ(seq[0].second, "entity_joined");
  EXPECT_EQ(seq[1].second, "entity_timeout");
  EXPECT_EQ(seq[2].second, "entity_joined");
  // Node 1's times, on the test's clock: a node slow to start (a loaded machine) starts at t = 0
  // that much past --start-at, and says so (CI once saw node 1 start about a second late).
  const double lag1 = lan::start_lag_s(dir / "out_1.txt");
  const std::string out1 = "node 1 started " + std::to_string(lag1) + " s late; " + seq_text;
  // Within a second of node 1's own start: t = 0, or where it joined when it came 2 s or more late.
  double t_start1 = 0;
  for (const auto& e : lan::of_type(ev, "exercise_joined")) t_start1 = e["t"].get<double>();
  EXPECT_LT(seq[0].first, t_start1 + 1.0) << out1;
  // Timed out 1.5 s after a2's last Entity State. a2 drives straight (its dead reckoning is
  // exact), so that last one may be a heartbeat (1.5 / 2.4 = 0.625 s) before the kill: the
  // timeout comes 0.875 to 1.5 s after the kill, give or take a tick or two.
  EXPECT_GT(seq[1].first + lag1, killed_at + 0.7) << out1;
  EXPECT_LT(seq[1].first + lag1, killed_at + 3.0) << out1;
  EXPECT_GT(seq[2].first + lag1, 6.0) << out1;
  for (const auto& e : ev)
    if (e["event"] == "entity_joined" || e["event"] == "entity_timeout") {
      EXPECT_EQ(e["marking"], e["id"]);
      EXPECT_EQ(e["kind"], "bmp");
      EXPECT_EQ(e["entity"], "1:2:2");
    }
  // The restarted node hears node 1 again.
  bool rejoined_sees_t1 = false;
  for (const auto& e : lan::read_events(dir / "events_2b.jsonl"))
    if (e["event"] == "entity_joined" && e["id"] == "t1") rejoined_sees_t1 = true;
  EXPECT_TRUE(rejoined_sees_t1);
  std::filesystem::remove_all(dir);
}

TEST(LanExercise, BadNetInputExitsTwoWritingNothing) {
  const auto dir = lan::fresh_dir("badnet");
  lan::Procs procs;
  const std::string scenario = (kData / "rejoin.toml").string();
  struct Case {
    std::vector<std::string> args;
    std::vector<std::string> env;
    std::string says;
  };
  const std::vector<Case> cases{
      {{"--net", "udp://239.1.2:3000"}, {}, "--net"},
      {{"--net", "tcp://239.1.2.3:3000"}, {}, "--net"},
      {{"--net", "udp://239.1.2.3:70000"}, {}, "--net"},
      {{"--net", "udp://239.1.2.3:3000", "--iface", "10.255.255.254"}, {}, "--iface"},
      {{"--net", "udp://239.1.2.3:3000"}, {"NPSNET_DIS_TIMEOUT_S=soon"}, "NPSNET_DIS_TIMEOUT_S"},
      {{"--net", "udp://239.1.2.3:3000"}, {"NPSNET_DIS_TIMEOUT_S=-1"}, "NPSNET_DIS_TIMEOUT_S"},
  };
  int i = 0;
  for (const auto& c : cases) {
    const auto ev = dir / ("events_" + std::to_string(i) + ".jsonl");
    std::vector<std::string> args{"run", "--scenario", scenario, "--no-render", "--seconds", "1", "--events", ev.string()};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto out = dir / ("out_" + std::to_string(i++) + ".txt");
    const int pid = procs.start(args, out, c.env);
    EXPECT_EQ(procs.wait(pid, 20.0), 2) << lan::read_text(out);
    EXPECT_NE(lan::read_text(out).find(c.says), std::string::npos) << lan::read_text(out);
    EXPECT_FALSE(std::filesystem::exists(ev)) << "nothing written on bad input";
  }
  std::filesystem::remove_all(dir);
}
