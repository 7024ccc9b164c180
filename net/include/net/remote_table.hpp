// net/remote_table.hpp — remote entities heard on the network, dead-reckoned and smoothed.
// Contract:
//  * Keyed by EntityId (site, application, entity). apply(EntityStatePdu, now_s) adds or updates
//    an entity; apply(EntityStateUpdatePdu, now_s) updates a known one (unknown: Ignored, as the
//    ESU lacks type and marking). An ES whose appearance has the Deactivated bit (23) removes
//    the entity (Deactivated). `now_s` is the receiver's own clock in seconds (monotonic); the
//    PDU timestamp is kept but never used to drop a PDU.
//  * dead_reckoned_pose(i, now) extrapolates the last state with its DR algorithm from the time
//    it arrived. displayed_pose(i, now) is what to draw: after an update, it starts at the pose
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
  std::uint32_t last_timestamp = 0;  // DIS timestamp of that update
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

  explicit RemoteEntityTable(DrThresholds t = {}) : thresholds_(t) {}

  ApplyResult apply(const EntityStatePdu& p, double now_s);
  ApplyResult apply(const EntityStateUpdatePdu& p, double now_s);

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

  DrThresholds thresholds_;
  std::vector<RemoteEntity> entities_;
  std::unordered_map<EntityId, std::size_t, IdHash> index_;
};

}  // namespace net
