#include "touchline/behaviour/skills/head_scan.hpp"

#include <cmath>

#include "touchline/behaviour/skills/actioncommand.hpp"

namespace touchline::behaviour::skills {

using namespace api;

void HeadScan::reset() {
  started_ = false;
  step_ = 0;
  direction_ = 1;
}

ActionCommand::All HeadScan::tick(const Blackboard& blackboard) {
  if (!started_) {
    const float yaw = clamp(blackboard.motion.headYaw, -MAX_HEAD_YAW, MAX_HEAD_YAW);
    // Nearest step: the head often rests on one exactly (the limits included), where
    // truncation could fall either side in float32 and float64.
    step_ = static_cast<int>(std::floor(yaw / SCAN_YAW_STEP + 0.5f));
    direction_ = blackboard.localisation.ballPosRR.heading >= 0.f ? 1 : -1;
    started_ = true;
  }
  step_ += direction_;
  if (step_ >= SCAN_STEPS) {
    step_ = SCAN_STEPS;
    direction_ = -1;
  } else if (step_ <= -SCAN_STEPS) {
    step_ = -SCAN_STEPS;
    direction_ = 1;
  }
  return actioncommand::compose(actioncommand::head(static_cast<float>(step_) * SCAN_YAW_STEP, SCAN_PITCH));
}

} // namespace touchline::behaviour::skills
