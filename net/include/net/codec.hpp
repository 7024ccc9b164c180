// net/codec.hpp — big-endian, byte-exact encode/decode of single DIS PDUs.
// Contract:
//  * encode(pdu, out) writes exactly encoded_size(pdu) octets at the start of `out` and returns
//    that size; it writes the PDU type and the computed length into the header (all other header
//    fields as given). It writes nothing and returns an error if `out` is too small, there are
//    more than 255 variable parameters, or the PDU would exceed 8192 octets.
//  * decode(bytes, out) reads the one PDU at the start of `bytes` (the header's length says how
//    long it is; bytes past it are ignored) into `out`, reusing `out`'s vector capacity, so a
//    decoder that keeps its structs allocates nothing in steady state. Network input never
//    throws: every problem is a DecodeError. Protocol versions 5, 6 and 7 are accepted (the
//    layouts of these PDUs are the same); the version octet is kept for re-encoding.
//  * Padding and opaque octets are kept, so decode -> encode gives back the same bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "net/pdu.hpp"
#include "net/result.hpp"

namespace net {

enum class DecodeError : std::uint8_t {
  None = 0,
  TruncatedHeader,        // fewer than 12 octets left where a header should start
  LengthBelowHeader,      // header length field < 12: cannot be walked past
  LengthExceedsData,      // header length field > octets left in the datagram
  TooShortForType,        // length < the fixed part of this PDU type
  VariableCountMismatch,  // fixed part + 16 x (variable parameter count) != length
  LengthMismatch,         // fixed-size PDU (Fire, Collision) whose length is not its size
  UnsupportedVersion,     // protocol version other than 6 or 7 (datagram walk: skipped)
  WrongType,              // decode(bytes, FirePdu&) on a PDU of another type
  Count_
};
inline constexpr std::size_t kDecodeErrorCount = static_cast<std::size_t>(DecodeError::Count_);

// Short snake_case name ("length_exceeds_data"), for counters and logs.
std::string_view to_string(DecodeError e) noexcept;

enum class EncodeError : std::uint8_t {
  None = 0,
  BufferTooSmall,
  TooManyVariableParameters,  // > 255
  PduTooLarge,                // > 8192 octets
};
std::string_view to_string(EncodeError e) noexcept;

// Octets encode() will write.
std::size_t encoded_size(const EntityStatePdu& p) noexcept;
std::size_t encoded_size(const FirePdu& p) noexcept;
std::size_t encoded_size(const DetonationPdu& p) noexcept;
std::size_t encoded_size(const CollisionPdu& p) noexcept;
std::size_t encoded_size(const EntityStateUpdatePdu& p) noexcept;
std::size_t encoded_size(const RemoveEntityPdu& p) noexcept;
std::size_t encoded_size(const StartResumePdu& p) noexcept;
std::size_t encoded_size(const StopFreezePdu& p) noexcept;
std::size_t encoded_size(const AcknowledgePdu& p) noexcept;

Result<std::size_t, EncodeError> encode(const EntityStatePdu& p, std::span<std::uint8_t> out) noexcept;
Result<std::size_t, EncodeError> encode(const FirePdu& p, std::span<std::uint8_t> out) noexcept;
Result<std::size_t, EncodeError> encode(const DetonationPdu& p, std::span<std::uint8_t> out) noexcept;
Result<std::size_t, EncodeError> encode(const CollisionPdu& p, std::span<std::uint8_t> out) noexcept;
Result<std::size_t, EncodeError> encode(const EntityStateUpdatePdu& p, std::span<std::uint8_t> out) noexcept;
Result<std::size_t, EncodeError> encode(const RemoveEntityPdu& p, std::span<std::uint8_t> out) noexcept;
Result<std::size_t, EncodeError> encode(const StartResumePdu& p, std::span<std::uint8_t> out) noexcept;
Result<std::size_t, EncodeError> encode(const StopFreezePdu& p, std::span<std::uint8_t> out) noexcept;
Result<std::size_t, EncodeError> encode(const AcknowledgePdu& p, std::span<std::uint8_t> out) noexcept;

// Appends the encoded PDU to `out` (convenience; allocates as a vector does).
template <class Pdu>
Result<std::size_t, EncodeError> encode_append(const Pdu& p, std::vector<std::uint8_t>& out) {
  const std::size_t old = out.size();
  out.resize(old + encoded_size(p));
  auto r = encode(p, std::span<std::uint8_t>(out).subspan(old));
  if (!r) out.resize(old);
  return r;
}

// Header only (12 octets). Does not check the version.
DecodeError decode_header(std::span<const std::uint8_t> bytes, PduHeader& out) noexcept;

DecodeError decode(std::span<const std::uint8_t> bytes, EntityStatePdu& out) noexcept;
DecodeError decode(std::span<const std::uint8_t> bytes, FirePdu& out) noexcept;
DecodeError decode(std::span<const std::uint8_t> bytes, DetonationPdu& out) noexcept;
DecodeError decode(std::span<const std::uint8_t> bytes, CollisionPdu& out) noexcept;
DecodeError decode(std::span<const std::uint8_t> bytes, EntityStateUpdatePdu& out) noexcept;
DecodeError decode(std::span<const std::uint8_t> bytes, RemoveEntityPdu& out) noexcept;
DecodeError decode(std::span<const std::uint8_t> bytes, StartResumePdu& out) noexcept;
DecodeError decode(std::span<const std::uint8_t> bytes, StopFreezePdu& out) noexcept;
DecodeError decode(std::span<const std::uint8_t> bytes, AcknowledgePdu& out) noexcept;

// Convenience: decode into a fresh struct, e.g. decode_as<FirePdu>(bytes).
template <class Pdu>
Result<Pdu, DecodeError> decode_as(std::span<const std::uint8_t> bytes) {
  Pdu p;
  const DecodeError e = decode(bytes, p);
  if (e != DecodeError::None) return Result<Pdu, DecodeError>::failure(e);
  return Result<Pdu, DecodeError>::success(std::move(p));
}

// True for the PDU types decoded above.
bool is_supported_type(std::uint8_t pdu_type) noexcept;
// True for protocol versions 5 (1278.1-1995), 6 and 7.
bool is_supported_version(std::uint8_t protocol_version) noexcept;

}  // namespace net
