// The views a node renders decide tiers (issue 13): through the real run path, with a collision
// budget of 0, a pair of background tanks colliding in the frame the node renders (the periodic
// snapshot from the driver's station of its vehicle) is decided by the exact tier, the same
// collision out of view by the sphere tier; with the snapshot budget spent or without rendering,
// both by the sphere tier.
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

// The observer looks east along y = 200; pair "seen" closes head-on 70-110 m ahead of it, pair
// "unseen" the same way 180 m north (about 70 degrees off its line of sight).
std::string scenario() {
  std::string s = "duration_s = 3.0\ncollision_budget_ms = 0.0\n[world]\nterrain = \"" +
                  test::source("tests/multinode/data/flat.asc").string() +
                  "\"\norigin_geodetic = [35.98, -121.25, 0.0]\n"
                  "[[vehicle]]\nid = \"observer\"\nkind = \"m1a1\"\nposition_m = [100.0, 200.0]\nheading_deg = 90.0\n";
  for (const auto& [id, y] : {std::pair<std::string, double>{"seen", 200.0}, {"unseen", 380.0}})
    for (const auto& [side, x, h] : {std::tuple<const char*, double, double>{"w", 170.0, 90.0}, {"e", 210.0, 270.0}})
      s += "[[vehicle]]\nid = \"" + id + "_" + side + "\"\nkind = \"m1a1\"\nposition_m = [" + std::to_string(x) + ", " +
           std::to_string(y) + "]\nheading_deg = " + std::to_string(h) + "\nspeed_kmh = 36.0\nsnapshots = false\n";
  return s;
}

// The tier of each pair's first collision ("seen" / "unseen").
std::map<std::string, std::string> tiers(const std::string& name, const std::string& args) {
  const auto dir = test::scratch_dir() / name;
  fs::remove_all(dir);
  const auto sc = test::write_file(name + ".toml", scenario());
  const auto out = test::npsnet_cli("run --quiet --size 160x90 --scenario " + sc.string() + " --snapshots " + dir.string() +
                                    " --events " + (dir.string() + ".jsonl") + " " + args);
  EXPECT_EQ(out.rc, 0) << out.text;
  std::map<std::string, std::string> r;
  std::ifstream in(dir.string() + ".jsonl");
  for (std::string line; std::getline(in, line);) {
    const json e = json::parse(line);
    if (e["event"] != "collision") continue;
    const std::string a = e["a"];
    const std::string pair = a.substr(0, a.find('_'));
    if (!r.count(pair)) r[pair] = e["tier"];
  }
  return r;
}

}  // namespace

TEST(ViewTiers, APairInTheRenderedViewGetsTheExactTierOneOutsideOrSkippedTheSphere) {
  auto t = tiers("view-tiers-rendered", "--snapshot-every 0.1");
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t["seen"], "mesh") << "in the driver's frame rendered every tick";
  EXPECT_EQ(t["unseen"], "sphere") << "out of view, budget 0: the thesis spheres";
  // The same frames, but the snapshot budget is spent by the first (t = 0): the later frames are
  // skipped, never seen, so they do not make their pairs exact.
  t = tiers("view-tiers-spent", "--snapshot-every 0.1 --max-snapshots 1");
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t["seen"], "sphere") << "the frame is skipped by the snapshot budget: no view";
  EXPECT_EQ(t["unseen"], "sphere");
  t = tiers("view-tiers-headless", "--no-render");
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t["seen"], "sphere") << "nothing rendered: no view";
  EXPECT_EQ(t["unseen"], "sphere");
}
#endif  // NPSNET_HAVE_RENDER
