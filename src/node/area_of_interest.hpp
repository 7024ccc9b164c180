// The node's area of interest (--aoi CELL_M, shared/ARCHITECTURE.md "Area of interest"): which
// cell group each PDU goes to, and which cell groups this node holds.
// Contract:
//  * Cells and groups as net/aoi.hpp documents, from the --net group (the base) and
//    --aoi-groups: cell (floor(x / CELL_M), floor(y / CELL_M)) of the local frame, group
//    base + (i mod M) + M * (j mod M), M = floor(sqrt(--aoi-groups)).
//  * group_at(p): the group of the cell holding the local point p (metres).
//  * update(): each tick, before the receive; every active vehicle this node drives wants the
//    cells within   sensor_range_m (its kind, models/kinds.toml)
//                 + (its max speed + the exercise's fastest vehicle's max speed) x heartbeat
//    of it: the margin covers one heartbeat in which it and a remote entity close in, since a
//    remote entity in a group just joined is heard at its next Entity State (at most a heartbeat
//    later), while one that crosses into a held cell is announced there at once. Joined when
//    wanted, left only once farther than that radius + CELL_M / 2 (hysteresis). Joins, leaves
//    and groups held are counted in the session's counters.
//  * Every remote entity that can reach a vehicle of ours within a tick is well inside that
//    radius (sensor ranges are kilometres, a tick's travel metres), so collision checks see it.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/math.hpp"
#include "net/net.hpp"
#include "world/world.hpp"

namespace npsnet::node {

class AreaOfInterest {
 public:
  // Throws std::runtime_error naming --aoi / --aoi-groups / --net when the grid cannot be made.
  AreaOfInterest(double cell_m, int max_groups, const std::string& base_group, const world::World& w,
                 double heartbeat_s);

  std::uint32_t group_at(const Vec3& p) const noexcept {
    return grid_.address(grid_.group_of(p.x(), p.y()));
  }
  // Radius (m) a vehicle of entity index e wants around it.
  double radius_of(const world::World& w, int e) const;
  void update(const world::World& w, const std::vector<int>& own, net::Session& session);

  const net::AoiGrid& grid() const noexcept { return grid_; }
  const net::AoiMembership& membership() const noexcept { return membership_; }

 private:
  net::AoiGrid grid_;
  net::AoiMembership membership_;
  double heartbeat_s_;
  double fastest_mps_ = 0;
};

}  // namespace npsnet::node
