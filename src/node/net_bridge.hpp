// The net<->world bridge: one node's DIS 7 presence (net/) tied to its Simulation. Its parts:
//   bridge_options  --net/--iface/identity, NPSNET_DIS_TIMEOUT_S, NPSNET_DIS_PACK
//   usr1_signal     SIGUSR1 -> summary on stderr
//   dis_mapping     DIS types <-> our kinds, damage <-> appearance, enumerations
//   remote_entities vehicles of other nodes: join, pose, damage, timeout (and their events)
//   pdu_build       Entity State / cultural feature / Fire / Detonation / Collision PDUs
//   vehicle_publish the local vehicles' Entity States (DR, caps, round robin), deactivation
//   collision_exchange collisions across nodes: announce, repeat, receive once (collision_outcome)
//   repeat_ledger   Detonation and Collision PDUs repeated every heartbeat, applied once
//   fixed_exchange  changed fixed objects as cultural features: publish, heartbeat, receive
//   warfare_publish our Fire and Detonation PDUs (Detonations repeated every heartbeat)
//   warfare_receive other simulators' Fire and Detonation (munition_table, munition_codes)
//   net_bridge      session, receive dispatch, join catch-up, the tick's order, summary
//   sim_management  Stop/Freeze, Start/Resume, Remove Entity, Acknowledge
//   ownership       who decides a contact between entities of two nodes
//   area_of_interest --aoi: the cell group of each PDU, the groups this node holds
// Contract (shared/ARCHITECTURE.md, Network):
//  * Receive: receive(datagram, arrival_s) takes one UDP payload (from the socket, a recording
//    or a test) and hands its PDUs to the handlers below; before_step polls the socket into it.
//    arrival_s is the bridge clock (steady seconds, clock_s()). set_source() replaces the socket
//    by another source of datagrams (run --replay: a recording, node/replay_feed.hpp), called
//    each tick with the bridge clock, which is then the scenario clock (world t, s).
//  * Dating (issue 11): a received Entity State's relative timestamp gives its age past the least
//    delayed one of its entity (net/remote_table.hpp), counted from arrival_s; the remote copy is
//    dead-reckoned from there to the start of each tick (RemoteEntities::mirror(now)). Paced
//    (BridgeOptions::paced: the tick runs on the wall clock), a datagram from the socket
//    arrives at its own time: the transport's (the kernel's receive timestamp, net/transport.hpp,
//    on the steady clock that is then the bridge clock), clamped to the interval since the
//    previous poll. Dated instead with the start of the tick that read it (as before), a copy
//    was a whole tick behind when its datagrams came just after the receiver's tick began, and
//    right when just before: a few ms of tick phase between two nodes decided (issue 11, dr-error).
//    Unpaced (tests, the fuzz target) the wall clock means nothing to the scenario: every
//    datagram read in a tick is dated with that tick's start, as before.
//  * Threading: the bridge runs on the tick's thread; the per-vehicle local-frame work of
//    publishing (acceleration filter, yaw rate, the dead-reckoning bound of dr_bound.hpp) runs on
//    the Simulation's worker threads (Simulation::jobs), each vehicle into its own slot; then, in
//    order on the tick's thread, the vehicles the bound cannot clear get their exact ECEF state
//    and DR test and are sent: the same PDUs for any thread count. The exact tests (geodesy,
//    the DR test, and for its outcome the publisher's next state, the new anchor and the Entity
//    State) are made on the workers too, a batch ahead of that loop in its order, each into its
//    own slot; the loop takes a vehicle's when it reaches it (what it would compute there; those
//    it does not reach are dropped) and only sends, in order.
//  * Net out cost: a vehicle is turned into ECEF / DIS terms (geodesy) only when it may need an
//    Entity State (dr_bound.hpp: exactly the vehicles the exact DR test would send, never an
//    approximation), when its damage or cell changed, or when it is sent; past the per-tick cap
//    a vehicle that would only be deferred is not looked at (it changes nothing).
//  * Local vehicles (ents.local && ents.node == --node) go out as Entity State PDUs: ECEF
//    position (m), DIS Euler angles (rad), ECEF velocity (m/s) and acceleration (m/s^2, the
//    per-tick local-frame velocity change low-pass filtered over 0.5 s, zero at rest, turned
//    into ECEF axes when sent by the local->ECEF Jacobian at the vehicle; before issue 13 the
//    filter ran on ECEF velocities, which needed every vehicle's geodesy every tick; the two
//    differ by the Earth's curvature, ~v^2/R = 2e-5 m/s^2 at 10 m/s), yaw rate (rad/s,
//    body z), timestamp = the scenario time of the state (after the tick's step), the kind's
//    DIS type, marking = scenario id, damage in appearance bits 3-4 (dis_mapping.hpp), DR
//    algorithm RVW, sent when the DrPublisher says so (1 m /
//    3 deg / 5 s heartbeat) or when the appearance changes (the first one and a damage change
//    are repeated twice, 0.5 s apart: a lost datagram would hide them until the heartbeat).
//    Entity id = (site,
//    application + k * 4096, e % 32767 + 1) for entity index e, k = e / 32767 (ownership.hpp:
//    a node may own more than the 32,767 numbers of one application; receivers bind an entity
//    by its full id; every node loads the same scenario, so indices agree). One PDU a datagram (Wireshark 4.0
//    decodes only the first PDU of a datagram), at most 128 a tick (the rest follow on the next
//    ticks, round robin; a damage change never waits); NPSNET_DIS_PACK=1 packs a tick's Entity
//    States several to a datagram (at most 1400 octets).
//  * Collisions across nodes (collision_exchange.cpp): ownership.hpp decides who decides. The
//    decider applies the outcome to both sides in its world (its remote copy is display only)
//    and sends, after the Entity State of its own side, a Collision PDU: issuing = its entity,
//    colliding = the other, velocity/mass = the issuing entity's before the collision,
//    collision_type 1 = elastic (bounce) or 0 = inelastic (stop, kill), and the outcome itself
//    in octet 31 (collision_outcome.hpp; PDUs without it: kill when the issuer's appearance says
//    destroyed, else stop). It repeats the PDU unchanged every heartbeat (repeat_ledger.hpp, as
//    Detonations). The owner of the colliding entity injects the same collision record (same
//    pair, same outcomes) and applies the outcome to its own entity once, whoever repeats it (a
//    bounce by collision::bounce_impulse, with the PDU's mass; a mass of 0 or not finite, as
//    simulators that leave it unset send: the mass of the issuer's kind, the kind its DIS type
//    maps to); a PDU naming an entity not (yet) known here is not noted, so a repeat can apply.
//  * Fixed objects whose state changes are published as cultural-feature Entity States (kind 5,
//    the object kind's DIS type): entity id (site, 0x8000 | application, object index + 1),
//    damage in the standard appearance bits 3-4 (as vehicles, dis_mapping.hpp; was the state
//    index); heartbeat 5 s. Receivers move the same object forward to that
//    state (a state never goes back). Objects past index 65534 cannot be numbered: counted and
//    reported once on stderr.
//  * Every local fire sends a Fire PDU and every local detonation a Detonation PDU (munition
//    type = the kind's DIS type, warhead 1000 HE, fuse 1000 contact, quantity 1, result 1 entity
//    impact / 3 ground impact). A remote Detonation is queued with Simulation::inject_detonation
//    with the effect its descriptor has here (munition_table.hpp: our kind, or a generic class
//    such as smoke: no crater, no blast, no damage) and its result allows (munition_codes.hpp:
//    no crater for a dud, an entity impact, an airburst; nothing at all for a dud); a burst of
//    `quantity` rounds adds each round's blast levels. Its event names the warhead and fuse
//    classes and the quantity; a timed or proximity fuse bursting above the ground (result
//    other/detonation, higher than the kind's crater radius) is logged as an airburst.
//  * Area of interest (--aoi CELL_M, area_of_interest.hpp): each Entity State goes to the group
//    of the cell its entity is in, and at once (past the per-tick cap) when that cell's group
//    changed; a Fire to the group of the round's cell, a Detonation to the group of its point,
//    a Collision PDU to the group of the colliding entity (whose owner holds that cell), a
//    cultural feature to its object's cell, the end-of-run deactivation to each vehicle's cell.
//    NPSNET_DIS_PACK is ignored with --aoi (a datagram goes to one group).
//  * Counters (net::Counters::summary) and the remote entities (id, safe marking, type, owner,
//    last update age, damage) are printed at the end of a run and on SIGUSR1.
//  * PDUs with our (site, application) that are not our echo (net::Session: not a datagram we
//    sent) mean another simulator uses our identity: reported once on stderr and as an event
//    id_clash (site, application); its PDUs are ignored.
//  * --dis-version 6|7: the protocol version of everything we send (default 7); 5, 6 and 7 are
//    received.
// Every change to the world goes through world::Changes (Simulation::inject), except the remote
// state stage (remote_entities.hpp: pose, velocity, active flag of remote entities).
// Nothing received from the network throws or aborts; hot paths allocate only when an entity
// joins or a munition from the network detonates.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "net/net.hpp"
#include "node/area_of_interest.hpp"
#include "node/bridge_options.hpp"
#include "node/event_log.hpp"
#include "node/repeat_ledger.hpp"
#include "node/dr_bound.hpp"
#include "node/ownership.hpp"
#include "node/remote_entities.hpp"
#include "node/simulation.hpp"
#include "node/usr1_signal.hpp"

namespace npsnet::node {

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
  // Joining a running exercise (run.cpp): while catching up, the node replays its past ticks
  // headless: the bridge neither receives nor sends, the chained on_tick (snapshots) is not
  // called, and the fixed objects this node's vehicles changed are only noted (published from
  // the join on, with their heartbeat). catch_up(false) goes live: every local vehicle's Entity
  // State and every noted object go out at the next tick (a new entity announced at once).
  void catch_up(bool on);
  bool catching_up() const { return catching_up_; }
  // Our round m's network identity, when its Fire PDU went out: the Fire's event number and the
  // munition's DIS entity id (node/checkpoint.hpp keeps it for a restart).
  bool round_identity(int m, std::uint16_t& event, net::EntityId& munition) const;
  // A restart put our round m back in flight (node/checkpoint.hpp): it detonates under the
  // identity its Fire PDU gave it. Detonating while the node still catches up, its Detonation goes
  // out when the node goes live (then repeated as every Detonation of ours).
  void adopt_round(int m, std::uint16_t event, const net::EntityId& munition);

  // The receive path: one datagram's bytes, arrived at arrival_s (bridge clock, s). Any bytes.
  void receive(std::span<const std::uint8_t> datagram, double arrival_s);
  // The bridge clock: steady seconds, or scenario seconds with a source.
  double clock_s() const;
  // A source of datagrams besides the socket: called in before_step with the bridge clock, it
  // hands receive() every datagram that has arrived by then.
  using DatagramSource = std::function<void(double now_s, NetBridge& bridge)>;
  void set_source(DatagramSource source);

  void before_step(world::World& w);
  bool decides(const collision::Contact& c);
  void after_tick(const TickReport& r);

  const net::Counters& counters() const { return session_->counters(); }
  // Counters plus the Entity State rate of the local vehicles, then one line per remote entity
  // (RemoteEntities::listing: id, marking made safe, type, owner, last update age, damage).
  std::string summary() const;
  // Entity State PDUs sent for local ground vehicles, their number, and seconds published.
  std::uint64_t ground_es_sent() const { return ground_es_sent_; }
  int ground_vehicles() const { return ground_vehicles_; }
  double published_s() const { return now_s_ - start_s_; }
  // Local vehicles turned into ECEF for the dead-reckoning test so far (dr_bound.hpp), and a
  // digest (FNV-1a) of the kinematics, ids, appearance and timestamp of every Entity State sent.
  std::uint64_t exact_dr_tests() const { return exact_tests_; }
  std::uint64_t entity_state_digest() const { return es_digest_; }
  // Handles a pending SIGUSR1 (prints the summary to stderr).
  void check_signal();

  // Simulation management (sim_management.cpp). frozen() says whether the scenario clock stands
  // still now (a Stop/Freeze took effect at its real-world time and no Start/Resume has yet);
  // while it does, the run loop calls idle() instead of ticking: it receives (Entity States only
  // when the freeze's frozen behaviour has "process updates", bit 2), answers simulation
  // management, and sends heartbeats of our vehicles standing still with the Frozen Status
  // appearance bit (21) only when it has "transmit updates" (bit 1). Start/Resume restarts the
  // clock at its real-world time and, when its simulation time is not zero, at that scenario
  // time (s); else, when the freeze had "run simulation clock" (bit 0), at the scenario time the
  // clock ran to meanwhile (the entities stood still), else where it stopped. Remove Entity (receiving id = one of our vehicles, or entity 0xFFFF = all of
  // them) takes it out: a deactivation Entity State, no more publishing, inactive here.
  bool frozen();
  void idle();

 private:
  net::EntityId own_id(int e) const { return ownership_.own_id(e); }
  // Whether an id is (site, one of our applications): ours, whatever its number.
  bool ours(const net::EntityId& id) const { return id.site == opt_.site && ownership_.own_application(id.application); }
  bool is_own_vehicle(int e) const;
  // Our own entity (vehicle) named by a received id, or -1.
  int own_entity_of(const net::EntityId& id) const;
  // The id a PDU gives entity e: its remote id, or ours.
  net::EntityId net_id(int e) const;
  net::EventId next_event();
  nlohmann::json event(const char* type) const;

  void on_cultural(const net::EntityStatePdu& p);
  // A Collision PDU received: applied (try_collision) at once, or, when an entity it names is
  // not known here yet (its first Entity State lost or still to come: a late joiner, a partition),
  // kept in waiting_collisions_ and tried again each tick (retry_waiting_collisions) for one DIS
  // timeout from its arrival; so it applies the tick the entity appears, not a heartbeat later
  // at the next repeat (and not never, when the repeats stopped: the issuer dead, nobody adopting).
  void on_collision(const net::CollisionPdu& p, double arrival_s);
  enum class CollisionWait { Done, Waits };
  CollisionWait try_collision(const net::CollisionPdu& p, double arrival_s);
  void retry_waiting_collisions();
  // Whether a PDU's relative timestamp (an NPSNET node's: scenario time, s past the hour) is
  // before the scenario time this node joined a running exercise at (never when it did not join;
  // a PDU more than 30 min older than the join reads as newer: timestamps wrap at the hour).
  bool dated_before_join(std::uint32_t timestamp) const;
  // A collision of our vehicle `own` from before we joined, outcome res (other: -1 when unknown).
  void past_collision(int own, int other, world::Result res);
  void on_fire(const net::FirePdu& p);
  void on_detonation(const net::DetonationPdu& p, double arrival_s);
  void publish_vehicles();
  void digest_entity_state(const net::EntityStatePdu& es);  // into es_digest_
  void publish_collisions(const TickReport& r);
  void publish_fixed(const TickReport& r);
  void start_publishing(int o);  // object o joins fixed_published_ (sent each heartbeat from now)
  void publish_fires(const TickReport& r);
  void publish_detonations(const TickReport& r);
  void send_cultural(int object);
  void send_deactivation(int e);
  bool addressed_to_us(const net::EntityId& receiving) const;
  void acknowledge(const net::EntityId& to, std::uint16_t flag, std::uint16_t response, std::uint32_t request);
  void on_stop_freeze(const net::StopFreezePdu& p);
  void on_start_resume(const net::StartResumePdu& p);
  void on_remove_entity(const net::RemoveEntityPdu& p);
  bool pack(const net::EntityStatePdu& es);  // into batch_ (flushed when full); false: too big
  void flush_batch();
  void report_clash();
  // Reads the socket into receive(), each datagram dated as the contract says (Receive).
  void poll_socket();
  // The group a PDU about the local point p goes to (the --net destination without --aoi).
  std::uint32_t group_at(const Vec3& p) const { return aoi_ ? aoi_->group_at(p) : net::Session::kDestination; }

  BridgeOptions opt_;
  std::shared_ptr<const MunitionTable> munitions_;
  Simulation& sim_;
  EventLog& log_;
  std::unique_ptr<net::Session> session_;
  RemoteEntities remotes_;
  Ownership ownership_;
  Usr1Signal usr1_;
  std::uint16_t cultural_app_;
  double start_s_ = 0, now_s_ = 0;
  double polled_s_ = 0;  // bridge clock of the last socket poll
  bool started_ = false;
  bool catching_up_ = false;
  double joined_t_ = -1;  // scenario time (s) this node joined a running exercise at; -1: from the start

  // Local vehicles we publish (world indices), one DrPublisher each.
  std::vector<int> own_;
  std::vector<net::DrPublisher> pubs_;
  std::vector<std::uint32_t> sent_appearance_;
  std::vector<Vec3> prev_vel_;  // per own vehicle: last tick's local velocity, m/s
  std::vector<Vec3> accel_;     // per own vehicle: filtered local acceleration, m/s^2
  std::vector<float> yaw_rate_;  // per own vehicle: this tick's heading change, rad/s
  std::vector<DrAnchor> anchors_;  // per own vehicle: its last exact DR test (dr_bound.hpp)
  // per own vehicle: dr_quick(anchors_[i], pubs_[i]), made again whenever either changes (the
  // serial loop of publish_vehicles); all that the per-vehicle pass reads of them
  std::vector<DrQuick> quick_;
  std::vector<std::vector<std::uint32_t>> due_;  // per range of own vehicles: not removed, and the Entity State maybe due
  std::vector<std::vector<std::uint32_t>> altered_;  // per range: those of due_ whose damage or group changed
  std::vector<size_t> altered_at_;  // this tick: the changed vehicles' places in order_, ascending
  std::vector<std::uint8_t> changed_;  // per own vehicle: this tick, damage or group not as last sent
  std::vector<std::uint32_t> order_;  // this tick's own vehicles not skipped, in round-robin order
  // One vehicle's exact test (vehicle_publish.cpp), made by test_vehicle on the pool ahead of
  // the serial loop or by the loop itself: its exact state and that state's anchor (exact_state),
  // whether it is to be sent (damage or group changed, a quick repeat due, or the DR test), and
  // what the vehicle's publisher, anchor and quick bound become then: sent (next_pub marked sent,
  // es its Entity State) or not (next_anchor rebased on its publisher as it is).
  struct Tested {
    DrAnchor anchor, next_anchor;
    net::KinematicState state;
    DrQuick next_quick;
    net::DrPublisher next_pub;
    net::EntityStatePdu es;
    bool send = false, repeat = false;
  };
  // Reads the world and vehicle i's fields only (any thread; writes r alone).
  void test_vehicle(size_t i, double t, Tested& r) const;
  std::vector<Tested> tested_;  // the batch made ahead on the pool
  Tested tested_here_;          // one the loop makes itself
  std::uint64_t exact_tests_ = 0;   // vehicles turned into ECEF for the DR test, all ticks
  std::uint64_t es_digest_ = 1469598103934665603ull;  // FNV-1a of every Entity State sent
  std::vector<std::uint32_t> sent_group_;  // per own vehicle: the group of its last Entity State
  std::unique_ptr<AreaOfInterest> aoi_;
  std::vector<float> prev_heading_;
  std::vector<std::uint8_t> removed_;  // per local vehicle: taken out by a Remove Entity
  std::vector<std::uint8_t> announce_left_;  // per own vehicle: quick repeats still to send
  std::vector<double> announce_at_;          // per own vehicle: scenario time of the next one
  // Simulation management: pending freeze / resume (UNIX s, -1 none), scenario time to resume at.
  double freeze_at_ = -1, resume_at_ = -1, resume_sim_t_ = -1, frozen_hb_s_ = 0;
  double frozen_since_ = 0, frozen_t_ = 0;  // UNIX s and scenario time the clock stopped at
  bool frozen_ = false;
  std::uint8_t frozen_behavior_ = 0;
  std::uint64_t ground_es_sent_ = 0;
  int ground_vehicles_ = 0;
  net::EntityStatePdu es_;      // reused
  net::DatagramBuilder batch_;  // this tick's Entity States, packed (1400 octets a datagram)
  bool pack_ = false;           // NPSNET_DIS_PACK=1
  bool clash_reported_ = false;  // another simulator using our (site, application): said once
  size_t rr_ = 0;               // first local vehicle looked at next tick (send cap round robin)

  // Fixed objects: the state last published or heard (-1: never), heartbeat times.
  std::vector<int16_t> fixed_net_state_;
  std::vector<int> fixed_published_;     // objects we publish
  std::vector<double> fixed_last_sent_;  // per published object
  std::vector<int> fixed_slot_;          // per fixed object: its index in fixed_published_, or -1
  std::uint64_t fixed_unnumbered_ = 0;   // changed objects past the last cultural entity number
  std::unordered_map<int, std::uint16_t> fire_event_;  // munition index -> event number
  std::unordered_map<int, net::EntityId> round_id_;    // adopt_round: munition index -> its old DIS id
  struct CaughtUpDetonation {
    net::DetonationPdu pdu;
    std::uint32_t group;
  };
  std::vector<CaughtUpDetonation> caught_up_detonations_;  // sent when the node goes live
  DetonationLedger detonations_;  // ours repeated every heartbeat; received ones applied once
  CollisionLedger collisions_;    // the same for Collision PDUs
  struct WaitingCollision {
    net::CollisionPdu pdu;
    std::uint64_t key;  // repeat_key(pdu)
    double first_s;     // bridge time it first arrived
  };
  static constexpr std::size_t kMaxWaitingCollisions = 256;  // past it the oldest gives up
  std::vector<WaitingCollision> waiting_collisions_;
  std::uint64_t collisions_given_up_ = 0;  // waited a DIS timeout, or pushed out by the cap
  double drop_detonations_s_ = 0;  // test hook NPSNET_TEST_DROP_DETONATIONS_S (bridge_options.hpp)
  std::uint64_t dropped_detonations_ = 0;
  std::uint16_t event_number_ = 0;
  world::Changes inject_;  // reused for injected changes
  std::function<void(const TickReport&)> chained_on_tick_;
  DatagramSource source_;  // empty: the socket only
};

}  // namespace npsnet::node
