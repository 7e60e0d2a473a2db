#pragma once
// What the world says about the match, as messages: the truth of each frame (TL_TRUTH,
// whose bytes make the match's truth hash) and the referee's events (TL_EVENT). The world
// node publishes them; touchline_match (world and robots in one process) hashes and
// reports the same messages, so both modes give one truth hash for one match.
#include <cstdint>
#include <vector>

#include "touchline/game_state_t.hpp"
#include "touchline/hash.hpp"
#include "touchline/match_event_t.hpp"
#include "touchline/sim/match.hpp"
#include "touchline/world_truth_t.hpp"

namespace touchline::transport {

world_truth_t to_msg(const sim::TruthFrame& truth);
match_event_t to_msg(const sim::MatchEvent& event);
/// TL_GAME: the game at `utime`; `finished` says FINISHED whatever the referee's state (the
/// world's last word, said when it stops).
game_state_t to_msg(const GameInfo& game, int64_t utime, bool finished = false);

/// A message's bytes as LCM encodes it (no bus tag).
template <typename Msg>
std::vector<uint8_t> encoded(const Msg& msg) {
  std::vector<uint8_t> bytes(static_cast<size_t>(msg.getEncodedSize()));
  msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

/// The match's truth hash: FNV-1a over every frame's world_truth_t encoding in order (the
/// message as published, without the bus's tag, so the same seed gives the same hash
/// whatever the match secret).
class TruthHash {
 public:
  /// One frame, from the encoding as published (or, in process, as encoded()).
  void add(const uint8_t* encoded, size_t size) { hash_.add(encoded, size); }
  uint64_t value() const { return hash_.value(); }

 private:
  Fnv1a hash_;
};

} // namespace touchline::transport
