#include "touchline/sim/touch.hpp"

#include <cmath>

#include "touchline/angles.hpp"

namespace touchline::sim {

namespace {

/// Folds a toucher at (x, y) into `touch` for a robot at `body` if it is nearer than reach_mm.
void touch_within(float reach_mm, const Pose2D& body, float x_mm, float y_mm, Touch& touch) {
  const float dx = x_mm - body.x_mm, dy = y_mm - body.y_mm;
  if (std::hypot(dx, dy) >= reach_mm) return;
  const float bearing = normalise_angle(std::atan2(dy, dx) - body.theta_rad); // + left
  constexpr float kQuarter = kPi / 4;
  if (std::fabs(bearing) > 3 * kQuarter) touch.back = true;
  else if (bearing > kQuarter) touch.left = true;
  else if (bearing < -kQuarter) touch.right = true;
  else if (bearing >= 0) touch.front_left = true;
  else touch.front_right = true;
}

} // namespace

void touch_update(const TouchDef& def, const Pose2D& body, float x_mm, float y_mm, Touch& touch) {
  touch_within(def.distance_mm, body, x_mm, y_mm, touch);
}

void touch_post_update(const TouchDef& def, const Pose2D& body, float x_mm, float y_mm, Touch& touch) {
  touch_within(def.post_distance_mm, body, x_mm, y_mm, touch);
}

} // namespace touchline::sim
