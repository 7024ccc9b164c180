// The persistent broad phase (pair_cache.hpp): tick after tick of moving bodies, some appearing,
// some gone, some turning large or not finite, its pairs are brute force's (the set MovingGrid
// gives), and the same in the same order on one and on several threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "collision/pair_cache.hpp"

using namespace npsnet;
using collision::Box;
using Pairs = std::vector<std::pair<uint32_t, uint32_t>>;
using Travel = collision::PairCache::Travel;

namespace {

// A world of `ids` bodies drifting, each active or not this tick; boxes of the active ones in id order.
struct Drift {
  std::mt19937 rng;
  std::vector<Vec3> pos, vel;
  std::vector<float> r;
  std::vector<uint8_t> active;
  float side;
  Drift(int ids, float side_m, unsigned seed) : rng(seed), side(side_m) {
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < ids; ++i) {
      pos.emplace_back(u(rng) * side, u(rng) * side, u(rng) * 4);
      vel.emplace_back((u(rng) - 0.5) * 6, (u(rng) - 0.5) * 6, 0);  // up to 3 m a tick
      r.push_back(1 + 5 * u(rng));
      active.push_back(u(rng) < 0.9);
    }
  }
  // One tick: bodies move (a few turn, a few switch on or off, now and then one flies fast).
  // travel: each listed body's x-y travel this tick (PairCache's margins), when asked.
  void step(std::vector<Box>& boxes, std::vector<uint32_t>& ids, std::vector<Travel>* travel = nullptr) {
    std::uniform_real_distribution<float> u(0, 1);
    boxes.clear(), ids.clear();
    if (travel) travel->clear();
    for (size_t i = 0; i < pos.size(); ++i) {
      if (u(rng) < 0.02) active[i] = !active[i];
      if (u(rng) < 0.05) vel[i] = Vec3((u(rng) - 0.5) * 6, (u(rng) - 0.5) * 6, 0);
      const Vec3 v = u(rng) < 0.01 ? Vec3(vel[i] * 60) : vel[i];  // a round's sweep: large
      const Vec3 c0 = pos[i];
      pos[i] += v;
      if (!active[i]) continue;
      ids.push_back(static_cast<uint32_t>(i));
      boxes.push_back(collision::swept_box(c0, pos[i], r[i]));
      if (travel) travel->push_back({static_cast<float>(v.x()), static_cast<float>(v.y())});
    }
  }
};

Pairs sorted(Pairs p) {
  std::sort(p.begin(), p.end());
  return p;
}

}  // namespace

TEST(PairCache, AgreesWithBruteForceTickAfterTick) {
  for (bool with_travel : {false, true})  // margins by extent alone, or by each body's travel too
    for (int scene = 0; scene < 6; ++scene) {
      const int n = 200 + scene * 300;
      const float side = scene % 2 ? 150.0f : 20.0f * std::sqrt(static_cast<float>(n)) * 4;  // crowded, spread
      Drift d(n, side, 100 + scene);
      collision::PairCache cache;
      std::vector<Box> boxes;
      std::vector<uint32_t> ids;
      std::vector<Travel> travel;
      Pairs got, want;
      size_t found = 0, moved = 0;
      for (int tick = 0; tick < 60; ++tick) {
        d.step(boxes, ids, with_travel ? &travel : nullptr);
        cache.pairs(boxes, ids, d.pos.size(), got, nullptr, with_travel ? &travel : nullptr);
        collision::brute_pairs(boxes, want);
        ASSERT_EQ(sorted(got), want) << "scene " << scene << ", tick " << tick << (with_travel ? ", travel" : "");
        found += want.size(), moved += cache.moved();
      }
      EXPECT_GT(found, 0u) << "scene " << scene << ": pairs to find";
      // (about a quarter move a tick here; with no margin, fat box = box, about two thirds)
      EXPECT_LT(moved, static_cast<size_t>(60 * n) * 2 / 5) << "most bodies keep their fat box from tick to tick";
    }
}

TEST(PairCache, SamePairsInTheSameOrderOnOneAndSeveralThreads) {
  for (int threads : {2, 3}) {
    Drift a(3000, 800, 7), b(3000, 800, 7);
    collision::PairCache one, many;
    core::Jobs jobs(threads);
    jobs.set_max_grain(1);  // every stage split as finely as the pool allows
    std::vector<Box> boxes_a, boxes_b;
    std::vector<uint32_t> ids_a, ids_b;
    std::vector<Travel> travel_a, travel_b;  // margins by travel half the ticks
    Pairs pa, pb;
    for (int tick = 0; tick < 30; ++tick) {
      a.step(boxes_a, ids_a, &travel_a), b.step(boxes_b, ids_b, &travel_b);
      one.pairs(boxes_a, ids_a, a.pos.size(), pa, nullptr, tick % 10 < 5 ? &travel_a : nullptr);
      many.pairs(boxes_b, ids_b, b.pos.size(), pb, &jobs, tick % 10 < 5 ? &travel_b : nullptr);
      ASSERT_EQ(pa, pb) << threads << " threads, tick " << tick;
    }
  }
}

// Bodies not finite, far beyond any cell, or suddenly all large (the cell is built again) still
// give brute force's pairs, and never a pair with a body that is not finite.
TEST(PairCache, OddBoxesAndACellThatNoLongerFits) {
  collision::PairCache cache;
  std::vector<Box> boxes;
  std::vector<uint32_t> ids;
  Pairs got, want;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int tick = 0; tick < 8; ++tick) {
    boxes.clear(), ids.clear();
    const float grow = tick < 4 ? 1.0f : 200.0f;  // from tick 4 every body is 200x as large
    for (uint32_t i = 0; i < 400; ++i) {
      const float x = static_cast<float>(i % 20) * 9 + tick, y = static_cast<float>(i / 20) * 9, h = 3 * grow;
      boxes.push_back(Box{{x - h, y - h, 0}, {x + h, y + h, 2}});
      ids.push_back(i * 2);  // ids with gaps
    }
    boxes[7] = Box{{nan, 0, 0}, {1, 1, 1}};
    boxes[8] = Box{{1e12f, 1e12f, 0}, {1e12f + 5, 1e12f + 5, 1}};
    // Margins by travel on odd ticks: none, some, a NaN's and an infinite one among them.
    std::vector<Travel> travel(boxes.size());
    for (size_t i = 0; i < travel.size(); ++i) travel[i] = {static_cast<float>(i % 4) - 1.5f, static_cast<float>(i % 3)};
    travel[7] = {nan, 0}, travel[9] = {std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
    travel[11] = {0, nan};
    cache.pairs(boxes, ids, 800, got, nullptr, tick % 2 ? &travel : nullptr);
    collision::brute_pairs(boxes, want);
    ASSERT_EQ(sorted(got), want) << "tick " << tick;
    for (const auto& [i, j] : got) EXPECT_TRUE(i != 7 && j != 7);
  }
  EXPECT_GE(cache.builds(), 2u) << "the cell was built again for the bodies grown 200x";
}

// A crowd rocking within its fat boxes: on the ticks no body moves or goes, the kept pairs stand
// as they are (pair_cache.cpp, step 4); one body leaping away, one gone and back, and the ids
// listed in another order (slots change, ids keep their pairs) still give brute force's pairs.
TEST(PairCache, ACrowdRockingInPlaceKeepsItsPairsTickAfterTick) {
  for (int threads : {1, 2}) {
    collision::PairCache cache;
    core::Jobs jobs(threads);
    jobs.set_max_grain(1);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<Vec3> pos;
    for (int i = 0; i < 400; ++i) pos.emplace_back(u(rng) * 120, u(rng) * 120, 0);
    // Body 8 stands where 7 does, and takes 7's slot while 7 is gone: pairs of 7 kept past its
    // going would come out as 8's, twice.
    pos[8] = pos[7];
    std::vector<Box> boxes;
    std::vector<uint32_t> ids;
    Pairs got, want;
    int still = 0;
    for (int tick = 0; tick < 30; ++tick) {
      if (tick == 10) pos[5] += Vec3(60, 0, 0);  // leaps out of its fat box
      const Vec3 rock(tick % 2 ? 0.3 : -0.3, 0, 0);  // within every fat box (its margin: over 2 m)
      boxes.clear(), ids.clear();
      for (uint32_t i = 0; i < pos.size(); ++i) {
        if (i == 7 && tick >= 15 && tick < 20) continue;  // gone for five ticks
        ids.push_back(i);
        boxes.push_back(collision::swept_box(pos[i], pos[i] + rock, 2.0));
      }
      if (tick >= 25) std::reverse(ids.begin(), ids.end()), std::reverse(boxes.begin(), boxes.end());
      cache.pairs(boxes, ids, pos.size(), got, threads > 1 ? &jobs : nullptr);
      collision::brute_pairs(boxes, want);
      ASSERT_EQ(sorted(got), want) << threads << " thread(s), tick " << tick;
      still += cache.moved() == 0;
    }
    EXPECT_GE(still, 20) << "most ticks, no body left its fat box";
  }
}

// n bodies for `ticks` ticks, body i swept from sweep(tick, i).first to .second (radius r), in a
// PairCache with margins by travel (each sweep's x-y) or by extent alone; each tick's pairs are
// brute force's; then on_tick(tick, cache).
template <class Sweep, class OnTick>
void run_bodies(bool with_travel, int ticks, uint32_t n, double r, Sweep&& sweep, OnTick&& on_tick) {
  collision::PairCache cache;
  std::vector<Box> boxes;
  std::vector<uint32_t> ids;
  std::vector<Travel> travel;
  Pairs got, want;
  for (int tick = 0; tick < ticks; ++tick) {
    boxes.clear(), ids.clear(), travel.clear();
    for (uint32_t i = 0; i < n; ++i) {
      const auto [c0, c1] = sweep(tick, i);
      ids.push_back(i);
      boxes.push_back(collision::swept_box(c0, c1, r));
      travel.push_back({static_cast<float>(c1.x() - c0.x()), static_cast<float>(c1.y() - c0.y())});
    }
    cache.pairs(boxes, ids, n, got, nullptr, with_travel ? &travel : nullptr);
    collision::brute_pairs(boxes, want);
    ASSERT_EQ(sorted(got), want) << "tick " << tick << (with_travel ? ", travel" : "");
    EXPECT_GE(cache.kept_pairs(), want.size());
    on_tick(tick, cache);
  }
}

// Margins by travel (the detector's: each sweep's end less its start): a dense crowd whose bodies
// rock by 4 cm keeps fat boxes an eighth of their extent wider all round (kMarginMinOfExtent)
// and 8 ticks of travel (32 cm) ahead, not a half all round, so it keeps far fewer pairs that do
// not overlap; no body leaves its fat box after the first tick; the pairs are brute force's.
TEST(PairCache, MarginsByTravelKeepFewerPairsInADenseCrowd) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<Vec3> pos;
  for (int i = 0; i < 2000; ++i) pos.emplace_back(u(rng) * 200, u(rng) * 200, 0);
  size_t kept[2] = {0, 0};
  for (int with_travel : {0, 1}) {
    auto rocking = [&](int tick, uint32_t i) {
      return std::pair<Vec3, Vec3>(pos[i], pos[i] + Vec3(tick % 2 ? 0.04 : -0.04, 0, 0));
    };
    run_bodies(with_travel, 6, 2000, 3.0, rocking, [&](int tick, const collision::PairCache& cache) {
      if (tick > 1) {
        EXPECT_EQ(cache.moved(), 0u) << "tick " << tick;
      }
      kept[with_travel] = cache.kept_pairs();
    });
  }
  // (6.04 m boxes: fat 12.1 m square with the half margin; 7.55 m by 7.9 m by travel: about 2.5x
  // fewer kept)
  EXPECT_LT(kept[1] * 2, kept[0]) << kept[1] << " kept pairs by travel, " << kept[0] << " by extent";
}

// Bodies driving straight (1 m a tick, 6.5 m boxes), all set off on the same tick, keep their fat
// boxes about kTravelTicks ticks: 6 to 10 ticks of travel ahead (6-10 m) against the extent's
// half all round (3.25 m: 3 or 4 ticks); and they do not renew them all on the same ticks (by
// travel, the most in one tick is a third of them). The pairs are brute force's either way.
TEST(PairCache, ABodyGoingStraightKeepsItsFatBoxTravelTicks) {
  size_t moved[2] = {0, 0}, most[2] = {0, 0};
  for (int with_travel : {0, 1}) {
    auto driving = [](int tick, uint32_t i) {
      const Vec3 dir = i % 2 ? Vec3(1, 0, 0) : Vec3(0, -1, 0);  // east or south
      const Vec3 p = Vec3((i % 20) * 40.0, (i / 20) * 40.0, 0) + dir * tick;
      return std::pair<Vec3, Vec3>(p - dir, p);
    };
    run_bodies(with_travel, 65, 300, 2.75, driving, [&](int tick, const collision::PairCache& cache) {
      if (tick > 0) moved[with_travel] += cache.moved(), most[with_travel] = std::max(most[with_travel], cache.moved());
    });
  }
  EXPECT_LE(moved[1], 300u * 9) << "64 ticks: about 8 fat boxes each by travel";
  EXPECT_GE(moved[0], 300u * 15) << "64 ticks: 16 to 21 fat boxes each by extent";
  EXPECT_LE(most[1], 100u) << "the renewals spread over the ticks";
  std::printf("fat boxes made again in 64 ticks, 300 bodies: %zu by travel (at most %zu in a tick), %zu by extent\n",
              moved[1], most[1], moved[0]);
}
