// record/pdu_tally.hpp — what a stream of DIS datagrams holds: PDUs by type (every type, also
// those the node does not decode), entities seen (Entity State ids), octets, and the malformed
// PDUs with the frame they came in. Used by the recorder's summary, `npsnet check FILE.pcap` and
// the replayer.
// Contract: add(datagram, frame) walks the PDU headers by their length field (like
// net::DatagramParser, which also decodes the five types we speak, with no filter) and never
// reads past the span. A PDU is malformed when the parser rejects it (net::DecodeError); the
// first kMaxListed malformed ones are kept with their frame number, all are counted.
#pragma once

#include <array>
#include <cstdint>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "net/datagram.hpp"

namespace npsnet::record {

struct MalformedPdu {
  std::uint64_t frame = 0;
  std::string reason;  // net::DecodeError names, e.g. "length_exceeds_data"
};

class PduTally {
 public:
  static constexpr std::size_t kMaxListed = 1000;
  // Returns the number of malformed PDUs in this datagram.
  std::size_t add(std::span<const std::uint8_t> datagram, std::uint64_t frame);

  std::uint64_t datagrams() const { return datagrams_; }
  std::uint64_t bytes() const { return bytes_; }  // UDP payload octets
  std::uint64_t pdus() const;                     // headers walked
  std::uint64_t pdus_of(std::uint8_t type) const { return by_type_[type]; }
  std::uint64_t malformed_total() const { return counters_.rejected_total(); }
  const std::vector<MalformedPdu>& malformed() const { return malformed_; }
  std::size_t entities() const { return entities_.size(); }
  const net::Counters& counters() const { return counters_; }
  // "entity_state=120 fire=1 type_20=3" (zero entries left out; "none" when empty).
  std::string by_type_text() const;

 private:
  std::uint64_t datagrams_ = 0, bytes_ = 0;
  std::array<std::uint64_t, 256> by_type_{};
  net::DatagramParser parser_;
  net::Counters counters_;
  std::set<net::EntityId> entities_;
  std::vector<MalformedPdu> malformed_;
};

}  // namespace npsnet::record
