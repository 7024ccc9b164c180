#include "world/world.hpp"

#include <algorithm>
#include <cmath>

namespace npsnet::world {

void FixedObjects::add(std::string id_, int kind_, const Vec3& p, float heading, float radius) {
  id.push_back(std::move(id_));
  kind.push_back(static_cast<int16_t>(kind_));
  state.push_back(0);
  pos.push_back(p);
  heading_deg.push_back(heading);
  radius_m.push_back(radius);
}

int Entities::add(std::string id_, int kind_, const Vec3& p, float heading, float radius) {
  id.push_back(std::move(id_));
  kind.push_back(static_cast<int16_t>(kind_));
  state.push_back(0);
  pos.push_back(p);
  vel.push_back(Vec3::Zero());
  heading_deg.push_back(heading);
  pitch_deg.push_back(0);
  roll_deg.push_back(0);
  radius_m.push_back(radius);
  cruise_mps.push_back(0);
  max_mps.push_back(0);
  active.push_back(1);
  local.push_back(1);
  snapshots.push_back(1);
  autonomous.push_back(0);
  target.push_back(-1);
  aim.push_back(p);
  owner.push_back(-1);
  rounds.push_back(0);
  fuel_l.push_back(0);
  node.push_back(1);
  route.emplace_back();
  leg.push_back(0);
  loop_route.push_back(0);
  flee_until.push_back(-1);
  calm_until.push_back(-1);
  driven.push_back(0);
  return static_cast<int>(id.size() - 1);
}

bool FixedObjects::valid() const {
  const size_t n = id.size();
  return kind.size() == n && state.size() == n && pos.size() == n && heading_deg.size() == n && radius_m.size() == n;
}

bool Entities::valid() const {
  const size_t n = id.size();
  for (size_t s : {kind.size(), state.size(), pos.size(), vel.size(), heading_deg.size(), pitch_deg.size(),
                   roll_deg.size(), radius_m.size(), cruise_mps.size(), max_mps.size(), active.size(), local.size(),
                   snapshots.size(), autonomous.size(), target.size(), aim.size(), owner.size(), rounds.size(),
                   fuel_l.size(), node.size(), route.size(), leg.size(), loop_route.size(), flee_until.size(),
                   calm_until.size()})
    if (s != n) return false;
  return true;
}

bool World::valid() const {
  if (!ents.valid() || !fixed.valid()) return false;
  const int ne = static_cast<int>(ents.size());
  auto kind_ok = [&](int k, int state) { return k >= 0 && k < kinds.size() && state < static_cast<int>(kinds[k].states.size()); };
  for (int e = 0; e < ne; ++e)
    if (!kind_ok(ents.kind[e], ents.state[e]) || ents.owner[e] < -1 || ents.owner[e] >= ne || ents.target[e] < -1 ||
        ents.target[e] >= ne)
      return false;
  for (size_t o = 0; o < fixed.size(); ++o)
    if (!kind_ok(fixed.kind[o], fixed.state[o])) return false;
  return grid.cols() == 0 || grid.valid(fixed);
}

bool GridIndex::valid(const FixedObjects& objs) const {
  const size_t ncell = static_cast<size_t>(cols_) * rows_;
  if (start_.size() != ncell + 1 || start_[0] != 0 || start_[ncell] != items_.size()) return false;
  std::vector<uint32_t> listed(objs.size(), 0);
  for (size_t c = 0; c < ncell; ++c) {
    if (start_[c + 1] < start_[c]) return false;
    for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
      if (items_[k] >= objs.size()) return false;
      ++listed[items_[k]];
    }
  }
  for (size_t o = 0; o < objs.size(); ++o) {
    const CellRect r = cells_of(objs.pos[o].x(), objs.pos[o].y(), home_only_ ? 0.0 : objs.radius_m[o]);
    if (listed[o] != static_cast<uint32_t>((r.i1 - r.i0 + 1) * (r.j1 - r.j0 + 1))) return false;
  }
  return true;
}

int GridIndex::cell_of(double x, double y) const {
  const int i = std::clamp(static_cast<int>(std::floor(x / cell_)), 0, cols_ - 1);
  const int j = std::clamp(static_cast<int>(std::floor(y / cell_)), 0, rows_ - 1);
  return j * cols_ + i;
}

GridIndex::CellRect GridIndex::cells_of(double x, double y, double r) const {
  return {std::clamp(static_cast<int>(std::floor((x - r) / cell_)), 0, cols_ - 1),
          std::clamp(static_cast<int>(std::floor((y - r) / cell_)), 0, rows_ - 1),
          std::clamp(static_cast<int>(std::floor((x + r) / cell_)), 0, cols_ - 1),
          std::clamp(static_cast<int>(std::floor((y + r) / cell_)), 0, rows_ - 1)};
}

void GridIndex::build(const FixedObjects& objs, double width_m, double depth_m, double cell_m, bool home_only) {
  cell_ = cell_m;
  cols_ = std::max(1, static_cast<int>(std::ceil(width_m / cell_m)));
  rows_ = std::max(1, static_cast<int>(std::ceil(depth_m / cell_m)));
  const size_t ncell = static_cast<size_t>(cols_) * rows_;
  home_only_ = home_only;
  // For each object, the range of cells its bounding circle overlaps (or its home cell).
  auto range = [&](size_t k, int& i0, int& j0, int& i1, int& j1) {
    const CellRect c = cells_of(objs.pos[k].x(), objs.pos[k].y(), home_only ? 0.0 : objs.radius_m[k]);
    i0 = c.i0, j0 = c.j0, i1 = c.i1, j1 = c.j1;
  };
  start_.assign(ncell + 1, 0);
  for (size_t k = 0; k < objs.size(); ++k) {
    int i0, j0, i1, j1;
    range(k, i0, j0, i1, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) ++start_[static_cast<size_t>(j) * cols_ + i + 1];
  }
  for (size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  items_.assign(start_[ncell], 0);
  std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
  for (size_t k = 0; k < objs.size(); ++k) {
    int i0, j0, i1, j1;
    range(k, i0, j0, i1, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) items_[fill[static_cast<size_t>(j) * cols_ + i]++] = static_cast<uint32_t>(k);
  }
}

}  // namespace npsnet::world
