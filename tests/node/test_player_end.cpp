// How a player's drive ends (shared/ARCHITECTURE.md, "Player"), headless with --input:
//  - an aircraft flown by the input file into a watertower: a collision like any other (the
//    tower crushed, the helicopter a wreck that stays where it died, in the air), and the player
//    moves on to the node's next live vehicle at once (a `drive` event);
//  - a `quit` action ends the run cleanly: exit 0, the summary printed, an event log of whole
//    lines that ends at the quit, or, with snapshots, once the result frame of every imminent
//    frame taken is written (the pair is never cut in half).
// The window's own quit paths (Esc, closing the window) are in tests/window/test_window_quit.cpp.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <set>

#include "support/fixture.hpp"
#include "support/npsnet_cli.hpp"

using namespace npsnet;
using nlohmann::json;

namespace {
std::filesystem::path fresh_dir(const std::string& name) { return test::fresh_dir("player-end-" + name); }
// Every line of an event log, parsed; fails the test on a line that is not whole JSON.
std::vector<json> read_log(const std::filesystem::path& f) {
  std::vector<json> out;
  std::ifstream in(f, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "the log ends in a whole line";
  size_t at = 0;
  while (at < text.size()) {
    const size_t nl = text.find('\n', at);
    out.push_back(json::parse(text.substr(at, nl - at)));
    at = nl + 1;
  }
  return out;
}
const std::string kAir = test::source("tests/node/data/air.toml").string();
const std::string kAirInput = test::source("tests/node/data/air.jsonl").string();
}  // namespace

TEST(PlayerEnd, AnAircraftFlownIntoATowerCrushesItAndThePlayerMovesOn) {
  const auto dir = fresh_dir("air");
  const auto log = dir / "events.jsonl";
  const auto o = test::npsnet_cli("run --scenario " + kAir + " --input " + kAirInput + " --no-render --quiet --events " +
                                  log.string());
  ASSERT_EQ(o.rc, 0) << o.text;
  const auto ev = read_log(log);
  const json* hit = nullptr;
  const json* crushed = nullptr;
  const json* wreck = nullptr;
  const json* moved = nullptr;
  int h1_damage = 0;
  for (const auto& e : ev) {
    if (e["event"] == "collision" && e["a"] == "h1") hit = &e;
    if (e["event"] == "damage" && e["object"] == "tower1") crushed = &e;
    if (e["event"] == "damage" && e["object"] == "h1") wreck = &e, ++h1_damage;
    if (e["event"] == "drive" && e["vehicle"] == "p9") moved = &e;
    EXPECT_NE(e["event"], "entity_removed");
  }
  ASSERT_TRUE(hit) << o.text;
  EXPECT_EQ((*hit)["b"], "tower1");
  EXPECT_EQ((*hit)["a_kind"], "ah64");
  EXPECT_EQ((*hit)["outcome_a"], "kill");          // a quick aircraft against a large fixed object
  EXPECT_EQ((*hit)["outcome_b"], "destroy_fixed");
  EXPECT_NEAR((*hit)["point"][2].get<double>(), 120.0, 3.0);  // in the air, at the tower's tank
  ASSERT_TRUE(crushed);
  EXPECT_EQ((*crushed)["to_state"], "crushed");
  ASSERT_TRUE(wreck);
  EXPECT_EQ((*wreck)["to_state"], "wreck");
  EXPECT_EQ(h1_damage, 1);  // it stays a wreck to the end
  ASSERT_TRUE(moved);       // the player moves on at once: the next tick
  EXPECT_NEAR((*moved)["t"].get<double>(), (*hit)["t"].get<double>() + 0.1, 1e-9);
  EXPECT_EQ(ev.front()["event"], "drive");
  EXPECT_EQ(ev.front()["vehicle"], "h1");
}

TEST(PlayerEnd, AQuitActionEndsTheRunWithTheSummaryAndAWholeLog) {
  const auto dir = fresh_dir("quit");
  const auto log = dir / "events.jsonl";
  const auto input = test::write_file("player-end-quit.jsonl",
                                      "{\"t\": 0.2, \"action\": \"throttle\", \"value\": 1.0}\n"
                                      "{\"t\": 2.0, \"action\": \"quit\"}\n");
  const auto o = test::npsnet_cli("run --scenario " + kAir + " --input " + input.string() + " --no-render --events " +
                                  log.string());
  ASSERT_EQ(o.rc, 0) << o.text;
  EXPECT_NE(o.text.find("npsnet: quit at t = 2.1 s"), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("npsnet: done: 21 ticks"), std::string::npos) << o.text;  // the summary
  EXPECT_NE(o.text.find("collision method"), std::string::npos) << o.text;
  const auto ev = read_log(log);
  ASSERT_FALSE(ev.empty());
  for (const auto& e : ev) {
    EXPECT_LE(e["t"].get<double>(), 2.1 + 1e-9) << e;  // nothing after the quit
    EXPECT_NE(e["event"], "collision") << e;            // it quit before the tower
  }
}

TEST(PlayerEnd, AQuitRightAfterACollisionStillWritesItsResultFrame) {
  const auto dir = fresh_dir("quit-snap");
  const auto log = dir / "events.jsonl";
  const auto input = test::write_file("player-end-quit-snap.jsonl",
                                      "{\"t\": 0.2, \"action\": \"throttle\", \"value\": 1.0}\n"
                                      "{\"t\": 4.8, \"action\": \"quit\"}\n");  // 0.1 s after h1 meets tower1
  const auto o = test::npsnet_cli("run --scenario " + kAir + " --input " + input.string() + " --quiet --snapshots " +
                                  (dir / "snap").string() + " --events " + log.string());
  ASSERT_EQ(o.rc, 0) << o.text;
  std::set<std::string> imminent, result;
  double collision_t = -1;
  for (const auto& e : read_log(log)) {
    if (e["event"] == "collision") collision_t = e["t"].get<double>();
    if (e["event"] != "snapshot") continue;
    const std::string f = e["file"];
    ASSERT_TRUE(std::filesystem::exists(f)) << f;
    const auto cut = f.rfind('-');
    if (f.substr(cut) == "-imminent.png") imminent.insert(f.substr(0, cut));
    if (f.substr(cut) == "-result.png") result.insert(f.substr(0, cut));
  }
  ASSERT_GT(collision_t, 0) << o.text;
  ASSERT_EQ(imminent.size(), 1u);
  EXPECT_EQ(imminent, result);  // the pair whole
}
