#include "touchline/behaviour/skills/learned_go_to_pose.hpp"

#include <cmath>

#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/robot_api/data.hpp"

namespace touchline::behaviour::skills {

using namespace api;

RelativeTarget relativeTarget(const AbsCoord& pos, double x, double y, double theta) {
  const double dx = x - double{pos.x};
  const double dy = y - double{pos.y};
  const double c = std::cos(double{pos.theta}); // double, as Python's math.cos: not cosf
  const double s = std::sin(double{pos.theta});
  return {c * dx + s * dy, c * dy - s * dx, theta - double{pos.theta}};
}

LearnedGoToPose::LearnedGoToPose(double x, double y, double theta, const std::string& policy)
    : policy_(cachedPolicy(data_path(policy))) {
  setTarget(x, y, theta);
}

void LearnedGoToPose::setTarget(double x, double y, double theta) {
  x_ = x;
  y_ = y;
  theta_ = theta;
}

ActionCommand::All LearnedGoToPose::tick(const Blackboard& blackboard) {
  const RelativeTarget target = relativeTarget(blackboard.localisation.robotPos, x_, y_, theta_);
  if (policy_->arrived(target.x, target.y, target.theta)) return actioncommand::compose({}, actioncommand::stand());
  const WalkAction& action = policy_->actions()[policy_->greedyAction(target.x, target.y, target.theta)];
  // Body holds floats, as robot.Body does: Python's assignment rounds the same way.
  return actioncommand::compose({}, actioncommand::walk(static_cast<float>(action.forward),
                                                        static_cast<float>(action.left),
                                                        static_cast<float>(action.turn)));
}

} // namespace touchline::behaviour::skills
