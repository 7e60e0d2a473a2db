#pragma once
// HeadScan: sweep the head yaw across the joint range at a steady pace, mid pitch; the port
// of behaviour_py/skills/head_scan.py. Driven by its own frame count (one step per tick),
// never by wall time: the yaw is SCAN_YAW_STEP times an integer step that walks between
// -SCAN_STEPS and SCAN_STEPS.
#include "touchline/behaviour/skills/robot_limits.hpp"
#include "touchline/robot_api/behaviour.hpp"

namespace touchline::behaviour::skills {

inline constexpr int SCAN_STEPS = 40;                                     ///< frames from centre to either side
inline constexpr float SCAN_YAW_STEP = MAX_HEAD_YAW / SCAN_STEPS;         ///< rad per frame (1.56 rad/s at 30 Hz)
inline constexpr float SCAN_PITCH = (MIN_HEAD_PITCH + MAX_HEAD_PITCH) / 2; ///< rad: mid pitch

class HeadScan : public api::Behaviour {
 public:
  HeadScan() { reset(); }
  /// Start afresh at the next tick: from the head's yaw, towards the ball's side.
  void reset();
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;

  int step() const { return step_; }
  int direction() const { return direction_; }

 private:
  bool started_ = false;
  int step_ = 0;
  int direction_ = 1;
};

} // namespace touchline::behaviour::skills
