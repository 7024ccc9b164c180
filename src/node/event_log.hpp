// The event log: JSON Lines, one object a line, flushed every tick (shared/ARCHITECTURE.md).
// Entities and objects are named by their ids (markings). Also keeps counts per event type.
// Crash safety: events are buffered as whole lines and each flush hands whole lines to the
// kernel in one write(2), so a node killed at any moment leaves only complete lines; a failed
// or short write (disk full, /dev/full, I/O error) is cut back to the last whole line and
// thrown as OutputError naming the file.
// A string that is not valid UTF-8 is written with U+FFFD in place of the bad bytes (never throws).
#pragma once
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace npsnet::node {

// An output file or folder that cannot be written; what() names it and says why.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Creates `dir` if needed and proves that a file can be created in it (a probe file, removed
// again). Throws OutputError "<flag> <dir>: ..." when it is not a folder or not writable.
void ensure_writable_dir(const std::filesystem::path& dir, const std::string& flag);

class EventLog {
 public:
  EventLog() = default;  // not open: events are only counted (and kept, with keep(true))
  // Opens `file` for writing (truncates; creates its folder). Throws OutputError on failure.
  explicit EventLog(const std::filesystem::path& file) { open(file); }
  ~EventLog();
  EventLog(const EventLog&) = delete;
  EventLog& operator=(const EventLog&) = delete;

  void open(const std::filesystem::path& file);  // throws OutputError
  bool is_open() const { return fd_ >= 0; }
  void write(const nlohmann::json& event);  // needs "event"; counted by type; buffered
  void flush();                             // throws OutputError when the write fails
  const std::map<std::string, int>& counts() const { return counts_; }
  // Every event written, kept in memory when `keep` (tests read them back).
  void keep(bool k) { keep_ = k; }
  const std::vector<nlohmann::json>& kept() const { return kept_; }
  // While muted, write() drops events (not counted, not kept): a node catching up to a running
  // exercise replays its past ticks without logging them as live (run.cpp).
  void mute(bool m) { muted_ = m; }

 private:
  int fd_ = -1;
  std::filesystem::path file_;
  std::string buf_;     // whole lines not yet written
  long long size_ = 0;  // bytes of whole lines in the file
  std::map<std::string, int> counts_;
  bool keep_ = false;
  bool muted_ = false;
  std::vector<nlohmann::json> kept_;
};

}  // namespace npsnet::node
