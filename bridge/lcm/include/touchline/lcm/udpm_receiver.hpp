#pragma once
// Receives LCM's udpm datagrams in the caller's own thread. LCM 1.3.1's udpm provider reads
// its socket in a thread of its own and hands each message over through a pipe: two thread
// switches per message where one would do, and on a 2-core machine carrying 9 processes of a
// lockstep match those switches, not the work, were most of a frame (issue #14, item 3).
// The bus reads a lane it listens to with this instead, and still sends through LCM (an LCM
// instance that only publishes starts no thread). The datagrams are LCM's own, so lcm-spy,
// lcm-logger and the Python tools read the same traffic as before.
//
// Reads LCM's short messages ("LC02": magic, sequence number, channel, NUL, payload); LCM
// splits a message into fragments ("LC03") only above 65,499 bytes, far beyond any message
// of a match, so a fragment is counted and dropped.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace touchline::transport {

class UdpmReceiver {
 public:
  /// Joins the group of `url` ("udpm://GROUP:PORT?options"; recv_buf_size is honoured) on
  /// its port, as LCM does (SO_REUSEADDR, so every process of a match can). Throws
  /// std::runtime_error (one line) if it cannot.
  explicit UdpmReceiver(const std::string& url);
  ~UdpmReceiver();
  UdpmReceiver(const UdpmReceiver&) = delete;
  UdpmReceiver& operator=(const UdpmReceiver&) = delete;

  /// The socket, to wait on (readable: a datagram is waiting).
  int fd() const { return fd_; }

  /// One message as received: valid until the next receive().
  struct Message {
    const char* channel;
    const uint8_t* data;
    size_t size;
  };
  /// Reads one waiting datagram into `out` without blocking. false when none is waiting.
  /// Datagrams that are not an LCM short message are skipped (counted in dropped()).
  bool receive(Message& out);

  int64_t dropped() const { return dropped_; }

 private:
  int fd_ = -1;
  std::vector<uint8_t> buffer_;
  int64_t dropped_ = 0;
};

/// Whether `url` is one UdpmReceiver reads ("udpm://...").
bool is_udpm_url(const std::string& url);

} // namespace touchline::transport
