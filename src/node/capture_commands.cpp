#include "node/capture_commands.hpp"

#include <csignal>
#include <cstdio>

#ifdef NPSNET_HAVE_RECORD
#include "net/transport.hpp"
#include "record/capture_check.hpp"
#include "record/pcap_file.hpp"
#include "record/recorder.hpp"
#include "record/replayer.hpp"
#endif

namespace npsnet::node {

void add_capture_commands(CLI::App& app, CaptureOptions& o) {
  auto* rec = app.add_subcommand("record", "record an exercise's datagrams to a pcap file (Wireshark reads it)");
  rec->add_option("OUT", o.file, "pcap file to write (raw IPv4/UDP frames)")->required();
  rec->add_option("--net", o.net, "exercise group udp://ADDR:PORT (default 239.1.2.3:3000)");
  rec->add_option("--iface", o.iface, "local address the group is joined on (default 127.0.0.1)");
  rec->add_option("--exercise", o.exercise, "write only datagrams of this exercise id")->check(CLI::Range(1, 255));
  rec->add_option("--seconds", o.seconds, "stop after S seconds (default: at SIGINT/SIGTERM)")->check(CLI::PositiveNumber);
  auto* aoi = rec->add_flag("--aoi", o.aoi,
                            "also join every area-of-interest cell group of `run --aoi CELL_M` (any CELL_M): the "
                            "--aoi-groups groups from the --net group up");
  rec->add_option("--aoi-groups", o.aoi_groups, "with --aoi: the nodes' --aoi-groups N (default 1024)")
      ->check(CLI::Range(1, 65536))
      ->needs(aoi);
  rec->footer("Ends cleanly on Ctrl-C / SIGTERM; flushed every 0.1 s, so a killed recorder leaves a readable file.\n"
              "Each frame's IP destination is the group the datagram was sent to.\n"
              "Example: npsnet record --net udp://239.1.2.3:3000 --iface 127.0.0.1 --seconds 60 exercise.pcap\n"
              "         npsnet record --aoi --net udp://239.1.2.3:3000 --iface 127.0.0.1 aoi-exercise.pcap");
  auto* rep = app.add_subcommand("replay", "send a recorded exercise (pcap) into an exercise at its recorded pace");
  rep->add_option("IN", o.file, "pcap or pcapng file")->required();
  rep->add_option("--net", o.net, "destination udp://ADDR:PORT (default 239.1.2.3:3000)");
  rep->add_option("--iface", o.iface, "local address multicast is sent on (default 127.0.0.1)");
  rep->add_option("--speed", o.speed, "X times the recorded pace (default 1)")->check(CLI::Range(1e-3, 1e6));
  rep->add_option("--from", o.from_s, "start S seconds into the recording")->check(CLI::NonNegativeNumber);
  rep->add_option("--to", o.to_s, "stop S seconds into the recording")->check(CLI::NonNegativeNumber);
  rep->add_option("--exercise", o.exercise, "rewrite every PDU's exercise id to N")->check(CLI::Range(1, 255));
  rep->footer("Payloads are sent unchanged (one datagram per frame) unless --exercise is given.\n"
              "Example: npsnet replay exercise.pcap --net udp://239.1.2.3:3000 --speed 2 --from 10 --to 70");
  o.record = rec;
  o.replay = rep;
}

#ifdef NPSNET_HAVE_RECORD
namespace {
void on_stop_signal(int) {
  record::Recorder::stop();
  record::Replayer::stop();
}
void catch_stop_signals() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;  // no SA_RESTART: poll/sleep return early
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}
net::TransportConfig transport(const CaptureOptions& o) {
  net::TransportConfig c;
  c.url = o.net;
  c.iface = o.iface;
  return c;
}
int record_command(const CaptureOptions& o) {
  record::RecordOptions r;
  r.groups.push_back(transport(o));
  r.aoi_groups = o.aoi ? o.aoi_groups : 0;  // every cell group too (record/recorder.hpp)
  r.exercise = o.exercise;
  r.seconds = o.seconds;
  r.out = o.file;
  std::unique_ptr<record::Recorder> rec;
  try {
    rec = std::make_unique<record::Recorder>(r);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "npsnet record: --net %s --iface %s -> %s: %s\n", o.net.c_str(), o.iface.c_str(),
                 o.file.string().c_str(), e.what());
    return 2;
  }
  catch_stop_signals();
  std::fprintf(stderr, "npsnet record: joined %s%s on %s, writing %s\n", o.net.c_str(),
               o.aoi ? (" and its cell groups (" + std::to_string(rec->groups_joined()) + " groups)").c_str() : "",
               o.iface.c_str(), o.file.string().c_str());
  rec->run();
  std::printf("%s\n", rec->summary().c_str());
  return 0;
}
int replay_command(const CaptureOptions& o) {
  if (o.from_s && o.to_s && *o.to_s < *o.from_s) {
    std::fprintf(stderr, "npsnet replay: --to %.3f is before --from %.3f\n", *o.to_s, *o.from_s);
    return 2;
  }
  record::ReplayOptions r;
  r.in = o.file;
  r.net = transport(o);
  r.speed = o.speed;
  r.from_s = o.from_s, r.to_s = o.to_s;
  r.exercise = o.exercise;
  std::unique_ptr<record::Replayer> rep;
  try {
    rep = std::make_unique<record::Replayer>(r);
  } catch (const record::NotACapture& e) {
    std::fprintf(stderr, "%s:0: file: %s\n", o.file.string().c_str(), e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "npsnet replay: --net %s --iface %s: %s\n", o.net.c_str(), o.iface.c_str(), e.what());
    return 2;
  }
  catch_stop_signals();
  const auto report = rep->run();
  std::printf("%s\n", report.summary(o.file).c_str());
  return 0;
}
}  // namespace

std::optional<int> run_capture_command(const CaptureOptions& o) {
  if (o.record && *o.record) return record_command(o);
  if (o.replay && *o.replay) return replay_command(o);
  return std::nullopt;
}

bool is_capture_file(const std::filesystem::path& f) { return record::looks_like_capture(f); }

std::vector<CaptureProblem> check_capture(const std::filesystem::path& f) {
  std::vector<CaptureProblem> out;
  record::CaptureReport r;
  try {
    r = record::inspect_capture(f);
  } catch (const record::NotACapture& e) {
    out.push_back({0, "file", e.what()});
    return out;
  }
  std::printf("%s\n", r.summary(f).c_str());
  for (const auto& m : r.tally.malformed()) out.push_back({m.frame, "pdu", "malformed DIS PDU: " + m.reason});
  if (r.tally.malformed_total() > r.tally.malformed().size())
    out.push_back({0, "pdu", std::to_string(r.tally.malformed_total() - r.tally.malformed().size()) + " more malformed PDUs"});
  for (auto n : r.cut_short) out.push_back({n, "frame", "UDP payload not captured whole (snap length)"});
  if (!r.cut.empty()) out.push_back({r.frames + 1, "file", r.cut});
  return out;
}
#else
std::optional<int> run_capture_command(const CaptureOptions& o) {
  if ((o.record && *o.record) || (o.replay && *o.replay)) {
    std::fprintf(stderr, "record/replay: this build has no networking or libpcap (NPSNET_NET=OFF)\n");
    return 2;
  }
  return std::nullopt;
}
bool is_capture_file(const std::filesystem::path& f) {
  std::string e = f.extension().string();
  return e == ".pcap" || e == ".pcapng";
}
std::vector<CaptureProblem> check_capture(const std::filesystem::path&) {
  return {{0, "file", "this build cannot read captures (NPSNET_NET=OFF)"}};
}
#endif

}  // namespace npsnet::node
