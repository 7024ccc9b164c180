// The player of this node (shared/ARCHITECTURE.md, "Player"): which vehicle it drives, the
// actions it takes (from an input file by scenario time, and from live devices as they come),
// its camera. Each tick, before dynamics (Simulation::before_dynamics), the actions due are
// applied in order: axes set Simulation::controls, `fire` fires the driven vehicle's munition
// (kind data) where it points (dynamics::aim_from) through Simulation::fire like every scheduled
// fire, `switch` moves to the next live vehicle of this node (or the one named) at once, `camera`
// sets the view, `quit` ends the run after this tick. Every applied action is recorded (with the
// scenario time it took effect) when recording, so a replay gives the same event log.
// A `drive` event (t, frame, vehicle) is logged at the start and whenever the vehicle changes; a
// driven vehicle that becomes a wreck is left (its wreck stays) for the next live one.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "input/action_file.hpp"
#include "input/devices.hpp"
#include "node/simulation.hpp"

namespace npsnet::node {

class Player {
 public:
  // The vehicle to start in: drive_id, or "" = the first vehicle of this node. Throws
  // world::InputError when drive_id, or a `switch` target of `script`, is not a vehicle of this
  // node (script_file names the file in the message). Call before anything is written. A vehicle
  // of this node: one marked `node = node`; with own_any (no network) a named one may be any.
  static int first_vehicle(const world::World& w, int node, bool own_any, const std::string& drive_id,
                           const std::vector<input::Action>& script, const std::string& script_file);
  // first: from first_vehicle(); the `drive` event for it is logged in the first tick.
  Player(Simulation& sim, EventLog& log, int first, std::vector<input::Action> script = {});
  void record_to(std::unique_ptr<input::ActionRecorder> rec) { recorder_ = std::move(rec); }
  // Actions from live devices: applied at the start of the next tick.
  void push(const std::vector<input::TimedAction>& live);
  void before_dynamics();  // Simulation::before_dynamics

  int driven() const { return sim_.driven(); }
  input::CameraMode camera() const { return camera_; }
  bool quit() const { return quit_; }
  // Wall time (steady clock) of the earliest device event applied in the last tick that moved
  // the controls, or < 0 (for input-to-photon latency: the first frame after it that shows it).
  double applied_device_wall_s() const { return applied_wall_s_; }

 private:
  void apply(const input::Action& a);
  void switch_to(int e);
  int next_live(int after) const { return next_live(sim_.world(), after); }
  static int next_live(const world::World& w, int after);
  bool drivable(int e) const { return drivable(sim_.world(), e); }
  static bool drivable(const world::World& w, int e);

  Simulation& sim_;
  EventLog& log_;
  std::vector<input::Action> script_;
  size_t next_ = 0;
  std::vector<input::TimedAction> live_;
  std::unique_ptr<input::ActionRecorder> recorder_;
  input::CameraMode camera_ = input::CameraMode::Driver;
  bool quit_ = false, started_ = false;
  int first_ = -1;
  double applied_wall_s_ = -1;
};

}  // namespace npsnet::node
