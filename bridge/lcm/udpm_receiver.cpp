#include "touchline/lcm/udpm_receiver.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace touchline::transport {

namespace {

constexpr uint32_t kShortMagic = 0x4c433032; ///< "LC02": a whole message in one datagram
constexpr size_t kShortHeaderBytes = 8;      ///< magic, sequence number (both big-endian)
constexpr size_t kMaxDatagramBytes = 65536;
constexpr const char* kLcmDefaultNetwork = "239.255.76.67:7667";

struct Address {
  in_addr group{};
  uint16_t port = 0;
  int recv_buf_size = 0; ///< 0: the kernel's default
};

/// "udpm://GROUP:PORT?key=value&..." as LCM reads it.
Address parse(const std::string& url) {
  const std::string rest = url.substr(std::strlen("udpm://"));
  const size_t options_at = rest.find('?');
  std::string network = rest.substr(0, options_at);
  if (network.empty()) network = kLcmDefaultNetwork;
  const size_t colon = network.find(':');
  Address address;
  if (inet_aton(network.substr(0, colon).c_str(), &address.group) == 0)
    throw std::runtime_error("cannot listen on " + url + ": bad multicast address");
  if (colon != std::string::npos) {
    const std::string port = network.substr(colon + 1);
    char* end = nullptr;
    const long value = std::strtol(port.c_str(), &end, 0);
    if (end == port.c_str() || value < 0 || value > 65535)
      throw std::runtime_error("cannot listen on " + url + ": bad port");
    address.port = static_cast<uint16_t>(value);
  }
  if (options_at == std::string::npos) return address;
  const std::string options = rest.substr(options_at + 1);
  for (size_t at = 0; at <= options.size();) {
    const size_t amp = std::min(options.find('&', at), options.size());
    const std::string option = options.substr(at, amp - at);
    if (option.rfind("recv_buf_size=", 0) == 0) address.recv_buf_size = std::atoi(option.c_str() + 14);
    at = amp + 1;
  }
  return address;
}

} // namespace

bool is_udpm_url(const std::string& url) { return url.rfind("udpm://", 0) == 0; }

UdpmReceiver::UdpmReceiver(const std::string& url) : buffer_(kMaxDatagramBytes) {
  const Address address = parse(url);
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw std::runtime_error("cannot listen on " + url + ": " + std::strerror(errno));
  const auto fail = [&](const char* what) {
    const std::string reason = std::strerror(errno);
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error("cannot listen on " + url + ": " + what + ": " + reason);
  };
  const int on = 1;
  if (::setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on) < 0) fail("SO_REUSEADDR");
  // Only this group's datagrams on the port (Linux would otherwise deliver any group's that
  // some other socket of the host joined).
  const int off = 0;
  ::setsockopt(fd_, IPPROTO_IP, IP_MULTICAST_ALL, &off, sizeof off);
  if (address.recv_buf_size > 0)
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &address.recv_buf_size, sizeof address.recv_buf_size);
  sockaddr_in bound{};
  bound.sin_family = AF_INET;
  bound.sin_addr.s_addr = htonl(INADDR_ANY);
  bound.sin_port = htons(address.port);
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&bound), sizeof bound) < 0) fail("bind");
  ip_mreq membership{};
  membership.imr_multiaddr = address.group;
  membership.imr_interface.s_addr = htonl(INADDR_ANY);
  if (::setsockopt(fd_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &membership, sizeof membership) < 0)
    fail("joining the multicast group");
}

UdpmReceiver::~UdpmReceiver() {
  if (fd_ >= 0) ::close(fd_);
}

bool UdpmReceiver::receive(Message& out) {
  for (;;) {
    const ssize_t n = ::recv(fd_, buffer_.data(), buffer_.size(), 0);
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) return false;
      throw std::runtime_error(std::string("LCM receive failed: ") + std::strerror(errno));
    }
    const auto size = static_cast<size_t>(n);
    uint32_t magic = 0;
    if (size >= kShortHeaderBytes) {
      std::memcpy(&magic, buffer_.data(), sizeof magic);
      magic = ntohl(magic);
    }
    const auto* channel = reinterpret_cast<const char*>(buffer_.data() + kShortHeaderBytes);
    const void* nul = size > kShortHeaderBytes ? std::memchr(channel, 0, size - kShortHeaderBytes) : nullptr;
    if (magic != kShortMagic || !nul) { // a fragment, or not LCM's
      ++dropped_;
      continue;
    }
    const auto* data = static_cast<const uint8_t*>(nul) + 1;
    out = Message{channel, data, size - static_cast<size_t>(data - buffer_.data())};
    return true;
  }
}

} // namespace touchline::transport
