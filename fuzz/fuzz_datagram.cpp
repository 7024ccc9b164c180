// Fuzz target (a): one UDP datagram through the node's receive path as far as it stands apart
// from a socket: DatagramParser (the session's filter: exercise 1, our own site:app 1:1 ignored)
// -> RemoteEntityTable (join, update, deactivate, dead reckoning, smoothing, timeout) -> the
// entity_joined / entity_timeout / fire / detonation / collision events as the bridge names
// them (ids, markings) -> EventLog (JSON Lines, to /dev/null). Each input starts from an empty
// table, so a finding replays alone.
#include <cmath>
#include <string>

#include "fuzz_support.hpp"
#include "net/net.hpp"
#include "node/event_log.hpp"

namespace {

std::string id_text(const net::EntityId& id) {
  return std::to_string(id.site) + ":" + std::to_string(id.application) + ":" + std::to_string(id.entity);
}

nlohmann::json event(const char* type, double t) { return {{"event", type}, {"t", t}}; }

void finite_or_null(nlohmann::json& ev, const char* key, double x, double y, double z) {
  if (std::isfinite(x) && std::isfinite(y) && std::isfinite(z)) ev[key] = {x, y, z};
  else ev[key] = nullptr;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using npsnet::node::EventLog;
  static EventLog log("/dev/null");
  static net::DatagramParser parser(net::ReceiveFilter{true, 1, true, 1, 1});
  static net::Counters counters;
  net::RemoteEntityTable table;
  const double now = 100.0;
  parser.parse(std::span<const std::uint8_t>(data, size), counters,
               net::Overloaded{
                   [&](const net::EntityStatePdu& p) {
                     if (table.apply(p, now) != net::RemoteEntityTable::ApplyResult::Joined) return;
                     auto ev = event("entity_joined", now);
                     ev["entity"] = id_text(p.entity_id);
                     ev["marking"] = net::marking_text(p.marking);
                     log.write(ev);
                   },
                   [&](const net::EntityStateUpdatePdu& p) { table.apply(p, now); },
                   [&](const net::FirePdu& p) {
                     auto ev = event("fire", now);
                     ev["shooter"] = id_text(p.firing_entity_id);
                     ev["round"] = id_text(p.munition_id);
                     log.write(ev);
                   },
                   [&](const net::DetonationPdu& p) {
                     auto ev = event("detonation", now);
                     finite_or_null(ev, "point", p.location.x, p.location.y, p.location.z);
                     ev["result"] = p.detonation_result;
                     log.write(ev);
                   },
                   [&](const net::CollisionPdu& p) {
                     auto ev = event("collision", now);
                     ev["a"] = id_text(p.issuing_entity_id);
                     ev["b"] = id_text(p.colliding_entity_id);
                     log.write(ev);
                   }});
  // Poses shown over the next seconds (blend, then dead reckoning), then the timeout.
  for (double dt : {0.05, 0.5, 3.0}) {
    for (std::size_t i = 0; i < table.size(); ++i) {
      const net::Pose p = table.displayed_pose(i, now + dt);
      const net::Pose q = table.dead_reckoned_pose(i, now + dt);
      (void)p, (void)q;
    }
  }
  table.expire(now + 60, [&](const net::RemoteEntity& r) {
    auto ev = event("entity_timeout", now + 60);
    ev["entity"] = id_text(r.id);
    ev["marking"] = net::marking_text(r.marking);
    log.write(ev);
  });
  log.flush();
  return 0;
}
