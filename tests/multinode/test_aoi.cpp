// Area of interest (--aoi 2000) on loopback multicast (--iface 127.0.0.1, a random port, groups
// from 239.1.2.3 up): two `npsnet run` processes on tests/multinode/data/aoi_far.toml, once with
// and once without --aoi (at the same time, on two ports). w1 (node 1) and e2 (node 2) are 30 km
// apart: with AOI neither node hears the other's vehicle, without AOI both do; b1/b2 collide
// head-on exactly on the cell border x = 20 km: one decider, the same collision in both logs,
// with and without AOI. aoi_drive.toml: node 2's f16 flies at node 1's tank and is shown before
// it comes within the tank's 5 km sensor range, not at the start.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <set>

#include "support/dirs.hpp"
#include "lan_support.hpp"

namespace {

using nlohmann::json;
const std::filesystem::path kData = std::filesystem::path(npsnet::dirs::source()) / "tests" / "multinode" / "data";

struct Node {
  std::filesystem::path events, out;
  int pid = -1;
};

Node start_node(lan::Procs& procs, const std::string& scenario, int port, int node, double start_at, bool aoi,
                const std::filesystem::path& dir, const std::string& tag) {
  char s[64];
  std::snprintf(s, sizeof s, "%.3f", start_at);
  Node n;
  n.events = dir / ("events_" + tag + ".jsonl");
  n.out = dir / ("out_" + tag + ".txt");
  std::vector<std::string> args{"run",      "--scenario", (kData / scenario).string(),
                                "--net",    "udp://239.1.2.3:" + std::to_string(port),
                                "--iface",  "127.0.0.1",
                                "--node",   std::to_string(node),
                                "--start-at", s,
                                "--no-render",
                                "--events", n.events.string(),
                                "--snapshots", (dir / ("snap_" + tag)).string()};
  if (aoi) args.insert(args.end(), {"--aoi", "2000"});
  n.pid = procs.start(args, n.out);
  return n;
}

using lan::of_type;

std::set<std::string> joined_ids(const std::vector<json>& evs) {
  std::set<std::string> s;
  for (const auto& e : of_type(evs, "entity_joined")) s.insert(e["id"].get<std::string>());
  return s;
}

// "decoded entity_state=N" of the counters printed at the end of a run (0 when absent).
long decoded_entity_states(const std::string& out) {
  std::smatch m;
  static const std::regex re("decoded[^|]*entity_state=([0-9]+)");
  return std::regex_search(out, m, re) ? std::stol(m[1]) : 0;
}

}  // namespace

TEST(AoiExercise, FarNodesHearNoneOfEachOtherWithAoiAllWithoutAndAgreeOnABorderCollision) {
  const auto dir = lan::fresh_dir("aoi_far");
  const int port = lan::random_port();
  const double start = lan::unix_now() + 2.0;
  lan::Procs procs;
  std::vector<Node> nodes;  // [aoi node 1, aoi node 2, flat node 1, flat node 2]
  for (int aoi = 1; aoi >= 0; --aoi)
    for (int n = 1; n <= 2; ++n)
      nodes.push_back(start_node(procs, "aoi_far.toml", port + (aoi ? 0 : 1), n, start, aoi, dir,
                                 (aoi ? "aoi" : "flat") + std::to_string(n)));
  for (const auto& n : nodes) ASSERT_EQ(procs.wait(n.pid, 40.0), 0) << lan::read_text(n.out);
  std::vector<std::vector<json>> logs;
  std::vector<std::string> outs;
  for (const auto& n : nodes) logs.push_back(lan::read_events(n.events)), outs.push_back(lan::read_text(n.out));

  // 30 km apart: with AOI none of the far vehicle's Entity States arrive, without AOI they do.
  EXPECT_EQ(joined_ids(logs[0]), std::set<std::string>{"b2"}) << outs[0];
  EXPECT_EQ(joined_ids(logs[1]), std::set<std::string>{"b1"}) << outs[1];
  EXPECT_EQ(joined_ids(logs[2]), (std::set<std::string>{"b2", "e2"})) << outs[2];
  EXPECT_EQ(joined_ids(logs[3]), (std::set<std::string>{"b1", "w1"})) << outs[3];
  for (int n = 0; n < 2; ++n) {
    std::printf("node %d decoded entity states: %ld with --aoi 2000, %ld without\n", n + 1,
                decoded_entity_states(outs[n]), decoded_entity_states(outs[n + 2]));
    EXPECT_LT(decoded_entity_states(outs[n]), decoded_entity_states(outs[n + 2]))
        << "with AOI a node decodes fewer Entity States\n" << outs[n] << outs[n + 2];
    EXPECT_NE(outs[n].find("aoi groups="), std::string::npos) << outs[n];
    EXPECT_EQ(outs[n + 2].find("aoi groups="), std::string::npos) << outs[n + 2];
    EXPECT_NE(outs[n].find("rejected none"), std::string::npos) << outs[n];
  }

  // The head-on collision on the cell border x = 20000: once in every log, decided by node 1.
  for (int run = 0; run < 2; ++run) {
    std::vector<json> hits;
    for (int n = 0; n < 2; ++n) {
      SCOPED_TRACE((run == 0 ? "aoi node " : "flat node ") + std::to_string(n + 1));
      std::vector<json> c;
      for (const auto& e : of_type(logs[2 * run + n], "collision"))
        if (std::set<std::string>{e["a"], e["b"]} == std::set<std::string>{"b1", "b2"}) c.push_back(e);
      ASSERT_EQ(c.size(), 1u) << outs[2 * run + n];
      EXPECT_NEAR(c[0]["point"][0].get<double>(), 20000.0, 8.0) << "on the border of cells 9 and 10";
      hits.push_back(c[0]);
      int damage = 0;
      for (const auto& d : of_type(logs[2 * run + n], "damage")) damage += d["object"] == "b1" || d["object"] == "b2";
      EXPECT_EQ(damage, c[0]["outcome_a"] == "kill" ? 2 : 0) << "each side's damage once";
    }
    EXPECT_EQ(hits[0]["outcome_a"], hits[1]["outcome_a"]);
    EXPECT_EQ(hits[0]["outcome_b"], hits[1]["outcome_b"]);
    EXPECT_EQ(hits[0]["outcome_a"], "kill") << "head-on (180 degrees) is in the kill band";
    EXPECT_NE(hits[0]["method"], "network") << "node 1 decides (b1 has the lower DIS entity id)";
    EXPECT_EQ(hits[1]["method"], "network");
  }
  std::filesystem::remove_all(dir);
}

TEST(AoiExercise, VehicleFlyingInIsShownBeforeItComesWithinRange) {
  const auto dir = lan::fresh_dir("aoi_drive");
  const int port = lan::random_port();
  const double start = lan::unix_now() + 1.5;
  lan::Procs procs;
  std::vector<Node> nodes;
  for (int n = 1; n <= 2; ++n)
    nodes.push_back(start_node(procs, "aoi_drive.toml", port, n, start, true, dir, std::to_string(n)));
  for (const auto& n : nodes) ASSERT_EQ(procs.wait(n.pid, 40.0), 0) << lan::read_text(n.out);
  const auto log1 = lan::read_events(nodes[0].events);
  // f2 starts 8.5 km east of w1 at 1000 km/h (277.8 m/s) flying west: its distance at time t.
  auto distance = [](double t) { return 8500.0 - 1000.0 / 3.6 * t; };
  double seen_at = -1;
  for (const auto& e : of_type(log1, "entity_joined"))
    if (e["id"] == "f2") seen_at = e["t"].get<double>();
  ASSERT_GE(seen_at, 0) << "node 1 never showed f2\n" << lan::read_text(nodes[0].out);
  std::printf("f2 shown on node 1 at t = %.1f s, %.0f m from w1\n", seen_at, distance(seen_at));
  EXPECT_GT(seen_at, 1.0) << "not heard at the start (8.5 km, outside w1's area of interest)";
  EXPECT_GT(distance(seen_at), 5000.0) << "shown before it comes within w1's 5 km sensor range (t = " << seen_at << ")";
  // w1 joins the cells within 5 km + (16.7 + 277.8) m/s x 5 s = 6.47 km: cell x 10-12 km is the
  // first f2 meets, at 7 km (t = 5.4 s). f2 flies straight, so its heartbeats (t = 5, 10 s) find
  // it at 12.1 and 10.7 km: only the announcement on entering a cell shows it near 7 km.
  EXPECT_GT(distance(seen_at), 6500.0) << "announced in its new cell at once, not at its next heartbeat";
  EXPECT_LT(distance(seen_at), 5000.0 + (1000.0 / 3.6 + 60.0 / 3.6) * 5.0 + 2000.0 * std::sqrt(2.0))
      << "and not before its cell is within range + margin";
  // Node 2's f16 sees 20 km: it hears w1 from the start.
  const auto log2 = lan::read_events(nodes[1].events);
  EXPECT_EQ(joined_ids(log2), std::set<std::string>{"w1"});
  std::filesystem::remove_all(dir);
}

TEST(AoiExercise, BadAoiInputExitsTwoWritingNothing) {
  const auto dir = lan::fresh_dir("aoi_bad");
  lan::Procs procs;
  const std::string scenario = (kData / "aoi_far.toml").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--aoi", "2000"}, "--aoi"},                                                   // no --net
      {{"--net", "udp://127.0.0.1:3000", "--aoi", "2000"}, "multicast"},              // not a group
      {{"--net", "udp://224.1.2.3:3000", "--aoi", "2000"}, "239.0.0.0/8"},            // not scoped
      {{"--net", "udp://239.255.255.200:3000", "--aoi", "2000"}, "239.0.0.0/8"},      // runs past it
      {{"--net", "udp://239.1.2.3:3000", "--aoi", "2000", "--aoi-groups", "0"}, "--aoi-groups"},
      {{"--net", "udp://239.1.2.3:3000", "--aoi", "-5"}, "--aoi"},
  };
  int i = 0;
  for (const auto& [extra, says] : cases) {
    const auto ev = dir / ("events_" + std::to_string(i) + ".jsonl");
    std::vector<std::string> args{"run", "--scenario", scenario, "--no-render", "--seconds", "1", "--events", ev.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto out = dir / ("out_" + std::to_string(i++) + ".txt");
    const int pid = procs.start(args, out);
    EXPECT_EQ(procs.wait(pid, 20.0), 2) << lan::read_text(out);
    EXPECT_NE(lan::read_text(out).find(says), std::string::npos) << lan::read_text(out);
    EXPECT_FALSE(std::filesystem::exists(ev)) << "nothing written on bad input";
  }
  std::filesystem::remove_all(dir);
}
