// Crash safety (issue 11): a node killed with SIGKILL at any moment leaves an event log whose
// every line is complete JSON, and only whole PNGs under their final names.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <thread>

#include "support/dirs.hpp"
#include "support/scratch.hpp"

extern char** environ;

namespace fs = std::filesystem;

namespace {
// Starts npsnet with `args`; once `ready()` (polled, at most 60 s) kills it with SIGKILL after
// `ms` more milliseconds. Returns false when it had already ended.
template <class Ready>
bool run_and_kill(std::vector<std::string> args, Ready ready, int ms) {
  args.insert(args.begin(), std::string(npsnet::dirs::binary()) + "/npsnet");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return false;
  int st = 0;
  for (int i = 0; i < 6000 && !ready(); ++i) {
    if (waitpid(pid, &st, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(ms));
  const bool killed = kill(pid, SIGKILL) == 0;
  waitpid(pid, &st, 0);
  return killed && WIFSIGNALED(st);
}

bool whole_png(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  const std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  static const std::string sig = "\x89PNG\r\n\x1a\n";
  static const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  return b.size() > sig.size() + iend.size() && b.compare(0, sig.size(), sig) == 0 &&
         b.compare(b.size() - iend.size(), iend.size(), iend) == 0;
}

void expect_whole_lines(const fs::path& log, int& lines) {
  std::ifstream in(log, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!text.empty()) { EXPECT_EQ(text.back(), '\n') << log << ": ends in the middle of a line"; }
  size_t at = 0;
  while (at < text.size()) {
    const size_t nl = text.find('\n', at);
    const std::string line = text.substr(at, nl == std::string::npos ? std::string::npos : nl - at);
    EXPECT_TRUE(nlohmann::json::accept(line)) << log << ": not a complete JSON line: " << line;
    ++lines;
    if (nl == std::string::npos) break;
    at = nl + 1;
  }
}
}  // namespace

TEST(CrashSafety, KilledAtAnyMomentLeavesWholeLinesAndWholePngs) {
  const auto dir = npsnet::test::scratch_dir() / "crash";
  int killed = 0, lines = 0, pngs = 0;
  auto count_pngs = [&] {
    int n = 0;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
      n += it->path().extension() == ".png";
    return n;
  };
  // Kill times spread over start-up, the rendered Appendix A cases and a long headless run:
  // after the k-th PNG (or the first lines of the log) and some milliseconds more.
  for (int k = 0; k < 12; ++k) {
    const int ms = (37 * k) % 150;
    fs::remove_all(dir);
    std::vector<std::string> args = {"run", "--quiet", "--snapshots", dir.string()};
    if (k % 2) {
      args.insert(args.end(), {"--no-render", "--seconds", "3000"});
    } else {
      args.insert(args.end(), {"--size", "320x180", "--snapshot-every", "0.5"});
    }
    if (k % 2) {
      killed += run_and_kill(args, [&] { std::error_code ec; return fs::file_size(dir / "events.jsonl", ec) > 2000 * static_cast<unsigned>(k) && !ec; }, ms);
    } else {
      killed += run_and_kill(args, [&] { return count_pngs() >= 1 + k / 2; }, ms);
    }
    if (!fs::exists(dir)) continue;
    if (fs::exists(dir / "events.jsonl")) expect_whole_lines(dir / "events.jsonl", lines);
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".png") {
        EXPECT_TRUE(whole_png(e.path())) << e.path() << " is not a whole PNG";
        ++pngs;
      }
  }
  EXPECT_GE(killed, 8) << "most runs must still be going when killed";
  EXPECT_GT(lines, 100);
  EXPECT_GT(pngs, 5);
}
