// The fixed-object grid and its brute-force twin (fixed_grid.hpp).
#include "world/fixed_grid.hpp"

#include <atomic>
#include <cassert>

namespace npsnet::world {

namespace {
GridItem item(const Gridsquares& g, const std::vector<Vec3>& pos, const std::vector<float>& reach_m, size_t k) {
  return {static_cast<float>(pos[k].x()), static_cast<float>(pos[k].y()), reach_m[k], static_cast<uint32_t>(k),
          g.cell_of(pos[k].x(), pos[k].y())};
}
// Calls f(gridsquare) for every gridsquare the item's reach square overlaps, row by row.
template <class F>
void each_cell(const Gridsquares& g, const GridItem& it, F&& f) {
  const int i0 = g.col(it.x - it.r), i1 = g.col(it.x + it.r), j0 = g.row(it.y - it.r), j1 = g.row(it.y + it.r);
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) f(static_cast<size_t>(j) * g.cols() + i);
}
}  // namespace

void Gridsquares::set(double width_m, double depth_m, double cell_m) {
  cell_ = cell_m;
  cols_ = std::max(1, static_cast<int>(std::ceil(width_m / cell_m)));
  rows_ = std::max(1, static_cast<int>(std::ceil(depth_m / cell_m)));
}

void FixedGrid::build(const std::vector<Vec3>& pos, const std::vector<float>& reach_m, double width_m, double depth_m,
                      double cell_m) {
  assert(pos.size() == reach_m.size());
  static std::atomic<uint64_t> builds{0};
  generation_ = ++builds;
  set(width_m, depth_m, cell_m);
  objects_ = pos.size();
  const size_t ncell = static_cast<size_t>(cols_) * rows_;
  start_.assign(ncell + 1, 0);
  for (size_t k = 0; k < pos.size(); ++k) each_cell(*this, item(*this, pos, reach_m, k), [&](size_t c) { ++start_[c + 1]; });
  for (size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  items_.resize(start_[ncell]);
  std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
  for (size_t k = 0; k < pos.size(); ++k) {
    const GridItem it = item(*this, pos, reach_m, k);
    each_cell(*this, it, [&](size_t c) { items_[fill[c]++] = it; });
  }
  occupied_.assign((ncell + 63) / 64, 0);
  for (size_t c = 0; c < ncell; ++c)
    if (start_[c + 1] > start_[c]) occupied_[c >> 6] |= uint64_t{1} << (c & 63);
}

bool FixedGrid::valid(const std::vector<Vec3>& pos, const std::vector<float>& reach_m) const {
  const size_t ncell = static_cast<size_t>(cols_) * rows_;
  if (objects_ != pos.size() || reach_m.size() != pos.size()) return false;
  if (start_.size() != ncell + 1 || start_[0] != 0 || start_[ncell] != items_.size()) return false;
  std::vector<uint32_t> listed(pos.size(), 0);
  for (size_t c = 0; c < ncell; ++c) {
    if (start_[c + 1] < start_[c]) return false;
    for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
      const GridItem& it = items_[k];
      if (it.id >= pos.size() || it.home != cell_of(pos[it.id].x(), pos[it.id].y())) return false;
      if (k > start_[c] && items_[k - 1].id >= it.id) return false;
      ++listed[it.id];
    }
  }
  for (size_t k = 0; k < pos.size(); ++k) {
    uint32_t want = 0;
    each_cell(*this, item(*this, pos, reach_m, k), [&](size_t) { ++want; });
    if (listed[k] != want) return false;
  }
  return true;
}

void FixedBrute::build(const std::vector<Vec3>& pos, const std::vector<float>& reach_m, double width_m, double depth_m,
                       double cell_m) {
  set(width_m, depth_m, cell_m);
  items_.clear();
  for (size_t k = 0; k < pos.size(); ++k) items_.push_back(item(*this, pos, reach_m, k));
}

}  // namespace npsnet::world
