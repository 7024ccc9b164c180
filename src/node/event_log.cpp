#include "node/event_log.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace npsnet::node {

void ensure_writable_dir(const std::filesystem::path& dir, const std::string& flag) {
  const std::string what = flag + " " + dir.string() + ": ";
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw OutputError(what + "not a folder");
  std::filesystem::create_directories(dir, ec);
  if (ec) throw OutputError(what + "cannot create the folder: " + ec.message());
  const auto probe = dir / (".npsnet-probe-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) throw OutputError(what + "cannot write there: " + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

void EventLog::open(const std::filesystem::path& file) {
  if (file.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
  }
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw OutputError(file.string() + ": cannot write the event log: it is a directory");
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputError(file.string() + ": cannot write the event log: " + std::strerror(errno));
  if (fd_ >= 0) ::close(fd_);
  fd_ = fd, file_ = file, size_ = 0;
}

EventLog::~EventLog() {
  if (fd_ < 0) return;
  try {
    flush();
  } catch (const OutputError&) {  // already reported by the flush the run made
  }
  ::close(fd_);
}

void EventLog::write(const nlohmann::json& event) {
  if (muted_) return;
  counts_[event.value("event", "?")] += 1;
  if (keep_) kept_.push_back(event);
  if (fd_ < 0) return;
  // Any byte that is not UTF-8 is written as U+FFFD, never thrown on (strings from the network
  // are decoded before they get here; this is the last line of defence).
  buf_ += event.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  buf_ += '\n';
}

void EventLog::flush() {
  if (fd_ < 0 || buf_.empty()) return;
  size_t done = 0;
  std::string err;
  while (done < buf_.size()) {
    const ssize_t w = ::write(fd_, buf_.data() + done, buf_.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      err = w < 0 ? std::strerror(errno) : "nothing written";
      break;
    }
    done += static_cast<size_t>(w);
  }
  if (err.empty()) {
    size_ += static_cast<long long>(done);
    buf_.clear();
    return;
  }
  // Keep the whole lines that went out; cut a partial one back off.
  const size_t nl = done > 0 ? buf_.rfind('\n', done - 1) : std::string::npos;
  size_ += nl == std::string::npos ? 0 : static_cast<long long>(nl + 1);
  if (done > 0) (void)::ftruncate(fd_, size_);
  (void)::lseek(fd_, size_, SEEK_SET);
  buf_.clear();
  throw OutputError(file_.string() + ": cannot write the event log: " + err);
}

}  // namespace npsnet::node
