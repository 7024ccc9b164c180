// Area of interest: the cell -> group formula, the cells near a point against brute force, joins
// and leaves with hysteresis, and a many-groups transport on loopback (127.0.0.1) holding more
// groups than one socket may (igmp_max_memberships), hearing only the groups it joined.
// Every wait is bounded (2 s).
#include <gtest/gtest.h>

#include <arpa/inet.h>

#include <chrono>
#include <map>
#include <random>
#include <set>
#include <thread>

#include "run_command.hpp"
#include "test_util.hpp"

using namespace nettest;

namespace {

std::uint32_t ip(const char* dotted) {
  in_addr a{};
  ::inet_pton(AF_INET, dotted, &a);
  return ntohl(a.s_addr);
}

net::AoiGrid grid(const char* base, double cell, int groups) {
  auto g = net::AoiGrid::make(base, cell, groups);
  EXPECT_TRUE(g.ok()) << (g ? "" : g.error());
  return g.value();
}

std::string read_text_file(const char* path) {
  const auto b = read_file(path);
  return std::string(b.begin(), b.end());
}

}  // namespace

TEST(AoiGrid, CellAndGroupFollowTheDocumentedFormula) {
  const auto g = grid("239.1.2.3", 2000.0, 1024);
  EXPECT_EQ(g.side(), 32);
  EXPECT_EQ(g.group_count(), 1024u);
  EXPECT_EQ(g.cell_of(0.0, 0.0), (net::CellIndex{0, 0}));
  EXPECT_EQ(g.cell_of(1999.999, 2000.0), (net::CellIndex{0, 1}));
  EXPECT_EQ(g.cell_of(-0.001, -4000.0), (net::CellIndex{-1, -2}));
  // k = (i mod M) + M * (j mod M), address = base + k
  EXPECT_EQ(g.group_of(net::CellIndex{3, 5}), 3u + 32u * 5u);
  EXPECT_EQ(g.group_of(net::CellIndex{-1, 0}), 31u);
  EXPECT_EQ(g.group_of(net::CellIndex{35, -33}), 3u + 32u * 31u);
  EXPECT_EQ(g.address(0), ip("239.1.2.3"));
  EXPECT_EQ(g.address_text(1023), "239.1.6.2");
  // Non-square counts use the largest square below.
  EXPECT_EQ(grid("239.1.2.3", 100.0, 30).group_count(), 25u);
  EXPECT_EQ(grid("239.1.2.3", 100.0, 1).group_count(), 1u);
  // Not a number: cell (0, 0), never undefined behaviour.
  EXPECT_EQ(g.cell_of(std::nan(""), 1e300), (net::CellIndex{0, static_cast<std::int64_t>(1e15)}));
}

TEST(AoiGrid, NeighboursWithinTheTileHaveDistinctGroups) {
  const auto g = grid("239.1.0.0", 1000.0, 64);  // M = 8
  for (std::int64_t i0 : {-20, 0, 13})
    for (std::int64_t j0 : {-9, 0, 40}) {
      std::set<std::uint32_t> seen;
      for (std::int64_t dj = 0; dj < 8; ++dj)
        for (std::int64_t di = 0; di < 8; ++di) seen.insert(g.group_of(net::CellIndex{i0 + di, j0 + dj}));
      EXPECT_EQ(seen.size(), 64u) << "any 8 x 8 block of cells uses every group once";
      EXPECT_EQ(g.group_of(net::CellIndex{i0, j0}), g.group_of(net::CellIndex{i0 + 8, j0 - 16}));
    }
}

TEST(AoiGrid, BadParametersSayWhatIsWrong) {
  struct Case {
    const char* base;
    double cell;
    int groups;
    const char* says;
  };
  for (const Case& c : {Case{"239.1.2.3", 0.0, 16, "cell size"}, Case{"239.1.2.3", -5.0, 16, "cell size"},
                        Case{"239.1.2.3", std::nan(""), 16, "cell size"}, Case{"239.1.2.3", 100.0, 0, "--aoi-groups"},
                        Case{"239.1.2.3", 100.0, 70000, "--aoi-groups"}, Case{"224.1.2.3", 100.0, 16, "239.0.0.0/8"},
                        Case{"239.255.255.250", 100.0, 16, "239.0.0.0/8"}, Case{"239.1.2", 100.0, 16, "dotted"}}) {
    auto g = net::AoiGrid::make(c.base, c.cell, c.groups);
    ASSERT_FALSE(g.ok()) << c.base << " " << c.cell << " " << c.groups;
    EXPECT_NE(g.error().find(c.says), std::string::npos) << g.error();
  }
}

TEST(AoiGrid, AllGroupsListsEveryAddressOnce) {
  auto all = net::aoi_all_groups("239.1.2.3", 100);
  ASSERT_TRUE(all.ok());
  ASSERT_EQ(all.value().size(), 100u);
  EXPECT_EQ(all.value().front(), "239.1.2.3");
  EXPECT_EQ(all.value().back(), "239.1.2.102");
  EXPECT_EQ(std::set<std::string>(all.value().begin(), all.value().end()).size(), 100u);
  EXPECT_FALSE(net::aoi_all_groups("10.0.0.1", 100).ok());
}

TEST(AoiGrid, GroupsNearAPointMatchBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-30000, 30000), rad(0, 12000);
  for (int groups : {4, 64, 1024}) {
    const auto g = grid("239.2.0.0", 1500.0, groups);
    for (int n = 0; n < 200; ++n) {
      const double x = pos(rng), y = pos(rng), r = rad(rng);
      std::set<std::uint32_t> fast, brute;
      g.for_each_group_near(x, y, r, [&](std::uint32_t k) { fast.insert(k); });
      for (std::int64_t j = -40; j <= 40; ++j)
        for (std::int64_t i = -40; i <= 40; ++i) {
          const double x0 = i * 1500.0, y0 = j * 1500.0;
          const double dx = std::max({x0 - x, 0.0, x - (x0 + 1500.0)});
          const double dy = std::max({y0 - y, 0.0, y - (y0 + 1500.0)});
          if (dx * dx + dy * dy <= r * r) brute.insert(g.group_of(net::CellIndex{i, j}));
        }
      ASSERT_EQ(fast, brute) << "groups " << groups << " at " << x << "," << y << " r " << r;
    }
  }
}

TEST(AoiMembership, JoinsNearLeavesOnlyPastTheHysteresis) {
  const auto g = grid("239.3.0.0", 1000.0, 256);  // M = 16
  net::AoiMembership m(g, 500.0);
  std::vector<std::uint32_t> joins, leaves;
  auto update = [&](double x, double y, double r) {
    joins.clear(), leaves.clear();
    m.begin();
    m.want(x, y, r);
    m.end([&](std::uint32_t k) { joins.push_back(k); return true; }, [&](std::uint32_t k) { leaves.push_back(k); });
  };
  update(500, 500, 400);  // inside cell (0, 0), 100 m from every border
  EXPECT_EQ(joins, std::vector<std::uint32_t>{g.group_of(500.0, 500.0)});
  update(1500, 500, 400);  // one cell east: (1, 0) joined, (0, 0) kept (within 400 + 500 m)
  EXPECT_EQ(joins, std::vector<std::uint32_t>{g.group_of(1500.0, 500.0)});
  EXPECT_TRUE(leaves.empty());
  EXPECT_EQ(m.held_count(), 2u);
  update(1950, 500, 400);  // 950 m from cell (0, 0): past 400 + 500 -> left
  EXPECT_EQ(leaves, std::vector<std::uint32_t>{g.group_of(500.0, 500.0)});
  EXPECT_TRUE(m.held(g.group_of(1500.0, 500.0)));
  EXPECT_TRUE(m.held(g.group_of(2500.0, 500.0))) << "(2, 0) is 50 m away";
  // A refused join is not held and is asked again next update.
  m.begin();
  m.want(9500, 9500, 10);
  int asked = 0;
  m.end([&](std::uint32_t) { ++asked; return false; }, [](std::uint32_t) {});
  EXPECT_EQ(asked, 1);
  EXPECT_FALSE(m.held(g.group_of(9500.0, 9500.0)));
}

TEST(AoiTransport, HoldsMoreGroupsThanOneSocketAndHearsOnlyThoseJoined) {
  const std::uint16_t port = test_port(2);
  const auto g = grid("239.77.0.0", 1000.0, 64);
  net::SessionConfig rc;
  rc.transport.url = "udp://239.77.0.0:" + std::to_string(port);
  rc.transport.iface = "127.0.0.1";
  rc.transport.join_destination = false;
  rc.application = 2;
  net::SessionConfig sc = rc;
  sc.application = 1;
  net::Session rx(rc), tx(sc);
  // Another many-groups session of the host joins group 63: rx must not hear it.
  net::SessionConfig oc = rc;
  oc.application = 3;
  net::Session other(oc);
  ASSERT_TRUE(other.join_group(g.address(63)));
  constexpr std::uint32_t kJoined = 45;  // more than the default igmp_max_memberships (20)
  for (std::uint32_t k = 0; k < kJoined; ++k) ASSERT_TRUE(rx.join_group(g.address(k))) << rx.transport().last_error();
  EXPECT_EQ(rx.counters().aoi_joins, kJoined);
  EXPECT_EQ(rx.counters().aoi_groups_held, kJoined);
  EXPECT_EQ(rx.transport().groups_joined(), kJoined);
  const std::string cap = trim(read_text_file("/proc/sys/net/ipv4/igmp_max_memberships"));
  if (!cap.empty() && std::stoul(cap) < kJoined) {
    EXPECT_GE(rx.transport().socket_count(), 2u) << "the kernel caps a socket at " << cap << " groups";
  }
  // One Entity State to each of the 64 groups; entity number = group index + 1.
  auto es = sample_entity_state(0);
  for (std::uint32_t k = 0; k < 64; ++k) {
    es.entity_id = tx.entity_id(static_cast<std::uint16_t>(k + 1));
    ASSERT_TRUE(tx.send_to(g.address(k), es)) << tx.transport().last_error();
  }
  std::set<std::uint16_t> heard;
  int heard_other = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (std::chrono::steady_clock::now() < deadline && (heard.size() < kJoined || heard_other == 0)) {
    rx.poll([&](const net::EntityStatePdu& p) { heard.insert(p.entity_id.entity); });
    other.poll([&](const net::EntityStatePdu& p) { heard_other += p.entity_id.entity == 64; });
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  rx.poll([&](const net::EntityStatePdu& p) { heard.insert(p.entity_id.entity); });
  std::set<std::uint16_t> expect;
  for (std::uint16_t k = 1; k <= kJoined; ++k) expect.insert(k);
  EXPECT_EQ(heard, expect) << "exactly the joined groups, not group 63 joined by another socket";
  EXPECT_EQ(heard_other, 1);
  // After a leave, that group is silent.
  ASSERT_TRUE(rx.leave_group(g.address(0)));
  EXPECT_EQ(rx.counters().aoi_leaves, 1u);
  EXPECT_EQ(rx.counters().aoi_groups_held, kJoined - 1);
  es.entity_id = tx.entity_id(1);
  ASSERT_TRUE(tx.send_to(g.address(0), es));
  es.entity_id = tx.entity_id(2);
  ASSERT_TRUE(tx.send_to(g.address(1), es));
  std::set<std::uint16_t> after;
  const auto d2 = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (std::chrono::steady_clock::now() < d2 && !after.count(2)) {
    rx.poll([&](const net::EntityStatePdu& p) { after.insert(p.entity_id.entity); });
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  EXPECT_EQ(after, std::set<std::uint16_t>{2});
  EXPECT_NE(rx.counters().summary().find("aoi groups=44 joins=45 leaves=1"), std::string::npos)
      << rx.counters().summary();
}

TEST(AoiTransport, OneGroupTransportDoesNotJoinMore) {
  net::SessionConfig c;
  c.transport.url = "udp://239.1.2.3:" + std::to_string(test_port(3));
  c.transport.iface = "127.0.0.1";
  net::Session s(c);
  EXPECT_FALSE(s.join_group(ip("239.1.2.4")));
  EXPECT_EQ(s.counters().aoi_join_failures, 1u);
  EXPECT_NE(s.transport().last_error().find("many-groups"), std::string::npos);
}

// A recorder holding many groups on one transport must write each datagram's true destination:
// receive(from) gives it (IP_PKTINFO), for the many-groups sockets and for a one-group transport.
TEST(AoiTransport, ReceiveGivesEachDatagramsDestinationGroup) {
  const std::uint16_t port = test_port(1);
  const auto g = grid("239.78.0.0", 1000.0, 64);
  net::TransportConfig rc;
  rc.url = "udp://239.78.0.0:" + std::to_string(port);
  rc.iface = "127.0.0.1";
  rc.join_destination = false;
  net::UdpTransport rx(rc);
  constexpr std::uint32_t kJoined = 30;  // more than one socket holds (igmp_max_memberships 20)
  for (std::uint32_t k = 0; k < kJoined; ++k) ASSERT_TRUE(rx.join(g.address(k))) << rx.last_error();
  std::vector<int> fds;
  for (std::size_t i = 0; i < rx.socket_count(); ++i) fds.push_back(rx.native_handle(i));
  EXPECT_EQ(fds.front(), rx.native_handle());
  EXPECT_EQ(std::set<int>(fds.begin(), fds.end()).size(), rx.socket_count()) << "one descriptor per socket";
  net::TransportConfig one;
  one.url = "udp://" + g.address_text(7) + ":" + std::to_string(port);
  one.iface = "127.0.0.1";
  net::UdpTransport rx_one(one);
  net::UdpTransport tx(rc);
  // Datagram k (one octet, k) to group k; the one-group transport hears only group 7.
  for (std::uint32_t k = 0; k < kJoined; ++k) {
    const std::uint8_t b = static_cast<std::uint8_t>(k);
    ASSERT_TRUE(tx.send_to(g.address(k), std::span<const std::uint8_t>(&b, 1))) << tx.last_error();
  }
  std::map<std::uint32_t, std::uint32_t> dest;  // payload octet -> destination heard
  std::vector<std::uint32_t> one_dest;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (std::chrono::steady_clock::now() < deadline && (dest.size() < kJoined || one_dest.empty())) {
    net::UdpSource from;
    while (auto d = rx.receive(from)) dest[(*d)[0]] = from.destination;
    while (auto d = rx_one.receive(from)) one_dest.push_back(from.destination);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_EQ(dest.size(), kJoined);
  for (const auto& [k, to] : dest) EXPECT_EQ(to, g.address(k)) << "datagram " << k;
  EXPECT_EQ(one_dest, std::vector<std::uint32_t>{g.address(7)});
}
