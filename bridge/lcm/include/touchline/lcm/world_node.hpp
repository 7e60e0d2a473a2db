#pragma once
// sim_world's LCM adapter: runs a Match over LCM. It publishes each frame's sense_t,
// gathers the robots' act_t answers (lockstep: waits for every active robot up to a
// timeout; free: never waits, late answers apply late), steps the world and publishes
// world truth, game state and robot status.
#include <cstdint>
#include <functional>
#include <spdlog/fwd.h>
#include <optional>
#include <string>
#include <vector>

#include "touchline/lcm/bus.hpp"
#include "touchline/lcm/codec.hpp"
#include "touchline/lcm/match_key.hpp"
#include "touchline/lcm/process_probe.hpp"
#include "touchline/gamecontroller/receiver.hpp"
#include "touchline/sim/match.hpp"

namespace touchline::transport {

enum class Pacing {
  kLockstep, ///< wait for every active robot, as fast as they allow (default)
  kRealtime, ///< lockstep, paced to the wall clock at `speed` times real time
  kFree,     ///< never wait; paced at `speed`; late answers apply late
};

struct WorldNodeDef {
  std::string lcm_url = kDefaultUrl;
  MatchKey key;                  ///< the match secret every message is authenticated with
  Pacing pacing = Pacing::kLockstep;
  double speed = 1.0;            ///< real-time multiple for kRealtime and kFree
  int64_t robot_timeout_ms = 1000; ///< wall time a robot may take to answer a frame ...
  /// ... or, lockstep and realtime, this long while its robot_shim still runs on this machine
  /// (shim_runs: a busy machine or a debugger's breakpoint must not change the match)
  int64_t live_robot_timeout_ms = 60000;
  /// Whether the robot_shim of process id `pid` (its join's) still runs; the default asks /proc.
  std::function<bool(int pid)> shim_runs = [](int pid) { return process_runs(pid, "robot_shim"); };
  int64_t resend_ms = 20;        ///< wall time after which the frame's sense goes out again to late robots
  int robots = 8;                ///< joins to wait for before kick-off
  double join_timeout_s = 30;    ///< wall time to wait for them
  std::string summary_path;      ///< write a JSON summary here at the end (empty: none)
  std::string log_path;          ///< record every message to this LCM event log (empty: none)
  /// Take the game from the official GameController's UDP packets instead of the built-in
  /// referee (which the config must switch off: rules.referee = false).
  std::optional<GameControllerReceiverOptions> gamecontroller;
  bool progress = true;          ///< print a line per simulated 10 s
};

/// What a run did, for the summary and the tests.
struct RunSummary {
  int64_t frames = 0;
  double sim_s = 0;
  double wall_s = 0;
  uint64_t truth_hash = 0;  ///< FNV-1a over every published world_truth_t, in order
  int64_t malformed = 0;    ///< messages that failed to decode or validate (implausible and future answers too)
  int64_t stale = 0;        ///< answers that came too late (lockstep) and were dropped
  int64_t future = 0;       ///< answers to frames not yet sensed: dropped
  int64_t duplicates = 0;   ///< second answers to an answered frame (to a repeated sense): dropped
  int64_t implausible = 0;  ///< answers moving a foot or the head beyond any robot: dropped
  int64_t unauthenticated = 0;  ///< messages without a valid tag (not from this match): dropped
  int64_t handler_failures = 0; ///< messages whose handling failed: dropped
  int64_t resent_senses = 0;    ///< senses sent again to late robots
  int64_t slow_answers = 0;     ///< answers waited for past robot_timeout_ms (their shim still ran)
  bool interrupted = false; ///< stopped by SIGINT/SIGTERM
  /// Every event published on TL_EVENT, oldest first: the world's own record, which a
  /// listener on the bus may have missed part of (UDP drops packets under load).
  std::vector<sim::MatchEvent> events;
};

/// Opens the bus at def.lcm_url and runs the match to its end. Messages for the user go to
/// `log`: progress, joins and the GameController at info, refused or malformed messages at warn. Throws std::runtime_error when the robots do not join in time or
/// LCM fails.
RunSummary run_world(sim::Match& match, const WorldNodeDef& def, spdlog::logger& log);
/// The same on a bus someone else opened (e.g. memq:// shared with RobotNodes in one
/// process: this loop then dispatches their messages too). def.lcm_url and def.key are unused.
RunSummary run_world(sim::Match& match, const WorldNodeDef& def, Bus& bus, spdlog::logger& log);

/// 16 lowercase hex digits.
std::string hex_hash(uint64_t value);

/// Asks a running run_world to stop after the current frame (signal-safe).
void request_stop();

} // namespace touchline::transport
