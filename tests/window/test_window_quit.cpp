// Quitting the player's node in a real GLFW window (under Xvfb in ctest): Esc (the quit action)
// and closing the window as a window manager does (WM_DELETE_WINDOW) each end a 60 s run at
// once and cleanly: exit 0, the reason and the summary on stderr, an event log of whole lines
// that starts with the `drive` event and stops at the quit.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include "support/dirs.hpp"
#include "support/fixture.hpp"
#include "window_support.hpp"

using namespace npsnet;
using nlohmann::json;

namespace {
using test::slurp;
std::string first_line(const std::string& cmd) {
  const std::string out = test::capture(cmd);
  return out.substr(0, out.find('\n'));
}

// Runs the window scenario for up to 60 s, drives 1 s, then `how` ends it: "esc" or "close".
void quit_by(const std::string& how, const std::string& expected_reason) {
  const auto dir = test::fresh_dir("window-quit-" + how);
  const std::string events = (dir / "events.jsonl").string(), out = (dir / "out.txt").string();
  const pid_t pid = test::spawn_logged({std::string(npsnet::dirs::binary()) + "/npsnet", "run", "--window", "--scenario",
                                        test::source("tests/node/data/window.toml").string(), "--seconds", "60",
                                        "--events", events, "--snapshots", (dir / "snap").string()},
                                       out);
  ASSERT_GT(pid, 0);
  const std::string wid = first_line("timeout 20 xdotool search --sync --onlyvisible --name '^NPSNET$'");
  ASSERT_FALSE(wid.empty()) << slurp(out);
  std::system(("xdotool mousemove --window " + wid + " 480 270").c_str());
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  std::system("xdotool keydown w");
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  std::system("xdotool keyup w");
  const auto asked = std::chrono::steady_clock::now();
  if (how == "esc") {
    std::system("xdotool key Escape");
  } else {
    ASSERT_TRUE(test::close_window(wid));
  }
  const int rc = test::wait_bounded(pid, 20);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count();
  const std::string text = slurp(out);
  ASSERT_EQ(rc, 0) << text;
  EXPECT_LT(took, 5.0) << text;  // at once, not at the end of the 60 s
  EXPECT_NE(text.find("npsnet: " + expected_reason + " at t = "), std::string::npos) << text;
  EXPECT_NE(text.find("npsnet: done: "), std::string::npos) << text;
  EXPECT_NE(text.find("collision method"), std::string::npos) << text;
  const std::string log = slurp(events);
  ASSERT_FALSE(log.empty());
  EXPECT_EQ(log.back(), '\n');
  std::istringstream lines(log);
  std::vector<json> ev;
  for (std::string line; std::getline(lines, line);) ev.push_back(json::parse(line));  // whole lines
  ASSERT_FALSE(ev.empty());
  EXPECT_EQ(ev.front()["event"], "drive");
  EXPECT_LT(ev.back()["t"].get<double>(), 30.0);
}
}  // namespace

TEST(WindowQuit, EscEndsTheRunCleanly) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no display (ctest runs this under xvfb-run)";
  quit_by("esc", "quit");
}

TEST(WindowQuit, ClosingTheWindowEndsTheRunCleanly) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no display (ctest runs this under xvfb-run)";
  quit_by("close", "the window was closed");
}
