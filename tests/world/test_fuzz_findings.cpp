// Inputs the fuzz targets (fuzz/, scripts/fuzz.sh) found, each pinned down with the answer it
// must get: a plain problem (FILE:LINE: field: message), never undefined behaviour or a crash.
// The raw inputs are also replayed by the ctest tests fuzz.replay.<target> (fuzz/regressions/).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/dirs.hpp"
#include "world/kinds.hpp"
#include "world/scenario.hpp"

using namespace npsnet;

namespace {

const std::string kModels = std::string(npsnet::dirs::source()) + "/models/fuzz-kinds.toml";

// Every problem `load` throws, as text (none: it loaded).
template <class F>
std::vector<std::string> problems(F load) {
  std::vector<std::string> out;
  try {
    load();
  } catch (const world::InputError& e) {
    for (const auto& p : e.problems()) out.push_back(p.str());
  }
  return out;
}

std::vector<std::string> kinds_problems(const std::string& text) {
  world::ModelLibrary models;
  return problems([&] { (void)world::KindTable::load_text(text, kModels, models); });
}

std::vector<std::string> scenario_problems(const std::string& text) {
  return problems([&] { (void)world::load_scenario_text(text, std::string(npsnet::dirs::source()) + "/scenarios/fuzz.toml"); });
}

const char* kTank = "[tank]\nmobility = \"ground\"\nmass_kg = 1000\nstates = [\"intact\"]\nmodels = [\"m1a1.obj\"]\n";

}  // namespace

// fuzz_kinds: `rounds = 1e300` was cast to int (undefined behaviour; UBSan stopped the run).
TEST(FuzzFindings, KindRoundsOutOfIntRangeIsAProblem) {
  const auto p = kinds_problems(std::string(kTank) + "dis_type = [1, 1, 225, 1, 1, 3, 0]\nrounds = 1e300\n");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], kModels + ":7: tank.rounds: must be 0 to 1e+06 (got 1e+300)");
  EXPECT_EQ(kinds_problems(std::string(kTank) + "dis_type = [1, 1, 225, 1, 1, 3, 0]\nrounds = 2.5\n").size(), 1u);
  EXPECT_TRUE(kinds_problems(std::string(kTank) + "dis_type = [1, 1, 225, 1, 1, 3, 0]\nrounds = 40\n").empty());
}

// fuzz_kinds: dis_type fields were cast to their octets whatever their value (300, -1, 1e300).
TEST(FuzzFindings, DisTypeFieldsMustFitTheirOctets) {
  const auto p = kinds_problems(std::string(kTank) + "dis_type = [300, -1, 70000, 0, 0, 0, 1e300]\n");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find(":6: tank.dis_type: field 1 must be an integer 0 to 255 (got 300)"), std::string::npos) << p[0];
  EXPECT_EQ(kinds_problems(std::string(kTank) + "dis_type = [1, 1, 65536, 1, 1, 3, 0]\n").size(), 1u);
  EXPECT_EQ(kinds_problems(std::string(kTank) + "dis_type = [1, 1, 225, 1, 1, 3, 0.5]\n").size(), 1u);
  EXPECT_TRUE(kinds_problems(std::string(kTank) + "dis_type = [255, 255, 65535, 255, 255, 255, 255]\n").empty());
}

// A vehicle's `node` and the background `seed` out of range were reported, then cast anyway.
TEST(FuzzFindings, NodeAndSeedOutOfRangeAreProblemsOnly) {
  const auto p = scenario_problems(
      "[world]\nterrain = \"../terrain/default.tif\"\n[[vehicle]]\nid = \"t1\"\nkind = \"m1a1\"\n"
      "position_m = [3000.0, 3000.0]\nnode = 1e300\n[background]\nvehicles = 1\nseed = -1e300\n");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NE(p[0].find(":7: vehicle[0].node: must be an integer 1-65535"), std::string::npos) << p[0];
  EXPECT_NE(p[1].find(":10: background.seed: must be 0 to 9.0072e+15 (got -1e+300)"), std::string::npos) << p[1];
}
