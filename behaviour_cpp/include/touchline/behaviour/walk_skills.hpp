#pragma once
// Walking skills that need nothing but the robot API.
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

/// Parameters of GoToPose.
struct GoToPoseDef {
  float max_forward_mm_s = 300.f;   ///< forward request when far
  float max_left_mm_s = 200.f;      ///< sideways request limit when close
  float max_turn_rad_s = 1.5f;      ///< turn request limit
  float far_mm = 400.f;             ///< beyond this: face the target and walk forward
  float arrive_mm = 40.f;           ///< within this and arrive_rad: arrived, stand
  float arrive_rad = 0.1f;
  float leave_mm = 150.f;           ///< arrived until pushed this far away (hysteresis)
  float gain_per_s = 2.0f;          ///< proportional gain: request = gain * error
};

/// Walks to an absolute pose (field frame): turn towards it and walk when far, walk
/// omnidirectionally onto it when near, then stand until moved away.
class GoToPose : public api::Behaviour {
 public:
  GoToPose(const api::AbsCoord& target, const GoToPoseDef& def = {}) : target_(target), def_(def) {}
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;
  bool arrived() const { return arrived_; }

 private:
  api::AbsCoord target_;
  GoToPoseDef def_;
  bool arrived_ = false;
};

} // namespace touchline::behaviour
