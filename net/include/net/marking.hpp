// net/marking.hpp — the Entity State marking: character set + 11 characters, NUL padded.
// make_marking accepts at most 11 printable ASCII characters (0x20..0x7E), character set 1
// (ASCII); anything else is an error with a message naming the problem.
// marking_text decodes a marking from the network, whatever its bytes, into safe UTF-8 text:
// characters up to the first NUL (or all 11); printable ASCII as it is; bytes 0xA0..0xFF as
// ISO 8859-1 (Latin-1: the code point of the same value, as European simulators send under set
// 1); every other byte (controls, DEL, 0x80..0x9F) as U+FFFD. Character sets (SISO-REF-010):
// 1 ASCII, 2 Army Marking (CCTT, an ASCII subset), 3 Digit Chevron (digits; octets 0..9 are the
// digits themselves); any other set is read as set 1. The result never holds a control
// character and is always valid UTF-8 (at most 33 octets).
#pragma once

#include <string>
#include <string_view>

#include "net/pdu.hpp"
#include "net/result.hpp"

namespace net {

inline constexpr std::uint8_t kMarkingAscii = 1;
inline constexpr std::uint8_t kMarkingArmyCctt = 2;
inline constexpr std::uint8_t kMarkingDigitChevron = 3;

Result<Marking, std::string> make_marking(std::string_view text);
std::string marking_text(const Marking& m);

}  // namespace net
