// Persistent broad phase: fat boxes in a hashed grid, their pairs kept across ticks (pair_cache.hpp).
#include "collision/pair_cache.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/prefetch.hpp"
#include "world/random.hpp"

namespace npsnet::collision {

namespace {
constexpr size_t kSlotGrain = 2048;   // bodies per range below which a pass stays on one thread
constexpr size_t kQueryGrain = 256;   // moved bodies per range of grid queries
constexpr size_t kKeptGrain = 4096;   // kept pairs per range of the kept pairs' two passes
// Moved bodies lie in no spatial order: the buckets of the one kQueryAhead later are asked of the
// cache before a body's grid update or query (a hint: no result changes).
constexpr size_t kQueryAhead = 4;
// Kept pairs name bodies in no spatial order: their per-body words are asked of the cache
// kKeptAhead pairs ahead (the slot, then, half as far ahead, the box the slot names).
constexpr size_t kKeptAhead = 32;
constexpr double kMaxCell = 0x1p29;   // a fat box's corners beyond this many cells: large
}  // namespace

float PairCache::ahead_ticks(uint32_t id) const {
  world::Rng hash((uint64_t{id} << 32) | tick_);  // (splitmix64 of the body and the call: one draw)
  return kTravelTicks * (1.0f - kAheadJitter + 2 * kAheadJitter * static_cast<float>(hash.unit()));
}

PairCache::Fat PairCache::fat_of(const Box& b, const Travel* travel, uint32_t id) const {
  const float ext = std::max(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]);
  if (!travel) {
    const float m = kMarginOfExtent * ext;
    return {b.lo[0] - m, b.lo[1] - m, b.hi[0] + m, b.hi[1] + m};
  }
  // Ahead: where the box goes in the next ticks if the body keeps going (a NaN travel: nowhere).
  const float m = kMarginMinOfExtent * ext, most = kAheadOfExtent * ext, k = ahead_ticks(id);
  const float ax = std::clamp(k * travel->x, -most, most), ay = std::clamp(k * travel->y, -most, most);
  return {b.lo[0] - m + std::min(0.0f, ax), b.lo[1] - m + std::min(0.0f, ay), b.hi[0] + m + std::max(0.0f, ax),
          b.hi[1] + m + std::max(0.0f, ay)};
}

PairCache::Range PairCache::cells_of(const Fat& f) const {
  return {ifloor(f.lox * inv_), ifloor(f.loy * inv_), ifloor(f.hix * inv_), ifloor(f.hiy * inv_)};
}

uint32_t PairCache::bucket_of(int32_t x, int32_t y) const { return hash_cell(x, y, mask_); }

void PairCache::prefetch_cells(const Range& r) const {
  if (r.i1 - r.i0 >= kMaxCellsPerAxis || r.j1 - r.j0 >= kMaxCellsPerAxis) return;  // (a large body's stale range)
  for (int32_t y = r.j0; y <= r.j1; ++y)
    for (int32_t x = r.i0; x <= r.i1; ++x) core::prefetch(&buckets_[bucket_of(x, y)]);
}

bool PairCache::ordinary(const Fat& f) const {
  const bool finite = std::isfinite(f.lox) && std::isfinite(f.loy) && std::isfinite(f.hix) && std::isfinite(f.hiy);
  if (!finite || std::max(std::abs(f.lox), std::abs(f.hix)) * inv_ >= kMaxCell ||
      std::max(std::abs(f.loy), std::abs(f.hiy)) * inv_ >= kMaxCell)
    return false;
  const Range r = cells_of(f);
  return r.i1 - r.i0 < kMaxCellsPerAxis && r.j1 - r.j0 < kMaxCellsPerAxis;
}

void PairCache::build(const std::vector<Box>& boxes) {
  ++builds_;
  for (auto& b : buckets_) b.n = 0;
  for (auto& v : overflow_) v.clear();
  kept_.clear();
  std::fill(state_.begin(), state_.end(), kOut);
  live_ = 0;
  // The cell: twice the largest fat extent among the ordinary bodies (at most 4x the mean).
  double sum = 0;
  size_t counted = 0;
  for (const Box& b : boxes) {
    const Fat f = fat_of(b, nullptr, 0);
    const double e = std::max(f.hix - f.lox, f.hiy - f.loy);
    if (std::isfinite(e)) sum += e, ++counted;
  }
  const double cap = counted ? 4 * sum / counted : 0;
  double ext = 0;
  for (const Box& b : boxes) {
    const Fat f = fat_of(b, nullptr, 0);
    const double e = std::max(f.hix - f.lox, f.hiy - f.loy);
    if (e <= cap) ext = std::max(ext, e);
  }
  cell_ = std::max(2 * ext, 1e-3);
  inv_ = 1.0 / cell_;
  uint32_t nb = 64;
  while (nb < boxes.size()) nb <<= 1;
  buckets_.resize(nb), overflow_.resize(nb);
  mask_ = nb - 1;
  built_for_ = std::max<size_t>(boxes.size(), 1);
}

template <class F>
void PairCache::each(uint32_t h, F&& fn) const {
  const Bucket& b = buckets_[h];
  const uint32_t in = std::min<uint32_t>(b.n, kInline);
  for (uint32_t k = 0; k < in; ++k) fn(b.e[k]);
  if (b.n > kInline)
    for (const Entry& e : overflow_[h]) fn(e);
}

void PairCache::remove_entry(uint32_t h, const Entry& gone) {
  Bucket& b = buckets_[h];
  auto same = [&](const Entry& e) { return e.id == gone.id && e.cx == gone.cx && e.cy == gone.cy; };
  if (b.n > kInline) {  // the overflow's last fills the hole
    std::vector<Entry>& v = overflow_[h];
    --b.n;
    for (Entry& e : v)
      if (same(e)) {
        e = v.back(), v.pop_back();
        return;
      }
    const Entry last = v.back();
    v.pop_back();
    for (Entry& e : b.e)
      if (same(e)) {
        e = last;
        return;
      }
    assert(false && "PairCache: an entry listed nowhere");
    return;
  }
  for (uint32_t k = 0; k < b.n; ++k)
    if (same(b.e[k])) {
      b.e[k] = b.e[--b.n];
      return;
    }
  assert(false && "PairCache: an entry listed nowhere");
}

void PairCache::remove(uint32_t id, const Range& r) {
  for (int32_t y = r.j0; y <= r.j1; ++y)
    for (int32_t x = r.i0; x <= r.i1; ++x) remove_entry(bucket_of(x, y), Entry{id, x, y});
}

void PairCache::insert(uint32_t id, const Range& r) {
  for (int32_t y = r.j0; y <= r.j1; ++y)
    for (int32_t x = r.i0; x <= r.i1; ++x) {
      const uint32_t h = bucket_of(x, y);
      Bucket& b = buckets_[h];
      if (b.n < kInline) b.e[b.n] = Entry{id, x, y};
      else overflow_[h].push_back(Entry{id, x, y});
      ++b.n;
    }
}

void PairCache::query(const Moved& m, std::vector<std::pair<uint32_t, uint32_t>>& to) const {
  const uint32_t id = m.id;
  const Fat& f = m.fat;
  const Range& r = m.cells;
  for (int32_t y = r.j0; y <= r.j1; ++y)
    for (int32_t x = r.i0; x <= r.i1; ++x)
      each(bucket_of(x, y), [&](const Entry& e) {
        if (e.cx != x || e.cy != y || e.id == id) return;  // another cell in this bucket; itself
        const uint32_t o = e.id;
        const Fat& g = fat_[o];
        if (g.lox > f.hix || f.lox > g.hix || g.loy > f.hiy || f.loy > g.hiy) return;
        if (o < id && gone_moved_[o] == tick_) return;  // two moved bodies: the lower id's query
        const Range& q = range_[o];
        if (std::max(r.i0, q.i0) != x || std::max(r.j0, q.j0) != y) return;  // the first cell both list
        to.emplace_back(std::min(id, o), std::max(id, o));
      });
}

void PairCache::pairs(const std::vector<Box>& boxes, const std::vector<uint32_t>& ids, size_t id_count,
                      std::vector<std::pair<uint32_t, uint32_t>>& out, core::Jobs* jobs,
                      const std::vector<Travel>* travel) {
  assert(boxes.size() == ids.size() && (!travel || travel->size() == boxes.size()));
  out.clear();
  const size_t n = boxes.size();
  if (++tick_ == 0) {  // the call counter wrapped: no stamp may look like this call's
    std::fill(seen_.begin(), seen_.end(), 0u);
    std::fill(gone_moved_.begin(), gone_moved_.end(), 0u);
    tick_ = 1;
  }
  if (id_count > fat_.size()) {
    fat_.resize(id_count), range_.resize(id_count), state_.resize(id_count, kOut);
    seen_.resize(id_count, 0), gone_moved_.resize(id_count, 0), slot_.resize(id_count);
  }
  if (cell_ == 0 || rebuild_ || n > 4 * built_for_) build(boxes), rebuild_ = false;
  const int kmax = jobs ? jobs->chunks(std::max(n, fat_.size()), kSlotGrain, 4) : 1;
  if (chunk_ids_.size() < static_cast<size_t>(kmax)) chunk_ids_.resize(kmax), chunk_moved_.resize(kmax), chunk_regrid_.resize(kmax), chunk_new_.resize(kmax);
  // 1. Every body: its slot; moved when not listed, or its box left its fat box. A moved body
  //    gets its new fat box here when it stays in the same cells (most do: no bucket changes);
  //    the others are left to the serial pass (3).
  const int k1 = core::run_chunks(jobs, n, kSlotGrain, [&](int c, size_t i0, size_t i1) {
    auto& mv = chunk_moved_[c];
    auto& regrid = chunk_regrid_[c];
    mv.clear(), regrid.clear();
    size_t fresh = 0;
    for (size_t i = i0; i < i1; ++i) {
      const uint32_t id = ids[i];
      // (slot_ is read at random by both threads in step 5: written only when it changes, its
      // line is not taken from the other core's cache each tick)
      if (slot_[id] != i) slot_[id] = static_cast<uint32_t>(i);
      fresh += state_[id] == kOut;
      const Box& b = boxes[i];
      const Fat& was = fat_[id];
      if (state_[id] == kIn && b.lo[0] >= was.lox && b.lo[1] >= was.loy && b.hi[0] <= was.hix && b.hi[1] <= was.hiy)
        continue;
      gone_moved_[id] = tick_;
      const Fat f = fat_of(b, travel ? &(*travel)[i] : nullptr, id);
      const Range r = ordinary(f) ? cells_of(f) : Range{0, 0, -1, -1};
      mv.push_back(Moved{id, f, r});
      const Range& q = range_[id];
      const bool in = state_[id] == kIn;
      if (in && r.i1 >= r.i0 && q.i0 == r.i0 && q.j0 == r.j0 && q.i1 == r.i1 && q.j1 == r.j1)
        fat_[id] = f;
      else
        regrid.push_back(Regrid{static_cast<uint32_t>(i), id, in, f, r, q});
    }
    chunk_new_[c] = fresh;
  }, 4);
  moved_.clear(), regrid_.clear();
  for (int c = 0; c < k1; ++c) {
    moved_.insert(moved_.end(), chunk_moved_[c].begin(), chunk_moved_[c].end());
    regrid_.insert(regrid_.end(), chunk_regrid_[c].begin(), chunk_regrid_[c].end());
  }
  // 2. Bodies listed before and not now: gone. Looked for only when some are: the listed
  //    bodies that were listed before are fewer than the bodies listed before.
  size_t fresh = 0;
  for (int c = 0; c < k1; ++c) fresh += chunk_new_[c];
  const size_t ids_n = live_ > n - fresh ? fat_.size() : 0;
  if (ids_n)  // (stamped only then: a tick in which none went writes no line of seen_)
    core::run_chunks(jobs, n, kSlotGrain, [&](int, size_t i0, size_t i1) {
      for (size_t i = i0; i < i1; ++i) seen_[ids[i]] = tick_;
    }, 4);
  const int k2 = core::run_chunks(jobs, ids_n, kSlotGrain, [&](int c, size_t d0, size_t d1) {
    auto& gone = chunk_ids_[c];
    gone.clear();
    for (size_t d = d0; d < d1; ++d)
      if (state_[d] != kOut && seen_[d] != tick_) gone.push_back(static_cast<uint32_t>(d));
  }, 4);
  for (int c = 0; c < k2; ++c)
    for (uint32_t d : chunk_ids_[c]) {
      if (state_[d] == kIn) remove(d, range_[d]);
      state_[d] = kOut, gone_moved_[d] = tick_;
    }
  // 3. The moved bodies that change cells, or turn large: the grid's buckets (serial: each
  //    bucket's order is the calls' own, whatever the threads).
  large_.clear();
  for (size_t g = 0; g < regrid_.size(); ++g) {
    if (g + kQueryAhead < regrid_.size()) {
      const Regrid& ahead = regrid_[g + kQueryAhead];
      if (ahead.was_in) prefetch_cells(ahead.from);
      prefetch_cells(ahead.to);
    }
    const Regrid& q = regrid_[g];
    if (q.was_in) remove(q.id, q.from);
    if (q.to.i1 < q.to.i0) {  // large
      state_[q.id] = kLarge;
      large_.push_back(q.slot);
      continue;
    }
    fat_[q.id] = q.fat, range_[q.id] = q.to, state_[q.id] = kIn;
    insert(q.id, q.to);
  }
  live_ = n;  // every listed body is in the grid or large; the gone ones are out
  if (large_.size() > std::max(kRebuildLarge, n / 8)) rebuild_ = true;  // the cell no longer fits: next call
  // fn(p0, p1, to) over [0, count) in ranges on the pool, each into its own list, appended to
  // `out` in range order (the serial order); one range writes to `out` directly.
  auto gather = [&](size_t count, size_t grain, std::vector<std::pair<uint32_t, uint32_t>>& out, auto&& fn) {
    const int k = jobs ? jobs->chunks(count, grain, 4) : 1;
    if (k <= 1) return fn(size_t{0}, count, out);
    if (chunk_pairs_.size() < static_cast<size_t>(k)) chunk_pairs_.resize(k);
    core::run_chunks(jobs, count, grain, [&](int c, size_t p0, size_t p1) {
      chunk_pairs_[c].clear();
      fn(p0, p1, chunk_pairs_[c]);
    }, 4);
    for (int c = 0; c < k; ++c) out.insert(out.end(), chunk_pairs_[c].begin(), chunk_pairs_[c].end());
  };
  // 4. Kept pairs: those of two bodies that stayed (per range, concatenated in range order: the
  //    serial order); then the moved bodies' pairs, from the grid. When no body moved or went (a
  //    crowd rocking within its fat boxes, a parked convoy), every kept pair stays as it is.
  auto stayed = [&](const std::pair<uint32_t, uint32_t>& p) { return gone_moved_[p.first] != tick_ && gone_moved_[p.second] != tick_; };
  auto prefetch_stayed = [&](const std::pair<uint32_t, uint32_t>& p) {
    core::prefetch(&gone_moved_[p.first]), core::prefetch(&gone_moved_[p.second]);
  };
  const bool all_stayed = moved_.empty() && ids_n == 0;  // (ids_n == 0: none went, step 2)
  const int kk = jobs ? jobs->chunks(kept_.size(), kKeptGrain, 4) : 1;
  if (all_stayed) {
    // nothing to drop
  } else if (kk <= 1) {
    size_t to = 0;
    for (size_t p = 0; p < kept_.size(); ++p) {
      if (p + kKeptAhead < kept_.size()) prefetch_stayed(kept_[p + kKeptAhead]);
      if (stayed(kept_[p])) kept_[to++] = kept_[p];
    }
    kept_.resize(to);
  } else {
    if (chunk_pairs_.size() < static_cast<size_t>(kk)) chunk_pairs_.resize(kk);
    core::run_chunks(jobs, kept_.size(), kKeptGrain, [&](int c, size_t p0, size_t p1) {
      auto& to = chunk_pairs_[c];
      to.clear();
      for (size_t p = p0; p < p1; ++p) {
        if (p + kKeptAhead < p1) prefetch_stayed(kept_[p + kKeptAhead]);
        if (stayed(kept_[p])) to.push_back(kept_[p]);
      }
    }, 4);
    kept_.clear();
    for (int c = 0; c < kk; ++c) kept_.insert(kept_.end(), chunk_pairs_[c].begin(), chunk_pairs_[c].end());
  }
  gather(moved_.size(), kQueryGrain, kept_, [&](size_t m0, size_t m1, auto& to) {
    for (size_t m = m0; m < m1; ++m) {
      if (m + kQueryAhead < m1) prefetch_cells(moved_[m + kQueryAhead].cells);
      if (moved_[m].cells.i1 >= moved_[m].cells.i0) query(moved_[m], to);  // (not a large one)
    }
  });
  // 5. This tick's pairs: the kept ones whose boxes overlap (per range, concatenated in range
  //    order); the large bodies against every box.
  gather(kept_.size(), kKeptGrain, out, [&](size_t p0, size_t p1, auto& to) {
    // Every pair is written and only those that overlap kept (no branch on the test: about half
    // the kept pairs overlap in a crowd, a branch the predictor would miss).
    size_t n = to.size();
    to.resize(n + (p1 - p0));
    const std::pair<uint32_t, uint32_t>* kept = kept_.data();
    const uint32_t* slot = slot_.data();
    for (size_t p = p0; p < p1; ++p) {
      core::prefetch_write(&to[std::min(n + kKeptAhead, to.size() - 1)]);  // (read by the other thread last tick)
      if (p + kKeptAhead < p1) core::prefetch(&slot[kept[p + kKeptAhead].first]), core::prefetch(&slot[kept[p + kKeptAhead].second]);
      if (p + kKeptAhead / 2 < p1)
        for (const uint32_t id : {kept[p + kKeptAhead / 2].first, kept[p + kKeptAhead / 2].second})
          core::prefetch_object(&boxes[slot[id]]);  // a box may span two lines
      const uint32_t i = slot[kept[p].first], j = slot[kept[p].second];
      to[n] = {std::min(i, j), std::max(i, j)};
      n += overlap_branchless(boxes[i], boxes[j]);
    }
    to.resize(n);
  });
  large_pairs(boxes, large_, [&](uint32_t j) { return state_[ids[j]] == kLarge; }, out, chunk_pairs_, jobs);
}

}  // namespace npsnet::collision
