// Broad phase of moving bodies for the continuous method (and the speed benchmark), on plain arrays.
//  MovingGrid: all pairs i < j of overlapping boxes among N moving bodies. A hashed 2D grid
//    whose cell is 3x the largest extent among the ordinary boxes (boxes more than 4x the
//    mean extent are "large" and tested against every box), so a box lies in at most 2 x 2
//    cells; each box is listed in the cells it overlaps, counting-sorted by hash bucket into one
//    contiguous array; then every bucket's entries are tested pairwise, a pair reported only in
//    the first cell the two boxes share (and only between entries of the same cell when two
//    cells share a bucket). Rebuilt every call into reused buffers (no allocation once warm).
//    Given a core::Jobs, the listing is built per range of boxes too (the mean extent from an
//    integer sum, counts per range, offsets per range of buckets from a scan of their sums,
//    bucket by bucket then range by range, each range filling its own slots): the same array.
//    Linear in N for bounded density, also where bodies crowd (the cell shrinks to the bodies).
//  Fixed objects are the world's one grid (world/fixed_grid.hpp), not indexed again here.
//  brute_pairs: the plain O(N^2) reference the tests compare MovingGrid with.
//  Threading: given a core::Jobs, the pair search runs per range of buckets, each range into its
//    own buffer, concatenated in range order: the same pairs in the same order for any thread count.
// Units: metres, local frame; boxes in float (a 50 km map keeps ~4 mm resolution).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/jobs.hpp"
#include "core/math.hpp"

namespace npsnet::collision {

struct Box {
  float lo[3], hi[3];
};
inline bool overlap(const Box& a, const Box& b) {
  return a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] && a.lo[1] <= b.hi[1] && b.lo[1] <= a.hi[1] &&
         a.lo[2] <= b.hi[2] && b.lo[2] <= a.hi[2];
}
// The same answer, every comparison made (no early exit, so no branch): for loops where the
// answer is as often yes as no.
inline bool overlap_branchless(const Box& a, const Box& b) {
  return (a.lo[0] <= b.hi[0]) & (b.lo[0] <= a.hi[0]) & (a.lo[1] <= b.hi[1]) & (b.lo[1] <= a.hi[1]) &
         (a.lo[2] <= b.hi[2]) & (b.lo[2] <= a.hi[2]);
}
// The box of a sphere of radius r swept from c0 to c1. (Lane-wise selects: in a crowd whose
// bodies go either way, a branch per axis here is mispredicted every other time.)
inline Box swept_box(const Vec3& c0, const Vec3& c1, double r) {
  using D4 = double __attribute__((vector_size(32)));
  const D4 a = {c0[0], c0[1], c0[2], 0}, z = {c1[0], c1[1], c1[2], 0};
  const auto lt = a < z;
  const D4 lo = (lt ? a : z) - r, hi = (lt ? z : a) + r;  // c0 < c1 ? c0 : c1, and the other
  Box b;
  for (int k = 0; k < 3; ++k) b.lo[k] = static_cast<float>(lo[k]), b.hi[k] = static_cast<float>(hi[k]);
  return b;
}

// floor(v) for |v| < 2^30 without a libm call (grid cells).
inline int32_t ifloor(double v) { return static_cast<int32_t>(static_cast<int64_t>(v + 1073741824.0) - 1073741824); }
// The hash of grid cell (x, y) in a table of mask + 1 buckets (a power of two).
inline uint32_t hash_cell(int32_t x, int32_t y, uint32_t mask) {
  return (static_cast<uint32_t>(x) * 73856093u ^ static_cast<uint32_t>(y) * 19349663u) & mask;
}

// llround(e * 256) for an extent e >= 0 that is a float's value (the grid's mean extent sums
// these), without the libm call where that is exact: e * 256 has at most 24 significant bits, so
// below 2^28 adding 0.5 rounds nothing and truncation rounds half away from zero as llround does.
inline int64_t in_256ths(double e) {
  const double y = e * 256;
  return y < 0x1p28 ? static_cast<int64_t>(y + 0.5) : std::llround(y);
}

using BoxPairs = std::vector<std::pair<uint32_t, uint32_t>>;

// Appends to `out` the pairs (min, max) of each large box l (in `large`'s order) with every other
// box whose box overlaps it, a pair of two large boxes once (is_large(j) names the large ones).
// Per range of boxes on the pool, each range into chunk_out[c], concatenated in range order: the
// same pairs in the same order for any thread count. Both broad phases test their large boxes so.
template <class IsLarge>
void large_pairs(const std::vector<Box>& boxes, const std::vector<uint32_t>& large, IsLarge&& is_large, BoxPairs& out,
                 std::vector<BoxPairs>& chunk_out, core::Jobs* jobs) {
  constexpr size_t kGrain = 4096;  // boxes per range a large box is tested against
  const size_t n = boxes.size();
  const int k = jobs ? jobs->chunks(n, kGrain) : 1;
  if (chunk_out.size() < static_cast<size_t>(k)) chunk_out.resize(k);
  for (const uint32_t l : large) {
    core::run_chunks(jobs, n, kGrain, [&](int c, size_t j0, size_t j1) {
      BoxPairs& o = k == 1 ? out : chunk_out[c];
      if (k > 1) o.clear();
      for (uint32_t j = static_cast<uint32_t>(j0); j < j1; ++j) {
        if (j == l || (j < l && is_large(j))) continue;  // large-large pairs once
        if (overlap(boxes[l], boxes[j])) o.emplace_back(std::min(l, j), std::max(l, j));
      }
    });
    if (k > 1)
      for (int c = 0; c < k; ++c) out.insert(out.end(), chunk_out[c].begin(), chunk_out[c].end());
  }
}

class MovingGrid {
 public:
  // Appends to `out` (cleared first) every pair (i, j), i < j, whose boxes overlap, each once,
  // in an order that depends only on the input.
  void pairs(const std::vector<Box>& boxes, std::vector<std::pair<uint32_t, uint32_t>>& out,
             core::Jobs* jobs = nullptr);
  double cell_m() const { return cell_; }

 private:
  struct Entry {      // 28 bytes: the x, y extent; z and the first cell only for candidates
    float lox, loy, hix, hiy;
    int32_t cx, cy;  // this entry's cell
    uint32_t id;
  };
  double cell_ = 1;
  std::vector<uint32_t> start_;       // CSR over hash buckets
  std::vector<uint32_t> bucket_;      // per (box, cell) listing: its bucket; box i's from 4 i
  std::vector<std::vector<uint32_t>> count_;        // per range of boxes: its count, then its next slot, per bucket
  std::vector<std::vector<uint32_t>> large_chunk_;  // per range of boxes: its large boxes
  std::vector<Entry> entries_;        // by bucket
  std::vector<uint32_t> large_;
  std::vector<uint8_t> is_large_;
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> chunk_out_;  // per range of buckets
  struct Part {
    int64_t sum = 0;  // extents in 1/256 m
    double ext = 0;   // the largest ordinary extent
  };
  std::vector<Part> part_;      // per range of boxes
  std::vector<uint32_t> scan_;  // per range of buckets: its first slot (the offsets' scan)
};

void brute_pairs(const std::vector<Box>& boxes, std::vector<std::pair<uint32_t, uint32_t>>& out);

}  // namespace npsnet::collision
