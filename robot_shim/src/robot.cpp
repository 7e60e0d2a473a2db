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

namespace {
/// Checked before the adapters bind to it.
std::unique_ptr<api::Behaviour> required(std::unique_ptr<api::Behaviour> behaviour) {
  if (!behaviour) throw std::invalid_argument("Robot needs a behaviour");
  return behaviour;
}

MotionDef motion_def(const RobotDef& def) {
  MotionDef motion;
  motion.head = def.head;
  motion.joint_feet.legs = def.engine.nao_joints.legs;
  return motion;
}
} // namespace

Robot::Robot(RobotDef def, std::unique_ptr<api::Behaviour> behaviour)
    : def_(std::move(def)), behaviour_(required(std::move(behaviour))),
      behaviour_adapter_(*behaviour_, def_.timing.cpu_clock), motion_(make_walk_engine(def_.engine, def_.walk, def_.kick), motion_def(def_)),
      localisation_(def_.localisation.filters, def_.localisation.perfect) {
  blackboard_.behaviour.skill = describe(def_.behaviour);
}

bool Robot::behaviour_due(int64_t frame) const {
  // A frame index going backwards is a new run of frames: nothing is owed from the old one.
  return !def_.timing.charge_cpu || frame >= next_behaviour_frame_ || frame < last_behaviour_frame_;
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
  act.id = def_.id;
  act.frame = frame.frame;
  act.motion_ticks = frame.motion_ticks;
  if (sense.placed) motion_.placed();
  for (int i = 0; i < frame.motion_ticks; ++i) act.ticks[static_cast<size_t>(i)] = motion_.tick(blackboard_);
  act.head_yaw_rad = motion_.head_yaw();
  act.head_pitch_rad = motion_.head_pitch();
  act.leds = blackboard_.behaviour.request.leds.chest;
  act.behaviour_cpu_us = stats_.ticked_last_step ? stats_.last_cpu_us : 0;
  const api::AbsCoord& believed = blackboard_.localisation.robotPos;
  act.localised = to_world_frame({believed.x, believed.y, believed.theta}, def_.id.team);
  const auto& cov = blackboard_.localisation.robotPosCovariance; // row-major (x, y, theta)
  act.localised_cov_mm2 = {cov[0], cov[1], cov[4]};
  const api::AbsCoord& ball = blackboard_.localisation.ballPos;
  const Pose2D ball_world = to_world_frame({ball.x, ball.y, 0}, def_.id.team);
  act.ball_x_mm = ball_world.x_mm;
  act.ball_y_mm = ball_world.y_mm;
  act.ball_lost_frames = blackboard_.localisation.ballLostCount;
  const auto& message = blackboard_.behaviour.request.teamMessage;
  if (stats_.ticked_last_step && message.size() <= kMaxTeamMessageBytes) act.team_message = message;
  return act;
}

} // namespace touchline::robot
