#pragma once
// The match bus: LCM with every message authenticated. Both programs talk through it
// and nothing else of theirs includes LCM's own headers.
//
// On the wire a message is its LCM encoding followed by a 32-byte tag, HMAC-SHA-256 over
// the channel name, a zero byte and the encoding, keyed with the match secret. LCM's
// decoders (C++, Python, Java: lcm-spy, lcm-logplayer, the viewer) read the encoding and
// ignore what follows, so every tool still decodes the match. A message whose tag does
// not verify is counted and dropped before any handler sees it.
//
// Built on LCM's C API: the programs run clean under AddressSanitizer with it, which they
// did not with Debian's LCM 1.3.1 C++ wrapper (issue #13, item 13). The wrapper was not at
// fault: GCC 12 miscompiles its dispatch, (subs->handler->*subs->handlerMethod)(...) in
// lcm-cpp-impl.hpp, under -fsanitize=vptr (part of undefined). The vptr check of `subs`
// for the call's second member access reads `subs` from a register loaded only on the
// virtual-function path, so a handler that is not virtual gets a stale `this` (reported as
// heap-use-after-free, stack-buffer-underflow or SEGV, by what the register last held).
// Any `(p->object->*p->method)(...)` with a polymorphic `*p` does it, no LCM involved;
// without vptr the same build is clean. So no member-function handlers via lcm::LCM here.
//
// A match's channels travel on three lanes (lanes.hpp): on a udpm URL, what robots send the
// world goes to the port above the URL's, which only the world joins, and what the robots
// need from the world is copied to the port above that, the only one robots join. The bus
// opens one LCM instance per lane to send on, routes each publish by its channel and each
// subscription by its pattern and role, and listens only on the lanes it subscribed to, so
// a robot is woken by neither the other robots' answers nor the truth, and the world not by
// its own senses. A udpm lane is read in the caller's
// thread (udpm_receiver.hpp), not by LCM's receive thread and its pipe.
//
// Handlers never let an exception out: one that throws is counted and reported, and the
// bus goes on (an exception must never unwind through liblcm's C frames).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "touchline/lcm/lanes.hpp"
#include "touchline/lcm/match_key.hpp"

typedef struct _lcm_t lcm_t;

namespace touchline::transport {

/// Bytes of the authentication tag after each message's LCM encoding.
constexpr size_t kTagBytes = 32;

/// One authenticated message, as a handler sees it.
struct BusMessage {
  const std::string& channel;
  const uint8_t* payload;   ///< the LCM encoding (tag removed)
  size_t payload_size;
  const uint8_t* wire;      ///< payload followed by its tag, as received (for recorders)
  size_t wire_size;
};

/// What the bus refused or failed at, for the summaries and the tests.
struct BusCounters {
  int64_t unauthenticated = 0;  ///< messages whose tag did not verify (or with no tag): dropped
  int64_t handler_failures = 0; ///< handlers that threw: the message was dropped
};

/// Who listens on a bus, which decides where it hears what the world sends the robots.
enum class BusRole {
  kObserver, ///< the world, a tool or a test: the world's messages on the match lane
  kRobot,    ///< a robot: TL_SENSE, TL_GAME, TL_JOIN_REPLY on the robots' lane (lanes.hpp)
};

class Bus {
 public:
  using Handler = std::function<void(const BusMessage&)>;
  /// Receives one line per refused message or failed handler (the caller bounds how many
  /// it prints).
  using Reporter = std::function<void(const std::string&)>;

  /// Opens LCM at `url` (every lane: lane_urls(url)). Throws std::runtime_error (one line)
  /// if LCM cannot.
  Bus(const std::string& url, MatchKey key, Reporter report = {}, BusRole role = BusRole::kObserver);
  ~Bus();
  Bus(const Bus&) = delete;
  Bus& operator=(const Bus&) = delete;

  /// Calls `handler` for every authenticated message on channels matching `channel_regex`,
  /// heard on the lane of the pattern (lane_of(channel_regex); for a robot, the robots' lane
  /// for what to_robots() names).
  void subscribe(const std::string& channel_regex, Handler handler);

  /// Sends `payload` (an LCM encoding) with its tag on its channel's lane (and what the
  /// robots need on theirs first, then on the match lane); returns the bytes as sent.
  std::vector<uint8_t> publish(const std::string& channel, const uint8_t* payload, size_t size);
  /// Encodes `msg` and sends it; returns the bytes as sent (the encoding is all but the
  /// last kTagBytes).
  template <typename Msg>
  std::vector<uint8_t> publish(const std::string& channel, const Msg& msg) {
    std::vector<uint8_t> encoded(static_cast<size_t>(msg.getEncodedSize()));
    msg.encode(encoded.data(), 0, static_cast<int>(encoded.size()));
    return publish(channel, encoded.data(), encoded.size());
  }

  /// Sends again bytes that publish() returned (a repeat, as sent the first time).
  void publish_sealed(const std::string& channel, const std::vector<uint8_t>& wire);

  /// Waits up to `timeout_ms` (0: not at all) for a message on any lane subscribed to and
  /// dispatches what came.
  /// Returns whether one was handled. Throws std::runtime_error if LCM fails.
  bool handle(int timeout_ms);
  /// Dispatches every message already waiting, without waiting for more.
  void drain();

  const BusCounters& counters() const { return counters_; }
  /// The URLs this bus opened, one per lane.
  const LaneUrls& urls() const { return urls_; }

  /// `payload` followed by its tag for `channel` (what publish() sends).
  std::vector<uint8_t> seal(const std::string& channel, const uint8_t* payload, size_t size) const;
  /// Whether `wire` ends in the right tag for `channel`.
  bool verify(const std::string& channel, const uint8_t* wire, size_t size) const;

 private:
  struct Subscription;
  /// One lane: the LCM instance it sends on and, once subscribed to, what it listens with
  /// (a UdpmReceiver on a udpm URL, LCM itself on any other).
  struct LaneState;
  static void on_message(const void* rbuf, const char* channel, void* user);
  void dispatch(Subscription& subscription, const std::string& channel, const uint8_t* wire, size_t size);
  /// Dispatches every datagram waiting on a lane read with a UdpmReceiver.
  bool receive_all(LaneState& lane);
  void tag(const std::string& channel, const uint8_t* payload, size_t size, uint8_t* out) const;
  LaneState& lane(Lane lane) const;

  MatchKey key_;
  Reporter report_;
  LaneUrls urls_;
  BusRole role_;
  std::vector<std::unique_ptr<LaneState>> lanes_; ///< one, or three (Lane's order) when urls_.split()
  std::vector<std::unique_ptr<Subscription>> subscriptions_;
  BusCounters counters_;
};

} // namespace touchline::transport
