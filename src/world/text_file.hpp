// Reading a whole input file into memory, so that each loader has one in-memory entry point
// (`..._text(text, file)`, used by the file version, the tests and the fuzz targets in fuzz/).
#pragma once
#include <filesystem>
#include <string>

namespace npsnet::world {

// The bytes of `file` as they are (binary). Throws InputError(file, 0, field, "cannot open
// file: <reason>") when it cannot be opened or read.
std::string read_text_file(const std::filesystem::path& file, const std::string& field);

// Whether `file` exists, never throwing: a name the system cannot look up at all (too long, a
// component that is not a folder, no permission) is "not found" (std::filesystem::exists throws
// filesystem_error there; a fuzzed kinds file found it).
bool file_exists(const std::filesystem::path& file) noexcept;

}  // namespace npsnet::world
