#pragma once
// The match summary sim_world --summary and touchline_match --summary write, and
// tools/launch.py reads: the run (frames, sim and wall time, real-time factor, truth hash,
// dropped messages), the score, where the ball and each robot ended, each robot's
// answers, behaviour CPU and localisation error; and the one-line plan of a match that
// sim_world --check and touchline_match --print-match print before one is played.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "touchline/lcm/world_node.hpp"
#include "touchline/sim/match.hpp"
#include "touchline/sim/config.hpp"

namespace touchline::apps {

/// What only the in-process match adds: it can tell the world's time from the robots'.
struct InProcessExtras {
  double world_wall_s = 0; ///< wall seconds spent in the world, not in robot code
  double cpu_s = 0;        ///< CPU seconds the process spent on the match (any load beside it aside)
};

/// Writes the summary of `match`, run as `s` with `seed`, to `path`, with s.events as
/// "match_events" (each as the world node publishes it on TL_EVENT: utime, kind, team,
/// player, text); with `extras` also "world_wall_s" and "physics_rtf" (simulated seconds
/// per wall second of the world alone: the fastest the match could run with free robots),
/// "cpu_s" and "cpu_rtf" (simulated seconds per CPU second: the rtf on a core of its own).
/// Throws std::runtime_error if the file cannot be written.
void write_summary_json(const std::string& path, const sim::Match& match, const transport::RunSummary& s,
                        uint64_t seed, const std::optional<InProcessExtras>& extras = std::nullopt);

/// One line of JSON a launcher reads before a match: its planned length ("planned_s": two
/// halves with their set-up states and half time, capped at "duration_s"), the stoppage each
/// goal adds ("goal_stoppage_s"), "team_size" and the field ("field_length_mm",
/// "field_width_mm").
std::string match_plan_json(const sim::WorldConfig& config);

} // namespace touchline::apps
