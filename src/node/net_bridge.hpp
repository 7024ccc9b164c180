// The net<->world bridge: one node's DIS 7 presence (net/) tied to its Simulation.
// Contract (shared/ARCHITECTURE.md, Network):
//  * Local vehicles (ents.local && ents.node == --node) go out as Entity State PDUs: ECEF
//    position (m), DIS Euler angles (rad), ECEF velocity (m/s) and acceleration (m/s^2), yaw
//    rate (rad/s, body z), the kind's DIS type, marking = scenario id, damage in appearance
//    bits 3-4 (0 none, 1 slight, 2 moderate, 3 destroyed), DR algorithm RVW, sent when the
//    DrPublisher says so (1 m / 3 deg / 5 s heartbeat) or when the appearance changes. Entity
//    number = entity index + 1 (every node loads the same scenario, so indices agree). One PDU
//    a datagram (Wireshark 4.0 decodes only the first PDU of a datagram), at most 128 a tick (the
//    rest follow on the next ticks, round robin; a damage change never waits); NPSNET_DIS_PACK=1
//    packs a tick's Entity States several to a datagram (at most 1400 octets), which keeps
//    start-up and heartbeat bursts of hundreds of vehicles within a receiver's socket buffer.
//  * Vehicles of other nodes start local = 0 and inactive; their first Entity State activates
//    them (matched by marking; an unknown marking adds an entity of the kind whose DIS type
//    matches, or the generic kind of its domain). Each tick, before dynamics, a remote entity's
//    pose and velocity are set from RemoteEntityTable::displayed_pose. No update for the DR
//    timeout (12 s; NPSNET_DIS_TIMEOUT_S overrides, > 0) deactivates it. Events entity_joined /
//    entity_timeout: id (marking), entity "site:app:entity", marking, kind. A timeout below 12 s
//    also shortens our heartbeat to timeout x 5/12 (the Annex C ratio).
//  * Collisions between entities of two nodes are decided by the node owning the lower DIS
//    entity id (site, application, entity). That node applies the outcome to both sides in its
//    world (its remote copy is display only) and sends, after the Entity State of its own side
//    (whose appearance holds the new damage), a Collision PDU: issuing = its entity, colliding =
//    the other, velocity/mass = the issuing entity's before the collision, collision_type
//    1 = elastic (outcome bounce) or 0 = inelastic (outcome kill when the issuing entity's
//    appearance says destroyed, else stop; vehicle pairs always share one outcome). The owner of
//    the colliding entity injects the same collision record (same pair, same outcomes) and
//    applies the outcome to its own entity, once. Contacts between a remote entity and a fixed
//    object, or two remote entities, are left to their owners.
//  * Fixed objects whose state changes are published as cultural-feature Entity States (kind 5,
//    the object kind's DIS type): entity id (site, 0x8000 | application, object index + 1),
//    appearance = state index; heartbeat 5 s. Receivers move the same object forward to that
//    state (a state never goes back).
//  * Every local fire sends a Fire PDU and every local detonation a Detonation PDU (munition
//    type = the kind's DIS type, result 1 entity impact / 3 ground impact). A remote Detonation
//    is injected as a detonation of a munition of the matching kind (he_round when unknown):
//    crater and blast damage as if it happened here; the events detonation and crater follow.
//  * Counters (net::Counters::summary) are printed at the end of a run and on SIGUSR1.
// Nothing received from the network throws or aborts; hot paths allocate only when an entity
// joins or a munition from the network detonates.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/constants.hpp"
#include "net/net.hpp"
#include "node/event_log.hpp"
#include "node/simulation.hpp"

namespace npsnet::node {

struct BridgeOptions {
  std::string url = "udp://239.1.2.3:3000";  // --net
  std::string iface = "127.0.0.1";           // --iface
  int node = 1;                              // --node: vehicles with node = N are ours
  int exercise = 1, site = 1, app = 1;       // DIS identity (app default = node, set by caller)
  double timeout_s = dis_defaults::kTimeoutS;  // remote entity timeout, s
};

// Application ids at or above this carry cultural features (fixed objects).
inline constexpr std::uint16_t kCulturalAppBit = 0x8000;

// Reads NPSNET_DIS_TIMEOUT_S (seconds, > 0, finite) or returns `fallback`; throws
// std::runtime_error with a message on a bad value.
double dis_timeout_from_env(double fallback);

// Opens the DIS session of `o` (socket bound, group joined). Throws std::runtime_error with an
// actionable message (bad URL, iface, identity). Done before anything is written.
std::unique_ptr<net::Session> open_session(const BridgeOptions& o);

class NetBridge {
 public:
  // Opens the session (throws std::runtime_error with an actionable message) and marks the
  // vehicles of other nodes remote and inactive.
  NetBridge(const BridgeOptions& o, Simulation& sim, EventLog& log);
  // The same with a session opened by open_session(o).
  NetBridge(const BridgeOptions& o, std::unique_ptr<net::Session> session, Simulation& sim, EventLog& log);
  ~NetBridge();
  NetBridge(const NetBridge&) = delete;
  NetBridge& operator=(const NetBridge&) = delete;

  // Sets sim.before_step and sim.decides, chains sim.on_tick (the earlier handler runs first).
  void attach();
  // Sends a deactivation Entity State for every local vehicle (end of a run).
  void leave();

  void before_step(world::World& w);
  bool decides(const collision::Contact& c);
  void after_tick(const TickReport& r);

  const net::Counters& counters() const { return session_->counters(); }
  // Counters plus the Entity State rate of the local vehicles, several lines.
  std::string summary() const;
  // Entity State PDUs sent for local ground vehicles, their number, and seconds published.
  std::uint64_t ground_es_sent() const { return ground_es_sent_; }
  int ground_vehicles() const { return ground_vehicles_; }
  double published_s() const { return now_s_ - start_s_; }
  // Handles a pending SIGUSR1 (prints the summary to stderr).
  void check_signal();

 private:
  struct Pending {  // a contact this node decided, with the velocities before the response
    int own = -1, other = -1;
    Vec3 own_vel{0, 0, 0};
  };
  double clock_s() const;
  net::EntityId own_id(int e) const;
  bool is_own_vehicle(int e) const;
  int remote_index_of(const net::EntityId& id) const;  // world index or -1
  std::string id_text(const net::EntityId& id) const;
  nlohmann::json event(const char* type) const;
  int kind_for(const net::EntityType& t, world::Mobility fallback_domain_hint) const;
  int kind_for_munition(const net::EntityType& t) const;
  std::uint32_t appearance_of(int e) const;
  int state_from_appearance(int kind, std::uint32_t appearance) const;

  void on_entity_state(const net::EntityStatePdu& p);
  void on_cultural(const net::EntityStatePdu& p);
  void on_collision(const net::CollisionPdu& p);
  void on_fire(const net::FirePdu& p);
  void on_detonation(const net::DetonationPdu& p);
  void joined(std::size_t remote_index);
  void set_remote_poses(world::World& w);
  void publish_vehicles();
  void publish_collisions(const TickReport& r);
  void publish_fixed(const TickReport& r);
  void publish_fires(const TickReport& r);
  void publish_detonations(const TickReport& r);
  void send_cultural(int object);
  net::KinematicState truth(int e) const;

  BridgeOptions opt_;
  Simulation& sim_;
  EventLog& log_;
  std::unique_ptr<net::Session> session_;
  net::RemoteEntityTable remotes_;
  std::uint16_t cultural_app_;
  double start_s_ = 0, now_s_ = 0;
  bool started_ = false;

  // Local vehicles we publish (world indices), one DrPublisher each.
  std::vector<int> own_;
  std::vector<net::DrPublisher> pubs_;
  std::vector<std::uint32_t> sent_appearance_;
  std::vector<Vec3> prev_vel_ecef_;
  std::vector<float> prev_heading_;
  std::uint64_t ground_es_sent_ = 0;
  int ground_vehicles_ = 0;
  net::EntityStatePdu es_;  // reused
  net::DatagramBuilder batch_;  // this tick's Entity States, packed (1400 octets a datagram)
  bool pack_ = false;           // NPSNET_DIS_PACK=1
  size_t rr_ = 0;               // first local vehicle looked at next tick (send cap round robin)
  void flush_batch();

  // Remote entities: id -> world index (kept across timeouts, so a rejoin reuses the entity).
  struct IdHash {
    std::size_t operator()(const net::EntityId& e) const noexcept {
      return (std::size_t{e.site} << 32) ^ (std::size_t{e.application} << 16) ^ e.entity;
    }
  };
  std::unordered_map<net::EntityId, int, IdHash> world_of_;
  std::vector<net::EntityId> remote_id_;  // per world entity; site 0 = not remote

  // Fixed objects: the state last published or heard (-1: never), heartbeat times.
  std::vector<int16_t> fixed_net_state_;
  std::vector<int> fixed_published_;        // objects we publish
  std::vector<double> fixed_last_sent_;     // per published object
  std::vector<Pending> pending_;            // this tick's decided cross-node contacts
  std::unordered_map<int, std::uint16_t> fire_event_;  // munition index -> event number
  std::uint16_t event_number_ = 0;
  world::Changes inject_;                   // reused for injected changes
  std::function<void(const TickReport&)> chained_on_tick_;
};

}  // namespace npsnet::node
