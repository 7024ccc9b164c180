// Two players on two nodes over loopback multicast (--iface 127.0.0.1, a random port), each
// replaying its own input file headless: node 1's player drives tank n1 east, node 2's drives n2
// west, head-on into each other. Each driven tank is published like any other; both event logs
// hold the one n1/n2 collision with the same outcomes, and each log its own `drive` event.
#include <gtest/gtest.h>

#include <set>

#include "support/dirs.hpp"
#include "lan_support.hpp"

namespace {
using nlohmann::json;
const std::filesystem::path kData = std::filesystem::path(npsnet::dirs::source()) / "tests" / "multinode" / "data";
}  // namespace

TEST(LanPlayers, TwoDrivenTanksCollideAndBothLogsAgree) {
  const auto dir = lan::fresh_dir("players");
  const int port = lan::random_port();
  char start[64];
  std::snprintf(start, sizeof start, "%.3f", lan::unix_now() + 2.0);
  lan::Procs procs;
  std::vector<int> pids;
  for (int n = 1; n <= 2; ++n) {
    const std::string tag = std::to_string(n);
    pids.push_back(procs.start({"run", "--scenario", (kData / "players.toml").string(), "--net",
                                "udp://239.1.2.3:" + std::to_string(port), "--iface", "127.0.0.1", "--node", tag,
                                "--start-at", start, "--no-render", "--seconds", "10", "--input",
                                (kData / ("players-" + tag + ".jsonl")).string(), "--events",
                                (dir / ("events_" + tag + ".jsonl")).string(), "--snapshots", (dir / ("snap_" + tag)).string()},
                               dir / ("out_" + tag + ".txt")));
  }
  for (int n = 1; n <= 2; ++n)
    ASSERT_EQ(procs.wait(pids[n - 1], 40.0), 0) << lan::read_text(dir / ("out_" + std::to_string(n) + ".txt"));
  std::vector<json> hits;
  for (int n = 1; n <= 2; ++n) {
    SCOPED_TRACE("node " + std::to_string(n));
    const auto ev = lan::read_events(dir / ("events_" + std::to_string(n) + ".jsonl"));
    std::vector<json> drives, coll;
    for (const auto& e : ev) {
      if (e.value("event", "") == "drive") drives.push_back(e);
      if (e.value("event", "") == "collision" && std::set<std::string>{e.value("a", ""), e.value("b", "")} ==
                                                     std::set<std::string>{"n1", "n2"})
        coll.push_back(e);
    }
    ASSERT_EQ(drives.size(), 1u);
    EXPECT_EQ(drives[0]["vehicle"], n == 1 ? "n1" : "n2");  // the first vehicle of its node
    ASSERT_EQ(coll.size(), 1u) << "one collision episode, logged once on each node";
    hits.push_back(coll[0]);
  }
  auto outcome = [](const json& c, const std::string& id) { return c["a"] == id ? c["outcome_a"] : c["outcome_b"]; };
  EXPECT_EQ(outcome(hits[0], "n1"), outcome(hits[1], "n1"));
  EXPECT_EQ(outcome(hits[0], "n2"), outcome(hits[1], "n2"));
  EXPECT_EQ(outcome(hits[0], "n1"), "kill");  // head-on (180 +- 5 deg) above 5 m/s closing: both killed
  EXPECT_NEAR(hits[0]["t"].get<double>(), hits[1]["t"].get<double>(), 0.5);
  // the tanks met between their starts, nearer n2's (n1 started half a second earlier)
  EXPECT_GT(hits[0]["point"][0].get<double>(), 185.0);
  EXPECT_LT(hits[0]["point"][0].get<double>(), 225.0);
}
