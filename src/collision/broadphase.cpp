// Hashed moving grid, brute-force reference (broadphase.hpp).
#include "collision/broadphase.hpp"

#include <algorithm>
#include <cmath>

#include "core/prefetch.hpp"

namespace npsnet::collision {

namespace {
// A box's larger extent in x and y.
inline double extent(const Box& b) { return std::max(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]); }
}  // namespace

void MovingGrid::pairs(const std::vector<Box>& boxes, std::vector<std::pair<uint32_t, uint32_t>>& out,
                       core::Jobs* jobs) {
  out.clear();
  const uint32_t n = static_cast<uint32_t>(boxes.size());
  large_.clear();
  if (n < 2) return;
  // Cell: 3x the largest extent among ordinary boxes (extent <= 4x the mean): 1.78 cells a
  // box on average, few boxes a cell. Both passes per range of boxes (on the pool when there is
  // one): the mean from a sum in whole 1/256 m (integers: the same sum in any split), the
  // largest extent from each range's largest.
  constexpr size_t kBoxGrain = 256;  // (a chunk's count array is nb entries: nb ~ n)
  const int kc = jobs ? jobs->chunks(n, kBoxGrain) : 1;
  if (count_.size() < static_cast<size_t>(kc)) count_.resize(kc), large_chunk_.resize(kc), part_.resize(kc);
  auto on_ranges = [&](auto&& fn) { core::run_chunks(jobs, n, kBoxGrain, fn); };
  on_ranges([&](int c, size_t b0, size_t b1) {
    int64_t sum = 0;
    for (size_t i = b0; i < b1; ++i)
      if (const double e = extent(boxes[i]); e > 0) sum += in_256ths(std::min(e, 1e9));  // (NaN: 0)
    part_[c].sum = sum;
  });
  int64_t sum = 0;
  for (int c = 0; c < kc; ++c) sum += part_[c].sum;
  const double cap = 4 * (static_cast<double>(sum) / 256 / n);
  on_ranges([&](int c, size_t b0, size_t b1) {
    double ext = 0;
    for (size_t i = b0; i < b1; ++i)
      if (const double e = extent(boxes[i]); e <= cap) ext = std::max(ext, e);
    part_[c].ext = ext;
  });
  double ext = 0;
  for (int c = 0; c < kc; ++c) ext = std::max(ext, part_[c].ext);
  cell_ = std::max(3 * ext, 1e-3);
  const double inv = 1.0 / cell_;
  uint32_t nb = 1;
  while (nb < n) nb <<= 1;  // about one bucket per box: the table stays in L1/L2
  const uint32_t mask = nb - 1;
  is_large_.assign(n, 0);
  bucket_.resize(4 * static_cast<size_t>(n));  // at most 2 x 2 cells a box: box i's from 4 i
  // Count, per range of boxes: each ordinary box in the (at most 2 x 2) cells it overlaps, into
  // the range's own counts per bucket.
  auto count = [&](int c, size_t b0, size_t b1) {
    std::vector<uint32_t>& cnt = count_[c];
    cnt.assign(nb, 0);
    large_chunk_[c].clear();
    for (size_t i = b0; i < b1; ++i) {
      const Box& b = boxes[i];
      if (extent(b) > cap) {
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
  on_ranges(count);
  // Offsets, bucket by bucket and within a bucket range by range: each bucket lists its boxes in
  // box order, as one pass over all boxes would. count_[c][h] becomes range c's next slot in h.
  // On the pool: each range of buckets sums its counts, the sums are scanned in range order,
  // then each range writes its offsets from its start (integers: the same for any split).
  constexpr size_t kScanGrain = 4096;
  const int ks = jobs ? jobs->chunks(nb, kScanGrain) : 1;
  if (scan_.size() < static_cast<size_t>(ks) + 1) scan_.resize(ks + 1);
  start_.resize(nb + 1);
  auto bucket_ranges = [&](auto&& fn) { core::run_chunks(jobs, nb, kScanGrain, fn); };
  bucket_ranges([&](int r, size_t h0, size_t h1) {
    uint32_t total = 0;
    for (size_t h = h0; h < h1; ++h)
      for (int c = 0; c < kc; ++c) total += count_[c][h];
    scan_[r + 1] = total;
  });
  scan_[0] = 0;
  for (int r = 0; r < ks; ++r) scan_[r + 1] += scan_[r];
  bucket_ranges([&](int r, size_t h0, size_t h1) {
    uint32_t next = scan_[r];
    for (size_t h = h0; h < h1; ++h) {
      start_[h] = next;
      for (int c = 0; c < kc; ++c) {
        const uint32_t k = count_[c][h];
        count_[c][h] = next;
        next += k;
      }
    }
  });
  const uint32_t next = scan_[ks];
  start_[nb] = next;
  entries_.resize(next);
  for (int c = 0; c < kc; ++c) large_.insert(large_.end(), large_chunk_[c].begin(), large_chunk_[c].end());
  // Fill, per the same ranges: each writes only its own slots.
  constexpr size_t kFillAhead = 8;
  auto fill = [&](int c, size_t b0, size_t b1) {
    std::vector<uint32_t>& slot = count_[c];
    for (size_t i = b0; i < b1; ++i) {
      // The boxes lie in no spatial order: each one's first slot is asked of the cache
      // kFillAhead boxes before it is written (a hint: no result changes).
      if (i + kFillAhead < b1 && !is_large_[i + kFillAhead])
        core::prefetch(entries_.data() + slot[bucket_[4 * (i + kFillAhead)]]);
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
  on_ranges(fill);
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
  // Large boxes against every box (each pair once), per range of boxes into the range's buffer,
  // concatenated in range order: box order, as on one thread.
  large_pairs(boxes, large_, [&](uint32_t j) { return is_large_[j] != 0; }, out, chunk_out_, jobs);
}

void brute_pairs(const std::vector<Box>& boxes, std::vector<std::pair<uint32_t, uint32_t>>& out) {
  out.clear();
  for (uint32_t i = 0; i < boxes.size(); ++i)
    for (uint32_t j = i + 1; j < boxes.size(); ++j)
      if (overlap(boxes[i], boxes[j])) out.emplace_back(i, j);
}

}  // namespace npsnet::collision
