#include "support/dirs.hpp"
#include "lan_support.hpp"

#include "support/scratch.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace lan {

int random_port() {
  std::random_device rd;
  return 20000 + static_cast<int>(rd() % 40000);
}

double unix_now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

std::filesystem::path npsnet_binary() {
  // NPSNET_TEST_BINARY: run the tests against another build (e.g. an older one, to see a test fail).
  if (const char* b = std::getenv("NPSNET_TEST_BINARY"); b && *b) return b;
  return std::filesystem::path(npsnet::dirs::binary()) / "npsnet";
}

std::filesystem::path fresh_dir(const std::string& tag) { return npsnet::test::fresh_dir(tag); }

Procs::~Procs() {
  for (int pid : running_) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
  }
}

int Procs::start(const std::vector<std::string>& args, const std::filesystem::path& out,
                 const std::vector<std::string>& env) {
  return start_program(npsnet_binary().string(), args, out, env);
}

int Procs::start_program(const std::string& bin, const std::vector<std::string>& args,
                         const std::filesystem::path& out, const std::vector<std::string>& env) {
  // Everything the child needs is made before fork: between fork and exec a child of a
  // threaded process (a test's flooding or listening thread) may only make async-signal-safe
  // calls; a malloc there can wait forever on a lock another thread held at the fork (seen as a
  // node that printed nothing under ASan, whose allocator is not fork-safe).
  std::vector<std::string> all{bin};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<std::string> envs;  // this process's environment, `env`'s KEY=VALUE replacing KEY
  for (char** e = environ; *e; ++e) {
    const std::string kv = *e;
    const auto same_key = [&](const std::string& x) { return x.substr(0, x.find('=')) == kv.substr(0, kv.find('=')); };
    if (std::none_of(env.begin(), env.end(), same_key)) envs.push_back(kv);
  }
  envs.insert(envs.end(), env.begin(), env.end());
  std::vector<char*> argv, envp;
  for (auto& a : all) argv.push_back(a.data());
  for (auto& e : envs) envp.push_back(e.data());
  argv.push_back(nullptr), envp.push_back(nullptr);
  const std::string out_path = out.string();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    const int fd = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::close(fd);
    }
    ::execve(bin.c_str(), argv.data(), envp.data());
    ::_exit(127);
  }
  running_.push_back(pid);
  return pid;
}

int Procs::wait(int pid, double timeout_s, double term_grace_s) {
  auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  int status = 0;
  bool termed = term_grace_s <= 0;
  while (true) {
    if (std::chrono::steady_clock::now() >= end) {
      if (termed) break;
      ::kill(pid, SIGTERM);  // let it clean up (e.g. a script's trap), then SIGKILL
      termed = true;
      end = std::chrono::steady_clock::now() + std::chrono::duration<double>(term_grace_s);
    }
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) {
      running_.erase(std::remove(running_.begin(), running_.end(), pid), running_.end());
      if (WIFEXITED(status)) return WEXITSTATUS(status);
      if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
      return -1;
    }
    if (r < 0) return -1;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill_now(pid);
  return -1;
}

void Procs::kill_now(int pid) {
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  running_.erase(std::remove(running_.begin(), running_.end(), pid), running_.end());
}

std::vector<nlohmann::json> read_events(const std::filesystem::path& file) {
  std::vector<nlohmann::json> out;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty()) out.push_back(nlohmann::json::parse(line));
  return out;
}

std::vector<nlohmann::json> of_type(const std::vector<nlohmann::json>& events, const std::string& type) {
  std::vector<nlohmann::json> r;
  for (const auto& e : events)
    if (e.value("event", "") == type) r.push_back(e);
  return r;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

double start_lag_s(const std::filesystem::path& out) {
  const std::string text = read_text(out);
  const std::string key = "npsnet: started ";
  const auto at = text.find(key);
  return at == std::string::npos ? 0.0 : std::strtod(text.c_str() + at + key.size(), nullptr);
}

double worst_late_s(const std::filesystem::path& out) {
  const std::string text = read_text(out);
  const std::string key = "ticks ended past their deadline, the worst by ";
  const auto at = text.find(key);
  return at == std::string::npos ? 0.0 : std::strtod(text.c_str() + at + key.size(), nullptr) / 1000;
}

bool await_udp_port(int port, double timeout_s) {
  char want[16];
  std::snprintf(want, sizeof want, ":%04X", port);
  const double until = unix_now() + timeout_s;
  for (int i = 0; i < 100000; ++i) {
    for (const char* table : {"/proc/net/udp", "/proc/net/udp6"}) {
      std::ifstream in(table);
      std::string line, local;
      std::getline(in, line);  // the header
      while (std::getline(in, line)) {
        std::istringstream fields(line);
        fields >> local >> local;  // "sl", then the local address "HEXIP:PORT"
        if (local.size() > 5 && local.compare(local.size() - 5, 5, want) == 0) return true;
      }
    }
    if (unix_now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

std::vector<std::string> node_args(const std::string& scenario, int port, int node, double start_at, double seconds,
                                   const std::filesystem::path& dir, const std::string& tag) {
  char s[64];
  std::snprintf(s, sizeof s, "%.3f", start_at);
  return {"run",      "--scenario", (std::filesystem::path(npsnet::dirs::source()) / "tests" / "multinode" / "data" / scenario).string(),
          "--net",    "udp://239.1.2.3:" + std::to_string(port),
          "--iface",  "127.0.0.1",
          "--node",   std::to_string(node),
          "--start-at", s,
          "--no-render",
          "--seconds", std::to_string(seconds),
          "--events", (dir / ("events_" + tag + ".jsonl")).string(),
          "--snapshots", (dir / ("snap_" + tag)).string()};
}

}  // namespace lan
