#include "record/recorder.hpp"

#include <arpa/inet.h>
#include <poll.h>

#include <chrono>
#include <cstdio>
#include <stdexcept>

namespace npsnet::record {

std::atomic<bool> Recorder::stop_{false};

namespace {
double unix_now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}
std::uint32_t addr_of(const std::string& dotted_text) {
  in_addr a{};
  return ::inet_pton(AF_INET, dotted_text.c_str(), &a) == 1 ? ntohl(a.s_addr) : 0;
}
}  // namespace

Recorder::Recorder(const RecordOptions& o) : opt_(o) {
  if (opt_.groups.empty()) throw std::runtime_error("no group to record");
  for (const auto& g : opt_.groups) {
    net::TransportConfig c = g;
    c.max_datagrams_per_poll = 1 << 16;
    socks_.emplace_back(c);  // throws with the reason (bad URL, iface, bind, join)
  }
  writer_ = std::make_unique<PcapWriter>(opt_.out);
  stop_ = false;
}

Recorder::~Recorder() = default;

void Recorder::stop() noexcept { stop_ = true; }

void Recorder::run() {
  const auto t0 = std::chrono::steady_clock::now();
  auto since = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  std::vector<pollfd> fds(socks_.size());
  std::vector<std::uint32_t> group(socks_.size());
  for (std::size_t i = 0; i < socks_.size(); ++i) {
    fds[i].fd = socks_[i].native_handle();
    fds[i].events = POLLIN;
    group[i] = addr_of(socks_[i].destination().address);
    if (socks_[i].destination().mode != net::UdpMode::Multicast) group[i] = addr_of(socks_[i].iface());
  }
  double last_flush = 0;
  while (!stop_) {
    const double now = since();
    if (opt_.seconds > 0 && now >= opt_.seconds) break;
    double wait_s = 0.05;
    if (opt_.seconds > 0) wait_s = std::min(wait_s, opt_.seconds - now);
    ::poll(fds.data(), fds.size(), static_cast<int>(wait_s * 1000) + 1);  // EINTR on a signal: fine
    for (std::size_t i = 0; i < socks_.size(); ++i) {
      net::UdpSource from;
      for (std::size_t n = 0; n < (1u << 16); ++n) {
        auto d = socks_[i].receive(from);
        if (!d) break;
        const double t = unix_now();
        if (opt_.exercise && d->size() >= 2 && (*d)[1] != *opt_.exercise) {
          ++other_exercise_;
          continue;
        }
        UdpPacket p;
        p.src_addr = from.address, p.src_port = from.port;
        p.dst_addr = group[i], p.dst_port = socks_[i].destination().port;
        p.payload = *d;
        if (writer_->write(t, p)) tally_.add(*d, writer_->frames());
      }
    }
    if (since() - last_flush >= opt_.flush_s) writer_->flush(), last_flush = since();
  }
  elapsed_s_ = since();
  writer_->close();
}

std::string Recorder::summary() const {
  char b[512];
  const double s = std::max(elapsed_s_, 1e-9);
  std::snprintf(b, sizeof b,
                "record: %llu datagrams, %llu PDUs, %zu entities, %llu payload octets (%llu in the file) in %.1f s "
                "(%.0f datagrams/s) -> %s\n  PDUs by type: %s\n  malformed %llu, other exercise %llu",
                (unsigned long long)tally_.datagrams(), (unsigned long long)tally_.pdus(), tally_.entities(),
                (unsigned long long)tally_.bytes(), (unsigned long long)writer_->file_bytes(), elapsed_s_,
                tally_.datagrams() / s, opt_.out.string().c_str(), tally_.by_type_text().c_str(),
                (unsigned long long)tally_.malformed_total(), (unsigned long long)other_exercise_);
  return b;
}

}  // namespace npsnet::record
