// record/recorder.hpp — `npsnet record`: join an exercise's multicast group(s) and write every
// datagram, with its arrival time, to a pcap file (see pcap_file.hpp).
// Contract:
//  * Recorder(options) joins every group of options.groups (throws std::runtime_error with an
//    actionable message, before the output file is created) and then creates the file.
//  * run() receives until options.seconds have passed (0: no limit) or stop() is called (from a
//    signal handler: it only sets a flag); the wait for datagrams is at most 50 ms, and the file
//    is flushed at least every options.flush_s seconds, so a killed recorder loses at most that.
//  * With options.aoi_groups = N > 0 (`record --aoi`): one many-groups transport on groups[0]'s
//    port joins every area-of-interest cell group of net/aoi.hpp, from groups[0]'s group (cell
//    group 0, the exercise group itself) up: floor(sqrt(N))^2 groups, the grid `run --aoi CELL_M
//    --aoi-groups N` publishes into whatever CELL_M is. A refused join throws, naming the group.
//  * Each datagram is stamped with the wall clock (UNIX seconds) right after recvmsg and written
//    behind IPv4/UDP headers holding the sender's address and port and the datagram's own
//    destination address (IP_PKTINFO: the group it was sent to) and port. With options.exercise,
//    a datagram whose first PDU belongs to another exercise is not written (other_exercise()).
#pragma once

#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "net/transport.hpp"
#include "record/pcap_file.hpp"
#include "record/pdu_tally.hpp"

namespace npsnet::record {

struct RecordOptions {
  // Every group to join, each a transport (url + iface): the exercise's group.
  std::vector<net::TransportConfig> groups;
  int aoi_groups = 0;           // > 0: also every AOI cell group (see the contract above)
  std::optional<int> exercise;  // write only this exercise id
  double seconds = 0;           // 0: until stop()
  double flush_s = 0.1;         // longest time between two flushes, s
  int receive_buffer_bytes = 4 << 20;  // per socket: room for a burst (capped by net.core.rmem_max)
  std::filesystem::path out;
};

class Recorder {
 public:
  explicit Recorder(const RecordOptions& o);
  ~Recorder();
  void run();
  static void stop() noexcept;  // async-signal-safe

  const PduTally& tally() const { return tally_; }
  std::uint64_t other_exercise() const { return other_exercise_; }
  double elapsed_s() const { return elapsed_s_; }
  const PcapWriter& writer() const { return *writer_; }
  std::size_t groups_joined() const { return groups_joined_; }
  int receive_buffer_bytes() const { return socks_.front().receive_buffer_bytes(); }  // as granted
  // Datagrams written per destination group (host order address).
  const std::map<std::uint32_t, std::uint64_t>& per_destination() const { return per_destination_; }
  // Several lines: what was recorded, for the end of `npsnet record`.
  std::string summary() const;

 private:
  RecordOptions opt_;
  std::vector<net::UdpTransport> socks_;
  std::unique_ptr<PcapWriter> writer_;
  PduTally tally_;
  std::uint64_t other_exercise_ = 0;
  double elapsed_s_ = 0;
  std::size_t groups_joined_ = 0;
  std::map<std::uint32_t, std::uint64_t> per_destination_;
  static std::atomic<bool> stop_;
};

}  // namespace npsnet::record
