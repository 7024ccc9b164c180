// marking.cpp — ASCII markings.
#include "net/marking.hpp"

namespace net {

Result<Marking, std::string> make_marking(std::string_view text) {
  Marking m;
  m.character_set = kMarkingAscii;
  if (text.size() > m.characters.size())
    return Result<Marking, std::string>::failure(
        "marking \"" + std::string(text) + "\" has " + std::to_string(text.size()) +
        " characters; a DIS marking holds at most 11");
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c > 0x7E)
      return Result<Marking, std::string>::failure(
          "marking \"" + std::string(text) + "\": character " + std::to_string(i + 1) +
          " is not printable ASCII (code " + std::to_string(c) + ")");
    m.characters[i] = text[i];
  }
  return m;
}

std::string marking_text(const Marking& m) {
  std::string s;
  for (char ch : m.characters) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == 0) break;
    if (m.character_set == kMarkingDigitChevron && c <= 9) {
      s.push_back(static_cast<char>('0' + c));
    } else if (c >= 0x20 && c <= 0x7E) {
      s.push_back(static_cast<char>(c));
    } else if (c >= 0xA0) {  // Latin-1: U+00A0..U+00FF in two UTF-8 octets
      s.push_back(static_cast<char>(0xC0 | (c >> 6)));
      s.push_back(static_cast<char>(0x80 | (c & 0x3F)));
    } else {  // U+FFFD REPLACEMENT CHARACTER
      s += "\xEF\xBF\xBD";
    }
  }
  return s;
}

}  // namespace net
