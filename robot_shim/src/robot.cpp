#include "touchline/robot/robot.hpp"

#include <stdexcept>

namespace touchline::robot {

Robot::Robot(RobotId id, const WalkDef& walk, std::unique_ptr<api::Behaviour> behaviour)
    : id_(id), behaviour_(std::move(behaviour)), behaviour_adapter_(*behaviour_), motion_(walk) {
  if (!behaviour_) throw std::invalid_argument("Robot needs a behaviour");
}

RobotAct Robot::step(const SenseFrame& frame, const RobotSense& sense) {
  write_game_controller(frame, id_, blackboard_);
  write_perception(frame, sense, blackboard_);
  behaviour_adapter_.tick(blackboard_);

  RobotAct act;
  act.id = id_;
  act.frame = frame.frame;
  act.motion_ticks = frame.motion_ticks;
  for (int i = 0; i < frame.motion_ticks; ++i) {
    const EffectorTick tick = motion_.tick(blackboard_);
    act.left[i] = tick.left;
    act.right[i] = tick.right;
  }
  act.head_yaw_rad = motion_.head_yaw();
  act.head_pitch_rad = motion_.head_pitch();
  act.action_type = static_cast<int>(blackboard_.motion.active.actionType);
  act.leds = blackboard_.behaviour.request.leds.chest;
  const Pose2D odometry = motion_.walk().odometry();
  act.odometry = odometry;
  return act;
}

} // namespace touchline::robot
