// A 5 x 7 pixel bitmap font made in code for HUD text: space, digits, A-Z (lower case is drawn as
// upper case) and the punctuation a HUD needs. Unknown characters draw as a hollow box.
#pragma once
#include <cstdint>
#include <vector>

namespace npsnet::render::font {

inline constexpr int kGlyphW = 5, kGlyphH = 7;       // glyph pixels
inline constexpr int kCellW = 6, kCellH = 9;         // atlas cell (glyph + spacing)
inline constexpr int kAtlasCols = 16, kAtlasRows = 6;  // ASCII 32..127
inline constexpr int kAtlasW = kAtlasCols * kCellW, kAtlasH = kAtlasRows * kCellH;

// 7 rows of 5 bits (bit 4 = leftmost column) for ASCII code c.
const uint8_t* glyph(char c);
// R8 atlas, kAtlasW x kAtlasH, row 0 at the top; 255 where a glyph pixel is set.
std::vector<uint8_t> atlas();

}  // namespace npsnet::render::font
