// Remote-entity table: join, update, dead-reckoned pose, smoothing without jumps, timeout.
#include <gtest/gtest.h>

#include <random>

#include "test_util.hpp"

using Eigen::Vector3d;
using Apply = net::RemoteEntityTable::ApplyResult;

namespace {

net::EntityStatePdu es_at(net::EntityId id, Vector3d pos, Vector3d vel, double psi = 0.0) {
  net::EntityStatePdu p;
  p.entity_id = id;
  p.entity_type = {1, 1, 225, 1, 1, 3, 0};
  p.marking = net::make_marking("remote" + std::to_string(id.entity)).value();
  net::KinematicState s;
  s.position = pos;
  s.velocity = vel;
  s.orientation.psi = psi;
  net::write_kinematics(s, net::DrAlgorithm::FPW, p);
  return p;
}

net::EntityStateUpdatePdu esu_at(net::EntityId id, Vector3d pos, Vector3d vel) {
  net::EntityStateUpdatePdu p;
  p.entity_id = id;
  p.location = {pos.x(), pos.y(), pos.z()};
  p.linear_velocity = {float(vel.x()), float(vel.y()), float(vel.z())};
  return p;
}

}  // namespace

TEST(RemoteTable, JoinUpdateFind) {
  net::RemoteEntityTable table;
  const net::EntityId a{1, 2, 3}, b{1, 2, 4};
  EXPECT_EQ(table.apply(es_at(a, {0, 0, 0}, {1, 0, 0}), 0.0), Apply::Joined);
  EXPECT_EQ(table.apply(es_at(b, {5, 0, 0}, {0, 0, 0}), 0.0), Apply::Joined);
  EXPECT_EQ(table.apply(es_at(a, {1, 0, 0}, {1, 0, 0}), 1.0), Apply::Updated);
  EXPECT_EQ(table.size(), 2u);
  auto i = table.find(a);
  ASSERT_TRUE(i);
  EXPECT_EQ(net::marking_text(table[*i].marking), "remote3");
  EXPECT_EQ(table[*i].updates, 2u);
  EXPECT_EQ(table[*i].algorithm, net::DrAlgorithm::FPW);
  EXPECT_FALSE(table.find({9, 9, 9}));
  // ESU: ignored for an unknown entity, an update for a known one.
  EXPECT_EQ(table.apply(esu_at({9, 9, 9}, {0, 0, 0}, {0, 0, 0}), 2.0), Apply::Ignored);
  EXPECT_EQ(table.apply(esu_at(b, {6, 0, 0}, {0, 0, 0}), 2.0), Apply::Updated);
  EXPECT_EQ(table.size(), 2u);
}

TEST(RemoteTable, DeadReckonedPoseFollowsTheTrack) {
  net::RemoteEntityTable table;
  table.apply(es_at({1, 1, 1}, {100, 200, 300}, {10, -2, 0}), 5.0);
  const auto i = *table.find({1, 1, 1});
  for (double t : {5.0, 5.5, 8.0}) {
    const auto p = table.dead_reckoned_pose(i, t);
    EXPECT_NEAR((p.position - Vector3d(100 + 10 * (t - 5), 200 - 2 * (t - 5), 300)).norm(), 0, 1e-9);
    // No correction yet: what is displayed is the DR pose.
    EXPECT_NEAR((table.displayed_pose(i, t).position - p.position).norm(), 0, 1e-12);
  }
}

TEST(RemoteTable, CorrectionConvergesSmoothlyWithoutJump) {
  net::DrThresholds th;
  th.blend_s = 0.5;
  net::RemoteEntityTable table(th);
  const net::EntityId id{1, 1, 1};
  table.apply(es_at(id, {0, 0, 0}, {10, 0, 0}, 0.0), 0.0);
  // At t = 2 the sender corrects: it is really 3 m to the north and heading 20 deg left.
  const double tu = 2.0;
  const auto i = *table.find(id);
  const auto before = table.displayed_pose(i, tu);
  table.apply(es_at(id, {20, 3, 0}, {10, 0, 0}, 20 * net::kDegToRad), tu);
  const auto j = *table.find(id);
  const auto at = table.displayed_pose(j, tu);
  // No jump at the update instant.
  EXPECT_NEAR((at.position - before.position).norm(), 0.0, 1e-9);
  EXPECT_NEAR(net::orientation_error_rad(at.orientation, before.orientation), 0.0, 1e-9);
  // Per 10 ms step, the displayed pose moves at most the track speed plus the blend's peak
  // rate (1.5 x offset / blend for smoothstep): no step anywhere is a jump.
  const double dt = 0.01, offset = 3.0;
  const double max_step = 10.0 * dt + 1.5 * offset / th.blend_s * dt + 1e-6;
  const double max_turn = 1.5 * (20 * net::kDegToRad) / th.blend_s * dt + 1e-6;
  auto prev = at;
  for (double t = tu + dt; t <= tu + 1.0 + 1e-9; t += dt) {
    const auto p = table.displayed_pose(j, t);
    EXPECT_LE((p.position - prev.position).norm(), max_step) << t;
    EXPECT_LE(net::orientation_error_rad(p.orientation, prev.orientation), max_turn) << t;
    prev = p;
  }
  // After the blend time the displayed pose is on the new dead-reckoned track.
  const auto after = table.displayed_pose(j, tu + 0.5);
  const auto track = table.dead_reckoned_pose(j, tu + 0.5);
  EXPECT_NEAR((after.position - track.position).norm(), 0.0, 1e-9);
  EXPECT_NEAR(net::orientation_error_rad(after.orientation, track.orientation), 0.0, 1e-9);
  // Halfway through the blend it is strictly between the old and new tracks.
  const auto mid = table.displayed_pose(j, tu + 0.25);
  EXPECT_GT(mid.position.y(), 0.1);
  EXPECT_LT(mid.position.y(), 2.9);
}

TEST(RemoteTable, UpdateDuringABlendStartsFromWhatIsShown) {
  net::RemoteEntityTable table;  // blend 0.5 s
  const net::EntityId id{1, 1, 1};
  table.apply(es_at(id, {0, 0, 0}, {0, 0, 0}), 0.0);
  table.apply(es_at(id, {0, 10, 0}, {0, 0, 0}), 1.0);
  const auto shown = table.displayed_pose(*table.find(id), 1.2);
  table.apply(es_at(id, {0, -10, 0}, {0, 0, 0}), 1.2);
  EXPECT_NEAR((table.displayed_pose(*table.find(id), 1.2).position - shown.position).norm(), 0, 1e-9);
}

TEST(RemoteTable, TimeoutAfterTwelveSecondsWithoutUpdate) {
  net::RemoteEntityTable table;  // timeout 12 s
  table.apply(es_at({1, 1, 1}, {0, 0, 0}, {0, 0, 0}), 0.0);
  table.apply(es_at({1, 1, 2}, {0, 0, 0}, {0, 0, 0}), 0.0);
  table.apply(es_at({1, 1, 2}, {0, 0, 0}, {0, 0, 0}), 6.0);  // heartbeat keeps 2 alive
  std::vector<std::string> gone;
  EXPECT_EQ(table.expire(12.0, [&](const net::RemoteEntity& e) { gone.push_back(net::marking_text(e.marking)); }), 0u);
  EXPECT_EQ(table.expire(12.01, [&](const net::RemoteEntity& e) { gone.push_back(net::marking_text(e.marking)); }), 1u);
  EXPECT_EQ(gone, std::vector<std::string>{"remote1"});
  EXPECT_EQ(table.size(), 1u);
  EXPECT_TRUE(table.find({1, 1, 2}));
  EXPECT_FALSE(table.find({1, 1, 1}));
  EXPECT_EQ(table.expire(18.01), 1u);
  EXPECT_EQ(table.size(), 0u);
}

TEST(RemoteTable, ConfigurableTimeoutAndDeactivation) {
  net::DrThresholds th;
  th.timeout_s = 1.0;
  net::RemoteEntityTable table(th);
  table.apply(es_at({1, 1, 1}, {0, 0, 0}, {0, 0, 0}), 0.0);
  table.apply(es_at({1, 1, 2}, {0, 0, 0}, {0, 0, 0}), 0.0);
  EXPECT_EQ(table.expire(1.5), 2u);
  table.apply(es_at({1, 1, 3}, {0, 0, 0}, {0, 0, 0}), 2.0);
  auto leave = es_at({1, 1, 3}, {0, 0, 0}, {0, 0, 0});
  leave.appearance |= net::kAppearanceDeactivated;
  EXPECT_EQ(table.apply(leave, 2.1), Apply::Deactivated);
  EXPECT_EQ(table.size(), 0u);
  EXPECT_EQ(table.apply(leave, 2.2), Apply::Ignored);  // not re-joined by its goodbye
}

TEST(RemoteTable, IndexStaysConsistentUnderChurn) {
  net::DrThresholds th;
  th.timeout_s = 3.0;
  net::RemoteEntityTable table(th);
  std::mt19937 rng(7);
  for (int step = 0; step < 2000; ++step) {
    const double now = step * 0.1;
    const std::uint16_t e = static_cast<std::uint16_t>(rng() % 50);
    table.apply(es_at({1, 1, e}, {double(e), 0, 0}, {0, 0, 0}), now);
    table.expire(now);
    for (std::size_t i = 0; i < table.size(); ++i) {
      auto f = table.find(table[i].id);
      ASSERT_TRUE(f);
      ASSERT_EQ(*f, i);
      ASSERT_EQ(table[i].state.position.x(), double(table[i].id.entity));
    }
  }
}
