// The ownership rule of collisions between entities of two nodes (shared/ARCHITECTURE.md,
// Ownership): the node owning the lower DIS entity id (site, application, entity) decides the
// contact for both sides; a contact of our munition is ours (we detonate our round); contacts of
// a remote entity with a fixed object, or of two remote entities, are left to their owners.
// For each contact it decides across nodes it keeps the own side's velocity before the
// response, for the Collision PDU. The list is cleared every tick and grows as needed: every
// decided contact is kept (no limit; it allocates only when a tick has more such contacts than
// any tick before).
#pragma once
#include <vector>

#include "collision/collision.hpp"
#include "net/pdu.hpp"
#include "node/remote_entities.hpp"

namespace npsnet::node {

class Ownership {
 public:
  struct Pending {  // a contact this node decided, with the own side's velocity before it
    int own = -1, other = -1;
    Vec3 own_vel{0, 0, 0};
  };
  // own_base: our (site, application); an own entity e has id (site, application + k * 4096,
  // e % 32767 + 1), k = e / 32767 (net::kEntitiesPerApplication, net::kApplicationStride):
  // entity numbers 1-32767 under each application, so a node may own more than 32,767.
  explicit Ownership(net::EntityId own_base) : base_(own_base) { pending_.reserve(16); }

  net::EntityId own_id(int e) const {
    const int k = e / net::kEntitiesPerApplication;
    return {base_.site, static_cast<std::uint16_t>(base_.application + k * net::kApplicationStride),
            static_cast<std::uint16_t>(e % net::kEntitiesPerApplication + 1)};
  }
  // The entity index an id of ours names (any application of ours), or -1.
  int own_index(const net::EntityId& id) const {
    if (id.site != base_.site || !own_application(id.application) || id.entity < 1 ||
        id.entity > net::kEntitiesPerApplication)
      return -1;
    const int k = (id.application - base_.application) / net::kApplicationStride;
    return k * net::kEntitiesPerApplication + id.entity - 1;
  }
  bool own_application(std::uint16_t a) const {
    const int d = static_cast<int>(a) - static_cast<int>(base_.application);
    return d >= 0 && d % net::kApplicationStride == 0 && d / net::kApplicationStride < blocks_;
  }
  // Applications our entities are numbered under (1 up to 32,767 entities).
  void set_application_blocks(int n) { blocks_ = n; }
  int application_blocks() const { return blocks_; }
  // Whether this node decides contact c (records the cross-node ones it decides).
  bool decides(const world::World& w, const RemoteEntities& remotes, const collision::Contact& c);
  // The own side's velocity before the response of a decided cross-node contact, or `fallback`.
  Vec3 velocity_before(int own, int other, const Vec3& fallback) const;
  // Whether we announce (issue the Collision PDU of) a contact between own and other.
  bool announces(int own, const RemoteEntities& remotes, int other) const;
  void clear() { pending_.clear(); }

 private:
  net::EntityId base_;
  int blocks_ = 1;
  std::vector<Pending> pending_;
};

}  // namespace npsnet::node
