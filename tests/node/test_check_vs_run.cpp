// `npsnet check` must catch everything `npsnet run` would reject (issue 11): every number of a
// scenario, objects file and kinds file set to extreme values; whenever the run does not succeed,
// check says so (exit 2) and the run itself exits 2 with nothing written, never 1 or a crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "support/fixture.hpp"
#include "support/npsnet_cli.hpp"

using namespace npsnet;
namespace fs = std::filesystem;

namespace {
// One folder per test: ctest runs the tests of this file in parallel processes.
fs::path kDir;

// A 2 km flat square at 50 m posts, no coordinate system (local metres).
void write_terrain() {
  kDir = npsnet::test::scratch_dir() /
         (std::string("check-vs-run-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::create_directories(kDir);
  std::ofstream t(kDir / "t.asc");
  t << "ncols 41\nnrows 41\nxllcorner 0\nyllcorner 0\ncellsize 50\n";
  for (int j = 0; j < 41; ++j) {
    for (int i = 0; i < 41; ++i) t << (i ? " " : "") << 100 + i;
    t << "\n";
  }
}

const std::map<std::string, std::string> kDefaults = {
    {"dur", "3.0"}, {"wl", "50.0"},   {"oh", "0.0"},   {"z", "100.0"}, {"hdg", "90.0"}, {"spd", "40.0"},
    {"max", "70.0"}, {"wy", "1000.0"}, {"jz", "600.0"}, {"jspd", "800.0"}, {"fh", "0.0"},  {"ft", "1.0"},
    {"bgn", "2"},   {"seed", "1"},    {"ch", "45.0"}};

std::string scenario(const std::map<std::string, std::string>& v, const std::string& kinds) {
  auto g = [&](const char* k) { return v.count(k) ? v.at(k) : kDefaults.at(k); };
  std::ostringstream s;
  s << "duration_s = " << g("dur") << "\n[world]\nterrain = \"t.asc\"\nobjects = \"o.csv\"\n"
    << (kinds.empty() ? "" : "kinds = \"" + kinds + "\"\n") << "water_level_m = " << g("wl")
    << "\norigin_geodetic = [35.98, -121.25, " << g("oh") << "]\n"
    << "[[vehicle]]\nid = \"tank1\"\nkind = \"m1a1\"\nposition_m = [500.0, 1000.0, " << g("z") << "]\nheading_deg = "
    << g("hdg") << "\nspeed_kmh = " << g("spd") << "\nmax_speed_kmh = " << g("max") << "\nwaypoints_m = [[1500.0, "
    << g("wy") << "]]\n"
    << "[[vehicle]]\nid = \"jet1\"\nkind = \"f16\"\nposition_m = [1000.0, 1000.0, " << g("jz")
    << "]\nspeed_kmh = " << g("jspd") << "\n"
    << "[[fixed]]\nid = \"tw\"\nkind = \"watertower\"\nposition_m = [1000.0, 500.0]\nheading_deg = " << g("fh") << "\n"
    << "[[fire]]\nt_s = " << g("ft") << "\nshooter = \"tank1\"\nmunition = \"he_round\"\ntarget_m = [1200.0, 1000.0]\n"
    << "[background]\nvehicles = " << g("bgn") << "\nseed = " << g("seed") << "\n";
  std::ofstream(kDir / "o.csv") << "id,kind,x_m,y_m,heading_deg\ntree1,tree,700,1000," << g("ch") << "\n";
  return s.str();
}

// The bundled kinds with absolute model paths and `key = value` set in table [kind].
std::string kinds_with(const std::string& kind, const std::string& key, const std::string& value) {
  std::ifstream in(test::source("models/kinds.toml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text = std::regex_replace(text, std::regex(R"re("([A-Za-z0-9_]+\.obj)")re"), "\"" + test::source("models").string() + "/$1\"");
  const size_t head = text.find("[" + kind + "]\n");
  const size_t body = head + kind.size() + 3, next = text.find("\n[", body);
  const size_t line = text.find("\n" + key + " =", body - 1);
  if (line != std::string::npos && line < next) {
    text.replace(line + 1, text.find('\n', line + 1) - line - 1, key + " = " + value);
  } else {
    text.insert(body, key + " = " + value + "\n");
  }
  return text;
}

struct Verdict {
  int check = -1, run = -1;
  std::string text;
};
Verdict judge(const std::string& scenario_text) {
  std::ofstream(kDir / "s.toml") << scenario_text;
  const auto events = kDir / "e.jsonl";
  fs::remove(events);
  Verdict v;
  const auto c = test::npsnet_cli("check " + (kDir / "s.toml").string());
  const auto r = test::npsnet_cli("run --no-render --quiet --seconds 3 --scenario " + (kDir / "s.toml").string() + " --events " +
                                  events.string());
  v.check = c.rc, v.run = r.rc, v.text = c.text + r.text;
  if (r.rc != 0) { EXPECT_FALSE(fs::exists(events)) << "the run wrote its log before rejecting the input"; }
  return v;
}

void expect_consistent(const Verdict& v, const std::string& what) {
  EXPECT_TRUE(v.run == 0 || v.run == 2) << what << ": run exit " << v.run << "\n" << v.text;
  EXPECT_EQ(v.check == 0, v.run == 0) << what << ": check " << v.check << ", run " << v.run << "\n" << v.text;
  EXPECT_EQ(v.text.find("internal error"), std::string::npos) << what << "\n" << v.text;
  EXPECT_LT(v.text.size(), 4000u) << what;
}
}  // namespace

TEST(CheckVsRun, BaselineRuns) {
  write_terrain();
  const auto v = judge(scenario({}, ""));
  EXPECT_EQ(v.check, 0) << v.text;
  EXPECT_EQ(v.run, 0) << v.text;
}

TEST(CheckVsRun, ExtremeScenarioAndObjectNumbers) {
  write_terrain();
  const char* values[] = {"1e308", "-1e308", "1e30", "-1e30", "-1.0", "0.0", "1e-308", "1e6", "4e9"};
  int rejected = 0;
  for (const auto& [key, def] : kDefaults)
    for (const char* val : values) {
      if (key == "bgn" && std::string(val) == "1e6") continue;  // valid, but a million vehicles: slow
      const auto v = judge(scenario({{key, val}}, ""));
      expect_consistent(v, key + " = " + val);
      rejected += v.check == 2;
    }
  EXPECT_GT(rejected, 60);  // most of these are rejected, with a message
  const auto speed = judge(scenario({{"spd", "1e308"}, {"max", "1e308"}}, ""));
  EXPECT_EQ(speed.check, 2);
  EXPECT_NE(speed.text.find("speed_kmh: must be 0 to 50000 km/h (got 1e+308)"), std::string::npos) << speed.text;
}

TEST(CheckVsRun, ExtremeKindNumbers) {
  write_terrain();
  const std::pair<const char*, const char*> fields[] = {
      {"m1a1", "mass_kg"},         {"m1a1", "radius_m"},        {"m1a1", "max_speed_kmh"}, {"m1a1", "rounds"},
      {"m1a1", "fuel_l"},          {"m1a1", "resistance"},      {"m1a1", "sensor_range_m"}, {"he_round", "blast_radius_m"},
      {"he_round", "crater_radius_m"}, {"he_round", "crater_depth_m"}, {"he_round", "max_speed_kmh"}};
  for (const auto& [kind, key] : fields)
    for (const char* val : {"1e308", "-1e308", "1e30", "-1.0", "0.0"}) {
      std::ofstream(kDir / "k.toml") << kinds_with(kind, key, val);
      expect_consistent(judge(scenario({}, "k.toml")), std::string(kind) + "." + key + " = " + val);
    }
  std::ofstream(kDir / "k.toml") << kinds_with("m1a1", "dis_type", "[1, 1, 1e308, 1, 1, 1, 0]");
  const auto v = judge(scenario({}, "k.toml"));
  expect_consistent(v, "dis_type");
  EXPECT_NE(v.text.find("m1a1.dis_type: field 3 must be an integer 0 to 65535 (got 1e+308)"), std::string::npos) << v.text;
}
