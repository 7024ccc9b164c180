// Remote-entity bookkeeping of the bridge: vehicles of other nodes, tied to world entities.
//  * Receiving (on_entity_state / on_update, while the bridge drains its socket) only updates
//    the DIS table and notes what each PDU did; the world is not touched then.
//  * mirror(now) is stage 1 of the tick's world changes (the "remote entity states -> World"
//    stage of shared/ARCHITECTURE.md, node/simulation.hpp): the noted joins, removals and
//    damage in arrival order, then timeouts, then every active remote entity's pose, each a
//    world::Mirror applied by world::apply (Simulation::apply_net_in), the events logged as
//    they are decided. Nothing else writes a remote entity's pose or activity.
//  * A join: a scenario vehicle of another node with that marking is bound to the remote id;
//    an unknown marking adds an entity of the kind its DIS type has in models/entity_types.toml
//    (entity_type_table.hpp: our kind of that exact type, else the most specific entry, e.g. the
//    generic kind of its domain). A type the table tracks without a model (lifeform, cultural
//    feature, environmental, ...) is logged (entity_joined with model "none" and tracked_as)
//    and listed, but not put into the world. A scenario vehicle whose owner sends another DIS
//    type takes the kind of that type through world::Changes (to_kind).
//  * Poses: the dead-reckoned pose and velocity at now (world axes: v + a t, body axes turned
//    into the world) from RemoteEntityTable::displayed_pose.
//  * No update for the DR timeout deactivates it. Events entity_joined / entity_timeout /
//    entity_removed (the owner's deactivation, in an Entity State or an Entity State Update): id
//    (marking), entity "site:app:entity", marking, kind (or the DIS type when unknown, with
//    model = the kind shown). Tracked-only entities get the same three events (kind = the DIS
//    type, tracked_as), so every remote entity's arrival and departure is logged.
//  * Damage from the owner's appearance (Entity State or Update) goes to world::Changes, also
//    backwards (a repair): a `damage` event with "remote": true. A tracked-only entity's damage
//    bits changing are a `damage` event too: object, entity, kind (DIS type), tracked_as,
//    from_state / to_state = none | slight | moderate | destroyed, "remote": true.
// Ids: world entities keep their remote id across timeouts, so a rejoin reuses the entity.
// Timeout then rejoin (issue 11): a parked or straight-driving entity sends only the 5 s
// heartbeat, so two lost heartbeats time it out (DIS: 2.4 heartbeats) though it never left. The
// same id coming back is the same entity: its entity_joined event says "rejoin": true (the world
// entity is reused, nothing spawns), and the contact episodes it was in when it timed out go on:
// a contact with one of those partners within kResumeS of the rejoin is not a new collision
// (resumed_contact; the bridge decides none, so no event, no outcome, no Collision PDU), and the
// detector carries the episode on from there while the pair still touches.
// Threading: the tick's thread only (as the Simulation it writes to).
#pragma once
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "net/net.hpp"
#include "node/entity_type_table.hpp"
#include "node/event_log.hpp"
#include "node/simulation.hpp"

namespace npsnet::node {

class RemoteEntities {
 public:
  // types: the entity-type table (null: the bundled models/entity_types.toml).
  RemoteEntities(const net::DrThresholds& t, Simulation& sim, EventLog& log,
                 std::shared_ptr<const EntityTypeTable> types = nullptr);

  // The remote id of world entity e (site 0: not a remote entity).
  net::EntityId id_of(int e) const;
  bool is_remote(int e) const { return id_of(e).site != 0; }
  // World index of a remote id, or -1.
  int index_of(const net::EntityId& id) const;
  // The table entry of a remote id, or nullptr.
  const net::RemoteEntity* find(const net::EntityId& id) const;
  std::size_t size() const { return table_.size(); }
  const net::DrThresholds& thresholds() const { return table_.thresholds(); }

  // A vehicle's Entity State (not a cultural feature, not a munition) arriving at now_s (bridge
  // clock), UTC unix_now_s (net::RemoteEntityTable::kNoUtc when unknown): its timestamp dates it.
  void on_entity_state(const net::EntityStatePdu& p, double now_s, double unix_now_s);
  void on_update(const net::EntityStateUpdatePdu& p, double now_s, double unix_now_s);
  // Stage 1 (see above): what was noted since the last call, then timeouts (entities silent for
  // longer than the timeout), then, when `poses`, every active remote entity's displayed pose at
  // now_s (a frozen node skips the poses).
  void mirror(double now_s, bool poses = true);
  // One line per remote entity heard and not gone (at most max_lines, then how many more):
  // "  remote 1:50:1 \"r1\" type 1:1:225:1:1:3:0 (m1a1) owner site 1 app 50 last update 0.4 s ago
  // damage intact (appearance damage 0) force 1". The marking is JSON-quoted (decoded, made safe).
  // A tracked-only entity shows what it is tracked as ("(lifeform)") and its damage bits' name.
  std::string listing(double now_s, std::size_t max_lines = 100) const;
  // Whether the contact of world entities a and b, now_s, is the episode a rejoined entity was in
  // when it timed out (see above); true once per remembered pair.
  bool resumed_contact(int a, int b, double now_s);
  static constexpr double kResumeS = 1.0;  // after the rejoin, s
  static constexpr std::size_t kMaxResumes = 4096;

 private:
  // What the table knew of an entity before a PDU was applied (heard = false: nothing).
  struct Known {
    bool heard = false;
    net::EntityType type;
    net::Marking marking;
    std::uint32_t appearance = 0;
    std::uint8_t force_id = 0;
  };
  // What one Entity State (Update) did to the table, decided in mirror() (no allocation).
  struct Noted {
    net::EntityId id;
    net::RemoteEntityTable::ApplyResult result;
    Known before, after;
    std::uint32_t appearance = 0;  // the PDU's
  };
  Known known(const net::EntityId& id) const;
  // After an Entity State or Entity State Update was applied: join, removal (deactivation) and
  // damage changes, for world entities and tracked-only ones alike.
  void settle(const Noted& n);
  // What a type is tracked as when it is not put into the world ("lifeform", ...), else "".
  const char* tracked_as(const net::EntityType& t) const;
  // An event about a tracked-only entity: id (marking, or site:app:entity), entity, marking,
  // kind (the DIS type), tracked_as.
  nlohmann::json tracked_event(const char* type, const net::EntityId& id, const net::EntityType& t,
                               const net::Marking& m) const;
  void joined(const net::EntityId& id, const Known& r);
  void expire(double now_s);
  void set_poses(double now_s);
  void deactivate(int e);  // a Deactivate mirror
  void flush();            // applies mirrors_ (Simulation::apply_net_in)
  // The kind a remote entity is shown as: its own when the owner's type matches, else the kind
  // of that type.
  int kind_for(int e, const net::EntityType& t) const;
  void grow();
  void inject(const world::EntityChange& ch);  // queued for this tick's world::apply
  nlohmann::json event(const char* type) const;

  Simulation& sim_;
  EventLog& log_;
  std::shared_ptr<const EntityTypeTable> types_;
  net::RemoteEntityTable table_;
  struct IdHash {
    std::size_t operator()(const net::EntityId& e) const noexcept {
      return (std::size_t{e.site} << 32) ^ (std::size_t{e.application} << 16) ^ e.entity;
    }
  };
  std::unordered_map<net::EntityId, int, IdHash> world_of_;
  std::vector<net::EntityId> remote_id_;  // per world entity; site 0 = not remote
  world::Changes inject_;                 // reused
  world::Changes mirrors_;                // reused; only .mirrors
  std::vector<Noted> noted_;              // since the last mirror()
  // A remote entity that timed out in contact with `partner`: until_s is +inf until it rejoins.
  struct Resume {
    int entity, partner;
    double until_s;
  };
  std::vector<Resume> resumes_;
  double now_s_ = 0;  // of the last mirror()
};

}  // namespace npsnet::node
