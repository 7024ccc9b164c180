#include "node/simulation.hpp"

#include <algorithm>
#include <cassert>

#include "collision/ground.hpp"
#include "dynamics/autonomous.hpp"
#include "world/pose.hpp"

namespace npsnet::node {

namespace {
nlohmann::json vec(const Vec3& p) {
  auto r = [](double v) { return std::round(v * 1000.0) / 1000.0; };
  return nlohmann::json::array({r(p.x()), r(p.y()), r(p.z())});
}
double round3(double v) { return std::round(v * 1000.0) / 1000.0; }
}  // namespace

Simulation::Simulation(world::World w, const world::Scenario& s, EventLog& log, double dt)
    : w_(std::move(w)), log_(log), dt_(dt) {
  detector_ = collision::Detector(collision::options_from(s.collision_method, s.collision_tier, dt));
  detector_.set_budget_ms(s.collision_budget_ms);
  for (const auto& f : s.fires) {
    Scheduled sc{f.t_s, find_entity(f.shooter), w_.kinds.find(f.munition), -1, -1, Vec3::Zero(), f.target};
    if (f.target_m) {
      sc.point = Vec3(f.target_m->x(), f.target_m->y(), w_.terrain.height(f.target_m->x(), f.target_m->y()));
      sc.target_name = "";
    } else {
      sc.target_entity = find_entity(f.target);
      if (sc.target_entity < 0)
        for (size_t o = 0; o < w_.fixed.size(); ++o)
          if (w_.fixed.id[o] == f.target) sc.target_fixed = static_cast<int>(o);
    }
    schedule_.push_back(sc);
  }
  std::stable_sort(schedule_.begin(), schedule_.end(), [](const Scheduled& a, const Scheduled& b) { return a.t < b.t; });
}

int Simulation::find_entity(const std::string& id) const {
  for (size_t e = 0; e < w_.ents.size(); ++e)
    if (w_.ents.id[e] == id) return static_cast<int>(e);
  return -1;
}

nlohmann::json Simulation::base(const char* type) const {
  return {{"event", type}, {"t", round3(w_.t)}, {"frame", w_.frame}};
}

void Simulation::apply_now(const world::Changes& c) {
  now_applied_.clear();
  world::apply(w_, c, now_applied_);
}

int Simulation::relaunch(const world::Launch& l) {
  now_.clear();
  now_.launches.push_back(l);
  apply_now(now_);
  return now_applied_.launched.back();
}

int Simulation::fire(int shooter, int munition_kind, const Vec3 point, int target_entity, const std::string target_name) {
  if (fire_held_) return -1;
  auto launch = dynamics::fire(w_, shooter, munition_kind, point, target_entity);
  if (!launch) return -1;
  // Reclaim the slot of a round spent at least two ticks ago (no contact episode, PDU or
  // snapshot of this tick or the last still names it).
  if (!spent_.empty() && spent_.front().first + 2 <= w_.frame) {
    launch->slot = spent_.front().second;
    spent_.pop_front();
  }
  now_.clear();
  now_.launches.push_back(*launch);
  apply_now(now_);
  const int m = now_applied_.launched.back();
  fired_.push_back(m);
  auto ev = base("fire");
  ev["shooter"] = w_.ents.id[shooter];
  ev["munition"] = w_.kinds[munition_kind].name;
  ev["round"] = w_.ents.id[m];
  ev["target"] = target_name;
  ev["point"] = vec(point);
  log_.write(ev);
  if (target_entity >= 0) threatened(shooter, target_entity);
  return m;
}

void Simulation::threatened(int shooter, int victim) {
  world::EntityChange change;
  const auto r = dynamics::react_to_fire(w_, victim, shooter, change);
  if (r == dynamics::Reaction::None) return;
  now_.clear();
  now_.entities.push_back(change);
  apply_now(now_);
  auto ev = base("autonomous");
  ev["id"] = w_.ents.id[victim];
  ev["reaction"] = r == dynamics::Reaction::ReturnFire ? "return_fire" : "flee";
  ev["shooter"] = shooter >= 0 ? w_.ents.id[shooter] : "";
  log_.write(ev);
  if (r == dynamics::Reaction::ReturnFire)  // with its kind's munition (react_to_fire checked it)
    fire(victim, w_.kinds.find(w_.kinds[w_.ents.kind[victim]].munition), w_.ents.pos[shooter], shooter, w_.ents.id[shooter]);
}

void Simulation::scheduled_fires() {
  while (next_fire_ < schedule_.size() && schedule_[next_fire_].t <= w_.t + 1e-9) {
    const Scheduled& s = schedule_[next_fire_++];
    if (s.shooter < 0 || s.munition < 0) continue;
    if (!w_.ents.local[s.shooter]) continue;  // another node drives it: its node fires
    Vec3 point = s.point;
    if (s.target_entity >= 0) point = world::entity_centre(w_, s.target_entity);
    if (s.target_fixed >= 0) point = world::fixed_centre(w_, s.target_fixed);
    fire(s.shooter, s.munition, point, s.target_entity, s.target_name);
  }
}

void Simulation::log_changes() {
  const auto& ents = w_.ents;
  for (const auto& c : changes_.collisions) {
    auto ev = base("collision");
    ev["a"] = ents.id[c.a];
    const bool ground = !c.b_fixed && c.b < 0;
    ev["b"] = ground ? "ground" : c.b_fixed ? w_.fixed.id[c.b] : ents.id[c.b];
    ev["a_kind"] = w_.kinds[ents.kind[c.a]].name;
    ev["b_kind"] = ground ? "terrain" : c.b_fixed ? w_.kinds[w_.fixed.kind[c.b]].name : w_.kinds[ents.kind[c.b]].name;
    ev["point"] = vec(c.point);
    ev["closing_speed_mps"] = round3(c.closing_speed_mps);
    ev["angle_deg"] = round3(c.angle_deg);
    ev["method"] = c.method;
    ev["tier"] = c.tier;
    ev["outcome_a"] = world::result_name(c.result_a);
    ev["outcome_b"] = world::result_name(c.result_b);
    log_.write(ev);
  }
  for (const auto& d : changes_.detonations) {
    auto ev = base("detonation");
    ev["point"] = vec(d.point);
    ev["munition"] = *d.munition_name ? d.munition_name : w_.kinds[d.kind].name;
    ev["round"] = d.round;
    ev["shooter"] = d.shooter >= 0 ? ents.id[d.shooter] : "";
    ev["target"] = d.target >= 0 ? ents.id[d.target] : "";
    ev["result"] = d.result;
    if (*d.warhead) {  // another node's round: what its descriptor said
      ev["warhead"] = d.warhead;
      ev["fuse"] = d.fuse;
      ev["quantity"] = d.quantity;
    }
    log_.write(ev);
  }
  for (const auto& c : changes_.craters) {
    craters_.push_back(c);
    auto ev = base("crater");
    ev["point"] = vec(c.point);
    ev["radius_m"] = c.radius_m;
    ev["depth_m"] = c.depth_m;
    log_.write(ev);
  }
  for (const auto& d : applied_.damage) {
    auto ev = base("damage");
    const world::Kind& k = d.fixed ? w_.kinds[w_.fixed.kind[d.index]] : w_.kinds[ents.kind[d.index]];
    ev["object"] = d.fixed ? w_.fixed.id[d.index] : ents.id[d.index];
    ev["kind"] = k.name;
    ev["from_state"] = k.states[d.from_state];
    ev["to_state"] = k.states[d.to_state];
    if (!d.fixed && !ents.local[d.index]) ev["remote"] = true;  // as its owner's Entity State says
    log_.write(ev);
  }
}

namespace {
template <class T>
void append_vec(std::vector<T>& to, const std::vector<T>& from) {
  to.insert(to.end(), from.begin(), from.end());
}
void append(world::Changes& to, const world::Changes& from) {
  append_vec(to.entities, from.entities);
  append_vec(to.fixed, from.fixed);
  append_vec(to.craters, from.craters);
  append_vec(to.collisions, from.collisions);
  append_vec(to.detonations, from.detonations);
}
}  // namespace

void Simulation::set_driven(int e) {
  if (driven_ >= 0) w_.ents.driven[driven_] = 0;
  driven_ = e;
  if (e >= 0) w_.ents.driven[e] = 1;
}

void Simulation::set_threads(int n, size_t max_grain) {
  jobs_.reset();
  if (n > 1) jobs_ = std::make_unique<core::Jobs>(n);
  if (jobs_) jobs_->set_max_grain(max_grain);
  detector_.set_jobs(jobs_.get());
}

void Simulation::inject(const world::Changes& c) {
  assert(c.mirrors.empty());
  append(injected_, c);
}

void Simulation::apply_net_in(const world::Changes& c) {
  net_in_applied_.clear();
  world::apply(w_, c, net_in_applied_);
  assert(net_in_applied_.damage.empty() && net_in_applied_.launched.empty());
}
void Simulation::set_time(double t) {
  w_.frame = std::llround(std::max(0.0, t) / dt_);
  w_.t = w_.frame * dt_;
}
void Simulation::inject_detonation(const world::DetonationRecord& d) { injected_detonations_.push_back(d); }

void Simulation::tick() {
  if (jobs_) jobs_->wake();  // the workers spin through the tick's stages (core/jobs.hpp)
  fired_.clear();
  changes_.clear();
  applied_.clear();
  contacts_.clear();
  impacts_.clear();
  crashes_.clear();
  if (before_step) before_step(w_);
  scheduled_fires();
  if (before_dynamics) before_dynamics();
  dynamics::step(w_, dt_, impacts_, jobs_.get(), &heading_dirs_);
  if (driven_ >= 0 && w_.ents.driven[driven_] && w_.ents.local[driven_]) dynamics::drive(w_, driven_, controls, dt_, crashes_);
  if (before_detect) before_detect(w_);
  detector_.set_heading_memo(&heading_dirs_);  // this tick's address of it (a Simulation can move)
  detector_.detect(w_, contacts_);
  if (decides)
    contacts_.erase(std::remove_if(contacts_.begin(), contacts_.end(), [&](const collision::Contact& c) { return !decides(c); }),
                    contacts_.end());
  collision::respond(w_, contacts_, changes_, respond_scratch_);
  append(changes_, injected_);
  injected_.clear();
  for (const auto& d : injected_detonations_) collision::detonate(w_, d, changes_);
  injected_detonations_.clear();
  for (const auto& im : impacts_) collision::detonate(w_, im.munition, im.point, -1, changes_);
  for (const auto& c : crashes_) collision::ground_contact(w_, c.entity, c.point, c.speed_mps, changes_);
  if (before_apply) before_apply(w_, changes_);
  world::apply(w_, changes_, applied_);
  log_changes();
  for (const auto& im : impacts_) spent_.emplace_back(w_.frame, im.munition);
  for (const auto& c : changes_.entities)
    if (c.deactivate && w_.ents.local[c.entity] && w_.is_munition(c.entity)) spent_.emplace_back(w_.frame, c.entity);
  // 6. Autonomous vehicles near a detonation they did not cause have been fired upon.
  for (const auto& d : changes_.detonations) {
    const int shooter = d.shooter;
    for (int e = 0; e < static_cast<int>(w_.ents.size()); ++e)
      if (w_.ents.autonomous[e] && e != shooter && (w_.ents.pos[e] - d.point).norm() < dynamics::kThreatRadiusM)
        threatened(shooter, e);
  }
  if (on_tick) on_tick(TickReport{changes_, applied_, fired_});
  log_.flush();
  w_.frame += 1;
  w_.t = w_.frame * dt_;
}

}  // namespace npsnet::node
