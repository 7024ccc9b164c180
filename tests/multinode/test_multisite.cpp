// The routed multi-site exercise, short version (scripts/multisite.sh --short): three sites in
// network namespaces, two nodes each on a bridge, joined by a router namespace running smcrouted
// with static (*,G) routes; site links delayed 30 ms each way (netem, or scripts/linkshaper.py in
// user space where the kernel has no netem; no loss in this short run); every node with
// --aoi 2000. Every node's event log must hold the cross-site collision s1t1/s2a1 once with the
// same outcomes (decided at site 1) and the crater of site 3's round at the same place. Skips
// where namespaces or smcroute are not available (the script exits 77); the script is bounded
// (its nodes run 8 s, it kills them 30 s later) and the test gives it 110 s, then SIGTERM (its
// trap removes the namespaces by name) and 10 s later SIGKILL.
#include <gtest/gtest.h>

#include <set>

#include "support/dirs.hpp"
#include "lan_support.hpp"

namespace {
using nlohmann::json;

using lan::of_type;
}  // namespace

TEST(MultiSite, CrossSiteCollisionAndCraterReachEverySite) {
  const auto dir = lan::fresh_dir("multisite");
  lan::Procs procs;
  const std::string script = std::string(npsnet::dirs::source()) + "/scripts/multisite.sh";
  const int pid = procs.start_program("/bin/bash", {script, "--short", "--out", dir.string()}, dir / "script.txt");
  const int rc = procs.wait(pid, 110.0, 10.0);
  const std::string out = lan::read_text(dir / "script.txt");
  if (rc == 77) GTEST_SKIP() << out;
  EXPECT_EQ(rc, 0) << out;

  const std::vector<std::string> tags{"s1n1", "s1n2", "s2n1", "s2n2", "s3n1", "s3n2"};
  std::vector<json> hits, craters;
  for (const auto& tag : tags) {
    SCOPED_TRACE(tag);
    const auto ev = lan::read_events(dir / ("events_" + tag + ".jsonl"));
    std::vector<json> c;
    for (const auto& e : of_type(ev, "collision"))
      if (std::set<std::string>{e["a"], e["b"]} == std::set<std::string>{"s1t1", "s2a1"}) c.push_back(e);
    ASSERT_EQ(c.size(), 1u) << lan::read_text(dir / ("out_" + tag + ".txt"));
    hits.push_back(c[0]);
    const auto cr = of_type(ev, "crater");
    ASSERT_EQ(cr.size(), 1u) << "site 3's round craters the ground once on every node";
    craters.push_back(cr[0]);
    EXPECT_NE(lan::read_text(dir / ("out_" + tag + ".txt")).find("aoi groups="), std::string::npos);
  }
  for (size_t n = 1; n < hits.size(); ++n) {
    EXPECT_EQ(hits[n]["outcome_a"], hits[0]["outcome_a"]);
    EXPECT_EQ(hits[n]["outcome_b"], hits[0]["outcome_b"]);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(craters[n]["point"][k].get<double>(), craters[0]["point"][k].get<double>(), 0.05);
  }
  EXPECT_NE(hits[0]["method"], "network") << "s1n1 (site 1, node 1) decides: the lower DIS entity id";
  EXPECT_EQ(hits[2]["method"], "network");
  std::filesystem::remove_all(dir);
}
