// Rotation during a tick (issue 13): a body turning fast must not tunnel through a thin object
// because its orientation is held fixed over the tick (collision/shapes.hpp: cast_turning).
#include <gtest/gtest.h>


#include "collision/collision.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

namespace {

collision::Shape shape_of(const world::World& w, const char* kind) {
  const auto& k = w.kinds[w.kinds.find(kind)];
  const auto& m = w.models[k.models[0]];
  return !k.trunk_radius_by_state.empty() && k.trunk_radius_by_state[0] > 0 ? collision::make_trunk(m, k.trunk_radius_by_state[0])
                                                                            : collision::make_shape(m);
}

// Whether the shapes of entity `e` at heading h and of `other` (an entity, or a fixed object when
// fixed) overlap, or come within `margin` (m), at the pair's tier (hull with a fixed object, mesh
// between vehicles).
bool overlap(const world::World& w, int e, double h, int other, bool fixed, double margin = 0) {
  collision::ShapeScratch s;
  const auto sa = shape_of(w, w.kinds[w.ents.kind[e]].name.c_str());
  const collision::Pose pa{world::pose_rotation(h, 0, 0), w.ents.pos[e]};
  const Vec3 still = Vec3::Zero();
  if (fixed) {
    const auto sb = shape_of(w, w.kinds[w.fixed.kind[other]].name.c_str());
    return collision::hull_overlap_swept(sa, pa, sb, {world::pose_rotation(w.fixed.heading_deg[other], 0, 0), w.fixed.pos[other]},
                                         still, margin);
  }
  const auto sb = shape_of(w, w.kinds[w.ents.kind[other]].name.c_str());
  return collision::mesh_overlap_swept(sa, pa, sb, {world::pose_rotation(w.ents.heading_deg[other], 0, 0), w.ents.pos[other]},
                                       still, s, margin);
}

// The contact of a turn from h0 to h1 is the first touch: no later than the first of 400 sampled
// headings where the shapes overlap, and there the shapes are within the search's tolerance.
void expect_first_touch(const world::World& w, const collision::Contact& c, double h0, double h1, int other, bool fixed) {
  int k = 0;
  while (k < 400 && !overlap(w, 0, h0 + (h1 - h0) * k / 400, other, fixed)) ++k;
  ASSERT_LT(k, 400);
  EXPECT_LE(c.fraction, k / 400.0);
  EXPECT_GT(c.fraction, 0.0);
  EXPECT_TRUE(overlap(w, 0, h0 + (h1 - h0) * c.fraction, other, fixed, 2 * collision::kTurnTolM)) << c.fraction;
}

// Entity e standing still turns from heading h0 to h1 in one tick of 0.1 s (its first tick at
// h0, then the turn): the contacts the detector reports in the turning tick.
// narrowed: the pairs of the turning tick whose bounding spheres met (a narrow phase ran).
std::vector<collision::Contact> turn(world::World& w, int e, double h0, double h1, int64_t* narrowed = nullptr) {
  collision::Detector d(collision::options_from("continuous", "auto", 0.1));
  std::vector<collision::Contact> first, out;
  w.ents.heading_deg[e] = static_cast<float>(h0);
  d.detect(w, first);
  EXPECT_TRUE(first.empty()) << "clear at the start of the turn";
  const int64_t before = d.stats().sweep_hits;
  w.ents.heading_deg[e] = static_cast<float>(h1);
  d.detect(w, out);
  if (narrowed) *narrowed = d.stats().sweep_hits - before;
  return out;
}

// A standing vehicle at (1000, 1000), still, and a thin object at `rel` from it.
world::World still(const char* kind, const char* object, const Vec2& rel, bool object_is_vehicle = false) {
  auto w = test::flat_world();
  const int e = test::add_vehicle(w, "mover", kind, 1000, 1000, 0, 0);
  w.ents.vel[e] = Vec3::Zero();
  if (object_is_vehicle) {
    const int o = test::add_vehicle(w, "parked", object, 1000 + rel.x(), 1000 + rel.y(), 0, 0);
    w.ents.vel[o] = Vec3::Zero();
  } else {
    test::add_fixed(w, "thin", object, 1000 + rel.x(), 1000 + rel.y());
  }
  test::index_fixed(w);
  return w;
}

}  // namespace

// An F-16 yawing at 100 deg/s (85 -> 95 deg in a tick of 0.1 s): its nose sweeps through a
// telephone pole (r 0.16 m) that it clears at both ends of the tick. Held at its end heading
// over the tick (the code before this test) it never touches the pole.
TEST(Turning, AJetYawingHardDoesNotTunnelThroughAPole) {
  auto w = still("f16", "telephone_pole", Vec2(7.5, 0.0));
  ASSERT_FALSE(overlap(w, 0, 85, 0, true));
  ASSERT_FALSE(overlap(w, 0, 95, 0, true));
  ASSERT_TRUE(overlap(w, 0, 90, 0, true)) << "the pole is in the nose's path";
  const auto c = turn(w, 0, 85, 95);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].b_fixed);
  EXPECT_STREQ(c[0].tier, "hull");
  EXPECT_GT(c[0].fraction, 0.0);
  EXPECT_LT(c[0].fraction, 1.0);
  expect_first_touch(w, c[0], 85, 95, 0, true);
}

// An M1A1 pivoting at 120 deg/s (80 -> 92 deg): its rear corner sweeps through a tree's trunk.
TEST(Turning, ATankTurningFastDoesNotTunnelThroughATreeTrunk) {
  auto w = still("m1a1", "tree", Vec2(-4.25, 1.75));
  ASSERT_FALSE(overlap(w, 0, 80, 0, true));
  ASSERT_FALSE(overlap(w, 0, 92, 0, true));
  const auto c = turn(w, 0, 80, 92);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].b_fixed);
  expect_first_touch(w, c[0], 80, 92, 0, true);
}

// Vehicle against vehicle (the mesh tier): the same pivot sweeps the tank's gun through a
// parked tank's gun, clear of it at both ends of the tick.
TEST(Turning, ATankTurningFastDoesNotTunnelThroughAParkedTank) {
  auto w = still("m1a1", "m1a1", Vec2(7.5, 1.5), true);
  ASSERT_FALSE(overlap(w, 0, 80, 1, false));
  ASSERT_FALSE(overlap(w, 0, 92, 1, false));
  const auto c = turn(w, 0, 80, 92);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_FALSE(c[0].b_fixed);
  EXPECT_STREQ(c[0].tier, "mesh");
  expect_first_touch(w, c[0], 80, 92, 1, false);
  // On the meshes' intersection there: within the guns' reach of the parked tank's muzzle.
  EXPECT_LT((c[0].point.head<2>() - Vec2(1007.5, 1001.5)).norm(), 8.0);
}

// No new false hits: the same turns with the object 0.3 m beyond the farthest reach of the
// turning model (the pole and the trunk stand inside its bounding sphere, so the narrow phase
// runs and must clear them).
TEST(Turning, AVehicleTurningNearButClearOfAnObjectDoesNotHitIt) {
  for (const char* kind : {"f16", "m1a1"}) {
    SCOPED_TRACE(kind);
    auto probe = test::flat_world();
    const auto shape = shape_of(probe, kind);
    for (const char* object : {"telephone_pole", "tree"}) {
      SCOPED_TRACE(object);
      const double r = probe.kinds[probe.kinds.find(object)].trunk_radius_by_state[0];
      // Beyond the reach of every vertex, on the side the turn sweeps.
      const double reach = shape.pivot_radius + r / std::cos(kPi / collision::kTrunkSides) + 0.3;
      const Vec2 dir = heading_to_dir(90 + 6);
      auto w = still(kind, object, dir * reach);
      int64_t narrowed = 0;
      EXPECT_TRUE(turn(w, 0, 85, 100, &narrowed).empty());
      EXPECT_EQ(narrowed, 1) << "the bounding spheres meet: the narrow phase cleared it";
      EXPECT_TRUE(turn(w, 0, 100, 85, &narrowed).empty());
      EXPECT_EQ(narrowed, 1);
    }
  }
}

// The entity pass keeps each entity's model centre turned into the local frame from tick to tick
// (Detector::Turn) and makes it again only when the orientation or the centre changes. Sphere
// tier, still vehicles, a parked hmmwv (centre 0.9 m up, r 2.32 m) at the origin of the frame:
//  * an M1A1 (centre 0.975 m ahead of its origin, r 4.77 m) 7.5 m north of it, facing north: its
//    sphere's centre 8.5 m from the hmmwv's, clear; the tick it faces south, 6.5 m: the contact;
//  * a second hmmwv 5 m east of it: clear; the tick it is wrecked (its wreck's centre 0.71 m to
//    its right, further off, and r 2.90 m), 5.7 m apart against 5.22: still clear. With the
//    intact centre kept, 5.0 m: a false contact.
TEST(Turning, TheCentreKeptFromTickToTickFollowsOrientationAndState) {
  for (const bool wreck : {false, true}) {
    SCOPED_TRACE(wreck ? "wrecked" : "turned");
    auto w = test::flat_world();
    const int b = test::add_vehicle(w, "parked", "hmmwv", 1000, 1000, 0, 0);
    const int a = wreck ? test::add_vehicle(w, "a", "hmmwv", 1005, 1000, 0, 0) : test::add_vehicle(w, "a", "m1a1", 1000, 1007.5, 0, 0);
    w.ents.vel[a] = w.ents.vel[b] = Vec3::Zero();
    test::index_fixed(w);
    const world::Kind& ka = w.kinds[w.ents.kind[a]];
    collision::Detector d(collision::options_from("continuous", "sphere", 0.1));
    std::vector<collision::Contact> out;
    for (int tick = 0; tick < 3; ++tick) {
      d.detect(w, out);
      EXPECT_TRUE(out.empty()) << tick;
    }
    if (wreck) {
      w.ents.state[a] = static_cast<uint8_t>(ka.centre_by_state.size() - 1);
      ASSERT_GT(ka.centre_by_state.back().x(), 0.5f) << "the wreck's centre lies to its right (kinds data)";
    } else {
      w.ents.heading_deg[a] = 180;
    }
    d.detect(w, out);
    EXPECT_EQ(out.size(), wreck ? 0u : 1u);
  }
}
