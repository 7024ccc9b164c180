// net/session.hpp — what a node holds: one UDP transport, our identity (exercise, site,
// application), a datagram parser that filters other exercises and our own echo, and counters.
// Contract:
//  * Session(config) throws std::runtime_error with an actionable message (see transport.hpp).
//  * send(pdu) encodes into the session's own buffer (no allocation), writes our exercise id
//    into the header, sends one datagram, and counts it in counters().sent[type] (or
//    send_failures). The caller sets ids, timestamp and the rest of the header.
//  * send(builder) sends a datagram packed with DatagramBuilder (counted as one datagram; the
//    caller's exercise id is used as given).
//  * send_to(group, pdu) / send_to(group, builder): the same, to an area-of-interest group
//    (IPv4 host order) instead of the configured destination.
//  * join_group / leave_group: the transport's join/leave, counted in counters().aoi_*.
//  * poll(visitor) drains every waiting datagram without blocking and hands each accepted PDU to
//    the visitor (see datagram.hpp for the visitor rules); returns the number of PDUs handed.
//  * poll_datagrams(f) drains the waiting datagrams as raw bytes, f(std::span<const uint8_t>),
//    or f(bytes, arrival_s) with each one's arrival time (steady clock, s; transport.hpp);
//    parse(datagram, visitor) walks one datagram (from the socket, a recording or a test) through
//    the session's filter and counters exactly as poll does.
//  * Our own (site, application) in a received datagram: our echo when the datagram is one of
//    the last 1024 we sent (same bytes), else another simulator using our identity
//    (Counters::own_id_clash); both are ignored (but for a Detonation or Collision that is not
//    our echo: an adopter repeating our earlier process's PDU, delivered; datagram.hpp).
//  * SessionConfig::offline: no socket at all (a node fed from a recording): send() encodes and
//    counts as usual, and the datagram goes nowhere (or to the offline sink, when one is set:
//    tests wire nodes of one process together with it); poll() finds nothing; transport() must
//    not be called.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>

#include "net/codec.hpp"
#include "net/counters.hpp"
#include "net/datagram.hpp"
#include "net/transport.hpp"

namespace net {

struct SessionConfig {
  TransportConfig transport;
  std::uint8_t exercise_id = 1;
  std::uint16_t site = 1;
  std::uint16_t application = 1;
  bool ignore_own_echo = true;   // drop PDUs from our (site, application)
  bool filter_exercise = true;   // drop PDUs of other exercises
  bool offline = false;          // no socket: sends are counted and dropped (replay of a recording)
  // Protocol version written into every PDU sent alone (6 or 7: the same layouts for our types;
  // both are received). A DatagramBuilder's PDUs keep the version their headers hold.
  std::uint8_t protocol_version = kProtocolVersion7;
};

class Session {
 public:
  explicit Session(const SessionConfig& config);

  template <class Pdu>
  bool send(const Pdu& pdu) noexcept {
    return send_to(kDestination, pdu);
  }
  bool send(const DatagramBuilder& datagram) noexcept { return send_to(kDestination, datagram); }

  // group 0 (kDestination) = the configured destination.
  template <class Pdu>
  bool send_to(std::uint32_t group, const Pdu& pdu) noexcept {
    auto r = encode(pdu, std::span<std::uint8_t>(buffer_));
    if (!r) {
      ++counters_.send_failures;
      return false;
    }
    buffer_[0] = config_.protocol_version;
    buffer_[1] = config_.exercise_id;
    return send_raw(group, std::span<const std::uint8_t>(buffer_.data(), r.value()),
                    static_cast<std::uint8_t>(buffer_[2]));
  }
  bool send_to(std::uint32_t group, const DatagramBuilder& datagram) noexcept;

  bool join_group(std::uint32_t group) noexcept;
  bool leave_group(std::uint32_t group) noexcept;
  static constexpr std::uint32_t kDestination = 0;

  template <class Visitor>
  std::size_t poll(Visitor&& visitor) {
    std::size_t delivered = 0;
    if (!transport_) return 0;
    transport_->poll([&](std::span<const std::uint8_t> d) { delivered += parse(d, visitor); });
    note_overload();
    return delivered;
  }
  template <class F>
  std::size_t poll_datagrams(F&& on_datagram) {
    if (!transport_) return 0;
    const std::size_t n = transport_->poll(on_datagram);
    note_overload();
    return n;
  }
  template <class Visitor>
  std::size_t parse(std::span<const std::uint8_t> datagram, Visitor&& visitor) {
    parser_.set_echo(sent_recently(datagram));
    return parser_.parse(datagram, counters_, visitor);
  }

  // Whether `datagram` is one of the last datagrams we sent (same bytes): our own echo.
  bool sent_by_us(std::span<const std::uint8_t> datagram) const noexcept { return sent_recently(datagram); }
  // An entity id of ours: (site, application, entity).
  EntityId entity_id(std::uint16_t entity) const noexcept {
    return {config_.site, config_.application, entity};
  }
  // Our entities numbered under n applications (ReceiveFilter::application_blocks): PDUs of
  // every one of them are ours (echo or clash).
  void set_application_blocks(std::uint16_t n) noexcept {
    ReceiveFilter f = parser_.filter();
    f.application_blocks = n;
    parser_.set_filter(f);
  }
  const SessionConfig& config() const noexcept { return config_; }
  const Counters& counters() const noexcept { return counters_; }
  Counters& counters() noexcept { return counters_; }
  UdpTransport& transport() noexcept { return *transport_; }
  bool offline() const noexcept { return !transport_; }
  // Offline only: every datagram sent is handed to `sink` (group, bytes) instead of nowhere.
  using OfflineSink = std::function<void(std::uint32_t group, std::span<const std::uint8_t> bytes)>;
  void set_offline_sink(OfflineSink sink) { sink_ = std::move(sink); }

 private:
  bool send_raw(std::uint32_t group, std::span<const std::uint8_t> bytes, std::uint8_t pdu_type) noexcept;
  bool transmit(std::uint32_t group, std::span<const std::uint8_t> bytes) noexcept {
    remember_sent(bytes);
    if (!transport_) {  // offline: counted, sent nowhere (or to the test's sink)
      if (sink_) sink_(group, bytes);
      return true;
    }
    return group == kDestination ? transport_->send(bytes) : transport_->send_to(group, bytes);
  }
  // Our echo vs a clash: hashes of the last kSentMemory datagrams we sent (FNV-1a, 64 bits).
  void remember_sent(std::span<const std::uint8_t> bytes) noexcept;
  bool sent_recently(std::span<const std::uint8_t> bytes) const noexcept;
  static constexpr std::size_t kSentMemory = 1024;  // > a tick's sends (128 capped + fires)
  std::array<std::uint64_t, kSentMemory> sent_hash_{};
  std::size_t sent_next_ = 0;

  void note_overload() noexcept {  // the transport's flood counters into counters()
    counters_.dropped_by_kernel = transport_->dropped_by_kernel();
    counters_.polls_capped = transport_->polls_capped();
  }

  SessionConfig config_;
  std::optional<UdpTransport> transport_;  // empty when offline
  OfflineSink sink_;                        // offline: where sent datagrams go (tests)
  DatagramParser parser_;
  Counters counters_;
  std::array<std::uint8_t, kMaxPduSize> buffer_{};
};

}  // namespace net
