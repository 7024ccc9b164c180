// The one fixed-object grid (world/fixed_grid.hpp) agrees with its brute-force twin on random
// scenes: the thesis's per-gridsquare lists, blast/crater neighbourhoods and box queries (each
// object once), on a map that is not a whole number of gridsquares, with objects on borders and
// reaches from a bush to past a gridsquare.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "support/fixture.hpp"
#include "world/fixed_grid.hpp"

using namespace npsnet;

namespace {
constexpr double kW = 2030, kD = 1410, kCell = thesis::kGridsquareM;

template <class G, class... A>
std::vector<int> near(const G& g, A... a) {
  std::vector<int> out;
  g.for_each_near(a..., [&](int o) { out.push_back(o); });
  return out;
}
template <class G>
std::vector<int> boxed(const G& g, float lx, float ly, float hx, float hy) {
  std::vector<int> out;
  g.query(lx, ly, hx, hy, [&](int o, float) { out.push_back(o); });
  return out;
}
std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}
}  // namespace

TEST(FixedGrid, AgreesWithBruteForceOnRandomScenes) {
  std::mt19937 rng(7);
  for (int scene = 0; scene < 12; ++scene) {
    std::uniform_real_distribution<double> x(-5, kW + 5), y(-5, kD + 5), u(0, 1), reach(0.3, 12);
    std::vector<Vec3> pos;
    std::vector<float> r;
    const int n = 200 + 400 * scene;
    for (int i = 0; i < n; ++i) {
      Vec3 p(x(rng), y(rng), 0);
      if (u(rng) < 0.1) p.x() = kCell * std::floor(p.x() / kCell);  // exactly on a gridsquare border
      pos.push_back(p);
      r.push_back(static_cast<float>(u(rng) < 0.05 ? 150 * u(rng) : reach(rng)));
    }
    world::FixedGrid g;
    world::FixedBrute b;
    g.build(pos, r, kW, kD, kCell);
    b.build(pos, r, kW, kD, kCell);
    ASSERT_TRUE(g.valid(pos, r));
    ASSERT_EQ(g.size(), b.size());
    for (int c = 0; c < g.cols() * g.rows(); ++c) {
      std::vector<int> gl, bl;
      g.for_each_home(c, [&](int o) { gl.push_back(o); });
      b.for_each_home(c, [&](int o) { bl.push_back(o); });
      ASSERT_EQ(gl, bl) << "scene " << scene << " gridsquare " << c;  // same order: ascending
    }
    for (int q = 0; q < 300; ++q) {
      const double qx = x(rng), qy = y(rng), qr = u(rng) < 0.5 ? 40 * u(rng) : 400 * u(rng);
      const auto gn = near(g, qx, qy, qr);
      EXPECT_EQ(sorted(gn), sorted(near(b, qx, qy, qr))) << "scene " << scene << " near " << q;
      // gridsquare by gridsquare, row by row: the order blasts and craters are decided in
      for (size_t k = 1; k < gn.size(); ++k) {
        const int c0 = g.cell_of(pos[gn[k - 1]].x(), pos[gn[k - 1]].y()), c1 = g.cell_of(pos[gn[k]].x(), pos[gn[k]].y());
        EXPECT_TRUE(c0 < c1 || (c0 == c1 && gn[k - 1] < gn[k]));
      }
      const float lx = static_cast<float>(qx), ly = static_cast<float>(qy);
      const float hx = lx + static_cast<float>(u(rng) < 0.8 ? 20 * u(rng) : 600 * u(rng)), hy = ly + static_cast<float>(30 * u(rng));
      const auto gb = boxed(g, lx, ly, hx, hy);
      const auto s = sorted(gb);
      EXPECT_EQ(std::adjacent_find(s.begin(), s.end()), s.end()) << "an object reported twice";
      EXPECT_EQ(s, sorted(boxed(b, lx, ly, hx, hy))) << "scene " << scene << " box " << q;
      // The listings of a larger box, kept, answer the box inside it (collision's objects near a
      // vehicle): those that overlap it are the box's query, each once.
      const float m = static_cast<float>(u(rng) < 0.5 ? 10 * u(rng) : 200 * u(rng));
      std::vector<int> kept;
      g.query_listed(lx - m, ly - m, hx + m, hy + m, [&](uint32_t k, const world::GridItem& it) {
        EXPECT_EQ(&g.listing(k), &it);
        if (world::FixedGrid::overlaps(g.listing(k), lx, ly, hx, hy)) kept.push_back(static_cast<int>(it.id));
      });
      EXPECT_EQ(sorted(kept), s) << "scene " << scene << " box " << q << " margin " << m;
    }
  }
}

TEST(FixedGrid, EveryBuildHasItsOwnGeneration) {
  const std::vector<Vec3> pos = {Vec3(10, 10, 0), Vec3(300, 200, 0)};
  const std::vector<float> r = {2, 5};
  world::FixedGrid a, b;
  a.build(pos, r, kW, kD, kCell);
  b.build(pos, r, kW, kD, kCell);
  const world::FixedGrid copy = a;
  EXPECT_NE(a.generation(), 0u);
  EXPECT_NE(a.generation(), b.generation());
  EXPECT_EQ(copy.generation(), a.generation());  // the same listings
  const uint64_t first = a.generation();
  a.build(pos, r, kW, kD, kCell);
  EXPECT_NE(a.generation(), first);
}

TEST(FixedGrid, AGridNeverBuiltListsNothing) {
  const world::FixedGrid g;
  int calls = 0;
  g.query(-10, -10, 1e4f, 1e4f, [&](int, float) { ++calls; });
  g.query_listed(0, 0, 500, 500, [&](uint32_t, const world::GridItem&) { ++calls; });
  g.for_each_near(100, 100, 1000, [&](int) { ++calls; });
  g.for_each_home(0, [&](int) { ++calls; });
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(g.size(), 0u);
}

TEST(FixedGrid, AWorldIndexesEveryObjectByItsReach) {
  auto w = test::flat_world();
  const int t = test::add_fixed(w, "t", "tree", 124.0, 300.0);  // 1 m west of a gridsquare border
  const int h = test::add_fixed(w, "h", "building", 600, 600);
  test::index_fixed(w);
  EXPECT_TRUE(w.valid());
  EXPECT_GE(w.fixed.reach_m[h], w.fixed.radius_m[h]);
  // the tree's reach crosses the border: a box east of it finds it, the thesis's list of the
  // eastern gridsquare does not hold it (its home is the western one)
  EXPECT_EQ(boxed(w.grid, 125.2f, 299.0f, 126.0f, 301.0f), std::vector<int>{t});
  std::vector<int> east;
  w.grid.for_each_home(w.grid.cell_of(125.5, 300.0), [&](int o) { east.push_back(o); });
  EXPECT_TRUE(east.empty());
}
