#include "touchline/behaviour/walk_skills.hpp"

#include <algorithm>
#include <cmath>

namespace touchline::behaviour {

using namespace api;

ActionCommand::All ConstantWalk::tick(const Blackboard&) {
  ActionCommand::All all;
  all.body = ActionCommand::walk(forward_, left_, turn_);
  return all;
}

ActionCommand::All GoToPose::tick(const Blackboard& blackboard) {
  const AbsCoord& robot = blackboard.localisation.robotPos;
  const RRCoord to_target = toRobotRelative(robot, target_.x, target_.y);
  const float heading_error = normaliseTheta(target_.theta - robot.theta);

  if (arrived_) {
    arrived_ = to_target.distance < def_.leave_mm;
  } else {
    arrived_ = to_target.distance < def_.arrive_mm && std::fabs(heading_error) < def_.arrive_rad;
  }
  ActionCommand::All all;
  if (arrived_) return all; // stand

  const float g = def_.gain_per_s;
  const float turn_limit = def_.max_turn_rad_s;
  if (to_target.distance > def_.far_mm) {
    // Face the target first: the walk is fastest forward (thesis 4.3's lesson).
    const float facing = std::cos(to_target.heading);
    const float forward = facing > 0.7f ? def_.max_forward_mm_s * facing : 0.f;
    const float turn = std::clamp(g * to_target.heading, -turn_limit, turn_limit);
    all.body = ActionCommand::walk(forward, 0, turn);
  } else {
    const float forward = std::clamp(g * to_target.x(), -def_.max_forward_mm_s, def_.max_forward_mm_s);
    const float left = std::clamp(g * to_target.y(), -def_.max_left_mm_s, def_.max_left_mm_s);
    const float turn = std::clamp(g * heading_error, -turn_limit, turn_limit);
    all.body = ActionCommand::walk(forward, left, turn);
  }
  return all;
}

} // namespace touchline::behaviour
