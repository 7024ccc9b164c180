// PDUs sent once that heal (issue 11): a Detonation or a Collision PDU is sent once, and a lost
// datagram would lose its crater, its damage or its collision outcome for good. The repair,
// within the DIS rules (ARCHITECTURE.md "Network"): such a PDU is only ever sent again unchanged
// (same originating entity, event id, place), so every receiver can tell a repeat from a new
// event, whoever sends it. One ledger per PDU type (RepeatLedger<net::DetonationPdu>,
// RepeatLedger<net::CollisionPdu>); the originator is the firing entity of a Detonation and the
// issuing entity of a Collision.
//  * Sent: the originating node keeps each such PDU it sent and sends it again every heartbeat
//    (Annex C: 5 s), so a node that lost it, or joined later, gets it within one heartbeat.
//    The first kQuickRepeats repeats go kQuickGapS apart (at most a heartbeat), as a first Entity
//    State's do (vehicle_publish.cpp): a lost datagram heals in half a second, and a node killed
//    a second after its round fell has sent it three times, not once (nobody holds a PDU that
//    was lost on every link, so nobody could adopt it).
//  * Received: a PDU is applied once. Its key is the originating entity, the event id and the
//    place to the centimetre (a Detonation's location; a Collision's colliding entity and
//    location in the issuer's coordinates): a node restarted with the same site and application
//    numbers its events from 1 again, and a new event elsewhere is a new one. Repeats, network
//    duplicates included, are counted and ignored. At most kMaxSeen keys (the oldest forgotten;
//    counted).
//  * Adoption (an originating node killed before its repeat reached everyone): a receiver keeps
//    each PDU it applied whose originator is a scenario vehicle of another NPSNET node
//    (`adoptable`: such nodes repeat; PDUs of other simulators are never re-sent), and notes
//    when it last heard it (the original or any repeat). A kept PDU nobody has repeated for
//    (2 + rank) heartbeats is adopted: this node sends it every heartbeat from then on, as the
//    originating node did. rank = how many live nodes (an Entity State heard within the DIS
//    timeout) other than the originating one have a lower (site, application) than ours. So while
//    the originating node lives (it repeats each heartbeat) nobody adopts; once it is silent
//    (killed, or restarted: a new process holds none of its old PDUs) the lowest live node that
//    holds the PDU adopts it 2 heartbeats after it was last heard, the next one a heartbeat later
//    only if it still hears nobody, and so on: exactly one adopter repeats it each heartbeat. An
//    adopter that hears the PDU from someone else (the originator back, or another adopter after
//    a partition) stops and watches again. Receivers apply a PDU once whoever repeats it, so two
//    adopters at once cost datagrams, never a second crater or collision.
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

// The key of a PDU (see above) and its originating entity; defined for the two PDU types.
std::uint64_t repeat_key(const net::DetonationPdu& p);
std::uint64_t repeat_key(const net::CollisionPdu& p);
inline const net::EntityId& originator(const net::DetonationPdu& p) { return p.firing_entity_id; }
inline const net::EntityId& originator(const net::CollisionPdu& p) { return p.issuing_entity_id; }

template <class Pdu>
class RepeatLedger {
 public:
  static constexpr std::size_t kMaxKept = 4096;
  static constexpr std::size_t kMaxSeen = 65536;
  static constexpr std::size_t kMaxPeers = 1024;
  static constexpr int kQuickRepeats = 2;
  static constexpr double kQuickGapS = 0.5;

  // Our own (site, application): ranks are counted against it.
  void set_identity(std::uint16_t site, std::uint16_t application) { site_ = site, app_ = application; }
  // A node (site, application) was heard (one of its Entity States) at now_s.
  void heard(std::uint16_t site, std::uint16_t application, double now_s);

  // A PDU we sent to `group` (0 = the exercise's destination) at bridge time now_s.
  void sent(const Pdu& p, std::uint32_t group, double now_s);
  // A PDU received at now_s (not our own datagram's echo). True the first time (apply it);
  // false for a repeat. `adoptable`: keep it for adoption (see above), to be repeated to `group`.
  bool received(const Pdu& p, double now_s, bool adoptable, std::uint32_t group);
  // Sends (resend(pdu, group)) each kept PDU that is due: our own and adopted ones a heartbeat
  // after their last sending, the others when adopted. live_s: the DIS timeout (s).
  void resend_due(double now_s, double heartbeat_s, double live_s,
                  const std::function<void(const Pdu&, std::uint32_t)>& resend);
  // Live nodes other than `origin`'s (site, application) with a lower (site, application) than ours.
  int rank(const net::EntityId& origin, double now_s, double live_s) const;

  std::uint64_t repeats_sent() const { return repeats_sent_; }
  std::uint64_t repeats_ignored() const { return repeats_ignored_; }
  std::uint64_t dropped_kept() const { return dropped_kept_; }
  std::uint64_t adoptions() const { return adoptions_; }
  std::uint64_t adopted_sent() const { return adopted_sent_; }
  std::size_t kept() const { return kept_.size(); }

 private:
  enum class Role : std::uint8_t { Own, Held, Adopted };
  struct Kept {
    Pdu pdu;
    std::uint32_t group;
    double last_s;  // last sent by us or heard from anyone
    std::uint64_t key;
    Role role;
    std::uint8_t quick;  // Own: quick repeats still to send (kQuickGapS apart)
  };
  struct Peer {
    std::uint32_t id;  // site << 16 | application
    double last_s;
  };
  void remember(std::uint64_t key);  // into seen_order_ (the oldest key forgotten past kMaxSeen)
  void keep(const Pdu& p, std::uint32_t group, double now_s, std::uint64_t key, Role role);

  std::uint16_t site_ = 0, app_ = 0;
  std::vector<Kept> kept_;
  std::size_t oldest_ = 0;  // ring position once kept_ is full
  std::unordered_map<std::uint64_t, std::int32_t> seen_;  // key -> index in kept_, or -1
  std::deque<std::uint64_t> seen_order_;
  std::vector<Peer> peers_;
  std::uint64_t repeats_sent_ = 0, repeats_ignored_ = 0, dropped_kept_ = 0, adoptions_ = 0, adopted_sent_ = 0;
};

extern template class RepeatLedger<net::DetonationPdu>;
extern template class RepeatLedger<net::CollisionPdu>;
using DetonationLedger = RepeatLedger<net::DetonationPdu>;
using CollisionLedger = RepeatLedger<net::CollisionPdu>;

}  // namespace npsnet::node
