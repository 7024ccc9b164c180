// Hashed moving grid, brute-force reference (broadphase.hpp).
#include "collision/broadphase.hpp"

#include <algorithm>

namespace npsnet::collision {

namespace {
// floor(v) for |v| < 2^30 without a libm call.
inline int32_t ifloor(double v) { return static_cast<int32_t>(static_cast<int64_t>(v + 1073741824.0) - 1073741824); }
inline uint32_t hash_cell(int32_t x, int32_t y, uint32_t mask) {
  return (static_cast<uint32_t>(x) * 73856093u ^ static_cast<uint32_t>(y) * 19349663u) & mask;
}
}  // namespace

void MovingGrid::pairs(const std::vector<Box>& boxes, std::vector<std::pair<uint32_t, uint32_t>>& out,
                       core::Jobs* jobs) {
  out.clear();
  const uint32_t n = static_cast<uint32_t>(boxes.size());
  large_.clear();
  if (n < 2) return;
  // Cell: 3x the largest extent among ordinary boxes (extent <= 4x the mean): 1.78 cells a
  // box on average, few boxes a cell.
  double mean = 0;
  for (const Box& b : boxes) mean += std::max(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]);
  mean /= n;
  const double cap = 4 * mean;
  double ext = 0;
  for (const Box& b : boxes) {
    const double e = std::max(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]);
    if (e <= cap) ext = std::max(ext, e);
  }
  cell_ = std::max(3 * ext, 1e-3);
  const double inv = 1.0 / cell_;
  uint32_t nb = 1;
  while (nb < n) nb <<= 1;  // about one bucket per box: the table stays in L1/L2
  const uint32_t mask = nb - 1;
  is_large_.assign(n, 0);
  bucket_.resize(4 * static_cast<size_t>(n));  // at most 2 x 2 cells a box: box i's from 4 i
  // Count, per range of boxes (on the pool when there is one): each ordinary box in the (at most
  // 2 x 2) cells it overlaps, into the range's own counts per bucket.
  constexpr size_t kBoxGrain = 256;  // (a chunk's count array is nb entries: nb ~ n)
  const int kc = jobs ? jobs->chunks(n, kBoxGrain) : 1;
  if (count_.size() < static_cast<size_t>(kc)) count_.resize(kc), large_chunk_.resize(kc);
  auto count = [&](int c, size_t b0, size_t b1) {
    std::vector<uint32_t>& cnt = count_[c];
    cnt.assign(nb, 0);
    large_chunk_[c].clear();
    for (size_t i = b0; i < b1; ++i) {
      const Box& b = boxes[i];
      if (std::max(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]) > cap) {
        large_chunk_[c].push_back(static_cast<uint32_t>(i));
        is_large_[i] = 1;
        continue;
      }
      const int32_t i0 = ifloor(b.lo[0] * inv), i1 = ifloor(b.hi[0] * inv);
      const int32_t j0 = ifloor(b.lo[1] * inv), j1 = ifloor(b.hi[1] * inv);
      uint32_t* bucket = bucket_.data() + 4 * i;
      for (int32_t y = j0; y <= j1; ++y)
        for (int32_t x = i0; x <= i1; ++x) {
          const uint32_t h = hash_cell(x, y, mask);
          *bucket++ = h;
          ++cnt[h];
        }
    }
  };
  if (kc > 1) jobs->for_chunks(n, kBoxGrain, count);
  else count(0, 0, n);
  // Offsets, bucket by bucket and within a bucket range by range: each bucket lists its boxes in
  // box order, as one pass over all boxes would. count_[c][h] becomes range c's next slot in h.
  start_.resize(nb + 1);
  uint32_t next = 0;
  for (uint32_t h = 0; h < nb; ++h) {
    start_[h] = next;
    for (int c = 0; c < kc; ++c) {
      const uint32_t k = count_[c][h];
      count_[c][h] = next;
      next += k;
    }
  }
  start_[nb] = next;
  entries_.resize(next);
  for (int c = 0; c < kc; ++c) large_.insert(large_.end(), large_chunk_[c].begin(), large_chunk_[c].end());
  // Fill, per the same ranges: each writes only its own slots.
  auto fill = [&](int c, size_t b0, size_t b1) {
    std::vector<uint32_t>& slot = count_[c];
    for (size_t i = b0; i < b1; ++i) {
      if (is_large_[i]) continue;
      const Box& b = boxes[i];
      const int32_t i0 = ifloor(b.lo[0] * inv), i1 = ifloor(b.hi[0] * inv);
      const int32_t j0 = ifloor(b.lo[1] * inv), j1 = ifloor(b.hi[1] * inv);
      const uint32_t* bucket = bucket_.data() + 4 * i;
      for (int32_t y = j0; y <= j1; ++y)
        for (int32_t x = i0; x <= i1; ++x)
          entries_[slot[*bucket++]++] = Entry{b.lo[0], b.lo[1], b.hi[0], b.hi[1], x, y, static_cast<uint32_t>(i)};
    }
  };
  if (kc > 1) jobs->for_chunks(n, kBoxGrain, fill);
  else fill(0, 0, n);
  // Pairs inside each bucket: same cell, reported in the first cell the two boxes share.
  // Ranges of buckets, each into its own buffer (chunk_out_), concatenated in range order.
  constexpr size_t kBucketGrain = 256;
  const int k = jobs ? jobs->chunks(nb, kBucketGrain) : 1;
  if (chunk_out_.size() < static_cast<size_t>(k)) chunk_out_.resize(k);
  auto range = [&](int c, size_t h0, size_t h1) {
    auto& o = k == 1 ? out : chunk_out_[c];
    o.clear();
    for (uint32_t h = static_cast<uint32_t>(h0); h < h1; ++h) {
      const uint32_t e0 = start_[h], e1 = start_[h + 1];
      if (e1 - e0 < 2) continue;
      for (uint32_t a = e0; a < e1; ++a) {
        const Entry& ea = entries_[a];
        for (uint32_t b = a + 1; b < e1; ++b) {
          const Entry& eb = entries_[b];
          // All four compares, no early exit: in a crowded bucket most pairs fail on one of them
          // at random, and a branch per compare mispredicts.
          const bool apart = (ea.lox > eb.hix) | (eb.lox > ea.hix) | (ea.loy > eb.hiy) | (eb.loy > ea.hiy);
          if (apart) continue;
          if (ea.cx != eb.cx || ea.cy != eb.cy) continue;  // another cell in this bucket
          // Reported only in the first cell the two boxes share.
          if (std::max(ifloor(ea.lox * inv), ifloor(eb.lox * inv)) != ea.cx ||
              std::max(ifloor(ea.loy * inv), ifloor(eb.loy * inv)) != ea.cy)
            continue;
          const Box& ba = boxes[ea.id];
          const Box& bb = boxes[eb.id];
          if (ba.lo[2] > bb.hi[2] || bb.lo[2] > ba.hi[2]) continue;
          o.emplace_back(std::min(ea.id, eb.id), std::max(ea.id, eb.id));
        }
      }
    }
  };
  if (k == 1) {
    range(0, 0, nb);
  } else {
    jobs->for_chunks(nb, kBucketGrain, range);
    for (int c = 0; c < k; ++c) out.insert(out.end(), chunk_out_[c].begin(), chunk_out_[c].end());
  }
  // Large boxes against every box (each pair once).
  for (uint32_t l : large_) {
    for (uint32_t j = 0; j < n; ++j) {
      if (j == l || (is_large_[j] && j < l)) continue;  // large-large pairs once
      if (overlap(boxes[l], boxes[j])) out.emplace_back(std::min(l, j), std::max(l, j));
    }
  }
}

void brute_pairs(const std::vector<Box>& boxes, std::vector<std::pair<uint32_t, uint32_t>>& out) {
  out.clear();
  for (uint32_t i = 0; i < boxes.size(); ++i)
    for (uint32_t j = i + 1; j < boxes.size(); ++j)
      if (overlap(boxes[i], boxes[j])) out.emplace_back(i, j);
}

}  // namespace npsnet::collision
