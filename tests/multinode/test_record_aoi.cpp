// `npsnet record --aoi` (issue 15) on loopback multicast (--iface 127.0.0.1, a random port, cell
// groups from 239.1.2.3 up): two `npsnet run --aoi 2000` nodes (tests/multinode/data/
// record_aoi.toml), each publishing into its own cell's group. A recorder with --aoi joins every
// cell group and records them all into one pcap, each frame with the group it was sent to as its
// IP destination; tshark decodes it with no malformed frame and as many DIS PDUs as the nodes'
// counters say they sent. A recorder without --aoi (the --net group only) misses them.
#include <gtest/gtest.h>
#include <signal.h>

#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "support/dirs.hpp"
#include "lan_support.hpp"
#include "net/aoi.hpp"
#include "../net/tests/run_command.hpp"  // nettest::run_command: a shell command's exit code and stdout

namespace {

namespace fs = std::filesystem;
const fs::path kData = fs::path(npsnet::dirs::source()) / "tests" / "multinode" / "data";

// PDUs a node sent, from its counters line ("| sent entity_state=N fire=M ... datagrams=D").
long sent_pdus(const std::string& out) {
  const auto at = out.find("| sent ");
  if (at == std::string::npos) return -1;
  const std::string line = out.substr(at + 7, out.find('\n', at) - at - 7);
  const std::string rest = line.substr(0, line.find('|'));  // not the "| aoi groups=..." after it
  long n = 0;
  const std::regex kv("([a-z_0-9]+)=([0-9]+)");
  for (std::sregex_iterator it(rest.begin(), rest.end(), kv), end; it != end; ++it)
    if ((*it)[1] != "datagrams" && (*it)[1] != "failures") n += std::stol((*it)[2]);
  return n;
}

}  // namespace

TEST(RecordAoi, EveryCellGroupInOneCaptureWithItsTrueDestination) {
  if (nettest::run_command("command -v tshark >/dev/null 2>&1").rc != 0) GTEST_SKIP() << "tshark is not installed";
  const fs::path dir = lan::fresh_dir("record_aoi");
  const int port = lan::random_port();
  const std::string url = "udp://239.1.2.3:" + std::to_string(port);
  lan::Procs procs;
  const int rec = procs.start({"record", "--aoi", "--net", url, "--iface", "127.0.0.1", "--seconds", "40",
                               (dir / "aoi.pcap").string()}, dir / "out_rec.txt");
  const int flat = procs.start({"record", "--net", url, "--iface", "127.0.0.1", "--seconds", "40",
                                (dir / "flat.pcap").string()}, dir / "out_flat.txt");
  const double start = lan::unix_now() + 2.0;
  char s[64];
  std::snprintf(s, sizeof s, "%.3f", start);
  std::vector<int> nodes;
  for (int n = 1; n <= 2; ++n)
    nodes.push_back(procs.start({"run", "--scenario", (kData / "record_aoi.toml").string(), "--net", url, "--iface",
                                 "127.0.0.1", "--node", std::to_string(n), "--aoi", "2000", "--start-at", s,
                                 "--no-render", "--events", (dir / ("events_" + std::to_string(n) + ".jsonl")).string(),
                                 "--snapshots", (dir / "snap").string()},
                                dir / ("out_" + std::to_string(n) + ".txt")));
  long sent = 0;
  for (int n = 1; n <= 2; ++n) {
    const fs::path out = dir / ("out_" + std::to_string(n) + ".txt");
    ASSERT_EQ(procs.wait(nodes[n - 1], 40.0), 0) << lan::read_text(out);
    const long k = sent_pdus(lan::read_text(out));
    ASSERT_GT(k, 0) << lan::read_text(out);
    EXPECT_NE(lan::read_text(out).find("aoi groups="), std::string::npos) << "the node ran with AOI";
    sent += k;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(rec, SIGINT);
  ::kill(flat, SIGINT);
  ASSERT_EQ(procs.wait(rec, 10.0), 0) << lan::read_text(dir / "out_rec.txt");
  ASSERT_EQ(procs.wait(flat, 10.0), 0) << lan::read_text(dir / "out_flat.txt");
  const std::string rec_out = lan::read_text(dir / "out_rec.txt");
  EXPECT_NE(rec_out.find("groups: 1024 joined"), std::string::npos) << rec_out;

  // tshark: no malformed frame, every PDU the nodes sent.
  const std::string f = (dir / "aoi.pcap").string();
  const std::string decode = "tshark -r '" + f + "' -d udp.port==" + std::to_string(port) + ",dis";
  const auto malformed = nettest::run_command(decode + " -Y _ws.malformed 2>/dev/null");
  EXPECT_EQ(malformed.rc, 0);
  EXPECT_EQ(malformed.out, "") << "tshark marks frames malformed";
  const auto pdus = nettest::run_command(decode + " -Y dis -T fields -e dis.pdu_type 2>/dev/null | wc -l");
  EXPECT_EQ(std::stol(pdus.out), sent) << "DIS PDUs in the recording vs sent by the nodes\n" << rec_out;

  // Each frame's IP destination is the group of the cell its PDU was published into.
  const auto grid = net::AoiGrid::make("239.1.2.3", 2000.0, 1024);
  ASSERT_TRUE(grid.ok()) << grid.error();
  const std::string g1 = grid.value().address_text(grid.value().group_of(5000.0, 5000.0));
  const std::string g2 = grid.value().address_text(grid.value().group_of(35000.0, 35000.0));
  ASSERT_NE(g1, "239.1.2.3");
  ASSERT_NE(g2, "239.1.2.3");
  const auto fields = nettest::run_command(decode + " -Y dis -T fields -E 'separator=;' -e ip.dst -e dis.pdu_type "
                                           "-e dis.entity_marking -e udp.dstport 2>/dev/null");
  std::map<std::string, std::set<std::string>> dst_of;  // "pdu type marking" -> destinations
  std::set<std::string> all_dst;
  std::istringstream lines(fields.out);
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> v;
    std::stringstream ls(line);
    for (std::string x; std::getline(ls, x, ';');) v.push_back(x);
    ASSERT_EQ(v.size(), 4u) << line;
    EXPECT_EQ(v[3], std::to_string(port)) << line;
    dst_of[v[1] + " " + v[2]].insert(v[0]);
    all_dst.insert(v[0]);
  }
  EXPECT_EQ(dst_of["1 t1"], std::set<std::string>{g1}) << "t1's Entity States, cell (2, 2)";
  EXPECT_EQ(dst_of["1 t2"], std::set<std::string>{g2}) << "t2's Entity States, cell (17, 17)";
  EXPECT_EQ(dst_of["2 "], std::set<std::string>{g1}) << "the Fire PDU, in t1's cell";
  EXPECT_EQ(dst_of["3 "], std::set<std::string>{g1}) << "the Detonation, in cell (2, 2)";
  EXPECT_EQ(all_dst, (std::set<std::string>{g1, g2}));
  EXPECT_NE(rec_out.find(g1 + " ("), std::string::npos) << rec_out;
  EXPECT_NE(rec_out.find(g2 + " ("), std::string::npos) << rec_out;

  // npsnet check agrees; the recorder without --aoi heard none of it (only the --net group).
  const auto chk = nettest::run_command(lan::npsnet_binary().string() + " check '" + f + "' 2>&1");
  EXPECT_EQ(chk.rc, 0) << chk.out;
  EXPECT_NE(chk.out.find(std::to_string(sent) + " DIS PDUs"), std::string::npos) << chk.out;
  EXPECT_NE(chk.out.find("malformed PDUs: 0"), std::string::npos) << chk.out;
  const std::string flat_out = lan::read_text(dir / "out_flat.txt");
  EXPECT_NE(flat_out.find("record: 0 datagrams"), std::string::npos) << flat_out;
  fs::remove_all(dir);
}
