#include "touchline/robot/motion_adapter.hpp"

#include <algorithm>

namespace touchline::robot {

namespace {
constexpr float kTickS = kMotionTickUs * 1e-6f;

float approach(float current, float target, float max_step) {
  return current + std::clamp(target - current, -max_step, max_step);
}
} // namespace

MotionAdapter::MotionAdapter(const WalkDef& walk, const HeadDef& head) : walk_(walk), head_(head) {}

WalkRequest MotionAdapter::walk_request(const api::ActionCommand::Body& body) const {
  using api::ActionCommand::ActionType;
  if (body.actionType != ActionType::WALK) return {};
  const float speed = std::clamp(body.speed, 0.f, 1.f);
  return {body.forward * speed, body.left * speed, body.turn * speed};
}

void MotionAdapter::tick_head(const api::ActionCommand::Head& request) {
  float yaw = request.isRelative ? yaw_ + request.yaw : request.yaw;
  float pitch = request.isRelative ? pitch_ + request.pitch : request.pitch;
  yaw = std::clamp(yaw, -head_.max_yaw_rad, head_.max_yaw_rad);
  pitch = std::clamp(pitch, head_.min_pitch_rad, head_.max_pitch_rad);
  const float step = head_.max_speed_rad_s * kTickS;
  yaw_ = approach(yaw_, yaw, step * std::clamp(request.yawSpeed, 0.01f, 1.f));
  pitch_ = approach(pitch_, pitch, step * std::clamp(request.pitchSpeed, 0.01f, 1.f));
}

EffectorTick MotionAdapter::tick(api::Blackboard& blackboard) {
  const api::ActionCommand::All& request = blackboard.behaviour.request;
  tick_head(request.head);

  const FeetPose before = walk_.feet();
  walk_.tick(walk_request(request.body), kTickS);
  EffectorTick out;
  feet_motion(before, walk_.feet(), out.left, out.right);

  auto& motion = blackboard.motion;
  const Pose2D odometry = walk_.odometry();
  motion.odometry = {odometry.x_mm, odometry.y_mm, odometry.theta_rad};
  motion.active = request.body;
  motion.headYaw = yaw_;
  motion.headPitch = pitch_;
  motion.standing = walk_.standing();
  ++motion.ticks;
  return out;
}

} // namespace touchline::robot
