// World invariants (World::valid, asserted in debug builds by apply and detect): a built world
// holds them, and each kind of break is caught.
#include <gtest/gtest.h>

#include "support/fixture.hpp"

using namespace npsnet;

namespace {
world::World small_world() {
  auto w = test::flat_world();
  test::add_vehicle(w, "a", "m1a1", 500, 500, 0, 5);
  test::add_fixed(w, "t", "tree", 700, 700);
  test::add_fixed(w, "b", "building", 1000, 1000);
  test::index_fixed(w);
  return w;
}
}  // namespace

TEST(WorldValid, ABuiltWorldHoldsItsInvariants) { EXPECT_TRUE(small_world().valid()); }

TEST(WorldValid, ArraysOfDifferentLengthsAreCaught) {
  auto w = small_world();
  w.ents.vel.pop_back();
  EXPECT_FALSE(w.valid());
  auto v = small_world();
  v.fixed.radius_m.push_back(1);
  EXPECT_FALSE(v.valid());
}

TEST(WorldValid, IndicesOutOfRangeAreCaught) {
  auto w = small_world();
  w.ents.owner[0] = 7;  // no entity 7
  EXPECT_FALSE(w.valid());
  auto v = small_world();
  v.fixed.state[1] = 9;  // a building has four states
  EXPECT_FALSE(v.valid());
}

TEST(WorldValid, AnObjectMissingFromTheGridIsCaught) {
  auto w = small_world();
  test::add_fixed(w, "late", "rock", 1500, 1500);  // added after the grid was built
  EXPECT_FALSE(w.valid());
  test::index_fixed(w);
  EXPECT_TRUE(w.valid());
}
