#pragma once
// One robot, as the robot's own process runs it: per camera frame the adapters write the
// Blackboard, the behaviour ticks (30 Hz perception), then the frame's 100 Hz motion
// ticks run and their foot motions become the answer to the world. No transport here:
// robot_shim carries frames over LCM, the in-process runner calls step() directly.
#include <memory>

#include "touchline/frame.hpp"
#include "touchline/robot/adapters.hpp"
#include "touchline/robot/motion_adapter.hpp"
#include "touchline/robot_api/behaviour.hpp"

namespace touchline::robot {

class Robot {
 public:
  Robot(RobotId id, const WalkDef& walk, std::unique_ptr<api::Behaviour> behaviour);

  /// Runs one camera frame. `sense` is this robot's entry of `frame`.
  RobotAct step(const SenseFrame& frame, const RobotSense& sense);

  RobotId id() const { return id_; }
  const api::Blackboard& blackboard() const { return blackboard_; }
  /// CPU time of the last behaviour tick, microseconds (thread CPU clock).
  int64_t behaviour_cpu_us() const { return behaviour_adapter_.last_cpu_us(); }

 private:
  RobotId id_;
  std::unique_ptr<api::Behaviour> behaviour_;
  api::Blackboard blackboard_;
  BehaviourAdapter behaviour_adapter_;
  MotionAdapter motion_;
};

} // namespace touchline::robot
