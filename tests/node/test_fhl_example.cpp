// The bundled "own exercise" (issue 16, README "Your own exercise"): scenarios/fhl is what the
// committed script scripts/make-fhl-example.py makes (run here again with python3-gdal, compared
// raster to raster and CSV to CSV); `npsnet check` explains it (the UTM 10N raster places itself:
// its corners inside the printed extent); `npsnet run` plays its ground, ship and air vehicles
// to the outcomes the scenario's comments promise. And every scenario a --help example names exists.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "support/fixture.hpp"
#include "support/gdal_read.hpp"
#include "support/npsnet_cli.hpp"
#include "../net/tests/run_command.hpp"  // nettest::run_command: a shell command's exit code and stdout

using namespace npsnet;
namespace fs = std::filesystem;

namespace {

fs::path test_dir() {
  const fs::path d = test::scratch_dir() / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(d);
  return d;
}

std::string read_text(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// UTM zone 10N (EPSG:32610) -> lat, lon through PROJ.
std::pair<double, double> utm10n_to_geodetic(double e, double n) {
  double x = e, y = n;
  if (!test::transform_epsg(32610, 4326, &x, &y, 1)) x = y = NAN;
  return {y, x};
}

std::vector<nlohmann::json> events(const fs::path& f) {
  std::vector<nlohmann::json> out;
  std::ifstream in(f);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(nlohmann::json::parse(line));
  return out;
}

}  // namespace

TEST(FhlExample, TheCommittedScriptMakesTheBundledFiles) {
  if (nettest::run_command("/usr/bin/python3 -c 'from osgeo import gdal; import numpy' 2>/dev/null").rc != 0)
    GTEST_SKIP() << "python3-gdal / python3-numpy are not installed (scripts/install-deps.sh installs them)";
  const fs::path d = test_dir();
  fs::create_directories(d / "scenarios" / "fhl");
  const auto made = nettest::run_command("cd '" + d.string() + "' && /usr/bin/python3 '" +
                                         test::source("scripts/make-fhl-example.py").string() + "' 2>&1");
  ASSERT_EQ(made.rc, 0) << made.out;
  EXPECT_EQ(read_text(d / "scenarios/fhl/fhl-objects.csv"), read_text(test::source("scenarios/fhl/fhl-objects.csv")));
  // The raster: same grid, georeference, CRS and heights (the file's octets may differ by GDAL version).
  const test::RasterGrid a = test::read_raster_grid(d / "scenarios/fhl/fhl-utm10n.tif"), b = test::read_raster_grid(test::source("scenarios/fhl/fhl-utm10n.tif"));
  ASSERT_GT(a.cols, 100);
  EXPECT_EQ(a.cols, b.cols);
  EXPECT_EQ(a.rows, b.rows);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(a.gt[i], b.gt[i]) << "geotransform " << i;
  EXPECT_EQ(a.epsg, "32610");
  EXPECT_EQ(b.epsg, "32610");
  EXPECT_TRUE(a.h == b.h) << "heights differ from the committed raster";
}

TEST(FhlExample, CheckExplainsTheProjectedWorld) {
  const fs::path scen = test::source("scenarios/fhl/fhl.toml");
  const auto c = test::npsnet_cli("check " + scen.string());
  ASSERT_EQ(c.rc, 0) << c.text;
  EXPECT_NE(c.text.find("coordinate system: WGS 84 / UTM zone 10N (EPSG:32610)"), std::string::npos) << c.text;
  EXPECT_NE(c.text.find("(from the raster's coordinate system)"), std::string::npos) << c.text;
  EXPECT_EQ(c.text.find("warning"), std::string::npos) << c.text;
  std::smatch m;
  const std::string& t = c.text;
  ASSERT_TRUE(std::regex_search(t, m, std::regex(R"(extent: x 0 to ([0-9.]+) m \(east\), y 0 to ([0-9.]+) m)"))) << t;
  const test::RasterGrid g = test::read_raster_grid(test::source("scenarios/fhl/fhl-utm10n.tif"));
  ASSERT_GT(g.cols, 100);
  // Resampled into the local TM frame: the raster, turned by the grid convergence (~1 deg here),
  // fits in an extent a little larger than its own side.
  const double side = (g.cols - 1) * g.gt[1];
  for (int k = 1; k <= 2; ++k) {
    EXPECT_GE(std::stod(m[k]), side) << t;
    EXPECT_LE(std::stod(m[k]), side * 1.03) << t;
  }
  std::smatch sw, ne;
  ASSERT_TRUE(std::regex_search(t, sw, std::regex(R"(origin \(SW corner, local 0,0\): lat (-?[0-9.]+), lon (-?[0-9.]+))"))) << t;
  ASSERT_TRUE(std::regex_search(t, ne, std::regex(R"(NE corner: lat (-?[0-9.]+), lon (-?[0-9.]+))"))) << t;
  const double lat0 = std::stod(sw[1]), lon0 = std::stod(sw[2]), lat1 = std::stod(ne[1]), lon1 = std::stod(ne[2]);
  // The raster's four corner posts (PROJ) lie inside the printed corners, within ~100 m.
  const double slack = 0.0012;
  for (int i : {0, g.cols - 1})
    for (int j : {0, g.rows - 1}) {
      const auto [lat, lon] = utm10n_to_geodetic(g.gt[0] + (i + 0.5) * g.gt[1], g.gt[3] + (j + 0.5) * g.gt[5]);
      EXPECT_GT(lat, lat0 - slack) << i << "," << j;
      EXPECT_LT(lat, lat1 + slack) << i << "," << j;
      EXPECT_GT(lon, lon0 - slack) << i << "," << j;
      EXPECT_LT(lon, lon1 + slack) << i << "," << j;
    }
  EXPECT_NE(t.find("fixed objects: 61 (building 2, telephone_pole 10, tree 48, watertower 1)"), std::string::npos) << t;
  EXPECT_NE(t.find("    node 1: f16 1 m1a1 1 patrol_ship 1\n"), std::string::npos) << t;
  EXPECT_NE(t.find("    node 2: ah64 1 hmmwv 1\n"), std::string::npos) << t;
}

// The whole 30 s scenario, one process: the tank crushes the watertower (ground), the helicopter's
// round makes a crater at its target (air); the ship and the jet are loaded (check refuses a ship
// on land) and are intact at the end, as is every vehicle but the tank. (The state file holds no
// positions: where the ship and jet went is not asserted here.)
TEST(FhlExample, RunsWithGroundShipAndAirVehicles) {
  const fs::path d = test_dir();
  const auto r = test::npsnet_cli("run --no-render --quiet --scenario " + test::source("scenarios/fhl/fhl.toml").string() +
                                  " --events " + (d / "e.jsonl").string() + " --state-out " + (d / "s.json").string());
  ASSERT_EQ(r.rc, 0) << r.text;
  const auto ev = events(d / "e.jsonl");
  std::set<std::string> seen;
  for (const auto& e : ev) {
    if (e["event"] == "collision") seen.insert("collision " + e["a"].get<std::string>() + "/" + e["b"].get<std::string>() + " " +
                                               e["outcome_a"].get<std::string>() + "/" + e["outcome_b"].get<std::string>());
    if (e["event"] == "damage") seen.insert("damage " + e["object"].get<std::string>() + " " + e["to_state"].get<std::string>());
    if (e["event"] == "fire") seen.insert("fire " + e["shooter"].get<std::string>());
    if (e["event"] == "crater") {
      EXPECT_NEAR(e["point"][0].get<double>(), 3000.0, 5.0);
      EXPECT_NEAR(e["point"][1].get<double>(), 3100.0, 5.0);
      seen.insert("crater");
    }
  }
  for (const char* s : {"collision tank1/tower1 kill/destroy_fixed", "damage tower1 crushed", "damage tank1 wreck", "fire heli1", "crater"})
    EXPECT_TRUE(seen.count(s)) << s << " missing from " << (d / "e.jsonl");
  const auto state = nlohmann::json::parse(read_text(d / "s.json"));
  std::map<std::string, std::string> states;
  for (const auto& e : state["entities"]) states[e["id"].get<std::string>() + " " + e["kind"].get<std::string>()] = e["state"];
  const std::map<std::string, std::string> want = {{"tank1 m1a1", "wreck"},   {"jeep1 hmmwv", "intact"}, {"ship1 patrol_ship", "intact"},
                                                   {"jet1 f16", "intact"},    {"heli1 ah64", "intact"}};
  EXPECT_EQ(states, want);
}

// Every scenario file a --help example names is in the repository.
TEST(FhlExample, HelpExamplesNameScenariosThatExist) {
  std::string help;
  for (const char* cmd : {"--help", "run --help", "check --help", "record --help", "replay --help"}) help += test::npsnet_cli(cmd).text;
  const std::regex scen(R"((scenarios/[A-Za-z0-9_./-]+\.toml))");
  int named = 0;
  for (std::sregex_iterator it(help.begin(), help.end(), scen), end; it != end; ++it, ++named)
    EXPECT_TRUE(fs::exists(test::source((*it)[1]))) << (*it)[1] << " (a --help example) does not exist";
  EXPECT_GE(named, 2) << help;
}
