// Net out's local-frame dead-reckoning bound (node/dr_bound.hpp, issue 13): its constants hold on
// the default world's frame, and a crowd sends exactly the Entity States (same digest of ids,
// kinematics, appearance, timestamps) with the bound as when every vehicle is turned into ECEF
// every tick, on 1 and 2 threads, capped (one PDU a datagram) and packed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "node/dr_bound.hpp"
#include "node/net_bridge.hpp"
#include "node/pdu_build.hpp"
#include "node/simulation.hpp"
#include "support/fixture.hpp"
#include "support/scratch.hpp"

using namespace npsnet;

namespace {

const world::Scenario& crowd_scenario() {
  static const world::Scenario sc = test::default_with_crowd(2000, 7, Vec2(20000, 30000), Vec2(23000, 33000));
  return sc;
}

const world::World& crowd_world() {
  static const world::World w = world::build_world(crowd_scenario());
  return w;
}

struct Sent {
  std::uint64_t digest = 0, exact_tests = 0, entity_states = 0;  // ground vehicles' Entity States
};

// damage: at ticks 20 and 26 (the send cap still defers: first Entity States and their quick
// repeats), every 37th local ground vehicle is damaged one state further.
Sent run(bool prefilter, int threads, bool pack, int ticks, bool damage = false) {
  if (pack) ::setenv("NPSNET_DIS_PACK", "1", 1);
  else ::unsetenv("NPSNET_DIS_PACK");
  const auto file = test::scratch_dir() / ("dr-bound-" + std::to_string(prefilter) + std::to_string(threads) + ".jsonl");
  node::EventLog log(file);
  node::Simulation sim(crowd_world(), crowd_scenario(), log, 0.1);
  sim.set_threads(threads, threads > 1 ? 1 : 0);
  node::BridgeOptions bo;
  bo.offline = true;
  bo.dr_prefilter = prefilter;
  node::NetBridge bridge(bo, sim, log);
  bridge.attach();
  for (int i = 0; i < ticks; ++i) {
    if (damage && (i == 20 || i == 26)) {
      const world::World& w = sim.world();
      world::Changes c;
      for (int e = 0; e < static_cast<int>(w.ents.size()); e += 37)
        if (w.ents.local[e] && w.kinds[w.ents.kind[e]].mobility == world::Mobility::Ground &&
            w.ents.state[e] + 1 < static_cast<int>(w.kinds[w.ents.kind[e]].states.size()))
          c.entities.push_back(world::EntityChange{.entity = e, .to_state = w.ents.state[e] + 1});
      sim.inject(c);
    }
    sim.tick();
  }
  ::unsetenv("NPSNET_DIS_PACK");
  return {bridge.entity_state_digest(), bridge.exact_dr_tests(), bridge.ground_es_sent()};
}

}  // namespace

// K (curvature of the local -> ECEF map) and Kf (turn of the level frame per metre) bound what
// they claim over the whole 50 km map, up to the anchor distance.
TEST(DrBound, CurvatureAndFrameTurnBoundsHoldOnTheDefaultWorld) {
  const auto& frame = crowd_world().terrain.frame();
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> map(0, 50000), off(-1, 1), hgt(0, 3000), ang(-180, 180);
  double worst_pos = 0, worst_rot = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 pc(map(rng), map(rng), hgt(rng));
    Vec3 d(off(rng), off(rng), off(rng));
    d *= node::kMaxAnchorDistM * std::abs(off(rng)) / d.norm();
    const Vec3 pe = frame.to_ecef(pc);
    Mat3 jac;
    for (int c = 0; c < 3; ++c) jac.col(c) = frame.to_ecef(pc + Vec3::Unit(c)) - pe;
    const double nd = d.norm();
    const double lin = (frame.to_ecef(pc + d) - pe - jac * d).norm();
    const double pos_bound = 0.5 * node::kCurvaturePerM * nd * nd + node::kCurvaturePerM * nd;
    EXPECT_LE(lin, pos_bound) << "at " << pc.transpose() << " d " << d.transpose();
    // The anchors' Jacobian (the derivative, exact_state) needs only the curvature term.
    const double lin_exact = (frame.to_ecef(pc + d) - pe - frame.jacobian(frame.to_geodetic(pc)) * d).norm();
    EXPECT_LE(lin_exact, 0.5 * node::kCurvaturePerM * nd * nd + node::kBoundEpsM) << "at " << pc.transpose();
    worst_pos = std::max(worst_pos, lin / pos_bound);
    const double h = ang(rng), p = ang(rng) / 4, r = ang(rng) / 4;
    const Vec3 a = frame.to_dis_euler(pc, h, p, r), b = frame.to_dis_euler(pc + d, h, p, r);
    const double turn = net::orientation_error_rad({a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()});
    EXPECT_LE(turn, node::kFrameTurnPerM * nd + node::kBoundEpsRad) << "at " << pc.transpose() << " d " << d.transpose();
    worst_rot = std::max(worst_rot, turn / (node::kFrameTurnPerM * nd + node::kBoundEpsRad));
  }
  std::printf("worst share of the bound used: position %.3f, orientation %.3f\n", worst_pos, worst_rot);
}

// The bound as net out reads it (DrQuick: the position term in the local frame) says quiet only
// when the exact test says None: a vehicle anywhere on the map sends its state (with a little
// acceleration and yaw rate), then goes on near that track, with up to two exact tests between
// that send nothing (the anchor moves on), and is checked at the end.
TEST(DrBound, QuietOnlyWhenTheExactTestSaysNone) {
  world::World w = crowd_world();
  const net::DrThresholds th = node::dr_thresholds(node::BridgeOptions{}.timeout_s);
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> map(1000, 49000), u(-1, 1), gap(0, 2.4);
  int e = 0;
  while (w.kinds[w.ents.kind[e]].mobility != world::Mobility::Ground) ++e;
  auto& ents = w.ents;
  int quiet = 0, none = 0;
  const int cases = 20000;
  for (int k = 0; k < cases; ++k) {
    const double x = map(rng), y = map(rng);
    ents.pos[e] = Vec3(x, y, w.terrain.height(x, y));
    ents.heading_deg[e] = static_cast<float>(180 * u(rng));
    ents.pitch_deg[e] = static_cast<float>(10 * u(rng)), ents.roll_deg[e] = static_cast<float>(10 * u(rng));
    ents.vel[e] = Vec3(15 * u(rng), 15 * u(rng), 0.5 * u(rng));
    net::DrPublisher pub(net::DrAlgorithm::RVW, th);
    node::DrAnchor a;
    double t = 10 + gap(rng);
    net::KinematicState s = node::exact_state(w, e, a);
    s.acceleration = a.jac * Vec3(0.02 * u(rng), 0.02 * u(rng), 0.005 * u(rng));
    s.angular_velocity = Vec3(0, 0, 0.01 * u(rng));
    pub.mark_sent(s, t);
    node::dr_rebase(s, pub, t, a);
    const int steps = 1 + static_cast<int>(rng() % 3);
    for (int j = 0; j < steps; ++j) {
      const double dt = gap(rng);
      t += dt;
      ents.pos[e] += ents.vel[e] * dt + Vec3(u(rng), u(rng), u(rng)) * 0.5;
      ents.heading_deg[e] += static_cast<float>(0.4 * u(rng));
      ents.pitch_deg[e] += static_cast<float>(0.4 * u(rng)), ents.roll_deg[e] += static_cast<float>(0.4 * u(rng));
      if (j + 1 < steps) node::dr_rebase(node::exact_state(w, e, a), pub, t, a);
    }
    const bool q = node::dr_quiet(node::dr_quick(a, pub), w, e, t);
    const auto reason = pub.needs_update(node::entity_truth(w, e), t);
    none += reason == net::DrPublisher::Reason::None;
    if (!q) continue;
    ++quiet;
    ASSERT_EQ(reason, net::DrPublisher::Reason::None) << "case " << k << " at " << ents.pos[e].transpose() << ", t " << t;
  }
  std::printf("%d cases: the exact test says None in %d, the bound says quiet in %d\n", cases, none, quiet);
  EXPECT_GT(quiet, cases / 10) << "the bound should clear a good share of the vehicles near their track";
  EXPECT_GT(quiet * 2, none) << "and most of those the exact test clears";
}

// DrQuick keeps floats (two cache lines): what a float adds to the bound is rounded up and a limit
// down, and a value beyond the floats' range leaves the bound unusable (never quiet).
TEST(DrBound, QuickFloatsRoundTheSafeWayAndOverflowIsNeverQuiet) {
  const world::World& w = crowd_world();
  int e = 0;
  while (w.kinds[w.ents.kind[e]].mobility != world::Mobility::Ground) ++e;
  const net::DrThresholds th{0.7, 0.1, 4.7};  // (position m, orientation rad, heartbeat s: not floats)
  for (const double theta : {0.1, 0.7, 1.0 / 3, 0.0}) {
    for (const double rate : {0.3, 0.7, 0.0}) {
      node::DrAnchor a;
      a.jac = Mat3::Identity(), a.p = w.ents.pos[e], a.err = Vec3(0.1, -0.7, 1.0 / 3), a.t = 10, a.theta = theta;
      a.heading = w.ents.heading_deg[e], a.pitch = w.ents.pitch_deg[e], a.roll = w.ents.roll_deg[e], a.valid = true;
      net::DrPublisher pub(net::DrAlgorithm::RVW, th);
      net::KinematicState s;
      s.velocity = Vec3(0.7, 0.1, 0), s.angular_velocity = Vec3(0, 0, rate);
      pub.mark_sent(s, 10);
      const node::DrQuick q = node::dr_quick(a, pub);
      ASSERT_TRUE(q.usable);
      EXPECT_GE(double(q.theta), theta);
      EXPECT_GE(double(q.turn_rate), pub.sent_state().angular_velocity.norm());  // (as sent: DIS floats)
      EXPECT_GE(double(q.sigma), 1.0);
      EXPECT_LE(double(q.pos_limit), th.position_threshold_m);
      EXPECT_LE(double(q.rot_limit), th.orientation_threshold_rad);
      EXPECT_LE(double(q.heartbeat_s), th.heartbeat_s);
    }
  }
  for (const double huge : {1e39, -1e300}) {  // an anchor error beyond a float
    node::DrAnchor a;
    a.jac = Mat3::Identity(), a.p = w.ents.pos[e], a.err = Vec3(0, huge, 0), a.t = 10, a.valid = true;
    a.heading = w.ents.heading_deg[e], a.pitch = w.ents.pitch_deg[e], a.roll = w.ents.roll_deg[e];
    net::DrPublisher pub(net::DrAlgorithm::RVW, th);
    pub.mark_sent(net::KinematicState{}, 10);
    const node::DrQuick q = node::dr_quick(a, pub);
    EXPECT_FALSE(q.usable) << huge;
    EXPECT_FALSE(node::dr_quiet(q, w, e, 10.05)) << huge;
  }
}

TEST(DrBound, CrowdSendsTheSameEntityStatesAsTheExactTestEveryTick) {
  const int ticks = 150;  // 15 s: three heartbeats, turns, collisions
  const Sent exact = run(false, 1, false, ticks);
  const Sent fast = run(true, 1, false, ticks);
  const Sent fast2 = run(true, 2, false, ticks);
  std::printf("capped: %llu Entity States; ECEF turns: exact %llu, with the bound %llu\n",
              static_cast<unsigned long long>(exact.entity_states), static_cast<unsigned long long>(exact.exact_tests),
              static_cast<unsigned long long>(fast.exact_tests));
  EXPECT_EQ(fast.entity_states, exact.entity_states);
  EXPECT_EQ(fast.digest, exact.digest);
  EXPECT_EQ(fast2.entity_states, exact.entity_states);
  EXPECT_EQ(fast2.digest, exact.digest);
  EXPECT_LT(fast.exact_tests * 5, exact.exact_tests) << "the bound should spare most vehicles their geodesy";

  const Sent pexact = run(false, 1, true, ticks);
  const Sent pfast = run(true, 2, true, ticks);
  std::printf("packed: %llu Entity States; ECEF turns: exact %llu, with the bound %llu\n",
              static_cast<unsigned long long>(pexact.entity_states), static_cast<unsigned long long>(pexact.exact_tests),
              static_cast<unsigned long long>(pfast.exact_tests));
  EXPECT_GT(pexact.entity_states, 2000u * 3) << "every vehicle at least at each heartbeat";
  EXPECT_LT(exact.entity_states, pexact.entity_states) << "the send cap (128 a tick) should defer some";
  EXPECT_EQ(pfast.entity_states, pexact.entity_states);
  EXPECT_EQ(pfast.digest, pexact.digest);
  EXPECT_LT(pfast.exact_tests * 3, pexact.exact_tests);
}

// Damage changes while the send cap defers go out at once, wherever the vehicle is in the round
// robin, as when every vehicle is turned into ECEF every tick: the per-vehicle pass flags the
// change (changed_) for the serial loop, which past the cap looks at nothing else.
TEST(DrBound, DamageChangesPastTheCapGoOutAtOnce) {
  const int ticks = 40;
  const Sent exact = run(false, 1, false, ticks, true);
  const Sent fast = run(true, 1, false, ticks, true);
  const Sent fast2 = run(true, 2, false, ticks, true);
  const Sent quiet = run(true, 1, false, ticks, false);
  EXPECT_EQ(fast.entity_states, exact.entity_states);
  EXPECT_EQ(fast.digest, exact.digest);
  EXPECT_EQ(fast2.entity_states, exact.entity_states);
  EXPECT_EQ(fast2.digest, exact.digest);
  EXPECT_GT(fast.entity_states, quiet.entity_states + 50) << "the damaged vehicles' Entity States (and repeats)";
}
