// session.cpp — sending with counters; the filter set up from our identity.
#include "net/session.hpp"

namespace net {

Session::Session(const SessionConfig& config)
    : config_(config),
      parser_(ReceiveFilter{config.filter_exercise, config.exercise_id, config.ignore_own_echo,
                            config.site, config.application}) {
  if (!config.offline) transport_.emplace(config.transport);
}

namespace {
std::uint64_t fnv1a(std::span<const std::uint8_t> b) noexcept {
  std::uint64_t h = 1469598103934665603ull;
  for (const std::uint8_t c : b) h = (h ^ c) * 1099511628211ull;
  return h | 1;  // never 0: 0 marks an empty slot
}
}  // namespace

void Session::remember_sent(std::span<const std::uint8_t> bytes) noexcept {
  sent_hash_[sent_next_] = fnv1a(bytes);
  sent_next_ = (sent_next_ + 1) % kSentMemory;
}

bool Session::sent_recently(std::span<const std::uint8_t> bytes) const noexcept {
  const std::uint64_t h = fnv1a(bytes);
  for (const std::uint64_t s : sent_hash_)
    if (s == h) return true;
  return false;
}

bool Session::send_raw(std::uint32_t group, std::span<const std::uint8_t> bytes, std::uint8_t pdu_type) noexcept {
  if (!transmit(group, bytes)) {
    ++counters_.send_failures;
    return false;
  }
  ++counters_.datagrams_sent;
  ++counters_.sent[pdu_type];
  return true;
}

bool Session::send_to(std::uint32_t group, const DatagramBuilder& datagram) noexcept {
  if (datagram.empty()) return false;
  if (!transmit(group, datagram.bytes())) {
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

namespace net {

bool Session::join_group(std::uint32_t group) noexcept {
  if (!transport_) return false;  // offline: no groups
  if (!transport_->join(group)) {
    ++counters_.aoi_join_failures;
    return false;
  }
  ++counters_.aoi_joins;
  counters_.aoi_groups_held = transport_->groups_joined();
  return true;
}

bool Session::leave_group(std::uint32_t group) noexcept {
  if (!transport_) return false;
  const bool ok = transport_->leave(group);
  ++counters_.aoi_leaves;
  counters_.aoi_groups_held = transport_->groups_joined();
  return ok;
}

}  // namespace net
