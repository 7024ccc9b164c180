#include "node/ownership.hpp"

namespace npsnet::node {

bool Ownership::decides(const world::World& w, const RemoteEntities& remotes, const collision::Contact& c) {
  const auto& ents = w.ents;
  if (c.b_fixed) return ents.local[c.a] != 0;  // the vehicle's owner decides
  const bool la = ents.local[c.a] != 0, lb = ents.local[c.b] != 0;
  if (la && lb) return true;
  if (!la && !lb) return false;  // two remote entities: their owners decide
  const int own = la ? c.a : c.b, other = la ? c.b : c.a;
  if (w.kinds[ents.kind[own]].mobility == world::Mobility::Munition) return true;  // our round: we detonate it
  const net::EntityId rid = remotes.id_of(other);
  if (rid.site == 0) return true;
  const bool d = own_id(own) < rid;
  if (d) pending_.push_back({own, other, ents.vel[own]});
  return d;
}

Vec3 Ownership::velocity_before(int own, int other, const Vec3& fallback) const {
  Vec3 v = fallback;
  for (const auto& pd : pending_)
    if (pd.own == own && pd.other == other) v = pd.own_vel;
  return v;
}

bool Ownership::announces(int own, const RemoteEntities& remotes, int other) const {
  return remotes.is_remote(other) && own_id(own) < remotes.id_of(other);
}

}  // namespace npsnet::node
