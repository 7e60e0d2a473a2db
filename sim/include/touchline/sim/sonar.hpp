#pragma once
// The sonar model of thesis 2.2.5 (Algorithm 2.4): an obstacle ahead within 1 m and
// within a ±100 mm corridor of the robot's centre line sets the left or right reading
// to its distance (as a fraction of the range, 1 = nothing seen).
#include "touchline/frame.hpp"

namespace touchline::sim {

struct SonarDef {
  float range_mm = 1000.f;       ///< farthest obstacle reported
  float half_width_mm = 100.f;   ///< corridor half width either side of the centre line
};

struct SonarReading {
  float left = 1.f;  ///< nearest obstacle on the left half of the corridor, fraction of range
  float right = 1.f; ///< nearest obstacle on the right half, fraction of range
};

/// Folds one obstacle at (x, y) into `reading` for a robot at `body` (Algorithm 2.4).
void sonar_update(const SonarDef& sonar, const Pose2D& body, float x_mm, float y_mm, SonarReading& reading);

} // namespace touchline::sim
