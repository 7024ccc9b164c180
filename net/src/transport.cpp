// transport.cpp — Asio UDP socket setup for multicast / unicast / broadcast, non-blocking I/O.
#ifndef ASIO_STANDALONE
#define ASIO_STANDALONE
#endif
#include "net/transport.hpp"

#include <algorithm>
#include <array>
#include <asio.hpp>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <unordered_map>
#include <vector>

#include <netinet/in.h>
#include <sys/socket.h>
#include <stdexcept>

namespace net {

std::string_view to_string(UdpMode m) noexcept {
  switch (m) {
    case UdpMode::Multicast: return "multicast";
    case UdpMode::Unicast: return "unicast";
    case UdpMode::Broadcast: return "broadcast";
  }
  return "unknown";
}

Result<UdpUrl, std::string> parse_udp_url(std::string_view url) {
  using R = Result<UdpUrl, std::string>;
  const std::string expected = " (expected udp://ADDR:PORT, e.g. udp://239.1.2.3:3000)";
  const std::string quoted = std::string("\"").append(url).append("\"");
  constexpr std::string_view scheme = "udp://";
  if (url.substr(0, scheme.size()) != scheme)
    return R::failure("network URL " + quoted + " does not start with udp://" + expected);
  std::string_view rest = url.substr(scheme.size());
  const auto colon = rest.rfind(':');
  if (colon == std::string_view::npos)
    return R::failure("network URL " + quoted + " has no :PORT" + expected);
  const std::string host(rest.substr(0, colon));
  const std::string_view port_text = rest.substr(colon + 1);
  if (host.empty()) return R::failure("network URL " + quoted + " has no address" + expected);
  asio::error_code ec;
  const auto addr = asio::ip::make_address_v4(host, ec);
  if (ec)
    return R::failure("network URL " + quoted + ": \"" + host +
                      "\" is not a dotted IPv4 address" + expected);
  unsigned port = 0;
  const auto [end, perr] =
      std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (port_text.empty() || perr != std::errc() || end != port_text.data() + port_text.size() ||
      port < 1 || port > 65535)
    return R::failure("network URL " + quoted + ": port \"" + std::string(port_text) +
                      "\" is not a number in 1..65535" + expected);
  UdpUrl u;
  u.address = host;
  u.port = static_cast<std::uint16_t>(port);
  if (addr.is_multicast())
    u.mode = UdpMode::Multicast;
  else if ((addr.to_uint() & 0xFFu) == 0xFFu)
    u.mode = UdpMode::Broadcast;
  else
    u.mode = UdpMode::Unicast;
  return u;
}

struct UdpTransport::Impl {
  asio::io_context io;
  std::vector<asio::ip::udp::socket> sockets;  // [0] sends; all receive
  asio::ip::udp::endpoint destination;
  asio::ip::address_v4 iface_addr;
  UdpUrl url;
  std::string iface;
  std::string where;
  std::string last_error;
  TransportConfig config;
  std::unordered_map<std::uint32_t, std::size_t> joined;  // group -> socket index
  std::vector<std::size_t> joined_per_socket;
  std::vector<std::uint32_t> kernel_drops;  // per socket: the last SO_RXQ_OVFL count seen
  std::uint64_t kernel_drops_total = 0;
  std::size_t next_rx = 0;
  std::array<std::uint8_t, 65536> buffer{};

  asio::ip::udp::socket& open_socket();  // throws
};

namespace {

[[noreturn]] void fail(const std::string& what, const asio::error_code& ec) {
  throw std::runtime_error(what + ": " + ec.message());
}

// Only the groups this socket joined (Linux: otherwise a socket bound to 0.0.0.0 hears every
// group any socket of the host joined on that port).
void hear_only_own_groups(asio::ip::udp::socket& s, asio::error_code& ec) {
#ifdef IP_MULTICAST_ALL
  const int off = 0;
  if (::setsockopt(s.native_handle(), IPPROTO_IP, IP_MULTICAST_ALL, &off, sizeof off) != 0)
    ec = asio::error_code(errno, asio::error::get_system_category());
#else
  (void)s, (void)ec;
#endif
}

}  // namespace

asio::ip::udp::socket& UdpTransport::Impl::open_socket() {
  asio::error_code ec;
  asio::ip::udp::socket s(io);
  s.open(asio::ip::udp::v4(), ec);
  if (ec) fail("cannot open UDP socket for " + where, ec);
  s.set_option(asio::socket_base::reuse_address(true), ec);
  if (ec) fail("cannot set SO_REUSEADDR for " + where, ec);
  const auto addr = destination.address().to_v4();
  asio::ip::udp::endpoint bind_to(asio::ip::address_v4::any(), url.port);
  if (url.mode == UdpMode::Multicast && config.join_destination) bind_to = asio::ip::udp::endpoint(addr, url.port);
  s.bind(bind_to, ec);
  if (ec) fail("cannot bind UDP port " + std::to_string(url.port) + " for " + where, ec);
  if (url.mode == UdpMode::Multicast) {
    if (config.join_destination) {
      s.set_option(asio::ip::multicast::join_group(addr, iface_addr), ec);
      if (ec) fail("cannot join multicast group for " + where + " (is " + iface +
                       " an address of this host?)", ec);
    } else {
      hear_only_own_groups(s, ec);
      if (ec) fail("cannot turn IP_MULTICAST_ALL off for " + where, ec);
    }
    s.set_option(asio::ip::multicast::outbound_interface(iface_addr), ec);
    if (ec) fail("cannot set IP_MULTICAST_IF for " + where + " (is " + iface + " an address of this host?)", ec);
    s.set_option(asio::ip::multicast::hops(config.multicast_ttl), ec);
    if (ec) fail("cannot set multicast TTL for " + where, ec);
    s.set_option(asio::ip::multicast::enable_loopback(config.multicast_loopback), ec);
    if (ec) fail("cannot enable multicast loopback for " + where, ec);
  } else if (url.mode == UdpMode::Broadcast) {
    s.set_option(asio::socket_base::broadcast(true), ec);
    if (ec) fail("cannot set SO_BROADCAST for " + where, ec);
  }
  if (config.receive_buffer_bytes > 0) {  // a recorder's burst room; capped by net.core.rmem_max
    s.set_option(asio::socket_base::receive_buffer_size(config.receive_buffer_bytes), ec);
    if (ec) fail("cannot set SO_RCVBUF for " + where, ec);
  }
  s.non_blocking(true, ec);
  if (ec) fail("cannot make the socket non-blocking for " + where, ec);
  // The kernel's count of datagrams it dropped because this socket's receive buffer was full
  // (a flood): given with every datagram read (recvmsg control data). Not fatal where missing.
  const int on = 1;
#ifdef SO_RXQ_OVFL
  (void)::setsockopt(s.native_handle(), SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof on);
#endif
  // Each datagram's arrival time (the kernel's receive timestamp) with every datagram read.
  // Not fatal where missing: the time of the read stands in (receive()).
#ifdef SO_TIMESTAMPNS
  (void)::setsockopt(s.native_handle(), SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof on);
#endif
  // Each datagram's destination address (the group it was sent to) with every datagram read.
  const int pktinfo = 1;
  if (::setsockopt(s.native_handle(), IPPROTO_IP, IP_PKTINFO, &pktinfo, sizeof pktinfo) != 0)
    fail("cannot set IP_PKTINFO for " + where, asio::error_code(errno, asio::error::get_system_category()));
  joined_per_socket.push_back(0);
  kernel_drops.push_back(0);
  return sockets.emplace_back(std::move(s));
}

UdpTransport::UdpTransport(const TransportConfig& config) : impl_(std::make_unique<Impl>()) {
  auto parsed = parse_udp_url(config.url);
  if (!parsed) throw std::runtime_error(parsed.error());
  Impl& m = *impl_;
  m.config = config;
  m.url = parsed.value();
  if (config.mode) m.url.mode = *config.mode;
  m.iface = config.iface;
  max_per_poll_ = config.max_datagrams_per_poll == 0 ? 1 : config.max_datagrams_per_poll;

  asio::error_code ec;
  m.iface_addr = asio::ip::make_address_v4(config.iface, ec);
  if (ec)
    throw std::runtime_error("interface address \"" + config.iface +
                             "\" is not a dotted IPv4 address (give the local address to send "
                             "and join multicast on, e.g. --iface 127.0.0.1)");
  const auto addr = asio::ip::make_address_v4(m.url.address);
  if (m.url.mode == UdpMode::Multicast && !addr.is_multicast())
    throw std::runtime_error("network URL \"" + config.url + "\": " + m.url.address +
                             " is not a multicast group (224.0.0.0/4)");
  if (config.multicast_ttl < 1 || config.multicast_ttl > 255)
    throw std::runtime_error("multicast TTL " + std::to_string(config.multicast_ttl) + " must be 1..255");
  m.destination = asio::ip::udp::endpoint(addr, m.url.port);
  m.where = std::string(to_string(m.url.mode)) + " " + m.url.address + ":" +
            std::to_string(m.url.port) + " on " + config.iface;
  m.open_socket();
}

UdpTransport::~UdpTransport() = default;
UdpTransport::UdpTransport(UdpTransport&&) noexcept = default;
UdpTransport& UdpTransport::operator=(UdpTransport&&) noexcept = default;

namespace {
bool send_on(asio::ip::udp::socket& s, const asio::ip::udp::endpoint& to, std::span<const std::uint8_t> d,
             std::string& last_error) noexcept {
  asio::error_code ec;
  s.send_to(asio::buffer(d.data(), d.size()), to, 0, ec);
  if (!ec) return true;
  last_error = "send to " + to.address().to_string() + ":" + std::to_string(to.port()) + " failed: " + ec.message();
  return false;
}
}  // namespace

bool UdpTransport::send(std::span<const std::uint8_t> datagram) noexcept {
  return send_on(impl_->sockets.front(), impl_->destination, datagram, impl_->last_error);
}

bool UdpTransport::send_to(std::uint32_t group, std::span<const std::uint8_t> datagram) noexcept {
  const asio::ip::udp::endpoint to(asio::ip::address_v4(group), impl_->url.port);
  return send_on(impl_->sockets.front(), to, datagram, impl_->last_error);
}

bool UdpTransport::join(std::uint32_t group) noexcept {
  Impl& m = *impl_;
  const asio::ip::address_v4 g(group);
  if (m.config.join_destination || m.url.mode != UdpMode::Multicast || !g.is_multicast()) {
    m.last_error = "join " + g.to_string() + ": only a many-groups multicast transport joins groups";
    return false;
  }
  if (m.joined.count(group)) return true;
  asio::error_code ec;
  for (std::size_t i = 0;; ++i) {
    if (i == m.sockets.size()) {
      try {
        m.open_socket();
      } catch (const std::exception& e) {
        m.last_error = std::string("join ") + g.to_string() + ": " + e.what();
        return false;
      }
    }
    m.sockets[i].set_option(asio::ip::multicast::join_group(g, m.iface_addr), ec);
    if (!ec) {
      m.joined.emplace(group, i);
      ++m.joined_per_socket[i];
      return true;
    }
    // The per-socket cap (igmp_max_memberships): try the next socket, or a new one.
    if (ec != asio::error::no_buffer_space || m.joined_per_socket[i] == 0) break;
  }
  m.last_error = "join " + g.to_string() + " on " + m.iface + ": " + ec.message();
  return false;
}

bool UdpTransport::leave(std::uint32_t group) noexcept {
  Impl& m = *impl_;
  auto it = m.joined.find(group);
  if (it == m.joined.end()) return false;
  asio::error_code ec;
  m.sockets[it->second].set_option(asio::ip::multicast::leave_group(asio::ip::address_v4(group), m.iface_addr), ec);
  --m.joined_per_socket[it->second];
  m.joined.erase(it);
  if (ec) {
    m.last_error = "leave " + asio::ip::address_v4(group).to_string() + ": " + ec.message();
    return false;
  }
  return true;
}

std::size_t UdpTransport::groups_joined() const noexcept { return impl_->joined.size(); }
std::size_t UdpTransport::socket_count() const noexcept { return impl_->sockets.size(); }

std::optional<std::span<const std::uint8_t>> UdpTransport::receive() noexcept {
  UdpSource ignored;
  return receive(ignored);
}

std::optional<std::span<const std::uint8_t>> UdpTransport::receive(UdpSource& source) noexcept {
  Impl& m = *impl_;
  const std::size_t n_sockets = m.sockets.size();
  for (std::size_t k = 0; k < n_sockets; ++k) {
    const std::size_t i = (m.next_rx + k) % n_sockets;
    sockaddr_in from{};
    iovec iov{m.buffer.data(), m.buffer.size()};
    alignas(cmsghdr) std::array<char, CMSG_SPACE(sizeof(std::uint32_t)) + CMSG_SPACE(sizeof(in_pktinfo)) +
                                          CMSG_SPACE(sizeof(timespec))>
        control{};
    msghdr msg{};
    msg.msg_name = &from;
    msg.msg_namelen = sizeof from;
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control.data();
    msg.msg_controllen = control.size();
    const ssize_t got = ::recvmsg(m.sockets[i].native_handle(), &msg, MSG_DONTWAIT);
    if (got < 0) {
      if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
        m.last_error = std::string("receive failed: ") + std::strerror(errno);
      continue;
    }
    const auto n = static_cast<std::size_t>(got);
    source.destination = 0;
    source.arrival_s = steady_now_s();  // the read, unless the kernel says when it came
    source.kernel_time = false;
    for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c; c = CMSG_NXTHDR(&msg, c)) {
#ifdef SO_TIMESTAMPNS
      if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_TIMESTAMPNS) {
        timespec stamp{}, wall{};
        std::memcpy(&stamp, CMSG_DATA(c), sizeof stamp);
        ::clock_gettime(CLOCK_REALTIME, &wall);
        // Its age on the wall clock, onto the steady clock (a wall clock set back: age 0).
        const double age = static_cast<double>(wall.tv_sec - stamp.tv_sec) +
                           1e-9 * static_cast<double>(wall.tv_nsec - stamp.tv_nsec);
        if (std::isfinite(age)) source.arrival_s -= std::max(0.0, age);
        source.kernel_time = true;
        continue;
      }
#endif
      if (c->cmsg_level == IPPROTO_IP && c->cmsg_type == IP_PKTINFO) {
        in_pktinfo info{};
        std::memcpy(&info, CMSG_DATA(c), sizeof info);
        source.destination = ntohl(info.ipi_addr.s_addr);  // the header's destination address
        continue;
      }
#ifdef SO_RXQ_OVFL
      if (c->cmsg_level != SOL_SOCKET || c->cmsg_type != SO_RXQ_OVFL) continue;
      std::uint32_t dropped = 0;
      std::memcpy(&dropped, CMSG_DATA(c), sizeof dropped);
      m.kernel_drops_total += static_cast<std::uint32_t>(dropped - m.kernel_drops[i]);  // wraps at 2^32
      m.kernel_drops[i] = dropped;
#endif
    }
    m.next_rx = i;  // drain this socket first next time
    source.address = from.sin_family == AF_INET ? ntohl(from.sin_addr.s_addr) : 0;
    source.port = ntohs(from.sin_port);
    return std::span<const std::uint8_t>(m.buffer.data(), n);
  }
  return std::nullopt;
}

double steady_now_s() noexcept {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::uint64_t UdpTransport::dropped_by_kernel() const noexcept { return impl_->kernel_drops_total; }

int UdpTransport::native_handle() const noexcept { return impl_->sockets.front().native_handle(); }
int UdpTransport::receive_buffer_bytes() const noexcept {
  asio::error_code ec;
  asio::socket_base::receive_buffer_size size;
  impl_->sockets.front().get_option(size, ec);
  return ec ? 0 : size.value();
}
int UdpTransport::native_handle(std::size_t i) const noexcept {
  return i < impl_->sockets.size() ? impl_->sockets[i].native_handle() : -1;
}

const UdpUrl& UdpTransport::destination() const noexcept { return impl_->url; }
const std::string& UdpTransport::iface() const noexcept { return impl_->iface; }
std::uint16_t UdpTransport::local_port() const noexcept {
  asio::error_code ec;
  auto ep = impl_->sockets.front().local_endpoint(ec);
  return ec ? 0 : ep.port();
}
const std::string& UdpTransport::last_error() const noexcept { return impl_->last_error; }

}  // namespace net
