// net/datagram.hpp — walking the PDUs of one UDP datagram, and packing several into one.
// Contract of DatagramParser::parse(datagram, counters, visitor):
//  * PDUs are walked in order using each header's length field. Each one is counted once in
//    `counters` (see net/counters.hpp) and, if it decodes and passes the filter, handed to the
//    visitor as `const EntityStatePdu&`, `const FirePdu&`, `const DetonationPdu&`,
//    `const CollisionPdu&`, `const EntityStateUpdatePdu&`, or a simulation management PDU
//    (`const RemoveEntityPdu&`, `StartResumePdu`, `StopFreezePdu`, `AcknowledgePdu`); overloads the visitor does not
//    accept are skipped at compile time (e.g. a lambda taking only `const FirePdu&`).
//  * Versions other than 5/6/7 and types other than those are skipped (counted) using their
//    length; inconsistent PDUs are rejected with a counted DecodeError. A length field < 12 or
//    past the end of the datagram stops the walk. Every step advances >= 12 octets, so the walk
//    ends after at most size/12 PDUs; no input can crash it or make it loop.
//  * The references passed to the visitor point into the parser's scratch structs: valid only
//    during the call. The parser allocates nothing once its scratch vectors have grown.
//  * Filter: PDUs of another exercise are ignored (counted); PDUs whose originating entity
//    (ES/ESU entity, Fire/Detonation firing entity, Collision issuing entity, simulation
//    management originating id) has our site and
//    application are our own echo and are ignored (counted); not our echo (a datagram we did not
//    send): another simulator using our identity (counted as own_id_clash, ignored), except a
//    Detonation or a Collision: another node repeating a round or a collision of ours
//    (node/repeat_ledger.hpp adoption, after our process was restarted), delivered.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#include "net/codec.hpp"
#include "net/counters.hpp"
#include "net/pdu.hpp"

namespace net {

// A node owning more entities than one application numbers (entity numbers 1-32767) numbers
// them under several applications: block k (its entities k * 32767 ... k * 32767 + 32766) under
// application + k * kApplicationStride, k < application_blocks. Receivers bind entities by
// their full id, so every block is an ordinary application to them.
inline constexpr std::uint16_t kEntitiesPerApplication = 32767, kApplicationStride = 0x1000;

struct ReceiveFilter {
  bool filter_exercise = false;  // when true, only exercise_id passes
  std::uint8_t exercise_id = 1;
  bool ignore_own = false;       // when true, PDUs from (site, application) are dropped
  std::uint16_t site = 1;
  std::uint16_t application = 1;
  std::uint16_t application_blocks = 1;  // ours: application + k * kApplicationStride, k < this
  bool own_application(std::uint16_t a) const noexcept {
    const int d = static_cast<int>(a) - static_cast<int>(application);
    return d >= 0 && d % kApplicationStride == 0 && d / kApplicationStride < application_blocks;
  }
  // Whether the datagram walked now is one we sent (our echo): its own PDUs count as
  // own_echo_ignored, else as own_id_clash (Session::parse sets it per datagram).
  bool echo = true;
};

// The entity a received PDU speaks for (the one whose site/application identify the sender).
EntityId originating_entity(const EntityStatePdu& p) noexcept;
EntityId originating_entity(const FirePdu& p) noexcept;
EntityId originating_entity(const DetonationPdu& p) noexcept;
EntityId originating_entity(const CollisionPdu& p) noexcept;
EntityId originating_entity(const EntityStateUpdatePdu& p) noexcept;
EntityId originating_entity(const RemoveEntityPdu& p) noexcept;
EntityId originating_entity(const StartResumePdu& p) noexcept;
EntityId originating_entity(const StopFreezePdu& p) noexcept;
EntityId originating_entity(const AcknowledgePdu& p) noexcept;

// Builds one visitor from several lambdas: parse(d, c, net::Overloaded{[](const FirePdu&){...},
// [](const EntityStatePdu&){...}}).
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

class DatagramParser {
 public:
  explicit DatagramParser(ReceiveFilter filter = {}) : filter_(filter) {}
  void set_filter(const ReceiveFilter& f) noexcept { filter_ = f; }
  void set_echo(bool echo) noexcept { filter_.echo = echo; }
  const ReceiveFilter& filter() const noexcept { return filter_; }

  // Returns the number of PDUs handed to the visitor.
  template <class Visitor>
  std::size_t parse(std::span<const std::uint8_t> datagram, Counters& counters, Visitor&& visitor) {
    ++counters.datagrams_received;
    counters.bytes_received += datagram.size();
    std::size_t offset = 0, delivered = 0;
    while (offset < datagram.size()) {
      const Step s = step(datagram.subspan(offset), counters);
      if (s.deliver) {
        ++delivered;
        dispatch(s.type, visitor);
      }
      if (s.advance == 0) break;
      offset += s.advance;
    }
    return delivered;
  }

 private:
  struct Step {
    std::size_t advance = 0;  // 0: stop walking
    PduType type = PduType::EntityState;
    bool deliver = false;
  };
  Step step(std::span<const std::uint8_t> rest, Counters& counters);

  template <class Visitor>
  void dispatch(PduType t, Visitor& v) {
    switch (t) {
      case PduType::EntityState: call(v, es_); break;
      case PduType::Fire: call(v, fire_); break;
      case PduType::Detonation: call(v, det_); break;
      case PduType::Collision: call(v, col_); break;
      case PduType::EntityStateUpdate: call(v, esu_); break;
      case PduType::RemoveEntity: call(v, remove_); break;
      case PduType::StartResume: call(v, start_); break;
      case PduType::StopFreeze: call(v, stop_); break;
      case PduType::Acknowledge: call(v, ack_); break;
    }
  }
  template <class Visitor, class Pdu>
  static void call(Visitor& v, const Pdu& p) {
    if constexpr (std::is_invocable_v<Visitor&, const Pdu&>) v(p);
  }

  ReceiveFilter filter_;
  EntityStatePdu es_;
  FirePdu fire_;
  DetonationPdu det_;
  CollisionPdu col_;
  EntityStateUpdatePdu esu_;
  RemoveEntityPdu remove_;
  StartResumePdu start_;
  StopFreezePdu stop_;
  AcknowledgePdu ack_;
};

// Packs encoded PDUs back to back into one datagram of at most max_size octets (default 1400,
// the Annex C smallest MTU). add() returns false and adds nothing when the PDU would not fit
// or cannot be encoded. The buffer is allocated once, at construction.
class DatagramBuilder {
 public:
  explicit DatagramBuilder(std::size_t max_size = 1400) : buf_(max_size) {}
  template <class Pdu>
  bool add(const Pdu& p) {
    auto r = encode(p, std::span<std::uint8_t>(buf_).subspan(size_));
    if (!r) return false;
    size_ += r.value();
    ++count_;
    return true;
  }
  std::span<const std::uint8_t> bytes() const noexcept { return {buf_.data(), size_}; }
  std::size_t pdu_count() const noexcept { return count_; }
  bool empty() const noexcept { return size_ == 0; }
  void clear() noexcept { size_ = 0, count_ = 0; }

 private:
  std::vector<std::uint8_t> buf_;
  std::size_t size_ = 0;
  std::size_t count_ = 0;
};

}  // namespace net
