// Record and replay (npsnet record / replay / check FILE.pcap) on loopback multicast
// (239.1.2.3, a random port, --iface 127.0.0.1), tests/multinode/data/record.toml.
// One live exercise is run once for the suite: nodes 1 and 2 play it, node 3 (no vehicles of
// its own) watches, `npsnet record` records it and ends on SIGINT, a second recorder is killed
// (SIGKILL) half-way. Then: tshark decodes the recording with no malformed frame and as many DIS
// PDUs as the nodes' counters say they sent; the recording replayed into a fresh node 3 gives
// that node the same remote entities, collisions, crater and tree state as the live node 3; the
// killed recorder's file is readable; a cut recording is read up to the cut; a file that is not
// a capture is refused with exit 2; `run --replay` of the recording as node 1 logs what the live
// node 1 logged (joins, collisions, crater) and writes the collision snapshots, and with --drive
// t1b its start view and periodic frames are t1b's.
#include <gtest/gtest.h>
#include <signal.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <set>
#include <thread>

#include "support/dirs.hpp"
#include "lan_support.hpp"
#include "../net/tests/run_command.hpp"  // nettest::run_command: a shell command's exit code and stdout

namespace {

using lan::of_type;
using nlohmann::json;
namespace fs = std::filesystem;
const fs::path kData = fs::path(npsnet::dirs::source()) / "tests" / "multinode" / "data";

nettest::CommandResult sh(const std::string& cmd) { return nettest::run_command(cmd); }
std::string npsnet() { return lan::npsnet_binary().string(); }

std::vector<std::string> node_args(int port, int node, double start_at, double seconds, const fs::path& dir,
                                   const std::string& tag) {
  char s[64];
  std::snprintf(s, sizeof s, "%.3f", start_at);
  return {"run", "--scenario", (kData / "record.toml").string(), "--net", "udp://239.1.2.3:" + std::to_string(port),
          "--iface", "127.0.0.1", "--node", std::to_string(node), "--start-at", s, "--no-render",
          "--seconds", std::to_string(seconds), "--events", (dir / ("events_" + tag + ".jsonl")).string(),
          "--snapshots", (dir / ("snap_" + tag)).string()};
}

// PDUs a node sent, from its counters line ("| sent entity_state=N fire=M ... datagrams=D").
long sent_pdus(const std::string& out) {
  const auto at = out.find("| sent ");
  if (at == std::string::npos) return -1;
  const std::string rest = out.substr(at + 7, out.find('\n', at) - at - 7);
  long n = 0;
  const std::regex kv("([a-z_0-9]+)=([0-9]+)");
  for (std::sregex_iterator it(rest.begin(), rest.end(), kv), end; it != end; ++it)
    if ((*it)[1] != "datagrams" && (*it)[1] != "failures") n += std::stol((*it)[2]);
  return n;
}

// What a watching node saw: joins, collisions (pair -> outcomes), craters, tree2's last state.
struct Seen {
  std::set<std::string> joined;
  std::set<std::string> collisions;
  std::vector<json> craters;
  std::string tree2;
};
Seen seen(const std::vector<json>& ev) {
  Seen s;
  for (const auto& e : of_type(ev, "entity_joined")) s.joined.insert(e["id"].get<std::string>());
  for (const auto& e : of_type(ev, "collision")) {
    std::string a = e["a"], b = e["b"], oa = e["outcome_a"], ob = e["outcome_b"];
    if (b < a) std::swap(a, b), std::swap(oa, ob);
    s.collisions.insert(a + "/" + b + ":" + oa + "/" + ob);
  }
  s.craters = of_type(ev, "crater");
  for (const auto& d : of_type(ev, "damage"))
    if (d["object"] == "tree2") s.tree2 = d["to_state"];
  return s;
}

// The live exercise, recorded (see the top of this file).
fs::path dir;
int port = 0;
double start = 0;
long nodes_sent = 0;  // PDUs the three nodes' counters say they sent

// Returns why the live exercise could not be recorded, or "".
std::string record_live_exercise() {
  std::string fail;
  dir = lan::fresh_dir("record");
  port = lan::random_port();
  lan::Procs procs;
  const std::string url = "udp://239.1.2.3:" + std::to_string(port);
  const int rec = procs.start({"record", "--net", url, "--iface", "127.0.0.1", "--seconds", "40",
                               (dir / "rec.pcap").string()}, dir / "out_rec.txt");
  const int killed = procs.start({"record", "--net", url, "--iface", "127.0.0.1", (dir / "killed.pcap").string()},
                                 dir / "out_killed.txt");
  start = lan::unix_now() + 2.0;
  std::vector<int> pids;
  for (int n = 1; n <= 3; ++n)
    pids.push_back(procs.start(node_args(port, n, start, 8, dir, std::to_string(n)), dir / ("out_" + std::to_string(n) + ".txt")));
  while (lan::unix_now() < start + 4.0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  procs.kill_now(killed);  // half-way through the exercise
  for (int n = 1; n <= 3; ++n)
    if (procs.wait(pids[n - 1], 40.0) != 0) fail += "node " + std::to_string(n) + " failed: " + lan::read_text(dir / ("out_" + std::to_string(n) + ".txt"));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(rec, SIGINT);
  if (const int rc = procs.wait(rec, 10.0); rc != 0) fail += "recorder exit " + std::to_string(rc) + ": " + lan::read_text(dir / "out_rec.txt");
  for (int n = 1; n <= 3; ++n) {
    const long s = sent_pdus(lan::read_text(dir / ("out_" + std::to_string(n) + ".txt")));
    if (s < 0) fail += "no counters from node " + std::to_string(n);
    nodes_sent += s;
  }
  return fail;
}

void TsharkDecodesTheRecordingWithEveryPduTheNodesSent() {
  if (sh("command -v tshark >/dev/null 2>&1").rc != 0) GTEST_SKIP() << "tshark is not installed";
  const std::string f = (dir / "rec.pcap").string();
  const std::string decode = " -d udp.port==" + std::to_string(port) + ",dis";
  const auto malformed = sh("tshark -r '" + f + "'" + decode + " -Y _ws.malformed 2>/dev/null");
  EXPECT_EQ(malformed.rc, 0);
  EXPECT_EQ(malformed.out, "") << "tshark marks frames malformed";
  const auto types = sh("tshark -r '" + f + "'" + decode + " -Y dis -T fields -e dis.pdu_type 2>/dev/null | wc -l");
  EXPECT_GT(nodes_sent, 20);
  EXPECT_EQ(std::stol(types.out), nodes_sent) << "DIS PDUs in the recording vs sent by the nodes";
  // Real headers: the sender's loopback address and an ephemeral port, the group and its port.
  const auto ip = sh("tshark -r '" + f + "'" + decode + " -c 1 -T fields -e ip.src -e ip.dst -e udp.dstport -e udp.checksum.status -o udp.check_checksum:TRUE 2>/dev/null");
  EXPECT_EQ(ip.out, "127.0.0.1\t239.1.2.3\t" + std::to_string(port) + "\t1\n") << "1 = checksum good";
  // The recorder's own summary and `npsnet check` agree.
  const std::string rec = lan::read_text(dir / "out_rec.txt");
  EXPECT_NE(rec.find(std::to_string(nodes_sent) + " PDUs"), std::string::npos) << rec;
  EXPECT_NE(rec.find("fire=1"), std::string::npos) << rec;
  // One round, its Detonation sent again by its firing node (the repair of a lost datagram,
  // repeat_ledger.hpp): twice 0.5 s apart, then every heartbeat (5 s): 1 to 4 times in this 8 s run.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(rec, m, std::regex(R"(detonation=(\d+))"))) << rec;
  EXPECT_GE(std::stoi(m[1]), 1);
  EXPECT_LE(std::stoi(m[1]), 4);
  const auto chk = sh(npsnet() + " check '" + f + "' 2>&1");
  EXPECT_EQ(chk.rc, 0) << chk.out;
  // 7 to 9 entities: the six vehicles and tree2 as a cultural feature once run down, published by
  // the node that ran it down and, once heard, by each other node too (so it outlives its first
  // publisher): up to three publishers in this run.
  ASSERT_TRUE(std::regex_search(chk.out, m, std::regex(std::to_string(nodes_sent) + R"( DIS PDUs, (\d+) entities)"))) << chk.out;
  EXPECT_GE(std::stoi(m[1]), 7);
  EXPECT_LE(std::stoi(m[1]), 9);
  EXPECT_NE(chk.out.find("malformed PDUs: 0"), std::string::npos) << chk.out;
}

void ReplayIntoAThirdNodeShowsWhatTheLiveThirdNodeSaw() {
  const int port2 = port + 1;
  lan::Procs procs;
  const double start2 = lan::unix_now() + 1.5;
  auto args = node_args(port2, 3, start2, 11, dir, "3r");
  const int n3 = procs.start(args, dir / "out_3r.txt");
  while (lan::unix_now() < start2 - 0.3) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const int rp = procs.start({"replay", (dir / "rec.pcap").string(), "--net", "udp://239.1.2.3:" + std::to_string(port2),
                              "--iface", "127.0.0.1"}, dir / "out_replay.txt");
  ASSERT_EQ(procs.wait(rp, 30.0), 0) << lan::read_text(dir / "out_replay.txt");
  ASSERT_EQ(procs.wait(n3, 30.0), 0) << lan::read_text(dir / "out_3r.txt");
  const std::string rout = lan::read_text(dir / "out_replay.txt");
  EXPECT_NE(rout.find(std::to_string(nodes_sent) + " datagrams sent"), std::string::npos) << rout;

  const Seen live = seen(lan::read_events(dir / "events_3.jsonl"));
  const Seen replayed = seen(lan::read_events(dir / "events_3r.jsonl"));
  EXPECT_EQ(live.joined, (std::set<std::string>{"t1", "t1b", "a2", "a2b", "h2", "s2"}));
  EXPECT_EQ(replayed.joined, live.joined);
  EXPECT_EQ(live.collisions, (std::set<std::string>{"a2/t1:kill/kill", "a2b/t1b:bounce/bounce"}));
  EXPECT_EQ(replayed.collisions, live.collisions);
  ASSERT_EQ(live.craters.size(), 1u);
  ASSERT_EQ(replayed.craters.size(), 1u);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(replayed.craters[0]["point"][k].get<double>(), live.craters[0]["point"][k].get<double>(), 0.01);
  EXPECT_EQ(replayed.craters[0]["radius_m"], live.craters[0]["radius_m"]);
  EXPECT_FALSE(live.tree2.empty());
  EXPECT_EQ(replayed.tree2, live.tree2);
}

// run --replay --node 1: node 1 again, headless and with no network, its remote side read from
// the recording (its own PDUs in it are its echo): the same joins, collisions (decided here
// again, as live), crater and tree state as the live node 1, and the collision snapshots.
void AfterActionReviewMatchesTheLiveNode() {
  char s[64];
  std::snprintf(s, sizeof s, "%.3f", start);
  const fs::path snaps = dir / "aar";
  const auto r = sh(npsnet() + " run --scenario '" + (kData / "record.toml").string() + "' --replay '" +
                    (dir / "rec.pcap").string() + "' --node 1 --start-at " + s + " --seconds 8 --snapshot-every 4 --size 320x180" +
                    " --snapshots '" + snaps.string() + "' --events '" + (dir / "aar.jsonl").string() + "' 2>&1");
  ASSERT_EQ(r.rc, 0) << r.out;
  EXPECT_NE(r.out.find("replay: " + (dir / "rec.pcap").string() + ": "), std::string::npos) << r.out;
  const auto live_ev = lan::read_events(dir / "events_1.jsonl");
  const auto aar_ev = lan::read_events(dir / "aar.jsonl");
  const Seen live = seen(live_ev), aar = seen(aar_ev);
  EXPECT_EQ(live.joined, (std::set<std::string>{"a2", "a2b", "h2", "s2"}));
  EXPECT_EQ(aar.joined, live.joined);
  EXPECT_EQ(aar.collisions, live.collisions);
  EXPECT_EQ(aar.collisions, (std::set<std::string>{"a2/t1:kill/kill", "a2b/t1b:bounce/bounce"}));
  for (const auto& c : of_type(aar_ev, "collision")) EXPECT_NE(c["method"], "network") << "node 1 decides its contacts";
  ASSERT_EQ(aar.craters.size(), 1u);
  ASSERT_EQ(live.craters.size(), 1u);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(aar.craters[0]["point"][k].get<double>(), live.craters[0]["point"][k].get<double>(), 0.01);
  EXPECT_EQ(aar.tree2, live.tree2);
  // The collision snapshots of node 1's vehicles, and the periodic frames, are written.
  for (const char* f : {"collision-a2-t1-result.png", "collision-a2b-t1b-imminent.png", "periodic-t00004.0.png"}) {
    bool found = false;
    for (const auto& e : fs::directory_iterator(snaps))
      if (e.path().filename().string().find(f) != std::string::npos && fs::file_size(e.path()) > 1000) found = true;
    EXPECT_TRUE(found) << f << " in " << snaps;
  }
  // A replay with --net, or of a file that is not a capture, is refused (exit 2).
  const auto both = sh(npsnet() + " run --scenario '" + (kData / "record.toml").string() + "' --no-render --replay '" +
                       (dir / "rec.pcap").string() + "' --net udp://239.1.2.3:3000 --events '" + (dir / "x.jsonl").string() + "' 2>&1");
  EXPECT_EQ(both.rc, 2) << both.out;
  const auto bad = sh(npsnet() + " run --scenario '" + (kData / "record.toml").string() + "' --no-render --replay '" +
                      (kData / "record.toml").string() + "' --events '" + (dir / "x.jsonl").string() + "' 2>&1");
  EXPECT_EQ(bad.rc, 2) << bad.out;
  EXPECT_NE(bad.out.find("record.toml:0: file: not a pcap"), std::string::npos) << bad.out;
  EXPECT_FALSE(fs::exists(dir / "x.jsonl")) << "nothing written on bad input";
}

// run --replay --drive t1b: the after-action review looks at the chosen vehicle: the start view
// and every periodic frame are t1b's (file name, snapshot events, drive event), where the review
// without --drive (above) showed node 1's first vehicle, t1.
void AfterActionReviewFollowsTheChosenVehicle() {
  char s[64];
  std::snprintf(s, sizeof s, "%.3f", start);
  const fs::path snaps = dir / "aar_t1b";
  const auto r = sh(npsnet() + " run --scenario '" + (kData / "record.toml").string() + "' --replay '" +
                    (dir / "rec.pcap").string() + "' --node 1 --drive t1b --start-at " + s +
                    " --seconds 7 --snapshot-every 2 --size 320x180 --snapshots '" + snaps.string() + "' --events '" +
                    (dir / "aar_t1b.jsonl").string() + "' 2>&1");
  ASSERT_EQ(r.rc, 0) << r.out;
  EXPECT_TRUE(fs::exists(dir / "aar" / "0000-view-t1-driver.png")) << "without --drive: node 1's first vehicle";
  EXPECT_TRUE(fs::exists(snaps / "0000-view-t1b-driver.png"));
  EXPECT_FALSE(fs::exists(snaps / "0000-view-t1-driver.png"));
  const auto ev = lan::read_events(dir / "aar_t1b.jsonl");
  const auto drives = of_type(ev, "drive");
  ASSERT_FALSE(drives.empty());
  EXPECT_EQ(drives[0]["vehicle"], "t1b");
  int periodic = 0;
  for (const auto& e : of_type(ev, "snapshot")) {
    const std::string file = e["file"];
    if (file.find("periodic") == std::string::npos) continue;
    ++periodic;
    EXPECT_EQ(e["vehicle"], "t1b") << file;
    EXPECT_EQ(e["camera"], "driver") << file;
  }
  EXPECT_EQ(periodic, 4) << "t = 0, 2, 4, 6";
  // A vehicle that is not this node's cannot be driven: refused, nothing written.
  const auto bad = sh(npsnet() + " run --scenario '" + (kData / "record.toml").string() + "' --no-render --replay '" +
                      (dir / "rec.pcap").string() + "' --node 1 --drive a2 --events '" + (dir / "y.jsonl").string() + "' 2>&1");
  EXPECT_EQ(bad.rc, 2) << bad.out;
  EXPECT_NE(bad.out.find("'a2' is not a live vehicle of this node"), std::string::npos) << bad.out;
  EXPECT_FALSE(fs::exists(dir / "y.jsonl"));
}

void KilledRecorderLeavesAReadableFile() {
  const auto chk = sh(npsnet() + " check '" + (dir / "killed.pcap").string() + "' 2>&1");
  EXPECT_EQ(chk.rc, 0) << chk.out;
  EXPECT_NE(chk.out.find("entity_state="), std::string::npos) << chk.out;
}

void CutRecordingIsReadUpToTheCut() {
  const fs::path cut = dir / "cut.pcap";
  fs::copy_file(dir / "rec.pcap", cut, fs::copy_options::overwrite_existing);
  fs::resize_file(cut, fs::file_size(cut) - 100);  // inside the last frame (each is >= 16 + 28 + 144)
  const auto chk = sh(npsnet() + " check '" + cut.string() + "' 2>&1");
  EXPECT_EQ(chk.rc, 2) << chk.out;
  const std::string whole = std::to_string(nodes_sent - 1);
  EXPECT_NE(chk.out.find(whole + " UDP datagrams"), std::string::npos) << chk.out;
  EXPECT_NE(chk.out.find("cut or damaged after frame " + whole), std::string::npos) << chk.out;
  // replay sends what is there (into a group nobody joined) and says where the file ends.
  const auto rp = sh(npsnet() + " replay '" + cut.string() + "' --speed 1000 --net udp://239.1.2.3:" +
                     std::to_string(port + 2) + " --iface 127.0.0.1 2>&1");
  EXPECT_EQ(rp.rc, 0) << rp.out;
  EXPECT_NE(rp.out.find(whole + " datagrams sent"), std::string::npos) << rp.out;
  EXPECT_NE(rp.out.find("cut or damaged"), std::string::npos) << rp.out;
}

void NotACaptureExitsTwo() {
  const auto chk = sh(npsnet() + " check '" + (kData / "record.toml").string() + "' '" + (dir / "nothing.pcap").string() + "' 2>&1");
  EXPECT_EQ(chk.rc, 2) << chk.out;
  { std::ofstream(dir / "text.pcap") << "not a capture\n"; }
  const auto txt = sh(npsnet() + " check '" + (dir / "text.pcap").string() + "' 2>&1");
  EXPECT_EQ(txt.rc, 2) << txt.out;
  EXPECT_NE(txt.out.find("text.pcap:0: file: not a pcap or pcapng file"), std::string::npos) << txt.out;
  const auto rp = sh(npsnet() + " replay '" + (dir / "text.pcap").string() + "' --net udp://239.1.2.3:" +
                     std::to_string(port + 2) + " 2>&1");
  EXPECT_EQ(rp.rc, 2) << rp.out;
  const auto rec = sh(npsnet() + " record --net udp://239.1.2.3:" + std::to_string(port + 2) + " --iface 10.255.255.254 --seconds 1 '" +
                      (dir / "never.pcap").string() + "' 2>&1");
  EXPECT_EQ(rec.rc, 2) << rec.out;
  EXPECT_FALSE(fs::exists(dir / "never.pcap")) << "nothing written on bad input";
}

}  // namespace

TEST(RecordReplay, LiveExerciseRecordedDecodedReplayedCutAndKilled) {
  const std::string fail = record_live_exercise();
  ASSERT_TRUE(fail.empty()) << fail;
  {
    SCOPED_TRACE("tshark decodes the recording with every PDU the nodes sent");
    TsharkDecodesTheRecordingWithEveryPduTheNodesSent();
  }
  {
    SCOPED_TRACE("replayed into a third node: what the live third node saw");
    ReplayIntoAThirdNodeShowsWhatTheLiveThirdNodeSaw();
  }
  {
    SCOPED_TRACE("run --replay: after-action review of node 1");
    AfterActionReviewMatchesTheLiveNode();
  }
  {
    SCOPED_TRACE("run --replay --drive t1b: the review looks at the chosen vehicle");
    AfterActionReviewFollowsTheChosenVehicle();
  }
  {
    SCOPED_TRACE("a recorder killed half-way leaves a readable file");
    KilledRecorderLeavesAReadableFile();
  }
  {
    SCOPED_TRACE("a cut recording is read up to the cut");
    CutRecordingIsReadUpToTheCut();
  }
  if (!std::getenv("NPSNET_KEEP_TEST_FILES")) fs::remove_all(dir);
}

TEST(RecordReplay, NotACaptureExitsTwo) {
  dir = lan::fresh_dir("notpcap");
  port = lan::random_port();
  NotACaptureExitsTwo();
  fs::remove_all(dir);
}
