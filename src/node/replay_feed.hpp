// `npsnet run --replay IN.pcap`: a recording as the remote side of a run with no network
// (after-action review). ReplayFeed is the bridge's datagram source (NetBridge::set_source):
// each tick it hands the bridge's receive path every recorded UDP payload whose arrival time,
// on the scenario clock, is at or before the tick's time. Scenario time 0 is the UNIX time
// `zero_unix_s` (run --start-at: the recorded exercise's start), or else the arrival of the
// first UDP frame. Frames cut short in the capture are not fed (counted); a capture that ends
// inside a frame is fed up to the cut and summary() says so. The constructor throws
// record::NotACapture (exit 2) when the file is not a pcap/pcapng file.
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace npsnet::record {
class PcapReader;
}

namespace npsnet::node {

class NetBridge;

class ReplayFeed {
 public:
  ReplayFeed(const std::filesystem::path& capture, std::optional<double> zero_unix_s);
  ~ReplayFeed();
  ReplayFeed(const ReplayFeed&) = delete;
  ReplayFeed& operator=(const ReplayFeed&) = delete;

  // Hands bridge.receive() every datagram that arrived by now_s (scenario seconds).
  void feed(double now_s, NetBridge& bridge);
  std::string summary() const;  // one line: fed, left, cut short, where the file ends

 private:
  bool load_next();  // the next UDP frame into pending_, or false at the end
  std::filesystem::path path_;
  std::unique_ptr<record::PcapReader> reader_;
  std::optional<double> zero_;
  std::vector<std::uint8_t> pending_;  // the next datagram, not yet due
  double pending_t_ = 0;               // its arrival, scenario s
  bool has_pending_ = false;
  std::uint64_t fed_ = 0, cut_short_ = 0;
  double first_s_ = 0, last_s_ = 0;
};

}  // namespace npsnet::node
