#include "record/pdu_tally.hpp"

#include <numeric>

namespace npsnet::record {

std::size_t PduTally::add(std::span<const std::uint8_t> d, std::uint64_t frame) {
  ++datagrams_;
  bytes_ += d.size();
  for (std::size_t off = 0; off + net::kHeaderSize <= d.size();) {  // by type, every type
    ++by_type_[d[off + 2]];
    const std::size_t len = (std::size_t{d[off + 8]} << 8) | d[off + 9];
    if (len < net::kHeaderSize) break;
    off += len;
  }
  const auto before = counters_.rejected;
  parser_.parse(d, counters_, net::Overloaded{[&](const net::EntityStatePdu& p) { entities_.insert(p.entity_id); }});
  std::size_t bad = 0;
  for (std::size_t e = 0; e < before.size(); ++e) {
    const auto n = counters_.rejected[e] - before[e];
    bad += n;
    for (std::uint64_t k = 0; k < n && malformed_.size() < kMaxListed; ++k)
      malformed_.push_back({frame, std::string(net::to_string(static_cast<net::DecodeError>(e)))});
  }
  return bad;
}

std::uint64_t PduTally::pdus() const { return counters_.pdus_seen; }

std::string PduTally::by_type_text() const {
  std::string s;
  for (std::size_t t = 0; t < by_type_.size(); ++t)
    if (by_type_[t]) {  // appends: GCC 12 warns (falsely) on "literal" + std::string
      if (!s.empty()) s += ' ';
      s.append(net::pdu_type_name(static_cast<std::uint8_t>(t))).append("=").append(std::to_string(by_type_[t]));
    }
  return s.empty() ? "none" : s;
}

}  // namespace npsnet::record
