// --track-every and `npsnet dr-error` (issue 11): hand-made event logs with known errors give
// known percentiles; bad logs are FILE:LINE: field: message, exit 2; a run with the flag logs
// every vehicle at the ticks it should.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <nlohmann/json.hpp>

#include "support/dirs.hpp"
#include "node/dr_error.hpp"
#include "support/npsnet_cli.hpp"
#include "support/scratch.hpp"
#include "world/error.hpp"

using namespace npsnet;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {
using test::fresh_dir;
json track(long frame, const std::string& id, const char* source, double x, double y, double z) {
  return {{"event", "track"}, {"t", frame * 0.1}, {"frame", frame}, {"id", id}, {"source", source}, {"pos", {x, y, z}}};
}
void write_lines(const fs::path& f, const std::vector<std::string>& lines) {
  std::ofstream out(f);
  for (const auto& l : lines) out << l << "\n";
}
// Two nodes' logs: node A owns a1 (frames 1-100 at (f, 2f, 10)), node B holds a copy of it off by
// (0.03 f, 0.04 f, 0.12 f): horizontal error 0.05 f, 3-D 0.13 f. B owns b1 (frames 1-10), which A
// holds exactly at frames 1-12 (11 and 12: B has no sample, unmatched). Other events in between.
std::pair<fs::path, fs::path> hand_made_logs(const fs::path& dir) {
  std::vector<std::string> a, b;
  a.push_back(json{{"event", "entity_joined"}, {"t", 0.1}, {"frame", 1}, {"id", "b1"}}.dump());
  for (long f = 1; f <= 100; ++f) {
    a.push_back(track(f, "a1", "local", f, 2.0 * f, 10).dump());
    b.push_back(track(f, "a1", "remote", f + 0.03 * f, 2.0 * f + 0.04 * f, 10 + 0.12 * f).dump());
    if (f <= 10) b.push_back(track(f, "b1", "local", 5, 6, 7).dump());
    if (f <= 12) a.push_back(track(f, "b1", "remote", 5, 6, 7).dump());
  }
  write_lines(dir / "a.jsonl", a);
  write_lines(dir / "b.jsonl", b);
  return {dir / "a.jsonl", dir / "b.jsonl"};
}
}  // namespace

TEST(DrError, PercentilesByNearestRank) {
  std::vector<double> e;
  for (int i = 100; i >= 1; --i) e.push_back(i);  // any order
  const auto s = node::error_stats(e);
  EXPECT_EQ(s.count, 100);
  EXPECT_EQ(s.p50, 50);
  EXPECT_EQ(s.p90, 90);
  EXPECT_EQ(s.p99, 99);
  EXPECT_EQ(s.max, 100);
  std::vector<double> one{3.5};
  const auto o = node::error_stats(one);
  EXPECT_EQ(o.p50, 3.5);
  EXPECT_EQ(o.p99, 3.5);
  std::vector<double> none;
  EXPECT_EQ(node::error_stats(none).count, 0);
}

TEST(DrError, HandMadeLogsGiveTheirKnownErrors) {
  const auto [a, b] = hand_made_logs(fresh_dir("dr-error-known"));
  const auto r = node::dr_error({a, b});
  ASSERT_EQ(r.per_log.size(), 2u);
  // Observer A: b1 exactly, 10 matched, 2 unmatched.
  EXPECT_EQ(r.per_log[0].name, "a.jsonl");
  EXPECT_EQ(r.per_log[0].horizontal.count, 10);
  EXPECT_EQ(r.per_log[0].unmatched, 2);
  EXPECT_NEAR(r.per_log[0].full.max, 0.0, 1e-12);
  // Observer B: a1, errors 0.05 f and 0.13 f for f = 1..100.
  const auto& bb = r.per_log[1];
  EXPECT_EQ(bb.horizontal.count, 100);
  EXPECT_NEAR(bb.horizontal.p50, 2.5, 1e-9);
  EXPECT_NEAR(bb.horizontal.p90, 4.5, 1e-9);
  EXPECT_NEAR(bb.horizontal.p99, 4.95, 1e-9);
  EXPECT_NEAR(bb.horizontal.max, 5.0, 1e-9);
  EXPECT_NEAR(bb.full.p50, 6.5, 1e-9);
  EXPECT_NEAR(bb.full.p99, 12.87, 1e-9);
  EXPECT_NEAR(bb.full.max, 13.0, 1e-9);
  // All: 10 zeros and 0.05 f: ranks 55, 99, 109 of 110.
  EXPECT_EQ(r.all.horizontal.count, 110);
  EXPECT_EQ(r.all.unmatched, 2);
  EXPECT_NEAR(r.all.horizontal.p50, 0.05 * 45, 1e-9);
  EXPECT_NEAR(r.all.horizontal.p90, 0.05 * 89, 1e-9);
  EXPECT_NEAR(r.all.horizontal.p99, 0.05 * 99, 1e-9);
  // Per entity.
  ASSERT_EQ(r.per_entity.size(), 2u);
  EXPECT_EQ(r.per_entity[0].name, "a1");
  EXPECT_NEAR(r.per_entity[0].full.p90, 0.13 * 90, 1e-9);
  // A window of scenario time: frames 20-40 only (a1's errors 0.05 x 20..40).
  const auto w = node::dr_error({a, b}, 2.0, 4.0);
  EXPECT_EQ(w.all.horizontal.count, 21);
  EXPECT_NEAR(w.all.horizontal.p50, 0.05 * 30, 1e-9);
  EXPECT_NEAR(w.all.horizontal.max, 0.05 * 40, 1e-9);
}

TEST(DrError, CommandPrintsTheFiguresAndRejectsBadLogs) {
  const auto dir = fresh_dir("dr-error-cli");
  const auto [a, b] = hand_made_logs(dir);
  auto o = test::npsnet_cli("dr-error " + a.string() + " " + b.string());
  EXPECT_EQ(o.rc, 0) << o.text;
  EXPECT_NE(o.text.find("observer b.jsonl"), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("4.950"), std::string::npos) << o.text;  // B's horizontal p99
  const auto bad = dir / "bad.jsonl";
  const auto expect_bad = [&](const std::vector<std::string>& lines, const std::string& want) {
    write_lines(bad, lines);
    const auto r = test::npsnet_cli("dr-error " + a.string() + " " + bad.string());
    EXPECT_EQ(r.rc, 2) << r.text;
    EXPECT_NE(r.text.find(want), std::string::npos) << "want " << want << "\n" << r.text;
    EXPECT_EQ(r.text.find("observer"), std::string::npos) << r.text;  // no figures
  };
  const std::string ok = track(1, "x", "local", 1, 2, 3).dump();
  expect_bad({ok, "{\"event\": \"track\", "}, bad.string() + ":2: json: not a JSON object");
  expect_bad({ok, R"({"event":"track","t":0.1,"frame":1,"id":"y","source":"remote"})"}, bad.string() + ":2: pos: must be [x, y, z]");
  expect_bad({R"({"event":"track","t":0.1,"frame":1,"id":"y","source":"mine","pos":[1,2,3]})"}, bad.string() + ":1: source: must be");
  expect_bad({R"({"event":"track","t":0.1,"frame":1.5,"id":"y","source":"local","pos":[1,2,3]})"}, bad.string() + ":1: frame: ");
  expect_bad({R"({"event":"track","t":0.1,"frame":1,"id":"y","source":"local","pos":[1,"2",3]})"}, bad.string() + ":1: pos: not a finite number");
  expect_bad({R"({"event":"collision","t":0.1})"}, bad.string() + ":0: track: no track events");
  expect_bad({track(1, "a1", "local", 1, 2, 3).dump()}, bad.string() + ":1: id: 'a1' is local");  // a1 is A's
  const auto missing = test::npsnet_cli("dr-error " + a.string() + " " + (dir / "nope.jsonl").string());
  EXPECT_EQ(missing.rc, 2);
  EXPECT_NE(missing.text.find((dir / "nope.jsonl").string() + ":0: file: cannot read"), std::string::npos) << missing.text;
  EXPECT_EQ(test::npsnet_cli("dr-error " + a.string()).rc, 2);  // one log: nothing to match
}

TEST(DrError, TrackEveryLogsEveryVehicleAtItsTicks) {
  const auto dir = fresh_dir("track-every");
  const auto events = dir / "e.jsonl";
  const auto o = test::npsnet_cli("run --scenario " + (fs::path(npsnet::dirs::source()) / "tests/multinode/data/lan.toml").string() +
                                  " --no-render --quiet --seconds 2 --track-every 0.2 --events " + events.string());
  ASSERT_EQ(o.rc, 0) << o.text;
  std::ifstream in(events);
  std::string line;
  std::map<long, std::set<std::string>> by_frame;
  while (std::getline(in, line)) {
    const auto e = json::parse(line);
    if (e["event"] != "track") continue;
    const long f = e["frame"];
    EXPECT_EQ(f % 2, 0) << line;  // every 2 ticks of 0.1 s
    EXPECT_NEAR(e["t"].get<double>(), f * 0.1, 1e-9) << line;
    EXPECT_EQ(e["source"], "local") << line;  // no network: every vehicle is this node's
    EXPECT_EQ(e["pos"].size(), 3u);
    by_frame[f].insert(e["id"]);
  }
  ASSERT_EQ(by_frame.size(), 10u);  // frames 2, 4, ..., 20
  EXPECT_EQ(by_frame.begin()->first, 2);
  for (const auto& [f, ids] : by_frame) EXPECT_EQ(ids.size(), 6u) << "frame " << f;  // lan.toml's 6 vehicles
}
