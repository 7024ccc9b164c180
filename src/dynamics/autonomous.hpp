// Autonomous vehicles (scenario `autonomous = true`): "react when fired upon by either returning
// fire or fleeing the area" (thesis p. 1). An intact vehicle with rounds left returns fire at the
// shooter (the caller fires); a damaged one, or one with no rounds, flees away from the shooter
// at its top speed for kFleeSeconds.
#pragma once
#include "world/world.hpp"

namespace npsnet::dynamics {

inline constexpr double kFleeSeconds = 20.0;
inline constexpr double kReactionSeconds = 10.0;  // one reaction per this long
inline constexpr double kThreatRadiusM = 300.0;  // a detonation this close counts as being fired upon

enum class Reaction { None, ReturnFire, Flee };
Reaction react_to_fire(world::World& w, int victim, int shooter);

}  // namespace npsnet::dynamics
