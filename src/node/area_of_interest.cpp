// area_of_interest.cpp — the node's cell groups: what to publish where, what to join.
#include "node/area_of_interest.hpp"

#include <algorithm>
#include <stdexcept>

namespace npsnet::node {

namespace {
net::AoiGrid make_grid(double cell_m, int max_groups, const std::string& base) {
  auto g = net::AoiGrid::make(base, cell_m, max_groups);
  if (!g) throw std::runtime_error(g.error());
  return g.value();
}
}  // namespace

AreaOfInterest::AreaOfInterest(double cell_m, int max_groups, const std::string& base_group, const world::World& w,
                               double heartbeat_s)
    : grid_(make_grid(cell_m, max_groups, base_group)), membership_(grid_, cell_m / 2), heartbeat_s_(heartbeat_s) {
  const auto& ents = w.ents;
  for (size_t e = 0; e < ents.size(); ++e) {
    const auto mob = w.kinds[ents.kind[e]].mobility;
    if (mob == world::Mobility::Fixed || mob == world::Mobility::Munition) continue;
    fastest_mps_ = std::max(fastest_mps_, static_cast<double>(ents.max_mps[e]));
  }
}

double AreaOfInterest::radius_of(const world::World& w, int e) const {
  const double range = w.kinds[w.ents.kind[e]].sensor_range_m;
  return range + (static_cast<double>(w.ents.max_mps[e]) + fastest_mps_) * heartbeat_s_;
}

void AreaOfInterest::update(const world::World& w, const std::vector<int>& own, net::Session& session) {
  membership_.begin();
  for (const int e : own)
    if (w.ents.active[e]) membership_.want(w.ents.pos[e].x(), w.ents.pos[e].y(), radius_of(w, e));
  membership_.end([&](std::uint32_t k) { return session.join_group(grid_.address(k)); },
                  [&](std::uint32_t k) { session.leave_group(grid_.address(k)); });
}

}  // namespace npsnet::node
