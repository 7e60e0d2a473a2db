#pragma once
// Receives the official SPL GameController's data packets over UDP (IPv4), for a world
// that takes its game state from the GameController instead of its built-in referee.
// Decoding is touchline/gamecontroller/packet.hpp; this only owns the socket.
//
// poll() never blocks: it reads every datagram waiting, and returns the latest one that
// decodes (in arrival order), or nothing if none did since the last poll. Datagrams that
// do not decode are counted and dropped (bad_packets(), last_error()).
//
// The GameController broadcasts; to receive broadcasts bind "0.0.0.0" (the default
// address, 127.0.0.1, receives only packets sent to loopback).
#include <cstdint>
#include <optional>
#include <string>

#include "touchline/gamecontroller/packet.hpp"

namespace touchline::transport {

struct GameControllerReceiverOptions {
  std::string address = "127.0.0.1";               ///< IPv4 address to bind, dotted quad
  uint16_t port = sim::gamecontroller::kDataPort; ///< 0: an ephemeral port (see port())
  sim::GameControllerConfig decode;               ///< how packets map to our teams
};

class GameControllerReceiver {
 public:
  /// Opens and binds a non-blocking UDP socket. Throws std::invalid_argument for an
  /// address that is not a dotted-quad IPv4 address or an invalid decode config,
  /// std::runtime_error (naming address, port and the reason) if the socket cannot be
  /// opened or bound.
  explicit GameControllerReceiver(GameControllerReceiverOptions options = {});
  ~GameControllerReceiver();
  GameControllerReceiver(const GameControllerReceiver&) = delete;
  GameControllerReceiver& operator=(const GameControllerReceiver&) = delete;

  /// Reads everything pending without blocking; the latest valid packet, if any arrived.
  /// Throws std::runtime_error only if the socket itself fails (not for bad packets).
  std::optional<sim::GameControllerPacket> poll();

  uint16_t port() const { return port_; } ///< the bound port (the ephemeral one for port 0)
  const std::string& address() const { return options_.address; }
  int64_t good_packets() const { return good_; }
  int64_t bad_packets() const { return bad_; }
  const std::string& last_error() const { return last_error_; } ///< why the last bad packet was bad

 private:
  GameControllerReceiverOptions options_;
  int fd_ = -1;
  uint16_t port_ = 0;
  int64_t good_ = 0;
  int64_t bad_ = 0;
  std::string last_error_;
};

} // namespace touchline::transport
