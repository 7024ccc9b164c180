// bench_record_replay: what `npsnet record` sustains and how closely `npsnet replay` keeps the
// recorded pace (issue 15). Real sockets on loopback multicast (127.0.0.1, group 239.9.0.1, a port
// from the process id), the real npsnet::record::Recorder (writing its pcap to the system temp folder)
// and npsnet::record::Replayer.
//   record   a flood sender offers R datagrams/s (144-octet DIS Entity States, paced on the steady
//            clock, for 1 s) to the group the recorder joined; after a 0.3 s drain the recorder
//            stops. lost = sent - recorded (kernel drops at a full socket buffer and anything
//            else). The recorder's sustained rate is the highest R with lost = 0 (and the sender
//            reaching R). R = 5k ... 160k, and "max" (the sender unpaced); once with the system's
//            default receive buffer, once with the recorder's own SO_RCVBUF request (4 MiB,
//            capped by net.core.rmem_max); the label gives the size the kernel granted.
//   replay   a capture written with PcapWriter at a recorded pace (steady 200/s for 3 s, steady
//            2000/s for 2 s, bursts of 50 datagrams every 100 ms for 3 s) is replayed at speed 1
//            into a group a receiver joined. send lateness = the Replayer's own measure (actual
//            send - scheduled send, per datagram); arrival lateness = a datagram's arrival at the
//            receiver (steady clock) minus its recorded offset, less the smallest such difference
//            (the earliest datagram is 0 late). p50 / p99 / max in ms.
// Usage: bench_record_replay [--quick] [--csv FILE]   (--quick: fewer rates, shorter, no CSV)
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_args.hpp"
#include "net/net.hpp"
#include "record/pcap_file.hpp"
#include "record/recorder.hpp"
#include "record/replayer.hpp"

namespace {

using clock_type = std::chrono::steady_clock;
namespace fs = std::filesystem;

const std::string kGroup = "239.9.0.1";
int port() { return 40000 + static_cast<int>(::getpid() % 5000) * 2; }
std::string url() { return "udp://" + kGroup + ":" + std::to_string(port()); }

net::TransportConfig transport() {
  net::TransportConfig c;
  c.url = url();
  c.iface = "127.0.0.1";
  return c;
}

// One valid DIS 7 Entity State (144 octets), its entity number set per datagram.
std::vector<std::uint8_t> entity_state(std::uint16_t entity) {
  net::EntityStatePdu p;
  p.header.exercise_id = 1;
  p.entity_id = {1, 1, entity};
  std::vector<std::uint8_t> out;
  if (!net::encode_append(p, out)) out.clear();
  return out;
}

struct Quantiles {
  double p50 = 0, p99 = 0, max = 0;
};
Quantiles quantiles(std::vector<double> v) {
  Quantiles q;
  if (v.empty()) return q;
  std::sort(v.begin(), v.end());
  auto at = [&](double p) { return v[std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1) + 0.5))]; };
  q.p50 = at(0.5), q.p99 = at(0.99), q.max = v.back();
  return q;
}

struct Row {
  std::string part, label;
  double offered = 0;
  std::uint64_t sent = 0, got = 0;
  double achieved = 0;
  Quantiles late;
};

// Offers `rate` datagrams/s (0: as fast as the socket takes them) for `seconds` to a recorder.
// rcvbuf: the recorder's SO_RCVBUF request (0: the system default, net.core.rmem_default).
Row record_at(double rate, double seconds, int rcvbuf, const fs::path& dir) {
  Row r;
  r.part = "record";
  npsnet::record::RecordOptions o;
  o.groups.push_back(transport());
  o.out = dir / "flood.pcap";
  o.receive_buffer_bytes = rcvbuf;
  npsnet::record::Recorder rec(o);
  r.label = (rate > 0 ? std::to_string(static_cast<int>(rate)) + "/s" : std::string("max")) + " rcvbuf " +
            std::to_string(rec.receive_buffer_bytes());
  std::thread t([&] { rec.run(); });
  net::UdpTransport tx(transport());
  const std::uint64_t n = rate > 0 ? static_cast<std::uint64_t>(rate * seconds) : 2'000'000;
  std::vector<std::vector<std::uint8_t>> msgs;
  for (std::uint16_t e = 1; e <= 64; ++e) msgs.push_back(entity_state(e));
  const auto t0 = clock_type::now();
  const auto end = t0 + std::chrono::duration<double>(seconds);
  for (std::uint64_t i = 0; i < n; ++i) {
    if (rate > 0) {
      const auto due = t0 + std::chrono::duration_cast<clock_type::duration>(std::chrono::duration<double>(i / rate));
      while (clock_type::now() < due) {
        if (due - clock_type::now() > std::chrono::microseconds(300)) std::this_thread::sleep_for(std::chrono::microseconds(100));
      }
    } else if (clock_type::now() >= end) {
      break;
    }
    r.sent += tx.send(msgs[i % msgs.size()]);
  }
  const double wall = std::chrono::duration<double>(clock_type::now() - t0).count();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  npsnet::record::Recorder::stop();
  t.join();
  r.offered = rate > 0 ? rate : r.sent / wall;
  r.got = rec.tally().datagrams();
  r.achieved = r.sent / wall;
  fs::remove(o.out);
  return r;
}

// Writes `frames` datagrams at `times` (seconds from 0) to a capture, replays it at speed 1 into
// the group and measures send and arrival lateness.
std::pair<Row, Row> replay(const std::string& label, const std::vector<double>& times, const fs::path& dir) {
  const fs::path f = dir / ("replay-" + std::to_string(times.size()) + ".pcap");
  {
    npsnet::record::PcapWriter w(f);
    const double base = 1.7e9;
    for (std::size_t i = 0; i < times.size(); ++i) {
      const auto es = entity_state(static_cast<std::uint16_t>(1 + i % 1000));
      npsnet::record::UdpPacket p;
      p.src_addr = 0x7F000001, p.dst_addr = 0xEF090001;
      p.src_port = p.dst_port = static_cast<std::uint16_t>(port());
      p.payload = es;
      w.write(base + times[i], p);
    }
  }
  net::TransportConfig rc = transport();
  net::UdpTransport rx(rc);
  std::atomic<bool> done{false};
  std::vector<double> arrival;  // steady seconds
  arrival.reserve(times.size());
  std::thread listener([&] {
    pollfd pfd{rx.native_handle(), POLLIN, 0};
    const auto give_up = clock_type::now() + std::chrono::duration<double>(times.back() + 5.0);
    while (!done && arrival.size() < times.size() && clock_type::now() < give_up) {
      ::poll(&pfd, 1, 2);
      while (rx.receive()) arrival.push_back(std::chrono::duration<double>(clock_type::now().time_since_epoch()).count());
    }
  });
  npsnet::record::ReplayOptions o;
  o.in = f;
  o.net = transport();
  npsnet::record::Replayer rep(o);
  const auto report = rep.run();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  done = true;
  listener.join();
  fs::remove(f);
  Row s, a;
  s.part = "replay_send", a.part = "replay_arrival";
  s.label = a.label = label;
  s.offered = a.offered = times.size() / std::max(1e-9, times.back() - times.front());
  s.sent = a.sent = report.sent;
  s.got = a.got = arrival.size();
  s.achieved = a.achieved = report.sent / std::max(1e-9, report.wall_s);
  s.late.p50 = report.late_p50_ms, s.late.p99 = report.late_p99_ms, s.late.max = report.late_max_ms;
  // Arrival lateness against the recorded pace, aligned on the earliest datagram: the smallest
  // (arrival - recorded offset) of all is 0 late.
  std::vector<double> late;
  if (!arrival.empty() && arrival.size() == times.size()) {
    double best = arrival[0] - times[0];
    for (std::size_t i = 0; i < arrival.size(); ++i) best = std::min(best, arrival[i] - times[i]);
    for (std::size_t i = 0; i < arrival.size(); ++i) late.push_back(1000.0 * (arrival[i] - times[i] - best));
  }
  a.late = quantiles(late);
  return {s, a};
}

// "p50,p99,max" in ms, or ",," for the recorder's rows (no lateness).
std::string late_text(const Row& r) {
  if (r.part == "record") return ",,";
  char b[96];
  std::snprintf(b, sizeof b, "%.3f,%.3f,%.3f", r.late.p50, r.late.p99, r.late.max);
  return b;
}

void print(const Row& r) {
  std::printf("%-15s %-22s offered %9.0f/s sent %8llu got %8llu lost %6lld achieved %9.0f/s late p50,p99,max ms %s\n",
              r.part.c_str(), r.label.c_str(), r.offered, (unsigned long long)r.sent, (unsigned long long)r.got,
              (long long)r.sent - (long long)r.got, r.achieved, late_text(r).c_str());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const auto [quick, csv] = npsnet::bench::bench_args(argc, argv, "bench_record_replay: recorder loss and replay lateness",
                                                      "fewer rates, shorter, no CSV", "");
  const fs::path dir = fs::temp_directory_path() / ("bench_record_replay-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::vector<Row> rows;
  const std::vector<double> rates = quick ? std::vector<double>{10000, 40000, 0}
                                          : std::vector<double>{5000, 10000, 20000, 30000, 40000, 80000, 160000, 0};
  for (int rcvbuf : {0, npsnet::record::RecordOptions{}.receive_buffer_bytes}) {
    double sustained = 0;
    for (double rate : rates) {
      rows.push_back(record_at(rate, 1.0, rcvbuf, dir));
      print(rows.back());
      const Row& r = rows.back();
      if (r.got == r.sent && r.achieved >= 0.95 * r.offered) sustained = std::max(sustained, r.achieved);
    }
    std::printf("recorder (SO_RCVBUF asked %d) sustained without loss: %.0f datagrams/s\n", rcvbuf, sustained);
  }
  std::vector<std::pair<std::string, std::vector<double>>> paces;
  {
    std::vector<double> a, b, c;
    for (int i = 0; i < (quick ? 200 : 600); ++i) a.push_back(i / 200.0);
    for (int i = 0; i < (quick ? 2000 : 4000); ++i) b.push_back(i / 2000.0);
    for (int k = 0; k < (quick ? 10 : 30); ++k)
      for (int i = 0; i < 50; ++i) c.push_back(k * 0.1);
    paces = {{"steady 200/s", a}, {"steady 2000/s", b}, {"bursts 50 per 100 ms", c}};
  }
  for (const auto& [label, times] : paces) {
    const auto [s, a] = replay(label, times, dir);
    rows.push_back(s), print(s);
    rows.push_back(a), print(a);
  }
  fs::remove_all(dir);
  if (!csv.empty() && !quick) {
    std::ofstream out(csv);
    out << "part,case,offered_per_s,sent,received,lost,achieved_per_s,late_p50_ms,late_p99_ms,late_max_ms\n";
    for (const auto& r : rows) {
      char b[320];
      std::snprintf(b, sizeof b, "%s,%s,%.0f,%llu,%llu,%lld,%.0f,%s\n", r.part.c_str(), r.label.c_str(), r.offered,
                    (unsigned long long)r.sent, (unsigned long long)r.got, (long long)r.sent - (long long)r.got, r.achieved,
                    late_text(r).c_str());
      out << b;
    }
    std::printf("wrote %s\n", csv.c_str());
  }
  return 0;
}
