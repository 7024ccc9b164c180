#include "record/recorder.hpp"

#include "net/aoi.hpp"

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
  if (opt_.aoi_groups > 0) {
    if (opt_.groups.size() != 1) throw std::runtime_error("--aoi records one exercise: give one --net group");
    const auto url = net::parse_udp_url(opt_.groups[0].url);
    if (!url) throw std::runtime_error(url.error());
    const auto cells = net::aoi_all_groups(url.value().address, opt_.aoi_groups);  // cell group 0 = the exercise's
    if (!cells) throw std::runtime_error(cells.error());
    net::TransportConfig c = opt_.groups[0];
    c.join_destination = false;
    c.max_datagrams_per_poll = 1 << 16;
    c.receive_buffer_bytes = opt_.receive_buffer_bytes;
    auto& t = socks_.emplace_back(c);  // throws with the reason (bad URL, iface, bind)
    for (const auto& g : cells.value())
      if (!t.join(addr_of(g))) throw std::runtime_error("--aoi: " + t.last_error());
    groups_joined_ = t.groups_joined();
  } else {
    for (const auto& g : opt_.groups) {
      net::TransportConfig c = g;
      c.max_datagrams_per_poll = 1 << 16;
      c.receive_buffer_bytes = opt_.receive_buffer_bytes;
      socks_.emplace_back(c);  // throws with the reason (bad URL, iface, bind, join)
      ++groups_joined_;
    }
  }
  writer_ = std::make_unique<PcapWriter>(opt_.out);
  stop_ = false;
}

Recorder::~Recorder() = default;

void Recorder::stop() noexcept { stop_ = true; }

void Recorder::run() {
  const auto t0 = std::chrono::steady_clock::now();
  auto since = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  std::vector<pollfd> fds;  // every socket of every transport (a many-groups one has several)
  std::vector<std::uint32_t> group(socks_.size());  // the destination when IP_PKTINFO gave none
  for (std::size_t i = 0; i < socks_.size(); ++i) {
    for (std::size_t k = 0; k < socks_[i].socket_count(); ++k) fds.push_back({socks_[i].native_handle(k), POLLIN, 0});
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
        p.dst_addr = from.destination ? from.destination : group[i], p.dst_port = socks_[i].destination().port;
        p.payload = *d;
        if (writer_->write(t, p)) tally_.add(*d, writer_->frames()), ++per_destination_[p.dst_addr];
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
  std::string out = b;
  out += "\n  groups: " + std::to_string(groups_joined_) + " joined, " + std::to_string(per_destination_.size()) + " heard";
  std::size_t listed = 0;
  for (const auto& [addr, n] : per_destination_) {
    if (++listed > 8) {
      out += ", ...";
      break;
    }
    out += (listed == 1 ? ": " : ", ") + dotted(addr) + " (" + std::to_string(n) + ")";
  }
  return out;
}

}  // namespace npsnet::record
