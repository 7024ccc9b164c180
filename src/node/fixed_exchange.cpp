// Changed fixed objects across nodes (net_bridge.hpp "Fixed objects"): published as cultural-feature
// Entity States with their heartbeat, moved forward from the network (states only go forward),
// and republished by every node that knows them, so they reach a late joiner.
#include <cstdio>

#include "node/dis_mapping.hpp"
#include "node/net_bridge.hpp"
#include "node/pdu_build.hpp"

namespace npsnet::node {

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

}  // namespace npsnet::node
