// record/replayer.hpp — `npsnet replay`: send a capture's UDP payloads into an exercise at their
// recorded pace.
// Contract:
//  * Times are seconds from the capture's first UDP frame. Frames before `from_s` or after `to_s`
//    are not sent; the first sent frame leaves at once, every later one at
//    start + (t - t_first_sent) / speed on the steady clock (speed > 0; 2 = twice as fast).
//  * Payloads go out unchanged, one datagram per frame, through one net::UdpTransport; with
//    `exercise` the exercise id octet of every PDU in the datagram is rewritten (PDUs walked by
//    their length field, never past the datagram). Frames cut short in the capture (caplen < UDP
//    length) are not sent (counted).
//  * A capture that ends inside a frame is sent up to the cut; report().cut says so.
//  * Lateness (actual send time - scheduled time) is measured for every datagram sent.
#pragma once

#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "net/transport.hpp"
#include "record/pdu_tally.hpp"

namespace npsnet::record {

struct ReplayOptions {
  std::filesystem::path in;
  net::TransportConfig net;
  double speed = 1.0;
  std::optional<double> from_s, to_s;
  std::optional<int> exercise;  // rewrite the exercise id
};

struct ReplayReport {
  std::uint64_t sent = 0, send_failures = 0, not_sent_cut = 0, skipped_frames = 0;
  double span_s = 0, wall_s = 0;  // recorded span of what was sent, and wall time it took
  double late_p50_ms = 0, late_p99_ms = 0, late_max_ms = 0;
  std::string cut;      // the reader's message when the capture ends inside a frame
  PduTally tally;       // what was sent
  std::string summary(const std::filesystem::path& in) const;
};

// Rewrites the exercise id octet of each PDU of datagram `d` in place.
void rewrite_exercise(std::span<std::uint8_t> d, std::uint8_t exercise) noexcept;

class Replayer {
 public:
  explicit Replayer(const ReplayOptions& o);  // opens the capture and the socket; throws
  ~Replayer();
  ReplayReport run();
  static void stop() noexcept;  // async-signal-safe: ends run() after the current datagram

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  static std::atomic<bool> stop_;
};

}  // namespace npsnet::record
