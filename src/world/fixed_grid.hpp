// The one index of fixed objects, built once per world (World::index_fixed) and used by every
// room that looks objects up by place: the thesis's per-gridsquare lists (collision, thesis
// method, p. 8-10), blasts and craters (collision::detonate, world::apply), the continuous broad
// phase and the renderer's culling blocks.
// Thesis p. 8-9: 125 m gridsquares, a list per gridsquare. Layout: CSR, the objects of gridsquare c
// are items[start[c] .. start[c+1]), ascending by object index. Each object is listed in every
// gridsquare its reach circle (centre = its base position, radius = reach_m) overlaps, so a box
// query never misses an object across a border (the thesis's Figure 9 miss); it also keeps its
// home gridsquare (the one holding its base position), which the thesis's lists are made of.
// FixedBrute answers the same queries by looking at every object: the reference the grid is
// tested against on random scenes (as Jolt keeps BroadPhaseBruteForce beside its quadtree).
// Units: metres, local frame. Gridsquare column / row: floor(x / cell_m), clamped to the map.
// Threading: built before the run; queries are const and may run on any number of threads.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/math.hpp"

namespace npsnet::world {

struct GridItem {
  float x, y, r;    // base position and reach (m)
  uint32_t id;      // object index
  int32_t home;     // home gridsquare
};

// Gridsquare arithmetic shared by the grid and its brute-force twin.
class Gridsquares {
 public:
  void set(double width_m, double depth_m, double cell_m);
  int cols() const { return cols_; }
  int rows() const { return rows_; }
  double cell_m() const { return cell_; }
  // (truncation, not floor: the two differ only below 0, which clamps to 0 either way)
  int col(double x) const { return std::clamp(static_cast<int>(x / cell_), 0, cols_ - 1); }
  int row(double y) const { return std::clamp(static_cast<int>(y / cell_), 0, rows_ - 1); }
  int cell_of(double x, double y) const { return row(y) * cols_ + col(x); }
  // Whether the item's reach square overlaps the box [lo, hi] (the box queries' test).
  static bool overlaps(const GridItem& it, float lox, float loy, float hix, float hiy) {
    return !(it.x + it.r < lox || it.x - it.r > hix || it.y + it.r < loy || it.y - it.r > hiy);
  }

 protected:
  int cols_ = 0, rows_ = 0;
  double cell_ = 125;
};

class FixedGrid : public Gridsquares {
 public:
  // Objects at base positions `pos` with reach `reach_m` (m), in a width x depth map from (0, 0).
  // A grid never built answers every query with nothing.
  void build(const std::vector<Vec3>& pos, const std::vector<float>& reach_m, double width_m, double depth_m,
             double cell_m);
  size_t size() const { return objects_; }
  // Invariant: offsets ascend, every listing names an object, each object is listed in exactly
  // the gridsquares its reach overlaps, in ascending order within each, with its home.
  bool valid(const std::vector<Vec3>& pos, const std::vector<float>& reach_m) const;

  // f(object) for the objects whose home is gridsquare `cell`, ascending (the thesis's list).
  template <class F>
  void for_each_home(int cell, F&& f) const {
    if (start_.empty()) return;  // never built: lists nothing
    for (uint32_t k = start_[cell]; k < start_[cell + 1]; ++k)
      if (items_[k].home == cell) f(static_cast<int>(items_[k].id));
  }
  // f(object) for the objects whose home lies in a gridsquare that the square
  // [x - r, x + r] x [y - r, y + r] overlaps: gridsquares row by row, ascending within each.
  template <class F>
  void for_each_near(double x, double y, double r, F&& f) const {
    if (start_.empty()) return;  // never built
    const int i0 = col(x - r), i1 = col(x + r), j0 = row(y - r), j1 = row(y + r);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) for_each_home(j * cols_ + i, f);
  }
  // f(object, reach) once for every object whose reach square overlaps the box [lo, hi] in x, y.
  template <class F>
  void query(float lox, float loy, float hix, float hiy, F&& f) const {
    query_listed(lox, loy, hix, hiy, [&](uint32_t, const GridItem& it) { f(static_cast<int>(it.id), it.r); });
  }
  // The same objects as listings: f(k, listing(k)), k a listing's place (stable until the grid
  // is built again: generation()). A caller that keeps the listings a larger box gave may answer
  // a box inside it with them and `overlaps` (collision: the fixed objects near a vehicle).
  template <class F>
  void query_listed(float lox, float loy, float hix, float hiy, F&& f) const {
    if (occupied_.empty()) return;  // never built: lists nothing
    const int i0 = col(lox), i1 = col(hix), j0 = row(loy), j1 = row(hiy);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const size_t c = static_cast<size_t>(j) * cols_ + i;
        if (!(occupied_[c >> 6] >> (c & 63) & 1)) continue;  // most gridsquares are empty
        for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
          const GridItem& it = items_[k];
          if (!overlaps(it, lox, loy, hix, hiy)) continue;
          // Reported in the first gridsquare the box and the object's reach share.
          if ((i != i0 && col(it.x - it.r) != i) || (j != j0 && row(it.y - it.r) != j)) continue;
          f(k, it);
        }
      }
  }
  const GridItem& listing(uint32_t k) const { return items_[k]; }
  // Distinct for every build of any grid in the process (a copy keeps its original's).
  uint64_t generation() const { return generation_; }

 private:
  size_t objects_ = 0;
  uint64_t generation_ = 0;
  std::vector<uint32_t> start_;
  std::vector<uint64_t> occupied_;  // bit per gridsquare: lists something
  std::vector<GridItem> items_;
};

// The same queries over every object (no index): the reference for tests.
class FixedBrute : public Gridsquares {
 public:
  void build(const std::vector<Vec3>& pos, const std::vector<float>& reach_m, double width_m, double depth_m,
             double cell_m);
  size_t size() const { return items_.size(); }
  template <class F>
  void for_each_home(int cell, F&& f) const {
    for (const GridItem& it : items_)
      if (it.home == cell) f(static_cast<int>(it.id));
  }
  template <class F>
  void for_each_near(double x, double y, double r, F&& f) const {
    const int i0 = col(x - r), i1 = col(x + r), j0 = row(y - r), j1 = row(y + r);
    for (const GridItem& it : items_) {
      const int i = it.home % cols_, j = it.home / cols_;
      if (i >= i0 && i <= i1 && j >= j0 && j <= j1) f(static_cast<int>(it.id));
    }
  }
  template <class F>
  void query(float lox, float loy, float hix, float hiy, F&& f) const {
    for (const GridItem& it : items_)
      if (overlaps(it, lox, loy, hix, hiy)) f(static_cast<int>(it.id), it.r);
  }

 private:
  std::vector<GridItem> items_;
};

}  // namespace npsnet::world
