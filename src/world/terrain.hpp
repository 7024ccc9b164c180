// Terrain heightfield in the local frame (x east, y north, z up, metres; origin at the SW corner).
// Loaded from any GDAL raster. A raster with a coordinate system is resampled into a transverse
// Mercator frame centred on the terrain; one without (a bare .asc) is taken as local metres with
// its lower-left corner at `origin`. Heights are bilinear between posts; outside the map the
// nearest edge post is used. Craters lower the posts inside their radius (the only mutation).
#pragma once
#include <algorithm>
#include <filesystem>
#include <vector>

#include "core/geodesy.hpp"
#include "core/math.hpp"
#include "core/prefetch.hpp"

namespace npsnet::world {

// Rectangle of posts [i0, i1] x [j0, j1] (inclusive; i = column/x, j = row/y) changed by an edit.
struct PostRect {
  int i0 = 0, j0 = 0, i1 = -1, j1 = -1;
  bool empty() const { return i1 < i0 || j1 < j0; }
};

class Terrain {
 public:
  Terrain() = default;
  // Posts in row-major order, row 0 = south edge; spacing in metres; SW corner geodetic.
  Terrain(int cols, int rows, double spacing_m, std::vector<float> heights,
          const geo::Geodetic& origin);
  // Throws InputError (file:0: terrain: message) on a missing or unreadable raster.
  // `origin` is used only when the raster has no coordinate system.
  static Terrain load(const std::filesystem::path& file, const geo::Geodetic& origin);

  double height(double x, double y) const {  // bilinear (inline: the hottest call of a tick)
    const double u = std::clamp(x / spacing_, 0.0, static_cast<double>(cols_ - 1));
    const double v = std::clamp(y / spacing_, 0.0, static_cast<double>(rows_ - 1));
    const int i = std::min(static_cast<int>(u), cols_ - 2);
    const int j = std::min(static_cast<int>(v), rows_ - 2);
    const double fx = u - i, fy = v - j;
    const double h00 = post(i, j), h10 = post(i + 1, j), h01 = post(i, j + 1), h11 = post(i + 1, j + 1);
    return (h00 * (1 - fx) + h10 * fx) * (1 - fy) + (h01 * (1 - fx) + h11 * fx) * fy;
  }
  // height() of four points at once (a vehicle's corners), bit for bit: the same operations in
  // the same order on each lane, the eight divisions by the spacing as two vector divisions (the
  // divider, not the loads, bounded terrain following: perf, 500 vehicles).
  void heights4(const double (&x)[4], const double (&y)[4], double (&h)[4]) const {
    using D4 = double __attribute__((vector_size(32)));
    using I4 = int __attribute__((vector_size(16)));
    const D4 s = {spacing_, spacing_, spacing_, spacing_};
    D4 u = D4{x[0], x[1], x[2], x[3]} / s, v = D4{y[0], y[1], y[2], y[3]} / s;
    const double ui = cols_ - 1, vj = rows_ - 1;
    // std::clamp(u, 0, ui): u < 0 ? 0 : ui < u ? ui : u, lane by lane
    u = u < 0.0 ? D4{} : u, u = ui < u ? D4{ui, ui, ui, ui} : u;
    v = v < 0.0 ? D4{} : v, v = vj < v ? D4{vj, vj, vj, vj} : v;
    I4 i = __builtin_convertvector(u, I4), j = __builtin_convertvector(v, I4);
    i = i > cols_ - 2 ? I4{} + (cols_ - 2) : i, j = j > rows_ - 2 ? I4{} + (rows_ - 2) : j;
    const D4 fx = u - __builtin_convertvector(i, D4), fy = v - __builtin_convertvector(j, D4);
    D4 h00, h10, h01, h11;
    for (int k = 0; k < 4; ++k) {
      const float* p = h_.data() + (static_cast<size_t>(j[k]) * cols_ + i[k]);
      h00[k] = p[0], h10[k] = p[1], h01[k] = p[cols_], h11[k] = p[cols_ + 1];
    }
    const D4 r = (h00 * (1 - fx) + h10 * fx) * (1 - fy) + (h01 * (1 - fx) + h11 * fx) * fy;
    for (int k = 0; k < 4; ++k) h[k] = r[k];
  }
  // True only when height(x, y) > level for certain (World::is_water asks it first: most of a
  // map is well above its water, and height() is two divisions and four posts). kBlock x kBlock
  // cells share one bound: the lowest post of their cells and of the cells around them, less a
  // billionth of the largest |post| there (the bilinear sum's rounding is below 1e-15 of it), so
  // that the cell this finds by the spacing's reciprocal, at most one off the cell height()
  // divides out, is covered (off the map: its edge cell, as height()). False when unsure (x or y
  // not finite, or the level near).
  bool surely_above(double x, double y, double level) const {
    if (!(std::isfinite(x) && std::isfinite(y)) || block_lo_.empty()) return false;
    long i, j;
    near_cell(x, y, i, j);
    return block_lo_[static_cast<size_t>((j / kBlock) * block_cols_ + i / kBlock)] > level;
  }
  static constexpr int kBlock = 8;  // cells a side that share surely_above's bound
  // Asks the cache for the two rows of posts height(x, y) reads (core/prefetch.hpp): a hint that
  // changes no result, for a loop over entities scattered over the map to call a few entities
  // ahead (at 100,000 vehicles the first height() of each otherwise waits on memory; the 50 km
  // map's posts are 2.5 MB). Any x, y: NaN and infinities clamp like the map's edges.
  // (A hint: the spacing's reciprocal, not a division; a post off by one is still a hint.)
  void prefetch(double x, double y) const {
    long i, j;
    near_cell(x, y, i, j);
    const float* p = h_.data() + (j * cols_ + i);
    core::prefetch(p);
    core::prefetch(p + cols_);
  }
  Vec3 normal(double x, double y) const;     // unit, from the bilinear surface's gradient
  bool contains(double x, double y) const {
    return x >= 0 && y >= 0 && x <= width_m() && y <= depth_m();
  }
  // Lower the ground by a bowl of `radius_m` and `depth_m` at (cx, cy); returns the posts changed.
  PostRect crater(double cx, double cy, double radius_m, double depth_m);

  int cols() const { return cols_; }
  int rows() const { return rows_; }
  double spacing_m() const { return spacing_; }
  double width_m() const { return (cols_ - 1) * spacing_; }
  double depth_m() const { return (rows_ - 1) * spacing_; }
  float post(int i, int j) const { return h_[static_cast<size_t>(j) * cols_ + i]; }
  const std::vector<float>& posts() const { return h_; }
  const geo::LocalFrame& frame() const { return frame_; }
  const geo::Geodetic& origin() const { return origin_; }

 private:
  int cols_ = 0, rows_ = 0;
  double spacing_ = 1, inv_spacing_ = 1;  // (inv_spacing_: prefetch's and surely_above's only)
  std::vector<float> h_;
  // surely_above's bound of each block of kBlock x kBlock cells (row-major, block_cols_ a row);
  // made by the constructor, kept by crater() for the blocks whose posts it lowered.
  long block_cols_ = 0;
  std::vector<double> block_lo_;
  void bound_blocks(long bi0, long bj0, long bi1, long bj1);
  // The cell (i, j) of (x, y) by the spacing's reciprocal, clamped to the map (NaN: 0): the cell
  // height() divides out, or one beside it (prefetch's and surely_above's).
  void near_cell(double x, double y, long& i, long& j) const {
    const double u = x * inv_spacing_, v = y * inv_spacing_, ui = cols_ - 2, vj = rows_ - 2;
    i = static_cast<long>(u > 0 ? (u < ui ? u : ui) : 0);  // NaN: 0
    j = static_cast<long>(v > 0 ? (v < vj ? v : vj) : 0);
  }
  geo::Geodetic origin_;
  geo::LocalFrame frame_;
};

}  // namespace npsnet::world
