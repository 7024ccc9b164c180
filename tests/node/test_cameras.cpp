// The player's cameras (node/cameras.hpp) and the result frame's camera of a fixed object
// (node/result_camera.hpp): the driver camera rolls and pitches with the vehicle and does not
// draw the vehicle it sits in; a result frame sees the changed object, through the vehicle
// (drawn see-through) when the vehicle stands on it.
#include <gtest/gtest.h>

#ifdef NPSNET_HAVE_RENDER

#include <cmath>

#include "node/cameras.hpp"
#include "node/result_camera.hpp"
#include "render/view.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

namespace {
int state_named(const world::World& w, int object, const std::string& name) {
  const auto& st = w.kinds[w.fixed.kind[object]].states;
  for (size_t i = 0; i < st.size(); ++i)
    if (st[i] == name) return static_cast<int>(i);
  return -1;
}
}  // namespace

TEST(DriverCamera, RollsAndPitchesWithTheVehicleAndHidesIt) {
  world::World w = test::flat_world();
  const int e = test::add_vehicle(w, "t", "m1a1", 1000, 1000, 90.0, 0.0);
  w.ents.roll_deg[e] = 12.0f;  // right side down
  w.ents.pitch_deg[e] = 5.0f;  // nose up
  const render::Camera c = node::player_camera(w, w.ents, e, input::CameraMode::Driver);
  EXPECT_EQ(c.hide_entity, e);
  const render::ViewMath vm = render::make_view(c.eye, c.target, c.fov_y_deg, 960, 540, c.up);
  // heading east: the frame's right is south-ish, dipped by the roll; the view looks 5 deg up
  EXPECT_NEAR(rad2deg(std::asin(static_cast<double>(vm.forward.z()))), 5.0, 0.2);
  EXPECT_NEAR(rad2deg(std::asin(-static_cast<double>(vm.right.z()))), 12.0, 0.3);
  // level again: the frame is level too
  w.ents.roll_deg[e] = 0, w.ents.pitch_deg[e] = 0;
  const render::Camera l = node::player_camera(w, w.ents, e, input::CameraMode::Driver);
  const render::ViewMath lv = render::make_view(l.eye, l.target, l.fov_y_deg, 960, 540, l.up);
  EXPECT_NEAR(lv.right.z(), 0.0f, 1e-6f);
  // the other cameras draw the vehicle
  for (auto m : {input::CameraMode::Chase, input::CameraMode::Orbit, input::CameraMode::Map})
    EXPECT_EQ(node::player_camera(w, w.ents, e, m).hide_entity, -1);
}

TEST(ResultCamera, SeesTheStumpBesideTheTank) {
  world::World w = test::flat_world();
  const int tree = test::add_fixed(w, "tree", "tree", 1000, 1000);
  w.fixed.state[tree] = static_cast<uint8_t>(state_named(w, tree, "stump"));
  test::add_vehicle(w, "t", "m1a1", 985, 1000, 90.0, 8.0);  // 15 m short of it
  const render::Camera c = node::changed_object_camera(w, 0, tree);
  EXPECT_EQ(c.ghost_entity, -1);
  EXPECT_GE(node::object_visible_share(w, tree, c), 0.9);
}

TEST(ResultCamera, ATankStandingOnTheStumpIsDrawnSeeThrough) {
  world::World w = test::flat_world();
  const int tree = test::add_fixed(w, "tree", "tree", 1000, 1000);
  w.fixed.state[tree] = static_cast<uint8_t>(state_named(w, tree, "stump"));
  const int e = test::add_vehicle(w, "t", "m1a1", 1000, 1000, 90.0, 8.0);  // as tank4 of the default run at 1 s
  const render::Camera c = node::changed_object_camera(w, e, tree);
  EXPECT_EQ(c.ghost_entity, e);
  EXPECT_LT(node::object_visible_share(w, tree, c), 0.5);  // the tank's polygons hide most of it
  w.ents.active[e] = 0;                                     // seen through the tank, all of it
  EXPECT_GE(node::object_visible_share(w, tree, c), 0.9);
}

TEST(ResultCamera, ATallTowerIsSeenWholeFromTheSide) {
  world::World w = test::flat_world();
  const int tower = test::add_fixed(w, "tower", "watertower", 1000, 1000);
  w.fixed.state[tower] = 1;
  test::add_vehicle(w, "t", "m1a1", 1000 - w.kinds[w.fixed.kind[tower]].radius_m - 5, 1000, 90.0, 0.0);
  const render::Camera c = node::changed_object_camera(w, 0, tower);
  EXPECT_EQ(c.ghost_entity, -1);
  EXPECT_GE(node::object_visible_share(w, tower, c), 0.9);
  const Vec3 d = c.eye - c.target;
  EXPECT_LT(rad2deg(std::atan2(d.z(), d.head<2>().norm())), 60.0);  // not a view of its roof
}

#endif  // NPSNET_HAVE_RENDER
