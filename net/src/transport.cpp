// transport.cpp — Asio UDP socket setup for multicast / unicast / broadcast, non-blocking I/O.
#ifndef ASIO_STANDALONE
#define ASIO_STANDALONE
#endif
#include "net/transport.hpp"

#include <array>
#include <asio.hpp>
#include <charconv>
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
  const std::string quoted = "\"" + std::string(url) + "\"";
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
  asio::ip::udp::socket socket{io};
  asio::ip::udp::endpoint destination;
  UdpUrl url;
  std::string iface;
  std::string last_error;
  std::array<std::uint8_t, 65536> buffer{};
};

namespace {

[[noreturn]] void fail(const std::string& what, const asio::error_code& ec) {
  throw std::runtime_error(what + ": " + ec.message());
}

}  // namespace

UdpTransport::UdpTransport(const TransportConfig& config) : impl_(std::make_unique<Impl>()) {
  auto parsed = parse_udp_url(config.url);
  if (!parsed) throw std::runtime_error(parsed.error());
  Impl& m = *impl_;
  m.url = parsed.value();
  if (config.mode) m.url.mode = *config.mode;
  m.iface = config.iface;
  max_per_poll_ = config.max_datagrams_per_poll == 0 ? 1 : config.max_datagrams_per_poll;

  asio::error_code ec;
  const auto iface = asio::ip::make_address_v4(config.iface, ec);
  if (ec)
    throw std::runtime_error("interface address \"" + config.iface +
                             "\" is not a dotted IPv4 address (give the local address to send "
                             "and join multicast on, e.g. --iface 127.0.0.1)");
  const auto addr = asio::ip::make_address_v4(m.url.address);
  if (m.url.mode == UdpMode::Multicast && !addr.is_multicast())
    throw std::runtime_error("network URL \"" + config.url + "\": " + m.url.address +
                             " is not a multicast group (224.0.0.0/4)");
  m.destination = asio::ip::udp::endpoint(addr, m.url.port);

  const std::string where = std::string(to_string(m.url.mode)) + " " + m.url.address + ":" +
                            std::to_string(m.url.port) + " on " + config.iface;
  m.socket.open(asio::ip::udp::v4(), ec);
  if (ec) fail("cannot open UDP socket for " + where, ec);
  m.socket.set_option(asio::socket_base::reuse_address(true), ec);
  if (ec) fail("cannot set SO_REUSEADDR for " + where, ec);

  asio::ip::udp::endpoint bind_to(asio::ip::address_v4::any(), m.url.port);
  if (m.url.mode == UdpMode::Multicast) bind_to = asio::ip::udp::endpoint(addr, m.url.port);
  m.socket.bind(bind_to, ec);
  if (ec) fail("cannot bind UDP port " + std::to_string(m.url.port) + " for " + where, ec);

  if (m.url.mode == UdpMode::Multicast) {
    m.socket.set_option(asio::ip::multicast::join_group(addr, iface), ec);
    if (ec) fail("cannot join multicast group for " + where + " (is " + config.iface +
                     " an address of this host?)", ec);
    m.socket.set_option(asio::ip::multicast::outbound_interface(iface), ec);
    if (ec) fail("cannot set IP_MULTICAST_IF for " + where, ec);
    m.socket.set_option(asio::ip::multicast::hops(config.multicast_ttl), ec);
    if (ec) fail("cannot set multicast TTL for " + where, ec);
    m.socket.set_option(asio::ip::multicast::enable_loopback(config.multicast_loopback), ec);
    if (ec) fail("cannot enable multicast loopback for " + where, ec);
  } else if (m.url.mode == UdpMode::Broadcast) {
    m.socket.set_option(asio::socket_base::broadcast(true), ec);
    if (ec) fail("cannot set SO_BROADCAST for " + where, ec);
  }
  m.socket.non_blocking(true, ec);
  if (ec) fail("cannot make the socket non-blocking for " + where, ec);
}

UdpTransport::~UdpTransport() = default;
UdpTransport::UdpTransport(UdpTransport&&) noexcept = default;
UdpTransport& UdpTransport::operator=(UdpTransport&&) noexcept = default;

bool UdpTransport::send(std::span<const std::uint8_t> datagram) noexcept {
  asio::error_code ec;
  impl_->socket.send_to(asio::buffer(datagram.data(), datagram.size()), impl_->destination, 0, ec);
  if (ec) {
    impl_->last_error = "send to " + impl_->url.address + ":" + std::to_string(impl_->url.port) +
                        " failed: " + ec.message();
    return false;
  }
  return true;
}

std::optional<std::span<const std::uint8_t>> UdpTransport::receive() noexcept {
  asio::error_code ec;
  asio::ip::udp::endpoint from;
  const std::size_t n =
      impl_->socket.receive_from(asio::buffer(impl_->buffer), from, 0, ec);
  if (ec) {
    if (ec != asio::error::would_block && ec != asio::error::try_again)
      impl_->last_error = "receive failed: " + ec.message();
    return std::nullopt;
  }
  return std::span<const std::uint8_t>(impl_->buffer.data(), n);
}

const UdpUrl& UdpTransport::destination() const noexcept { return impl_->url; }
const std::string& UdpTransport::iface() const noexcept { return impl_->iface; }
std::uint16_t UdpTransport::local_port() const noexcept {
  asio::error_code ec;
  auto ep = impl_->socket.local_endpoint(ec);
  return ec ? 0 : ep.port();
}
const std::string& UdpTransport::last_error() const noexcept { return impl_->last_error; }

}  // namespace net
