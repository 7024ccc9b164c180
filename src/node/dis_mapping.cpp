#include "node/dis_mapping.hpp"

#include <algorithm>
#include <cstdio>

namespace npsnet::node {

net::EntityType to_net(const world::DisType& d) {
  return {d.kind, d.domain, d.country, d.category, d.subcategory, d.specific, d.extra};
}

bool same_type(const world::DisType& d, const net::EntityType& t) { return to_net(d) == t; }

std::string type_text(const net::EntityType& t) {
  char b[64];
  std::snprintf(b, sizeof b, "%u:%u:%u:%u:%u:%u:%u", t.kind, t.domain, t.country, t.category, t.subcategory,
                t.specific, t.extra);
  return b;
}

std::string id_text(const net::EntityId& id) {
  return std::to_string(id.site) + ":" + std::to_string(id.application) + ":" + std::to_string(id.entity);
}

int vehicle_kind_for(const world::KindTable& kinds, const net::EntityType& t) {
  for (int k = 0; k < kinds.size(); ++k)
    if (kinds[k].mobile() && kinds[k].mobility != world::Mobility::Munition && same_type(kinds[k].dis, t)) return k;
  const char* generic = t.domain == 2 ? "generic_air" : t.domain == 3 ? "generic_sea" : "generic_ground";
  const int k = kinds.find(generic);
  if (k >= 0) return k;
  for (int j = 0; j < kinds.size(); ++j)
    if (kinds[j].mobility == world::Mobility::Ground) return j;
  return -1;
}

int munition_kind_for(const world::KindTable& kinds, const net::EntityType& t) {
  for (int k = 0; k < kinds.size(); ++k)
    if (kinds[k].mobility == world::Mobility::Munition && same_type(kinds[k].dis, t)) return k;
  const int k = kinds.find("he_round");
  if (k >= 0) return k;
  for (int j = 0; j < kinds.size(); ++j)
    if (kinds[j].mobility == world::Mobility::Munition) return j;
  return -1;
}

std::uint32_t damage_appearance(const world::Kind& k, int s) {
  const int n = static_cast<int>(k.states.size());
  std::uint32_t d = 0;
  if (s <= 0) d = 0;
  else if (s >= n - 1) d = dis::kDamageDestroyed;
  else d = (n > 3 && s >= 2) ? 2 : 1;
  return d << dis::kDamageShift;
}

int state_from_appearance(const world::Kind& k, std::uint32_t appearance) {
  const int n = static_cast<int>(k.states.size());
  const unsigned d = damage_bits(appearance);
  if (d == 0 || n <= 1) return 0;
  if (d == dis::kDamageDestroyed) return n - 1;
  return std::min<int>(n - 2, n > 3 ? static_cast<int>(d) : 1);
}

}  // namespace npsnet::node
