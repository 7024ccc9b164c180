// Our cultural-feature Entity States as Wireshark's DIS dissector reads them (issue 10, defect 6:
// damage in the standard appearance bits 3-4), through the real path: node 1 runs
// tests/multinode/data/cultural.toml on loopback multicast, its tank shells the ground beside
// two buildings and a tree, and a listener on the group keeps every datagram the node sends;
// they go into a pcap (Ethernet/IPv4/UDP around each datagram, as captured) and tshark decodes
// them. Expected, per object (entity = object index + 1, application 0x8000 | 1): b1 damaged_low
// then destroyed (damage 1, 3), tr1 damaged then stump (1, 3), b2 damaged_med (2): appearance
// 0x08, 0x18, 0x10, no other bit set, entity kind 5. Skipped (with a message) only without tshark.
#include <gtest/gtest.h>

#include <map>

#include "../net/tests/pcap_writer.hpp"
#include "../net/tests/run_command.hpp"
#include "peer_support.hpp"

TEST(FederateTshark, OurCulturalFeaturesCarryDamageInAppearanceBits3And4) {
  if (!nettest::have_tool("tshark")) GTEST_SKIP() << "tshark is not installed: wire test skipped";
  fed::Federate f("fed_tshark", "cultural.toml", 3.5);
  auto& node = f.node;
  auto& listener = f.peer;
  const std::string pcap = (node.dir / "sent.pcap").string();
  size_t datagrams = 0;
  {
    nettest::PcapWriter out(pcap);
    ASSERT_TRUE(out.ok()) << pcap;
    for (int i = 0; i < 1000 && lan::unix_now() < node.start + 4.0; ++i) {
      listener.poll_datagrams([&](std::span<const std::uint8_t> d) {
        out.add(d, static_cast<std::uint16_t>(node.port));
        ++datagrams;
      });
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  ASSERT_TRUE(f.finished());
  ASSERT_GT(datagrams, 0u);
  const std::string decode = "tshark -r '" + pcap + "' -d udp.port==" + std::to_string(node.port) + ",dis";
  const auto malformed = nettest::run_command(decode + " -Y _ws.malformed 2>/dev/null");
  EXPECT_EQ(malformed.rc, 0);
  EXPECT_EQ(malformed.out, "") << "tshark marks frames malformed";
  const auto r = nettest::run_command(decode + " -Y 'dis.pdu_type == 1 && dis.entity_id_application == 32769'" +
                                      " -T fields -E separator='|' -E occurrence=f -e dis.entity_id_entity" +
                                      " -e dis.entityKind -e dis.appearance 2>/dev/null");
  ASSERT_EQ(r.rc, 0);
  std::map<int, std::vector<unsigned long>> seen;  // entity -> appearance values, repeats merged
  for (const auto& line : nettest::split(r.out, '\n')) {
    const auto f = nettest::split(line, '|');
    if (f.size() != 3) continue;
    EXPECT_EQ(f[1], "5") << line << ": a cultural feature";
    auto& v = seen[std::stoi(f[0])];
    const unsigned long app = std::stoul(f[2], nullptr, 16);
    if (v.empty() || v.back() != app) v.push_back(app);
  }
  using V = std::vector<unsigned long>;
  EXPECT_EQ(seen[1], (V{1u << 3, 3u << 3})) << "b1: damaged_low (slight), then destroyed\n" << r.out;
  EXPECT_EQ(seen[2], (V{1u << 3, 3u << 3})) << "tr1: damaged (slight), then stump (destroyed)\n" << r.out;
  EXPECT_EQ(seen[3], (V{2u << 3})) << "b2: damaged_med (moderate)\n" << r.out;
  EXPECT_EQ(seen.size(), 3u) << r.out;
  // What the node logged agrees: each change of a fixed object is a damage event.
  std::map<std::string, std::vector<std::string>> logged;
  for (const auto& d : fed::of_type(f.events(), "damage"))
    logged[d["object"].get<std::string>()].push_back(d["to_state"]);
  EXPECT_EQ(logged["b1"], (std::vector<std::string>{"damaged_low", "destroyed"}));
  EXPECT_EQ(logged["tr1"], (std::vector<std::string>{"damaged", "stump"}));
  EXPECT_EQ(logged["b2"], (std::vector<std::string>{"damaged_med"}));
}
