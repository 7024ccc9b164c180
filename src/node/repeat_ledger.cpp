#include "node/repeat_ledger.hpp"

#include <algorithm>
#include <cmath>

namespace npsnet::node {
namespace {

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {  // FNV-1a over 64-bit words
  return (h ^ v) * 0x100000001b3ULL;
}

std::uint64_t word(const net::EntityId& id) {
  return (std::uint64_t(id.site) << 32) | (std::uint64_t(id.application) << 16) | id.entity;
}
std::uint64_t word(const net::EventId& id) {
  return (std::uint64_t(id.site) << 32) | (std::uint64_t(id.application) << 16) | id.event_number;
}
std::uint64_t centimetres(double c) { return std::isfinite(c) ? static_cast<std::uint64_t>(std::llround(c * 100.0)) : 0; }

std::uint32_t node_id(std::uint16_t site, std::uint16_t app) { return (std::uint32_t(site) << 16) | app; }

}  // namespace

std::uint64_t repeat_key(const net::DetonationPdu& p) {
  std::uint64_t h = mix(mix(0xcbf29ce484222325ULL, word(p.firing_entity_id)), word(p.event_id));
  for (const double c : {p.location.x, p.location.y, p.location.z}) h = mix(h, centimetres(c));
  return h;
}

std::uint64_t repeat_key(const net::CollisionPdu& p) {
  std::uint64_t h = mix(mix(mix(0x6c62272e07bb0142ULL, word(p.issuing_entity_id)), word(p.event_id)),
                        word(p.colliding_entity_id));
  for (const float c : {p.location_in_entity.x, p.location_in_entity.y, p.location_in_entity.z})
    h = mix(h, centimetres(c));
  return h;
}

template <class Pdu>
void RepeatLedger<Pdu>::heard(std::uint16_t site, std::uint16_t application, double now_s) {
  const std::uint32_t id = node_id(site, application);
  for (auto& p : peers_)
    if (p.id == id) {
      p.last_s = now_s;
      return;
    }
  if (peers_.size() < kMaxPeers) peers_.push_back({id, now_s});
}

template <class Pdu>
int RepeatLedger<Pdu>::rank(const net::EntityId& origin, double now_s, double live_s) const {
  const std::uint32_t self = node_id(site_, app_), fired_by = node_id(origin.site, origin.application);
  int r = 0;
  for (const auto& p : peers_)
    if (p.id < self && p.id != fired_by && now_s - p.last_s <= live_s) ++r;
  return r;
}

template <class Pdu>
void RepeatLedger<Pdu>::keep(const Pdu& p, std::uint32_t group, double now_s, std::uint64_t key,
                            Role role) {
  const Kept k{p, group, now_s, key, role, role == Role::Own ? std::uint8_t(kQuickRepeats) : std::uint8_t(0)};
  if (kept_.size() < kMaxKept) {
    kept_.push_back(k);
    seen_[key] = static_cast<std::int32_t>(kept_.size() - 1);
    return;
  }
  auto old = seen_.find(kept_[oldest_].key);  // the oldest stops being repeated
  if (old != seen_.end() && old->second == static_cast<std::int32_t>(oldest_)) old->second = -1;
  kept_[oldest_] = k;
  seen_[key] = static_cast<std::int32_t>(oldest_);
  oldest_ = (oldest_ + 1) % kMaxKept;
  ++dropped_kept_;
}

template <class Pdu>
void RepeatLedger<Pdu>::remember(std::uint64_t k) {
  seen_order_.push_back(k);
  if (seen_order_.size() > kMaxSeen) {
    seen_.erase(seen_order_.front());
    seen_order_.pop_front();
  }
}

template <class Pdu>
void RepeatLedger<Pdu>::sent(const Pdu& p, std::uint32_t group, double now_s) {
  const std::uint64_t k = repeat_key(p);
  if (seen_.find(k) == seen_.end()) remember(k);
  keep(p, group, now_s, k, Role::Own);
}

template <class Pdu>
bool RepeatLedger<Pdu>::received(const Pdu& p, double now_s, bool adoptable, std::uint32_t group) {
  const std::uint64_t k = repeat_key(p);
  const auto it = seen_.find(k);
  if (it != seen_.end()) {
    ++repeats_ignored_;
    if (it->second >= 0) {
      Kept& e = kept_[static_cast<std::size_t>(it->second)];
      if (e.role != Role::Own) {  // someone repeats it: watch (an adopter stands down)
        e.last_s = now_s;
        e.role = Role::Held;
      }
    }
    return false;
  }
  remember(k);
  if (adoptable) keep(p, group, now_s, k, Role::Held);
  else seen_[k] = -1;
  return true;
}

template <class Pdu>
void RepeatLedger<Pdu>::resend_due(double now_s, double heartbeat_s, double live_s,
                                  const std::function<void(const Pdu&, std::uint32_t)>& resend) {
  for (auto& k : kept_) {
    const double quiet = now_s - k.last_s;
    if (k.quick > 0 && quiet >= std::min(kQuickGapS, heartbeat_s)) {
      --k.quick;
    } else if (quiet < heartbeat_s) {
      continue;
    }
    if (k.role == Role::Held) {
      if (quiet < heartbeat_s * (2 + rank(originator(k.pdu), now_s, live_s))) continue;
      k.role = Role::Adopted;
      ++adoptions_;
    }
    k.last_s = now_s;
    resend(k.pdu, k.group);
    ++(k.role == Role::Own ? repeats_sent_ : adopted_sent_);
  }
}

template class RepeatLedger<net::DetonationPdu>;
template class RepeatLedger<net::CollisionPdu>;

}  // namespace npsnet::node
