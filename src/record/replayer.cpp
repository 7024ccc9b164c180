#include "record/replayer.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

#include "record/pcap_file.hpp"

namespace npsnet::record {

std::atomic<bool> Replayer::stop_{false};

void rewrite_exercise(std::span<std::uint8_t> d, std::uint8_t exercise) noexcept {
  for (std::size_t off = 0; off + net::kHeaderSize <= d.size();) {
    d[off + 1] = exercise;
    const std::size_t len = (std::size_t{d[off + 8]} << 8) | d[off + 9];
    if (len < net::kHeaderSize) break;
    off += len;
  }
}

struct Replayer::Impl {
  ReplayOptions opt;
  PcapReader reader;
  net::UdpTransport sock;
  explicit Impl(const ReplayOptions& o) : opt(o), reader(o.in), sock(o.net) {}
};

Replayer::Replayer(const ReplayOptions& o) : impl_(std::make_unique<Impl>(o)) { stop_ = false; }
Replayer::~Replayer() = default;
void Replayer::stop() noexcept { stop_ = true; }

ReplayReport Replayer::run() {
  using clock = std::chrono::steady_clock;
  ReplayReport rep;
  const ReplayOptions& o = impl_->opt;
  std::vector<std::uint8_t> buf;
  std::vector<double> late;
  PcapFrame f;
  std::optional<double> t_file0, t_sent0;
  clock::time_point start;
  double last_t = 0;
  while (!stop_ && impl_->reader.next(f)) {
    if (!t_file0) t_file0 = f.time_s;
    const double t = f.time_s - *t_file0;
    if (o.from_s && t < *o.from_s) continue;
    if (o.to_s && t > *o.to_s) break;
    if (f.udp.truncated) {
      ++rep.not_sent_cut;
      continue;
    }
    buf.assign(f.udp.payload.begin(), f.udp.payload.end());
    if (o.exercise) rewrite_exercise(buf, static_cast<std::uint8_t>(*o.exercise));
    clock::time_point due;
    if (!t_sent0) {
      t_sent0 = t;
      start = due = clock::now();
    } else {
      due = start + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>((t - *t_sent0) / o.speed));
      std::this_thread::sleep_until(due);
    }
    const bool ok = impl_->sock.send(buf);
    late.push_back(std::chrono::duration<double, std::milli>(clock::now() - due).count());
    if (!ok) {
      ++rep.send_failures;
      continue;
    }
    ++rep.sent;
    rep.tally.add(buf, f.number);
    last_t = t;
  }
  rep.cut = impl_->reader.error();
  rep.skipped_frames = impl_->reader.skipped();
  if (t_sent0) rep.span_s = last_t - *t_sent0, rep.wall_s = std::chrono::duration<double>(clock::now() - start).count();
  if (!late.empty()) {
    std::sort(late.begin(), late.end());
    auto q = [&](double p) { return late[std::min(late.size() - 1, static_cast<std::size_t>(p * (late.size() - 1) + 0.5))]; };
    rep.late_p50_ms = q(0.5), rep.late_p99_ms = q(0.99), rep.late_max_ms = late.back();
  }
  return rep;
}

std::string ReplayReport::summary(const std::filesystem::path& in) const {
  char b[640];
  std::snprintf(b, sizeof b,
                "replay: %s: %llu datagrams sent (%llu PDUs, %zu entities) over %.2f s recorded in %.2f s wall; "
                "send failures %llu, frames cut short %llu, frames not UDP %llu\n"
                "  PDUs by type: %s\n  lateness against the recorded pace: p50 %.3f ms, p99 %.3f ms, max %.3f ms",
                in.string().c_str(), (unsigned long long)sent, (unsigned long long)tally.pdus(), tally.entities(), span_s,
                wall_s, (unsigned long long)send_failures, (unsigned long long)not_sent_cut,
                (unsigned long long)skipped_frames, tally.by_type_text().c_str(), late_p50_ms, late_p99_ms, late_max_ms);
  std::string s = b;
  if (!cut.empty()) s += "\n  " + in.string() + ": " + cut;
  return s;
}

}  // namespace npsnet::record
