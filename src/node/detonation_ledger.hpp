// Detonations that heal (issue 11): a Detonation is sent once, and a lost datagram would lose its
// crater and its damage for good. The repair, within the DIS rules (ARCHITECTURE.md "Network"):
//  * Sent: the firing node keeps each Detonation it sent and sends it again, unchanged (same
//    event id), every heartbeat (Annex C: 5 s), so a node that lost it, or joined later, gets it
//    within one heartbeat. At most kMaxKept are kept (the oldest then stop being repeated; counted).
//  * Received: a Detonation is applied once. Its key is the firing entity, the event id and the
//    location to the centimetre (a node restarted with the same site and application numbers its
//    events from 1 again; a new event elsewhere is a new detonation). Repeats, network duplicates
//    included, are counted and ignored. At most kMaxSeen keys (the oldest forgotten; counted).
// Not thread-safe: the net bridge's thread only. No allocation per call once full.
#pragma once
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <unordered_set>
#include <vector>

#include "net/pdu.hpp"

namespace npsnet::node {

class DetonationLedger {
 public:
  static constexpr std::size_t kMaxKept = 4096;
  static constexpr std::size_t kMaxSeen = 65536;

  // A Detonation we sent to `group` (0 = the exercise's destination) at bridge time now_s.
  void sent(const net::DetonationPdu& p, std::uint32_t group, double now_s);
  // Calls resend(pdu, group) for each kept Detonation last sent heartbeat_s or more ago.
  void resend_due(double now_s, double heartbeat_s,
                  const std::function<void(const net::DetonationPdu&, std::uint32_t)>& resend);
  // True the first time this detonation is seen (apply it); false for a repeat.
  bool first_time(const net::DetonationPdu& p);

  std::uint64_t repeats_sent() const { return repeats_sent_; }
  std::uint64_t repeats_ignored() const { return repeats_ignored_; }
  std::uint64_t dropped_kept() const { return dropped_kept_; }
  std::size_t kept() const { return kept_.size(); }

 private:
  struct Kept {
    net::DetonationPdu pdu;
    std::uint32_t group;
    double last_s;
  };
  std::vector<Kept> kept_;
  std::size_t oldest_ = 0;  // ring position once kept_ is full
  std::unordered_set<std::uint64_t> seen_;
  std::deque<std::uint64_t> seen_order_;
  std::uint64_t repeats_sent_ = 0, repeats_ignored_ = 0, dropped_kept_ = 0;
};

}  // namespace npsnet::node
