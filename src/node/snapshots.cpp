#ifdef NPSNET_HAVE_RENDER
#include "npsnet_dirs.hpp"
#include "node/snapshots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "node/cameras.hpp"
#include "node/result_camera.hpp"
#include "render/renderer.hpp"
#include "world/pose.hpp"

namespace npsnet::node {

namespace {
// The HUD of the driven vehicle `d` in entity arrays `ents` (the world's own or a past copy).
render::Hud make_hud(const world::World& w, const world::Entities& ents, int d, const std::string& camera) {
  render::Hud hud;
  hud.camera = camera;
  if (d < 0 || d >= static_cast<int>(ents.size())) return hud;
  hud.show = true;
  hud.speed_kmh = mps2kmh(ents.vel[d].head<2>().norm());
  hud.heading_deg = ents.heading_deg[d], hud.pitch_deg = ents.pitch_deg[d], hud.roll_deg = ents.roll_deg[d];
  hud.rounds = ents.rounds[d], hud.fuel_l = ents.fuel_l[d];
  // an index keeps its id for the whole run: the live world's (a past copy holds no strings)
  hud.label = (d < static_cast<int>(w.ents.size()) ? w.ents.id[d] : std::string()) + " " + w.kinds[ents.kind[d]].name;
  return hud;
}

// Copies what a frame needs (kind, state, pose, velocity, flags, HUD numbers) into `to`, reusing
// its storage: no strings, no routes (ids stay empty; size() still counts the entities).
void copy_frame(const world::Entities& from, world::Entities& to) {
  to.id.resize(from.size());
  to.kind = from.kind, to.state = from.state, to.pos = from.pos, to.vel = from.vel;
  to.heading_deg = from.heading_deg, to.pitch_deg = from.pitch_deg, to.roll_deg = from.roll_deg;
  to.radius_m = from.radius_m, to.active = from.active, to.local = from.local;
  to.rounds = from.rounds, to.fuel_l = from.fuel_l;
}

// The first of this node's vehicles that is alive (not a wreck), else the first wreck; -1: none.
int live_vehicle(const world::World& w, bool& alive) {
  int wreck = -1;
  for (size_t e = 0; e < w.ents.size(); ++e) {
    const world::Kind& k = w.kinds[w.ents.kind[e]];
    if (!w.ents.local[e] || !w.ents.active[e] || k.mobility == world::Mobility::Munition) continue;
    if (w.ents.state[e] + 1 < static_cast<int>(k.states.size())) return alive = true, static_cast<int>(e);
    if (wreck < 0) wreck = static_cast<int>(e);
  }
  alive = false;
  return wreck;
}

float lerp_deg(float a, float b, double f) {
  const double d = wrap180(static_cast<double>(b) - a);  // the short way round
  return static_cast<float>(a + f * d);
}

std::string sanitize(const std::string& s) {
  std::string o;
  for (char c : s) o += (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-') ? c : '_';
  return o;
}
}  // namespace

Snapshots::Snapshots(const SnapshotOptions& o, const world::World& w, double dt, EventLog& log) : opt_(o), log_(log) {
  render::RenderOptions ro;
  ro.width = o.width, ro.height = o.height, ro.window = o.window;
  ro.shader_dir = NPSNET_SHADER_DIR;
  r_ = std::make_unique<render::Renderer>(ro, w);
  std::error_code ec;
  std::filesystem::create_directories(o.dir, ec);
  // States of the last kImminentLeadS (the ticks before this one), enough to reach t - 0.5 s.
  ring_.resize(static_cast<size_t>(std::max(1.0, std::ceil(kImminentLeadS / dt - 1e-9))));
  dt_ = dt;
  next_periodic_ = 0;
}

Snapshots::~Snapshots() = default;

int Snapshots::driven(const world::World& w) const {
  if (driven_ >= 0 && driven_ < static_cast<int>(w.ents.size())) return driven_;
  for (size_t e = 0; e < w.ents.size(); ++e)
    if (w.ents.local[e] && w.kinds[w.ents.kind[e]].mobility != world::Mobility::Munition) return static_cast<int>(e);
  return -1;
}

const Snapshots::State* Snapshots::past_state(double t) {
  if (filled_ == 0) return nullptr;
  auto at = [&](size_t k) -> const State& { return ring_[(head_ + ring_.size() - filled_ + k) % ring_.size()]; };
  const double eps = 1e-6 * dt_;
  if (t <= at(0).t + eps) return &at(0);  // not that much history yet (or exactly the oldest)
  for (size_t k = 1; k < filled_; ++k) {
    const State& b = at(k);
    if (b.t < t - eps) continue;
    if (b.t <= t + eps) return &b;
    const State& a = at(k - 1);
    const double f = (t - a.t) / (b.t - a.t);
    copy_frame(a.ents, lerp_.ents);
    lerp_.fixed_state = a.fixed_state;  // a state change happens at a tick: a's holds until b
    lerp_.t = t;
    world::Entities& e = lerp_.ents;
    const size_t n = std::min(a.ents.size(), b.ents.size());
    for (size_t i = 0; i < n; ++i) {
      e.pos[i] = a.ents.pos[i] + f * (b.ents.pos[i] - a.ents.pos[i]);
      e.vel[i] = a.ents.vel[i] + f * (b.ents.vel[i] - a.ents.vel[i]);
      e.heading_deg[i] = lerp_deg(a.ents.heading_deg[i], b.ents.heading_deg[i], f);
      e.pitch_deg[i] = lerp_deg(a.ents.pitch_deg[i], b.ents.pitch_deg[i], f);
      e.roll_deg[i] = lerp_deg(a.ents.roll_deg[i], b.ents.roll_deg[i], f);
    }
    return &lerp_;
  }
  return &at(filled_ - 1);
}

int Snapshots::frames_left(double t) const {
  const auto recent = std::count_if(taken_.begin(), taken_.end(), [&](double u) { return u > t - 60.0 + 1e-9; });
  return std::min(opt_.max_frames - taken_total_, opt_.max_per_minute - static_cast<int>(recent));
}

bool Snapshots::budget(const world::World& w, int n, const std::vector<std::string>& files) {
  const double t = w.t;
  taken_.erase(std::remove_if(taken_.begin(), taken_.end(), [&](double u) { return u <= t - 60.0 + 1e-9; }), taken_.end());
  std::string reason;
  if (taken_total_ + n > opt_.max_frames)
    reason = "budget: at most " + std::to_string(opt_.max_frames) + " frames per run (--max-snapshots)";
  else if (static_cast<int>(taken_.size()) + n > opt_.max_per_minute)
    reason = "budget: at most " + std::to_string(opt_.max_per_minute) +
             " frames in 60 s of scenario time (--max-snapshots-per-minute)";
  if (reason.empty()) {
    taken_total_ += n;
    taken_.insert(taken_.end(), static_cast<size_t>(n), t);
    return true;
  }
  if (skipped_ == 0)
    std::fprintf(stderr, "npsnet: warning: t = %.1f s: snapshot %s reached; frames are skipped (each logged as a snapshot_skipped event)\n",
                 t, reason.c_str());
  for (const auto& f : files) {
    log_.write({{"event", "snapshot_skipped"}, {"t", std::round(t * 1000) / 1000}, {"frame", w.frame},
                {"file", (opt_.dir / f).string()}, {"reason", reason}});
    ++skipped_;
  }
  return false;
}

void Snapshots::write(const world::World& w, const std::string& name, const State* past, const render::Camera& cam,
                      double t, const std::string& mode, int hud_entity, const nlohmann::json& extra) {
  render::SceneView v;
  v.world = &w;
  v.ents = past ? &past->ents : &w.ents;
  v.fixed_state = past ? &past->fixed_state : &w.fixed.state;
  v.t = t;
  v.driven = hud_entity == kDriven ? driven(w) : hud_entity;
  const render::Hud hud = make_hud(w, *v.ents, v.driven, mode);
  r_->render(v, cam, hud, true);
  const auto file = opt_.dir / name;
  std::string why;
  if (!r_->write_png(file, &why)) throw OutputError(file.string() + ": cannot write the snapshot: " + why);
  nlohmann::json ev = {{"event", "snapshot"}, {"t", std::round(w.t * 1000) / 1000}, {"frame", w.frame},
                       {"file", file.string()}, {"scene_t", std::round(t * 1000) / 1000}};
  if (extra.is_object()) ev.update(extra);
  log_.write(ev);
  ++written_;
}

void Snapshots::before_apply(const world::World& w, const world::Changes& c) {
  auto snap = [&](const std::string& kind, int a, const std::string& a_id, const std::string& b_id, const Vec3& pa,
                  const Vec3& pb, Pending more) {
    if (a < 0 || !w.ents.snapshots[a]) return;
    char num[16];
    std::snprintf(num, sizeof num, "%04d", ++counter_);
    const std::string base = std::string(num) + "-" + kind + "-" + sanitize(a_id) + "-" + sanitize(b_id);
    if (!budget(w, 2, {base + "-imminent.png", base + "-result.png"})) return;
    const render::Camera cam = render::look_at_pair(w, pa, pb);
    const State* past = past_state(w.t - kImminentLeadS);
    write(w, base + "-imminent.png", past, cam, past ? past->t : w.t, "outside", a);
    more.due_t = w.t + kResultDelayS, more.base = base, more.eye = cam.eye, more.target = cam.target, more.subject = a;
    pending_.push_back(more);
  };
  const auto& ents = w.ents;
  for (const auto& r : c.collisions) {
    const bool snap_a = ents.snapshots[r.a];
    const bool ground = !r.b_fixed && r.b < 0;
    const bool snap_b = !r.b_fixed && !ground && ents.snapshots[r.b];
    if (!snap_a && !snap_b) continue;
    if (!r.b_fixed && !ground && w.kinds[ents.kind[r.b]].mobility == world::Mobility::Munition) continue;  // the detonation covers it
    if (w.kinds[ents.kind[r.a]].mobility == world::Mobility::Munition) continue;
    const Vec3 pa = world::entity_centre(w, r.a);
    const Vec3 pb = ground ? r.point : r.b_fixed ? world::fixed_centre(w, r.b) : world::entity_centre(w, r.b);
    const int who = snap_a ? r.a : r.b;
    Pending more;
    more.a = r.a, more.b = r.b, more.b_fixed = r.b_fixed, more.b_point = r.point;
    snap("collision", who, ents.id[r.a], ground ? "ground" : r.b_fixed ? w.fixed.id[r.b] : ents.id[r.b], pa, pb, more);
  }
  for (const auto& d : c.detonations) {
    const int shooter = d.shooter;
    if (shooter < 0 || !ents.snapshots[shooter]) continue;
    // Frame ~40 m of ground around the point of impact, across the line of fire.
    Vec2 dir = (d.point - ents.pos[shooter]).head<2>();
    dir = dir.norm() > 1e-6 ? Vec2(dir.normalized()) : Vec2(1, 0);
    const Vec3 side(-dir.y() * 20, dir.x() * 20, 0);
    Vec3 pa = d.target >= 0 ? world::entity_centre(w, d.target) - side : d.point - side;
    Vec3 pb = d.target >= 0 ? world::entity_centre(w, d.target) + side : d.point + side;
    // A fixed object the blast changed (a tree to a stump): framed beside the point of impact,
    // so the fireball does not stand in front of it.
    if (d.target < 0 && d.kind >= 0) {
      const double blast = w.kinds[d.kind].blast_radius_m;
      for (const auto& f : c.fixed)
        if (f.object >= 0 && (w.fixed.pos[f.object] - d.point).head<2>().norm() <= blast + world::fixed_radius(w, f.object)) {
          pa = d.point, pb = world::fixed_centre(w, f.object);
          break;
        }
    }
    snap("detonation", shooter, d.round, d.target >= 0 ? ents.id[d.target] : "ground", pa, pb, Pending{});
  }
}

void Snapshots::after_tick(const world::World& w, const world::Changes& c, const world::Applied& a) {
  for (const auto& d : c.detonations)
    if (d.blast) r_->add_explosion(d.point, w.t, d.target >= 0 ? 1.5f : 1.0f);  // a dud or smoke: none
  for (int e : a.killed) {
    const Vec3 p = world::entity_centre(w, e);
    if (w.kinds[w.ents.kind[e]].explosive) r_->add_explosion(p, w.t, 1.5f);
    r_->add_fire(p, w.t, 20.0);
  }
  for (const auto& p : a.terrain_patches) r_->terrain_changed(p);
  for (const auto& cr : c.craters) r_->add_crater(cr.point, cr.radius_m, w.t);
  for (size_t i = 0; i < pending_.size();) {
    if (pending_[i].due_t <= w.t + 1e-9) {
      const Pending& p = pending_[i];
      write(w, p.base + "-result.png", nullptr, result_camera(w, p), w.t, "outside", p.subject);
      pending_.erase(pending_.begin() + static_cast<long>(i));
    } else {
      ++i;
    }
  }
  if (!start_view_) {  // the driver's view at the start (the thesis's Figure A.1)
    start_view_ = true;
    const int d = driven(w);
    const std::string name = d >= 0 ? "0000-view-" + sanitize(w.ents.id[d]) + "-driver.png" : "";
    if (d >= 0 && budget(w, 1, {name})) {
      const auto cam = player_camera(w, w.ents, d, input::CameraMode::Driver);
      write(w, name, nullptr, cam, w.t, "driver", d);
    }
  }
  if (opt_.every_s > 0 && w.t + 1e-9 >= next_periodic_) {
    bool alive = false;
    render::Camera cam;
    const int d = periodic_camera(w, cam, alive);
    if (d >= 0) {
      char name[64];
      std::snprintf(name, sizeof name, "%04d-periodic-t%07.1f.png", ++counter_, w.t);
      if (budget(w, 1, {name}))
        write(w, name, nullptr, cam, w.t, alive ? "driver" : "outside", alive ? d : -1,
              {{"camera", alive ? "driver" : "outside"}, {"vehicle", w.ents.id[d]}});
    }
    next_periodic_ += opt_.every_s;
  }
  // buffer this state for later imminent frames (slots reuse their storage)
  State& s = ring_[head_];
  s.t = w.t;
  copy_frame(w.ents, s.ents);
  s.fixed_state = w.fixed.state;
  head_ = (head_ + 1) % ring_.size();
  filled_ = std::min(filled_ + 1, ring_.size());
}

render::Camera Snapshots::result_camera(const world::World& w, const Pending& p) const {
  render::Camera cam;
  cam.eye = p.eye, cam.target = p.target;
  if (p.a >= 0 && p.b_fixed) {  // the object it changed, close, from where the vehicle hides none of it
    cam = changed_object_camera(w, p.a, p.b);
  } else if (p.a >= 0) {  // framed again from where the pair is now
    const Vec3 pb = p.b >= 0 ? world::entity_centre(w, p.b) : p.b_point;
    cam = render::look_at_pair(w, world::entity_centre(w, p.a), pb);
  }
  return cam;
}

int Snapshots::periodic_camera(const world::World& w, render::Camera& cam, bool& alive) const {
  alive = false;
  int d = live_vehicle(w, alive);
  if (driven_ >= 0 && driven_ < static_cast<int>(w.ents.size()) &&
      w.ents.state[driven_] + 1 < static_cast<int>(w.kinds[w.ents.kind[driven_]].states.size()))
    d = driven_, alive = true;  // the player's vehicle
  if (d < 0) return d;
  if (alive) {
    cam = player_camera(w, w.ents, d, input::CameraMode::Driver);
  } else {  // every vehicle of this node is a wreck: look at the first one from outside
    const Vec3 c = world::entity_centre(w, d);
    const Vec2 f = heading_to_dir(w.ents.heading_deg[d]);
    cam.eye = c - Vec3(f.x(), f.y(), 0) * 40.0 + Vec3(0, 0, 25.0);
    cam.eye.z() = std::max(cam.eye.z(), w.terrain.height(cam.eye.x(), cam.eye.y()) + 10.0);
    cam.target = c;
  }
  return d;
}

void Snapshots::cameras_due(const world::World& w, std::vector<render::Camera>& out) const {
  if (frames_left(w.t) <= 0) return;  // after_tick skips every frame: nothing is seen
  for (const Pending& p : pending_)
    if (p.due_t <= w.t + 1e-9) out.push_back(result_camera(w, p));
  if (!start_view_) {
    const int d = driven(w);
    if (d >= 0) out.push_back(player_camera(w, w.ents, d, input::CameraMode::Driver));
  }
  bool alive = false;
  render::Camera cam;
  if (opt_.every_s > 0 && w.t + 1e-9 >= next_periodic_ && periodic_camera(w, cam, alive) >= 0) out.push_back(cam);
}

bool Snapshots::present(const world::World& w, const render::Camera& cam, const std::string& mode) {
  const int d = driven(w);
  render::SceneView v;
  v.world = &w, v.t = w.t, v.driven = d;
  const render::Hud hud = make_hud(w, w.ents, d, mode);
  r_->render(v, cam, hud, true);
  return !r_->window_should_close();
}

}  // namespace npsnet::node
#endif  // NPSNET_HAVE_RENDER
