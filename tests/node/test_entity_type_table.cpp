// models/entity_types.toml (issue 10, defect 6): what another simulator's entity type is here,
// in the order the file's header states.
#include <gtest/gtest.h>

#include "node/entity_type_table.hpp"
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
