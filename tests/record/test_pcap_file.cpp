// record/pcap_file + ipv4_udp: what PcapWriter writes libpcap reads back (times, addresses,
// ports, payloads, header checksums); a file cut inside a frame is read up to the cut with a
// message; a file that is not a capture is refused; a killed writer's file ends at a whole frame.
#include <gtest/gtest.h>
#include <pcap/pcap.h>

#include <filesystem>
#include <fstream>

#include "net/codec.hpp"
#include "record/capture_check.hpp"
#include "record/pcap_file.hpp"
#include "record/replayer.hpp"
#include "support/scratch.hpp"

namespace {

using namespace npsnet::record;
namespace fs = std::filesystem;

fs::path temp(const std::string& name) {
  return npsnet::test::fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name()) / name;
}

std::vector<std::uint8_t> entity_state(std::uint16_t entity, std::uint8_t exercise = 1) {
  net::EntityStatePdu p;
  p.entity_id = {1, 2, entity};
  p.header.exercise_id = exercise;
  p.location = {-2700000.0 + entity, -4300000.0, 3800000.0};
  std::vector<std::uint8_t> b;
  net::encode_append(p, b);
  return b;
}

std::uint16_t ones_complement(std::span<const std::uint8_t> b, std::uint32_t sum = 0) {
  for (std::size_t i = 0; i + 1 < b.size(); i += 2) sum += (b[i] << 8) | b[i + 1];
  if (b.size() % 2) sum += b.back() << 8;
  while (sum >> 16) sum = (sum & 0xFFFF) + (sum >> 16);
  return static_cast<std::uint16_t>(sum);
}

TEST(PcapFile, WrittenFramesReadBackWithTimesAddressesAndValidChecksums) {
  const auto f = temp("rt.pcap");
  {
    PcapWriter w(f);
    for (std::uint16_t i = 1; i <= 50; ++i) {
      const auto pdu = entity_state(i);
      UdpPacket p{0x7F000001, 0xEF010203, static_cast<std::uint16_t>(40000 + i), 3000, pdu};
      ASSERT_TRUE(w.write(1700000000.0 + i * 0.01, p));
    }
    EXPECT_EQ(w.frames(), 50u);
  }
  // Raw libpcap: link type raw IPv4, every IPv4 header and UDP checksum verifies.
  char err[PCAP_ERRBUF_SIZE];
  pcap_t* p = pcap_open_offline(f.c_str(), err);
  ASSERT_NE(p, nullptr) << err;
  EXPECT_EQ(pcap_datalink(p), DLT_RAW);
  pcap_pkthdr* h;
  const u_char* d;
  int n = 0;
  while (pcap_next_ex(p, &h, &d) == 1) {
    ++n;
    std::span<const std::uint8_t> ip(d, h->caplen);
    EXPECT_EQ(ones_complement(ip.subspan(0, 20)), 0xFFFF) << "IPv4 header checksum, frame " << n;
    const std::size_t udp_len = (ip[24] << 8) | ip[25];
    EXPECT_EQ(udp_len, 8 + 144u);
    EXPECT_EQ((ip[2] << 8) | ip[3], 20 + 8 + 144);
    const std::uint32_t pseudo = ones_complement(ip.subspan(12, 8)) + 17 + static_cast<std::uint32_t>(udp_len);
    EXPECT_EQ(ones_complement(ip.subspan(20), pseudo), 0xFFFF) << "UDP checksum, frame " << n;
  }
  pcap_close(p);
  EXPECT_EQ(n, 50);
  // Our reader: payloads, times, addresses.
  PcapReader r(f);
  PcapFrame fr;
  int k = 0;
  while (r.next(fr)) {
    ++k;
    EXPECT_EQ(fr.number, static_cast<std::uint64_t>(k));
    EXPECT_NEAR(fr.time_s, 1700000000.0 + k * 0.01, 2e-6);
    EXPECT_EQ(fr.udp.src_addr, 0x7F000001u);
    EXPECT_EQ(fr.udp.dst_addr, 0xEF010203u);
    EXPECT_EQ(fr.udp.src_port, 40000 + k);
    EXPECT_EQ(fr.udp.dst_port, 3000);
    const auto want = entity_state(static_cast<std::uint16_t>(k));
    EXPECT_TRUE(std::equal(fr.udp.payload.begin(), fr.udp.payload.end(), want.begin(), want.end()));
  }
  EXPECT_EQ(k, 50);
  EXPECT_TRUE(r.error().empty()) << r.error();
  const auto rep = inspect_capture(f);
  EXPECT_EQ(rep.tally.pdus_of(1), 50u);
  EXPECT_EQ(rep.tally.entities(), 50u);
  EXPECT_EQ(rep.tally.malformed_total(), 0u);
  fs::remove_all(f.parent_path());
}

TEST(PcapFile, CutFileIsReadUpToTheCutWithAMessage) {
  const auto f = temp("cut.pcap");
  {
    PcapWriter w(f);
    for (std::uint16_t i = 1; i <= 10; ++i) {
      const auto pdu = entity_state(i);
      w.write(1700000000.0 + i, UdpPacket{0x7F000001, 0xEF010203, 40000, 3000, pdu});
    }
  }
  const auto full = fs::file_size(f);
  const auto frame = (full - 24) / 10;
  for (std::uintmax_t cut : {full - 30, full - frame + 7, full - frame - 3}) {  // inside a payload, a record header
    fs::copy_file(f, f.string() + ".cut", fs::copy_options::overwrite_existing);
    fs::resize_file(f.string() + ".cut", cut);
    PcapReader r(f.string() + ".cut");
    PcapFrame fr;
    int n = 0;
    while (r.next(fr)) ++n;
    const int whole = static_cast<int>((cut - 24) / frame);
    EXPECT_EQ(n, whole);
    EXPECT_NE(r.error().find("cut or damaged after frame " + std::to_string(whole)), std::string::npos) << r.error();
    const auto rep = inspect_capture(f.string() + ".cut");
    EXPECT_EQ(rep.tally.datagrams(), static_cast<std::uint64_t>(whole));
    EXPECT_FALSE(rep.cut.empty());
  }
  fs::remove_all(f.parent_path());
}

TEST(PcapFile, NotACaptureIsRefused) {
  const auto f = temp("text.pcap");
  std::ofstream(f) << "duration_s = 8.0\n";
  EXPECT_THROW(PcapReader r(f), NotACapture);
  EXPECT_THROW(inspect_capture(f), NotACapture);
  EXPECT_THROW(PcapReader r(f.parent_path() / "missing.pcap"), NotACapture);
  EXPECT_TRUE(looks_like_capture(f)) << "by its extension";
  fs::remove_all(f.parent_path());
}

TEST(PcapFile, MalformedPdusAreListedWithTheirFrame) {
  const auto f = temp("bad.pcap");
  {
    PcapWriter w(f);
    auto good = entity_state(1);
    auto bad = entity_state(2);
    bad[9] = 200;  // length 200 > 144 octets in the datagram
    w.write(1.0, UdpPacket{1, 2, 3, 4, good});
    w.write(2.0, UdpPacket{1, 2, 3, 4, bad});
    w.write(3.0, UdpPacket{1, 2, 3, 4, good});
  }
  const auto rep = inspect_capture(f);
  ASSERT_EQ(rep.tally.malformed().size(), 1u);
  EXPECT_EQ(rep.tally.malformed()[0].frame, 2u);
  EXPECT_EQ(rep.tally.malformed()[0].reason, "length_exceeds_data");
  fs::remove_all(f.parent_path());
}

TEST(PcapFile, KilledWriterLeavesWholeFrames) {
  // The writer flushes before its buffer would cut a record: whatever reached the disk is whole.
  const auto f = temp("killed.pcap");
  PcapWriter w(f);
  std::vector<std::uint8_t> big(1400, 7);
  for (int i = 0; i < 2000; ++i) {  // ~2.9 MB: several buffer flushes, no explicit flush()
    w.write(1.0 + i * 1e-3, UdpPacket{1, 2, 3, 4, big});
    if (i % 97 == 0) {
      const auto on_disk = fs::file_size(f);
      EXPECT_EQ((on_disk - 24) % (16 + 28 + 1400), 0u) << "after " << i << " frames";
    }
  }
  w.close();
  const auto rep = inspect_capture(f);
  EXPECT_EQ(rep.frames, 2000u);
  EXPECT_TRUE(rep.cut.empty());
  fs::remove_all(f.parent_path());
}

TEST(Replay, ExerciseRewriteTouchesEveryPduAndNothingElse) {
  auto a = entity_state(1, 1), b = entity_state(2, 1);
  std::vector<std::uint8_t> d(a);
  d.insert(d.end(), b.begin(), b.end());
  auto want = d;
  want[1] = 9, want[144 + 1] = 9;
  rewrite_exercise(d, 9);
  EXPECT_EQ(d, want);
  std::vector<std::uint8_t> junk(30, 0);  // length 0: stops after the first header
  rewrite_exercise(junk, 9);
  EXPECT_EQ(junk[1], 9);
  EXPECT_EQ(std::count(junk.begin(), junk.end(), 9), 1);
}

}  // namespace
