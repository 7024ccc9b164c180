// net/transport.hpp — UDP endpoint (Asio) for DIS: multicast, unicast peer or broadcast.
// Contract:
//  * parse_udp_url("udp://ADDR:PORT") accepts a dotted IPv4 ADDR and PORT 1..65535; anything
//    else gives a message saying what is wrong and what is expected. The mode follows from ADDR:
//    224.0.0.0/4 multicast, 255.255.255.255 or an address ending in .255 broadcast, else
//    unicast (TransportConfig::mode overrides the guess).
//  * Multicast: socket bound to GROUP:PORT with SO_REUSEADDR (several processes on one host),
//    group joined on `iface`, IP_MULTICAST_IF = iface, TTL 1 (configurable), loopback on, so
//    nodes on one host hear each other (and themselves: filter own echo above this layer).
//    Unicast: bound to 0.0.0.0:PORT (SO_REUSEADDR), sends to ADDR:PORT.
//    Broadcast: bound to 0.0.0.0:PORT, SO_BROADCAST, sends to ADDR:PORT.
//  * Construction throws std::runtime_error with an actionable message (bad URL, bad iface,
//    bind/join failure). After that nothing throws: send() returns false on failure (the
//    reason in last_error()), poll() drains what has arrived without blocking.
//  * Many groups (area of interest, `join_destination = false`): the socket is bound to
//    0.0.0.0:PORT with IP_MULTICAST_ALL off, so it hears only the groups this transport joined
//    itself with join(group) on `iface` (not those other processes of the host joined); nothing
//    is joined at construction. The kernel caps the groups of one socket
//    (net.ipv4.igmp_max_memberships, 20 by default): when a join hits that cap, the transport
//    opens one more receive socket on the same port and joins there; send_to() always leaves
//    from the first socket. receive() drains the sockets in turn.
//  * Nothing here allocates per call: one receive buffer of 65536 octets is kept.
//  * receive(from) also gives the sender's IPv4 address and port and the datagram's own IPv4
//    destination (IP_PKTINFO: the group it was sent to, on whichever socket it arrived), so a
//    recorder holding many groups writes each frame's true addresses into its pcap;
//    native_handle(i) is socket i's descriptor, for poll(2) over every socket.
//  * Arrival time (issue 11): every datagram read carries when it arrived, arrival_s on the
//    steady clock (steady_now_s(): std::chrono::steady_clock, CLOCK_MONOTONIC, s): the kernel's
//    receive timestamp (SO_TIMESTAMPNS, wall clock, moved onto the steady clock by its age at
//    the read), or the time of the read where the kernel gives none (kernel_time false); never
//    later than the read. A node that reads its socket once a tick dates a state with it, not
//    with the read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

#include "net/result.hpp"

namespace net {

enum class UdpMode { Multicast, Unicast, Broadcast };
std::string_view to_string(UdpMode m) noexcept;

struct UdpUrl {
  std::string address;  // dotted IPv4
  std::uint16_t port = 3000;
  UdpMode mode = UdpMode::Multicast;
};

inline constexpr std::string_view kDefaultNetUrl = "udp://239.1.2.3:3000";
inline constexpr std::string_view kDefaultIface = "127.0.0.1";

Result<UdpUrl, std::string> parse_udp_url(std::string_view url);

// Where a datagram came from: IPv4 address and UDP port, host byte order.
struct UdpSource {
  std::uint32_t address = 0;
  std::uint16_t port = 0;
  std::uint32_t destination = 0;  // the datagram's IPv4 destination address (IP_PKTINFO); 0 = unknown
  double arrival_s = 0;      // steady clock (steady_now_s()), s: when the datagram arrived
  bool kernel_time = false;  // arrival_s is the kernel's timestamp (else: the time it was read)
};

// The steady clock arrival times are on: std::chrono::steady_clock, seconds.
double steady_now_s() noexcept;

struct TransportConfig {
  std::string url{kDefaultNetUrl};
  std::string iface{kDefaultIface};  // local IPv4 address multicast is sent and joined on
  std::optional<UdpMode> mode;       // overrides the mode guessed from the address
  int multicast_ttl = 1;             // 1 = the LAN; more to cross multicast routers
  bool join_destination = true;      // false: many groups, join()/leave() them (see above)
  bool multicast_loopback = true;
  std::size_t max_datagrams_per_poll = 4096;  // bounds one poll() call
  int receive_buffer_bytes = 0;  // > 0: SO_RCVBUF asked of every socket (the kernel caps it at
                                 // net.core.rmem_max); 0: the system default
};

class UdpTransport {
 public:
  explicit UdpTransport(const TransportConfig& config);  // throws std::runtime_error
  ~UdpTransport();
  UdpTransport(UdpTransport&&) noexcept;
  UdpTransport& operator=(UdpTransport&&) noexcept;
  UdpTransport(const UdpTransport&) = delete;
  UdpTransport& operator=(const UdpTransport&) = delete;

  // Sends one datagram to the configured destination. Non-blocking; false on failure.
  bool send(std::span<const std::uint8_t> datagram) noexcept;

  // Sends one datagram to group:PORT (IPv4 host order), e.g. an area-of-interest cell's group.
  bool send_to(std::uint32_t group, std::span<const std::uint8_t> datagram) noexcept;

  // Many-groups mode only: joins / leaves `group` (IPv4 host order) on the iface. false (reason
  // in last_error()) when the kernel refuses or the transport was made with join_destination.
  bool join(std::uint32_t group) noexcept;
  bool leave(std::uint32_t group) noexcept;
  std::size_t groups_joined() const noexcept;
  std::size_t socket_count() const noexcept;

  // Next datagram already received, or empty when none is waiting (never blocks). The span
  // stays valid until the next receive()/poll().
  std::optional<std::span<const std::uint8_t>> receive() noexcept;
  // The same, and the sender's address and port in `from`.
  std::optional<std::span<const std::uint8_t>> receive(UdpSource& from) noexcept;
  // Datagrams the kernel dropped because a receive buffer was full (a peer flooding us, or a
  // tick too slow to drain it), as of the last datagram read: counted, never fatal.
  std::uint64_t dropped_by_kernel() const noexcept;
  // The first socket's file descriptor (to wait on several transports with poll(2); the only
  // socket unless many-groups mode opened more); do not close it.
  int native_handle() const noexcept;
  // Socket i's descriptor, i < socket_count() (-1 otherwise): poll them all to hear every group.
  int native_handle(std::size_t i) const noexcept;
  // The first socket's receive buffer as the kernel granted it (SO_RCVBUF read back), octets.
  int receive_buffer_bytes() const noexcept;

  // Calls on_datagram(std::span<const std::uint8_t>) -- or on_datagram(span, double arrival_s)
  // when it takes the arrival time too -- for each waiting datagram, at most
  // max_datagrams_per_poll; returns how many.
  template <class F>
  std::size_t poll(F&& on_datagram) {
    std::size_t n = 0;
    UdpSource from;
    while (n < max_per_poll_) {
      auto d = receive(from);
      if (!d) return n;
      ++n;
      if constexpr (std::is_invocable_v<F&, std::span<const std::uint8_t>, double>)
        on_datagram(*d, from.arrival_s);
      else
        on_datagram(*d);
    }
    ++polls_capped_;  // more may be waiting: left for the next poll (bounded work per tick)
    return n;
  }

  // poll() calls that stopped at max_datagrams_per_poll with datagrams possibly still waiting.
  std::uint64_t polls_capped() const noexcept { return polls_capped_; }

  const UdpUrl& destination() const noexcept;
  const std::string& iface() const noexcept;
  std::uint16_t local_port() const noexcept;
  const std::string& last_error() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::size_t max_per_poll_ = 4096;
  std::uint64_t polls_capped_ = 0;
};

}  // namespace net
