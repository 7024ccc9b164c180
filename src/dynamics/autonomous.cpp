#include "dynamics/autonomous.hpp"

#include "world/pose.hpp"

namespace npsnet::dynamics {

Reaction react_to_fire(world::World& w, int victim, int shooter) {
  auto& ents = w.ents;
  if (victim < 0 || !ents.autonomous[victim] || !ents.local[victim] || !ents.active[victim]) return Reaction::None;
  const world::Kind& k = w.kinds[ents.kind[victim]];
  if (ents.state[victim] + 1 >= static_cast<int>(k.states.size())) return Reaction::None;  // a wreck
  if (ents.flee_until[victim] > w.t || ents.calm_until[victim] > w.t) return Reaction::None;  // reacting already
  ents.calm_until[victim] = static_cast<float>(w.t + kReactionSeconds);
  // Intact with rounds left and a live shooter in sight: return fire. Otherwise flee.
  if (ents.state[victim] == 0 && ents.rounds[victim] > 0 && shooter >= 0 && ents.active[shooter]) return Reaction::ReturnFire;
  if (shooter >= 0) ents.heading_deg[victim] = static_cast<float>(dir_to_heading((ents.pos[victim] - ents.pos[shooter]).head<2>()));
  else ents.heading_deg[victim] = static_cast<float>(wrap360(ents.heading_deg[victim] + 180));
  ents.flee_until[victim] = static_cast<float>(w.t + kFleeSeconds);
  ents.cruise_mps[victim] = ents.max_mps[victim];
  return Reaction::Flee;
}

}  // namespace npsnet::dynamics
