// An aircraft meeting the terrain (dynamics/drive.hpp Crash), answered like a collision with a
// fixed object: the ground is the largest fixed object there is, so Figure 8's rule for a large
// fixed object holds: moving quickly (at least thesis::kQuickSpeedMps) kills the aircraft, slower
// stops it (a landing). Appends one collision record (b = -1: the ground, method "terrain") and
// the entity's change; the world changes in world::apply like for every other collision.
#pragma once
#include "world/changes.hpp"

namespace npsnet::collision {

void ground_contact(const world::World& w, int e, const Vec3& point, double speed_mps, world::Changes& out);

}  // namespace npsnet::collision
