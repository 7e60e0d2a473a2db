#include "touchline/robot/motion_adapter.hpp"

#include <algorithm>

#include "approach.hpp"

namespace touchline::robot {

namespace {
constexpr float kTickS = kMotionTickUs * 1e-6f;

bool is_kick(api::ActionCommand::ActionType type) {
  return type == api::ActionCommand::ActionType::KICK || type == api::ActionCommand::ActionType::DRIBBLE;
}
} // namespace

MotionAdapter::MotionAdapter(const WalkDef& walk, const HeadDef& head, const KickDef& kick)
    : walk_(walk), kick_(kick), feet_(walk_.feet()), head_(head) {}

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

TickMotion MotionAdapter::tick(api::Blackboard& blackboard) {
  const api::ActionCommand::All& request = blackboard.behaviour.request;
  tick_head(request.head);

  auto& motion = blackboard.motion;
  if (!kick_.running() && is_kick(request.body.actionType)) kick_.start(request.body);
  FeetPose after;
  if (kick_.running()) {
    after = kick_.tick(walk_);
    motion.active = kick_.request();
    motion.kickPhase = static_cast<int>(kick_.last_phase());
  } else {
    walk_.tick(walk_request(request.body), kTickS);
    after = walk_.feet();
    motion.active = request.body;
    motion.kickPhase = static_cast<int>(KickPhase::kNone);
  }
  TickMotion out;
  feet_motion(feet_, after, out.left, out.right);
  feet_ = after;

  const Pose2D odometry = walk_.odometry();
  motion.odometry = {odometry.x_mm, odometry.y_mm, odometry.theta_rad};
  motion.headYaw = yaw_;
  motion.headPitch = pitch_;
  motion.standing = walk_.standing();
  ++motion.ticks;
  return out;
}

} // namespace touchline::robot
