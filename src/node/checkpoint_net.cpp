// The checkpoint's rounds and the net bridge (checkpoint.hpp): what identity a round's Fire PDU
// gave it, and giving it back to a round a restart put in flight again.
#include "node/checkpoint.hpp"

#ifdef NPSNET_HAVE_NET
#include "node/net_bridge.hpp"
#endif

namespace npsnet::node {

#ifdef NPSNET_HAVE_NET
RoundIdentity round_identities(const NetBridge* bridge) {
  if (!bridge) return {};
  return [bridge](int m, CheckpointRound& r) {
    std::uint16_t event = 0;
    net::EntityId id;
    if (!bridge->round_identity(m, event, id)) return false;
    r.event = event, r.site = id.site, r.application = id.application, r.entity = id.entity;
    return true;
  };
}

void adopt_rounds(NetBridge* bridge, const Checkpoint& c, const std::vector<int>& slots) {
  if (!bridge) return;
  for (size_t i = 0; i < slots.size() && i < c.rounds.size(); ++i) {
    const auto& r = c.rounds[i];
    bridge->adopt_round(slots[i], static_cast<std::uint16_t>(r.event),
                        net::EntityId{static_cast<std::uint16_t>(r.site), static_cast<std::uint16_t>(r.application),
                                      static_cast<std::uint16_t>(r.entity)});
  }
}
#else
RoundIdentity round_identities(const NetBridge*) { return {}; }
void adopt_rounds(NetBridge*, const Checkpoint&, const std::vector<int>&) {}
#endif

}  // namespace npsnet::node
