// net/remote_table.hpp — remote entities heard on the network, dead-reckoned and smoothed.
// Contract:
//  * Keyed by EntityId (site, application, entity). apply(EntityStatePdu, now_s) adds or updates
//    an entity; apply(EntityStateUpdatePdu, now_s) updates a known one (unknown: Ignored, as the
//    ESU lacks type and marking). An ES whose appearance has the Deactivated bit (23) removes
//    the entity (Deactivated). `now_s` is the receiver's own clock in seconds (monotonic),
//    `unix_now_s` the receiver's UTC (UNIX seconds; NaN when unknown, e.g. a replay). A PDU is
//    never dropped for its timestamp.
//  * The time a received state is valid at (state_s, receiver clock) comes from its timestamp
//    (DIS7-NOTES "Annex C defaults"; IEEE 1278.1-2012 6.2.88):
//     - absolute (low bit 1, the sender's UTC past the hour): age = receiver's UTC past the hour
//       - timestamp (wrapped to +-30 min); used when 0 <= age <= kMaxStateAgeS (clocks agree),
//       a small negative age (clock skew) counts as 0;
//     - relative (low bit 0, the sender's own clock), or an absolute one our clock disagrees
//       with: the offset receiver clock - sender clock is the smallest seen for this entity (the
//       least delayed PDU; it follows a slower sender clock by 1 % of each excess), so that
//       age = the excess of this PDU's delay over that one's, at most kMaxStateAgeS; an offset
//       that moves by more than kClockJumpS (the sender restarted its clock) starts again;
//     - a timestamp that does not advance past the entity's previous one (senders that leave
//       it 0): no timing, age 0.
//     state_s = arrival - age.
//  * dead_reckoned_pose(i, now) extrapolates the last state with its DR algorithm from
//    state_s. displayed_pose(i, now) is what to draw: after an update, it starts at the pose
//    that was displayed at that moment and converges to the new dead-reckoned track over
//    blend_s (smoothstep weight), so it never jumps; after blend_s it equals the DR pose.
//  * expire(now, f) removes every entity with no update for more than timeout_s, calling
//    f(const RemoteEntity&) for each just before it goes.
//  * Entities live in one contiguous array; indices are valid until the next apply/expire.
//    A lookup map from id to index is kept; memory is allocated only when an entity joins (or
//    its variable parameters outgrow earlier ones).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include "net/dead_reckoning.hpp"
#include "net/pdu.hpp"

namespace net {

struct RemoteEntity {
  EntityId id;
  EntityType type;
  std::uint8_t force_id = 0;
  Marking marking;
  std::uint32_t appearance = 0;
  std::uint8_t exercise_id = 0;
  DrAlgorithm algorithm = DrAlgorithm::Static;
  KinematicState state;          // as received, valid at last_update_s
  double last_update_s = 0;      // receiver clock when the last update arrived
  double state_s = 0;            // receiver clock the received state is valid at (<= last_update_s)
  std::uint32_t last_timestamp = 0;  // DIS timestamp of that update
  double clock_offset_s = 0;     // receiver clock - sender's timestamp seconds (relative time)
  bool has_clock_offset = false;
  std::uint64_t updates = 0;
  std::vector<VariableParameter> variable_parameters;  // last received (articulated parts...)
  // Smoothing: displayed = DR + offset * (1 - w(t)), w: 0 -> 1 over blend_s from blend_start_s.
  Eigen::Vector3d blend_offset = Eigen::Vector3d::Zero();
  Eigen::Quaterniond blend_rotation = Eigen::Quaterniond::Identity();
  double blend_start_s = 0;
};

class RemoteEntityTable {
 public:
  enum class ApplyResult : std::uint8_t { Joined, Updated, Deactivated, Ignored };

  // Ages past this (s) are not believed: the state is taken as of its arrival minus this.
  static constexpr double kMaxStateAgeS = 1.0;
  // A relative-clock offset moving by more than this (s) means the sender's clock restarted.
  static constexpr double kClockJumpS = 5.0;

  explicit RemoteEntityTable(DrThresholds t = {}) : thresholds_(t) {}

  ApplyResult apply(const EntityStatePdu& p, double now_s, double unix_now_s = kNoUtc);
  ApplyResult apply(const EntityStateUpdatePdu& p, double now_s, double unix_now_s = kNoUtc);
  static constexpr double kNoUtc = -1.0;  // unix_now_s unknown

  template <class F>
  std::size_t expire(double now_s, F&& on_timeout) {
    std::size_t removed = 0;
    for (std::size_t i = entities_.size(); i-- > 0;) {
      if (now_s - entities_[i].last_update_s > thresholds_.timeout_s) {
        on_timeout(static_cast<const RemoteEntity&>(entities_[i]));
        remove_at(i);
        ++removed;
      }
    }
    return removed;
  }
  std::size_t expire(double now_s) {
    return expire(now_s, [](const RemoteEntity&) {});
  }
  bool remove(const EntityId& id);

  std::optional<std::size_t> find(const EntityId& id) const;
  std::size_t size() const noexcept { return entities_.size(); }
  const RemoteEntity& operator[](std::size_t i) const { return entities_[i]; }
  std::span<const RemoteEntity> entities() const noexcept { return entities_; }

  Pose dead_reckoned_pose(std::size_t i, double now_s) const noexcept;
  Pose displayed_pose(std::size_t i, double now_s) const noexcept;

  const DrThresholds& thresholds() const noexcept { return thresholds_; }

 private:
  struct IdHash {
    std::size_t operator()(const EntityId& e) const noexcept {
      return (std::size_t{e.site} << 32) ^ (std::size_t{e.application} << 16) ^ e.entity;
    }
  };
  void remove_at(std::size_t i);
  void start_blend(RemoteEntity& e, const Pose& shown, double now_s) const;
  // Sets e.state_s (and the clock offset) from timestamp ts arriving at now_s.
  static void stamp(RemoteEntity& e, std::uint32_t ts, double now_s, double unix_now_s);

  DrThresholds thresholds_;
  std::vector<RemoteEntity> entities_;
  std::unordered_map<EntityId, std::size_t, IdHash> index_;
};

}  // namespace net
