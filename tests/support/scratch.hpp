// Scratch files for tests: one folder per test process, so tests that ctest runs side by side
// (-j2) never share a file. Removed when the process ends (set NPSNET_KEEP_TEST_FILES=1 to keep);
// a child made by fork() must leave by _exit, or its exit removes the folder under its parent.
// fresh_dir(name): an empty folder `name` in it (emptied if a test before made one).
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

inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path d = scratch_dir() / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace npsnet::test
