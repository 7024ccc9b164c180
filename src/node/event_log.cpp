#include "node/event_log.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace npsnet::node {

EventLog::EventLog(const std::filesystem::path& file) {
  if (file.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
  }
  f_ = std::fopen(file.string().c_str(), "w");
  if (!f_) throw std::runtime_error(file.string() + ": cannot write event log: " + std::strerror(errno));
}

EventLog::~EventLog() {
  if (f_) std::fclose(f_);
}

void EventLog::write(const nlohmann::json& event) {
  counts_[event.value("event", "?")] += 1;
  if (keep_) kept_.push_back(event);
  if (!f_) return;
  const std::string line = event.dump() + "\n";
  std::fwrite(line.data(), 1, line.size(), f_);
}

void EventLog::flush() {
  if (f_) std::fflush(f_);
}

}  // namespace npsnet::node
