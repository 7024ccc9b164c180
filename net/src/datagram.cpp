// datagram.cpp — one step of the datagram walk: classify, filter and decode one PDU.
#include "net/datagram.hpp"

namespace net {

EntityId originating_entity(const EntityStatePdu& p) noexcept { return p.entity_id; }
EntityId originating_entity(const FirePdu& p) noexcept { return p.firing_entity_id; }
EntityId originating_entity(const DetonationPdu& p) noexcept { return p.firing_entity_id; }
EntityId originating_entity(const CollisionPdu& p) noexcept { return p.issuing_entity_id; }
EntityId originating_entity(const EntityStateUpdatePdu& p) noexcept { return p.entity_id; }
EntityId originating_entity(const RemoveEntityPdu& p) noexcept { return p.originating_id; }
EntityId originating_entity(const StartResumePdu& p) noexcept { return p.originating_id; }
EntityId originating_entity(const StopFreezePdu& p) noexcept { return p.originating_id; }
EntityId originating_entity(const AcknowledgePdu& p) noexcept { return p.originating_id; }

namespace {

void reject(Counters& c, DecodeError e) { ++c.rejected[static_cast<std::size_t>(e)]; }

}  // namespace

DatagramParser::Step DatagramParser::step(std::span<const std::uint8_t> rest, Counters& c) {
  Step s;
  ++c.pdus_seen;
  PduHeader h;
  if (decode_header(rest, h) != DecodeError::None) {
    reject(c, DecodeError::TruncatedHeader);
    return s;  // stop
  }
  if (h.length < kHeaderSize) {
    reject(c, DecodeError::LengthBelowHeader);
    return s;
  }
  if (h.length > rest.size()) {
    reject(c, DecodeError::LengthExceedsData);
    return s;
  }
  s.advance = h.length;
  if (!is_supported_version(h.protocol_version)) {
    ++c.skipped_version;
    return s;
  }
  if (!is_supported_type(h.pdu_type)) {
    ++c.skipped_unknown_type;
    return s;
  }
  if (filter_.filter_exercise && h.exercise_id != filter_.exercise_id) {
    ++c.other_exercise_ignored;
    return s;
  }
  s.type = static_cast<PduType>(h.pdu_type);
  DecodeError e = DecodeError::None;
  EntityId origin;
  switch (s.type) {
    case PduType::EntityState:
      e = decode(rest, es_);
      origin = es_.entity_id;
      break;
    case PduType::Fire:
      e = decode(rest, fire_);
      origin = fire_.firing_entity_id;
      break;
    case PduType::Detonation:
      e = decode(rest, det_);
      origin = det_.firing_entity_id;
      break;
    case PduType::Collision:
      e = decode(rest, col_);
      origin = col_.issuing_entity_id;
      break;
    case PduType::EntityStateUpdate:
      e = decode(rest, esu_);
      origin = esu_.entity_id;
      break;
    case PduType::RemoveEntity:
      e = decode(rest, remove_);
      origin = remove_.originating_id;
      break;
    case PduType::StartResume:
      e = decode(rest, start_);
      origin = start_.originating_id;
      break;
    case PduType::StopFreeze:
      e = decode(rest, stop_);
      origin = stop_.originating_id;
      break;
    case PduType::Acknowledge:
      e = decode(rest, ack_);
      origin = ack_.originating_id;
      break;
  }
  if (e != DecodeError::None) {
    reject(c, e);
    return s;
  }
  if (filter_.ignore_own && origin.site == filter_.site && filter_.own_application(origin.application)) {
    // A Detonation of one of our rounds or a Collision PDU one of our vehicles issued that we did
    // not send is another node repeating it (a node that adopted the PDUs of our earlier process,
    // killed and restarted): delivered.
    if (filter_.echo || (s.type != PduType::Detonation && s.type != PduType::Collision)) {
      ++(filter_.echo ? c.own_echo_ignored : c.own_id_clash);
      return s;
    }
  }
  ++c.decoded[h.pdu_type];
  s.deliver = true;
  return s;
}

}  // namespace net
