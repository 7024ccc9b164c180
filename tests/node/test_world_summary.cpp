// `npsnet check SCENARIO` explains the world (issue 16): the summary's numbers against the known
// default world, read here on their own (GDAL for the raster, toml++ and the CSV for objects and
// vehicles, ECEF distances for the degrees); and the origin_geodetic warning (check and run) for
// a raster that has a coordinate system, absent otherwise.
#include <gtest/gtest.h>

#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <vector>

#include "core/geodesy.hpp"
#include "support/fixture.hpp"
#include "support/gdal_read.hpp"
#include "support/npsnet_cli.hpp"

using namespace npsnet;
namespace fs = std::filesystem;

namespace {

// The first match of `re` in `text`, its groups as numbers; fails the test when absent.
std::vector<double> numbers(const std::string& text, const std::string& re) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(re))) {
    ADD_FAILURE() << "no line matching /" << re << "/ in:\n" << text;
    return std::vector<double>(8, NAN);
  }
  std::vector<double> v;
  for (size_t i = 1; i < m.size(); ++i) v.push_back(std::stod(m[i]));
  return v;
}

// Straight-line (chord) distance between two geodetic points on the ellipsoid, metres.
double chord_m(double lat0, double lon0, double lat1, double lon1) {
  return (geo::geodetic_to_ecef({lat0, lon0, 0}) - geo::geodetic_to_ecef({lat1, lon1, 0})).norm();
}

fs::path test_dir() {
  const fs::path d = test::scratch_dir() / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST(WorldSummary, DefaultScenarioAgainstTheKnownWorld) {
  const fs::path scen = test::source("scenarios/default.toml");
  const auto c = test::npsnet_cli("check " + scen.string());
  ASSERT_EQ(c.rc, 0) << c.text;
  const std::string& out = c.text;

  // Posts, spacing, extent and heights, as GDAL reads the raster.
  const test::RasterGrid r = test::read_raster_grid(test::source("terrain/default.tif"));
  ASSERT_GT(r.cols, 1);
  ASSERT_EQ(r.h.size(), static_cast<size_t>(r.cols) * r.rows);
  const double spacing = r.gt[1], width = (r.cols - 1) * spacing, depth = (r.rows - 1) * spacing;
  const auto ext = numbers(out, R"(extent: x 0 to ([0-9.]+) m \(east\), y 0 to ([0-9.]+) m \(north\); (\d+) x (\d+) posts at ([0-9.]+) m)");
  EXPECT_NEAR(ext[0], width, 0.01);
  EXPECT_NEAR(ext[1], depth, 0.01);
  EXPECT_EQ(ext[2], r.cols);
  EXPECT_EQ(ext[3], r.rows);
  EXPECT_NEAR(ext[4], spacing, 0.001);
  EXPECT_NE(out.find("coordinate system: none"), std::string::npos) << "default.tif has no CRS\n" << out;

  // Origin: origin_geodetic of the scenario (no CRS); the NE corner lies the extent's diagonal
  // away on the ellipsoid (TM scale error < 1e-5 here), the degrees are the corners' difference.
  const auto toml = toml::parse_file(scen.string());
  const auto* og = toml["world"]["origin_geodetic"].as_array();
  ASSERT_NE(og, nullptr);
  const double lat0 = og->get(0)->value<double>().value(), lon0 = og->get(1)->value<double>().value();
  const auto sw = numbers(out, R"(origin \(SW corner, local 0,0\): lat (-?[0-9.]+), lon (-?[0-9.]+) \(from origin_geodetic\))");
  EXPECT_NEAR(sw[0], lat0, 1e-6);
  EXPECT_NEAR(sw[1], lon0, 1e-6);
  const auto ne = numbers(out, R"(NE corner: lat (-?[0-9.]+), lon (-?[0-9.]+); ([0-9.]+) x ([0-9.]+) degrees \(lon x lat\))");
  EXPECT_NEAR(chord_m(sw[0], sw[1], ne[0], ne[1]), std::hypot(width, depth), 5.0);
  EXPECT_NEAR(chord_m(sw[0], sw[1], ne[0], sw[1]), depth, 150.0);  // the west edge, ~1 km of convergence
  EXPECT_NEAR(ne[2], ne[1] - sw[1], 1e-4);
  EXPECT_NEAR(ne[3], ne[0] - sw[0], 1e-4);
  EXPECT_NEAR(ne[3], depth / 111000.0, 0.005);  // a degree of latitude is ~111 km at 36 N

  // Heights and the water's share of the posts.
  const double wl = toml["world"]["water_level_m"].value<double>().value();
  size_t wet = 0;
  float lo = r.h[0], hi = r.h[0];
  for (float h : r.h) wet += h < wl, lo = std::min(lo, h), hi = std::max(hi, h);
  const auto hw = numbers(out, R"(heights: (-?[0-9.]+) to (-?[0-9.]+) m; water \(below ([0-9.]+) m\): ([0-9.]+) % of the posts)");
  EXPECT_NEAR(hw[0], lo, 0.051);
  EXPECT_NEAR(hw[1], hi, 0.051);
  EXPECT_NEAR(hw[2], wl, 0.01);
  EXPECT_GT(wet, 0u);
  EXPECT_NEAR(hw[3], 100.0 * wet / r.h.size(), 0.0051);

  // Objects per kind: the objects CSV plus the scenario's [[fixed]].
  std::map<std::string, int> kinds;
  int total = 0;
  {
    std::ifstream csv(test::source("terrain/default-objects.csv"));
    std::string line;
    std::getline(csv, line);  // header
    while (std::getline(csv, line)) {
      const size_t a = line.find(','), b = line.find(',', a + 1);
      if (a == std::string::npos || b == std::string::npos) continue;
      ++kinds[line.substr(a + 1, b - a - 1)], ++total;
    }
  }
  for (const auto& f : *toml["fixed"].as_array()) ++kinds[f.as_table()->get("kind")->value<std::string>().value()], ++total;
  EXPECT_GT(total, 40000);
  std::string per_kind;
  for (const auto& [k, n] : kinds) per_kind += (per_kind.empty() ? "" : ", ") + k + " " + std::to_string(n);
  EXPECT_NE(out.find("fixed objects: " + std::to_string(total) + " (" + per_kind + ")\n"), std::string::npos)
      << "expected " << total << " (" << per_kind << ")\n" << out;

  // Vehicles per node (a vehicle without `node` is node 1's), background traffic on node 1.
  std::map<int, std::map<std::string, int>> nodes;
  int vehicles = 0;
  for (const auto& v : *toml["vehicle"].as_array()) {
    const auto& t = *v.as_table();
    ++nodes[t["node"].value_or(1)][t["kind"].value<std::string>().value()], ++vehicles;
  }
  const int bg = toml["background"]["vehicles"].value_or(0);
  EXPECT_NE(out.find("vehicles: " + std::to_string(vehicles) + " in the scenario + " + std::to_string(bg) + " background (node 1)\n"),
            std::string::npos) << out;
  for (const auto& [n, ks] : nodes) {
    std::string line = "    node " + std::to_string(n) + ":";
    for (const auto& [k, c] : ks) line += " " + k + " " + std::to_string(c);
    EXPECT_NE(out.find(line + "\n"), std::string::npos) << line << "\n" << out;
  }
  EXPECT_EQ(out.find("warning"), std::string::npos) << "no CRS: origin_geodetic is used, no warning\n" << out;
}

// A raster with a coordinate system places itself: origin_geodetic is ignored, and both check and
// run say so at the line that gives it; without origin_geodetic, no warning.
TEST(WorldSummary, OriginGeodeticWithACrsRasterIsWarnedInCheckAndRun) {
  const fs::path d = test_dir();
  const std::string tif = test::source("scenarios/fhl/fhl-utm10n.tif").string();
  const std::string body = "[[vehicle]]\nid = \"tank1\"\nkind = \"m1a1\"\nposition_m = [3850.0, 4500.0]\n";
  std::ofstream(d / "with.toml") << "duration_s = 2.0\n[world]\nterrain = \"" << tif
                                 << "\"\nwater_level_m = 290.0\norigin_geodetic = [35.98, -121.25, 0.0]\n" << body;
  std::ofstream(d / "without.toml") << "duration_s = 2.0\n[world]\nterrain = \"" << tif << "\"\nwater_level_m = 290.0\n" << body;
  const std::string warn = (d / "with.toml").string() + ":5: world.origin_geodetic: warning: ignored: the terrain has a coordinate system";

  const auto c = test::npsnet_cli("check " + (d / "with.toml").string());
  EXPECT_EQ(c.rc, 0) << c.text;
  EXPECT_NE(c.text.find(warn), std::string::npos) << c.text;
  EXPECT_NE(c.text.find("(from the raster's coordinate system)"), std::string::npos) << c.text;
  // The origin it names is the raster's own, not the ignored one.
  const auto o = numbers(c.text, R"(its SW corner is at lat (-?[0-9.]+), lon (-?[0-9.]+))");
  const auto sw = numbers(c.text, R"(origin \(SW corner, local 0,0\): lat (-?[0-9.]+), lon (-?[0-9.]+))");
  EXPECT_NEAR(o[0], sw[0], 1e-6);
  EXPECT_NEAR(o[1], sw[1], 1e-6);
  EXPECT_GT(chord_m(o[0], o[1], 35.98, -121.25), 1000.0);

  const auto r = test::npsnet_cli("run --no-render --quiet --seconds 0.5 --scenario " + (d / "with.toml").string() +
                                  " --events " + (d / "with.jsonl").string());
  EXPECT_EQ(r.rc, 0) << r.text;
  EXPECT_NE(r.text.find(warn), std::string::npos) << r.text;

  const auto c2 = test::npsnet_cli("check " + (d / "without.toml").string());
  EXPECT_EQ(c2.rc, 0) << c2.text;
  EXPECT_EQ(c2.text.find("warning"), std::string::npos) << c2.text;
  const auto r2 = test::npsnet_cli("run --no-render --quiet --seconds 0.5 --scenario " + (d / "without.toml").string() +
                                   " --events " + (d / "without.jsonl").string());
  EXPECT_EQ(r2.rc, 0) << r2.text;
  EXPECT_EQ(r2.text.find("warning"), std::string::npos) << r2.text;
}
