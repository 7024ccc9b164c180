// Shared by the fuzz targets (fuzz/README in the header of fuzz/CMakeLists.txt):
// where the fixture lives, and the bytes as text.
// Every target defines LLVMFuzzerTestOneInput; built with clang's libFuzzer (NPSNET_FUZZ=ON,
// scripts/fuzz.sh) it fuzzes, built with any compiler and replay_main.cpp it replays the
// committed corpus and regressions as a ctest test (fuzz.replay.<target>).
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "support/dirs.hpp"

namespace npsnet::fuzz {

// fuzz/data: a small world (33 x 33 terrain posts, ~220 objects, the bundled kinds with one box
// model) that the scenario seeds name, so that a world builds in well under a millisecond.
inline std::filesystem::path data_dir() { return npsnet::dirs::fuzz_data(); }
// The source tree (the bundled models/ and kinds).
inline std::filesystem::path source_dir() { return npsnet::dirs::source(); }

inline std::string_view text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace npsnet::fuzz
