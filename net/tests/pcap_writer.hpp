// pcap_writer.hpp — test helper: a classic pcap file (Ethernet / IPv4 / UDP) around DIS payloads,
// for tshark to dissect. Addresses are made up (10.0.0.1 -> 239.1.2.3); nothing is sent anywhere.
#pragma once

#include <cstdint>
#include <fstream>
#include <span>
#include <string>
#include <vector>

namespace nettest {

class PcapWriter {
 public:
  explicit PcapWriter(const std::string& path) : out_(path, std::ios::binary) {
    le32(0xa1b2c3d4);  // magic, microsecond timestamps
    le16(2), le16(4);  // version 2.4
    le32(0), le32(0);  // thiszone, sigfigs
    le32(65535);       // snaplen
    le32(1);           // LINKTYPE_ETHERNET
  }
  bool ok() const { return static_cast<bool>(out_); }

  void add(std::span<const std::uint8_t> payload, std::uint16_t port = 3000) {
    std::vector<std::uint8_t> f;
    const std::uint8_t dst_mac[6] = {0x01, 0x00, 0x5e, 0x01, 0x02, 0x03};
    const std::uint8_t src_mac[6] = {0x02, 0x00, 0x00, 0x00, 0x00, 0x01};
    f.insert(f.end(), dst_mac, dst_mac + 6);
    f.insert(f.end(), src_mac, src_mac + 6);
    f.push_back(0x08), f.push_back(0x00);  // IPv4
    const std::size_t ip_len = 20 + 8 + payload.size();
    const std::size_t ip_at = f.size();
    const std::uint8_t ip[20] = {0x45, 0, std::uint8_t(ip_len >> 8), std::uint8_t(ip_len),
                                 std::uint8_t(id_ >> 8), std::uint8_t(id_), 0x40, 0,  // DF
                                 1, 17, 0, 0,                                        // TTL 1, UDP
                                 10, 0, 0, 1, 239, 1, 2, 3};
    ++id_;
    f.insert(f.end(), ip, ip + 20);
    std::uint32_t sum = 0;
    for (std::size_t i = 0; i < 20; i += 2) sum += (f[ip_at + i] << 8) | f[ip_at + i + 1];
    while (sum >> 16) sum = (sum & 0xFFFF) + (sum >> 16);
    const std::uint16_t csum = static_cast<std::uint16_t>(~sum);
    f[ip_at + 10] = std::uint8_t(csum >> 8), f[ip_at + 11] = std::uint8_t(csum);
    const std::size_t udp_len = 8 + payload.size();
    const std::uint8_t udp[8] = {std::uint8_t(port >> 8), std::uint8_t(port), std::uint8_t(port >> 8),
                                 std::uint8_t(port), std::uint8_t(udp_len >> 8), std::uint8_t(udp_len),
                                 0, 0};  // checksum 0: not computed (allowed in IPv4)
    f.insert(f.end(), udp, udp + 8);
    f.insert(f.end(), payload.begin(), payload.end());
    le32(1700000000u + frames_), le32(0);
    le32(static_cast<std::uint32_t>(f.size())), le32(static_cast<std::uint32_t>(f.size()));
    out_.write(reinterpret_cast<const char*>(f.data()), static_cast<std::streamsize>(f.size()));
    ++frames_;
  }
  void close() { out_.close(); }

 private:
  void le16(std::uint16_t v) {
    const char b[2] = {char(v), char(v >> 8)};
    out_.write(b, 2);
  }
  void le32(std::uint32_t v) {
    const char b[4] = {char(v), char(v >> 8), char(v >> 16), char(v >> 24)};
    out_.write(b, 4);
  }
  std::ofstream out_;
  std::uint16_t id_ = 1;
  std::uint32_t frames_ = 0;
};

}  // namespace nettest
