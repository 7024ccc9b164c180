// Vehicle and munition dynamics, one fixed step at a time (any dt from 0.01 to 1 s).
// Ground vehicles steer to their waypoints (holding the course while a waypoint lies within
// 0.01 deg of the heading) at cruise speed (never above their limit: Table 2 or
// the scenario's override) and follow the terrain (height, pitch and roll from the terrain under
// their footprint); ships stay on water; aircraft hold altitude. he_round flies a ballistic arc
// and meets the terrain by marching along the heightfield; a guided kind (missile) flies at its
// target entity.
// Only local, active entities are moved; remote ones come from the network.
// Threading: step and drive write only the pose, velocity, route leg and fuel of the entity they
// move. step moves the vehicles first (given a core::Jobs, ranges of entities on its workers:
// each vehicle reads the terrain and its own state only, so any thread count gives the same
// bytes), then the munitions on the calling thread in index order: a guided munition reads its
// target's pose after the vehicles have moved. fire and react_to_fire (autonomous.hpp) read a
// const world and return changes for world::apply.
#pragma once
#include <optional>
#include <vector>

#include "core/heading_memo.hpp"
#include "core/jobs.hpp"
#include "world/changes.hpp"
#include "world/world.hpp"

namespace npsnet::dynamics {

inline constexpr double kGravity = 9.80665;  // m/s^2

// A munition that met the ground this step, at `point` (the round is spent: active = 0).
struct GroundImpact {
  int munition = -1;
  Vec3 point{0, 0, 0};
};

// Moves every local active entity by dt. Appends munitions that met the terrain to `impacts`
// (in index order). `jobs`: worker threads for the vehicles (nullptr: this thread only).
// `memo`: the caller's heading directions (core/heading_memo.hpp), kept between calls; a vehicle
// moves along its stored heading and holds its course while the waypoint lies within 0.01 deg of
// it, so on a straight leg the heading stays the same float. Each moved ground vehicle's new
// heading is noted for the collision stage (nullptr: none; the same bits either way).
void step(world::World& w, double dt, std::vector<GroundImpact>& impacts, core::Jobs* jobs = nullptr,
          core::HeadingMemo* memo = nullptr);

// Terrain following for a ground vehicle at its current (x, y): sets z, pitch and roll from the
// terrain under the corners of its footprint (the intact model's extent).
void follow_terrain(world::World& w, int e);
// The same, given f = heading_to_dir(ents.heading_deg[e]) (the caller's, to spare its sin and cos).
void follow_terrain_along(world::World& w, int e, const Vec2& f);

// Decides a round of kind `munition` fired from `shooter` at a point (or an entity when target >= 0,
// which a guided kind then tracks); world::apply launches it (takes the round, adds the munition
// entity). nullopt when the shooter cannot fire (dead, no rounds left). A ballistic kind: lowest
// arc that reaches the point at the kind's muzzle speed (45 degrees when out of range).
std::optional<world::Launch> fire(const world::World& w, int shooter, int munition_kind, const Vec3& target_point,
                                  int target);

}  // namespace npsnet::dynamics
