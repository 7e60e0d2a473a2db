#pragma once
// Walking skills that need nothing but the robot API. (Walking to a pose: skills::GoToPose,
// which the registry's `goto` runs without a head.)
#include "touchline/robot_api/behaviour.hpp"

namespace touchline::behaviour {

/// Walks at a constant velocity (mm/s, rad/s) for ever: for calibrating the walk.
class ConstantWalk : public api::Behaviour {
 public:
  ConstantWalk(float forward, float left, float turn) : forward_(forward), left_(left), turn_(turn) {}
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;

 private:
  float forward_, left_, turn_;
};

} // namespace touchline::behaviour
