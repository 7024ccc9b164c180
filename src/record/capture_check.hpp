// record/capture_check.hpp — what a capture file holds, for `npsnet check FILE.pcap`.
// Contract: inspect_capture(path) reads every frame (throws NotACapture when the file is not a
// pcap/pcapng file) and tallies the UDP payloads as DIS (see pdu_tally.hpp): PDUs by type,
// malformed PDUs with their frame number, frames that are not IPv4/UDP, frames cut short by the
// snap length, and where the file is cut when it ends inside a frame.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "record/pdu_tally.hpp"

namespace npsnet::record {

struct CaptureReport {
  PduTally tally;
  std::uint64_t frames = 0, not_udp = 0;
  std::string not_udp_first;                 // reason for the first such frame
  std::vector<std::uint64_t> cut_short;      // frames whose UDP payload was not captured whole
  std::string cut;                           // empty when the file ends cleanly
  double first_s = 0, last_s = 0;            // UNIX seconds of the first and last UDP frame
  std::string summary(const std::filesystem::path& f) const;  // several lines
};

bool looks_like_capture(const std::filesystem::path& f);  // by extension or magic number
CaptureReport inspect_capture(const std::filesystem::path& f);

}  // namespace npsnet::record
