// One node's simulation: the fixed-step tick of shared/ARCHITECTURE.md, without I/O pacing.
//   scheduled fires -> dynamics::step -> collision::detect -> collision::respond (+ detonations)
//   -> world::apply -> events.
// Every collision, damage change, fire, detonation and crater goes to the event log.
#pragma once
#include <functional>
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
  world::World& world() { return w_; }
  const world::World& world() const { return w_; }
  double dt() const { return dt_; }
  // Sets the scenario clock to t seconds (rounded to a whole tick): a Start/Resume's simulation
  // time. Scheduled fires before t that have not happened go at the next tick.
  void set_time(double t);
  const collision::DetectStats& stats() const { return detector_.stats(); }
  std::function<void(const TickReport&)> on_tick;  // renderer, snapshots, network
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
  void inject(const world::Changes& c);
  void inject_detonation(const world::DetonationRecord& d);

  // Fires `munition_kind` from `shooter` at an entity or a point, logging the fire event.
  // point and target_name by value: callers pass references into the entity arrays, which grow.
  int fire(int shooter, int munition_kind, Vec3 point, int target_entity, std::string target_name);
  int find_entity(const std::string& id) const;

 private:
  void scheduled_fires();
  void threatened(int shooter, const Vec3& at, int victim);
  nlohmann::json base(const char* type) const;
  void log_changes();

  world::World w_;
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
  collision::Detector detector_;
  collision::RespondScratch respond_scratch_;
  std::vector<collision::Contact> contacts_;
  std::vector<dynamics::GroundImpact> impacts_;
  std::vector<dynamics::Crash> crashes_;
  int driven_ = -1;
  std::vector<int> fired_;
  world::Changes changes_, injected_;
  std::vector<world::DetonationRecord> injected_detonations_;
  world::Applied applied_;
};

}  // namespace npsnet::node
