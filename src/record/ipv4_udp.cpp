#include "record/ipv4_udp.hpp"

#include <string>

namespace npsnet::record {

namespace {
std::uint32_t sum16(std::span<const std::uint8_t> b, std::uint32_t sum = 0) {
  std::size_t i = 0;
  for (; i + 1 < b.size(); i += 2) sum += (std::uint32_t{b[i]} << 8) | b[i + 1];
  if (i < b.size()) sum += std::uint32_t{b[i]} << 8;
  return sum;
}
std::uint16_t fold(std::uint32_t sum) {
  while (sum >> 16) sum = (sum & 0xFFFF) + (sum >> 16);
  return static_cast<std::uint16_t>(~sum);
}
void be16(std::uint8_t* p, std::uint32_t v) { p[0] = std::uint8_t(v >> 8), p[1] = std::uint8_t(v); }
void be32(std::uint8_t* p, std::uint32_t v) { be16(p, v >> 16), be16(p + 2, v); }
std::uint32_t rd16(const std::uint8_t* p) { return (std::uint32_t{p[0]} << 8) | p[1]; }
std::uint32_t rd32(const std::uint8_t* p) { return (rd16(p) << 16) | rd16(p + 2); }
}  // namespace

bool build_ipv4_udp(const UdpPacket& p, std::uint16_t ip_id, std::vector<std::uint8_t>& out) {
  if (p.payload.size() > kMaxUdpPayload) return false;
  const std::size_t udp_len = 8 + p.payload.size();
  out.resize(kIpv4UdpHeaders + p.payload.size());
  std::uint8_t* ip = out.data();
  ip[0] = 0x45, ip[1] = 0;  // version 4, IHL 5; DSCP/ECN 0
  be16(ip + 2, static_cast<std::uint32_t>(20 + udp_len));
  be16(ip + 4, ip_id);
  be16(ip + 6, 0x4000);  // DF, offset 0
  ip[8] = 1, ip[9] = 17;  // TTL 1, UDP
  be16(ip + 10, 0);
  be32(ip + 12, p.src_addr);
  be32(ip + 16, p.dst_addr);
  be16(ip + 10, fold(sum16({ip, 20})));
  std::uint8_t* udp = ip + 20;
  be16(udp, p.src_port);
  be16(udp + 2, p.dst_port);
  be16(udp + 4, static_cast<std::uint32_t>(udp_len));
  be16(udp + 6, 0);
  if (!p.payload.empty()) std::copy(p.payload.begin(), p.payload.end(), udp + 8);
  // Pseudo header: source, destination, zero + protocol, UDP length.
  std::uint32_t s = sum16({ip + 12, 8}) + 17 + static_cast<std::uint32_t>(udp_len);
  std::uint16_t c = fold(sum16({udp, udp_len}, s));
  be16(udp + 6, c == 0 ? 0xFFFF : c);
  return true;
}

std::string_view to_string(PacketError e) noexcept {
  switch (e) {
    case PacketError::None: return "none";
    case PacketError::NotIpv4: return "not IPv4";
    case PacketError::NotUdp: return "not UDP";
    case PacketError::Fragment: return "IPv4 fragment";
    case PacketError::Truncated: return "IPv4/UDP headers cut short";
  }
  return "unknown";
}

PacketError parse_ipv4_udp(std::span<const std::uint8_t> ip, UdpPacket& out) noexcept {
  if (ip.size() < 20) return PacketError::Truncated;
  if ((ip[0] >> 4) != 4) return PacketError::NotIpv4;
  const std::size_t ihl = std::size_t{ip[0] & 0x0Fu} * 4;
  if (ihl < 20) return PacketError::NotIpv4;
  if (ip[9] != 17) return PacketError::NotUdp;
  const std::uint32_t frag = rd16(&ip[6]);
  if ((frag & 0x1FFF) != 0 || (frag & 0x2000) != 0) return PacketError::Fragment;
  if (ip.size() < ihl + 8) return PacketError::Truncated;
  const std::uint8_t* udp = ip.data() + ihl;
  out.src_addr = rd32(&ip[12]);
  out.dst_addr = rd32(&ip[16]);
  out.src_port = static_cast<std::uint16_t>(rd16(udp));
  out.dst_port = static_cast<std::uint16_t>(rd16(udp + 2));
  const std::size_t udp_len = rd16(udp + 4);
  if (udp_len < 8) return PacketError::Truncated;
  const std::size_t have = ip.size() - ihl - 8;
  const std::size_t want = udp_len - 8;
  out.truncated = have < want;
  out.payload = ip.subspan(ihl + 8, out.truncated ? have : want);
  return PacketError::None;
}

std::string dotted(std::uint32_t a) {
  return std::to_string(a >> 24) + "." + std::to_string((a >> 16) & 0xFF) + "." + std::to_string((a >> 8) & 0xFF) +
         "." + std::to_string(a & 0xFF);
}

}  // namespace npsnet::record
