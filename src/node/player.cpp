#include "node/player.hpp"

#include <cmath>
#include <cstdio>

#include "world/error.hpp"

namespace npsnet::node {

namespace {
bool is_vehicle(const world::World& w, int e) {
  const auto m = w.kinds[w.ents.kind[e]].mobility;
  return m == world::Mobility::Ground || m == world::Mobility::Ship || m == world::Mobility::Air;
}
}  // namespace

int Player::first_vehicle(const world::World& w, int node, bool own_any, const std::string& drive_id,
                          const std::vector<input::Action>& script, const std::string& script_file) {
  std::vector<world::Problem> problems;
  auto ours = [&](int e) { return drivable(w, e) && (own_any || w.ents.node[e] == node); };
  auto own = [&](const std::string& id) {
    for (size_t e = 0; e < w.ents.size(); ++e)
      if (w.ents.id[e] == id) return ours(static_cast<int>(e)) ? static_cast<int>(e) : -1;
    return -1;
  };
  int first = -1;
  if (drive_id.empty()) {
    for (int e = 0; e < static_cast<int>(w.ents.size()) && first < 0; ++e)
      if (drivable(w, e) && w.ents.node[e] == node) first = e;
    if (first < 0) problems.push_back({"--drive", 0, "drive", "this node drives no vehicle"});
  } else {
    first = own(drive_id);
    if (first < 0) problems.push_back({"--drive", 0, "drive", "'" + drive_id + "' is not a live vehicle of this node"});
  }
  for (const auto& a : script)
    if (a.type == input::ActionType::Switch && !a.to.empty() && own(a.to) < 0)
      problems.push_back({script_file, a.line, "to", "'" + a.to + "' is not a vehicle of this node"});
  if (!problems.empty()) throw world::InputError(std::move(problems));
  return first;
}

Player::Player(Simulation& sim, EventLog& log, int first, std::vector<input::Action> script)
    : sim_(sim), log_(log), script_(std::move(script)), first_(first) {}

bool Player::drivable(const world::World& w, int e) {
  if (e < 0 || e >= static_cast<int>(w.ents.size()) || !w.ents.active[e] || !w.ents.local[e] || !is_vehicle(w, e)) return false;
  return w.ents.state[e] + 1 < static_cast<int>(w.kinds[w.ents.kind[e]].states.size());
}

int Player::next_live(const world::World& w, int after) {
  const int n = static_cast<int>(w.ents.size());
  for (int k = 1; k <= n; ++k) {
    const int e = ((after < 0 ? -1 : after) + k) % n;
    if (drivable(w, e)) return e;
  }
  return -1;
}

void Player::switch_to(int e) {
  if (e < 0 || e == sim_.driven()) return;
  sim_.set_driven(e);
  sim_.controls = {};
  const auto& w = sim_.world();
  log_.write({{"event", "drive"}, {"t", std::round(w.t * 1000) / 1000}, {"frame", w.frame}, {"vehicle", w.ents.id[e]}});
}

void Player::push(const std::vector<input::TimedAction>& live) { live_.insert(live_.end(), live.begin(), live.end()); }

void Player::apply(const input::Action& a) {
  using input::ActionType;
  auto& w = sim_.world();
  const int d = sim_.driven();
  switch (a.type) {
    case ActionType::Throttle: sim_.controls.throttle = a.value; break;
    case ActionType::Steer: sim_.controls.steer = a.value; break;
    case ActionType::Climb: sim_.controls.climb = a.value; break;
    case ActionType::Fire: {
      if (!drivable(d)) break;
      const int m = w.kinds.find(w.kinds[w.ents.kind[d]].munition);
      if (m < 0) break;
      const dynamics::Aim aim = dynamics::aim_from(w, d);
      sim_.fire(d, m, aim.point, aim.target, aim.target >= 0 ? w.ents.id[aim.target] : "");
      break;
    }
    case ActionType::Switch: {
      const int to = a.to.empty() ? next_live(d) : sim_.find_entity(a.to);
      if (drivable(to)) switch_to(to);
      else std::fprintf(stderr, "npsnet: t = %.2f: switch: '%s' is not a live vehicle of this node\n", w.t, a.to.c_str());
      break;
    }
    case ActionType::Camera: camera_ = a.camera ? *a.camera : input::next_camera(camera_); break;
    case ActionType::Quit: quit_ = true; break;
  }
  if (recorder_) {
    input::Action rec = a;
    rec.t = w.t;
    if (a.type == ActionType::Camera) rec.camera = camera_;  // the mode it became
    if (a.type == ActionType::Switch && sim_.driven() >= 0) rec.to = w.ents.id[sim_.driven()];
    recorder_->write(rec);
  }
}

void Player::before_dynamics() {
  auto& w = sim_.world();
  if (!started_) {
    started_ = true;
    switch_to(first_);
  }
  if (sim_.driven() >= 0 && !drivable(sim_.driven())) {  // killed: the wreck stays, the player moves on
    const int n = next_live(sim_.driven());
    if (n >= 0) switch_to(n);
  }
  applied_wall_s_ = -1;
  while (next_ < script_.size() && script_[next_].t <= w.t + 1e-6) apply(script_[next_++]);
  for (const auto& ta : live_) {
    apply(ta.action);
    if (input::is_axis(ta.action.type) && (applied_wall_s_ < 0 || ta.wall_s < applied_wall_s_)) applied_wall_s_ = ta.wall_s;
  }
  live_.clear();
}

}  // namespace npsnet::node
