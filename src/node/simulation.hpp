// One node's simulation: the fixed-step tick of shared/ARCHITECTURE.md, without I/O pacing.
// The tick flows one way, in this order:
//   1. net in (before_step): the bridge mirrors remote entities (their joins, removals and poses,
//      world::Mirror, applied at once by world::apply through apply_net_in) and queues what
//      other nodes decided (inject / inject_detonation);
//   2. fire orders (scenario schedule, then the player, before_dynamics): each dynamics::fire
//      decision and the target's autonomous reaction (dynamics::react_to_fire) is applied by
//      world::apply at once, in the order decided, and logged;
//   3. dynamics::step / drive: the integrator moves local entities (poses, velocities only);
//   4. collision::detect (const world) -> contacts this node decides;
//   5. collision::respond + injected changes + detonations (impacts, other nodes' rounds) +
//      aircraft ground contacts -> Changes -> before_apply (imminent snapshots) -> world::apply
//      -> events;
//   6. autonomous reactions to this tick's detonations: decided, applied, logged as in 2;
//   7. on_tick (renderer, snapshots, net out), then the clock advances.
// Nothing else changes the world. Every collision, damage change, fire, detonation and crater
// goes to the event log.
// Threading: a Simulation and its World belong to one thread (the tick's). With set_threads(n),
// n > 1, stages 3 (dynamics::step, per range of vehicles) and 4 (collision::detect: sweeps, fixed
// tests, pair search, narrow phase) fan out to a core::Jobs pool of n threads; every range writes
// only its own entities or its own buffers, merged in a fixed order: the event log and the world
// are the same bytes for any thread count (tests/node/test_threads.cpp). Everything else runs on
// the tick's thread.
#pragma once
#include <deque>
#include <functional>
#include <memory>
#include <vector>

#include "collision/collision.hpp"
#include "dynamics/drive.hpp"
#include "dynamics/dynamics.hpp"
#include "node/event_log.hpp"
#include "world/changes.hpp"
#include "world/scenario.hpp"

namespace npsnet::node {

// What one tick did (valid during the on_tick callback).
struct TickReport {
  const world::Changes& changes;
  const world::Applied& applied;
  const std::vector<int>& fired;  // munitions launched this tick
};

class Simulation {
 public:
  Simulation(world::World w, const world::Scenario& s, EventLog& log, double dt);
  void tick();
  // Threads for the tick's parallel stages (1 = none besides the caller, the default; clamped to
  // [1, core::Jobs::kMaxThreads]). max_grain > 0 caps the stages' grain (core::Jobs::set_max_grain;
  // tests: 1 splits every stage however small).
  void set_threads(int n, size_t max_grain = 0);
  int threads() const { return jobs_ ? jobs_->threads() : 1; }
  // The worker pool (nullptr with one thread): other stages of the tick on its thread may use it.
  core::Jobs* jobs() { return jobs_.get(); }
  world::World& world() { return w_; }
  const world::World& world() const { return w_; }
  double dt() const { return dt_; }
  // Sets the scenario clock to t seconds (rounded to a whole tick): a Start/Resume's simulation
  // time. Scheduled fires before t that have not happened go at the next tick.
  void set_time(double t);
  const collision::DetectStats& stats() const { return detector_.stats(); }
  // The viewers' view volumes (the player's camera, ...): pairs seen get the exact tier (auto).
  void set_views(const std::vector<collision::ViewVolume>& v) { detector_.set_views(v); }
  const collision::Detector& detector() const { return detector_; }
  // Every crater made so far (local and remote rounds), in order (--state-out).
  const std::vector<world::Crater>& craters() const { return craters_; }
  std::function<void(const TickReport&)> on_tick;  // renderer, snapshots, network
  // Runs after dynamics, before collision::detect (stage 4), on the world as this tick leaves it:
  // the node sets the views it will render after the tick (set_views; run.cpp).
  std::function<void(const world::World&)> before_detect;
  // Runs after the outcomes are decided, before they are applied (imminent snapshots).
  std::function<void(const world::World&, const world::Changes&)> before_apply;
  // Network hooks (the net<->world bridge):
  //  before_step runs first in every tick (remote entity poses, received PDUs);
  //  decides(contact) says whether this node decides a contact (the owner of the lower DIS
  //  entity id does); contacts it does not decide are left to the other node;
  //  inject(changes) queues changes decided elsewhere (Collision PDUs, remote damage and
  //  kinds, remote fixed-object states), applied and logged in this tick's apply step;
  //  inject_detonation(d) queues another node's detonation (d.munition = -1): after the
  //  injected changes, collision::detonate works out its crater and blast into this tick's
  //  changes, applied and logged with them.
  std::function<void(world::World&)> before_step;
  // The player (player.hpp): runs after the scheduled fires, before dynamics (its fire and switch).
  std::function<void()> before_dynamics;
  // The vehicle a player drives (-1: none): dynamics::drive moves it by `controls` instead of its
  // route; an aircraft meeting the ground becomes a collision (collision/ground.hpp).
  void set_driven(int e);
  int driven() const { return driven_; }
  dynamics::Controls controls;
  std::function<bool(const collision::Contact&)> decides;
  void inject(const world::Changes& c);  // no mirrors: those go through apply_net_in
  // Stage 1 only (from before_step or a frozen node's idle): applies remote entities' mirrors
  // (c.mirrors: joins, activity, poses; world/changes.hpp) with world::apply at once.
  void apply_net_in(const world::Changes& c);
  void inject_detonation(const world::DetonationRecord& d);

  // Fires `munition_kind` from `shooter` at an entity or a point, logging the fire event.
  // point and target_name by value: callers pass references into the entity arrays, which grow.
  int fire(int shooter, int munition_kind, Vec3 point, int target_entity, std::string target_name);
  // While fire is held, fire() launches nothing and returns -1 (scheduled fires, the player's,
  // autonomous return fire): a node catching up to a running exercise (run.cpp) does not fire
  // again the rounds of its earlier process, nor those a late joiner would have fired before it
  // joined; their craters arrive from the network (node/repeat_ledger.hpp).
  void hold_fire(bool held) { fire_held_ = held; }
  int find_entity(const std::string& id) const;
  // Launches l between ticks as a round already in flight (a restored checkpoint,
  // node/checkpoint.hpp): no fire event, no Fire PDU (its old process sent one). Returns its slot.
  int relaunch(const world::Launch& l);
  // Entity e was put somewhere else between ticks (node/checkpoint.hpp): no turn over the move.
  void placed(int e) { detector_.forget_turn(e); }

 private:
  void scheduled_fires();
  void threatened(int shooter, int victim);
  void apply_now(const world::Changes& c);  // stages 2 and 6: one decision, applied at once
  nlohmann::json base(const char* type) const;
  void log_changes();

  world::World w_;
  std::vector<world::Crater> craters_;
  EventLog& log_;
  double dt_;
  struct Scheduled {
    double t;
    int shooter, munition, target_entity, target_fixed;
    Vec3 point;
    std::string target_name;
  };
  std::vector<Scheduled> schedule_;
  size_t next_fire_ = 0;
  std::unique_ptr<core::Jobs> jobs_;
  collision::Detector detector_;
  collision::RespondScratch respond_scratch_;
  std::vector<collision::Contact> contacts_;
  std::vector<dynamics::GroundImpact> impacts_;
  core::HeadingMemo heading_dirs_;  // dynamics::step's and collision::detect's, from tick to tick
  std::vector<dynamics::Crash> crashes_;
  int driven_ = -1;
  bool fire_held_ = false;
  std::vector<int> fired_;
  world::Changes changes_, injected_, now_;
  world::Applied now_applied_;
  std::deque<std::pair<int64_t, int>> spent_;  // (frame, slot) of local rounds spent, oldest first
  std::vector<world::DetonationRecord> injected_detonations_;
  world::Applied applied_, net_in_applied_;
};

}  // namespace npsnet::node
