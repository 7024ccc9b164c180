// Faults (issue 11): scripts/faults.sh runs four nodes in network namespaces on a bridge, every
// link impaired in user space (loss 20 %, duplicates 5 %, reordering 25 %, 20 +- 10 ms), with a
// 10 s partition that heals, a node killed with SIGKILL and started again, and a late joiner 30 s
// in, both given the exercise's start time (they join at its current time); 5 s after the faults stop every node writes its world. The script exits 0 only when all
// four worlds agree (vehicles and damage states, changed objects, craters) and their event logs
// the same collisions across nodes with the same outcomes. A control run of the
// same exercise without faults is the reference for what does not depend on timing: the craters
// and the changed objects must be the control's. Skips where namespaces are not available (77).
// Each run is bounded (nodes end 48 s after launch; the script kills them 30 s later); the test
// runs both at once and gives them 150 s from their start, then SIGTERM (the script's trap
// deletes its namespaces by name) and 10 s each to clean up.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "support/dirs.hpp"
#include "lan_support.hpp"

namespace {
using nlohmann::json;

json state(const std::filesystem::path& dir, int k) {
  std::ifstream in(dir / ("state_" + std::to_string(k) + ".json"));
  return in ? json::parse(in, nullptr, false) : json();
}

// Starts scripts/faults.sh with `args`, its output to dir/script.txt; returns its pid.
int start_script(lan::Procs& procs, const std::filesystem::path& dir, const std::vector<std::string>& args) {
  std::vector<std::string> a{std::string(npsnet::dirs::source()) + "/scripts/faults.sh", "--out", dir.string()};
  a.insert(a.end(), args.begin(), args.end());
  return procs.start_program("/bin/bash", a, dir / "script.txt");
}
// Waits for it until UNIX time `deadline` (then SIGTERM, and 10 s for its trap to clean up).
int wait_script(lan::Procs& procs, int pid, double deadline, const std::filesystem::path& dir, std::string& out) {
  const int rc = procs.wait(pid, std::max(1.0, deadline - lan::unix_now()), 10.0);
  out = lan::read_text(dir / "script.txt");
  return rc;
}
}  // namespace

TEST(Faults, FourNodesAgreeAfterLossPartitionKillAndLateJoin) {
  lan::Procs procs;
  const auto control = lan::fresh_dir("faults_control");
  const auto faulty = lan::fresh_dir("faults");
  // The two runs at once, each in namespaces and on a port of its own (the script names them by
  // its pid): run one after the other they took 23 s of CPU in 103 s, so together they leave the
  // nodes most of the machine, and the test takes one run's 50 s instead of two.
  const double deadline = lan::unix_now() + 150.0;
  const int control_pid = start_script(procs, control, {"--control"});
  const int faulty_pid = start_script(procs, faulty, {});
  std::string control_out, out;
  const int control_rc = wait_script(procs, control_pid, deadline, control, control_out);
  const int faulty_rc = wait_script(procs, faulty_pid, deadline, faulty, out);
  if (control_rc == 77) GTEST_SKIP() << control_out;
  ASSERT_EQ(control_rc, 0) << control_out;
  // The script compares every node's collisions across nodes (pairs, outcome_a, outcome_b) with
  // node 1's and prints node 1's: the kills of t1 and a2 and of b3 (node 3, killed and restarted
  // later) and k1, once each.
  const std::string kKill = "collisions across nodes: [('a2', 't1', 'kill', 'kill'), ('b3', 'k1', 'kill', 'kill')]";
  EXPECT_NE(control_out.find(kKill), std::string::npos) << control_out;
  ASSERT_EQ(faulty_rc, 0) << out;
  // The faults happened: frames lost, duplicated, reordered and cut on the links.
  for (const char* what : {"lost", "duplicated", "reordered"}) EXPECT_NE(out.find(std::string(what) + " "), std::string::npos);
  EXPECT_NE(out.find("t=12 node 3 killed"), std::string::npos) << out;
  // Whether t1 and a2 meet here depends on a2's first Entity State reaching node 1 before ~3 s
  // (a lost one hides a2 for a heartbeat: issue 11, not yet mended): the script's comparison says
  // that every node logged the same collisions across nodes, whichever there were.
  const json ref = state(control, 1);
  ASSERT_TRUE(ref.is_object());
  EXPECT_EQ(ref["craters"].size(), 3u) << "three rounds, three craters";
  for (int k = 1; k <= 4; ++k) {
    SCOPED_TRACE("node " + std::to_string(k));
    const json s = state(faulty, k);
    ASSERT_TRUE(s.is_object());
    EXPECT_EQ(s["craters"], ref["craters"]);
    EXPECT_EQ(s["fixed"], ref["fixed"]);
    EXPECT_EQ(s["entities"].size(), ref["entities"].size());
  }
  // The late joiner and the restarted node learned what happened before them from repeats.
  EXPECT_NE(lan::read_text(faulty / "out_n4.txt").find("repeats received and ignored"), std::string::npos);
  // Both joined at the exercise's time (--start-at T0): nothing of the past replayed as new.
  for (const char* tag : {"n3b", "n4"}) {
    SCOPED_TRACE(tag);
    const auto ev = lan::read_events(faulty / ("events_" + std::string(tag) + ".jsonl"));
    ASSERT_FALSE(ev.empty());
    EXPECT_EQ(ev.front()["event"], "exercise_joined");
    EXPECT_GE(ev.front()["t"].get<double>(), std::string(tag) == "n4" ? 29.0 : 15.0);
    for (const auto& f : lan::of_type(ev, "fire"))  // only other nodes' rounds (none after 14 s)
      EXPECT_TRUE(f.value("remote", false)) << f.dump() << ": s3's rounds of t = 2 s and 10 s are not fired again";
  }
  std::filesystem::remove_all(control);
  std::filesystem::remove_all(faulty);
}
