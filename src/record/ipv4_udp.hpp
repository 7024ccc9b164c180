// record/ipv4_udp.hpp — the IPv4 (RFC 791) and UDP (RFC 768) headers around one datagram's
// payload, as a capture file holds them, and back.
// Contract:
//  * build_ipv4_udp writes a 20-octet IPv4 header (no options, DF, TTL 1 as our exercises send,
//    protocol 17, header checksum) and an 8-octet UDP header (length, checksum over the pseudo
//    header; 0 is sent as 0xFFFF) before the payload; `out` is resized to 28 + payload octets
//    (payload at most 65507 octets, else false and `out` untouched).
//  * parse_ipv4_udp reads such a packet from any source: IPv4 with options, UDP, not a later
//    fragment; the payload is the UDP length's worth (cut to what was captured, `truncated` set).
//    Anything else is an error with a short reason; nothing in the bytes can make it read past
//    the span.
// Addresses and ports are host byte order.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace npsnet::record {

struct UdpPacket {
  std::uint32_t src_addr = 0, dst_addr = 0;
  std::uint16_t src_port = 0, dst_port = 0;
  std::span<const std::uint8_t> payload;
  bool truncated = false;  // the capture holds fewer octets than the UDP length says
};

inline constexpr std::size_t kIpv4UdpHeaders = 28;
inline constexpr std::size_t kMaxUdpPayload = 65535 - kIpv4UdpHeaders;

bool build_ipv4_udp(const UdpPacket& p, std::uint16_t ip_id, std::vector<std::uint8_t>& out);

enum class PacketError { None, NotIpv4, NotUdp, Fragment, Truncated };
std::string_view to_string(PacketError e) noexcept;

PacketError parse_ipv4_udp(std::span<const std::uint8_t> ip, UdpPacket& out) noexcept;

// "a.b.c.d" of a host-order address.
std::string dotted(std::uint32_t addr);

}  // namespace npsnet::record
