#include "touchline/gamecontroller/receiver.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace touchline::transport {

namespace {

std::string errno_text(int err) { return std::strerror(err); }

} // namespace

GameControllerReceiver::GameControllerReceiver(GameControllerReceiverOptions options)
    : options_(std::move(options)) {
  sim::validate(options_.decode);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(options_.port);
  if (inet_pton(AF_INET, options_.address.c_str(), &addr.sin_addr) != 1)
    throw std::invalid_argument("GameController receiver: \"" + options_.address +
                                "\" is not an IPv4 address (dotted quad)");
  const std::string where = options_.address + ":" + std::to_string(options_.port);

  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw std::runtime_error("GameController receiver: socket: " + errno_text(errno));
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error("GameController receiver: cannot bind " + where + ": " + errno_text(err));
  }
  sockaddr_in bound{};
  socklen_t len = sizeof bound;
  if (::getsockname(fd_, reinterpret_cast<sockaddr*>(&bound), &len) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error("GameController receiver: getsockname on " + where + ": " + errno_text(err));
  }
  port_ = ntohs(bound.sin_port);
}

GameControllerReceiver::~GameControllerReceiver() {
  if (fd_ >= 0) ::close(fd_);
}

std::optional<sim::GameControllerPacket> GameControllerReceiver::poll() {
  std::optional<sim::GameControllerPacket> latest;
  // Larger than any packet we accept, so a longer datagram is seen as too long (MSG_TRUNC
  // makes recv return its real length).
  uint8_t buffer[1024];
  for (;;) {
    const ssize_t n = ::recv(fd_, buffer, sizeof buffer, MSG_TRUNC);
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) break;
      throw std::runtime_error("GameController receiver on " + options_.address + ":" + std::to_string(port_) +
                               ": recv: " + errno_text(errno));
    }
    const auto size = static_cast<std::size_t>(n);
    if (size > sizeof buffer) {
      ++bad_;
      last_error_ = "GameController packet: " + std::to_string(size) + " bytes, expected " +
                    std::to_string(sim::gamecontroller::kPacketSize);
      continue;
    }
    try {
      latest = sim::decode_gamecontroller_packet(buffer, size, options_.decode);
      ++good_;
    } catch (const sim::GameControllerError& e) {
      ++bad_;
      last_error_ = e.what();
    }
  }
  return latest;
}

} // namespace touchline::transport
