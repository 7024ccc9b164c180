// Helpers of the multi-node tests: start `npsnet run` processes (fork/exec, output to a file),
// wait for them with a deadline (then SIGKILL), read JSON Lines event logs. Every child is killed
// and reaped when its Procs goes out of scope. Everything talks to 127.0.0.1 only.
#pragma once
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace lan {

// A random UDP port in [20000, 60000) for one test run.
int random_port();
// Wall clock, UNIX seconds.
double unix_now();
// <build>/npsnet, or $NPSNET_TEST_BINARY when set
std::filesystem::path npsnet_binary();
// A fresh empty folder under the system temp folder.
std::filesystem::path fresh_dir(const std::string& tag);

// The arguments of one headless node of a loopback exercise: `run --scenario
// tests/multinode/data/<scenario> --net udp://239.1.2.3:<port> --iface 127.0.0.1 --node <node>
// --start-at <start_at> --no-render --seconds <seconds>`, its event log events_<tag>.jsonl and
// its snapshots snap_<tag> in dir.
std::vector<std::string> node_args(const std::string& scenario, int port, int node, double start_at, double seconds,
                                   const std::filesystem::path& dir, const std::string& tag);

class Procs {
 public:
  Procs() = default;
  ~Procs();  // SIGKILL + reap every child still running
  Procs(const Procs&) = delete;
  Procs& operator=(const Procs&) = delete;
  // Starts npsnet with `args` (after argv[0]); extra environment "NAME=VALUE" entries; stdout and
  // stderr go to `out`. Returns the child's pid.
  int start(const std::vector<std::string>& args, const std::filesystem::path& out,
            const std::vector<std::string>& env = {});
  // The same for any program (e.g. /bin/bash and a script).
  int start_program(const std::string& program, const std::vector<std::string>& args,
                    const std::filesystem::path& out, const std::vector<std::string>& env = {});
  // Waits until `pid` exits or the deadline passes (then SIGKILL; with term_grace_s > 0 first
  // SIGTERM and that many seconds to clean up). Returns the exit status (0-255), 128+signal when
  // killed by a signal, or -1 when it had to be killed at the deadline.
  int wait(int pid, double timeout_s, double term_grace_s = 0);
  void kill_now(int pid);  // SIGKILL and reap

 private:
  std::vector<int> running_;
};

std::vector<nlohmann::json> read_events(const std::filesystem::path& file);
// The events of one type ("collision", "crater", ...), in order.
std::vector<nlohmann::json> of_type(const std::vector<nlohmann::json>& events, const std::string& type);
std::string read_text(const std::filesystem::path& file);
// How late (s) a node started past its --start-at, from its output `out` ("npsnet: started X s
// past --start-at"): its event times run that much behind the test's wall clock. 0 when on time.
double start_lag_s(const std::filesystem::path& out);
// How far (s) a paced node's ticks ran behind the wall clock at worst, from the summary it prints
// at the end ("paced: ... the worst by X ms"): a loaded machine can starve a node, whose tick then
// reads what arrived up to that long before its scenario time. 0 when the summary is missing.
double worst_late_s(const std::filesystem::path& out);
// Waits (at most timeout_s) until some UDP socket of this machine is bound to `port`
// (/proc/net/udp and udp6): a node started on that port is listening. False at the timeout.
bool await_udp_port(int port, double timeout_s);

}  // namespace lan
