// The bridge's simulation management (IEEE 1278.1-2012 5.6.5): Stop/Freeze, Start/Resume and
// Remove Entity addressed to this application (site, application) or to all (0xFFFF), each
// answered with an Acknowledge carrying its request id. Contract in net_bridge.hpp.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "node/dis_mapping.hpp"
#include "node/net_bridge.hpp"
#include "node/pdu_build.hpp"

namespace npsnet::node {

namespace {
constexpr std::uint16_t kAckRemove = 2, kAckStartResume = 3, kAckStopFreeze = 4;
constexpr std::uint16_t kAbleToComply = 1, kUnableToComply = 2;
constexpr std::uint8_t kFrozenRunClock = 1, kFrozenTransmit = 2, kFrozenProcess = 4;
double unix_now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}
// A real-world clock time in UNIX seconds; zero = now.
double unix_of(const net::ClockTime& c, double now) {
  if (c.hour == 0 && c.time_past_hour == 0) return now;
  return c.hour * 3600.0 + net::decode_timestamp(c.time_past_hour).seconds_past_hour;
}
// A simulation clock time in seconds of the exercise; -1 for zero (keep the scenario time).
double sim_seconds(const net::ClockTime& c) {
  if (c.hour == 0 && c.time_past_hour == 0) return -1;
  return std::max(0.0, c.hour * 3600.0 + net::decode_timestamp(c.time_past_hour).seconds_past_hour);
}
}  // namespace

bool NetBridge::addressed_to_us(const net::EntityId& r) const {
  return (r.site == opt_.site || r.site == net::kAllSites) &&
         (ownership_.own_application(r.application) || r.application == net::kAllApplications);
}

void NetBridge::acknowledge(const net::EntityId& to, std::uint16_t flag, std::uint16_t response, std::uint32_t request) {
  net::AcknowledgePdu a;
  a.originating_id = {static_cast<std::uint16_t>(opt_.site), static_cast<std::uint16_t>(opt_.app), 0};
  a.receiving_id = to;
  a.acknowledge_flag = flag;
  a.response_flag = response;
  a.request_id = request;
  a.header.timestamp = net::relative_timestamp(sim_.world().t);
  session_->send(a);
}

void NetBridge::on_stop_freeze(const net::StopFreezePdu& p) {
  if (!addressed_to_us(p.receiving_id)) return;
  const double now = unix_now();
  freeze_at_ = std::max(now, unix_of(p.real_world_time, now));
  resume_at_ = -1;
  frozen_behavior_ = p.frozen_behavior;
  auto ev = event("stop_freeze");
  ev["from"] = id_text(p.originating_id);
  ev["request_id"] = p.request_id;
  ev["reason"] = p.reason;
  ev["frozen_behavior"] = p.frozen_behavior;
  ev["in_s"] = std::round((freeze_at_ - now) * 1000) / 1000;
  log_.write(ev);
  acknowledge(p.originating_id, kAckStopFreeze, kAbleToComply, p.request_id);
}

void NetBridge::on_start_resume(const net::StartResumePdu& p) {
  if (!addressed_to_us(p.receiving_id)) return;
  const double now = unix_now();
  resume_at_ = std::max(now, unix_of(p.real_world_time, now));
  resume_sim_t_ = sim_seconds(p.simulation_time);
  if (freeze_at_ >= 0 && !frozen_) freeze_at_ = -1;  // a pending freeze is called off
  auto ev = event("start_resume");
  ev["from"] = id_text(p.originating_id);
  ev["request_id"] = p.request_id;
  ev["in_s"] = std::round((resume_at_ - now) * 1000) / 1000;
  if (resume_sim_t_ >= 0) ev["simulation_time_s"] = std::round(resume_sim_t_ * 1000) / 1000;
  log_.write(ev);
  acknowledge(p.originating_id, kAckStartResume, kAbleToComply, p.request_id);
}

void NetBridge::on_remove_entity(const net::RemoveEntityPdu& p) {
  const net::EntityId r = p.receiving_id;
  if (!addressed_to_us(r)) return;
  int removed = 0;
  for (size_t i = 0; i < own_.size(); ++i) {
    const int e = own_[i];
    const net::EntityId id = own_id(e);  // addressed: its application (or all) and number (or all)
    if (removed_[i] || !(r.application == net::kAllApplications || r.application == id.application) ||
        !(r.entity == net::kAllEntities || r.entity == id.entity))
      continue;
    removed_[i] = 1;
    ++removed;
    world::EntityChange ch;  // out of our world at this tick's apply
    ch.entity = e;
    ch.deactivate = true;
    ch.set_vel = true;
    ch.cruise_mps = 0;
    inject_.clear();
    inject_.entities.push_back(ch);
    sim_.inject(inject_);
    inject_.clear();
    send_deactivation(e);
    auto ev = event("entity_removed");
    ev["id"] = sim_.world().ents.id[e];
    ev["entity"] = id_text(own_id(e));
    ev["by"] = id_text(p.originating_id);
    ev["request_id"] = p.request_id;
    log_.write(ev);
  }
  acknowledge(p.originating_id, kAckRemove, removed ? kAbleToComply : kUnableToComply, p.request_id);
}

bool NetBridge::frozen() {
  const double now = unix_now();
  if (freeze_at_ >= 0 && now >= freeze_at_) {
    freeze_at_ = -1;
    frozen_ = true;
    frozen_hb_s_ = -1e9;
    frozen_since_ = now, frozen_t_ = sim_.world().t;
    log_.write(event("frozen"));
  }
  if (resume_at_ >= 0 && now >= resume_at_) {
    resume_at_ = -1;
    if (resume_sim_t_ >= 0) sim_.set_time(resume_sim_t_);
    else if (frozen_ && (frozen_behavior_ & kFrozenRunClock)) sim_.set_time(frozen_t_ + (now - frozen_since_));
    resume_sim_t_ = -1;
    if (frozen_) log_.write(event("resumed"));
    frozen_ = false;
  }
  return frozen_;
}

void NetBridge::idle() {
  now_s_ = clock_s();
  check_signal();
  poll_socket();
  if (frozen_behavior_ & kFrozenProcess) remotes_.mirror(now_s_, /*poses=*/false);
  if ((frozen_behavior_ & kFrozenTransmit) && now_s_ - frozen_hb_s_ >= remotes_.thresholds().heartbeat_s) {
    frozen_hb_s_ = now_s_;  // heartbeats: standing still, the Frozen Status bit set
    const auto& w = sim_.world();
    for (size_t i = 0; i < own_.size(); ++i) {
      if (removed_[i]) continue;
      const int e = own_[i];
      net::KinematicState s = entity_truth(w, e);
      s.velocity.setZero();
      fill_entity_state(w, e, own_id(e), s, net::DrAlgorithm::Static,
                        damage_appearance(w.kinds[w.ents.kind[e]], w.ents.state[e]) | net::kAppearanceFrozen,
                        static_cast<std::uint8_t>(opt_.exercise), w.t, es_);
      session_->send_to(group_at(w.ents.pos[e]), es_);
    }
  }
  log_.flush();
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

}  // namespace npsnet::node
