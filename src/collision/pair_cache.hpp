// Persistent broad phase of the moving bodies for the continuous method (issue 13): the same
// pairs as MovingGrid (broadphase.hpp), from work kept across ticks, as Box2D's dynamic tree
// keeps "fat" boxes and the pairs between them.
//
// Contract:
//  * pairs(boxes, ids, id_count, out, jobs): boxes[i] is this tick's box of body ids[i] (ids
//    unique, each < id_count; a body keeps its id from tick to tick). Appends to `out` (cleared
//    first) every (i, j), i < j, whose boxes overlap (collision::overlap, z included), each once:
//    the set MovingGrid::pairs gives for the same boxes. The order depends only on the inputs of
//    this call and the earlier ones, never on the thread count (the detector sorts its results).
//  * How: each body keeps a fat box, its x-y box grown by a margin, listed in the cells of a
//    hashed grid. The margin: kMarginOfExtent of the box's larger extent all round; given each
//    body's travel this tick (`travel`, m: the detector's sweep, end less start), kTravelTicks
//    of that travel ahead (at most kAheadOfExtent of the extent) and kMarginMinOfExtent all
//    round. A body going straight then keeps its fat box about kTravelTicks ticks (ahead_ticks:
//    a few more or fewer by a hash, so that bodies set off together do not renew together), a
//    slow one in a crowd keeps a thin one (fewer pairs kept that do not overlap). The grid's
//    cell is sized by the margin all round, whatever the travel. A body whose box leaves its fat box (or that is
//    new, or gone) "moves": its fat box is made again and its pairs found again, from the grid;
//    the others keep theirs. The kept pairs are those whose fat boxes overlap; a tick reports the
//    ones whose boxes overlap (when no body moved or went, the kept pairs are not walked to drop
//    any). A moved body that stays in the same cells touches no bucket. At 100,000 vehicles
//    driving (bench_tick_scaling, 0.1 s ticks), about a tenth move a tick by travel (a sixth by
//    the extent alone).
//  * Bodies whose fat box would span more than kMaxCellsPerAxis cells a side (a round in flight),
//    or is not finite, are "large": tested against every box each tick, as MovingGrid does its
//    large boxes.
//  * The grid's cell is twice the largest fat extent among the ordinary bodies (at most 4x the
//    mean) when it is built: on the first call, and again when bodies many times larger than
//    that cell came (more than max(kRebuildLarge, N / 8) large), or the bodies grew 4x in number.
//    A bucket is one cache line (kInline entries in place, more in its overflow list).
//  * Threading: the containment test (with the new fat box of a body that keeps its cells), the
//    gone bodies (looked for only when the count says some went) and the moved bodies' grid
//    queries, and the kept pairs' two passes (those of bodies that stayed; those whose boxes
//    overlap), run per range on the pool, each range into its own list, concatenated in range
//    order; the buckets' updates are serial, in body order. No allocation once warm (lists and
//    overflows keep their capacity).
// Units: metres, local frame (float boxes, as MovingGrid).
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "collision/broadphase.hpp"
#include "core/jobs.hpp"

namespace npsnet::collision {

class PairCache {
 public:
  // A fat box's margins, fractions of its box's larger extent (above), and ticks of travel.
  static constexpr float kMarginOfExtent = 0.5f, kMarginMinOfExtent = 0.125f, kAheadOfExtent = 2.0f;
  // Ticks of travel ahead: kTravelTicks, times 1 -/+ kAheadJitter by a hash of the body and the
  // call (ahead_ticks): bodies that set off together would otherwise renew their fat boxes
  // together every kTravelTicks ticks, whatever their speeds.
  static constexpr float kTravelTicks = 8.0f, kAheadJitter = 0.25f;
  struct Travel {  // a body's x-y travel over this tick (m)
    float x, y;
  };
  static constexpr int kMaxCellsPerAxis = 4;
  static constexpr size_t kRebuildLarge = 64;

  void pairs(const std::vector<Box>& boxes, const std::vector<uint32_t>& ids, size_t id_count,
             std::vector<std::pair<uint32_t, uint32_t>>& out, core::Jobs* jobs = nullptr,
             const std::vector<Travel>* travel = nullptr);
  // The last call's bodies that moved (fat box made again, large ones included); grid builds.
  size_t moved() const { return moved_.size(); }
  size_t kept_pairs() const { return kept_.size(); }  // pairs whose fat boxes overlap (large bodies' aside)
  size_t builds() const { return builds_; }

 private:
  struct Fat {
    float lox, loy, hix, hiy;
  };
  struct Entry {  // one cell of a body's fat box, in that cell's bucket
    uint32_t id;
    int32_t cx, cy;
  };
  // A bucket of the grid: one cache line, its first kInline entries in place, the rest in its
  // overflow list (a crowded cell).
  static constexpr int kInline = 5;
  struct alignas(64) Bucket {
    uint32_t n = 0;  // entries in all
    Entry e[kInline];
  };
  struct Range {
    int32_t i0, j0, i1, j1;
  };
  struct Moved {  // a body whose fat box was made again this call: it, in cells (empty: large)
    uint32_t id;
    Fat fat;
    Range cells;
  };
  struct Regrid {  // a moved body that changes cells or turns large (to: empty)
    uint32_t slot, id;
    bool was_in;  // listed in the grid, in cells `from`
    Fat fat;
    Range to, from;
  };
  enum State : uint8_t { kOut = 0, kIn = 1, kLarge = 2 };

  Fat fat_of(const Box& b, const Travel* travel, uint32_t id) const;  // (travel null: kMarginOfExtent all round)
  float ahead_ticks(uint32_t id) const;  // body id's ticks ahead in this call
  Range cells_of(const Fat& f) const;
  uint32_t bucket_of(int32_t x, int32_t y) const;
  bool ordinary(const Fat& f) const;
  void prefetch_cells(const Range& r) const;  // a hint: the buckets of cells r  // finite, and in at most kMaxCellsPerAxis^2 cells (else large)
  void build(const std::vector<Box>& boxes);
  void remove(uint32_t id, const Range& listed);  // from the buckets of its cells
  void remove_entry(uint32_t h, const Entry& e);
  void insert(uint32_t id, const Range& cells);
  // fn(entry) for each entry of bucket h.
  template <class F>
  void each(uint32_t h, F&& fn) const;
  // Pairs of moved body m with the grid's bodies (first found in their first shared cell), into `to`.
  void query(const Moved& m, std::vector<std::pair<uint32_t, uint32_t>>& to) const;

  double cell_ = 0, inv_ = 0;
  uint32_t mask_ = 0;
  size_t built_for_ = 0;  // bodies when the grid was built
  size_t builds_ = 0;
  uint32_t tick_ = 0;
  std::vector<Bucket> buckets_;
  std::vector<std::vector<Entry>> overflow_;  // per bucket: its entries past kInline
  bool rebuild_ = false;  // too many large bodies for the cell: built again on the next call
  std::vector<Fat> fat_;         // per id
  std::vector<Range> range_;     // per id: the cells its fat box is listed in
  std::vector<uint8_t> state_;   // per id
  size_t live_ = 0;              // ids not kOut (listed by the last call)
  std::vector<uint32_t> seen_;   // per id: the last call that listed it, of those that looked for gone ids
  std::vector<uint32_t> gone_moved_;  // per id: the last call in which it moved or went
  std::vector<uint32_t> slot_;   // per id: its index in this call's boxes
  std::vector<Moved> moved_;     // this call's moved bodies, in slot order
  std::vector<Regrid> regrid_;   // of those, the ones that change cells or turn large
  std::vector<uint32_t> large_;  // this call's large bodies (slots), ascending
  std::vector<std::pair<uint32_t, uint32_t>> kept_;  // id pairs whose fat boxes overlap
  std::vector<std::vector<uint32_t>> chunk_ids_;     // per range: gone bodies
  std::vector<std::vector<Moved>> chunk_moved_;      // per range: moved bodies
  std::vector<size_t> chunk_new_;                    // per range: bodies not listed before
  std::vector<std::vector<Regrid>> chunk_regrid_;    // per range: moved bodies that change cells
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> chunk_pairs_;  // per range
};

}  // namespace npsnet::collision
