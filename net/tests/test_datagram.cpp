// Datagram walking: several PDUs in one datagram, skips, each rejection reason, filters, fuzz.
#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include "test_util.hpp"

using namespace nettest;

namespace {

struct Seen {
  std::vector<int> order;
  void operator()(const net::EntityStatePdu&) { order.push_back(1); }
  void operator()(const net::FirePdu&) { order.push_back(2); }
  void operator()(const net::DetonationPdu&) { order.push_back(3); }
  void operator()(const net::CollisionPdu&) { order.push_back(4); }
  void operator()(const net::EntityStateUpdatePdu&) { order.push_back(67); }
};

std::vector<std::uint8_t> concat(std::initializer_list<std::vector<std::uint8_t>> parts) {
  std::vector<std::uint8_t> out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

void set_length(std::vector<std::uint8_t>& b, std::size_t at, std::size_t len) {
  b[at + 8] = static_cast<std::uint8_t>(len >> 8);
  b[at + 9] = static_cast<std::uint8_t>(len);
}

// One rejection: walks `d` and returns the counters.
net::Counters walk(const std::vector<std::uint8_t>& d, std::size_t* delivered = nullptr) {
  net::DatagramParser parser;
  net::Counters c;
  Seen seen;
  const auto n = parser.parse(d, c, seen);
  if (delivered) *delivered = n;
  return c;
}

}  // namespace

TEST(Datagram, FivePduTypesInOneDatagramInOrder) {
  const auto d = concat({bytes_of(sample_entity_state(2)), bytes_of(sample_fire()),
                         bytes_of(sample_detonation(1)), bytes_of(sample_collision()),
                         bytes_of(sample_esu(0))});
  net::DatagramParser parser;
  net::Counters c;
  Seen seen;
  EXPECT_EQ(parser.parse(d, c, seen), 5u);
  EXPECT_EQ(seen.order, (std::vector<int>{1, 2, 3, 4, 67}));
  EXPECT_EQ(c.decoded_total(), 5u);
  EXPECT_EQ(c.decoded[67], 1u);
  EXPECT_EQ(c.pdus_seen, 5u);
  EXPECT_EQ(c.datagrams_received, 1u);
}

TEST(Datagram, VisitorMayHandleOnlySomeTypes) {
  const auto d = concat({bytes_of(sample_entity_state(0)), bytes_of(sample_fire()),
                         bytes_of(sample_fire())});
  net::DatagramParser parser;
  net::Counters c;
  int fires = 0;
  parser.parse(d, c, [&](const net::FirePdu& f) { fires += f.range == 1500.0f; });
  EXPECT_EQ(fires, 2);
  EXPECT_EQ(c.decoded_total(), 3u);
}

TEST(Datagram, BuilderPacksUpToItsLimit) {
  net::DatagramBuilder b(1400);
  auto es = sample_entity_state(0);
  int added = 0;
  while (b.add(es) && added < 100) ++added;
  EXPECT_EQ(added, 9);  // 9 x 144 = 1296 <= 1400 < 1440
  EXPECT_EQ(b.bytes().size(), 1296u);
  std::size_t delivered = 0;
  const std::vector<std::uint8_t> d(b.bytes().begin(), b.bytes().end());
  walk(d, &delivered);
  EXPECT_EQ(delivered, 9u);
}

TEST(Datagram, UnknownTypeAndVersionAreSkippedByLength) {
  auto other = bytes_of(sample_fire());
  other[2] = 20;  // Data PDU: not ours
  auto v4 = bytes_of(sample_collision());
  v4[0] = 4;  // DIS 4 (1278.1-1993 draft): not ours; 5, 6 and 7 are
  const auto d = concat({other, v4, bytes_of(sample_fire())});
  std::size_t n = 0;
  const auto c = walk(d, &n);
  EXPECT_EQ(n, 1u);
  EXPECT_EQ(c.skipped_unknown_type, 1u);
  EXPECT_EQ(c.skipped_version, 1u);
  EXPECT_EQ(c.decoded[2], 1u);
  EXPECT_EQ(c.rejected_total(), 0u);
}

TEST(Datagram, RejectTruncatedHeader) {
  auto d = bytes_of(sample_fire());
  d.resize(96 + 7, 0);  // 7 stray octets after a good PDU
  std::size_t n = 0;
  const auto c = walk(d, &n);
  EXPECT_EQ(n, 1u);
  EXPECT_EQ(c.rejected_for(net::DecodeError::TruncatedHeader), 1u);
}

TEST(Datagram, RejectLengthBelowHeaderAndStop) {
  auto d = concat({bytes_of(sample_fire()), bytes_of(sample_fire())});
  set_length(d, 0, 4);
  std::size_t n = 0;
  const auto c = walk(d, &n);
  EXPECT_EQ(n, 0u);  // cannot walk past it: the second Fire is not reached
  EXPECT_EQ(c.rejected_for(net::DecodeError::LengthBelowHeader), 1u);
  EXPECT_EQ(c.pdus_seen, 1u);
}

TEST(Datagram, RejectLengthExceedsData) {
  auto d = bytes_of(sample_entity_state(2));
  d.resize(d.size() - 1);  // truncated in transit
  const auto c = walk(d);
  EXPECT_EQ(c.rejected_for(net::DecodeError::LengthExceedsData), 1u);
  EXPECT_EQ(c.decoded_total(), 0u);
}

TEST(Datagram, RejectTooShortForTypeAndContinue) {
  auto es = bytes_of(sample_entity_state(0));
  es.resize(100);
  set_length(es, 0, 100);  // consistent with the data, too short for an Entity State
  auto col = bytes_of(sample_collision());
  col.resize(40);
  set_length(col, 0, 40);
  const auto d = concat({es, col, bytes_of(sample_fire())});
  std::size_t n = 0;
  const auto c = walk(d, &n);
  EXPECT_EQ(c.rejected_for(net::DecodeError::TooShortForType), 2u);
  EXPECT_EQ(n, 1u);  // the Fire after them still arrives
}

TEST(Datagram, RejectVariableCountMismatch) {
  auto more = bytes_of(sample_entity_state(2));
  more[19] = 3;  // says 3 records, length holds 2
  auto fewer = bytes_of(sample_detonation(2));
  fewer[101] = 1;  // says 1 record, length holds 2
  auto esu = bytes_of(sample_esu(1));
  esu[19] = 200;
  const auto d = concat({more, fewer, esu, bytes_of(sample_collision())});
  std::size_t n = 0;
  const auto c = walk(d, &n);
  EXPECT_EQ(c.rejected_for(net::DecodeError::VariableCountMismatch), 3u);
  EXPECT_EQ(n, 1u);
}

TEST(Datagram, RejectLengthMismatchOfFixedSizeTypes) {
  auto fire = bytes_of(sample_fire());
  fire.resize(104, 0);
  set_length(fire, 0, 104);
  auto col = bytes_of(sample_collision());
  col.resize(64, 0);
  set_length(col, 0, 64);
  const auto c = walk(concat({fire, col}));
  EXPECT_EQ(c.rejected_for(net::DecodeError::LengthMismatch), 2u);
}

TEST(Datagram, ExerciseFilterAndOwnEcho) {
  auto mine = sample_entity_state(0);  // site 11, app 22: "ours"
  auto theirs = sample_entity_state(0);
  theirs.entity_id = {11, 23, 1};      // same site, other application: not ours
  auto other_ex = sample_fire();
  other_ex.header.exercise_id = 3;
  auto my_fire = sample_fire();         // firing entity 11:22:33 -> ours
  const auto d = concat({bytes_of(mine), bytes_of(theirs), bytes_of(other_ex), bytes_of(my_fire)});
  net::DatagramParser parser(net::ReceiveFilter{true, 9, true, 11, 22});
  net::Counters c;
  std::vector<net::EntityId> got;
  parser.parse(d, c, [&](const net::EntityStatePdu& p) { got.push_back(p.entity_id); });
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0], (net::EntityId{11, 23, 1}));
  EXPECT_EQ(c.own_echo_ignored, 2u);
  EXPECT_EQ(c.other_exercise_ignored, 1u);
  EXPECT_EQ(c.decoded_total(), 1u);
  const std::string s = c.summary();
  EXPECT_NE(s.find("own_echo=2"), std::string::npos) << s;
  EXPECT_NE(s.find("other_exercise=1"), std::string::npos) << s;
  EXPECT_NE(s.find("entity_state=1"), std::string::npos) << s;
}

// Issue 11: a datagram we did not send (not our echo) with our (site, application): another
// simulator using our identity (own_id_clash, ignored), except a Detonation of one of our rounds
// or a Collision PDU one of our vehicles issued, which is another node repeating it after our
// process restarted (adoption): delivered.
TEST(Datagram, NotOurEchoIsAClashExceptARepeatedDetonationOrCollisionOfOurs) {
  const auto d = concat({bytes_of(sample_entity_state(0)), bytes_of(sample_fire()), bytes_of(sample_detonation(1)),
                         bytes_of(sample_collision())});
  net::DatagramParser parser(net::ReceiveFilter{true, 9, true, 11, 22});  // 11:22 ours
  for (const bool echo : {true, false}) {
    SCOPED_TRACE(echo ? "our echo" : "not our echo");
    parser.set_echo(echo);
    net::Counters c;
    int detonations = 0, collisions = 0, others = 0;
    parser.parse(d, c,
                 net::Overloaded{[&](const net::DetonationPdu& p) {
                                   EXPECT_EQ(p.firing_entity_id, (net::EntityId{11, 22, 33}));
                                   ++detonations;
                                 },
                                 [&](const net::CollisionPdu& p) {
                                   EXPECT_EQ(p.issuing_entity_id, (net::EntityId{11, 22, 33}));
                                   ++collisions;
                                 },
                                 [&](const net::EntityStatePdu&) { ++others; }, [&](const net::FirePdu&) { ++others; }});
    EXPECT_EQ(others, 0);
    EXPECT_EQ(detonations, echo ? 0 : 1);
    EXPECT_EQ(collisions, echo ? 0 : 1);
    EXPECT_EQ(echo ? c.own_echo_ignored : c.own_id_clash, echo ? 4u : 2u);
  }
}

TEST(Datagram, CountersSummaryNamesRejections) {
  auto d = bytes_of(sample_entity_state(1));
  d[19] = 0;
  const auto c = walk(d);
  EXPECT_NE(c.summary().find("variable_count_mismatch=1"), std::string::npos) << c.summary();
}

// 100,000 random and mutated datagrams: no crash, the walk ends, every PDU counted exactly once.
TEST(DatagramFuzz, HundredThousandRandomAndMutatedDatagrams) {
  std::mt19937_64 rng(20261123);
  const std::vector<std::vector<std::uint8_t>> seeds = {
      bytes_of(sample_entity_state(0)), bytes_of(sample_entity_state(3)), bytes_of(sample_fire()),
      bytes_of(sample_detonation(2)),   bytes_of(sample_collision()),     bytes_of(sample_esu(1)),
      concat({bytes_of(sample_fire()), bytes_of(sample_collision()), bytes_of(sample_esu(0))})};
  net::DatagramParser parser;
  net::Counters c;
  std::vector<std::uint8_t> d;
  std::uint64_t delivered = 0;
  // Whatever decodes also goes through the remote table (NaN/inf poses must not crash it).
  net::RemoteEntityTable table;
  double now = 0;
  struct Apply {
    net::RemoteEntityTable& table;
    double& now;
    void operator()(const net::EntityStatePdu& p) { table.apply(p, now); }
    void operator()(const net::EntityStateUpdatePdu& p) { table.apply(p, now); }
    void operator()(const net::FirePdu&) {}
    void operator()(const net::DetonationPdu&) {}
    void operator()(const net::CollisionPdu&) {}
  };
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < 100000; ++i) {
    const int mode = static_cast<int>(rng() % 4);
    if (mode == 0) {  // pure noise, sometimes with a plausible version/type prefix
      d.resize(rng() % 1500);
      for (auto& b : d) b = static_cast<std::uint8_t>(rng());
      if (d.size() >= 3 && rng() % 2) d[0] = 7, d[2] = static_cast<std::uint8_t>(1 + rng() % 4);
    } else {  // a valid datagram with flips, truncation, extension, or length/count edits
      d = seeds[rng() % seeds.size()];
      const int flips = 1 + static_cast<int>(rng() % 8);
      for (int k = 0; k < flips; ++k) {
        const std::size_t at = rng() % d.size();
        switch (rng() % 5) {
          case 0: d[at] ^= static_cast<std::uint8_t>(1u << (rng() % 8)); break;
          case 1: d[at] = static_cast<std::uint8_t>(rng()); break;
          case 2: d[8] = static_cast<std::uint8_t>(rng()), d[9] = static_cast<std::uint8_t>(rng()); break;
          case 3: d[19 % d.size()] = static_cast<std::uint8_t>(rng()); break;
          case 4: d[at] = 0; break;
        }
      }
      if (mode == 2) d.resize(rng() % (d.size() + 1));
      if (mode == 3) d.resize(d.size() + rng() % 64, static_cast<std::uint8_t>(rng()));
    }
    const auto before = c.pdus_seen;
    delivered += parser.parse(d, c, Apply{table, now});
    now += 0.01;
    if (i % 100 == 0) {
      for (std::size_t k = 0; k < table.size(); ++k) (void)table.displayed_pose(k, now);
      table.expire(now);
    }
    // Each step consumes >= 12 octets, so at most size/12 + 1 PDUs per datagram.
    ASSERT_LE(c.pdus_seen - before, d.size() / 12 + 1) << "iteration " << i;
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(c.datagrams_received, 100000u);
  // Every PDU seen lands in exactly one bucket.
  EXPECT_EQ(c.pdus_seen, c.decoded_total() + c.skipped_unknown_type + c.skipped_version +
                             c.rejected_total() + c.own_echo_ignored + c.other_exercise_ignored);
  EXPECT_EQ(delivered, c.decoded_total());
  EXPECT_GT(c.decoded_total(), 0u);
  EXPECT_GT(c.rejected_total(), 0u);
  std::printf("fuzz: %.2f s, remote entities left %zu, %s\n", secs, table.size(), c.summary().c_str());
}
