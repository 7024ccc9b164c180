// The window of a player's node (--window): feeds the live devices (input/devices.hpp) to the
// player before each tick, shows the player's camera with the driven vehicle's HUD and map after
// it, and keeps handling input while the tick loop waits for the wall clock.
// Input-to-photon latency: for a device event that moved the controls, the steady-clock time of
// the event and of the swap of the first frame drawn after the tick that applied it (its camera
// then differs from the frame before) are printed to stderr:
//   npsnet: input-to-photon: 41.3 ms (event 12345.678901 s, swapped 12345.720201 s, steady clock)
#pragma once
#include <chrono>
#include <memory>

#include "input/devices.hpp"
#include "node/player.hpp"
#include "node/snapshots.hpp"
#include "render/renderer.hpp"

namespace npsnet::node {

class PlayerWindow {
 public:
  PlayerWindow(Snapshots& snaps, Player* player);  // player may be null (no devices then)
  void before_tick();
  bool present(const Simulation& sim);  // false once the window is closed
  // The camera the next present() shows (the driven vehicle's, in the player's mode; else the last).
  render::Camera camera(const Simulation& sim) const;
  void wait_until(std::chrono::steady_clock::time_point deadline);

 private:
  Snapshots& snaps_;
  Player* player_;
  std::unique_ptr<input::Devices> devices_;
  double orbit_deg_ = 45, orbit_m_;
  render::Camera last_;
  double pending_event_s_ = -1;
  int reported_ = 0;
};

}  // namespace npsnet::node
