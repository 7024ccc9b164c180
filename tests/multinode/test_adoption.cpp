// Rounds of a killed node (issue 11, node/repeat_ledger.hpp "Adoption"): three nodes on
// loopback multicast (--iface 127.0.0.1, a random port, a common --start-at). Node 1's player
// fires two unscripted rounds (--input, t = 1 s and 2 s) at the slope of ridge.asc; node 3 loses
// both Detonations and their quick repeats (0.5 s apart; test hook NPSNET_TEST_DROP_DETONATIONS_S=4);
// node 1 is SIGKILLed at t = 3 s, before its first heartbeat repeat. Nobody else fired them, so without adoption node 3 never
// gets these craters. With it node 2 (the lowest live node holding them, rank 0) adopts each 2
// heartbeats (10 s) after it last heard it and repeats it: node 3 must have both craters, at the
// same points as node 2, within one heartbeat after that, and no node has a crater twice.
#include <gtest/gtest.h>

#include <regex>
#include <thread>

#include "support/dirs.hpp"
#include "lan_support.hpp"

namespace {
using nlohmann::json;
using lan::of_type;
const std::filesystem::path kData = std::filesystem::path(npsnet::dirs::source()) / "tests" / "multinode" / "data";
constexpr double kHeartbeatS = 5.0;  // Annex C (the nodes run with the default DIS timeout, 12 s)

std::vector<std::string> args(int port, int node, double start_at, const std::filesystem::path& dir) {
  auto a = lan::node_args("adoption.toml", port, node, start_at, 24, dir, std::to_string(node));
  if (node == 1) a.insert(a.end(), {"--input", (kData / "adoption-1.jsonl").string()});
  return a;
}
}  // namespace

TEST(Adoption, RoundsOfAKilledNodeReachTheNodeThatLostThem) {
  const auto dir = lan::fresh_dir("adoption");
  const int port = lan::random_port();
  const double start = lan::unix_now() + 2.0;
  lan::Procs procs;
  std::vector<int> pids;
  for (int n = 1; n <= 3; ++n) {
    std::vector<std::string> env;
    if (n == 3) env.push_back("NPSNET_TEST_DROP_DETONATIONS_S=4");
    pids.push_back(procs.start(args(port, n, start, dir), dir / ("out_" + std::to_string(n) + ".txt"), env));
  }
  // Kill node 1 three seconds into the exercise (bounded: at most 10 s of waiting).
  for (int i = 0; i < 1000 && lan::unix_now() < start + 3.0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  procs.kill_now(pids[0]);
  for (int n = 2; n <= 3; ++n)
    ASSERT_EQ(procs.wait(pids[n - 1], 60.0), 0) << lan::read_text(dir / ("out_" + std::to_string(n) + ".txt"));

  const auto fired = of_type(lan::read_events(dir / "events_1.jsonl"), "fire");
  ASSERT_EQ(fired.size(), 2u) << "node 1 fired both rounds before it was killed";
  const auto c1 = of_type(lan::read_events(dir / "events_1.jsonl"), "crater");
  const auto c2 = of_type(lan::read_events(dir / "events_2.jsonl"), "crater");
  const auto c3 = of_type(lan::read_events(dir / "events_3.jsonl"), "crater");
  ASSERT_EQ(c1.size(), 2u);
  ASSERT_EQ(c2.size(), 2u) << "node 2 applied each round once (its own adopted repeats are not new rounds)";
  ASSERT_EQ(c3.size(), 2u) << "node 3 lost both Detonations: only an adopter's repeat brings them\n"
                           << lan::read_text(dir / "out_3.txt");
  for (int k = 0; k < 2; ++k) {
    SCOPED_TRACE("round " + std::to_string(k + 1));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(c3[k]["point"][i].get<double>(), c2[k]["point"][i].get<double>(), 0.01);
    EXPECT_LT(c2[k]["t"].get<double>(), 3.0);  // node 2 heard the original
    // Adoption 2 heartbeats after node 2 last heard it (the original or a quick repeat, at most
    // 2 x 0.5 s later: node 1 died before its heartbeat repeat).
    const double adopt = c2[k]["t"].get<double>() + 2 * kHeartbeatS;
    EXPECT_GE(c3[k]["t"].get<double>(), adopt - 0.5);
    EXPECT_LE(c3[k]["t"].get<double>(), adopt + 1.0 + kHeartbeatS);
  }
  const std::string out2 = lan::read_text(dir / "out_2.txt"), out3 = lan::read_text(dir / "out_3.txt");
  EXPECT_NE(out2.find("adopted 2 of silent nodes"), std::string::npos) << out2;
  EXPECT_NE(out3.find("adopted 0 of silent nodes"), std::string::npos) << out3;  // node 2 repeats them: 3 only watches
  // The two originals and the quick repeats node 1 sent before it died (up to 2 each).
  std::smatch m;
  ASSERT_TRUE(std::regex_search(out3, m, std::regex(R"(NPSNET_TEST_DROP_DETONATIONS_S dropped (\d+) )"))) << out3;
  EXPECT_GE(std::stoi(m[1]), 2);
  EXPECT_LE(std::stoi(m[1]), 6);
  std::filesystem::remove_all(dir);
}
