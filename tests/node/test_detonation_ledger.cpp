// DetonationLedger (node/repeat_ledger.hpp): a received round is applied once; a round of
// another NPSNET node is adopted by the lowest live holder when nobody has repeated it for
// (2 + rank) heartbeats; an adopter stands down when it hears the round from someone else.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "node/repeat_ledger.hpp"

namespace {
using npsnet::node::DetonationLedger;

net::DetonationPdu round_of(std::uint16_t app, std::uint16_t event) {
  net::DetonationPdu p;
  p.firing_entity_id = {1, app, 1};
  p.event_id = {1, app, event};
  p.location = {-2700000.0, -4300000.0, 3700000.0 + event};
  return p;
}

struct Sends {
  int n = 0;
  std::function<void(const net::DetonationPdu&, std::uint32_t)> f() {
    return [this](const net::DetonationPdu&, std::uint32_t) { ++n; };
  }
};
constexpr double kHb = 5.0, kLive = 12.0;
}  // namespace

TEST(DetonationLedger, ReceivedOnceWhoeverRepeatsIt) {
  DetonationLedger l;
  l.set_identity(1, 2);
  const auto r = round_of(1, 7);
  EXPECT_TRUE(l.received(r, 1.0, true, 0));
  EXPECT_FALSE(l.received(r, 1.1, true, 0));  // a duplicated datagram
  EXPECT_FALSE(l.received(r, 6.0, true, 0));  // the firing node's repeat
  EXPECT_EQ(l.repeats_ignored(), 2u);
  EXPECT_TRUE(l.received(round_of(1, 8), 6.0, false, 0));  // another round
}

TEST(DetonationLedger, NoAdoptionWhileTheFiringNodeRepeats) {
  DetonationLedger l;
  l.set_identity(1, 2);
  Sends s;
  const auto r = round_of(1, 1);
  l.received(r, 0.0, true, 0);
  for (double t = 0; t <= 60.0; t += 0.1) {
    l.heard(1, 1, t), l.heard(1, 3, t);
    if (t > 0 && std::fmod(t + 1e-9, kHb) < 0.1) l.received(r, t, true, 0);  // the firer's heartbeat repeat
    l.resend_due(t, kHb, kLive, s.f());
  }
  EXPECT_EQ(s.n, 0);
  EXPECT_EQ(l.adoptions(), 0u);
}

TEST(DetonationLedger, LowestLiveHolderAdoptsAfterTwoHeartbeatsThenRepeatsEachHeartbeat) {
  DetonationLedger b, c;  // nodes (1,2) and (1,3) hold node (1,1)'s round; node 1 is silent
  b.set_identity(1, 2), c.set_identity(1, 3);
  const auto r = round_of(1, 1);
  b.received(r, 1.0, true, 0), c.received(r, 1.0, true, 0);
  Sends sb, sc;
  double first_b = -1;
  for (int i = 0; i <= 300; ++i) {
    const double t = 1.0 + 0.1 * i;
    b.heard(1, 3, t), c.heard(1, 2, t);
    if (t < 3.0) b.heard(1, 1, t), c.heard(1, 1, t);  // node 1 is killed at t = 3
    const int before = sb.n;
    b.resend_due(t, kHb, kLive, sb.f());
    if (sb.n > before) {
      if (first_b < 0) first_b = t;
      c.received(r, t, true, 0);  // c hears b's repeat
    }
    c.resend_due(t, kHb, kLive, sc.f());
  }
  EXPECT_NEAR(first_b, 1.0 + 2 * kHb, 0.11) << "rank 0: 2 heartbeats after it was last heard";
  EXPECT_EQ(sb.n, 5);  // t = 11, 16, 21, 26, 31
  EXPECT_EQ(sc.n, 0) << "node 3 (rank 1) hears node 2's repeats: it never adopts";
  EXPECT_EQ(b.adoptions(), 1u);
  EXPECT_EQ(b.rank(r.firing_entity_id, 30.0, kLive), 0);
  EXPECT_EQ(c.rank(r.firing_entity_id, 30.0, kLive), 1);
}

TEST(DetonationLedger, AnAdopterStandsDownWhenItHearsTheRoundFromSomeoneElse) {
  DetonationLedger b;
  b.set_identity(1, 2);
  const auto r = round_of(1, 1);
  b.received(r, 0.0, true, 0);
  Sends s;
  b.resend_due(10.0, kHb, kLive, s.f());
  EXPECT_EQ(s.n, 1);
  b.received(r, 12.0, true, 0);  // another adopter, or the firing node back
  b.resend_due(15.5, kHb, kLive, s.f());
  EXPECT_EQ(s.n, 1) << "watching again: quiet for less than 2 heartbeats";
  b.resend_due(22.0, kHb, kLive, s.f());
  EXPECT_EQ(s.n, 2);
  EXPECT_EQ(b.adoptions(), 2u);
}

TEST(DetonationLedger, RoundsOfOtherSimulatorsAreNeverRepeated) {
  DetonationLedger b;
  b.set_identity(1, 2);
  b.received(round_of(1, 1), 0.0, false, 0);  // not adoptable: not a scenario vehicle's round
  Sends s;
  for (double t = 0; t < 100; t += 1.0) b.resend_due(t, kHb, kLive, s.f());
  EXPECT_EQ(s.n, 0);
  EXPECT_EQ(b.kept(), 0u);
}

TEST(DetonationLedger, OwnRoundsRepeatTwiceQuicklyThenEachHeartbeat) {
  DetonationLedger a;
  a.set_identity(1, 1);
  std::vector<double> at;
  a.sent(round_of(1, 1), 0, 0.0);
  for (int tick = 0; tick <= 205; ++tick) {
    const double t = tick * 0.1;
    a.resend_due(t, kHb, kLive, [&](const net::DetonationPdu&, std::uint32_t) { at.push_back(t); });
  }
  // Two quick repeats kQuickGapS apart, then a heartbeat after the last sending: t ~ 0.5, 1.0, 6, 11, 16.
  const std::vector<double> want = {0.5, 1.0, 6.0, 11.0, 16.0};
  ASSERT_EQ(at.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(at[i], want[i], 0.11) << i;
  EXPECT_EQ(a.repeats_sent(), 5u);
  EXPECT_FALSE(a.received(round_of(1, 1), 21.0, true, 0));  // an adopter's repeat of ours: not new
}

TEST(DetonationLedger, QuickRepeatsNeverComeSlowerThanTheHeartbeat) {
  DetonationLedger a;  // a heartbeat shorter than kQuickGapS (a test's short DIS timeout)
  a.set_identity(1, 1);
  std::vector<double> at;
  a.sent(round_of(1, 1), 0, 0.0);
  for (int tick = 0; tick <= 10; ++tick) {
    const double t = tick * 0.1;
    a.resend_due(t, 0.3, 0.72, [&](const net::DetonationPdu&, std::uint32_t) { at.push_back(t); });
  }
  const std::vector<double> want = {0.3, 0.6, 0.9};
  ASSERT_EQ(at.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(at[i], want[i], 0.11) << i;
}
