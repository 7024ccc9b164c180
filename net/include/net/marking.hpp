// net/marking.hpp — the Entity State marking: character set 1 (ASCII) + 11 characters, NUL padded.
// make_marking accepts at most 11 printable ASCII characters (0x20..0x7E); anything else is an
// error with a message naming the problem. marking_text returns the characters up to the first
// NUL (a marking from the network may hold any octets; they are returned as they are).
#pragma once

#include <string>
#include <string_view>

#include "net/pdu.hpp"
#include "net/result.hpp"

namespace net {

inline constexpr std::uint8_t kMarkingAscii = 1;

Result<Marking, std::string> make_marking(std::string_view text);
std::string marking_text(const Marking& m);

}  // namespace net
