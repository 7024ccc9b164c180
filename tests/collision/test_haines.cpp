// Haines' crossings test (Figure 6) and the ray/polygon search of L3.
#include <gtest/gtest.h>

#include <vector>

#include "collision/collision.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

namespace {
bool inside(std::vector<std::pair<float, float>> poly, float px, float py) {
  std::vector<float> u, v;
  for (auto [x, y] : poly) u.push_back(x - px), v.push_back(y - py);
  return collision::haines_inside(u.data(), v.data(), static_cast<int>(u.size()));
}
}  // namespace

TEST(Haines, ConvexSquare) {
  const std::vector<std::pair<float, float>> sq = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_TRUE(inside(sq, 1, 1));
  EXPECT_TRUE(inside(sq, 0.01f, 1.99f));
  EXPECT_FALSE(inside(sq, 3, 1));
  EXPECT_FALSE(inside(sq, -1, 1));
  EXPECT_FALSE(inside(sq, 1, 3));
  EXPECT_FALSE(inside(sq, 1, -0.5f));
}

TEST(Haines, ConcaveLShape) {
  // An L: the notch at (1.5, 1.5) is outside, the arms inside.
  const std::vector<std::pair<float, float>> l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_TRUE(inside(l, 0.5f, 0.5f));
  EXPECT_TRUE(inside(l, 1.5f, 0.5f));
  EXPECT_TRUE(inside(l, 0.5f, 1.5f));
  EXPECT_FALSE(inside(l, 1.5f, 1.5f));
  // A ray from the notch along +U crosses no edge; from the left arm it crosses two edges of
  // the notch before leaving: parity decides.
  EXPECT_FALSE(inside(l, -0.5f, 1.5f));
}

TEST(Haines, PointsOnEdgesAndVerticesAreConsistent) {
  // Two squares sharing the edge x = 1: a point on the shared edge belongs to exactly one.
  const std::vector<std::pair<float, float>> left = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<std::pair<float, float>> right = {{1, 0}, {2, 0}, {2, 1}, {1, 1}};
  for (float y : {0.25f, 0.5f, 0.75f}) EXPECT_NE(inside(left, 1, y), inside(right, 1, y)) << y;
  // Horizontal shared edge y = 1 (V' = 0 counted positive): exactly one of the two.
  const std::vector<std::pair<float, float>> top = {{0, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (float x : {0.25f, 0.5f}) EXPECT_NE(inside(left, x, 1), inside(top, x, 1)) << x;
  // The shared vertex (1, 1) of four squares lies in exactly one of them.
  const std::vector<std::pair<float, float>> tr = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  const int n = inside(left, 1, 1) + inside(right, 1, 1) + inside(top, 1, 1) + inside(tr, 1, 1);
  EXPECT_EQ(n, 1);
}

TEST(Haines, DegenerateIsOutside) {
  EXPECT_FALSE(inside({{0, 0}, {1, 1}}, 0.5f, 0.5f));
  EXPECT_FALSE(inside({{0, 0}, {1, 1}, {2, 2}}, 1, 1));  // collinear: zero area
}

TEST(RayModel, FindsTheFirstPolygonCrossed) {
  auto w = test::flat_world();
  const world::Model& m = w.models[w.kinds[w.kinds.find("building")].models[0]];
  // From far west at mid-height toward +x: hits the west wall first.
  const double zmid = 0.5 * (m.bbox_min.z() + m.bbox_max.z());
  const auto h = collision::ray_model(m, Vec3(-100, 0, zmid), Vec3(1, 0, 0), 0, 1000);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.point.x(), m.bbox_min.x(), 0.3);  // the wall, under the roof overhang
  EXPECT_LT(h.normal.x(), 0);
  // A ray that passes above the model misses every polygon.
  const auto miss = collision::ray_model(m, Vec3(-100, 0, m.bbox_max.z() + 5), Vec3(1, 0, 0), 0, 1000);
  EXPECT_FALSE(miss.hit);
}
