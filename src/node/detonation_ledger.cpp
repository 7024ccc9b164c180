#include "node/detonation_ledger.hpp"

#include <cmath>

namespace npsnet::node {
namespace {

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {  // FNV-1a over 64-bit words
  return (h ^ v) * 0x100000001b3ULL;
}

std::uint64_t key_of(const net::DetonationPdu& p) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  h = mix(h, (std::uint64_t(p.firing_entity_id.site) << 32) | (std::uint64_t(p.firing_entity_id.application) << 16) |
                 p.firing_entity_id.entity);
  h = mix(h, (std::uint64_t(p.event_id.site) << 32) | (std::uint64_t(p.event_id.application) << 16) |
                 p.event_id.event_number);
  for (const double c : {p.location.x, p.location.y, p.location.z})
    h = mix(h, std::isfinite(c) ? static_cast<std::uint64_t>(std::llround(c * 100.0)) : 0);
  return h;
}

}  // namespace

void DetonationLedger::sent(const net::DetonationPdu& p, std::uint32_t group, double now_s) {
  if (kept_.size() < kMaxKept) {
    kept_.push_back({p, group, now_s});
    return;
  }
  kept_[oldest_] = {p, group, now_s};  // the oldest stops being repeated
  oldest_ = (oldest_ + 1) % kMaxKept;
  ++dropped_kept_;
}

void DetonationLedger::resend_due(double now_s, double heartbeat_s,
                                  const std::function<void(const net::DetonationPdu&, std::uint32_t)>& resend) {
  for (auto& k : kept_)
    if (now_s - k.last_s >= heartbeat_s) {
      k.last_s = now_s;
      resend(k.pdu, k.group);
      ++repeats_sent_;
    }
}

bool DetonationLedger::first_time(const net::DetonationPdu& p) {
  const std::uint64_t k = key_of(p);
  if (!seen_.insert(k).second) {
    ++repeats_ignored_;
    return false;
  }
  seen_order_.push_back(k);
  if (seen_order_.size() > kMaxSeen) {
    seen_.erase(seen_order_.front());
    seen_order_.pop_front();
  }
  return true;
}

}  // namespace npsnet::node
