// Vehicle and munition dynamics, one fixed step at a time (any dt from 0.01 to 1 s).
// Ground vehicles steer to their waypoints at cruise speed (never above their limit: Table 2 or
// the scenario's override) and follow the terrain (height, pitch and roll from the terrain under
// their footprint); ships stay on water; aircraft hold altitude. he_round flies a ballistic arc
// and meets the terrain by marching along the heightfield; a guided kind (missile) flies at its
// target entity.
// Only local, active entities are moved; remote ones come from the network.
#pragma once
#include <vector>

#include "world/world.hpp"

namespace npsnet::dynamics {

inline constexpr double kGravity = 9.80665;  // m/s^2

// A munition that met the ground this step, at `point` (the round is spent: active = 0).
struct GroundImpact {
  int munition = -1;
  Vec3 point{0, 0, 0};
};

// Moves every local active entity by dt. Appends munitions that met the terrain to `impacts`.
void step(world::World& w, double dt, std::vector<GroundImpact>& impacts);

// Terrain following for a ground vehicle at its current (x, y): sets z, pitch and roll from the
// terrain under the corners of its footprint (the intact model's extent).
void follow_terrain(world::World& w, int e);

// Fires a round of kind `munition` from `shooter` at a point (or an entity when target >= 0,
// which a missile then tracks). Returns the new munition's entity index, or -1 when the shooter
// cannot fire (dead, no rounds left). he_round: lowest ballistic arc that reaches the point at
// the kind's muzzle speed (45 degrees when out of range).
int fire(world::World& w, int shooter, int munition_kind, Vec3 target_point, int target);

}  // namespace npsnet::dynamics
