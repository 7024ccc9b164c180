// Sorts 64-bit keys ascending: the same result as std::sort, in O(n) passes instead of
// comparisons. Below kRadixMin keys, std::sort. Above, least significant byte first, one stable
// counting pass per byte, skipping the bytes every key shares (the collision detector's pair
// keys, collision/detect.cpp, use 4 or 5 of their 8). scratch: reused between calls (no
// allocation once warm). Why: the detector sorts the pairs in contact every tick, 59,000 in the
// 100,000-vehicle crowd; std::sort took 3.5 ms of its tick on this machine.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace npsnet::core {

inline constexpr std::size_t kRadixMin = 1024;

inline void radix_sort(std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& scratch) {
  const std::size_t n = keys.size();
  if (n < kRadixMin) {
    std::sort(keys.begin(), keys.end());
    return;
  }
  std::array<std::array<std::uint32_t, 256>, 8> count{};  // per byte, keys per value
  for (const std::uint64_t k : keys)
    for (int b = 0; b < 8; ++b) ++count[b][(k >> (8 * b)) & 0xff];
  scratch.resize(n);
  std::uint64_t* from = keys.data();
  std::uint64_t* to = scratch.data();
  for (int b = 0; b < 8; ++b) {
    auto& c = count[b];
    if (c[(from[0] >> (8 * b)) & 0xff] == n) continue;  // one value: this byte orders nothing
    std::uint32_t sum = 0;
    for (auto& x : c) {  // counts -> where each value's run starts
      const std::uint32_t here = x;
      x = sum, sum += here;
    }
    for (std::size_t i = 0; i < n; ++i) to[c[(from[i] >> (8 * b)) & 0xff]++] = from[i];
    std::swap(from, to);
  }
  if (from != keys.data()) keys.swap(scratch);
}

}  // namespace npsnet::core
