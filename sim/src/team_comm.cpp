#include "touchline/sim/team_comm.hpp"

#include "touchline/random.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace touchline::sim {

void bind(IniSchema& s, CommDef& d) {
  s.bind("comm.max_bytes", &d.max_bytes, "longest team message, bytes")
      .bind("comm.max_rate_hz", &d.max_rate_hz, "messages per second per robot")
      .bind("comm.latency_ms", &d.latency_ms, "from sending to arriving, ms")
      .bind("comm.loss_probability", &d.loss_probability, "each delivery is lost with this chance, 0..1");
}

void validate(const CommDef& d) {
  // act_t carries the message's length in an int16_t.
  require_count("comm.max_bytes", d.max_bytes, 0, std::numeric_limits<int16_t>::max());
  require_positive("comm.max_rate_hz", d.max_rate_hz);
  require_non_negative("comm.latency_ms", d.latency_ms);
  require_fraction("comm.loss_probability", d.loss_probability);
}

TeamComm::TeamComm(const CommDef& def, uint64_t seed) : def_(def), seed_(seed) {}

SendResult TeamComm::send(RobotId from, int64_t utime, const std::vector<uint8_t>& data,
                          const std::vector<RobotId>& team) {
  if (static_cast<int64_t>(data.size()) > def_.max_bytes) {
    ++refused_;
    return SendResult::kTooLong;
  }
  const auto min_gap_us = static_cast<int64_t>(std::llround(1e6 / static_cast<double>(def_.max_rate_hz)));
  const auto last = last_sent_utime_.find(from);
  if (last != last_sent_utime_.end() && utime - last->second < min_gap_us) {
    ++refused_;
    return SendResult::kTooSoon;
  }
  last_sent_utime_[from] = utime;
  ++sent_;
  const int64_t arrives = utime + static_cast<int64_t>(std::llround(def_.latency_ms * 1000.0));
  for (RobotId to : team) {
    if (to == from || to.team != from.team) continue;
    auto draws = keyed_draws(seed_, DrawStream::kTeamMessage, utime, draw_id(from.team, from.player),
                             draw_id(to.team, to.player));
    if (uniform01(draws) < def_.loss_probability) {
      ++lost_;
      continue;
    }
    in_flight_[to].emplace(Arrival{arrives, from.player}, TeamMessageFrame{from.player, utime, data});
  }
  return SendResult::kSent;
}

std::vector<TeamMessageFrame> TeamComm::receive(RobotId to, int64_t utime) {
  std::vector<TeamMessageFrame> arrived;
  auto queue = in_flight_.find(to);
  if (queue == in_flight_.end()) return arrived;
  auto& waiting = queue->second;
  while (!waiting.empty() && waiting.begin()->first.first <= utime) {
    arrived.push_back(std::move(waiting.begin()->second));
    waiting.erase(waiting.begin());
    ++delivered_;
  }
  return arrived;
}

} // namespace touchline::sim
