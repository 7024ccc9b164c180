// net/pdu.hpp — plain DIS 7 (IEEE 1278.1-2012) PDU structs, as they travel on the wire.
// Contract: every field of the PDU types we speak (Entity State 1, Fire 2, Detonation 3,
// Collision 4, Entity State Update 67; simulation management: Remove Entity 12, Start/Resume 13,
// Stop/Freeze 14, Acknowledge 15) has a member here, including padding and opaque bytes,
// so that decode followed by encode gives back the same bytes. Units: positions WGS84 ECEF
// metres (double), velocities m/s and accelerations m/s^2 (float, world frame unless the DR
// algorithm says body), orientations DIS Euler angles psi/theta/phi in radians (float), angular
// velocity rad/s about the body axes, mass kg, range m. Byte offsets live in DIS7-NOTES.md.
#pragma once

#include <array>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace net {

// PDU types we decode. Anything else is skipped and counted by the datagram parser.
enum class PduType : std::uint8_t {
  EntityState = 1,
  Fire = 2,
  Detonation = 3,
  Collision = 4,
  RemoveEntity = 12,
  StartResume = 13,
  StopFreeze = 14,
  Acknowledge = 15,
  EntityStateUpdate = 67,
};

enum class ProtocolFamily : std::uint8_t { EntityInformation = 1, Warfare = 2, SimulationManagement = 5 };

inline constexpr std::uint8_t kProtocolVersion7 = 7;
inline constexpr std::uint8_t kProtocolVersion6 = 6;  // same layout for our types
inline constexpr std::uint8_t kProtocolVersion5 = 5;  // IEEE 1278.1-1995: same layouts (header
                                                      // octets 10-11 are padding)
inline constexpr std::size_t kHeaderSize = 12;
inline constexpr std::size_t kEntityStateFixedSize = 144;
inline constexpr std::size_t kFireSize = 96;
inline constexpr std::size_t kDetonationFixedSize = 104;
inline constexpr std::size_t kCollisionSize = 60;
inline constexpr std::size_t kEntityStateUpdateFixedSize = 72;
inline constexpr std::size_t kRemoveEntitySize = 28;
inline constexpr std::size_t kStartResumeSize = 44;
inline constexpr std::size_t kStopFreezeSize = 40;
inline constexpr std::size_t kAcknowledgeSize = 32;
inline constexpr std::size_t kVariableParameterSize = 16;
inline constexpr std::size_t kMaxPduSize = 8192;  // Annex C maximum PDU size (octets)
inline constexpr std::size_t kMaxVariableParameters = 255;  // the count is a u8

struct PduHeader {
  std::uint8_t protocol_version = kProtocolVersion7;
  std::uint8_t exercise_id = 1;
  std::uint8_t pdu_type = 0;         // overwritten by encode with the struct's type
  std::uint8_t protocol_family = 0;  // kept as given (the PDU structs default it correctly)
  std::uint32_t timestamp = 0;       // see net/timestamp.hpp
  std::uint16_t length = 0;          // whole PDU in octets; encode writes the computed value
  std::uint8_t pdu_status = 0;
  std::uint8_t padding = 0;
  friend bool operator==(const PduHeader&, const PduHeader&) = default;
};

// (site, application, entity). Also used for munition ids.
struct EntityId {
  std::uint16_t site = 0;
  std::uint16_t application = 0;
  std::uint16_t entity = 0;
  friend auto operator<=>(const EntityId&, const EntityId&) = default;
};

struct EventId {
  std::uint16_t site = 0;
  std::uint16_t application = 0;
  std::uint16_t event_number = 0;
  friend bool operator==(const EventId&, const EventId&) = default;
};

struct EntityType {
  std::uint8_t kind = 0;
  std::uint8_t domain = 0;
  std::uint16_t country = 0;
  std::uint8_t category = 0;
  std::uint8_t subcategory = 0;
  std::uint8_t specific = 0;
  std::uint8_t extra = 0;
  friend bool operator==(const EntityType&, const EntityType&) = default;
};

struct Vec3f {
  float x = 0, y = 0, z = 0;
  friend bool operator==(const Vec3f&, const Vec3f&) = default;
};
// A double as the float a PDU field carries: the nearest float within a float's range (as a plain
// conversion), the largest float of its sign beyond it, infinities included (a plain conversion
// is undefined there, and a peer should not be sent an infinity); NaN stays NaN.
constexpr float wire_float(double x) noexcept {
  constexpr float kMax = std::numeric_limits<float>::max();
  return x > kMax ? kMax : x < -kMax ? -kMax : static_cast<float>(x);
}
constexpr Vec3f wire_vec3f(double x, double y, double z) noexcept { return {wire_float(x), wire_float(y), wire_float(z)}; }
struct Vec3d {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Vec3d&, const Vec3d&) = default;
};
// DIS Euler angles, radians: psi about Z (ECEF), then theta about new Y, then phi about new X.
struct EulerAnglesF {
  float psi = 0, theta = 0, phi = 0;
  friend bool operator==(const EulerAnglesF&, const EulerAnglesF&) = default;
};

// Dead-reckoning parameters (40 octets at ES offset 88).
struct DeadReckoningParameters {
  std::uint8_t algorithm = 0;                 // 0..9, see net/dead_reckoning.hpp
  std::array<std::uint8_t, 15> other{};       // "other parameters", carried opaque
  Vec3f linear_acceleration;                  // m/s^2
  Vec3f angular_velocity;                     // rad/s, body axes
  friend bool operator==(const DeadReckoningParameters&, const DeadReckoningParameters&) = default;
};

// Marking: character set (1 = ASCII) + 11 characters, NUL padded. See net/marking.hpp.
struct Marking {
  std::uint8_t character_set = 1;
  std::array<char, 11> characters{};
  friend bool operator==(const Marking&, const Marking&) = default;
};

// Variable parameter record (articulated part, attached part, separation, ...): type + 15
// octets carried unchanged.
struct VariableParameter {
  std::uint8_t record_type = 0;
  std::array<std::uint8_t, 15> data{};
  friend bool operator==(const VariableParameter&, const VariableParameter&) = default;
};

// Munition / expendable descriptor (16 octets).
struct MunitionDescriptor {
  EntityType munition_type;
  std::uint16_t warhead = 0;
  std::uint16_t fuse = 0;
  std::uint16_t quantity = 0;
  std::uint16_t rate = 0;  // rounds per minute
  friend bool operator==(const MunitionDescriptor&, const MunitionDescriptor&) = default;
};

// Entity State, type 1, family 1: 144 + 16 per variable parameter.
struct EntityStatePdu {
  PduHeader header{kProtocolVersion7, 1, 1, 1};
  EntityId entity_id;
  std::uint8_t force_id = 0;
  EntityType entity_type;
  EntityType alternative_entity_type;
  Vec3f linear_velocity;  // m/s
  Vec3d location;         // ECEF m
  EulerAnglesF orientation;
  std::uint32_t appearance = 0;
  DeadReckoningParameters dead_reckoning;
  Marking marking;
  std::uint32_t capabilities = 0;
  std::vector<VariableParameter> variable_parameters;
  friend bool operator==(const EntityStatePdu&, const EntityStatePdu&) = default;
};

// Fire, type 2, family 2: 96.
struct FirePdu {
  PduHeader header{kProtocolVersion7, 1, 2, 2};
  EntityId firing_entity_id;
  EntityId target_entity_id;
  EntityId munition_id;
  EventId event_id;
  std::uint32_t fire_mission_index = 0;
  Vec3d location;  // ECEF m, where the round leaves
  MunitionDescriptor descriptor;
  Vec3f velocity;  // m/s
  float range = 0;  // m
  friend bool operator==(const FirePdu&, const FirePdu&) = default;
};

// Detonation, type 3, family 2: 104 + 16 per variable parameter.
struct DetonationPdu {
  PduHeader header{kProtocolVersion7, 1, 3, 2};
  EntityId firing_entity_id;
  EntityId target_entity_id;
  EntityId exploding_entity_id;
  EventId event_id;
  Vec3f velocity;  // m/s
  Vec3d location;  // ECEF m
  MunitionDescriptor descriptor;
  Vec3f location_in_entity;  // m, target's body frame
  std::uint8_t detonation_result = 0;
  std::uint16_t padding = 0;
  std::vector<VariableParameter> variable_parameters;
  friend bool operator==(const DetonationPdu&, const DetonationPdu&) = default;
};

// Collision, type 4, family 1: 60.
struct CollisionPdu {
  PduHeader header{kProtocolVersion7, 1, 4, 1};
  EntityId issuing_entity_id;
  EntityId colliding_entity_id;
  EventId event_id;
  std::uint8_t collision_type = 0;  // 0 inelastic, 1 elastic
  std::uint8_t padding = 0;  // octet 31; NPSNET states its collision outcome here (node/collision_outcome.hpp)
  Vec3f velocity;  // m/s, issuing entity
  float mass = 0;  // kg, issuing entity
  Vec3f location_in_entity;  // m, issuing entity's body frame
  friend bool operator==(const CollisionPdu&, const CollisionPdu&) = default;
};

// Entity State Update, type 67, family 1: 72 + 16 per variable parameter.
struct EntityStateUpdatePdu {
  PduHeader header{kProtocolVersion7, 1, 67, 1};
  EntityId entity_id;
  std::uint8_t padding = 0;
  Vec3f linear_velocity;
  Vec3d location;
  EulerAnglesF orientation;
  std::uint32_t appearance = 0;
  std::vector<VariableParameter> variable_parameters;
  friend bool operator==(const EntityStateUpdatePdu&, const EntityStateUpdatePdu&) = default;
};

// Clock time: hours since 1970-01-01 00:00 UTC (simulation time: hours of the exercise) and a
// DIS timestamp past that hour (net/timestamp.hpp).
struct ClockTime {
  std::int32_t hour = 0;
  std::uint32_t time_past_hour = 0;
  friend bool operator==(const ClockTime&, const ClockTime&) = default;
};

// Simulation management (family 5), IEEE 1278.1-2012 7.5: originating and receiving entity ids
// name a simulation (site, application, 0) or an entity; 0xFFFF in a field means "all".
// Remove Entity, type 12: 28.
struct RemoveEntityPdu {
  PduHeader header{kProtocolVersion7, 1, 12, 5};
  EntityId originating_id;
  EntityId receiving_id;
  std::uint32_t request_id = 0;
  friend bool operator==(const RemoveEntityPdu&, const RemoveEntityPdu&) = default;
};

// Start/Resume, type 13: 44.
struct StartResumePdu {
  PduHeader header{kProtocolVersion7, 1, 13, 5};
  EntityId originating_id;
  EntityId receiving_id;
  ClockTime real_world_time;  // when to start (UTC); zero or past = now
  ClockTime simulation_time;  // the simulation time to start at
  std::uint32_t request_id = 0;
  friend bool operator==(const StartResumePdu&, const StartResumePdu&) = default;
};

// Stop/Freeze, type 14: 40.
struct StopFreezePdu {
  PduHeader header{kProtocolVersion7, 1, 14, 5};
  EntityId originating_id;
  EntityId receiving_id;
  ClockTime real_world_time;    // when to stop (UTC); zero or past = now
  std::uint8_t reason = 0;      // 0 other, 1 recess, 2 termination, 3 system failure, ...
  std::uint8_t frozen_behavior = 0;  // bit 0 run simulation clock, 1 transmit updates, 2 process updates
  std::uint16_t padding = 0;
  std::uint32_t request_id = 0;
  friend bool operator==(const StopFreezePdu&, const StopFreezePdu&) = default;
};

// Acknowledge, type 15: 32.
struct AcknowledgePdu {
  PduHeader header{kProtocolVersion7, 1, 15, 5};
  EntityId originating_id;
  EntityId receiving_id;
  std::uint16_t acknowledge_flag = 0;  // 1 create entity, 2 remove entity, 3 start/resume, 4 stop/freeze
  std::uint16_t response_flag = 0;     // 0 other, 1 able to comply, 2 unable to comply, 3 pending
  std::uint32_t request_id = 0;
  friend bool operator==(const AcknowledgePdu&, const AcknowledgePdu&) = default;
};

inline constexpr std::uint16_t kAllSites = 0xFFFF, kAllApplications = 0xFFFF, kAllEntities = 0xFFFF;

// Entity appearance bit 21: Frozen Status (1 frozen).
inline constexpr std::uint32_t kAppearanceFrozen = 1u << 21;
// Entity appearance bit 23: State (0 active, 1 deactivated) — an entity leaving the exercise.
inline constexpr std::uint32_t kAppearanceDeactivated = 1u << 23;

}  // namespace net
