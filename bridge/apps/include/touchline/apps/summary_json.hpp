#pragma once
// The match summary sim_world --summary and touchline_match --summary write, and
// tools/launch.py reads: the run (frames, sim and wall time, real-time factor, truth hash,
// dropped messages), the score, where the ball and each robot ended, each robot's
// answers, behaviour CPU and localisation error.
#include <cstdint>
#include <string>
#include <vector>

#include "touchline/lcm/world_node.hpp"
#include "touchline/sim/match.hpp"

namespace touchline::apps {

/// Writes the summary of `match`, run as `s` with `seed`, to `path`; with `events` (the
/// in-process match, which has no bus for them) also "match_events": each as the world
/// node publishes it on TL_EVENT (utime, kind, team, player, text). Throws
/// std::runtime_error if the file cannot be written.
void write_summary_json(const std::string& path, const sim::Match& match, const transport::RunSummary& s,
                        uint64_t seed, const std::vector<sim::MatchEvent>* events = nullptr);

} // namespace touchline::apps
