// Our fires and detonations on the network (net_bridge.hpp): a Fire PDU per local fire, a
// Detonation PDU per local detonation (the fire's event id), each Detonation repeated every
// heartbeat and adopted ones re-sent (repeat_ledger.hpp); a round a restart put back in flight
// (node/checkpoint.hpp) detonates under its old identity. The receive side: warfare_receive.cpp.
#include "node/net_bridge.hpp"
#include "node/pdu_build.hpp"

namespace npsnet::node {

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

bool NetBridge::round_identity(int m, std::uint16_t& event, net::EntityId& munition) const {
  const auto it = fire_event_.find(m);
  if (it == fire_event_.end()) return false;
  event = it->second;
  const auto adopted = round_id_.find(m);
  munition = adopted != round_id_.end() ? adopted->second : own_id(m);
  return true;
}

void NetBridge::adopt_round(int m, std::uint16_t event, const net::EntityId& munition) {
  fire_event_[m] = event;
  round_id_[m] = munition;
}

void NetBridge::publish_detonations(const TickReport& r) {
  const auto& ents = sim_.world().ents;
  for (const auto& d : r.changes.detonations) {
    const int m = d.munition;
    if (m < 0 || !ents.local[m]) continue;  // another node's round
    // A round a restart put back keeps its old identity; caught up, it waits for the join.
    const auto adopted = round_id_.find(m);
    if (catching_up_ && adopted == round_id_.end()) continue;
    const net::EntityId munition = adopted != round_id_.end() ? adopted->second : own_id(m);
    if (adopted != round_id_.end()) round_id_.erase(adopted);
    auto it = fire_event_.find(m);
    net::EventId evn{static_cast<std::uint16_t>(opt_.site), static_cast<std::uint16_t>(opt_.app), 0};
    if (it != fire_event_.end()) {
      evn.event_number = it->second;
      fire_event_.erase(it);
    } else {
      evn = next_event();
    }
    const auto pdu = detonation_pdu(sim_.world(), d, ents.owner[m] >= 0 ? own_id(ents.owner[m]) : net::EntityId{},
                                    d.target >= 0 ? net_id(d.target) : net::EntityId{}, munition, evn);
    const std::uint32_t group = group_at(d.point);
    if (catching_up_) {
      caught_up_detonations_.push_back({pdu, group});
      continue;
    }
    session_->send_to(group, pdu);
    detonations_.sent(pdu, group, now_s_);
  }
  if (catching_up_) return;
  for (const auto& c : caught_up_detonations_) {  // the first live tick: rounds put back that fell while catching up
    session_->send_to(c.group, c.pdu);
    detonations_.sent(c.pdu, c.group, now_s_);
  }
  caught_up_detonations_.clear();
  detonations_.resend_due(now_s_, remotes_.thresholds().heartbeat_s, remotes_.thresholds().timeout_s,
                          [&](const net::DetonationPdu& pdu, std::uint32_t group) { session_->send_to(group, pdu); });
}

}  // namespace npsnet::node
