// MovingGrid's pair search on worker threads (broadphase.hpp, threading): the same pairs in the
// same order as on one thread, on random crowds, with every range as small as the pool allows.
#include <gtest/gtest.h>

#include <random>

#include "collision/broadphase.hpp"

using namespace npsnet;
using collision::Box;

TEST(ParallelBroadphase, SamePairsInTheSameOrderOnOneAndSeveralThreads) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> u(0, 1);
  for (int n : {2, 100, 5000, 20000}) {
    std::vector<Box> boxes(n);
    const float side = 20.0f * std::sqrt(static_cast<float>(n));  // crowded: a few neighbours each
    for (Box& b : boxes) {
      const float x = u(rng) * side, y = u(rng) * side, z = u(rng) * 5, r = 2 + 6 * u(rng);
      b = Box{{x - r, y - r, z - r}, {x + r + 5 * u(rng), y + r, z + r}};
    }
    boxes[n / 2] = Box{{0, 0, 0}, {side, 50, 10}};  // a large box, tested against all
    collision::MovingGrid one, many;
    std::vector<std::pair<uint32_t, uint32_t>> a, b, brute;
    one.pairs(boxes, a);
    for (int threads : {2, 3}) {
      core::Jobs jobs(threads);
      jobs.set_max_grain(1);
      many.pairs(boxes, b, &jobs);
      EXPECT_EQ(a, b) << n << " boxes, " << threads << " threads";
      EXPECT_EQ(one.cell_m(), many.cell_m()) << "the cell from the mean and largest extents, any split";
    }
    collision::brute_pairs(boxes, brute);
    std::sort(a.begin(), a.end());
    EXPECT_EQ(a, brute) << n;
    if (n >= 5000) {
      EXPECT_GT(brute.size(), static_cast<size_t>(n) / 2);  // the crowd has pairs to find
    }
  }
}
