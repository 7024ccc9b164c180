// Hashed moving grid, brute-force reference (broadphase.hpp).
#include "collision/broadphase.hpp"

#include <algorithm>
#include <cassert>

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
  start_.assign(nb + 1, 0);
  is_large_.assign(n, 0);
  bucket_.resize(4 * static_cast<size_t>(n));  // at most 2 x 2 cells a box
  uint32_t* bucket = bucket_.data();
  uint32_t* count = start_.data() + 1;
  size_t nbucket = 0;
  // Count: each ordinary box in the (at most 2 x 2) cells it overlaps.
  for (uint32_t i = 0; i < n; ++i) {
    const Box& b = boxes[i];
    if (std::max(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]) > cap) {
      large_.push_back(i);
      is_large_[i] = 1;
      continue;
    }
    const int32_t i0 = ifloor(b.lo[0] * inv), i1 = ifloor(b.hi[0] * inv);
    const int32_t j0 = ifloor(b.lo[1] * inv), j1 = ifloor(b.hi[1] * inv);
    for (int32_t y = j0; y <= j1; ++y)
      for (int32_t x = i0; x <= i1; ++x) {
        const uint32_t h = hash_cell(x, y, mask);
        bucket[nbucket++] = h;
        ++count[h];
      }
  }
  for (uint32_t h = 0; h < nb; ++h) start_[h + 1] += start_[h];
  entries_.resize(start_[nb]);
  // Fill (start_[h] advances to the bucket's end, then is shifted back).
  size_t q = 0;
  for (uint32_t i = 0; i < n; ++i) {
    if (is_large_[i]) continue;
    const Box& b = boxes[i];
    const int32_t i0 = ifloor(b.lo[0] * inv), i1 = ifloor(b.hi[0] * inv);
    const int32_t j0 = ifloor(b.lo[1] * inv), j1 = ifloor(b.hi[1] * inv);
    for (int32_t y = j0; y <= j1; ++y)
      for (int32_t x = i0; x <= i1; ++x) entries_[start_[bucket[q++]]++] = Entry{b.lo[0], b.lo[1], b.hi[0], b.hi[1], x, y, i};
  }
  assert(q == nbucket);
  for (uint32_t h = nb; h > 0; --h) start_[h] = start_[h - 1];
  start_[0] = 0;
  assert(start_[nb] == entries_.size());
  // Pairs inside each bucket: same cell, reported in the first cell the two boxes share.
  // Ranges of buckets, each into its own buffer (chunk_out_), concatenated in range order.
  const int k = jobs ? jobs->chunks(nb, 4096) : 1;
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
    jobs->for_chunks(nb, 4096, range);
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
