// DIS enumerations (SISO-REF-010) we send and read, and the mapping between our kinds and damage
// states and DIS entity types and appearance.
//  * Damage travels in appearance bits 3-4: 0 none, 1 slight, 2 moderate, 3 destroyed. A kind
//    with n states maps intact -> 0, the last state -> 3, the states between -> 1 (and 2 for
//    kinds with more than three states); reading goes back the same way.
//  * An incoming vehicle type takes the kind with exactly that type, else the generic kind of its
//    domain (generic_air, generic_sea, generic_ground), else the first ground kind; a munition
//    type the munition kind with that type, else he_round, else the first munition kind.
#pragma once
#include <cstdint>
#include <string>

#include "net/pdu.hpp"
#include "world/kinds.hpp"

namespace npsnet::node {

namespace dis {
inline constexpr std::uint16_t kWarheadHighExplosive = 1000;
inline constexpr std::uint16_t kFuseContact = 1000;
inline constexpr std::uint8_t kResultEntityImpact = 1;
inline constexpr std::uint8_t kResultGroundImpact = 3;
inline constexpr std::uint8_t kResultDetonation = 5;
inline constexpr std::uint8_t kCollisionInelastic = 0;
inline constexpr std::uint8_t kCollisionElastic = 1;
inline constexpr std::uint8_t kEntityKindMunition = 2;
inline constexpr std::uint8_t kEntityKindCultural = 5;
inline constexpr unsigned kDamageShift = 3;  // appearance bits 3-4: damage
inline constexpr std::uint32_t kDamageMask = 3u << kDamageShift;
inline constexpr unsigned kDamageDestroyed = 3;
}  // namespace dis

net::EntityType to_net(const world::DisType& d);
bool same_type(const world::DisType& d, const net::EntityType& t);
// "kind:domain:country:category:subcategory:specific:extra"
std::string type_text(const net::EntityType& t);
// "site:application:entity"
std::string id_text(const net::EntityId& id);

// Kind index for an incoming vehicle / munition type, -1 when the kinds file has none at all.
int vehicle_kind_for(const world::KindTable& kinds, const net::EntityType& t);
int munition_kind_for(const world::KindTable& kinds, const net::EntityType& t);

// Appearance damage bits of `state` of kind `k`, and the state the bits of `appearance` mean.
std::uint32_t damage_appearance(const world::Kind& k, int state);
int state_from_appearance(const world::Kind& k, std::uint32_t appearance);
// The damage bits (0-3) of an appearance.
inline unsigned damage_bits(std::uint32_t appearance) { return (appearance & dis::kDamageMask) >> dis::kDamageShift; }
// The names of the damage bits' values (SISO-REF-010 appearance damage).
inline constexpr const char* kDamageNames[4] = {"none", "slight", "moderate", "destroyed"};

}  // namespace npsnet::node
