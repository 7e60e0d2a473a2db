#pragma once
// Random draws every model shares. Not std:: distributions: their algorithms differ between
// standard libraries, and a seed must give the same match everywhere.
//
// The world's draws are keyed: each is a pure function of (seed, stream, frame, who, what),
// computed by a counter-based generator (Random123's Threefry4x64, 20 rounds) rather than
// taken from one shared sequence. So the order in which robots' answers arrive, a robot
// joining late, or one robot seeing one more object never shifts another's draws.
#include <cstdint>
#include <limits>

// threefry.h first: MicroURNG.hpp uses the compiler-feature macros it defines.
#include <Random123/threefry.h>
#include <Random123/MicroURNG.hpp>

namespace touchline {

/// Uniform in [0, 1) from the top 53 bits of one 64-bit draw.
template <typename Generator>
double uniform01(Generator& rng) {
  static_assert(std::numeric_limits<typename Generator::result_type>::digits == 64, "needs 64 random bits per draw");
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

/// Which model draws: one stream each, so no two models ever share a draw.
enum class DrawStream : uint64_t {
  kFall = 1,     ///< who: the pushed robot, what: the pusher
  kTeamMessage,  ///< who: the sender, what: the recipient
  kCamera,       ///< who: the viewer, what: the object (kind, id)
  kPhantomBall,  ///< who: the viewer
  kSonar,        ///< who: the listener
  kInertial,     ///< who: the robot
};

/// Names a robot in a draw key: team and player, distinct for every robot.
constexpr uint32_t draw_id(int team, int player) {
  return (static_cast<uint32_t>(team) << 8) | static_cast<uint32_t>(player);
}

/// A short sequence of draws named by its key: up to 2^34 numbers, each the same whenever
/// the same key is drawn again, in any order, in any process.
using KeyedDraws = r123::MicroURNG<r123::Threefry4x64>;

/// The draws of `stream` for `who` and `what` at `when` in the match seeded `seed`. `when`
/// is the frame number, or the frame's simulated time where a model knows only that.
inline KeyedDraws keyed_draws(uint64_t seed, DrawStream stream, int64_t when, uint64_t who, uint32_t what = 0) {
  // MicroURNG counts its draws in the high half of the counter's last word, left 0 here.
  const KeyedDraws::ctr_type counter = {{static_cast<uint64_t>(when), who, what, 0}};
  const KeyedDraws::ukey_type key = {{seed, static_cast<uint64_t>(stream), 0, 0}};
  return KeyedDraws(counter, key);
}

} // namespace touchline
