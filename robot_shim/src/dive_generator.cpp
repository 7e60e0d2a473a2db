#include "touchline/robot/dive_generator.hpp"

#include <algorithm>
#include <cmath>

#include "touchline/angles.hpp"
#include "touchline/robot/kick_generator.hpp"

namespace touchline::robot {

namespace {

/// Cosine ease in and out over s in [0, 1]: the feet start and land at rest, and a move of
/// D over n ticks peaks at pi * D / (2 * n) per tick (500 mm in 40 ticks: 19.6 mm).
float ease(float s) {
  if (s <= 0) return 0.f;
  if (s >= 1) return 1.f;
  return 0.5f * (1 - std::cos(kPi * s));
}

Pose2D lerp(const Pose2D& a, const Pose2D& b, float t) {
  return {a.x_mm + (b.x_mm - a.x_mm) * t, a.y_mm + (b.y_mm - a.y_mm) * t,
          normalise_angle(a.theta_rad + normalise_angle(b.theta_rad - a.theta_rad) * t)};
}

} // namespace

bool is_dive(api::ActionCommand::ActionType type) {
  return type == api::ActionCommand::ActionType::GOALIE_DIVE_LEFT ||
         type == api::ActionCommand::ActionType::GOALIE_DIVE_RIGHT;
}

DiveGenerator::DiveGenerator(const DiveDef& def) : def_(def) {}

int DiveGenerator::fall_ticks() const { return duration_ticks(def_.fall_s); }

int DiveGenerator::total_ticks() const { return std::max(fall_ticks(), duration_ticks(def_.duration_s)); }

void DiveGenerator::start(const api::ActionCommand::Body& body) {
  if (running_ || !is_dive(body.actionType)) return; // latched: a dive runs to completion
  request_ = body;
  running_ = true;
  ticks_ = 0;
}

FeetPose DiveGenerator::tick(WalkCycle& walk) {
  if (!running_) return walk.feet();
  if (ticks_ == 0) {
    start_feet_ = walk.feet();
    start_body_ = walk.odometry();
    const float side = request_.actionType == api::ActionCommand::ActionType::GOALIE_DIVE_LEFT ? 1.f : -1.f;
    const float c = std::cos(start_body_.theta_rad), s = std::sin(start_body_.theta_rad);
    // Sideways in the body frame: the body's y axis is (-sin, cos) in the odometry frame.
    landed_body_ = {start_body_.x_mm - s * side * def_.reach_mm, start_body_.y_mm + c * side * def_.reach_mm,
                    start_body_.theta_rad};
    landed_feet_ = walk.feet_at_rest(landed_body_);
  }
  ++ticks_;
  if (ticks_ < fall_ticks()) {
    const float t = ease(static_cast<float>(ticks_) / static_cast<float>(fall_ticks()));
    odometry_ = lerp(start_body_, landed_body_, t);
    return {lerp(start_feet_.left, landed_feet_.left, t), lerp(start_feet_.right, landed_feet_.right, t)};
  }
  if (ticks_ == fall_ticks()) walk.stand_at(landed_body_); // down: the walk stands up from here
  odometry_ = walk.odometry();
  if (ticks_ >= total_ticks()) running_ = false;
  return walk.feet();
}

} // namespace touchline::robot
