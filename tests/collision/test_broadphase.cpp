// The moving broad phase agrees with brute force on random scenes (crowded and spread, small and
// large boxes; the fixed-object grid's twin test is tests/world/test_fixed_grid.cpp), and the shape tiers nest (mesh contact => hull => box, and hull => sphere).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

#include "collision/collision.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

TEST(MovingGrid, AgreesWithBruteForceOnRandomScenes) {
  std::mt19937 rng(11);
  for (int scene = 0; scene < 20; ++scene) {
    const int n = 50 + scene * 60;
    const double span = scene % 2 ? 200.0 : 5000.0;
    std::uniform_real_distribution<double> pos(0, span), rad(0.5, 6), vel(-30, 30), u(0, 1);
    std::vector<collision::Box> boxes;
    for (int i = 0; i < n; ++i) {
      const Vec3 c0(pos(rng), pos(rng), pos(rng) * 0.01);
      Vec3 v(vel(rng), vel(rng), 0);
      if (u(rng) < 0.03) v *= 40;  // a few very fast bodies: "large" boxes
      boxes.push_back(collision::swept_box(c0, c0 + v, rad(rng)));
    }
    std::vector<std::pair<uint32_t, uint32_t>> a, b;
    collision::MovingGrid g;
    g.pairs(boxes, a);
    collision::brute_pairs(boxes, b);
    std::sort(a.begin(), a.end());
    EXPECT_EQ(a, b) << "scene " << scene;
  }
}

// The grid's mean extent sums extents in whole 1/256 m: in_256ths is llround(e * 256) for every
// float extent, halves (k + 1/2) / 256 and the ends of its exact range included.
// overlap_branchless (the kept broad phase's report) answers as overlap: boxes that touch at a
// face count, and a NaN corner meets nothing.
TEST(BoxOverlap, BranchlessAnswersAsTheEarlyExitTest) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> q(0, 8);  // corners on a coarse lattice: many exact touches
  auto box = [&] {
    collision::Box b;
    for (int k = 0; k < 3; ++k) {
      const int lo = q(rng), hi = lo + q(rng);
      b.lo[k] = static_cast<float>(lo), b.hi[k] = static_cast<float>(hi);
    }
    return b;
  };
  int yes = 0;
  for (int i = 0; i < 20000; ++i) {
    collision::Box a = box(), b = box();
    if (i % 97 == 0) a.lo[i % 3] = std::nanf("");
    const bool want = collision::overlap(a, b);
    yes += want;
    ASSERT_EQ(collision::overlap_branchless(a, b), want) << i;
  }
  EXPECT_GT(yes, 2000);
  EXPECT_LT(yes, 18000);
}

TEST(MovingGrid, ExtentsIn256thsRoundAsLlround) {
  std::mt19937 rng(12);
  std::uniform_int_distribution<uint32_t> bits(0, 0x7f7fffffu);  // every finite float >= 0
  auto check = [](float f) {
    const double e = f;
    ASSERT_EQ(collision::in_256ths(e), std::llround(e * 256)) << e;
  };
  for (int k = 0; k < 200000; ++k) {
    uint32_t b = bits(rng);
    float f;
    std::memcpy(&f, &b, sizeof f);
    if (f <= 1e9f) check(f);
  }
  for (int k = 0; k < 4096; ++k) check((k + 0.5f) / 256), check(k / 256.0f), check(std::nextafter((k + 0.5f) / 256, 0.0f));
  for (float f : {0.0f, 1e-45f, 0.49999997f / 256, 0.5f / 256, 0x1p20f, std::nextafter(0x1p20f, 0.0f),
                  std::nextafter(0x1p20f, 1e30f), 1e9f})
    check(f);
}

TEST(ShapeTiers, NestOnRealModelsAtRandomPoses) {
  auto w = test::flat_world();
  std::vector<collision::Shape> shapes;
  for (int i = 0; i < w.models.size(); ++i) shapes.push_back(collision::make_shape(w.models[i]));
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> pick(0, w.models.size() - 1);
  std::uniform_real_distribution<double> ang(0, 360), off(-1, 1);
  collision::ShapeScratch scratch;
  int mesh_hits = 0, hull_only = 0, box_only = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const auto& a = shapes[static_cast<size_t>(pick(rng))];
    const auto& b = shapes[static_cast<size_t>(pick(rng))];
    collision::Pose pa, pb;
    pa.rot = world::pose_rotation(ang(rng), ang(rng) / 8 - 22, ang(rng) / 8 - 22);
    pb.rot = world::pose_rotation(ang(rng), ang(rng) / 8 - 22, ang(rng) / 8 - 22);
    const double reach = a.bound_radius + b.bound_radius;
    pb.pos = Vec3(off(rng), off(rng), off(rng) * 0.3) * reach;
    const bool box = collision::box_overlap(a, pa, b, pb);
    const bool hull = collision::hull_overlap(a, pa, b, pb);
    Vec3 p;
    const bool mesh = collision::mesh_overlap(a, pa, b, pb, scratch, &p);
    const double dc = ((pb.rot * b.sphere_centre + pb.pos) - (pa.rot * a.sphere_centre + pa.pos)).norm();
    // The hull lies inside both the bounding sphere and the box (the box's corners may stick
    // out of the sphere, so the box is only a test between the sphere and the hull).
    if (hull) { EXPECT_LE(dc, reach * 1.0001); }
    if (hull) { EXPECT_TRUE(box) << trial; }
    if (mesh) {
      EXPECT_TRUE(hull) << trial;
      ++mesh_hits;
      // The point lies on both bodies' bounds.
      EXPECT_LE((p - (pa.rot * a.sphere_centre + pa.pos)).norm(), a.bound_radius * 1.001);
      EXPECT_LE((p - (pb.rot * b.sphere_centre + pb.pos)).norm(), b.bound_radius * 1.001);
    }
    hull_only += hull && !mesh;
    box_only += box && !hull;
  }
  EXPECT_GT(mesh_hits, 100);
  EXPECT_GT(box_only, 10) << "boxes are coarser than hulls";
  EXPECT_GT(hull_only, 10) << "hulls are coarser than meshes";
}

TEST(ShapeTiers, UnitCubesSeparateAtTheirFaces) {
  world::Model m;
  for (int i = 0; i < 8; ++i) m.vertices.emplace_back(i & 1 ? 1.f : -1.f, i & 2 ? 1.f : -1.f, i & 4 ? 1.f : -1.f);
  const uint32_t f[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (auto& q : f) {
    m.faces.push_back(world::Face{static_cast<uint32_t>(m.face_vertices.size()), 4});
    for (uint32_t k : q) m.face_vertices.push_back(k);
  }
  m.bbox_min = Vec3f(-1, -1, -1), m.bbox_max = Vec3f(1, 1, 1);
  const auto s = collision::make_shape(m);
  collision::ShapeScratch sc;
  collision::Pose a, b;
  for (double x : {1.9, 1.999, 2.001, 2.1}) {
    b.pos = Vec3(x, 0.3, 0.2);
    const bool want = x < 2;
    EXPECT_EQ(collision::box_overlap(s, a, s, b), want) << x;
    EXPECT_EQ(collision::hull_overlap(s, a, s, b), want) << x;
    EXPECT_EQ(collision::mesh_overlap(s, a, s, b, sc), want) << x;
  }
  // Rotated 45 degrees about z: the edge reaches sqrt(2).
  b.rot = Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()).toRotationMatrix();
  for (double x : {2.35, 2.45}) {
    b.pos = Vec3(x, 0, 0);
    const bool want = x < 1 + std::sqrt(2.0);
    EXPECT_EQ(collision::box_overlap(s, a, s, b), want) << x;
    EXPECT_EQ(collision::hull_overlap(s, a, s, b), want) << x;
    EXPECT_EQ(collision::mesh_overlap(s, a, s, b, sc), want) << x;
  }
}

TEST(ShapeTiers, SweptTestsCatchAThinPlateThatPassesBetweenTwoSamples) {
  // Two plates 2 m x 2 m x 2 cm; b moves 10 m through a within one interval: apart at both ends.
  world::Model m;
  for (int i = 0; i < 8; ++i) m.vertices.emplace_back(i & 1 ? 1.f : -1.f, i & 2 ? 1.f : -1.f, i & 4 ? 0.01f : -0.01f);
  const uint32_t f[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (auto& q : f) {
    m.faces.push_back(world::Face{static_cast<uint32_t>(m.face_vertices.size()), 4});
    for (uint32_t k : q) m.face_vertices.push_back(k);
  }
  m.bbox_min = Vec3f(-1, -1, -0.01f), m.bbox_max = Vec3f(1, 1, 0.01f);
  const auto s = collision::make_shape(m);
  collision::ShapeScratch sc;
  collision::Pose a, b;
  b.rot = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix();  // b stands on edge
  b.pos = Vec3(-5, 0, 0);
  const Vec3 through(10, 0, 0), over(10, 0, 5);  // over: b is 1 m above a while above it
  collision::Pose end = b;
  end.pos += through;
  EXPECT_FALSE(collision::mesh_overlap(s, a, s, b, sc));
  EXPECT_FALSE(collision::mesh_overlap(s, a, s, end, sc));
  EXPECT_TRUE(collision::box_overlap_swept(s, a, s, b, through));
  EXPECT_TRUE(collision::hull_overlap_swept(s, a, s, b, through));
  EXPECT_TRUE(collision::mesh_overlap_swept(s, a, s, b, through, sc));
  EXPECT_FALSE(collision::box_overlap_swept(s, a, s, b, over));
  EXPECT_FALSE(collision::hull_overlap_swept(s, a, s, b, over));
  EXPECT_FALSE(collision::mesh_overlap_swept(s, a, s, b, over, sc));
}

TEST(ShapeTiers, SweptMeshAgreesWithDenseSamplingOnRealModels) {
  auto w = test::flat_world();
  std::vector<collision::Shape> shapes;
  for (int i = 0; i < w.models.size(); ++i) shapes.push_back(collision::make_shape(w.models[i]));
  std::mt19937 rng(23);
  std::uniform_int_distribution<int> pick(0, w.models.size() - 1);
  std::uniform_real_distribution<double> ang(0, 360), off(-1, 1);
  collision::ShapeScratch sc;
  int hits = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto& a = shapes[static_cast<size_t>(pick(rng))];
    const auto& b = shapes[static_cast<size_t>(pick(rng))];
    collision::Pose pa, pb;
    pa.rot = world::pose_rotation(ang(rng), 0, 0);
    pb.rot = world::pose_rotation(ang(rng), 0, 0);
    const double reach = a.bound_radius + b.bound_radius;
    pb.pos = Vec3(off(rng), off(rng), off(rng) * 0.3) * reach * 1.5;
    const Vec3 d = Vec3(off(rng), off(rng), off(rng) * 0.2) * reach;
    const bool swept = collision::mesh_overlap_swept(a, pa, b, pb, d, sc);
    bool sampled = false;
    for (int k = 0; k <= 400 && !sampled; ++k) {
      collision::Pose q = pb;
      q.pos += d * (k / 400.0);
      sampled = collision::mesh_overlap(a, pa, b, q, sc);
    }
    if (sampled) { EXPECT_TRUE(swept) << "trial " << trial; }  // sampling can only miss, never invent
    hits += swept;
  }
  EXPECT_GT(hits, 30);
}
