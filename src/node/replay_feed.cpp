#include "node/replay_feed.hpp"
#ifdef NPSNET_HAVE_RECORD  // built with net/ and libpcap

#include <cstdio>

#include "node/net_bridge.hpp"
#include "record/pcap_file.hpp"

namespace npsnet::node {

ReplayFeed::ReplayFeed(const std::filesystem::path& capture, std::optional<double> zero_unix_s)
    : path_(capture), reader_(std::make_unique<record::PcapReader>(capture)), zero_(zero_unix_s) {
  has_pending_ = load_next();
}

ReplayFeed::~ReplayFeed() = default;

bool ReplayFeed::load_next() {
  record::PcapFrame f;
  while (reader_->next(f)) {
    if (f.udp.truncated) {
      ++cut_short_;
      continue;
    }
    if (!zero_) zero_ = f.time_s;
    pending_.assign(f.udp.payload.begin(), f.udp.payload.end());
    pending_t_ = f.time_s - *zero_;
    return true;
  }
  return false;
}

void ReplayFeed::feed(double now_s, NetBridge& bridge) {
  while (has_pending_ && pending_t_ <= now_s) {
    if (fed_ == 0) first_s_ = pending_t_;
    last_s_ = pending_t_;
    bridge.receive(pending_, pending_t_);
    ++fed_;
    has_pending_ = load_next();
  }
}

std::string ReplayFeed::summary() const {
  char b[256];
  std::snprintf(b, sizeof b, "  replay: %s: %llu datagrams fed (arrivals %.3f to %.3f s), %s, %llu cut short",
                path_.string().c_str(), (unsigned long long)fed_, first_s_, last_s_,
                has_pending_ ? "more after the run's end" : "all of the file", (unsigned long long)cut_short_);
  std::string s = b;
  if (!reader_->error().empty()) s += "\n  replay: " + path_.string() + ": " + reader_->error();
  return s;
}

}  // namespace npsnet::node
#endif
