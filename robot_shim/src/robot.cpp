#include "touchline/robot/robot.hpp"

#include <algorithm>
#include <stdexcept>

namespace touchline::robot {

int64_t behaviour_frames_used(int64_t cpu_us) {
  // A camera frame lasts kTicksPerCycle * kMotionTickUs / kFramesPerCycle = 33 333.3 us;
  // integer arithmetic keeps the boundary exact.
  constexpr int64_t cycle_us = kTicksPerCycle * kMotionTickUs;
  const int64_t frames = (std::max<int64_t>(cpu_us, 0) * kFramesPerCycle + cycle_us - 1) / cycle_us;
  return std::max<int64_t>(frames, 1);
}

Robot::Robot(RobotId id, const WalkDef& walk, std::unique_ptr<api::Behaviour> behaviour, BehaviourTimingDef timing,
             const KickDef& kick, const LocalisationModeDef& localisation)
    : id_(id), behaviour_(std::move(behaviour)), charge_cpu_(timing.charge_cpu),
      behaviour_adapter_(*behaviour_, std::move(timing.cpu_clock)), motion_(walk, HeadDef{}, kick),
      localisation_(localisation.filters, localisation.perfect) {
  if (!behaviour_) throw std::invalid_argument("Robot needs a behaviour");
}

bool Robot::behaviour_due(int64_t frame) const {
  // A frame index going backwards is a new run of frames: nothing is owed from the old one.
  return !charge_cpu_ || frame >= next_behaviour_frame_ || frame < last_behaviour_frame_;
}

void Robot::run_behaviour(int64_t frame) {
  behaviour_adapter_.tick(blackboard_);
  const int64_t cpu = behaviour_adapter_.last_cpu_us();
  ++stats_.ticks;
  stats_.last_cpu_us = cpu;
  stats_.max_cpu_us = std::max(stats_.max_cpu_us, cpu);
  stats_.total_cpu_us += cpu;
  last_behaviour_frame_ = frame;
  next_behaviour_frame_ = frame + behaviour_frames_used(cpu);
}

RobotAct Robot::step(const SenseFrame& frame, const RobotSense& sense) {
  write_game_controller(frame, sense, blackboard_);
  write_vision(frame, sense, blackboard_);
  write_fall(sense, blackboard_);
  write_receiver(sense, blackboard_);
  localisation_.tick(frame, sense, blackboard_);
  stats_.ticked_last_step = behaviour_due(frame.frame);
  if (stats_.ticked_last_step) {
    run_behaviour(frame.frame);
    if (keep_behaviour_view_) behaviour_view_ = blackboard_;
  } else {
    ++stats_.skipped_frames; // still busy with the last tick: its request stays in force
  }

  RobotAct act;
  act.id = id_;
  act.frame = frame.frame;
  act.motion_ticks = frame.motion_ticks;
  for (int i = 0; i < frame.motion_ticks; ++i) act.ticks[static_cast<size_t>(i)] = motion_.tick(blackboard_);
  act.head_yaw_rad = motion_.head_yaw();
  act.head_pitch_rad = motion_.head_pitch();
  act.action_type = static_cast<int>(blackboard_.motion.active.actionType);
  act.leds = blackboard_.behaviour.request.leds.chest;
  const Pose2D odometry = motion_.walk().odometry();
  act.odometry = odometry;
  act.behaviour_cpu_us = stats_.ticked_last_step ? stats_.last_cpu_us : 0;
  const api::AbsCoord& believed = blackboard_.localisation.robotPos;
  act.localised = to_world_frame({believed.x, believed.y, believed.theta}, id_.team);
  const auto& message = blackboard_.behaviour.request.teamMessage;
  if (stats_.ticked_last_step && message.size() <= kMaxTeamMessageBytes) act.team_message = message;
  return act;
}

} // namespace touchline::robot
