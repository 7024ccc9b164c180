// Scratch files for tests: one folder per test process, so tests that ctest runs side by side
// (-j2) never share a file. Removed when the process ends (set NPSNET_KEEP_TEST_FILES=1 to keep).
#pragma once
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace npsnet::test {

inline const std::filesystem::path& scratch_dir() {
  struct Dir {
    std::filesystem::path path = std::filesystem::temp_directory_path() / "npsnet-tests" / std::to_string(::getpid());
    Dir() {
      std::filesystem::remove_all(path);
      std::filesystem::create_directories(path);
    }
    ~Dir() {
      std::error_code ec;
      if (!std::getenv("NPSNET_KEEP_TEST_FILES")) std::filesystem::remove_all(path, ec);
    }
  };
  static const Dir dir;
  return dir.path;
}

}  // namespace npsnet::test
