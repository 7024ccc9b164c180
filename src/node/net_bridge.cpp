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

double round3(double v) { return std::round(v * 1000.0) / 1000.0; }

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
  collisions_.set_identity(static_cast<std::uint16_t>(o.site), static_cast<std::uint16_t>(o.app));
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
  quick_.assign(own_.size(), DrQuick{});
  changed_.assign(own_.size(), 0);
  prev_heading_.assign(own_.size(), 0.f);
  removed_.assign(own_.size(), 0);
  announce_left_.assign(own_.size(), 0);
  announce_at_.assign(own_.size(), 0.0);
  for (size_t i = 0; i < own_.size(); ++i) prev_heading_[i] = ents.heading_deg[own_[i]];
  fixed_net_state_.assign(w.fixed.size(), -1);
  fixed_slot_.assign(w.fixed.size(), -1);
  for (size_t f = 0; f < w.fixed.size(); ++f) fixed_net_state_[f] = static_cast<int16_t>(w.fixed.state[f]);
  start_s_ = now_s_ = polled_s_ = clock_s();
  pack_ = dis_pack_from_env();
}

NetBridge::~NetBridge() = default;

bool NetBridge::dated_before_join(std::uint32_t timestamp) const {
  // NPSNET nodes date their PDUs by the scenario clock in a relative timestamp (low bit 0).
  if (joined_t_ < 0 || (timestamp & 1u)) return false;
  if (net::timestamp_difference(net::relative_timestamp(joined_t_), timestamp) > 0) return true;
  // Relative timestamps wrap at the hour, so one dated more than 30 min before the join reads as
  // after it. A PDU of a new event is dated within seconds of now (the nodes share the scenario
  // clock, --start-at; one waiting for its entity waits one DIS timeout at most); one dated
  // further from now, either way, repeats the past.
  const double fresh_s = 2 * remotes_.thresholds().timeout_s;
  return std::fabs(net::timestamp_difference(net::relative_timestamp(sim_.world().t), timestamp)) > fresh_s;
}

void NetBridge::set_source(DatagramSource source) {
  source_ = std::move(source);
  start_s_ = now_s_ = clock_s();
}

double NetBridge::clock_s() const {
  if (source_) return sim_.world().t;
  return net::steady_now_s();  // the clock the transport dates arrivals on (poll_socket)
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
    quick_.assign(own_.size(), DrQuick{});
    accel_.assign(own_.size(), Vec3::Zero());
    const auto& ents = sim_.world().ents;
    for (size_t i = 0; i < own_.size(); ++i) prev_vel_[i] = ents.vel[own_[i]], prev_heading_[i] = ents.heading_deg[own_[i]];
    const double hb = remotes_.thresholds().heartbeat_s;
    for (double& s : fixed_last_sent_) s = clock_s() - hb;
    joined_t_ = sim_.world().t;
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
  if (collisions_.kept() || collisions_.repeats_ignored())
    r += "\n  net: collisions kept " + std::to_string(collisions_.kept()) + " (repeated " +
         std::to_string(collisions_.repeats_sent()) + " times); repeats received and ignored " +
         std::to_string(collisions_.repeats_ignored()) + "; adopted " + std::to_string(collisions_.adoptions());
  if (collisions_given_up_)
    r += "\n  net: " + std::to_string(collisions_given_up_) + " Collision PDUs gave up waiting for an entity (a DIS timeout)";
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
  // UTC dates absolute timestamps: ours at arrival_s (as long before now on the bridge clock);
  // a recording's clock is not now.
  const double utc =
      source_ ? net::RemoteEntityTable::kNoUtc
              : std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count() -
                    std::max(0.0, clock_s() - arrival_s);
  session_->parse(datagram, net::Overloaded{
                                [&](const net::StopFreezePdu& p) { on_stop_freeze(p); },
                                [&](const net::StartResumePdu& p) { on_start_resume(p); },
                                [&](const net::RemoveEntityPdu& p) { on_remove_entity(p); },
                                [&](const net::EntityStatePdu& p) {
                                  // A live node (adoption rank).
                                  const std::uint16_t app = p.entity_id.application & ~kCulturalAppBit;
                                  detonations_.heard(p.entity_id.site, app, arrival_s);
                                  collisions_.heard(p.entity_id.site, app, arrival_s);
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
                                [&](const net::CollisionPdu& p) {
                                  // An adopted collision we repeat comes back with the issuer's id.
                                  if (!session_->sent_by_us(datagram)) on_collision(p, arrival_s);
                                }});
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
  poll_socket();
  if (source_) source_(now_s_, *this);
  retry_waiting_collisions();  // after this tick's Entity States: an entity may have appeared
  remotes_.mirror(now_s_);
}

void NetBridge::poll_socket() {
  const double from = polled_s_;
  polled_s_ = now_s_;
  // Paced, the bridge clock is the steady clock the transport dates arrivals on: a datagram's
  // time is its arrival, clamped to this poll's interval (one that came before the previous poll
  // and was left waiting by a capped poll is dated at that poll). Unpaced: the tick's start.
  const bool by_arrival = opt_.paced && !source_;
  session_->poll_datagrams([&](std::span<const std::uint8_t> d, double arrival_s) {
    receive(d, by_arrival ? std::clamp(arrival_s, std::min(from, now_s_), now_s_) : now_s_);
  });
}

// ---------------------------------------------------------------- decide ----

bool NetBridge::decides(const collision::Contact& c) {
  // A rejoined entity's episode going on (remote_entities.hpp): nobody's new collision.
  if (!c.b_fixed && remotes_.resumed_contact(c.a, c.b, now_s_)) return false;
  return ownership_.decides(sim_.world(), remotes_, c);
}

// ---------------------------------------------------------------- send ------

void NetBridge::after_tick(const TickReport& r) {
  now_s_ = clock_s();
  if (catching_up_) {  // the past: our fires are held, remote entities absent; objects noted
    publish_fixed(r);
    publish_detonations(r);  // only rounds a restart put back: kept for the join
    return;
  }
  publish_fires(r);
  publish_vehicles();  // Entity States first: a Collision PDU's outcome reads the issuer's appearance
  publish_collisions(r);
  publish_detonations(r);
  publish_fixed(r);
}

}  // namespace npsnet::node
