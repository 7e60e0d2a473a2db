#pragma once
// Shared set-up for the world's tests (test_world.cpp, test_world_legs.cpp): robot ids,
// stepping with every robot still, and the ball parked out of the feet's way.
#include <cstddef>
#include <vector>

#include "touchline/sim/world.hpp"

namespace touchline::sim::testing {

constexpr RobotId kRed1{0, 1};
constexpr RobotId kBlue1{1, 1};

inline std::vector<TickMotion> still(int robots) { return std::vector<TickMotion>(static_cast<std::size_t>(robots)); }

inline void run(World& world, int ticks) {
  for (int t = 0; t < ticks; ++t) world.step(still(world.robot_count()));
}

/// The ball starts at the centre spot; tests about feet move it out of their way.
inline void park_ball(World& world) { world.place_ball(2500, -2200); }

} // namespace touchline::sim::testing
