#include "node/net_bridge.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "node/dis_mapping.hpp"
#include "node/pdu_build.hpp"

namespace npsnet::node {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
// Entity State datagrams one tick sends at most (one PDU each); the rest go on the next ticks.
// A receiver drains its socket once a tick: 128 datagrams fit its default receive buffer
// (Linux rmem_default 208 KiB), where the 517 first Entity States of the default scenario did not.
constexpr size_t kMaxDatagramsPerTick = 128;
// Received values past these are corrupt or hostile: a speed (m/s) and the offset of a contact
// point from its entity (m).
constexpr double kMaxSpeedMps = 1e4;
constexpr double kMaxContactOffsetM = 1000.0;
// Published acceleration (ours, not the standard's): low-pass time constant (s), and the speed
// (m/s) below which a vehicle is at rest and sends none.
constexpr double kAccelTauS = 0.5;
constexpr double kAtRestMps = 0.05;

double round3(double v) { return std::round(v * 1000.0) / 1000.0; }
Vec3 vv(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
double wrap180(double d) {
  d = std::fmod(d + 180.0, 360.0);
  if (d < 0) d += 360.0;
  return d - 180.0;
}

}  // namespace

NetBridge::NetBridge(const BridgeOptions& o, Simulation& sim, EventLog& log) : NetBridge(o, open_session(o), sim, log) {}

NetBridge::NetBridge(const BridgeOptions& o, std::unique_ptr<net::Session> session, Simulation& sim, EventLog& log)
    : opt_(o),
      sim_(sim),
      log_(log),
      session_(std::move(session)),
      remotes_(dr_thresholds(o.timeout_s), sim, log, o.entity_types),
      ownership_(net::EntityId{static_cast<std::uint16_t>(o.site), static_cast<std::uint16_t>(o.app), 0}),
      cultural_app_(static_cast<std::uint16_t>(kCulturalAppBit | o.app)) {
  if (!session_) throw std::runtime_error("--net: no session");
  detonations_.set_identity(static_cast<std::uint16_t>(o.site), static_cast<std::uint16_t>(o.app));
  drop_detonations_s_ = test_drop_detonations_from_env();
  munitions_ = o.munitions ? o.munitions : std::make_shared<const MunitionTable>(MunitionTable::load(MunitionTable::default_file()));
  world::World& w = sim_.world();
  auto& ents = w.ents;
  // Entity numbers 1-32767 under each of our applications (ownership.hpp), with room for the
  // rounds fired later: one block more than the scenario's entities need.
  const int blocks = static_cast<int>(ents.size() / net::kEntitiesPerApplication) + 1;
  if (o.app + (blocks - 1) * net::kApplicationStride >= kCulturalAppBit)
    throw std::runtime_error("--net: the scenario has " + std::to_string(ents.size()) + " entities: numbered " +
                             std::to_string(net::kEntitiesPerApplication) + " to an application from --app " +
                             std::to_string(o.app) + " in steps of " + std::to_string(net::kApplicationStride) +
                             ", they need " + std::to_string(blocks) + " applications, past 32767; give a smaller --app");
  ownership_.set_application_blocks(blocks);
  session_->set_application_blocks(static_cast<std::uint16_t>(blocks));
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
  pubs_.assign(own_.size(), net::DrPublisher(net::DrAlgorithm::RVW, dr_thresholds(o.timeout_s)));
  sent_appearance_.assign(own_.size(), 0);
  sent_group_.assign(own_.size(), net::Session::kDestination);
  if (o.aoi_cell_m > 0)
    aoi_ = std::make_unique<AreaOfInterest>(o.aoi_cell_m, o.aoi_groups, session_->transport().destination().address, w,
                                            dr_thresholds(o.timeout_s).heartbeat_s);
  prev_vel_.assign(own_.size(), Vec3::Zero());
  accel_.assign(own_.size(), Vec3::Zero());
  yaw_rate_.assign(own_.size(), 0.f);
  anchors_.assign(own_.size(), DrAnchor{});
  quiet_.assign(own_.size(), 0);
  prev_heading_.assign(own_.size(), 0.f);
  removed_.assign(own_.size(), 0);
  for (size_t i = 0; i < own_.size(); ++i) prev_heading_[i] = ents.heading_deg[own_[i]];
  fixed_net_state_.assign(w.fixed.size(), -1);
  fixed_slot_.assign(w.fixed.size(), -1);
  for (size_t f = 0; f < w.fixed.size(); ++f) fixed_net_state_[f] = static_cast<int16_t>(w.fixed.state[f]);
  start_s_ = now_s_ = clock_s();
  pack_ = dis_pack_from_env();
}

NetBridge::~NetBridge() = default;

void NetBridge::set_source(DatagramSource source) {
  source_ = std::move(source);
  start_s_ = now_s_ = clock_s();
}

double NetBridge::clock_s() const {
  if (source_) return sim_.world().t;
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void NetBridge::attach() {
  chained_on_tick_ = sim_.on_tick;
  sim_.before_step = [this](world::World& w) { before_step(w); };
  sim_.decides = [this](const collision::Contact& c) { return decides(c); };
  sim_.on_tick = [this](const TickReport& r) {
    if (chained_on_tick_ && !catching_up_) chained_on_tick_(r);
    after_tick(r);
  };
}

void NetBridge::catch_up(bool on) {
  if (catching_up_ && !on) {  // going live: announce everything at the next tick
    pubs_.assign(own_.size(), net::DrPublisher(net::DrAlgorithm::RVW, dr_thresholds(opt_.timeout_s)));
    anchors_.assign(own_.size(), DrAnchor{});
    accel_.assign(own_.size(), Vec3::Zero());
    const auto& ents = sim_.world().ents;
    for (size_t i = 0; i < own_.size(); ++i) prev_vel_[i] = ents.vel[own_[i]], prev_heading_[i] = ents.heading_deg[own_[i]];
    const double hb = remotes_.thresholds().heartbeat_s;
    for (double& s : fixed_last_sent_) s = clock_s() - hb;
  }
  catching_up_ = on;
}

void NetBridge::check_signal() {
  if (usr1_.take()) std::fprintf(stderr, "%s\n", summary().c_str());
}

std::string NetBridge::summary() const {
  char b[256];
  const double s = std::max(1e-9, published_s());
  const double per = ground_vehicles_ ? ground_es_sent_ / (ground_vehicles_ * s / 60.0) : 0.0;
  std::snprintf(b, sizeof b,
                "\n  net: %d local ground vehicles, %llu entity_state PDUs in %.1f s: %.1f per vehicle-minute "
                "(fixed 10 Hz: 600); %zu remote entities",
                ground_vehicles_, (unsigned long long)ground_es_sent_, s, per, remotes_.size());
  std::string r = "  net: " + session_->counters().summary() + b;
  if (detonations_.kept() || detonations_.repeats_ignored())
    r += "\n  net: detonations kept " + std::to_string(detonations_.kept()) + " (repeated " +
         std::to_string(detonations_.repeats_sent()) + " times, " + std::to_string(detonations_.dropped_kept()) +
         " past the cap); repeats received and ignored " + std::to_string(detonations_.repeats_ignored()) +
         "; adopted " + std::to_string(detonations_.adoptions()) + " of silent nodes (sent " +
         std::to_string(detonations_.adopted_sent()) + " times)";
  if (dropped_detonations_)
    r += "\n  net: test hook NPSNET_TEST_DROP_DETONATIONS_S dropped " + std::to_string(dropped_detonations_) +
         " received Detonation PDUs";
  if (fixed_unnumbered_)
    r += "\n  net: " + std::to_string(fixed_unnumbered_) + " fixed-object changes not published (index past 65534)";
  r += remotes_.listing(clock_s());
  return r;
}

bool NetBridge::is_own_vehicle(int e) const {
  const auto& ents = sim_.world().ents;
  return e >= 0 && static_cast<size_t>(e) < ents.size() && ents.local[e] && ents.node[e] == opt_.node &&
         !remotes_.is_remote(e) && sim_.world().kinds[ents.kind[e]].mobility != world::Mobility::Munition;
}

int NetBridge::own_entity_of(const net::EntityId& id) const {
  const int e = ownership_.own_index(id);
  return is_own_vehicle(e) ? e : -1;
}

net::EntityId NetBridge::net_id(int e) const { return remotes_.is_remote(e) ? remotes_.id_of(e) : own_id(e); }

net::EventId NetBridge::next_event() {
  return {static_cast<std::uint16_t>(opt_.site), static_cast<std::uint16_t>(opt_.app), ++event_number_};
}

nlohmann::json NetBridge::event(const char* type) const {
  const auto& w = sim_.world();
  return {{"event", type}, {"t", round3(w.t)}, {"frame", w.frame}};
}

// ---------------------------------------------------------------- receive ----

void NetBridge::receive(std::span<const std::uint8_t> datagram, double arrival_s) {
  const bool process = !frozen_ || (frozen_behavior_ & 4);  // a freeze may stop processing updates
  // UTC dates absolute timestamps; a recording's clock is not now.
  const double utc = source_ ? net::RemoteEntityTable::kNoUtc
                             : std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  session_->parse(datagram, net::Overloaded{
                                [&](const net::StopFreezePdu& p) { on_stop_freeze(p); },
                                [&](const net::StartResumePdu& p) { on_start_resume(p); },
                                [&](const net::RemoveEntityPdu& p) { on_remove_entity(p); },
                                [&](const net::EntityStatePdu& p) {
                                  detonations_.heard(p.entity_id.site, p.entity_id.application & ~kCulturalAppBit,
                                                     arrival_s);  // a live node (adoption rank)
                                  if (!process) return;
                                  if (p.entity_type.kind == dis::kEntityKindCultural &&
                                      (p.entity_id.application & kCulturalAppBit))
                                    on_cultural(p);
                                  else if (p.entity_type.kind != dis::kEntityKindMunition)  // rounds: Fire / Detonation
                                    remotes_.on_entity_state(p, arrival_s, utc);
                                },
                                [&](const net::EntityStateUpdatePdu& p) {
                                  if (process) remotes_.on_update(p, arrival_s, utc);
                                },
                                [&](const net::FirePdu& p) { on_fire(p); },
                                [&](const net::DetonationPdu& p) {
                                  // An adopted round we repeat comes back with the firing node's id:
                                  // our own datagram, not someone else repeating it.
                                  if (!session_->sent_by_us(datagram)) on_detonation(p, arrival_s);
                                },
                                [&](const net::CollisionPdu& p) { on_collision(p); }});
  if (!clash_reported_ && session_->counters().own_id_clash > 0) report_clash();
}

void NetBridge::report_clash() {
  clash_reported_ = true;
  std::fprintf(stderr,
               "npsnet: net: another simulator sends PDUs as site %d application %d, our DIS identity: its "
               "entities clash with ours and are ignored; give one of the two another --site/--app\n",
               opt_.site, opt_.app);
  auto ev = event("id_clash");
  ev["site"] = opt_.site;
  ev["application"] = opt_.app;
  log_.write(ev);
}

void NetBridge::before_step(world::World& w) {
  now_s_ = clock_s();
  if (catching_up_) return;  // the past: no network
  if (!started_) started_ = true, start_s_ = now_s_;  // rates count from the first tick
  ownership_.clear();
  check_signal();
  if (aoi_) aoi_->update(w, own_, *session_);  // join / leave before draining the socket
  session_->poll_datagrams([&](std::span<const std::uint8_t> d) { receive(d, now_s_); });
  if (source_) source_(now_s_, *this);
  remotes_.mirror(now_s_);
}

void NetBridge::on_cultural(const net::EntityStatePdu& p) {
  if (p.entity_id.site == opt_.site && p.entity_id.application == cultural_app_) return;  // our echo
  world::World& w = sim_.world();
  if (p.entity_id.entity == 0 || p.entity_id.entity > w.fixed.size()) return;
  const int o = p.entity_id.entity - 1;
  const world::Kind& k = w.kinds[w.fixed.kind[o]];
  if (!same_type(k.dis, p.entity_type)) return;  // not the same object: other scenario or objects file
  const int to = state_from_appearance(k, p.appearance);  // damage bits 3-4 (dis_mapping.hpp)
  if (to > fixed_net_state_[o]) {
    fixed_net_state_[o] = static_cast<int16_t>(to);
    // Every node that knows a changed object keeps publishing it (states only go forward, so
    // the highest heard wins): it outlives its first publisher, and a late joiner learns it.
    if (fixed_slot_[o] < 0) start_publishing(o);
  }
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
  if (ours(p.colliding_entity_id)) {
    own = own_entity_of(p.colliding_entity_id);
    if (own < 0) return;
  } else {
    own = remotes_.index_of(p.colliding_entity_id);
    if (own < 0 || !ents.active[own]) return;
    third = true;
  }
  const int other = remotes_.index_of(p.issuing_entity_id);
  if (other < 0 || !ents.active[other]) return;
  const net::RemoteEntity* issuer = remotes_.find(p.issuing_entity_id);
  if (!issuer) return;
  // Outcome: elastic = bounce; inelastic = kill when the issuer now reads destroyed, else stop.
  world::Result res = world::Result::Bounce;
  if (p.collision_type != dis::kCollisionElastic)
    res = damage_bits(issuer->appearance) == dis::kDamageDestroyed ? world::Result::Kill : world::Result::Stop;
  const auto& frame = w.terrain.frame();
  const Vec3 other_pos = ents.pos[other];
  Eigen::Vector3d ve(p.velocity.x, p.velocity.y, p.velocity.z);
  Vec3 v_other = ents.vel[other];
  if (ve.allFinite() && ve.norm() < kMaxSpeedMps) {
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
  const Vec3 loc(p.location_in_entity.x, p.location_in_entity.y, p.location_in_entity.z);
  rec.point = loc.allFinite() && loc.norm() < kMaxContactOffsetM
                  ? Vec3(other_pos + fwd * loc.x() + right * loc.y() - Vec3::UnitZ() * loc.z())
                  : Vec3((other_pos + ents.pos[own]) / 2);
  rec.closing_speed_mps = std::max(0.0, (v_other - ents.vel[own]).dot(n));
  rec.angle_deg = collision::impact_angle_deg(ents.heading_deg[rec.a], ents.heading_deg[rec.b]);
  rec.method = "network";
  rec.tier = "network";
  rec.result_a = rec.result_b = res;
  inject_.clear();
  inject_.collisions.push_back(rec);
  world::EntityChange mine;
  mine.entity = own;
  mine.set_vel = !third;
  if (res == world::Result::Bounce && third) {
    mine.set_vel = false;
  } else if (res == world::Result::Bounce) {
    // The issuer's mass as it says; left unset (0) or unusable: the mass of the kind its type
    // maps to (models/entity_types.toml), as for the contacts we decide.
    const double said = p.mass;
    const double ma = std::isfinite(said) && said > 0 ? said : w.kinds[ents.kind[other]].mass_kg;
    const double mb = w.kinds[ents.kind[own]].mass_kg;
    Vec3 vb = ents.vel[own];
    vb += (collision::bounce_impulse(v_other, vb, ma, mb, n) / mb) * n;
    if (w.kinds[ents.kind[own]].mobility != world::Mobility::Air) vb.z() = 0;
    mine.vel = vb;
    mine.cruise_mps = static_cast<float>(vb.norm());
  } else {
    mine.vel = Vec3::Zero();
    mine.cruise_mps = third ? -1.f : 0.f;
    // Our entity's damage is ours to decide; the issuer's (and a third node's copy) arrive in
    // their owners' appearance.
    if (res == world::Result::Kill && !third) mine.to_state = static_cast<int>(w.kinds[ents.kind[own]].states.size()) - 1;
  }
  inject_.entities.push_back(mine);
  sim_.inject(inject_);
  inject_.clear();
}

// ---------------------------------------------------------------- decide ----

bool NetBridge::decides(const collision::Contact& c) { return ownership_.decides(sim_.world(), remotes_, c); }

// ---------------------------------------------------------------- send ------

void NetBridge::publish_vehicles() {
  const auto& w = sim_.world();
  const double dt = sim_.dt();
  const double t = w.t + dt;  // the time of the state: dynamics has stepped, w.t not yet
  const size_t n = own_.size();
  size_t sent_now = 0, first_deferred = n;
  // Every vehicle in the local frame, on the tick's threads: the published acceleration (the
  // velocity change per tick, low-pass filtered over kAccelTauS, zero at rest: a tank stopping in
  // one tick is not sent as |a| = 100 m/s^2), the yaw rate, and whether its Entity State is surely
  // not due (dr_bound.hpp).
  const double alpha = dt / (kAccelTauS + dt);
  auto local = [&](int, size_t i0, size_t i1) {
    for (size_t i = i0; i < i1; ++i) {
      const int e = own_[i];
      const Vec3& v = w.ents.vel[e];
      if (pubs_[i].has_sent()) accel_[i] += ((v - prev_vel_[i]) / dt - accel_[i]) * alpha;
      if (!pubs_[i].has_sent() || v.norm() < kAtRestMps) accel_[i].setZero();
      prev_vel_[i] = v;
      yaw_rate_[i] = static_cast<float>(wrap180(w.ents.heading_deg[e] - prev_heading_[i]) * kDeg / dt);
      prev_heading_[i] = w.ents.heading_deg[e];
      quiet_[i] = opt_.dr_prefilter && !removed_[i] && dr_quiet(anchors_[i], pubs_[i], w, e, t);
    }
  };
  if (core::Jobs* jobs = sim_.jobs()) jobs->for_chunks(n, 2048, local);
  else local(0, 0, n);
  // Round robin from where the last tick's cap stopped, so no vehicle waits more than a few ticks.
  for (size_t k = 0; k < n; ++k) {
    const size_t i = (rr_ + k) % n;
    const int e = own_[i];
    if (removed_[i]) continue;  // taken out by a Remove Entity
    const std::uint32_t app = damage_appearance(w.kinds[w.ents.kind[e]], w.ents.state[e]);
    const std::uint32_t group = group_at(w.ents.pos[e]);
    // A damage change, or a move into another cell's group (announced there at once).
    const bool changed = pubs_[i].has_sent() && (app != sent_appearance_[i] || group != sent_group_[i]);
    if (!changed && quiet_[i]) continue;  // the exact test would say None
    const bool capped = (!pack_ || aoi_) && sent_now >= kMaxDatagramsPerTick;
    if (capped && !changed && first_deferred != n && opt_.dr_prefilter) continue;  // deferred whatever it says
    net::KinematicState s = exact_state(w, e, pubs_[i], t, anchors_[i]);
    ++exact_tests_;
    s.acceleration = anchors_[i].jac * accel_[i];
    s.angular_velocity = Eigen::Vector3d(0, 0, yaw_rate_[i]);
    if (!changed && pubs_[i].needs_update(s, t) == net::DrPublisher::Reason::None) continue;
    if (capped && !changed) {  // a damage change never waits
      if (first_deferred == n) first_deferred = i;
      continue;
    }
    fill_entity_state(w, e, own_id(e), s, pubs_[i].algorithm(), app, static_cast<std::uint8_t>(opt_.exercise), t, es_);
    es_.header.protocol_version = static_cast<std::uint8_t>(opt_.dis_version);  // packed datagrams too
    if (pack_ && !aoi_) {  // several Entity States to a datagram of at most 1400 octets
      if (!batch_.add(es_)) {
        flush_batch();
        if (!batch_.add(es_)) {  // cannot happen for our PDUs (no variable parameters)
          ++session_->counters().send_failures;
          continue;
        }
      }
    } else if (!session_->send_to(group, es_)) {
      continue;
    }
    pubs_[i].mark_sent(s, t);
    dr_rebase(s, pubs_[i], t, anchors_[i]);
    digest_entity_state();
    sent_appearance_[i] = app;
    sent_group_[i] = group;
    ++sent_now;
    if (w.kinds[w.ents.kind[e]].mobility == world::Mobility::Ground) ++ground_es_sent_;
  }
  if (first_deferred != n) rr_ = first_deferred;
  flush_batch();
}

void NetBridge::digest_entity_state() {
  auto mix = [&](const void* p, size_t len) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (size_t k = 0; k < len; ++k) es_digest_ = (es_digest_ ^ b[k]) * 1099511628211ull;
  };
  mix(&es_.entity_id.entity, sizeof es_.entity_id.entity);
  mix(&es_.location, sizeof es_.location);
  mix(&es_.linear_velocity, sizeof es_.linear_velocity);
  mix(&es_.orientation, sizeof es_.orientation);
  mix(&es_.dead_reckoning.linear_acceleration, sizeof es_.dead_reckoning.linear_acceleration);
  mix(&es_.dead_reckoning.angular_velocity, sizeof es_.dead_reckoning.angular_velocity);
  mix(&es_.appearance, sizeof es_.appearance);
  mix(&es_.header.timestamp, sizeof es_.header.timestamp);
}

void NetBridge::flush_batch() {
  if (!batch_.empty()) session_->send(batch_);
  batch_.clear();
}

void NetBridge::send_deactivation(int e) {
  const auto& w = sim_.world();
  const std::uint32_t app = damage_appearance(w.kinds[w.ents.kind[e]], w.ents.state[e]) | net::kAppearanceDeactivated;
  fill_entity_state(w, e, own_id(e), entity_truth(w, e), net::DrAlgorithm::Static, app,
                    static_cast<std::uint8_t>(opt_.exercise), w.t, es_);
  session_->send_to(group_at(w.ents.pos[e]), es_);
}

void NetBridge::leave() {
  for (size_t i = 0; i < own_.size(); ++i)
    if (!removed_[i]) send_deactivation(own_[i]);
}

void NetBridge::publish_collisions(const TickReport& r) {
  const auto& w = sim_.world();
  for (const auto& c : r.changes.collisions) {
    if (c.b_fixed || c.a < 0 || c.b < 0) continue;
    int own = -1, other = -1;
    if (is_own_vehicle(c.a) && remotes_.is_remote(c.b)) own = c.a, other = c.b;
    else if (is_own_vehicle(c.b) && remotes_.is_remote(c.a)) own = c.b, other = c.a;
    if (own < 0 || !ownership_.announces(own, remotes_, other)) continue;  // not ours to announce
    const world::Result res = own == c.a ? c.result_a : c.result_b;
    const Vec3 v = ownership_.velocity_before(own, other, w.ents.vel[own]);
    // To the colliding entity's cell: its owner holds that group.
    session_->send_to(group_at(w.ents.pos[other]),
                      collision_pdu(w, own, own_id(own), remotes_.id_of(other), next_event(), res, v, c.point));
  }
}

void NetBridge::send_cultural(int o) {
  if (static_cast<size_t>(o) + 1 > 0xFFFF) {
    if (fixed_unnumbered_++ == 0)
      std::fprintf(stderr, "npsnet: net: fixed object %d changed but cannot be published: cultural entity numbers end at 65535\n", o);
    return;
  }
  net::EntityStatePdu p;
  fill_cultural(sim_.world(), o, {static_cast<std::uint16_t>(opt_.site), cultural_app_, static_cast<std::uint16_t>(o + 1)}, p);
  session_->send_to(group_at(sim_.world().fixed.pos[o]), p);
}

void NetBridge::start_publishing(int o) {
  fixed_slot_[o] = static_cast<int>(fixed_published_.size());
  fixed_published_.push_back(o);
  fixed_last_sent_.push_back(now_s_);
}

void NetBridge::publish_fixed(const TickReport& r) {
  for (const auto& d : r.applied.damage) {
    if (!d.fixed) continue;
    if (d.to_state <= fixed_net_state_[d.index]) continue;  // heard from the network already
    fixed_net_state_[d.index] = static_cast<int16_t>(d.to_state);
    if (fixed_slot_[d.index] < 0) start_publishing(d.index);
    else fixed_last_sent_[fixed_slot_[d.index]] = now_s_;
    if (!catching_up_) send_cultural(d.index);
  }
  if (catching_up_) return;
  const double hb = remotes_.thresholds().heartbeat_s;
  for (size_t i = 0; i < fixed_published_.size(); ++i)
    if (now_s_ - fixed_last_sent_[i] >= hb) {
      fixed_last_sent_[i] = now_s_;
      send_cultural(fixed_published_[i]);
    }
}

void NetBridge::publish_fires(const TickReport& r) {
  const auto& ents = sim_.world().ents;
  for (const int m : r.fired) {
    if (m < 0 || !ents.local[m]) continue;
    const int shooter = ents.owner[m], tgt = ents.target[m];
    const net::EventId evn = next_event();
    fire_event_[m] = evn.event_number;
    session_->send_to(group_at(ents.pos[m]), fire_pdu(sim_.world(), m, shooter >= 0 ? own_id(shooter) : net::EntityId{},
                                                      tgt >= 0 ? net_id(tgt) : net::EntityId{}, own_id(m), evn));
  }
}

void NetBridge::publish_detonations(const TickReport& r) {
  const auto& ents = sim_.world().ents;
  for (const auto& d : r.changes.detonations) {
    const int m = d.munition;
    if (m < 0 || !ents.local[m]) continue;  // another node's round
    auto it = fire_event_.find(m);
    net::EventId evn{static_cast<std::uint16_t>(opt_.site), static_cast<std::uint16_t>(opt_.app), 0};
    if (it != fire_event_.end()) {
      evn.event_number = it->second;
      fire_event_.erase(it);
    } else {
      evn = next_event();
    }
    const auto pdu = detonation_pdu(sim_.world(), d, ents.owner[m] >= 0 ? own_id(ents.owner[m]) : net::EntityId{},
                                    d.target >= 0 ? net_id(d.target) : net::EntityId{}, own_id(m), evn);
    const std::uint32_t group = group_at(d.point);
    session_->send_to(group, pdu);
    detonations_.sent(pdu, group, now_s_);
  }
  detonations_.resend_due(now_s_, remotes_.thresholds().heartbeat_s, remotes_.thresholds().timeout_s,
                          [&](const net::DetonationPdu& pdu, std::uint32_t group) { session_->send_to(group, pdu); });
}

void NetBridge::after_tick(const TickReport& r) {
  now_s_ = clock_s();
  if (catching_up_) {  // the past: our fires are held, remote entities absent; objects noted
    publish_fixed(r);
    return;
  }
  publish_fires(r);
  publish_vehicles();  // Entity States first: a Collision PDU's outcome reads the issuer's appearance
  publish_collisions(r);
  publish_detonations(r);
  publish_fixed(r);
}

}  // namespace npsnet::node
