// net/counters.hpp — what the receive and send paths did, for logs and tests.
// All counts are totals since construction (or reset()). A datagram's PDUs are each counted once
// in exactly one of: decoded[type], skipped_unknown_type, skipped_version, rejected[reason],
// own_echo_ignored, own_id_clash, other_exercise_ignored; a rejection that stops the walk of a datagram
// (truncated_header, length_below_header, length_exceeds_data) counts the unreadable rest as
// that one rejection.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "net/codec.hpp"

namespace net {

struct Counters {
  std::uint64_t datagrams_received = 0;
  std::uint64_t pdus_seen = 0;                   // headers walked (incl. rejected / skipped)
  std::array<std::uint64_t, 256> decoded{};      // by PDU type
  std::uint64_t skipped_unknown_type = 0;
  std::uint64_t skipped_version = 0;
  std::array<std::uint64_t, kDecodeErrorCount> rejected{};  // by DecodeError
  std::uint64_t own_echo_ignored = 0;
  // PDUs with our (site, application) in a datagram we did not send: another simulator uses
  // our identity (its PDUs are ignored like our echo, and counted here).
  std::uint64_t own_id_clash = 0;
  std::uint64_t other_exercise_ignored = 0;
  std::array<std::uint64_t, 256> sent{};         // by PDU type
  std::uint64_t datagrams_sent = 0;
  std::uint64_t send_failures = 0;
  // Area of interest (Session::join_group / leave_group): groups joined and left so far, the
  // groups held now, joins the kernel refused.
  std::uint64_t aoi_joins = 0;
  std::uint64_t aoi_leaves = 0;
  std::uint64_t aoi_groups_held = 0;
  std::uint64_t aoi_join_failures = 0;
  std::uint64_t bytes_received = 0;              // datagram payload octets
  // Overload (a flood): datagrams the kernel dropped with the receive buffer full, and polls
  // that stopped at their bound with more waiting (the rest read next tick, or dropped).
  std::uint64_t dropped_by_kernel = 0;
  std::uint64_t polls_capped = 0;

  std::uint64_t decoded_total() const noexcept;
  std::uint64_t rejected_total() const noexcept;
  std::uint64_t sent_total() const noexcept;
  std::uint64_t rejected_for(DecodeError e) const noexcept {
    return rejected[static_cast<std::size_t>(e)];
  }
  void reset() noexcept { *this = Counters{}; }

  // One line, zero entries left out, e.g.
  // "datagrams 3 pdus 5 | decoded entity_state=2 fire=1 | skipped unknown_type=1 version=0 |
  //  rejected length_exceeds_data=1 | ignored own_echo=0 other_exercise=0 | sent entity_state=4"
  // (" own_id_clash=N" after own_echo when any), followed, once a group was joined through the area of interest, by
  // " | aoi groups=12 joins=15 leaves=3 join_failures=0", and under a flood by
  // " | overload dropped=120000 capped_polls=4".
  std::string summary() const;
};

// "entity_state", "fire", "detonation", "collision", "entity_state_update" or "type_<n>".
std::string pdu_type_name(std::uint8_t pdu_type);

}  // namespace net
