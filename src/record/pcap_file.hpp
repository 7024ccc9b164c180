// record/pcap_file.hpp — DIS datagrams in capture files, through libpcap (what Wireshark uses).
// Contract:
//  * PcapWriter(path) creates a classic pcap file, link type LINKTYPE_RAW (each frame an IPv4
//    packet: Wireshark and tshark decode IPv4 -> UDP -> DIS), microsecond timestamps, snaplen
//    65535. Throws std::runtime_error with the reason when the file cannot be created. write()
//    puts one datagram with its arrival time (UNIX seconds) behind real IPv4 + UDP headers
//    (see ipv4_udp.hpp). Writes go through a 1 MiB buffer that is flushed before it would
//    split a record, so the file on disk always ends at a whole frame: a recorder killed at any
//    moment leaves a readable file missing at most what came since the last flush().
//  * PcapReader(path) opens a pcap or pcapng file (libpcap reads both) and throws NotACapture
//    with libpcap's reason when it is neither. next() gives the UDP frames in file order with
//    their 1-based frame number and time (UNIX seconds, nanoseconds kept when the file has
//    them); link types raw IPv4, Ethernet (with 802.1Q), Linux cooked (SLL, SLL2) and BSD
//    loopback are understood, other frames are skipped and counted. At a cut (a file that ends
//    inside a frame) or damage, next() returns false and error() says where and why; at a clean
//    end error() is empty.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "record/ipv4_udp.hpp"

struct pcap;
struct pcap_dumper;

namespace npsnet::record {

class PcapWriter {
 public:
  explicit PcapWriter(const std::filesystem::path& path);
  ~PcapWriter();
  PcapWriter(const PcapWriter&) = delete;
  PcapWriter& operator=(const PcapWriter&) = delete;

  // false when the payload is too large for one IPv4 packet (nothing written).
  bool write(double unix_time_s, const UdpPacket& packet);
  void flush();
  void close();  // flushes and closes (also done by the destructor)

  std::uint64_t frames() const { return frames_; }
  std::uint64_t payload_bytes() const { return payload_bytes_; }
  std::uint64_t file_bytes() const { return file_bytes_; }

 private:
  pcap* dead_ = nullptr;
  pcap_dumper* dumper_ = nullptr;
  std::FILE* file_ = nullptr;
  std::vector<char> stdio_buffer_;
  std::vector<std::uint8_t> frame_;
  std::size_t buffered_ = 0;
  std::uint16_t ip_id_ = 0;
  std::uint64_t frames_ = 0, payload_bytes_ = 0, file_bytes_ = 0;
};

struct NotACapture : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct PcapFrame {
  std::uint64_t number = 0;  // 1-based, counting every frame of the file
  double time_s = 0;         // UNIX seconds
  UdpPacket udp;             // payload points into the reader: valid until the next next()
};

class PcapReader {
 public:
  explicit PcapReader(const std::filesystem::path& path);  // throws NotACapture
  ~PcapReader();
  PcapReader(const PcapReader&) = delete;
  PcapReader& operator=(const PcapReader&) = delete;

  bool next(PcapFrame& out);
  const std::string& error() const { return error_; }  // empty at a clean end
  std::uint64_t frames() const { return frames_; }      // frames read so far (all kinds)
  std::uint64_t skipped() const { return skipped_; }    // frames that are not IPv4/UDP
  const std::string& skipped_reason() const { return skipped_reason_; }  // the first one's
  int link_type() const { return link_type_; }

 private:
  pcap* p_ = nullptr;
  int link_type_ = 0;
  std::string error_;
  std::uint64_t frames_ = 0, skipped_ = 0;
  std::string skipped_reason_;
};

}  // namespace npsnet::record
