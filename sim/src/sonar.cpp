#include "touchline/sim/sonar.hpp"

#include <algorithm>
#include <cmath>

namespace touchline::sim {

void sonar_update(const SonarDef& sonar, const Pose2D& body, float x_mm, float y_mm, SonarReading& reading) {
  // The obstacle in the robot frame: ahead along +x, left along +y. (The thesis computes
  // the same through theta = 90 deg - angle with sin/cos swapped.)
  const float dx = x_mm - body.x_mm, dy = y_mm - body.y_mm;
  const float c = std::cos(body.theta_rad), s = std::sin(body.theta_rad);
  const float ahead = dx * c + dy * s;
  const float lateral = -dx * s + dy * c; // + left
  if (ahead <= 0 || ahead >= sonar.range_mm || std::fabs(lateral) >= sonar.half_width_mm) return;
  const float fraction = ahead / sonar.range_mm;
  // Algorithm 2.4's x_relative is positive to the right, which it gives the right sonar.
  if (lateral <= 0) {
    reading.right = std::min(reading.right, fraction);
  } else {
    reading.left = std::min(reading.left, fraction);
  }
}

} // namespace touchline::sim
