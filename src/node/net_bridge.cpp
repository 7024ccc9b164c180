#include "node/net_bridge.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "core/constants.hpp"
#include "world/pose.hpp"

namespace npsnet::node {

namespace {

volatile std::sig_atomic_t g_usr1 = 0;
extern "C" void on_usr1(int) { g_usr1 = 1; }

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
// DIS enumerations we send (SISO-REF-010).
constexpr std::uint16_t kWarheadHighExplosive = 1000;
constexpr std::uint16_t kFuseContact = 1000;
constexpr std::uint8_t kResultEntityImpact = 1;
constexpr std::uint8_t kResultGroundImpact = 3;
constexpr std::uint8_t kCollisionInelastic = 0;
constexpr std::uint8_t kCollisionElastic = 1;
constexpr std::uint8_t kEntityKindCultural = 5;
constexpr std::uint8_t kEntityKindMunition = 2;
// Entity State datagrams one tick sends at most (one PDU each); the rest go on the next ticks.
// A receiver drains its socket once a tick: 128 datagrams fit its default receive buffer
// (Linux rmem_default 208 KiB), where the 517 first Entity States of the default scenario did not.
constexpr size_t kMaxDatagramsPerTick = 128;
constexpr unsigned kDamageShift = 3;  // appearance bits 3-4: damage
constexpr std::uint32_t kDamageMask = 3u << kDamageShift;

double round3(double v) { return std::round(v * 1000.0) / 1000.0; }

net::EntityType to_net(const world::DisType& d) {
  return {d.kind, d.domain, d.country, d.category, d.subcategory, d.specific, d.extra};
}
bool same(const world::DisType& d, const net::EntityType& t) {
  return d.kind == t.kind && d.domain == t.domain && d.country == t.country && d.category == t.category &&
         d.subcategory == t.subcategory && d.specific == t.specific && d.extra == t.extra;
}
std::string type_text(const net::EntityType& t) {
  char b[64];
  std::snprintf(b, sizeof b, "%u:%u:%u:%u:%u:%u:%u", t.kind, t.domain, t.country, t.category, t.subcategory,
                t.specific, t.extra);
  return b;
}
Eigen::Vector3d ev(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
Vec3 vv(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
bool finite(const Eigen::Vector3d& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }
double wrap180(double d) {
  d = std::fmod(d + 180.0, 360.0);
  if (d < 0) d += 360.0;
  return d - 180.0;
}

}  // namespace

double dis_timeout_from_env(double fallback) {
  const char* v = std::getenv("NPSNET_DIS_TIMEOUT_S");
  if (!v || !*v) return fallback;
  char* end = nullptr;
  const double s = std::strtod(v, &end);
  if (end == v || *end != '\0' || !std::isfinite(s) || s <= 0 || s > 3600)
    throw std::runtime_error(std::string("NPSNET_DIS_TIMEOUT_S='") + v +
                             "': must be a number of seconds, more than 0 and at most 3600");
  return s;
}

namespace {
net::SessionConfig session_config(const BridgeOptions& o) {
  if (o.app < 1 || o.app >= kCulturalAppBit)
    throw std::runtime_error("--app " + std::to_string(o.app) + ": with --net it must be 1-32767 (32768 and up carry cultural features)");
  if (o.site < 1 || o.site > 65535) throw std::runtime_error("--site " + std::to_string(o.site) + ": must be 1-65535");
  if (o.exercise < 1 || o.exercise > 255) throw std::runtime_error("--exercise " + std::to_string(o.exercise) + ": must be 1-255");
  net::SessionConfig c;
  c.transport.url = o.url;
  c.transport.iface = o.iface;
  c.exercise_id = static_cast<std::uint8_t>(o.exercise);
  c.site = static_cast<std::uint16_t>(o.site);
  c.application = static_cast<std::uint16_t>(o.app);
  return c;
}
// A timeout shorter than the default (tests) shortens the heartbeat in the Annex C ratio 5:12,
// so that a quiet but living entity never times out.
net::DrThresholds thresholds(double timeout_s) {
  net::DrThresholds t;
  t.timeout_s = timeout_s;
  t.heartbeat_s = std::min(dis_defaults::kHeartbeatS, timeout_s * dis_defaults::kHeartbeatS / dis_defaults::kTimeoutS);
  return t;
}
}  // namespace

std::unique_ptr<net::Session> open_session(const BridgeOptions& o) {
  return std::make_unique<net::Session>(session_config(o));
}

NetBridge::NetBridge(const BridgeOptions& o, Simulation& sim, EventLog& log) : NetBridge(o, open_session(o), sim, log) {}

NetBridge::NetBridge(const BridgeOptions& o, std::unique_ptr<net::Session> session, Simulation& sim, EventLog& log)
    : opt_(o),
      sim_(sim),
      log_(log),
      session_(std::move(session)),
      remotes_(thresholds(o.timeout_s)),
      cultural_app_(static_cast<std::uint16_t>(kCulturalAppBit | o.app)) {
  if (!session_) throw std::runtime_error("--net: no session");
  world::World& w = sim_.world();
  auto& ents = w.ents;
  if (ents.size() >= 0x8000)
    throw std::runtime_error("--net: the scenario has " + std::to_string(ents.size()) +
                             " entities; DIS entity numbers of this node go up to 32767");
  for (size_t e = 0; e < ents.size(); ++e) {
    const auto mob = w.kinds[ents.kind[e]].mobility;
    if (mob == world::Mobility::Fixed || mob == world::Mobility::Munition) continue;
    if (ents.node[e] == o.node) {
      own_.push_back(static_cast<int>(e));
      if (mob == world::Mobility::Ground) ++ground_vehicles_;
    } else {
      ents.local[e] = 0;  // driven by another node: waits for its Entity State
      ents.active[e] = 0;
      ents.rounds[e] = 0;  // its owner fires its rounds (scheduled fires of it are theirs)
    }
  }
  pubs_.assign(own_.size(), net::DrPublisher(net::DrAlgorithm::RVW, thresholds(o.timeout_s)));
  sent_appearance_.assign(own_.size(), 0);
  prev_vel_ecef_.assign(own_.size(), Vec3::Zero());
  prev_heading_.assign(own_.size(), 0.f);
  for (size_t i = 0; i < own_.size(); ++i) prev_heading_[i] = ents.heading_deg[own_[i]];
  remote_id_.assign(ents.size(), net::EntityId{});
  fixed_net_state_.assign(w.fixed.size(), -1);
  for (size_t f = 0; f < w.fixed.size(); ++f) fixed_net_state_[f] = static_cast<int16_t>(w.fixed.state[f]);
  pending_.reserve(16);
  start_s_ = now_s_ = clock_s();
  if (const char* v = std::getenv("NPSNET_DIS_PACK")) pack_ = std::string(v) == "1";
  struct sigaction sa {};
  sa.sa_handler = on_usr1;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGUSR1, &sa, nullptr);
}

NetBridge::~NetBridge() { std::signal(SIGUSR1, SIG_DFL); }

double NetBridge::clock_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void NetBridge::attach() {
  chained_on_tick_ = sim_.on_tick;
  sim_.before_step = [this](world::World& w) { before_step(w); };
  sim_.decides = [this](const collision::Contact& c) { return decides(c); };
  sim_.on_tick = [this](const TickReport& r) {
    if (chained_on_tick_) chained_on_tick_(r);
    after_tick(r);
  };
}

void NetBridge::check_signal() {
  if (g_usr1) {
    g_usr1 = 0;
    std::fprintf(stderr, "%s\n", summary().c_str());
  }
}

std::string NetBridge::summary() const {
  char b[256];
  const double s = std::max(1e-9, published_s());
  const double per = ground_vehicles_ ? ground_es_sent_ / (ground_vehicles_ * s / 60.0) : 0.0;
  std::snprintf(b, sizeof b,
                "\n  net: %d local ground vehicles, %llu entity_state PDUs in %.1f s: %.1f per vehicle-minute "
                "(fixed 10 Hz: 600); %zu remote entities",
                ground_vehicles_, (unsigned long long)ground_es_sent_, s, per, remotes_.size());
  return "  net: " + session_->counters().summary() + b;
}

net::EntityId NetBridge::own_id(int e) const {
  return session_->entity_id(static_cast<std::uint16_t>(e + 1));
}

bool NetBridge::is_own_vehicle(int e) const {
  const auto& ents = sim_.world().ents;
  return e >= 0 && static_cast<size_t>(e) < ents.size() && ents.local[e] && ents.node[e] == opt_.node &&
         static_cast<size_t>(e) < remote_id_.size() && remote_id_[e].site == 0 &&
         sim_.world().kinds[ents.kind[e]].mobility != world::Mobility::Munition;
}

int NetBridge::remote_index_of(const net::EntityId& id) const {
  auto it = world_of_.find(id);
  return it == world_of_.end() ? -1 : it->second;
}

std::string NetBridge::id_text(const net::EntityId& id) const {
  return std::to_string(id.site) + ":" + std::to_string(id.application) + ":" + std::to_string(id.entity);
}

nlohmann::json NetBridge::event(const char* type) const {
  const auto& w = sim_.world();
  return {{"event", type}, {"t", round3(w.t)}, {"frame", w.frame}};
}

int NetBridge::kind_for(const net::EntityType& t, world::Mobility) const {
  const auto& kinds = sim_.world().kinds;
  for (int k = 0; k < kinds.size(); ++k)
    if (kinds[k].mobile() && kinds[k].mobility != world::Mobility::Munition && same(kinds[k].dis, t)) return k;
  const char* generic = t.domain == 2 ? "generic_air" : t.domain == 3 ? "generic_sea" : "generic_ground";
  int k = kinds.find(generic);
  if (k >= 0) return k;
  for (int j = 0; j < kinds.size(); ++j)
    if (kinds[j].mobility == world::Mobility::Ground) return j;
  return -1;
}

int NetBridge::kind_for_munition(const net::EntityType& t) const {
  const auto& kinds = sim_.world().kinds;
  for (int k = 0; k < kinds.size(); ++k)
    if (kinds[k].mobility == world::Mobility::Munition && same(kinds[k].dis, t)) return k;
  int k = kinds.find("he_round");
  if (k >= 0) return k;
  for (int j = 0; j < kinds.size(); ++j)
    if (kinds[j].mobility == world::Mobility::Munition) return j;
  return -1;
}

// Damage in appearance bits 3-4: intact 0, last state (wreck / destroyed) 3, between 1 (and 2
// for kinds with more than three states).
std::uint32_t NetBridge::appearance_of(int e) const {
  const auto& w = sim_.world();
  const int n = static_cast<int>(w.kinds[w.ents.kind[e]].states.size());
  const int s = w.ents.state[e];
  std::uint32_t d = 0;
  if (s <= 0) d = 0;
  else if (s >= n - 1) d = 3;
  else d = (n > 3 && s >= 2) ? 2 : 1;
  return d << kDamageShift;
}

int NetBridge::state_from_appearance(int kind, std::uint32_t appearance) const {
  const int n = static_cast<int>(sim_.world().kinds[kind].states.size());
  const unsigned d = (appearance & kDamageMask) >> kDamageShift;
  if (d == 0 || n <= 1) return 0;
  if (d == 3) return n - 1;
  return std::min<int>(n - 2, n > 3 ? static_cast<int>(d) : 1);
}

// ---------------------------------------------------------------- receive ----

void NetBridge::before_step(world::World& w) {
  now_s_ = clock_s();
  if (!started_) started_ = true, start_s_ = now_s_;  // rates count from the first tick
  pending_.clear();
  if (remote_id_.size() < w.ents.size()) remote_id_.resize(w.ents.size());
  check_signal();
  session_->poll(net::Overloaded{
      [&](const net::EntityStatePdu& p) { on_entity_state(p); },
      [&](const net::EntityStateUpdatePdu& p) { remotes_.apply(p, now_s_); },
      [&](const net::FirePdu& p) { on_fire(p); },
      [&](const net::DetonationPdu& p) { on_detonation(p); },
      [&](const net::CollisionPdu& p) { on_collision(p); }});
  remotes_.expire(now_s_, [&](const net::RemoteEntity& r) {
    const int e = remote_index_of(r.id);
    if (e < 0) return;
    w.ents.active[e] = 0;
    w.ents.vel[e] = Vec3::Zero();
    auto ev = event("entity_timeout");
    ev["id"] = w.ents.id[e];
    ev["entity"] = id_text(r.id);
    ev["marking"] = net::marking_text(r.marking);
    ev["kind"] = w.kinds[w.ents.kind[e]].name;
    log_.write(ev);
  });
  set_remote_poses(w);
}

void NetBridge::on_entity_state(const net::EntityStatePdu& p) {
  if (p.entity_type.kind == kEntityKindCultural && (p.entity_id.application & kCulturalAppBit)) {
    on_cultural(p);
    return;
  }
  if (p.entity_type.kind == kEntityKindMunition) return;  // rounds travel as Fire / Detonation
  if (!finite(Eigen::Vector3d(p.location.x, p.location.y, p.location.z))) return;
  const auto r = remotes_.apply(p, now_s_);
  if (r == net::RemoteEntityTable::ApplyResult::Joined) {
    if (auto i = remotes_.find(p.entity_id)) joined(*i);
  } else if (r == net::RemoteEntityTable::ApplyResult::Deactivated) {
    const int e = remote_index_of(p.entity_id);
    if (e >= 0) sim_.world().ents.active[e] = 0, sim_.world().ents.vel[e] = Vec3::Zero();
    return;
  }
  // Damage that arrives in the appearance (states only move forward).
  const int e = remote_index_of(p.entity_id);
  if (e < 0) return;
  auto& ents = sim_.world().ents;
  const int to = state_from_appearance(ents.kind[e], p.appearance);
  if (to > ents.state[e]) {
    inject_.clear();
    world::EntityChange ch;
    ch.entity = e;
    ch.to_state = to;
    inject_.entities.push_back(ch);
    sim_.inject(inject_);
    inject_.clear();
  }
}

void NetBridge::joined(std::size_t ri) {
  world::World& w = sim_.world();
  auto& ents = w.ents;
  const net::RemoteEntity& r = remotes_[ri];
  const std::string marking = net::marking_text(r.marking);
  int e = remote_index_of(r.id);
  bool known_type = true;
  if (e < 0) {
    // A scenario vehicle of another node with this marking, not yet bound to an entity id.
    for (size_t i = 0; i < ents.size(); ++i)
      if (!ents.local[i] && ents.id[i] == marking && remote_id_[i].site == 0 &&
          w.kinds[ents.kind[i]].mobility != world::Mobility::Munition) {
        e = static_cast<int>(i);
        break;
      }
    if (e >= 0 && !same(w.kinds[ents.kind[e]].dis, r.type)) {
      const int k = kind_for(r.type, world::Mobility::Ground);
      if (k >= 0) ents.kind[e] = static_cast<int16_t>(k);
    }
    if (e < 0) {
      const int k = kind_for(r.type, world::Mobility::Ground);
      if (k < 0) return;  // no vehicle kind at all in this kinds file
      const std::string name = marking.empty() ? id_text(r.id) : marking;
      e = ents.add(name, k, Vec3::Zero(), 0.f, static_cast<float>(w.kinds[k].radius_m));
      ents.node[e] = -1;
      remote_id_.resize(ents.size());
    }
    remote_id_[e] = r.id;
    world_of_[r.id] = e;
  }
  ents.local[e] = 0;
  ents.active[e] = 1;
  ents.autonomous[e] = 0;
  known_type = same(w.kinds[ents.kind[e]].dis, r.type);
  auto ev = event("entity_joined");
  ev["id"] = ents.id[e];
  ev["entity"] = id_text(r.id);
  ev["marking"] = marking;
  ev["kind"] = known_type ? w.kinds[ents.kind[e]].name : type_text(r.type);
  if (!known_type) ev["model"] = w.kinds[ents.kind[e]].name;
  log_.write(ev);
}

void NetBridge::set_remote_poses(world::World& w) {
  const auto& frame = w.terrain.frame();
  auto& ents = w.ents;
  for (std::size_t i = 0; i < remotes_.size(); ++i) {
    const net::RemoteEntity& r = remotes_[i];
    const int e = remote_index_of(r.id);
    if (e < 0 || !ents.active[e]) continue;
    const net::Pose pose = remotes_.displayed_pose(i, now_s_);
    if (!finite(pose.position)) continue;
    const Vec3 p = frame.from_ecef(vv(pose.position));
    const Vec3 hpr = frame.from_dis_euler(p, Vec3(pose.orientation.psi, pose.orientation.theta, pose.orientation.phi));
    const Vec3 ahead = frame.from_ecef(vv(pose.position + r.state.velocity));
    if (!std::isfinite(p.x()) || !std::isfinite(hpr.x())) continue;
    ents.pos[e] = p;
    ents.vel[e] = ahead - p;
    ents.heading_deg[e] = static_cast<float>(hpr.x());
    ents.pitch_deg[e] = static_cast<float>(hpr.y());
    ents.roll_deg[e] = static_cast<float>(hpr.z());
  }
}

void NetBridge::on_cultural(const net::EntityStatePdu& p) {
  if (p.entity_id.site == opt_.site && p.entity_id.application == cultural_app_) return;  // our echo
  world::World& w = sim_.world();
  if (p.entity_id.entity == 0 || p.entity_id.entity > w.fixed.size()) return;
  const int o = p.entity_id.entity - 1;
  const world::Kind& k = w.kinds[w.fixed.kind[o]];
  if (!same(k.dis, p.entity_type)) return;  // not the same object: other scenario or objects file
  if (p.appearance >= k.states.size()) return;
  const int to = static_cast<int>(p.appearance);
  if (to > fixed_net_state_[o]) fixed_net_state_[o] = static_cast<int16_t>(to);
  if (to > w.fixed.state[o]) {
    inject_.clear();
    inject_.fixed.push_back({o, to});
    sim_.inject(inject_);
    inject_.clear();
  }
}

void NetBridge::on_collision(const net::CollisionPdu& p) {
  world::World& w = sim_.world();
  auto& ents = w.ents;
  // The colliding entity is ours (we apply the outcome to it), or a third node's copy (we only
  // record the collision and the damage of both copies, as their owners do).
  int own = -1;
  bool third = false;
  if (p.colliding_entity_id.site == opt_.site && p.colliding_entity_id.application == opt_.app) {
    own = static_cast<int>(p.colliding_entity_id.entity) - 1;
    if (!is_own_vehicle(own)) return;
  } else {
    own = remote_index_of(p.colliding_entity_id);
    if (own < 0 || !ents.active[own]) return;
    third = true;
  }
  const int other = remote_index_of(p.issuing_entity_id);
  if (other < 0 || !ents.active[other]) return;
  const auto ri = remotes_.find(p.issuing_entity_id);
  if (!ri) return;
  // Outcome: elastic = bounce; inelastic = kill when the issuer now reads destroyed, else stop.
  world::Result res = world::Result::Bounce;
  if (p.collision_type != kCollisionElastic) {
    const unsigned d = (remotes_[*ri].appearance & kDamageMask) >> kDamageShift;
    res = d == 3 ? world::Result::Kill : world::Result::Stop;
  }
  const auto& frame = w.terrain.frame();
  const Vec3 other_pos = ents.pos[other];
  Eigen::Vector3d ve(p.velocity.x, p.velocity.y, p.velocity.z);
  Vec3 v_other = ents.vel[other];
  if (finite(ve)) {
    const Vec3 ecef = frame.to_ecef(other_pos);
    v_other = frame.from_ecef(ecef + vv(ve)) - other_pos;
  }
  Vec3 n = ents.pos[own] - other_pos;
  n.z() = 0;
  n = n.norm() > 1e-9 ? Vec3(n.normalized()) : Vec3::UnitX();
  world::CollisionRecord rec;
  rec.a = std::min(own, other);
  rec.b = std::max(own, other);
  const double h = ents.heading_deg[other] * kDeg;
  const Vec3 fwd(std::sin(h), std::cos(h), 0), right(std::cos(h), -std::sin(h), 0);
  rec.point = other_pos + fwd * p.location_in_entity.x + right * p.location_in_entity.y -
              Vec3::UnitZ() * p.location_in_entity.z;
  rec.closing_speed_mps = std::max(0.0, (v_other - ents.vel[own]).dot(n));
  rec.angle_deg = collision::impact_angle_deg(ents.heading_deg[rec.a], ents.heading_deg[rec.b]);
  rec.method = "network";
  rec.result_a = rec.result_b = res;
  inject_.clear();
  inject_.collisions.push_back(rec);
  world::EntityChange mine;
  mine.entity = own;
  mine.set_vel = !third;
  if (res == world::Result::Bounce && third) {
    mine.set_vel = false;
  } else if (res == world::Result::Bounce) {
    const double ma = std::max(1.0, static_cast<double>(p.mass));
    const double mb = w.kinds[ents.kind[own]].mass_kg;
    Vec3 vb = ents.vel[own];
    const double vn = (v_other - vb).dot(n);
    if (vn > 0) vb += ((1 + thesis::kBounceRestitution) * vn / (1 / ma + 1 / mb) / mb) * n;
    if (w.kinds[ents.kind[own]].mobility != world::Mobility::Air) vb.z() = 0;
    mine.vel = vb;
    mine.cruise_mps = static_cast<float>(vb.norm());
  } else {
    mine.vel = Vec3::Zero();
    mine.cruise_mps = third ? -1.f : 0.f;
    if (res == world::Result::Kill) {
      mine.to_state = static_cast<int>(w.kinds[ents.kind[own]].states.size()) - 1;
      world::EntityChange theirs;
      theirs.entity = other;
      theirs.to_state = static_cast<int>(w.kinds[ents.kind[other]].states.size()) - 1;
      inject_.entities.push_back(theirs);
    }
  }
  inject_.entities.push_back(mine);
  sim_.inject(inject_);
  inject_.clear();
}

void NetBridge::on_fire(const net::FirePdu& p) {
  const auto& w = sim_.world();
  const int shooter = remote_index_of(p.firing_entity_id);
  const int mk = kind_for_munition(p.descriptor.munition_type);
  auto ev = event("fire");
  ev["shooter"] = shooter >= 0 ? w.ents.id[shooter] : id_text(p.firing_entity_id);
  ev["munition"] = mk >= 0 ? w.kinds[mk].name : type_text(p.descriptor.munition_type);
  ev["round"] = id_text(p.munition_id);
  const int target = remote_index_of(p.target_entity_id);
  ev["target"] = target >= 0 ? w.ents.id[target] : "";
  const Eigen::Vector3d loc(p.location.x, p.location.y, p.location.z);
  if (finite(loc)) {
    const Vec3 l = w.terrain.frame().from_ecef(vv(loc));
    ev["from"] = nlohmann::json::array({round3(l.x()), round3(l.y()), round3(l.z())});
  }
  ev["remote"] = true;
  log_.write(ev);
}

void NetBridge::on_detonation(const net::DetonationPdu& p) {
  world::World& w = sim_.world();
  auto& ents = w.ents;
  const Eigen::Vector3d loc(p.location.x, p.location.y, p.location.z);
  if (!finite(loc)) return;
  const Vec3 point = w.terrain.frame().from_ecef(vv(loc));
  if (!std::isfinite(point.x()) || !w.terrain.contains(point.x(), point.y())) return;
  const int mk = kind_for_munition(p.descriptor.munition_type);
  if (mk < 0) return;
  int hit = -1;
  if (p.detonation_result == kResultEntityImpact) {
    if (p.target_entity_id.site == opt_.site && p.target_entity_id.application == opt_.app) {
      const int e = static_cast<int>(p.target_entity_id.entity) - 1;
      if (is_own_vehicle(e)) hit = e;
    } else {
      hit = remote_index_of(p.target_entity_id);
    }
    if (hit >= 0 && !ents.active[hit]) hit = -1;
  }
  const int m = ents.add("rd" + id_text(p.exploding_entity_id), mk, point, 0.f, static_cast<float>(w.kinds[mk].radius_m));
  ents.active[m] = 0;  // already spent: only its kind and owner matter
  ents.local[m] = 0;
  ents.node[m] = -1;
  ents.owner[m] = remote_index_of(p.firing_entity_id);
  remote_id_.resize(ents.size());
  inject_.clear();
  collision::detonate(w, m, point, hit, inject_);
  sim_.inject(inject_);
  inject_.clear();
}

// ---------------------------------------------------------------- decide ----

bool NetBridge::decides(const collision::Contact& c) {
  const auto& ents = sim_.world().ents;
  if (c.b_fixed) return ents.local[c.a] != 0;  // the vehicle's owner decides
  const bool la = ents.local[c.a] != 0, lb = ents.local[c.b] != 0;
  if (la && lb) return true;
  if (!la && !lb) return false;  // two remote entities: their owners decide
  const int own = la ? c.a : c.b, other = la ? c.b : c.a;
  const auto& mob = sim_.world().kinds[ents.kind[own]].mobility;
  if (mob == world::Mobility::Munition) return true;  // our round: we detonate it
  const net::EntityId rid = static_cast<size_t>(other) < remote_id_.size() ? remote_id_[other] : net::EntityId{};
  if (rid.site == 0) return true;
  const bool d = own_id(own) < rid;
  if (d && pending_.size() < pending_.capacity()) pending_.push_back({own, other, ents.vel[own]});
  return d;
}

// ---------------------------------------------------------------- send ------

net::KinematicState NetBridge::truth(int e) const {
  const auto& w = sim_.world();
  const auto& frame = w.terrain.frame();
  net::KinematicState s;
  const Vec3 p = w.ents.pos[e];
  const Vec3 pe = frame.to_ecef(p);
  s.position = ev(pe);
  s.velocity = ev(frame.to_ecef(p + w.ents.vel[e]) - pe);
  const Vec3 eu = frame.to_dis_euler(p, w.ents.heading_deg[e], w.ents.pitch_deg[e], w.ents.roll_deg[e]);
  s.orientation = {eu.x(), eu.y(), eu.z()};
  return s;
}

void NetBridge::publish_vehicles() {
  const auto& w = sim_.world();
  const double t = w.t;
  const double dt = sim_.dt();
  const size_t n = own_.size();
  size_t sent_now = 0, first_deferred = n;
  // Round robin from where the last tick's cap stopped, so no vehicle waits more than a few ticks.
  for (size_t k = 0; k < n; ++k) {
    const size_t i = (rr_ + k) % n;
    const int e = own_[i];
    net::KinematicState s = truth(e);
    const Vec3 v = vv(s.velocity);
    s.acceleration = ev((v - prev_vel_ecef_[i]) / dt);
    if (!pubs_[i].has_sent()) s.acceleration.setZero();
    s.angular_velocity = Eigen::Vector3d(0, 0, wrap180(w.ents.heading_deg[e] - prev_heading_[i]) * kDeg / dt);
    prev_vel_ecef_[i] = v;
    prev_heading_[i] = w.ents.heading_deg[e];
    const std::uint32_t app = appearance_of(e);
    const bool changed = pubs_[i].has_sent() && app != sent_appearance_[i];
    if (!changed && pubs_[i].needs_update(s, t) == net::DrPublisher::Reason::None) continue;
    if (!pack_ && sent_now >= kMaxDatagramsPerTick && !changed) {  // a damage change never waits
      if (first_deferred == n) first_deferred = i;
      continue;
    }
    es_.entity_id = own_id(e);
    es_.force_id = 1;
    es_.entity_type = to_net(w.kinds[w.ents.kind[e]].dis);
    es_.alternative_entity_type = es_.entity_type;
    auto mk = net::make_marking(w.ents.id[e]);
    es_.marking = mk ? mk.value() : net::Marking{};
    es_.appearance = app;
    net::write_kinematics(s, pubs_[i].algorithm(), es_);
    es_.header.timestamp = net::relative_timestamp(t);
    es_.header.exercise_id = static_cast<std::uint8_t>(opt_.exercise);
    if (pack_) {  // several Entity States to a datagram of at most 1400 octets
      if (!batch_.add(es_)) {
        flush_batch();
        if (!batch_.add(es_)) continue;  // cannot happen for our PDUs (no variable parameters)
      }
    } else if (!session_->send(es_)) {
      continue;
    }
    pubs_[i].mark_sent(s, t);
    sent_appearance_[i] = app;
    ++sent_now;
    if (w.kinds[w.ents.kind[e]].mobility == world::Mobility::Ground) ++ground_es_sent_;
  }
  if (first_deferred != n) rr_ = first_deferred;
  flush_batch();
}

void NetBridge::flush_batch() {
  if (!batch_.empty()) session_->send(batch_);
  batch_.clear();
}

void NetBridge::leave() {
  const auto& w = sim_.world();
  for (size_t i = 0; i < own_.size(); ++i) {
    const int e = own_[i];
    const net::KinematicState s = truth(e);
    es_.entity_id = own_id(e);
    es_.entity_type = to_net(w.kinds[w.ents.kind[e]].dis);
    es_.alternative_entity_type = es_.entity_type;
    auto mk = net::make_marking(w.ents.id[e]);
    es_.marking = mk ? mk.value() : net::Marking{};
    es_.appearance = appearance_of(e) | net::kAppearanceDeactivated;
    net::write_kinematics(s, net::DrAlgorithm::Static, es_);
    es_.header.timestamp = net::relative_timestamp(w.t);
    session_->send(es_);
  }
}

void NetBridge::publish_collisions(const TickReport& r) {
  const auto& w = sim_.world();
  const auto& ents = w.ents;
  for (const auto& c : r.changes.collisions) {
    if (c.b_fixed || c.a < 0 || c.b < 0) continue;
    int own = -1, other = -1;
    if (is_own_vehicle(c.a) && remote_id_[c.b].site != 0) own = c.a, other = c.b;
    else if (is_own_vehicle(c.b) && remote_id_[c.a].site != 0) own = c.b, other = c.a;
    if (own < 0 || !(own_id(own) < remote_id_[other])) continue;  // not ours to announce
    net::CollisionPdu p;
    p.issuing_entity_id = own_id(own);
    p.colliding_entity_id = remote_id_[other];
    p.event_id = {static_cast<std::uint16_t>(opt_.site), static_cast<std::uint16_t>(opt_.app), ++event_number_};
    const world::Result res = own == c.a ? c.result_a : c.result_b;
    p.collision_type = res == world::Result::Bounce ? kCollisionElastic : kCollisionInelastic;
    Vec3 v = ents.vel[own];
    for (const auto& pd : pending_)
      if (pd.own == own && pd.other == other) v = pd.own_vel;
    const auto& frame = w.terrain.frame();
    const Vec3 pe = frame.to_ecef(ents.pos[own]);
    const Vec3 ve = frame.to_ecef(ents.pos[own] + v) - pe;
    p.velocity = {static_cast<float>(ve.x()), static_cast<float>(ve.y()), static_cast<float>(ve.z())};
    p.mass = static_cast<float>(w.kinds[ents.kind[own]].mass_kg);
    const Vec3 d = c.point - ents.pos[own];
    const double h = ents.heading_deg[own] * kDeg;
    p.location_in_entity = {static_cast<float>(d.x() * std::sin(h) + d.y() * std::cos(h)),
                            static_cast<float>(d.x() * std::cos(h) - d.y() * std::sin(h)), static_cast<float>(-d.z())};
    p.header.timestamp = net::relative_timestamp(w.t);
    session_->send(p);
  }
}

void NetBridge::send_cultural(int o) {
  const auto& w = sim_.world();
  if (static_cast<size_t>(o) + 1 > 0xFFFF) return;
  net::EntityStatePdu p;
  p.entity_id = {static_cast<std::uint16_t>(opt_.site), cultural_app_, static_cast<std::uint16_t>(o + 1)};
  p.entity_type = to_net(w.kinds[w.fixed.kind[o]].dis);
  p.alternative_entity_type = p.entity_type;
  net::KinematicState s;
  const auto& frame = w.terrain.frame();
  s.position = ev(frame.to_ecef(w.fixed.pos[o]));
  const Vec3 eu = frame.to_dis_euler(w.fixed.pos[o], w.fixed.heading_deg[o], 0, 0);
  s.orientation = {eu.x(), eu.y(), eu.z()};
  net::write_kinematics(s, net::DrAlgorithm::Static, p);
  p.appearance = w.fixed.state[o];
  auto mk = net::make_marking(w.fixed.id[o].substr(0, 11));
  p.marking = mk ? mk.value() : net::Marking{};
  p.header.timestamp = net::relative_timestamp(w.t);
  session_->send(p);
}

void NetBridge::publish_fixed(const TickReport& r) {
  const auto& w = sim_.world();
  for (const auto& d : r.applied.damage) {
    if (!d.fixed) continue;
    if (d.to_state <= fixed_net_state_[d.index]) continue;  // heard from the network already
    fixed_net_state_[d.index] = static_cast<int16_t>(d.to_state);
    auto it = std::find(fixed_published_.begin(), fixed_published_.end(), d.index);
    if (it == fixed_published_.end()) {
      fixed_published_.push_back(d.index);
      fixed_last_sent_.push_back(now_s_);
    } else {
      fixed_last_sent_[it - fixed_published_.begin()] = now_s_;
    }
    send_cultural(d.index);
  }
  const double hb = remotes_.thresholds().heartbeat_s;
  for (size_t i = 0; i < fixed_published_.size(); ++i)
    if (now_s_ - fixed_last_sent_[i] >= hb) {
      fixed_last_sent_[i] = now_s_;
      send_cultural(fixed_published_[i]);
    }
  (void)w;
}

void NetBridge::publish_fires(const TickReport& r) {
  const auto& w = sim_.world();
  const auto& ents = w.ents;
  const auto& frame = w.terrain.frame();
  for (const int m : r.fired) {
    if (m < 0 || !ents.local[m]) continue;
    net::FirePdu p;
    const int shooter = ents.owner[m];
    if (shooter >= 0) p.firing_entity_id = own_id(shooter);
    const int tgt = ents.target[m];
    if (tgt >= 0) p.target_entity_id = remote_id_[tgt].site ? remote_id_[tgt] : own_id(tgt);
    p.munition_id = own_id(m);
    const std::uint16_t evn = ++event_number_;
    fire_event_[m] = evn;
    p.event_id = {static_cast<std::uint16_t>(opt_.site), static_cast<std::uint16_t>(opt_.app), evn};
    const Vec3 pe = frame.to_ecef(ents.pos[m]);
    p.location = {pe.x(), pe.y(), pe.z()};
    p.descriptor.munition_type = to_net(w.kinds[ents.kind[m]].dis);
    p.descriptor.warhead = kWarheadHighExplosive;
    p.descriptor.fuse = kFuseContact;
    p.descriptor.quantity = 1;
    const Vec3 ve = frame.to_ecef(ents.pos[m] + ents.vel[m]) - pe;
    p.velocity = {static_cast<float>(ve.x()), static_cast<float>(ve.y()), static_cast<float>(ve.z())};
    p.range = static_cast<float>((ents.aim[m] - ents.pos[m]).norm());
    p.header.timestamp = net::relative_timestamp(w.t);
    session_->send(p);
  }
}

void NetBridge::publish_detonations(const TickReport& r) {
  const auto& w = sim_.world();
  const auto& ents = w.ents;
  const auto& frame = w.terrain.frame();
  for (const auto& d : r.changes.detonations) {
    const int m = d.munition;
    if (m < 0 || !ents.local[m]) continue;  // injected from the network
    net::DetonationPdu p;
    if (ents.owner[m] >= 0) p.firing_entity_id = own_id(ents.owner[m]);
    if (d.target >= 0) p.target_entity_id = remote_id_[d.target].site ? remote_id_[d.target] : own_id(d.target);
    p.exploding_entity_id = own_id(m);
    auto it = fire_event_.find(m);
    p.event_id = {static_cast<std::uint16_t>(opt_.site), static_cast<std::uint16_t>(opt_.app),
                  it != fire_event_.end() ? it->second : ++event_number_};
    if (it != fire_event_.end()) fire_event_.erase(it);
    const Vec3 pe = frame.to_ecef(d.point);
    p.location = {pe.x(), pe.y(), pe.z()};
    const Vec3 ve = frame.to_ecef(d.point + ents.vel[m]) - pe;
    p.velocity = {static_cast<float>(ve.x()), static_cast<float>(ve.y()), static_cast<float>(ve.z())};
    p.descriptor.munition_type = to_net(w.kinds[ents.kind[m]].dis);
    p.descriptor.warhead = kWarheadHighExplosive;
    p.descriptor.fuse = kFuseContact;
    p.descriptor.quantity = 1;
    p.detonation_result = d.target >= 0 ? kResultEntityImpact : kResultGroundImpact;
    p.header.timestamp = net::relative_timestamp(w.t);
    session_->send(p);
  }
}

void NetBridge::after_tick(const TickReport& r) {
  now_s_ = clock_s();
  if (remote_id_.size() < sim_.world().ents.size()) remote_id_.resize(sim_.world().ents.size());
  publish_fires(r);
  publish_vehicles();  // Entity States first: a Collision PDU's outcome reads the issuer's appearance
  publish_collisions(r);
  publish_detonations(r);
  publish_fixed(r);
}

}  // namespace npsnet::node
