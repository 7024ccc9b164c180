// counters.cpp — totals and the printable summary.
#include "net/counters.hpp"

#include <numeric>

namespace net {

std::string pdu_type_name(std::uint8_t t) {
  switch (static_cast<PduType>(t)) {
    case PduType::EntityState: return "entity_state";
    case PduType::Fire: return "fire";
    case PduType::Detonation: return "detonation";
    case PduType::Collision: return "collision";
    case PduType::EntityStateUpdate: return "entity_state_update";
    case PduType::RemoveEntity: return "remove_entity";
    case PduType::StartResume: return "start_resume";
    case PduType::StopFreeze: return "stop_freeze";
    case PduType::Acknowledge: return "acknowledge";
  }
  return "type_" + std::to_string(t);
}

std::uint64_t Counters::decoded_total() const noexcept {
  return std::accumulate(decoded.begin(), decoded.end(), std::uint64_t{0});
}
std::uint64_t Counters::rejected_total() const noexcept {
  return std::accumulate(rejected.begin(), rejected.end(), std::uint64_t{0});
}
std::uint64_t Counters::sent_total() const noexcept {
  return std::accumulate(sent.begin(), sent.end(), std::uint64_t{0});
}

namespace {
// " name=count" appended (appends, not " " + name: GCC 12 warns on "literal" + std::string).
void tally(std::string& s, std::string_view name, std::uint64_t count) {
  s.append(" ").append(name).append("=").append(std::to_string(count));
}
}  // namespace

std::string Counters::summary() const {
  std::string s = "datagrams " + std::to_string(datagrams_received) + " pdus " +
                  std::to_string(pdus_seen) + " | decoded";
  for (std::size_t t = 0; t < decoded.size(); ++t)
    if (decoded[t]) tally(s, pdu_type_name(static_cast<std::uint8_t>(t)), decoded[t]);
  s += " | skipped unknown_type=" + std::to_string(skipped_unknown_type) +
       " version=" + std::to_string(skipped_version) + " | rejected";
  bool any = false;
  for (std::size_t e = 1; e < rejected.size(); ++e)
    if (rejected[e]) {
      tally(s, to_string(static_cast<DecodeError>(e)), rejected[e]);
      any = true;
    }
  if (!any) s += " none";
  s += " | ignored own_echo=" + std::to_string(own_echo_ignored) +
       (own_id_clash ? " own_id_clash=" + std::to_string(own_id_clash) : std::string()) + " other_exercise=" + std::to_string(other_exercise_ignored) + " | sent";
  any = false;
  for (std::size_t t = 0; t < sent.size(); ++t)
    if (sent[t]) {
      tally(s, pdu_type_name(static_cast<std::uint8_t>(t)), sent[t]);
      any = true;
    }
  if (!any) s += " none";
  s += " datagrams=" + std::to_string(datagrams_sent) + " failures=" + std::to_string(send_failures);
  if (aoi_joins || aoi_join_failures)
    s += " | aoi groups=" + std::to_string(aoi_groups_held) + " joins=" + std::to_string(aoi_joins) +
         " leaves=" + std::to_string(aoi_leaves) + " join_failures=" + std::to_string(aoi_join_failures);
  if (dropped_by_kernel || polls_capped)
    s += " | overload dropped=" + std::to_string(dropped_by_kernel) + " capped_polls=" + std::to_string(polls_capped);
  return s;
}

}  // namespace net
