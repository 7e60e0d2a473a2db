#pragma once
// TL_MATCH: the match's geometry and set-up (match_config_t) from the WorldConfig the world
// runs, so that the tools which draw or count a match (viewer, launcher) take the sizes
// from the match itself and never from their own copy of a config file.
#include <cstdint>

#include "touchline/match_config_t.hpp"
#include "touchline/sim/config.hpp"

namespace touchline::transport {

constexpr const char* kMatchChannel = "TL_MATCH";

/// `config` as the world plays it (after --set and --duration), the match `seed` and the
/// simulated time `utime` of sending, stamped with this build's types version.
match_config_t to_lcm(const sim::WorldConfig& config, uint64_t seed, int64_t utime);

} // namespace touchline::transport
