// Our fires and detonations on the network (net_bridge.hpp): a Fire PDU per local fire, a
// Detonation PDU per local detonation (the fire's event id), each Detonation repeated every
// heartbeat and adopted ones re-sent (repeat_ledger.hpp). The receive side: warfare_receive.cpp.
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

}  // namespace npsnet::node
