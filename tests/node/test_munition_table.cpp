// models/munitions.toml and the munition enumerations (issue 10, defect 3): what another
// simulator's round does here, in the order the file's header states, and bad tables reported
// as FILE:LINE: field: message.
#include <gtest/gtest.h>
#include <unistd.h>

#include "node/munition_codes.hpp"
#include "node/munition_table.hpp"
#include "support/fixture.hpp"
#include "world/scenario.hpp"

using namespace npsnet;
using node::MunitionTable;

namespace {

struct MunitionTableBundled : ::testing::Test {
  world::ModelLibrary models;
  world::KindTable kinds = world::KindTable::load(world::default_kinds_file(), models);
  MunitionTable table = MunitionTable::load(MunitionTable::default_file());
  node::MunitionEffect of(net::EntityType t, std::uint16_t warhead) const {
    return table.effect({t, warhead, 1000, 1, 0}, kinds);
  }
};

const net::EntityType kHe{2, 8, 225, 2, 14, 1, 0}, kMissile{2, 2, 225, 1, 1, 0, 0};

}  // namespace

TEST_F(MunitionTableBundled, BundledTableNamesOnlyBundledMunitionKinds) { EXPECT_TRUE(table.check_kinds(kinds).empty()); }

TEST_F(MunitionTableBundled, OurOwnRoundsAreTheirKinds) {
  const auto he = of(kHe, 1000);
  EXPECT_STREQ(he.name, "he_round");
  EXPECT_TRUE(he.crater && he.blast && he.hit_destroys);
  EXPECT_STREQ(he.warhead, "high_explosive");
  EXPECT_STREQ(of(kMissile, 1000).name, "missile");
}

TEST_F(MunitionTableBundled, NonExplosivePayloadsWinOverTheType) {
  for (std::uint16_t w : {2000, 2100, 3000, 4000, 5000, 5999}) {
    const auto fx = of(kHe, w);  // an HE shell's type carrying smoke, a flare, an inert or a kinetic round
    SCOPED_TRACE(w);
    EXPECT_FALSE(fx.crater || fx.blast || fx.hit_destroys);
    EXPECT_GE(fx.kind, 0) << "a kind for the record, its effects off";
  }
  EXPECT_STREQ(of(kHe, 2000).name, "smoke");
  EXPECT_STREQ(of(kHe, 3000).name, "illumination");
  EXPECT_STREQ(of(kHe, 4000).name, "practice");
  EXPECT_STREQ(of(kHe, 5000).name, "kinetic");
}

TEST_F(MunitionTableBundled, UnknownTypesByWildcardThenWarheadThenDefault) {
  EXPECT_STREQ(of({2, 1, 222, 1, 7, 3, 0}, 1000).name, "missile") << "guided, any domain or country";
  EXPECT_STREQ(of({2, 9, 222, 2, 5, 0, 0}, 0).name, "he_round") << "ballistic";
  EXPECT_STREQ(of({2, 9, 222, 3, 5, 0, 0}, 1300).name, "he_round") << "fixed munition: HE fragmentation class";
  const auto other = of({2, 9, 222, 3, 5, 0, 0}, 6000);  // mines: no class, the default
  EXPECT_STREQ(other.name, "he_round");
  EXPECT_STREQ(other.warhead, "other");
}

TEST(MunitionCodes, ResultsSayWhatTheyAllow) {
  EXPECT_STREQ(node::detonation_result(3).name, "ground_impact");
  EXPECT_TRUE(node::detonation_result(3).crater);
  EXPECT_STREQ(node::detonation_result(6).name, "dud");
  EXPECT_FALSE(node::detonation_result(6).crater || node::detonation_result(6).blast);
  EXPECT_STREQ(node::detonation_result(25).name, "airburst");
  EXPECT_FALSE(node::detonation_result(25).crater);
  EXPECT_TRUE(node::detonation_result(25).blast);
  EXPECT_FALSE(node::detonation_result(1).crater) << "entity impact";
  EXPECT_STREQ(node::detonation_result(200).name, "other");
  EXPECT_STREQ(node::fuse_class(3000), "proximity");
  EXPECT_STREQ(node::fuse_class(65535), "other");
  EXPECT_TRUE(node::air_fuse(2100));
  EXPECT_FALSE(node::air_fuse(1000));
}

TEST(MunitionTableFile, ProblemsAsFileLineFieldMessage) {
  const auto f = test::write_file("munitions-bad-" + std::to_string(::getpid()) + ".toml",
                                  "[default]\nkind = \"he_round\"\n"
                                  "[[munition]]\ndis_type = [2, 300]\nkind = \"missile\"\n"
                                  "[[warhead]]\nname = \"a\"\ncodes = [10, 20]\n"
                                  "[[warhead]]\nname = \"b\"\ncodes = [15, 30]\nbang = true\n"
                                  "[[munition]]\ndis_type = [2]\nkind = \"cannonball\"\n");
  std::vector<std::string> got;
  try {
    (void)MunitionTable::load(f);
  } catch (const world::InputError& e) {
    for (const auto& p : e.problems()) got.push_back(p.str());
  }
  const std::string n = f.string();
  EXPECT_EQ(got, (std::vector<std::string>{
                     n + ":4: munition[0].dis_type: field 2 must be -1 (any) or an integer 0 to 255 (got 300)",
                     n + ":12: warhead[1].bang: unknown field",
                     n + ":11: warhead[1].codes: overlaps warhead class 'a'",
                 }));
  // Structure fine, a kind the kinds file lacks: reported by check_kinds, with its line.
  const auto g = test::write_file("munitions-kind-" + std::to_string(::getpid()) + ".toml",
                                  "[default]\nkind = \"he_round\"\n[[munition]]\ndis_type = [2]\nkind = \"cannonball\"\n");
  world::ModelLibrary models;
  const auto kinds = world::KindTable::load(world::default_kinds_file(), models);
  const auto ps = MunitionTable::load(g).check_kinds(kinds);
  ASSERT_EQ(ps.size(), 1u);
  EXPECT_EQ(ps[0].str().rfind(g.string() + ":5: munition[0].kind: no munition kind 'cannonball' in ", 0), 0u) << ps[0].str();
  std::filesystem::remove(f);
  std::filesystem::remove(g);
}
