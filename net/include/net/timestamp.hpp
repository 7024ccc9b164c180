// net/timestamp.hpp — DIS timestamps (IEEE 1278.1 §6.2.88).
// A timestamp is 31 bits of time past the hour in units of 3600 s / 2^31 (about 1.676 us)
// followed by one bit: 0 = relative (the sender's own clock), 1 = absolute (UTC, synchronised).
// Encoding rounds to the nearest unit and wraps at the hour; decoding returns seconds past the
// hour in [0, 3600). Timestamps only help align dead reckoning: a PDU is never dropped for its
// timestamp alone (nothing in net/ does so).
#pragma once

#include <cstdint>

namespace net {

inline constexpr double kTimestampUnitSeconds = 3600.0 / 2147483648.0;  // 3600 s / 2^31

// seconds past the hour (any value; reduced modulo 3600) -> timestamp with low bit 0 / 1.
std::uint32_t relative_timestamp(double seconds_past_hour) noexcept;
std::uint32_t absolute_timestamp(double seconds_past_hour) noexcept;

// UNIX time (seconds since 1970, UTC) -> absolute timestamp (seconds past the UTC hour).
std::uint32_t absolute_timestamp_from_unix(double unix_seconds) noexcept;

struct DecodedTimestamp {
  double seconds_past_hour = 0;  // [0, 3600)
  bool absolute = false;
};
DecodedTimestamp decode_timestamp(std::uint32_t timestamp) noexcept;

// Signed difference later - earlier in seconds, wrapped into [-1800, 1800) across the hour.
double timestamp_difference(std::uint32_t later, std::uint32_t earlier) noexcept;

}  // namespace net
