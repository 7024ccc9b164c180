// session.cpp — sending with counters; the filter set up from our identity.
#include "net/session.hpp"

namespace net {

Session::Session(const SessionConfig& config)
    : config_(config),
      transport_(config.transport),
      parser_(ReceiveFilter{config.filter_exercise, config.exercise_id, config.ignore_own_echo,
                            config.site, config.application}) {}

bool Session::send_raw(std::span<const std::uint8_t> bytes, std::uint8_t pdu_type) noexcept {
  if (!transport_.send(bytes)) {
    ++counters_.send_failures;
    return false;
  }
  ++counters_.datagrams_sent;
  ++counters_.sent[pdu_type];
  return true;
}

bool Session::send(const DatagramBuilder& datagram) noexcept {
  if (datagram.empty()) return false;
  if (!transport_.send(datagram.bytes())) {
    ++counters_.send_failures;
    return false;
  }
  ++counters_.datagrams_sent;
  // Count each PDU by walking the headers we wrote ourselves.
  auto b = datagram.bytes();
  for (std::size_t off = 0; off + kHeaderSize <= b.size();) {
    const std::size_t len = (std::size_t{b[off + 8]} << 8) | b[off + 9];
    ++counters_.sent[b[off + 2]];
    if (len < kHeaderSize) break;
    off += len;
  }
  return true;
}

}  // namespace net
