// Broad phases for the continuous method (and the speed benchmark), on plain arrays.
//  MovingGrid: all pairs i < j of overlapping boxes among N moving bodies. A hashed 2D grid
//    whose cell is 3x the largest extent among the ordinary boxes (boxes more than 4x the
//    mean extent are "large" and tested against every box), so a box lies in at most 2 x 2
//    cells; each box is listed in the cells it overlaps, counting-sorted by hash bucket into one
//    contiguous array; then every bucket's entries are tested pairwise, a pair reported only in
//    the first cell the two boxes share (and only between entries of the same cell when two
//    cells share a bucket). Rebuilt every call into reused buffers (no allocation once warm).
//    Linear in N for bounded density, also where bodies crowd (the cell shrinks to the bodies).
//  FixedGrid: static spheres in a uniform grid (125 m gridsquares), each listed in every
//    gridsquare its circle overlaps (removes the thesis's Figure 9 border miss); a query lists
//    each object once over every gridsquare a box overlaps.
//  brute_pairs: the plain O(N^2) reference the tests compare MovingGrid with.
// Units: metres, local frame; boxes in float (a 50 km map keeps ~4 mm resolution).
#pragma once
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/math.hpp"

namespace npsnet::collision {

struct Box {
  float lo[3], hi[3];
};
inline bool overlap(const Box& a, const Box& b) {
  return a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] && a.lo[1] <= b.hi[1] && b.lo[1] <= a.hi[1] &&
         a.lo[2] <= b.hi[2] && b.lo[2] <= a.hi[2];
}
// The box of a sphere of radius r swept from c0 to c1.
inline Box swept_box(const Vec3& c0, const Vec3& c1, double r) {
  Box b;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = static_cast<float>((c0[k] < c1[k] ? c0[k] : c1[k]) - r);
    b.hi[k] = static_cast<float>((c0[k] < c1[k] ? c1[k] : c0[k]) + r);
  }
  return b;
}

class MovingGrid {
 public:
  // Appends to `out` (cleared first) every pair (i, j), i < j, whose boxes overlap, each once,
  // in an order that depends only on the input.
  void pairs(const std::vector<Box>& boxes, std::vector<std::pair<uint32_t, uint32_t>>& out);
  double cell_m() const { return cell_; }

 private:
  struct Entry {      // 28 bytes: the x, y extent; z and the first cell only for candidates
    float lox, loy, hix, hiy;
    int32_t cx, cy;  // this entry's cell
    uint32_t id;
  };
  double cell_ = 1;
  std::vector<uint32_t> start_;       // CSR over hash buckets
  std::vector<uint32_t> bucket_;      // per (box, cell) listing: its bucket, in insertion order
  std::vector<Entry> entries_;        // by bucket
  std::vector<uint32_t> large_;
  std::vector<uint8_t> is_large_;
};

void brute_pairs(const std::vector<Box>& boxes, std::vector<std::pair<uint32_t, uint32_t>>& out);

class FixedGrid {
 public:
  // Spheres (centre, radius) in a width x depth map from (0, 0), gridsquares of `cell_m`.
  void build(const std::vector<Vec3>& centres, const std::vector<float>& radii, double width_m,
             double depth_m, double cell_m);
  size_t size() const { return x_.size(); }
  // Calls f(id) once for every object whose circle's bounding square overlaps the box in x, y
  // (it still needs the sphere test); the object may lie in several of the box's gridsquares.
  template <class F>
  void query(const Box& b, F&& f) const {
    const int i0 = col(b.lo[0]), i1 = col(b.hi[0]), j0 = row(b.lo[1]), j1 = row(b.hi[1]);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const size_t c = static_cast<size_t>(j) * cols_ + i;
        if (!(occupied_[c >> 6] >> (c & 63) & 1)) continue;  // most gridsquares are empty
        for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
          const Item& it = items_[k];
          if (it.x + it.r < b.lo[0] || it.x - it.r > b.hi[0] || it.y + it.r < b.lo[1] || it.y - it.r > b.hi[1])
            continue;
          // Report in the first gridsquare the box and the object's circle share.
          if ((i != i0 && col(it.x - it.r) != i) || (j != j0 && row(it.y - it.r) != j)) continue;
          f(it.id, it);
        }
      }
  }
  struct Item {
    float x, y, z, r;
    uint32_t id;
  };
  // Gridsquare column / row of a coordinate, clamped to the map (truncation equals floor for
  // x >= 0, and every x < 0 clamps to 0 either way).
  int col(double x) const { return clampi(static_cast<int>(std::min(x * inv_, 1e9)), cols_); }
  int row(double y) const { return clampi(static_cast<int>(std::min(y * inv_, 1e9)), rows_); }

 private:
  static int clampi(int v, int n) { return v < 0 ? 0 : v >= n ? n - 1 : v; }
  int cols_ = 1, rows_ = 1;
  double cell_ = 125, inv_ = 1.0 / 125;
  std::vector<float> x_;
  std::vector<uint32_t> start_;
  std::vector<uint64_t> occupied_;  // bit per gridsquare: lists something
  std::vector<Item> items_;
};

}  // namespace npsnet::collision
