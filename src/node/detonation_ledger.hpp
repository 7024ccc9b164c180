// Detonations that heal (issue 11): a Detonation is sent once, and a lost datagram would lose its
// crater and its damage for good. The repair, within the DIS rules (ARCHITECTURE.md "Network"):
// a Detonation PDU is only ever sent again unchanged (same firing entity, event id, location), so
// every receiver can tell a repeat from a new round, whoever sends it.
//  * Sent: the firing node keeps each Detonation it sent and sends it again every heartbeat
//    (Annex C: 5 s), so a node that lost it, or joined later, gets it within one heartbeat.
//  * Received: a Detonation is applied once. Its key is the firing entity, the event id and the
//    location to the centimetre (a node restarted with the same site and application numbers its
//    events from 1 again; a new event elsewhere is a new detonation). Repeats, network duplicates
//    included, are counted and ignored. At most kMaxSeen keys (the oldest forgotten; counted).
//  * Adoption (a firing node killed before its repeat reached everyone): a receiver keeps each
//    Detonation it applied whose firing entity is a scenario vehicle of another NPSNET node
//    (`adoptable`: such nodes repeat; rounds of other simulators are never re-sent), and notes
//    when it last heard it (the original or any repeat). A kept Detonation nobody has repeated
//    for (2 + rank) heartbeats is adopted: this node sends it every heartbeat from then on, as the
//    firing node did. rank = how many live nodes (an Entity State heard within the DIS timeout)
//    other than the firing one have a lower (site, application) than ours. So while the firing
//    node lives (it repeats each heartbeat) nobody adopts; once it is silent (killed, or
//    restarted: a new process holds none of its old rounds) the lowest live node that holds the
//    round adopts it 2 heartbeats after it was last heard, the next one a heartbeat later only if
//    it still hears nobody, and so on: exactly one adopter repeats it each heartbeat. An adopter
//    that hears the round from someone else (the firing node back, or another adopter after a
//    partition) stops and watches again. Receivers apply a round once whoever repeats it, so two
//    adopters at once cost datagrams, never a second crater.
// Not thread-safe: the net bridge's thread only. No allocation per call once full.
#pragma once
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <unordered_map>
#include <vector>

#include "net/pdu.hpp"

namespace npsnet::node {

class DetonationLedger {
 public:
  static constexpr std::size_t kMaxKept = 4096;
  static constexpr std::size_t kMaxSeen = 65536;
  static constexpr std::size_t kMaxPeers = 1024;

  // Our own (site, application): ranks are counted against it.
  void set_identity(std::uint16_t site, std::uint16_t application) { site_ = site, app_ = application; }
  // A node (site, application) was heard (one of its Entity States) at now_s.
  void heard(std::uint16_t site, std::uint16_t application, double now_s);

  // A Detonation we sent to `group` (0 = the exercise's destination) at bridge time now_s.
  void sent(const net::DetonationPdu& p, std::uint32_t group, double now_s);
  // A Detonation received at now_s (not our own datagram's echo). True the first time (apply
  // it); false for a repeat. `adoptable`: keep it for adoption (see above), to be repeated to
  // `group`.
  bool received(const net::DetonationPdu& p, double now_s, bool adoptable, std::uint32_t group);
  // Sends (resend(pdu, group)) each kept Detonation that is due: our own and adopted ones a
  // heartbeat after their last sending, the others when adopted. live_s: the DIS timeout (s).
  void resend_due(double now_s, double heartbeat_s, double live_s,
                  const std::function<void(const net::DetonationPdu&, std::uint32_t)>& resend);
  // Live nodes other than `firer`'s (site, application) with a lower (site, application) than ours.
  int rank(const net::EntityId& firer, double now_s, double live_s) const;

  std::uint64_t repeats_sent() const { return repeats_sent_; }
  std::uint64_t repeats_ignored() const { return repeats_ignored_; }
  std::uint64_t dropped_kept() const { return dropped_kept_; }
  std::uint64_t adoptions() const { return adoptions_; }
  std::uint64_t adopted_sent() const { return adopted_sent_; }
  std::size_t kept() const { return kept_.size(); }

 private:
  enum class Role : std::uint8_t { Own, Held, Adopted };
  struct Kept {
    net::DetonationPdu pdu;
    std::uint32_t group;
    double last_s;  // last sent by us or heard from anyone
    std::uint64_t key;
    Role role;
  };
  struct Peer {
    std::uint32_t id;  // site << 16 | application
    double last_s;
  };
  void remember(std::uint64_t key);  // into seen_order_ (the oldest key forgotten past kMaxSeen)
  void keep(const net::DetonationPdu& p, std::uint32_t group, double now_s, std::uint64_t key, Role role);

  std::uint16_t site_ = 0, app_ = 0;
  std::vector<Kept> kept_;
  std::size_t oldest_ = 0;  // ring position once kept_ is full
  std::unordered_map<std::uint64_t, std::int32_t> seen_;  // key -> index in kept_, or -1
  std::deque<std::uint64_t> seen_order_;
  std::vector<Peer> peers_;
  std::uint64_t repeats_sent_ = 0, repeats_ignored_ = 0, dropped_kept_ = 0, adoptions_ = 0, adopted_sent_ = 0;
};

}  // namespace npsnet::node
