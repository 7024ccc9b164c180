// Fixed objects have shapes in the continuous method (issue 13): a building is an oriented box, a
// tree its standing trunk (a vertical cylinder, kinds.toml trunk_radius_m); the thesis method
// keeps their bounding spheres.
#include <gtest/gtest.h>

#include "collision/collision.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

namespace {

// Moves the entities straight for up to `ticks` ticks, detecting; stops after the first contact
// when `stop` (the entities then stand where that tick ended).
std::vector<collision::Contact> drive(world::World& w, collision::Method method, int ticks, bool stop = false) {
  const double dt = 0.1;
  collision::Detector d(collision::Options{method, collision::Tier::Auto, dt});
  std::vector<collision::Contact> all;
  for (int k = 0; k < ticks && !(stop && !all.empty()); ++k) {
    for (size_t e = 0; e < w.ents.size(); ++e) w.ents.pos[e] += w.ents.vel[e] * dt;
    d.detect(w, all);
  }
  return all;
}

const world::Model& intact(const world::World& w, const char* kind) {
  return w.models[w.kinds[w.kinds.find(kind)].models[0]];
}

}  // namespace

TEST(FixedShapes, TankAlongABuildingsLongWallAtOneAndAHalfMetresDoesNotTouchIt) {
  for (auto method : {collision::Method::Continuous, collision::Method::Thesis}) {
    auto w = test::flat_world();
    test::add_fixed(w, "house", "building", 1000, 1000);
    const auto& b = intact(w, "building");
    const auto& t = intact(w, "m1a1");
    ASSERT_GT(b.bbox_max.x() - b.bbox_min.x(), b.bbox_max.y() - b.bbox_min.y());  // long walls run east-west
    // heading east, north of the building: the tank's right side (model +x) faces the north wall
    const double y = 1000 + b.bbox_max.y() + 1.5 + t.bbox_max.x();
    test::add_vehicle(w, "tank", "m1a1", 960, y, 90, 10);
    test::index_fixed(w);
    const auto c = drive(w, method, 80);
    if (method == collision::Method::Continuous) {
      EXPECT_TRUE(c.empty()) << "a building is its box: 1.5 m off the wall is no contact";
    } else {
      EXPECT_FALSE(c.empty()) << "the thesis's 9 m sphere reaches 1.5 m off the wall";
    }
  }
}

TEST(FixedShapes, TankDrivenIntoTheWallMeetsItAtTheWall) {
  auto w = test::flat_world();
  test::add_fixed(w, "house", "building", 1000, 1000);
  const double wall = 1000 + intact(w, "building").bbox_min.y();  // the south wall
  const double front = intact(w, "m1a1").bbox_max.y();
  const int e = test::add_vehicle(w, "tank", "m1a1", 1000, wall - front - 20, 0, 5);
  test::index_fixed(w);
  const auto c = drive(w, collision::Method::Continuous, 80, true);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].b_fixed);
  EXPECT_STREQ(c[0].method, "continuous-box-fixed");
  EXPECT_NEAR(c[0].point.y(), wall, 0.25) << c[0].method;
  // the tank's front at the time of impact is at the wall, not 2 m before it
  const double at = w.ents.pos[e].y() - w.ents.vel[e].y() * 0.1 * (1 - c[0].fraction) + front;
  EXPECT_NEAR(at, wall, 0.25);
}

TEST(FixedShapes, ATreeIsItsTrunk) {
  auto w = test::flat_world();
  test::add_fixed(w, "oak", "tree", 1000, 1000);
  const auto& tr = w.kinds[w.kinds.find("tree")];
  ASSERT_GT(tr.trunk_radius_by_state[0], 0.f);
  const double r = tr.trunk_radius_by_state[0];
  const auto& t = intact(w, "m1a1");
  // one tank passes 1 m from the trunk (under the crown), another drives into it
  const int pass = test::add_vehicle(w, "pass", "m1a1", 1000 + r + 1.0 - t.bbox_min.x(), 960, 0, 5);
  test::index_fixed(w);
  auto c = drive(w, collision::Method::Continuous, 160);
  EXPECT_TRUE(c.empty()) << "1 m from the trunk";
  w.ents.pos[pass] = Vec3(1000, 1000 - r - t.bbox_max.y() - 10, 100);
  c = drive(w, collision::Method::Continuous, 40);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].point.y(), 1000 - r, 0.25) << c[0].method;
}
