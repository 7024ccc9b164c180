// Autonomous vehicles (scenario `autonomous = true`): "react when fired upon by either returning
// fire or fleeing the area" (thesis p. 1). An intact vehicle with rounds left returns fire at the
// shooter with its kind's munition (kinds.toml `munition`); a damaged one, or one with no rounds,
// flees away from the shooter at its top speed for kFleeSeconds.
// The decision reads a const world; the change (and the return fire's dynamics::fire launch) goes
// through world::apply.
#pragma once
#include "world/changes.hpp"

namespace npsnet::dynamics {

inline constexpr double kFleeSeconds = 20.0;
inline constexpr double kReactionSeconds = 10.0;  // one reaction per this long
inline constexpr double kThreatRadiusM = 300.0;  // a detonation this close counts as being fired upon

enum class Reaction { None, ReturnFire, Flee };
// The reaction of `victim` fired upon by `shooter` (-1: unknown) at the world's time t; fills
// `change` (calm_until; fleeing: heading, flee_until, cruise speed) unless None.
Reaction react_to_fire(const world::World& w, int victim, int shooter, world::EntityChange& change);

}  // namespace npsnet::dynamics
