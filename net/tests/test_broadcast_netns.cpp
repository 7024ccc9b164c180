// Broadcast transport, tested only inside a private network namespace this test creates (in a
// forked child, with a veth pair it adds and deletes by name), so nothing reaches a real
// interface. Skips with a message where namespaces cannot be created (no CAP_SYS_ADMIN) or
// `ip` is missing. The child is bounded by alarm(10); the parent waits at most 15 s.
#include <gtest/gtest.h>

#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "run_command.hpp"
#include "test_util.hpp"

using namespace nettest;

namespace {

constexpr int kNoNamespace = 77;
constexpr int kNoVeth = 78;

// Runs in the child, inside its own network namespace. Returns the exit code.
int broadcast_child(std::uint16_t port) {
  if (::unshare(CLONE_NEWNET) != 0) return kNoNamespace;
  if (std::system("ip link add npsnetA type veth peer name npsnetB && "
                  "ip addr add 10.213.0.1/24 broadcast 10.213.0.255 dev npsnetA && "
                  "ip link set npsnetA up && ip link set npsnetB up") != 0)
    return kNoVeth;
  int rc = 1;
  try {
    net::SessionConfig ca;
    ca.transport.url = "udp://10.213.0.255:" + std::to_string(port);
    ca.transport.iface = "10.213.0.1";
    ca.site = 5;
    ca.application = 1;
    net::SessionConfig cb = ca;
    cb.application = 2;
    net::Session a(ca), b(cb);
    if (a.transport().destination().mode != net::UdpMode::Broadcast) return 2;
    auto es = sample_entity_state(0);
    es.entity_id = a.entity_id(1);
    if (!a.send(es)) return 3;  // EACCES here would mean SO_BROADCAST is missing
    int got = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (got == 0 && std::chrono::steady_clock::now() < deadline) {
      b.poll([&](const net::EntityStatePdu& p) { got += p.entity_id == es.entity_id; });
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    rc = got == 1 ? 0 : 4;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "broadcast child: %s\n", e.what());
    rc = 5;
  }
  std::system("ip link del npsnetA");  // the peer goes with it; the namespace dies with us
  return rc;
}

}  // namespace

TEST(UdpBroadcast, BroadcastInsideAPrivateNetworkNamespace) {
  if (!have_tool("ip")) GTEST_SKIP() << "iproute2 `ip` is not installed: broadcast test skipped";
  const std::uint16_t port = test_port(0);
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::alarm(10);
    ::_exit(broadcast_child(port));
  }
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
  pid_t done = 0;
  while ((done = ::waitpid(pid, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  if (done == 0) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
    FAIL() << "broadcast child did not finish in 15 s";
  }
  ASSERT_TRUE(WIFEXITED(status)) << "child ended by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  const int rc = WEXITSTATUS(status);
  if (rc == kNoNamespace) GTEST_SKIP() << "cannot create a network namespace here (needs CAP_SYS_ADMIN)";
  if (rc == kNoVeth) GTEST_SKIP() << "cannot create a veth pair in the test namespace";
  EXPECT_EQ(rc, 0) << "2 wrong mode, 3 send failed, 4 not received, 5 exception";
}
