#include "record/capture_check.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "record/pcap_file.hpp"

namespace npsnet::record {

bool looks_like_capture(const std::filesystem::path& f) {
  std::string e = f.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (e == ".pcap" || e == ".pcapng" || e == ".cap") return true;
  std::ifstream in(f, std::ios::binary);
  unsigned char m[4] = {0, 0, 0, 0};
  if (!in.read(reinterpret_cast<char*>(m), 4)) return false;
  const std::uint32_t le = m[0] | (m[1] << 8) | (m[2] << 16) | (std::uint32_t{m[3]} << 24);
  const std::uint32_t be = (std::uint32_t{m[0]} << 24) | (m[1] << 16) | (m[2] << 8) | m[3];
  for (std::uint32_t magic : {0xa1b2c3d4u, 0xa1b23c4du, 0x0a0d0d0au})
    if (le == magic || be == magic) return true;
  return false;
}

CaptureReport inspect_capture(const std::filesystem::path& path) {
  CaptureReport r;
  PcapReader rd(path);
  PcapFrame f;
  bool first = true;
  while (rd.next(f)) {
    if (first) r.first_s = f.time_s, first = false;
    r.last_s = f.time_s;
    if (f.udp.truncated && r.cut_short.size() < PduTally::kMaxListed) r.cut_short.push_back(f.number);
    r.tally.add(f.udp.payload, f.number);
  }
  r.frames = rd.frames();
  r.not_udp = rd.skipped();
  r.not_udp_first = rd.skipped_reason();
  r.cut = rd.error();
  return r;
}

std::string CaptureReport::summary(const std::filesystem::path& f) const {
  char b[512];
  std::snprintf(b, sizeof b, "%s: %llu frames over %.3f s: %llu UDP datagrams, %llu DIS PDUs, %zu entities, %llu octets",
                f.string().c_str(), (unsigned long long)frames, last_s - first_s,
                (unsigned long long)tally.datagrams(), (unsigned long long)tally.pdus(), tally.entities(),
                (unsigned long long)tally.bytes());
  std::string s = b;
  s += "\n  PDUs by type: " + tally.by_type_text();
  s += "\n  malformed PDUs: " + std::to_string(tally.malformed_total());
  if (not_udp) s += "\n  frames that are not IPv4/UDP (ignored): " + std::to_string(not_udp) + ", first " + not_udp_first;
  return s;
}

}  // namespace npsnet::record
