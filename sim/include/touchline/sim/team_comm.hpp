#pragma once
// Team communication: each robot may send a bounded message at a bounded rate; the world
// relays it to every teammate on the field after a latency, losing each delivery with a
// probability. Seeded; no wall time. Reads: the robots' messages. Writes: deliveries.
//
// Order-free: whether a delivery is lost is a keyed draw on (seed, send time, sender,
// recipient), and a recipient gets what has arrived ordered by (arrival time, sender), so
// the same messages give the same deliveries in whatever order they are sent.
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "touchline/frame.hpp"
#include "touchline/ini.hpp"

namespace touchline::sim {

/// The [comm] section of a world config.
struct CommDef {
  int max_bytes = 128;            ///< longest message a robot may send, bytes (longer: not sent)
  float max_rate_hz = 5.f;        ///< messages per second a robot may send (faster: not sent)
  float latency_ms = 100.f;       ///< from sending to arriving, simulated milliseconds
  float loss_probability = 0.1f;  ///< each delivery to each teammate is lost with this chance
};

void bind(IniSchema& schema, CommDef& def);
void validate(const CommDef& def);

/// Why a message was not sent.
enum class SendResult { kSent, kTooLong, kTooSoon };

class TeamComm {
 public:
  TeamComm(const CommDef& def, uint64_t seed);

  /// `from` sends `data` at `utime` to the teammates in `team` (itself excluded). At most
  /// one message per robot per `utime` is sent (the rate limit sees to it).
  SendResult send(RobotId from, int64_t utime, const std::vector<uint8_t>& data, const std::vector<RobotId>& team);
  /// Messages for `to` that have arrived by `utime`, oldest first and, arriving together,
  /// by sender's player number; they are handed out once.
  std::vector<TeamMessageFrame> receive(RobotId to, int64_t utime);

  int64_t sent() const { return sent_; }
  int64_t delivered() const { return delivered_; }
  int64_t lost() const { return lost_; }
  int64_t refused() const { return refused_; }

 private:
  /// (arrival time in microseconds, sender's player number): the order of delivery.
  using Arrival = std::pair<int64_t, int>;
  CommDef def_;
  uint64_t seed_;
  std::map<RobotId, int64_t> last_sent_utime_;
  std::map<RobotId, std::multimap<Arrival, TeamMessageFrame>> in_flight_; ///< per recipient
  int64_t sent_ = 0, delivered_ = 0, lost_ = 0, refused_ = 0;
};

} // namespace touchline::sim
