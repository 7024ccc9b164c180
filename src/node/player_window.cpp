#ifdef NPSNET_HAVE_RENDER
#include "node/player_window.hpp"

#include <algorithm>
#include <cstdio>

#include "node/cameras.hpp"

namespace npsnet::node {

namespace {
constexpr int kMaxLatencyReports = 50;
}

PlayerWindow::PlayerWindow(Snapshots& snaps, Player* player) : snaps_(snaps), player_(player), orbit_m_(kOrbitDefaultM) {
  if (player_ && snaps_.renderer().native_window()) devices_ = std::make_unique<input::Devices>(snaps_.renderer().native_window());
}

void PlayerWindow::before_tick() {
  if (devices_ && player_) player_->push(devices_->take());
}

bool PlayerWindow::present(const Simulation& sim) {
  const world::World& w = sim.world();
  if (devices_) {
    orbit_deg_ += devices_->take_orbit_deg();
    orbit_m_ = std::clamp(orbit_m_ * devices_->take_zoom(), 10.0, 2000.0);
  }
  const render::Camera cam = camera(sim);
  if (player_ && player_->applied_device_wall_s() >= 0 && pending_event_s_ < 0) pending_event_s_ = player_->applied_device_wall_s();
  const bool moved = (cam.eye - last_.eye).norm() > 1e-6 || (cam.target - last_.target).norm() > 1e-6;
  last_ = cam;
  const bool open = snaps_.present(w, cam, input::camera_name(player_ ? player_->camera() : input::CameraMode::Driver));
  if (pending_event_s_ >= 0 && moved) {
    const double swapped = input::steady_now_s();
    if (reported_++ < kMaxLatencyReports)
      std::fprintf(stderr, "npsnet: input-to-photon: %.1f ms (event %.6f s, swapped %.6f s, steady clock)\n",
                   1000 * (swapped - pending_event_s_), pending_event_s_, swapped);
    pending_event_s_ = -1;
  }
  return open;
}

render::Camera PlayerWindow::camera(const Simulation& sim) const {
  const int d = sim.driven();
  if (d < 0) return last_;
  return player_camera(sim.world(), sim.world().ents, d, player_ ? player_->camera() : input::CameraMode::Driver,
                       orbit_deg_, orbit_m_);
}

void PlayerWindow::wait_until(std::chrono::steady_clock::time_point deadline) {
  for (;;) {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) return;
    snaps_.renderer().wait_events(left);
  }
}

}  // namespace npsnet::node
#endif  // NPSNET_HAVE_RENDER
