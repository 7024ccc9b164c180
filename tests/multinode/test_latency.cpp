// Node-to-node latency on loopback multicast: one Session sends an Entity State PDU (the size a
// node sends), another Session (a different DIS application, as another node is) polls until it
// arrives; the time from before send() to the decoded PDU in the visitor is one sample. Prints
// median and p99 (microseconds) over 2000 samples. This is the transport + codec latency; a
// node polls once per tick, so a PDU waits up to one tick (0.1 s) more before the world sees it.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>
#include <vector>

#include "lan_support.hpp"
#include "net/net.hpp"

TEST(LanLatency, LoopbackEntityStateMedianAndP99) {
  const int port = lan::random_port();
  auto cfg = [&](std::uint16_t app) {
    net::SessionConfig c;
    c.transport.url = "udp://239.1.2.3:" + std::to_string(port);
    c.transport.iface = "127.0.0.1";
    c.site = 1;
    c.application = app;
    return c;
  };
  net::Session a(cfg(101)), b(cfg(102));
  net::EntityStatePdu es;
  es.entity_type = {1, 1, 225, 1, 1, 3, 0};
  es.marking = net::make_marking("lat").value();
  using clock = std::chrono::steady_clock;
  constexpr int kSamples = 2000;
  std::vector<double> us;
  us.reserve(kSamples);
  int lost = 0;
  for (int i = 0; i < kSamples; ++i) {
    es.entity_id = a.entity_id(static_cast<std::uint16_t>(i % 60000 + 1));
    es.location = {6378137.0 + i, 0, 0};
    bool got = false;
    const auto t0 = clock::now();
    ASSERT_TRUE(a.send(es));
    const auto deadline = t0 + std::chrono::milliseconds(200);
    while (!got && clock::now() < deadline) {
      b.poll(net::Overloaded{[&](const net::EntityStatePdu& p) {
                               if (p.entity_id == es.entity_id && p.location.x == es.location.x) {
                                 us.push_back(std::chrono::duration<double, std::micro>(clock::now() - t0).count());
                                 got = true;
                               }
                             },
                             [](const auto&) {}});
    }
    if (!got) ++lost;
    a.poll(net::Overloaded{[](const auto&) {}});  // drain our own echo
  }
  ASSERT_EQ(lost, 0) << "every PDU arrives on loopback";
  std::sort(us.begin(), us.end());
  const double median = us[us.size() / 2];
  const double p99 = us[static_cast<size_t>(us.size() * 0.99)];
  std::printf("loopback ESPDU latency over %zu samples: median %.1f us, p99 %.1f us, max %.1f us\n", us.size(), median,
              p99, us.back());
  RecordProperty("median_us", std::to_string(median));
  RecordProperty("p99_us", std::to_string(p99));
  EXPECT_LT(median, 50000.0) << "loopback latency should be far below a tick (100 ms)";
}

// The same across two processes (what two nodes on one host see): a forked echo process
// sends every Entity State it hears back with its own application id; one sample is half the
// round trip. Bounded: the echo process exits after kSamples PDUs or 20 s, and is killed at
// the end in any case.
TEST(LanLatency, TwoProcessesHalfRoundTrip) {
  const int port = lan::random_port();
  auto cfg = [&](std::uint16_t app) {
    net::SessionConfig c;
    c.transport.url = "udp://239.1.2.3:" + std::to_string(port);
    c.transport.iface = "127.0.0.1";
    c.application = app;
    return c;
  };
  constexpr int kSamples = 1000;
  net::Session a(cfg(201));
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    int code = 0;
    try {
      net::Session b(cfg(202));
      net::EntityStatePdu back;
      int echoed = 0;
      const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      while (echoed < kSamples && std::chrono::steady_clock::now() < end)
        b.poll(net::Overloaded{[&](const net::EntityStatePdu& p) {
                                 if (p.entity_id.application != 201) return;
                                 back = p;
                                 back.entity_id.application = 202;
                                 b.send(back);
                                 ++echoed;
                               },
                               [](const auto&) {}});
    } catch (...) {
      code = 1;
    }
    ::_exit(code);
  }
  struct Reap {
    pid_t pid;
    ~Reap() {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
    }
  } reap{child};
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the echo process joins the group
  net::EntityStatePdu es;
  es.entity_type = {1, 1, 225, 1, 1, 3, 0};
  using clock = std::chrono::steady_clock;
  std::vector<double> us;
  int lost = 0;
  for (int i = 0; i < kSamples; ++i) {
    es.entity_id = a.entity_id(static_cast<std::uint16_t>(i + 1));
    bool got = false;
    const auto t0 = clock::now();
    ASSERT_TRUE(a.send(es));
    const auto deadline = t0 + std::chrono::milliseconds(200);
    while (!got && clock::now() < deadline)
      a.poll(net::Overloaded{[&](const net::EntityStatePdu& p) {
                               if (p.entity_id.application == 202 && p.entity_id.entity == es.entity_id.entity) {
                                 us.push_back(std::chrono::duration<double, std::micro>(clock::now() - t0).count() / 2);
                                 got = true;
                               }
                             },
                             [](const auto&) {}});
    if (!got) ++lost;
  }
  ASSERT_LT(lost, kSamples / 100) << "at most 1% lost on loopback";
  std::sort(us.begin(), us.end());
  const double median = us[us.size() / 2];
  const double p99 = us[static_cast<size_t>(us.size() * 0.99)];
  std::printf("two-process loopback ESPDU latency (half round trip) over %zu samples: median %.1f us, p99 %.1f us\n",
              us.size(), median, p99);
  RecordProperty("median_us", std::to_string(median));
  RecordProperty("p99_us", std::to_string(p99));
  EXPECT_LT(median, 50000.0) << "half a tick at most, even on a loaded machine";
}
