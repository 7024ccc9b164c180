#include "record/pcap_file.hpp"

#include <pcap/pcap.h>

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstring>

namespace npsnet::record {

namespace {
constexpr std::size_t kBuffer = 1 << 20;  // stdio buffer of the writer, octets
constexpr std::size_t kRecordHeader = 16;  // pcap per-frame header
constexpr int kSnaplen = 65535;

// The IPv4 packet inside a frame of link type `dlt`, or an empty span with a reason.
std::span<const std::uint8_t> ipv4_of(int dlt, std::span<const std::uint8_t> f, std::string& why) {
  auto u16 = [&](std::size_t at) { return at + 2 <= f.size() ? (unsigned{f[at]} << 8) | f[at + 1] : 0u; };
  switch (dlt) {
    case DLT_RAW:
    case DLT_IPV4: return f;
    case DLT_EN10MB: {
      std::size_t at = 12;
      unsigned type = u16(at);
      while ((type == 0x8100 || type == 0x88A8) && at + 6 <= f.size()) at += 4, type = u16(at);
      if (type == 0x0800 && at + 2 <= f.size()) return f.subspan(at + 2);
      why = "Ethernet frame without IPv4";
      return {};
    }
    case DLT_LINUX_SLL:
      if (u16(14) == 0x0800 && f.size() >= 16) return f.subspan(16);
      why = "Linux cooked frame without IPv4";
      return {};
    case DLT_LINUX_SLL2:
      if (u16(0) == 0x0800 && f.size() >= 20) return f.subspan(20);
      why = "Linux cooked v2 frame without IPv4";
      return {};
    case DLT_NULL:
    case DLT_LOOP: {
      if (f.size() < 4) break;
      std::uint32_t af = 0;
      if (dlt == DLT_LOOP) af = (std::uint32_t{f[0]} << 24) | (f[1] << 16) | (f[2] << 8) | f[3];
      else std::memcpy(&af, f.data(), 4);  // host order of the writer: accept either order
      if (af == 2 || af == 0x02000000) return f.subspan(4);
      why = "loopback frame without IPv4";
      return {};
    }
    default: break;
  }
  why = std::string("link type ") + (pcap_datalink_val_to_name(dlt) ? pcap_datalink_val_to_name(dlt) : "?") +
        " is not read (raw IPv4, Ethernet, Linux cooked or loopback are)";
  return {};
}
}  // namespace

PcapWriter::PcapWriter(const std::filesystem::path& path) {
  dead_ = pcap_open_dead_with_tstamp_precision(DLT_RAW, kSnaplen, PCAP_TSTAMP_PRECISION_MICRO);
  if (!dead_) throw std::runtime_error("libpcap: cannot set up a raw-IPv4 capture");
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) {
    const std::string why = std::strerror(errno);
    pcap_close(dead_);
    throw std::runtime_error("cannot create " + path.string() + ": " + why);
  }
  stdio_buffer_.resize(kBuffer);
  std::setvbuf(file_, stdio_buffer_.data(), _IOFBF, stdio_buffer_.size());
  dumper_ = pcap_dump_fopen(dead_, file_);
  if (!dumper_) {
    const std::string why = pcap_geterr(dead_);
    std::fclose(file_);
    pcap_close(dead_);
    throw std::runtime_error("cannot write a pcap header to " + path.string() + ": " + why);
  }
  buffered_ = 24;  // the file header
  file_bytes_ = 24;
  flush();
}

PcapWriter::~PcapWriter() { close(); }

bool PcapWriter::write(double t, const UdpPacket& p) {
  if (!dumper_ || !build_ipv4_udp(p, ip_id_, frame_)) return false;
  ++ip_id_;
  const std::size_t rec = kRecordHeader + frame_.size();
  if (buffered_ + rec > kBuffer) flush();  // never let stdio cut a record in two
  pcap_pkthdr h{};
  const double whole = std::floor(t);
  h.ts.tv_sec = static_cast<time_t>(whole);
  h.ts.tv_usec = static_cast<suseconds_t>(std::min(999999.0, std::round((t - whole) * 1e6)));
  h.caplen = h.len = static_cast<bpf_u_int32>(frame_.size());
  pcap_dump(reinterpret_cast<u_char*>(dumper_), &h, frame_.data());
  buffered_ += rec;
  file_bytes_ += rec;
  ++frames_;
  payload_bytes_ += p.payload.size();
  return true;
}

void PcapWriter::flush() {
  if (dumper_) pcap_dump_flush(dumper_);
  buffered_ = 0;
}

void PcapWriter::close() {
  if (dumper_) {
    flush();
    pcap_dump_close(dumper_);  // closes file_ too
    dumper_ = nullptr;
    file_ = nullptr;
  }
  if (dead_) pcap_close(dead_), dead_ = nullptr;
}

PcapReader::PcapReader(const std::filesystem::path& path) {
  char err[PCAP_ERRBUF_SIZE] = {0};
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw NotACapture("a folder, not a capture file");
  p_ = pcap_open_offline_with_tstamp_precision(path.c_str(), PCAP_TSTAMP_PRECISION_NANO, err);
  if (!p_) throw NotACapture(std::string("not a pcap or pcapng file (libpcap: ") + err + ")");
  link_type_ = pcap_datalink(p_);
}

PcapReader::~PcapReader() {
  if (p_) pcap_close(p_);
}

bool PcapReader::next(PcapFrame& out) {
  if (!p_) return false;
  for (;;) {
    pcap_pkthdr* h = nullptr;
    const u_char* data = nullptr;
    const int r = pcap_next_ex(p_, &h, &data);
    if (r == PCAP_ERROR_BREAK) return false;  // clean end
    if (r != 1) {
      error_ = "cut or damaged after frame " + std::to_string(frames_) + " (libpcap: " + pcap_geterr(p_) +
               "); read " + std::to_string(frames_) + " whole frames up to there";
      return false;
    }
    ++frames_;
    std::string why;
    const auto ip = ipv4_of(link_type_, {data, h->caplen}, why);
    PacketError pe = PacketError::NotIpv4;
    if (!ip.empty()) pe = parse_ipv4_udp(ip, out.udp);
    if (pe != PacketError::None) {
      if (skipped_++ == 0) skipped_reason_ = "frame " + std::to_string(frames_) + ": " + (why.empty() ? std::string(to_string(pe)) : why);
      continue;
    }
    out.number = frames_;
    out.time_s = static_cast<double>(h->ts.tv_sec) + static_cast<double>(h->ts.tv_usec) * 1e-9;
    return true;
  }
}

}  // namespace npsnet::record
