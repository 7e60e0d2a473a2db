#include "touchline/robot/gait_feet.hpp"

#include <algorithm>

namespace touchline::robot {

namespace {
bool is_kick(api::ActionCommand::ActionType type) {
  return type == api::ActionCommand::ActionType::KICK || type == api::ActionCommand::ActionType::DRIBBLE;
}
} // namespace

WalkRequest walk_request(const api::ActionCommand::Body& body) {
  using api::ActionCommand::ActionType;
  if (body.actionType != ActionType::WALK) return {};
  const float speed = std::clamp(body.speed, 0.f, 1.f);
  return {body.forward * speed, body.left * speed, body.turn * speed};
}

GaitFeet::GaitFeet(const WalkDef& walk, const KickDef& kick, const DiveDef& dive)
    : walk_(walk), kick_(kick), dive_(dive), feet_(walk_.feet()) {}

void GaitFeet::placed() {
  walk_.stand_at(odometry());
  kick_.cancel();
  dive_.cancel();
  feet_ = walk_.feet();
  status_ = {};
}

void GaitFeet::tick(const api::ActionCommand::Body& request, float dt_s) {
  if (!kick_.running() && !dive_.running()) {
    if (is_kick(request.actionType)) kick_.start(request);
    else if (is_dive(request.actionType)) dive_.start(request);
  }
  if (dive_.running()) {
    feet_ = dive_.tick(walk_);
    status_.active = dive_.request();
    status_.kick_phase = static_cast<int>(KickPhase::kNone);
    status_.standing = false; // down, or falling: not standing until the dive is over
    return;
  }
  if (kick_.running()) {
    feet_ = kick_.tick(walk_);
    status_.active = kick_.request();
    status_.kick_phase = static_cast<int>(kick_.last_phase());
  } else {
    walk_.tick(walk_request(request), dt_s);
    feet_ = walk_.feet();
    status_.active = request;
    status_.kick_phase = static_cast<int>(KickPhase::kNone);
  }
  status_.standing = walk_.standing();
}

} // namespace touchline::robot
