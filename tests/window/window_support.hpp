// For the real-window tests (test_window*.cpp, under Xvfb): start `npsnet` with its output in a
// file, wait for it within a bound, and close a window as a window manager does.
#pragma once
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace npsnet::test {

// The whole file (empty when it cannot be read).
std::string slurp(const std::filesystem::path& f);
// The standard output of a shell command.
std::string capture(const std::string& cmd);
// Starts args[0] with args, stdout and stderr into file `out`; the pid, or -1.
pid_t spawn_logged(const std::vector<std::string>& args, const std::string& out);
// Waits up to `seconds` for pid to end: its exit code, or -1 when it had to be killed (SIGKILL)
// or ended by a signal.
int wait_bounded(pid_t pid, double seconds);
// Sends window `xid` (as xdotool prints it) the WM_DELETE_WINDOW message a window manager sends
// when its close button is clicked. False when there is no display.
bool close_window(const std::string& xid);

}  // namespace npsnet::test
