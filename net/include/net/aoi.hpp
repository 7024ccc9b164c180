// net/aoi.hpp — area of interest (NPSNET-IV): square cells of the local frame, each cell a
// multicast group, and the set of groups a node holds (joins and leaves with hysteresis).
// Contract:
//  * Cells: the local frame (metres, x east, y north) cut into squares of cell_m metres;
//    cell (i, j) = (floor(x / cell_m), floor(y / cell_m)); non-finite input is cell (0, 0).
//  * Groups (the documented formula): side M = floor(sqrt(max_groups)), at least 1; cell (i, j)
//    has group index k = (i mod M) + M * (j mod M) (mod taken non-negative) and group address
//    base + k (IPv4 as a 32-bit number), all on the exercise's port. The M x M groups tile the
//    world: two cells share a group only when they lie a multiple of M cells apart on both
//    axes, so an area of interest narrower than M cells never hears a cell it did not ask for,
//    and a world of at most M x M cells has one group per cell. base and base + M*M - 1 must
//    both lie in 239.0.0.0/8 (administratively scoped); at most 65536 groups.
//  * all_groups(): every group address of the grid, for a recorder that must hear them all.
//  * AoiMembership: each update, want(x, y, r) for every vehicle (r = its sensor range plus a
//    margin, metres); a group is joined when one of its cells lies within r of a vehicle
//    (distance from the point to the cell's square) and left only when none of its cells lies
//    within r + hysteresis_m of any vehicle, so a vehicle going back and forth across a border
//    does not make the node join and leave every tick.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "net/result.hpp"

namespace net {

inline constexpr int kAoiMaxGroupsLimit = 65536;
inline constexpr int kAoiDefaultMaxGroups = 1024;  // M = 32: 64 km of 2 km cells without aliasing

struct CellIndex {
  std::int64_t i = 0, j = 0;
  bool operator==(const CellIndex&) const = default;
};

class AoiGrid {
 public:
  // base_group: dotted IPv4 in 239.0.0.0/8; cell_m > 0 (finite); max_groups 1..65536.
  static Result<AoiGrid, std::string> make(std::string_view base_group, double cell_m, int max_groups);

  double cell_m() const noexcept { return cell_m_; }
  int side() const noexcept { return side_; }
  std::uint32_t group_count() const noexcept { return static_cast<std::uint32_t>(side_) * side_; }
  std::uint32_t base() const noexcept { return base_; }

  CellIndex cell_of(double x, double y) const noexcept { return {coord(x), coord(y)}; }
  std::uint32_t group_of(CellIndex c) const noexcept {
    return static_cast<std::uint32_t>(wrap(c.i) + side_ * wrap(c.j));
  }
  std::uint32_t group_of(double x, double y) const noexcept { return group_of(cell_of(x, y)); }
  // IPv4 address (host order) of group index k < group_count().
  std::uint32_t address(std::uint32_t k) const noexcept { return base_ + k; }
  std::string address_text(std::uint32_t k) const;
  std::vector<std::string> all_groups() const;

  // Calls f(k) for each cell whose square lies within r metres of (x, y) (a group index may come
  // more than once when the disc is wider than M cells).
  template <class F>
  void for_each_group_near(double x, double y, double r, F&& f) const {
    if (!std::isfinite(x) || !std::isfinite(y) || !(r >= 0) || !std::isfinite(r)) {
      f(group_of(x, y));
      return;
    }
    const CellIndex lo = cell_of(x - r, y - r), hi = cell_of(x + r, y + r);
    // A disc wider than the tiling covers every group: no need to walk each cell.
    if (hi.i - lo.i >= 2 * side_ + 2 && hi.j - lo.j >= 2 * side_ + 2) {
      for (std::uint32_t k = 0; k < group_count(); ++k) f(k);
      return;
    }
    const double r2 = r * r;
    for (std::int64_t j = lo.j; j <= hi.j; ++j) {
      const double y0 = static_cast<double>(j) * cell_m_, y1 = y0 + cell_m_;
      const double dy = y < y0 ? y0 - y : (y > y1 ? y - y1 : 0.0);
      for (std::int64_t i = lo.i; i <= hi.i; ++i) {
        const double x0 = static_cast<double>(i) * cell_m_, x1 = x0 + cell_m_;
        const double dx = x < x0 ? x0 - x : (x > x1 ? x - x1 : 0.0);
        if (dx * dx + dy * dy <= r2) f(group_of(CellIndex{i, j}));
      }
    }
  }

 private:
  std::int64_t coord(double v) const noexcept {
    if (!std::isfinite(v)) return 0;
    const double c = std::floor(v / cell_m_);
    return static_cast<std::int64_t>(std::fmax(-1e15, std::fmin(1e15, c)));
  }
  std::int64_t wrap(std::int64_t v) const noexcept {
    const std::int64_t m = v % side_;
    return m < 0 ? m + side_ : m;
  }
  double cell_m_ = 1000.0;
  int side_ = 1;
  std::uint32_t base_ = 0;
};

// Every group of the grid from --net's group and --aoi-groups, as dotted text (for a recorder).
Result<std::vector<std::string>, std::string> aoi_all_groups(std::string_view base_group, int max_groups);

class AoiMembership {
 public:
  AoiMembership(const AoiGrid& grid, double hysteresis_m);

  void begin();                                   // starts an update: nothing wanted
  void want(double x, double y, double radius_m);  // a vehicle's area of interest
  // Ends the update: join(k) -> bool for each group newly wanted (held when it returns true),
  // leave(k) for each held group no longer kept. Groups are visited in index order.
  template <class Join, class Leave>
  void end(Join&& join, Leave&& leave) {
    for (std::uint32_t k = 0; k < held_.size(); ++k) {
      if (!held_[k] && inner_[k]) {
        if (join(k)) held_[k] = 1, ++count_;
      } else if (held_[k] && !outer_[k]) {
        leave(k);
        held_[k] = 0, --count_;
      }
    }
  }
  bool held(std::uint32_t k) const noexcept { return k < held_.size() && held_[k]; }
  std::size_t held_count() const noexcept { return count_; }
  double hysteresis_m() const noexcept { return hysteresis_m_; }
  const AoiGrid& grid() const noexcept { return grid_; }

 private:
  AoiGrid grid_;
  double hysteresis_m_;
  std::vector<std::uint8_t> inner_, outer_, held_;
  std::size_t count_ = 0;
};

}  // namespace net
