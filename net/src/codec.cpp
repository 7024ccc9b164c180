// codec.cpp — encode/decode of the five PDU types (layouts: DIS7-NOTES.md).
#include "net/codec.hpp"

#include "byte_io.hpp"

namespace net {
namespace {

using detail::Reader;
using detail::Writer;

constexpr std::size_t with_params(std::size_t fixed, std::size_t n) {
  return fixed + kVariableParameterSize * n;
}

void write_header(Writer& w, const PduHeader& h, PduType type, std::size_t length) {
  w.u8(h.protocol_version);
  w.u8(h.exercise_id);
  w.u8(static_cast<std::uint8_t>(type));
  w.u8(h.protocol_family);
  w.u32(h.timestamp);
  w.u16(static_cast<std::uint16_t>(length));
  w.u8(h.pdu_status);
  w.u8(h.padding);
}

void read_header(Reader& r, PduHeader& h) {
  h.protocol_version = r.u8();
  h.exercise_id = r.u8();
  h.pdu_type = r.u8();
  h.protocol_family = r.u8();
  h.timestamp = r.u32();
  h.length = r.u16();
  h.pdu_status = r.u8();
  h.padding = r.u8();
}

// Checks shared by every decode: header present, version, type, length within the data.
DecodeError check_common(std::span<const std::uint8_t> bytes, PduType type, PduHeader& h) {
  if (bytes.size() < kHeaderSize) return DecodeError::TruncatedHeader;
  Reader r(bytes.data());
  read_header(r, h);
  if (h.length < kHeaderSize) return DecodeError::LengthBelowHeader;
  if (h.length > bytes.size()) return DecodeError::LengthExceedsData;
  if (!is_supported_version(h.protocol_version)) return DecodeError::UnsupportedVersion;
  if (h.pdu_type != static_cast<std::uint8_t>(type)) return DecodeError::WrongType;
  return DecodeError::None;
}

// Variable-length types: fixed part, count octet at `count_offset`, 16 octets per record.
DecodeError check_variable(const PduHeader& h, std::span<const std::uint8_t> bytes,
                           std::size_t fixed, std::size_t count_offset, std::size_t& count) {
  if (h.length < fixed) return DecodeError::TooShortForType;
  count = bytes[count_offset];
  if (with_params(fixed, count) != h.length) return DecodeError::VariableCountMismatch;
  return DecodeError::None;
}

template <class Pdu>
EncodeError check_encode(const Pdu& p, std::size_t fixed, std::span<std::uint8_t> out,
                         std::size_t& size) {
  if (p.variable_parameters.size() > kMaxVariableParameters)
    return EncodeError::TooManyVariableParameters;
  size = with_params(fixed, p.variable_parameters.size());
  if (size > kMaxPduSize) return EncodeError::PduTooLarge;
  if (out.size() < size) return EncodeError::BufferTooSmall;
  return EncodeError::None;
}

void read_params(Reader& r, std::size_t n, std::vector<VariableParameter>& out) {
  out.resize(n);  // keeps capacity: no allocation once warmed up
  for (auto& v : out) r.param(v);
}

}  // namespace

std::string_view to_string(DecodeError e) noexcept {
  switch (e) {
    case DecodeError::None: return "none";
    case DecodeError::TruncatedHeader: return "truncated_header";
    case DecodeError::LengthBelowHeader: return "length_below_header";
    case DecodeError::LengthExceedsData: return "length_exceeds_data";
    case DecodeError::TooShortForType: return "too_short_for_type";
    case DecodeError::VariableCountMismatch: return "variable_count_mismatch";
    case DecodeError::LengthMismatch: return "length_mismatch";
    case DecodeError::UnsupportedVersion: return "unsupported_version";
    case DecodeError::WrongType: return "wrong_type";
    case DecodeError::Count_: break;
  }
  return "unknown";
}

std::string_view to_string(EncodeError e) noexcept {
  switch (e) {
    case EncodeError::None: return "none";
    case EncodeError::BufferTooSmall: return "buffer_too_small";
    case EncodeError::TooManyVariableParameters: return "too_many_variable_parameters";
    case EncodeError::PduTooLarge: return "pdu_too_large";
  }
  return "unknown";
}

bool is_supported_type(std::uint8_t t) noexcept {
  switch (static_cast<PduType>(t)) {
    case PduType::EntityState:
    case PduType::Fire:
    case PduType::Detonation:
    case PduType::Collision:
    case PduType::EntityStateUpdate:
    case PduType::RemoveEntity:
    case PduType::StartResume:
    case PduType::StopFreeze:
    case PduType::Acknowledge: return true;
  }
  return false;
}

bool is_supported_version(std::uint8_t v) noexcept {
  return v == kProtocolVersion5 || v == kProtocolVersion6 || v == kProtocolVersion7;
}

std::size_t encoded_size(const EntityStatePdu& p) noexcept {
  return with_params(kEntityStateFixedSize, p.variable_parameters.size());
}
std::size_t encoded_size(const FirePdu&) noexcept { return kFireSize; }
std::size_t encoded_size(const DetonationPdu& p) noexcept {
  return with_params(kDetonationFixedSize, p.variable_parameters.size());
}
std::size_t encoded_size(const CollisionPdu&) noexcept { return kCollisionSize; }
std::size_t encoded_size(const EntityStateUpdatePdu& p) noexcept {
  return with_params(kEntityStateUpdateFixedSize, p.variable_parameters.size());
}

DecodeError decode_header(std::span<const std::uint8_t> bytes, PduHeader& out) noexcept {
  if (bytes.size() < kHeaderSize) return DecodeError::TruncatedHeader;
  Reader r(bytes.data());
  read_header(r, out);
  return DecodeError::None;
}

// ---------------------------------------------------------------- Entity State (1)
Result<std::size_t, EncodeError> encode(const EntityStatePdu& p,
                                        std::span<std::uint8_t> out) noexcept {
  std::size_t size = 0;
  if (auto e = check_encode(p, kEntityStateFixedSize, out, size); e != EncodeError::None)
    return Result<std::size_t, EncodeError>::failure(e);
  Writer w(out.data());
  write_header(w, p.header, PduType::EntityState, size);
  w.id(p.entity_id);
  w.u8(p.force_id);
  w.u8(static_cast<std::uint8_t>(p.variable_parameters.size()));
  w.type(p.entity_type);
  w.type(p.alternative_entity_type);
  w.vec(p.linear_velocity);
  w.vec(p.location);
  w.euler(p.orientation);
  w.u32(p.appearance);
  w.u8(p.dead_reckoning.algorithm);
  w.bytes(p.dead_reckoning.other);
  w.vec(p.dead_reckoning.linear_acceleration);
  w.vec(p.dead_reckoning.angular_velocity);
  w.u8(p.marking.character_set);
  w.bytes(p.marking.characters);
  w.u32(p.capabilities);
  for (const auto& v : p.variable_parameters) w.param(v);
  return size;
}

DecodeError decode(std::span<const std::uint8_t> bytes, EntityStatePdu& p) noexcept {
  if (auto e = check_common(bytes, PduType::EntityState, p.header); e != DecodeError::None)
    return e;
  std::size_t n = 0;
  if (auto e = check_variable(p.header, bytes, kEntityStateFixedSize, 19, n);
      e != DecodeError::None)
    return e;
  Reader r(bytes.data() + kHeaderSize);
  r.id(p.entity_id);
  p.force_id = r.u8();
  r.u8();  // count, checked above
  r.type(p.entity_type);
  r.type(p.alternative_entity_type);
  r.vec(p.linear_velocity);
  r.vec(p.location);
  r.euler(p.orientation);
  p.appearance = r.u32();
  p.dead_reckoning.algorithm = r.u8();
  r.bytes(p.dead_reckoning.other);
  r.vec(p.dead_reckoning.linear_acceleration);
  r.vec(p.dead_reckoning.angular_velocity);
  p.marking.character_set = r.u8();
  r.bytes(p.marking.characters);
  p.capabilities = r.u32();
  read_params(r, n, p.variable_parameters);
  return DecodeError::None;
}

// ---------------------------------------------------------------- Fire (2)
Result<std::size_t, EncodeError> encode(const FirePdu& p, std::span<std::uint8_t> out) noexcept {
  if (out.size() < kFireSize) return Result<std::size_t, EncodeError>::failure(EncodeError::BufferTooSmall);
  Writer w(out.data());
  write_header(w, p.header, PduType::Fire, kFireSize);
  w.id(p.firing_entity_id);
  w.id(p.target_entity_id);
  w.id(p.munition_id);
  w.id(p.event_id);
  w.u32(p.fire_mission_index);
  w.vec(p.location);
  w.descriptor(p.descriptor);
  w.vec(p.velocity);
  w.f32(p.range);
  return kFireSize;
}

DecodeError decode(std::span<const std::uint8_t> bytes, FirePdu& p) noexcept {
  if (auto e = check_common(bytes, PduType::Fire, p.header); e != DecodeError::None) return e;
  if (p.header.length < kFireSize) return DecodeError::TooShortForType;
  if (p.header.length != kFireSize) return DecodeError::LengthMismatch;
  Reader r(bytes.data() + kHeaderSize);
  r.id(p.firing_entity_id);
  r.id(p.target_entity_id);
  r.id(p.munition_id);
  r.id(p.event_id);
  p.fire_mission_index = r.u32();
  r.vec(p.location);
  r.descriptor(p.descriptor);
  r.vec(p.velocity);
  p.range = r.f32();
  return DecodeError::None;
}

// ---------------------------------------------------------------- Detonation (3)
Result<std::size_t, EncodeError> encode(const DetonationPdu& p,
                                        std::span<std::uint8_t> out) noexcept {
  std::size_t size = 0;
  if (auto e = check_encode(p, kDetonationFixedSize, out, size); e != EncodeError::None)
    return Result<std::size_t, EncodeError>::failure(e);
  Writer w(out.data());
  write_header(w, p.header, PduType::Detonation, size);
  w.id(p.firing_entity_id);
  w.id(p.target_entity_id);
  w.id(p.exploding_entity_id);
  w.id(p.event_id);
  w.vec(p.velocity);
  w.vec(p.location);
  w.descriptor(p.descriptor);
  w.vec(p.location_in_entity);
  w.u8(p.detonation_result);
  w.u8(static_cast<std::uint8_t>(p.variable_parameters.size()));
  w.u16(p.padding);
  for (const auto& v : p.variable_parameters) w.param(v);
  return size;
}

DecodeError decode(std::span<const std::uint8_t> bytes, DetonationPdu& p) noexcept {
  if (auto e = check_common(bytes, PduType::Detonation, p.header); e != DecodeError::None)
    return e;
  std::size_t n = 0;
  if (auto e = check_variable(p.header, bytes, kDetonationFixedSize, 101, n);
      e != DecodeError::None)
    return e;
  Reader r(bytes.data() + kHeaderSize);
  r.id(p.firing_entity_id);
  r.id(p.target_entity_id);
  r.id(p.exploding_entity_id);
  r.id(p.event_id);
  r.vec(p.velocity);
  r.vec(p.location);
  r.descriptor(p.descriptor);
  r.vec(p.location_in_entity);
  p.detonation_result = r.u8();
  r.u8();  // count, checked above
  p.padding = r.u16();
  read_params(r, n, p.variable_parameters);
  return DecodeError::None;
}

// ---------------------------------------------------------------- Collision (4)
Result<std::size_t, EncodeError> encode(const CollisionPdu& p,
                                        std::span<std::uint8_t> out) noexcept {
  if (out.size() < kCollisionSize)
    return Result<std::size_t, EncodeError>::failure(EncodeError::BufferTooSmall);
  Writer w(out.data());
  write_header(w, p.header, PduType::Collision, kCollisionSize);
  w.id(p.issuing_entity_id);
  w.id(p.colliding_entity_id);
  w.id(p.event_id);
  w.u8(p.collision_type);
  w.u8(p.padding);
  w.vec(p.velocity);
  w.f32(p.mass);
  w.vec(p.location_in_entity);
  return kCollisionSize;
}

DecodeError decode(std::span<const std::uint8_t> bytes, CollisionPdu& p) noexcept {
  if (auto e = check_common(bytes, PduType::Collision, p.header); e != DecodeError::None)
    return e;
  if (p.header.length < kCollisionSize) return DecodeError::TooShortForType;
  if (p.header.length != kCollisionSize) return DecodeError::LengthMismatch;
  Reader r(bytes.data() + kHeaderSize);
  r.id(p.issuing_entity_id);
  r.id(p.colliding_entity_id);
  r.id(p.event_id);
  p.collision_type = r.u8();
  p.padding = r.u8();
  r.vec(p.velocity);
  p.mass = r.f32();
  r.vec(p.location_in_entity);
  return DecodeError::None;
}

// ---------------------------------------------------------------- Entity State Update (67)
Result<std::size_t, EncodeError> encode(const EntityStateUpdatePdu& p,
                                        std::span<std::uint8_t> out) noexcept {
  std::size_t size = 0;
  if (auto e = check_encode(p, kEntityStateUpdateFixedSize, out, size); e != EncodeError::None)
    return Result<std::size_t, EncodeError>::failure(e);
  Writer w(out.data());
  write_header(w, p.header, PduType::EntityStateUpdate, size);
  w.id(p.entity_id);
  w.u8(p.padding);
  w.u8(static_cast<std::uint8_t>(p.variable_parameters.size()));
  w.vec(p.linear_velocity);
  w.vec(p.location);
  w.euler(p.orientation);
  w.u32(p.appearance);
  for (const auto& v : p.variable_parameters) w.param(v);
  return size;
}

DecodeError decode(std::span<const std::uint8_t> bytes, EntityStateUpdatePdu& p) noexcept {
  if (auto e = check_common(bytes, PduType::EntityStateUpdate, p.header); e != DecodeError::None)
    return e;
  std::size_t n = 0;
  if (auto e = check_variable(p.header, bytes, kEntityStateUpdateFixedSize, 19, n);
      e != DecodeError::None)
    return e;
  Reader r(bytes.data() + kHeaderSize);
  r.id(p.entity_id);
  p.padding = r.u8();
  r.u8();  // count, checked above
  r.vec(p.linear_velocity);
  r.vec(p.location);
  r.euler(p.orientation);
  p.appearance = r.u32();
  read_params(r, n, p.variable_parameters);
  return DecodeError::None;
}



// ---------------------------------------------------------------- Simulation management (12-15)
namespace {
void write_clock(Writer& w, const ClockTime& c) {
  w.u32(static_cast<std::uint32_t>(c.hour));
  w.u32(c.time_past_hour);
}
void read_clock(Reader& r, ClockTime& c) {
  c.hour = static_cast<std::int32_t>(r.u32());
  c.time_past_hour = r.u32();
}
// Fixed-size PDUs: header checks, then the exact length.
template <class Pdu>
DecodeError check_fixed(std::span<const std::uint8_t> bytes, PduType type, Pdu& p, std::size_t size) {
  if (auto e = check_common(bytes, type, p.header); e != DecodeError::None) return e;
  if (p.header.length < size) return DecodeError::TooShortForType;
  if (p.header.length != size) return DecodeError::LengthMismatch;
  return DecodeError::None;
}
template <class Pdu, class Body>
Result<std::size_t, EncodeError> encode_fixed(const Pdu& p, PduType type, std::size_t size,
                                              std::span<std::uint8_t> out, Body&& body) {
  if (out.size() < size) return Result<std::size_t, EncodeError>::failure(EncodeError::BufferTooSmall);
  Writer w(out.data());
  write_header(w, p.header, type, size);
  w.id(p.originating_id);
  w.id(p.receiving_id);
  body(w);
  return size;
}
}  // namespace

std::size_t encoded_size(const RemoveEntityPdu&) noexcept { return kRemoveEntitySize; }
std::size_t encoded_size(const StartResumePdu&) noexcept { return kStartResumeSize; }
std::size_t encoded_size(const StopFreezePdu&) noexcept { return kStopFreezeSize; }
std::size_t encoded_size(const AcknowledgePdu&) noexcept { return kAcknowledgeSize; }

Result<std::size_t, EncodeError> encode(const RemoveEntityPdu& p, std::span<std::uint8_t> out) noexcept {
  return encode_fixed(p, PduType::RemoveEntity, kRemoveEntitySize, out, [&](Writer& w) { w.u32(p.request_id); });
}
Result<std::size_t, EncodeError> encode(const StartResumePdu& p, std::span<std::uint8_t> out) noexcept {
  return encode_fixed(p, PduType::StartResume, kStartResumeSize, out, [&](Writer& w) {
    write_clock(w, p.real_world_time);
    write_clock(w, p.simulation_time);
    w.u32(p.request_id);
  });
}
Result<std::size_t, EncodeError> encode(const StopFreezePdu& p, std::span<std::uint8_t> out) noexcept {
  return encode_fixed(p, PduType::StopFreeze, kStopFreezeSize, out, [&](Writer& w) {
    write_clock(w, p.real_world_time);
    w.u8(p.reason);
    w.u8(p.frozen_behavior);
    w.u16(p.padding);
    w.u32(p.request_id);
  });
}
Result<std::size_t, EncodeError> encode(const AcknowledgePdu& p, std::span<std::uint8_t> out) noexcept {
  return encode_fixed(p, PduType::Acknowledge, kAcknowledgeSize, out, [&](Writer& w) {
    w.u16(p.acknowledge_flag);
    w.u16(p.response_flag);
    w.u32(p.request_id);
  });
}

DecodeError decode(std::span<const std::uint8_t> bytes, RemoveEntityPdu& p) noexcept {
  if (auto e = check_fixed(bytes, PduType::RemoveEntity, p, kRemoveEntitySize); e != DecodeError::None) return e;
  Reader r(bytes.data() + kHeaderSize);
  r.id(p.originating_id);
  r.id(p.receiving_id);
  p.request_id = r.u32();
  return DecodeError::None;
}
DecodeError decode(std::span<const std::uint8_t> bytes, StartResumePdu& p) noexcept {
  if (auto e = check_fixed(bytes, PduType::StartResume, p, kStartResumeSize); e != DecodeError::None) return e;
  Reader r(bytes.data() + kHeaderSize);
  r.id(p.originating_id);
  r.id(p.receiving_id);
  read_clock(r, p.real_world_time);
  read_clock(r, p.simulation_time);
  p.request_id = r.u32();
  return DecodeError::None;
}
DecodeError decode(std::span<const std::uint8_t> bytes, StopFreezePdu& p) noexcept {
  if (auto e = check_fixed(bytes, PduType::StopFreeze, p, kStopFreezeSize); e != DecodeError::None) return e;
  Reader r(bytes.data() + kHeaderSize);
  r.id(p.originating_id);
  r.id(p.receiving_id);
  read_clock(r, p.real_world_time);
  p.reason = r.u8();
  p.frozen_behavior = r.u8();
  p.padding = r.u16();
  p.request_id = r.u32();
  return DecodeError::None;
}
DecodeError decode(std::span<const std::uint8_t> bytes, AcknowledgePdu& p) noexcept {
  if (auto e = check_fixed(bytes, PduType::Acknowledge, p, kAcknowledgeSize); e != DecodeError::None) return e;
  Reader r(bytes.data() + kHeaderSize);
  r.id(p.originating_id);
  r.id(p.receiving_id);
  p.acknowledge_flag = r.u16();
  p.response_flag = r.u16();
  p.request_id = r.u32();
  return DecodeError::None;
}

}  // namespace net
