// The player's node, headless (--input replays actions by scenario time): the input file of
// tests/node/data drives tank p1 through a tree, fires at the APC ahead, switches to the jeep p2
// and drives it into a building; the event log shows each, two replays are byte-identical, and a
// session recorded with --record-input replays to the same log. Bad input exits 2, writing nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "support/fixture.hpp"
#include "support/npsnet_cli.hpp"

using namespace npsnet;
using nlohmann::json;

namespace {
test::CliOut run(const std::string& args) { return test::npsnet_cli(args); }
std::string slurp(const std::filesystem::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
std::vector<json> events(const std::filesystem::path& f) {
  std::vector<json> out;
  std::ifstream in(f);
  std::string line;
  while (std::getline(in, line)) out.push_back(json::parse(line));
  return out;
}
std::filesystem::path tmp(const std::string& name) {
  const auto dir = npsnet::test::scratch_dir();
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / name);
  return dir / name;
}
const std::string kScenario = test::source("tests/node/data/drive.toml").string();
const std::string kInput = test::source("tests/node/data/drive.jsonl").string();
std::string replay(const std::filesystem::path& events, const std::string& input, const std::string& extra = "") {
  return "run --scenario " + kScenario + " --input " + input + " --no-render --quiet --events " + events.string() + " " + extra;
}
const json* find(const std::vector<json>& ev, const std::string& type, const std::string& key, const std::string& value) {
  for (const auto& e : ev)
    if (e["event"] == type && e.value(key, "") == value) return &e;
  return nullptr;
}
}  // namespace

TEST(PlayerReplay, TreeRoundSwitchAndWallInTheEventLog) {
  const auto f = tmp("player-1.jsonl");
  const auto o = run(replay(f, kInput));
  ASSERT_EQ(o.rc, 0) << o.text;
  const auto ev = events(f);
  ASSERT_FALSE(ev.empty());
  EXPECT_EQ(ev[0]["event"], "drive");  // the start
  EXPECT_EQ(ev[0]["vehicle"], "p1");
  EXPECT_EQ(ev[0]["frame"], 0);
  const json* tree = find(ev, "collision", "b", "tree1");
  ASSERT_TRUE(tree);
  EXPECT_EQ((*tree)["a"], "p1");
  EXPECT_EQ((*tree)["outcome_b"], "destroy_fixed");  // driven at full throttle: down to a stump
  const json* fire = find(ev, "fire", "shooter", "p1");
  ASSERT_TRUE(fire);
  EXPECT_EQ((*fire)["munition"], "he_round");  // the m1a1's munition (kinds.toml)
  EXPECT_EQ((*fire)["target"], "tgt");         // the APC its gun points at
  EXPECT_DOUBLE_EQ((*fire)["t"].get<double>(), 7.5);
  const json* det = find(ev, "detonation", "target", "tgt");
  ASSERT_TRUE(det);
  EXPECT_EQ((*det)["result"], "entity_impact");
  const json* sw = find(ev, "drive", "vehicle", "p2");
  ASSERT_TRUE(sw);
  EXPECT_DOUBLE_EQ((*sw)["t"].get<double>(), 8.5);
  const json* wall = find(ev, "collision", "b", "wall1");
  ASSERT_TRUE(wall);
  EXPECT_EQ((*wall)["a"], "p2");
  EXPECT_EQ((*wall)["outcome_a"], "kill");  // a quick jeep against a large fixed object
  // p2 is a wreck: the player moves on to the next live vehicle of the node, p1
  int drives = 0;
  for (const auto& e : ev)
    if (e["event"] == "drive") ++drives;
  EXPECT_EQ(drives, 3);
  EXPECT_EQ(ev.back()["event"], "drive");
  EXPECT_EQ(ev.back()["vehicle"], "p1");
  EXPECT_GT(ev.back()["t"].get<double>(), (*wall)["t"].get<double>());
}

TEST(PlayerReplay, TwoReplaysAreByteIdentical) {
  const auto a = tmp("player-a.jsonl"), b = tmp("player-b.jsonl");
  ASSERT_EQ(run(replay(a, kInput)).rc, 0);
  ASSERT_EQ(run(replay(b, kInput)).rc, 0);
  const std::string sa = slurp(a);
  EXPECT_GT(sa.size(), 1000u);
  EXPECT_EQ(sa, slurp(b));
}

TEST(PlayerReplay, ARecordedSessionReplaysToTheSameLog) {
  const auto first = tmp("player-rec-events.jsonl"), rec = tmp("player-rec.jsonl"), again = tmp("player-rec-again.jsonl");
  ASSERT_EQ(run(replay(first, kInput, "--record-input " + rec.string())).rc, 0);
  const std::string recorded = slurp(rec);
  EXPECT_NE(recorded.find("\"action\":\"switch\""), std::string::npos) << recorded;
  const auto o = run(replay(again, rec.string()));
  ASSERT_EQ(o.rc, 0) << o.text;
  EXPECT_EQ(slurp(first), slurp(again));
}

TEST(PlayerReplay, BadInputExits2AndWritesNothing) {
  const auto bad = test::write_file("player-bad.jsonl",
                                    "{\"t\": 1.0, \"action\": \"throttle\", \"value\": 1.0}\n"
                                    "{\"t\": 2.0, \"action\": \"switch\", \"to\": \"nobody\"}\n"
                                    "{\"t\": 3.0, \"action\": \"steer\", \"value\": 7}\n");
  const auto f = tmp("player-bad-events.jsonl");
  auto o = run(replay(f, bad.string()));
  EXPECT_EQ(o.rc, 2) << o.text;
  EXPECT_NE(o.text.find(bad.string() + ":3: value: must be from -1 to 1"), std::string::npos) << o.text;
  EXPECT_FALSE(std::filesystem::exists(f));
  const auto bad2 = test::write_file("player-bad2.jsonl", "{\"t\": 2.0, \"action\": \"switch\", \"to\": \"nobody\"}\n");
  o = run(replay(f, bad2.string()));
  EXPECT_EQ(o.rc, 2) << o.text;
  EXPECT_NE(o.text.find(bad2.string() + ":1: to: 'nobody' is not a vehicle of this node"), std::string::npos) << o.text;
  EXPECT_FALSE(std::filesystem::exists(f));
  o = run(replay(f, kInput, "--drive ghost"));
  EXPECT_EQ(o.rc, 2) << o.text;
  EXPECT_NE(o.text.find("--drive:0: drive: 'ghost' is not a live vehicle of this node"), std::string::npos) << o.text;
  EXPECT_FALSE(std::filesystem::exists(f));
}

TEST(PlayerReplay, DriveChoosesTheStartingVehicle) {
  const auto f = tmp("player-drive.jsonl");
  const auto quiet = test::write_file("player-quit.jsonl", "{\"t\": 0.3, \"action\": \"quit\"}\n");
  const auto o = run(replay(f, quiet.string(), "--drive p2"));
  ASSERT_EQ(o.rc, 0) << o.text;
  const auto ev = events(f);
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0]["vehicle"], "p2");
}
