// models/entity_types.toml (issue 10, defect 6): what another simulator's entity type is here,
// in the order the file's header states.
#include <gtest/gtest.h>
#include <unistd.h>

#include "node/entity_type_table.hpp"
#include "support/fixture.hpp"
#include "world/scenario.hpp"

using namespace npsnet;

namespace {
struct EntityTypesBundled : ::testing::Test {
  world::ModelLibrary models;
  world::KindTable kinds = world::KindTable::load(world::default_kinds_file(), models);
  node::EntityTypeTable table = node::EntityTypeTable::load(node::EntityTypeTable::default_file());
  std::string kind_of(net::EntityType t) const {
    const auto c = table.resolve(t, kinds);
    return c.kind >= 0 ? kinds[c.kind].name : std::string("track:") + c.track;
  }
};
}  // namespace

TEST_F(EntityTypesBundled, NamesOnlyBundledVehicleKinds) { EXPECT_TRUE(table.check_kinds(kinds).empty()); }

TEST_F(EntityTypesBundled, EachEntityAsWhatItIs) {
  EXPECT_EQ(kind_of({1, 1, 225, 1, 1, 3, 0}), "m1a1") << "our own type";
  EXPECT_EQ(kind_of({1, 1, 222, 1, 2, 0, 0}), "generic_ground") << "an unknown tank";
  EXPECT_EQ(kind_of({1, 2, 222, 1, 2, 0, 0}), "generic_air");
  EXPECT_EQ(kind_of({1, 3, 222, 1, 2, 0, 0}), "generic_sea");
  EXPECT_EQ(kind_of({1, 4, 222, 1, 2, 0, 0}), "generic_sea") << "a submarine: not a ground vehicle";
  EXPECT_EQ(kind_of({3, 1, 225, 1, 0, 0, 0}), "track:lifeform") << "a soldier: not a ground vehicle";
  EXPECT_EQ(kind_of({5, 1, 0, 3, 1, 0, 0}), "track:cultural_feature");
  EXPECT_EQ(kind_of({1, 0, 0, 0, 0, 0, 0}), "generic_ground") << "[default]";
}

// Every problem of a broken table at once, as FILE:LINE: field: message (node/table_file.hpp).
TEST(EntityTypesFile, ProblemsAsFileLineFieldMessage) {
  auto problems = [](const std::string& tag, const std::string& text) {
    const auto f = test::write_file("entity-types-" + tag + "-" + std::to_string(::getpid()) + ".toml", text);
    std::vector<std::string> got;
    try {
      (void)node::EntityTypeTable::load(f);
    } catch (const world::InputError& e) {
      for (const auto& p : e.problems()) got.push_back(p.str().substr(f.string().size()));
    }
    return got;
  };
  EXPECT_EQ(problems("a", "colour = 1\n"
                          "[[entity]]\ndis_type = [1, 1]\nkind = \"generic_ground\"\ntrack = \"lifeform\"\n"
                          "[[entity]]\ndis_type = [3, 999]\ntrack = \"lifeform\"\nsize = 2\n"),
            (std::vector<std::string>{
                ":1: colour: unknown field",
                ":1: default: a [default] table with the kind of an entity no entry covers is required",
                ":2: entity[0].kind: give either kind (a vehicle kind) or track (what it is)",
                ":9: entity[1].size: unknown field",
                ":7: entity[1].dis_type: field 2 must be -1 (any) or an integer 0 to 255 (got 999)",
            }));
  EXPECT_EQ(problems("b", "entity = 3\n[default]\nkind = \"generic_ground\"\n"),
            (std::vector<std::string>{":1: entity: must be an array of tables [[entity]]"}));
  EXPECT_EQ(problems("c", "entity = [1]\n[default]\ntrack = \"lifeform\"\nwhat = 1\n"),
            (std::vector<std::string>{":4: default.what: unknown field", ":1: entity[0].: must be a table"}));
}
