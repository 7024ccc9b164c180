// core::radix_sort gives std::sort's order for every size around its switch-over (kRadixMin),
// for keys that differ in every byte, in only some bytes (the detector's pair keys), in none,
// and with the top bit set (fixed contacts); the scratch is reused across calls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/radix_sort.hpp"
#include "world/random.hpp"

using namespace npsnet;

namespace {

std::vector<std::uint64_t> sorted_copy(std::vector<std::uint64_t> v) {
  std::sort(v.begin(), v.end());
  return v;
}

// The detector's key of a pair (collision/detect.cpp): flag << 63 | lo << 31 | hi.
std::uint64_t pair_key(std::uint64_t lo, std::uint64_t hi, bool fixed) {
  return (fixed ? 1ull << 63 : 0) | (lo << 31) | hi;
}

}  // namespace

TEST(RadixSort, SameOrderAsStdSortAtEverySize) {
  world::Rng rng(7);
  std::vector<std::uint64_t> scratch;
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{2}, core::kRadixMin - 1, core::kRadixMin,
                              core::kRadixMin + 1, std::size_t{5000}, std::size_t{100000}}) {
    std::vector<std::uint64_t> v(n);
    for (auto& k : v) k = rng.next();
    const auto want = sorted_copy(v);
    core::radix_sort(v, scratch);
    EXPECT_EQ(v, want) << n << " keys";
  }
}

TEST(RadixSort, PairKeysDuplicatesAndTheTopBit) {
  world::Rng rng(11);
  std::vector<std::uint64_t> v, scratch;
  for (int i = 0; i < 60000; ++i) {
    const std::uint64_t a = rng.next() % 100000, b = rng.next() % 100000;
    v.push_back(pair_key(std::min(a, b), std::max(a, b), i % 7 == 0));
    if (i % 5 == 0) v.push_back(v.back());  // the same key twice
  }
  const auto want = sorted_copy(v);
  core::radix_sort(v, scratch);
  EXPECT_EQ(v, want);
  // Sorted input, and every key the same: unchanged.
  core::radix_sort(v, scratch);
  EXPECT_EQ(v, want);
  std::vector<std::uint64_t> same(3000, pair_key(5, 9, true));
  core::radix_sort(same, scratch);
  EXPECT_EQ(same, std::vector<std::uint64_t>(3000, pair_key(5, 9, true)));
}

TEST(RadixSort, DescendingInputAndScratchKeptAcrossCalls) {
  std::vector<std::uint64_t> v, scratch;
  for (std::uint64_t i = 0; i < 4096; ++i) v.push_back(~i);
  const auto want = sorted_copy(v);
  core::radix_sort(v, scratch);
  EXPECT_EQ(v, want);
  EXPECT_GE(scratch.capacity(), std::size_t{4096});
  // A smaller set after a larger one: the scratch is only resized, and the answer still right.
  std::vector<std::uint64_t> w(2000);
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = (i * 2654435761u) % 1999 << 40;
  const auto want_w = sorted_copy(w);
  core::radix_sort(w, scratch);
  EXPECT_EQ(w, want_w);
}
