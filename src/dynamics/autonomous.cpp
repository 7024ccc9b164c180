#include "dynamics/autonomous.hpp"

#include "world/pose.hpp"

namespace npsnet::dynamics {

Reaction react_to_fire(const world::World& w, int victim, int shooter, world::EntityChange& change) {
  const auto& ents = w.ents;
  if (victim < 0 || !ents.autonomous[victim] || !ents.local[victim] || !ents.active[victim]) return Reaction::None;
  const world::Kind& k = w.kinds[ents.kind[victim]];
  if (ents.state[victim] + 1 >= static_cast<int>(k.states.size())) return Reaction::None;  // a wreck
  if (ents.flee_until[victim] > w.t || ents.calm_until[victim] > w.t) return Reaction::None;  // reacting already
  change = world::EntityChange{};
  change.entity = victim;
  change.calm_until = static_cast<float>(w.t + kReactionSeconds);
  // Intact with rounds (of its kind's munition) left and a live shooter in sight: return fire.
  // Otherwise flee.
  if (ents.state[victim] == 0 && ents.rounds[victim] > 0 && shooter >= 0 && ents.active[shooter] &&
      w.kinds.find(k.munition) >= 0)
    return Reaction::ReturnFire;
  if (shooter >= 0) change.heading_deg = static_cast<float>(dir_to_heading((ents.pos[victim] - ents.pos[shooter]).head<2>()));
  else change.heading_deg = static_cast<float>(wrap360(ents.heading_deg[victim] + 180));
  change.flee_until = static_cast<float>(w.t + kFleeSeconds);
  change.cruise_mps = ents.max_mps[victim];
  return Reaction::Flee;
}

}  // namespace npsnet::dynamics
