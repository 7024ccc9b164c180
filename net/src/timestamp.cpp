// timestamp.cpp — DIS timestamp helpers.
#include "net/timestamp.hpp"

#include <cmath>

namespace net {
namespace {

constexpr std::uint64_t kUnitsPerHour = 2147483648ull;  // 2^31

std::uint32_t units(double seconds_past_hour) {
  if (!std::isfinite(seconds_past_hour)) return 0;
  double s = std::fmod(seconds_past_hour, 3600.0);
  if (s < 0) s += 3600.0;
  auto u = static_cast<std::uint64_t>(std::llround(s / kTimestampUnitSeconds));
  return static_cast<std::uint32_t>(u % kUnitsPerHour);  // 3600 s rounds back to 0
}

}  // namespace

std::uint32_t relative_timestamp(double seconds_past_hour) noexcept {
  return units(seconds_past_hour) << 1;
}

std::uint32_t absolute_timestamp(double seconds_past_hour) noexcept {
  return (units(seconds_past_hour) << 1) | 1u;
}

std::uint32_t absolute_timestamp_from_unix(double unix_seconds) noexcept {
  // The UNIX epoch is at a whole UTC hour (leap seconds aside), so time past the hour is
  // unix_seconds modulo 3600.
  return absolute_timestamp(std::fmod(unix_seconds, 3600.0));
}

DecodedTimestamp decode_timestamp(std::uint32_t t) noexcept {
  return {static_cast<double>(t >> 1) * kTimestampUnitSeconds, (t & 1u) != 0};
}

double timestamp_difference(std::uint32_t later, std::uint32_t earlier) noexcept {
  double d = decode_timestamp(later).seconds_past_hour - decode_timestamp(earlier).seconds_past_hour;
  if (d >= 1800.0) d -= 3600.0;
  if (d < -1800.0) d += 3600.0;
  return d;
}

}  // namespace net
