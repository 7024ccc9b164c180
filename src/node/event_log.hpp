// The event log: JSON Lines, one object a line, flushed every tick (shared/ARCHITECTURE.md).
// Entities and objects are named by their ids (markings). Also keeps counts per event type.
#pragma once
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace npsnet::node {

class EventLog {
 public:
  EventLog() = default;
  // Opens `file` for writing (truncates). Throws std::runtime_error naming the file on failure.
  explicit EventLog(const std::filesystem::path& file);
  ~EventLog();
  EventLog(const EventLog&) = delete;
  EventLog& operator=(const EventLog&) = delete;

  void write(const nlohmann::json& event);  // needs "event"; counted by type
  void flush();
  const std::map<std::string, int>& counts() const { return counts_; }
  // Every event written, kept in memory when `keep` (tests read them back).
  void keep(bool k) { keep_ = k; }
  const std::vector<nlohmann::json>& kept() const { return kept_; }

 private:
  std::FILE* f_ = nullptr;
  std::map<std::string, int> counts_;
  bool keep_ = false;
  std::vector<nlohmann::json> kept_;
};

}  // namespace npsnet::node
