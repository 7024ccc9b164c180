// Snapshot policy (issue 16): imminent frames exactly 0.5 s before the event, result frames
// 1 s after, a budget per run and per minute that skips frames but keeps the event log
// complete, and periodic frames never taken from inside a wreck.
#ifdef NPSNET_HAVE_RENDER
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "support/fixture.hpp"
#include "support/npsnet_cli.hpp"

using namespace npsnet;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {
struct NodeRun {
  test::CliOut out;
  std::vector<json> events;
  std::vector<json> of(const std::string& type) const {
    std::vector<json> r;
    for (const auto& e : events)
      if (e["event"] == type) r.push_back(e);
    return r;
  }
};
NodeRun run_into(const std::string& name, const std::string& args) {
  const auto dir = npsnet::test::scratch_dir() / name;
  fs::remove_all(dir);
  NodeRun r;
  r.out = test::npsnet_cli("run --quiet --size 160x90 --snapshots " + dir.string() + " " + args);
  std::ifstream in(dir / "events.jsonl");
  for (std::string line; std::getline(in, line);) r.events.push_back(json::parse(line));
  return r;
}
bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}
}  // namespace

TEST(SnapshotPolicy, ImminentExactlyHalfASecondBeforeAndResultOneSecondAfter) {
  for (const std::string dt : {"0.1", "0.03", "0.2"}) {
    SCOPED_TRACE("dt " + dt);
    const NodeRun r = run_into("timing-" + dt, "--dt " + dt);
    ASSERT_EQ(r.out.rc, 0) << r.out.text;
    std::map<std::string, double> imminent_t;
    int imminent = 0, result = 0;
    for (const auto& s : r.of("snapshot")) {
      const std::string f = s["file"];
      const double t = s["t"], scene = s["scene_t"];
      if (ends_with(f, "-imminent.png")) {
        // The event it shows is logged at this tick, t; the frame shows the world of t - 0.5 s.
        if (t >= 0.5) { EXPECT_NEAR(scene, t - 0.5, 0.0011) << f; }
        imminent_t[f.substr(0, f.size() - 13)] = t;
        ++imminent;
      } else if (ends_with(f, "-result.png")) {
        EXPECT_NEAR(scene, t, 1e-9) << f;
        // the first tick at or after 1 s (exactly 1 s when dt divides it)
        const double late = t - (imminent_t.at(f.substr(0, f.size() - 11)) + 1.0);
        EXPECT_GE(late, -1e-6) << f;
        EXPECT_LT(late, std::stod(dt) - 1e-6) << f;
        ++result;
      }
    }
    EXPECT_EQ(imminent, 13);
    EXPECT_EQ(result, 13);
  }
}

TEST(SnapshotPolicy, BudgetPerRunSkipsFramesButTheEventLogStaysComplete) {
  const NodeRun full = run_into("budget-full", "");
  const NodeRun cut = run_into("budget-4", "--max-snapshots 4");
  ASSERT_EQ(full.out.rc, 0) << full.out.text;
  ASSERT_EQ(cut.out.rc, 0) << cut.out.text;
  EXPECT_EQ(full.of("snapshot").size(), 27u);  // 13 pairs + the start view 0000-view-player1-driver.png
  EXPECT_TRUE(full.of("snapshot_skipped").empty());
  EXPECT_EQ(cut.of("snapshot").size(), 3u);  // the start view and one pair (a second pair would make 5)
  EXPECT_EQ(cut.of("snapshot_skipped").size(), 24u);
  for (const auto& s : cut.of("snapshot_skipped")) {
    EXPECT_NE(s["reason"].get<std::string>().find("at most 4 frames per run"), std::string::npos);
    EXPECT_FALSE(fs::exists(s["file"].get<std::string>())) << s;
  }
  for (const auto* type : {"collision", "damage", "fire", "detonation", "crater"})
    EXPECT_EQ(cut.of(type), full.of(type)) << type;  // same simulation, every event still there
  EXPECT_NE(cut.out.text.find("warning: t = "), std::string::npos) << cut.out.text;
  EXPECT_NE(cut.out.text.find("24 snapshot frame(s) skipped"), std::string::npos) << cut.out.text;
}

TEST(SnapshotPolicy, BudgetPerMinuteOfScenarioTime) {
  // 90 s with a frame every second (t = 0 ... 89): 90 periodic frames + 26 of the cases + the
  // start view, at most 20 a minute.
  const NodeRun r = run_into("budget-minute", "--seconds 90 --snapshot-every 1 --max-snapshots-per-minute 20");
  ASSERT_EQ(r.out.rc, 0) << r.out.text;
  std::vector<double> taken;  // when each frame was taken from the budget (a pair: at its event)
  for (const auto& s : r.of("snapshot")) {
    const std::string f = s["file"];
    taken.push_back(s["t"].get<double>() - (ends_with(f, "-result.png") ? 1.0 : 0.0));
  }
  for (double t0 : taken) {
    int n = 0;
    for (double t : taken) n += t > t0 - 60 + 1e-6 && t <= t0 + 1e-6;
    EXPECT_LE(n, 20) << "in the minute before t = " << t0;
  }
  EXPECT_GE(taken.size(), 30u);  // the second minute has its own 20
  EXPECT_FALSE(r.of("snapshot_skipped").empty());
  EXPECT_EQ(taken.size() + r.of("snapshot_skipped").size(), 27u + 90u);
}

TEST(SnapshotPolicy, PeriodicFramesNeverFromInsideAWreck) {
  // tank6 dies on the watertower at t ~ 5 s (the A.9 case); a scenario of its own, with one
  // other vehicle of this node behind it (alive) or without.
  const std::string head = "duration_s = 10.0\n[world]\nterrain = \"" + test::source("terrain/default.tif").string() +
                           "\"\norigin_geodetic = [35.98, -121.25, 0.0]\n"
                           "[[vehicle]]\nid = \"tank6\"\nkind = \"m1a1\"\nposition_m = [7962.5, 3062.5]\n"
                           "heading_deg = 90.0\nspeed_kmh = 60.0\n"
                           "[[fixed]]\nid = \"tower2\"\nkind = \"watertower\"\nposition_m = [8062.5, 3062.5]\n";
  const std::string other = "[[vehicle]]\nid = \"tank2\"\nkind = \"m1a1\"\nposition_m = [7562.5, 3062.5]\n";
  for (const bool with_other : {true, false}) {
    SCOPED_TRACE(with_other ? "another vehicle alive" : "only the wreck");
    const auto sc = test::write_file(with_other ? "wreck-two.toml" : "wreck-one.toml", head + (with_other ? other : ""));
    const NodeRun r = run_into(with_other ? "wreck-two" : "wreck-one", "--scenario " + sc.string() + " --snapshot-every 1");
    ASSERT_EQ(r.out.rc, 0) << r.out.text;
    double killed_t = -1;
    for (const auto& d : r.of("damage"))
      if (d["object"] == "tank6" && d["to_state"] == "wreck") killed_t = d["t"];
    ASSERT_GT(killed_t, 0) << "tank6 must die in this scenario";
    int after = 0;
    for (const auto& s : r.of("snapshot")) {
      if (!s.contains("camera")) continue;  // the collision's own frames
      if (s["t"].get<double>() <= killed_t) {
        EXPECT_EQ(s["camera"], "driver");
        EXPECT_EQ(s["vehicle"], "tank6");
      } else {
        ++after;
        EXPECT_EQ(s["camera"], with_other ? "driver" : "outside") << s;
        EXPECT_EQ(s["vehicle"], with_other ? "tank2" : "tank6") << s;
      }
    }
    EXPECT_GE(after, 3);
  }
}
#endif
