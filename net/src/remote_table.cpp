// remote_table.cpp — remote entities: join, update with smoothing, timeout.
#include "net/remote_table.hpp"

#include <algorithm>
#include <cmath>

#include "net/timestamp.hpp"

namespace net {
namespace {

// 0 at t = start, 1 at start + blend; smoothstep so the displayed velocity has no jump either.
double blend_weight(double now_s, double start_s, double blend_s) {
  if (blend_s <= 0) return 1.0;
  const double u = std::clamp((now_s - start_s) / blend_s, 0.0, 1.0);
  return u * u * (3.0 - 2.0 * u);
}

}  // namespace

std::optional<std::size_t> RemoteEntityTable::find(const EntityId& id) const {
  auto it = index_.find(id);
  if (it == index_.end()) return std::nullopt;
  return it->second;
}

void RemoteEntityTable::remove_at(std::size_t i) {
  index_.erase(entities_[i].id);
  if (i + 1 != entities_.size()) {
    entities_[i] = std::move(entities_.back());
    index_[entities_[i].id] = i;
  }
  entities_.pop_back();
}

bool RemoteEntityTable::remove(const EntityId& id) {
  auto i = find(id);
  if (!i) return false;
  remove_at(*i);
  return true;
}

namespace {
double wrap_half_hour(double d) {
  d = std::fmod(d, 3600.0);
  if (d >= 1800.0) d -= 3600.0;
  if (d < -1800.0) d += 3600.0;
  return d;
}
}  // namespace

void RemoteEntityTable::stamp(RemoteEntity& e, std::uint32_t ts, double now_s, double unix_now_s) {
  const DecodedTimestamp d = decode_timestamp(ts);
  if (d.absolute && unix_now_s >= 0 && std::isfinite(unix_now_s)) {
    const double age = wrap_half_hour(std::fmod(unix_now_s, 3600.0) - d.seconds_past_hour);
    if (age >= -kMaxStateAgeS && age <= kMaxStateAgeS) {
      e.state_s = now_s - std::max(0.0, age);
      return;
    }
  }
  // A clock that does not advance (many senders leave the timestamp 0) tells nothing.
  if (e.updates > 0 && timestamp_difference(ts, e.last_timestamp) <= 0) {
    e.state_s = now_s;
    return;
  }
  // Relative (or an absolute clock we disagree with): delay beyond the least delayed PDU's.
  const double cand = now_s - d.seconds_past_hour;
  double excess = 0;
  if (e.has_clock_offset) excess = wrap_half_hour(cand - e.clock_offset_s);
  if (!e.has_clock_offset || excess < 0 || excess > kClockJumpS) {
    e.clock_offset_s = cand;  // a less delayed PDU, the first one, or a restarted clock
    e.has_clock_offset = true;
    excess = 0;
  } else {
    e.clock_offset_s += 0.01 * excess;  // follow a sender clock that runs slow
  }
  e.state_s = now_s - std::min(excess, kMaxStateAgeS);
}

void RemoteEntityTable::start_blend(RemoteEntity& e, const Pose& shown, double now_s) const {
  const Pose track = dead_reckon(e.state, e.algorithm, now_s - e.state_s);
  e.blend_offset = shown.position - track.position;
  e.blend_rotation = to_quaternion(shown.orientation) * to_quaternion(track.orientation).inverse();
  e.blend_start_s = now_s;
}

RemoteEntityTable::ApplyResult RemoteEntityTable::apply(const EntityStatePdu& p, double now_s, double unix_now_s) {
  auto found = find(p.entity_id);
  if (p.appearance & kAppearanceDeactivated) {
    if (!found) return ApplyResult::Ignored;
    remove_at(*found);
    return ApplyResult::Deactivated;
  }
  const bool joined = !found;
  std::size_t i;
  Pose shown;
  if (joined) {
    i = entities_.size();
    entities_.emplace_back();
    index_.emplace(p.entity_id, i);
  } else {
    i = *found;
    shown = displayed_pose(i, now_s);
  }
  RemoteEntity& e = entities_[i];
  e.id = p.entity_id;
  e.type = p.entity_type;
  e.force_id = p.force_id;
  e.marking = p.marking;
  e.appearance = p.appearance;
  e.exercise_id = p.header.exercise_id;
  e.algorithm = dr_algorithm_from_wire(p.dead_reckoning.algorithm);
  e.state = kinematic_state(p);
  e.last_update_s = now_s;
  if (joined) e.has_clock_offset = false, e.updates = 0;
  stamp(e, p.header.timestamp, now_s, unix_now_s);
  e.last_timestamp = p.header.timestamp;
  ++e.updates;
  e.variable_parameters.assign(p.variable_parameters.begin(), p.variable_parameters.end());
  if (joined) {
    e.blend_offset.setZero();
    e.blend_rotation.setIdentity();
    e.blend_start_s = now_s;
  } else {
    start_blend(e, shown, now_s);
  }
  return joined ? ApplyResult::Joined : ApplyResult::Updated;
}

RemoteEntityTable::ApplyResult RemoteEntityTable::apply(const EntityStateUpdatePdu& p, double now_s,
                                                        double unix_now_s) {
  auto found = find(p.entity_id);
  if (!found) return ApplyResult::Ignored;
  if (p.appearance & kAppearanceDeactivated) {
    remove_at(*found);
    return ApplyResult::Deactivated;
  }
  const Pose shown = displayed_pose(*found, now_s);
  RemoteEntity& e = entities_[*found];
  // ESU carries velocity, location, orientation; acceleration and body rates are kept.
  e.state.position = {p.location.x, p.location.y, p.location.z};
  e.state.velocity = {p.linear_velocity.x, p.linear_velocity.y, p.linear_velocity.z};
  e.state.orientation = {p.orientation.psi, p.orientation.theta, p.orientation.phi};
  e.appearance = p.appearance;
  e.last_update_s = now_s;
  stamp(e, p.header.timestamp, now_s, unix_now_s);
  e.last_timestamp = p.header.timestamp;
  ++e.updates;
  e.variable_parameters.assign(p.variable_parameters.begin(), p.variable_parameters.end());
  start_blend(e, shown, now_s);
  return ApplyResult::Updated;
}

Pose RemoteEntityTable::dead_reckoned_pose(std::size_t i, double now_s) const noexcept {
  const RemoteEntity& e = entities_[i];
  return dead_reckon(e.state, e.algorithm, now_s - e.state_s);
}

Pose RemoteEntityTable::displayed_pose(std::size_t i, double now_s) const noexcept {
  const RemoteEntity& e = entities_[i];
  Pose track = dead_reckoned_pose(i, now_s);
  const double w = blend_weight(now_s, e.blend_start_s, thresholds_.blend_s);
  if (w >= 1.0) return track;
  track.position += (1.0 - w) * e.blend_offset;
  const Eigen::Quaterniond residual =
      Eigen::Quaterniond::Identity().slerp(1.0 - w, e.blend_rotation);
  track.orientation = to_euler(residual * to_quaternion(track.orientation));
  return track;
}

}  // namespace net
