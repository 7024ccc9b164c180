#include "node/collision_outcome.hpp"

#include "node/dis_mapping.hpp"

namespace npsnet::node {

void set_outcome(net::CollisionPdu& p, world::Result r) {
  p.collision_type = r == world::Result::Bounce ? dis::kCollisionElastic : dis::kCollisionInelastic;
  p.padding = r == world::Result::Bounce ? kOutcomeBounce
              : r == world::Result::Stop ? kOutcomeStop
              : r == world::Result::Kill ? kOutcomeKill
                                         : kOutcomeUnstated;
}

world::Result outcome_of(const net::CollisionPdu& p, std::uint32_t issuer_appearance) {
  const bool elastic = p.collision_type == dis::kCollisionElastic;
  if (elastic && p.padding == kOutcomeBounce) return world::Result::Bounce;
  if (!elastic && p.collision_type == dis::kCollisionInelastic) {
    if (p.padding == kOutcomeStop) return world::Result::Stop;
    if (p.padding == kOutcomeKill) return world::Result::Kill;
  }
  if (elastic) return world::Result::Bounce;
  return damage_bits(issuer_appearance) == dis::kDamageDestroyed ? world::Result::Kill : world::Result::Stop;
}

}  // namespace npsnet::node
