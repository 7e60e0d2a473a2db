#include "touchline/python/runswift/request_converter.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "touchline/python/python_profile.hpp"

namespace touchline::python::runswift {

namespace AC = api::ActionCommand;

api::ActionCommand::Body convert_walk(float forward, float left, float turn, float speed,
                                      const RunswiftWalkLimits& limits) {
  if (forward == 0 && left == 0 && turn == 0) return AC::stand();
  const float s = std::clamp(speed, 0.f, 1.f);
  const float scale = limits.min_speed_fraction + (1 - limits.min_speed_fraction) * s;
  const float max_f = limits.max_forward_mm_s * scale, max_l = limits.max_left_mm_s * scale,
              max_t = limits.max_turn_rad_s * scale;
  // Inside the ellipsoid with these semi-axes as it is; outside, scaled onto its surface.
  const float norm = std::sqrt(std::pow(forward / max_f, 2.f) + std::pow(left / max_l, 2.f) + std::pow(turn / max_t, 2.f));
  const float k = norm > 1 ? 1 / norm : 1;
  AC::Body body = AC::walk(forward * k, left * k, turn * k);
  body.speed = 1; // their speed is in the limits above; Touchline's would scale the velocity again
  return body;
}

api::ActionCommand::Body convert_body(const BodyCommand& b, const RunswiftWalkLimits& limits) {
  switch (b.actionType) {
    case WALK:
      return convert_walk(static_cast<float>(b.forward), static_cast<float>(b.left), b.turn, b.speed, limits);
    case KICK:
    case TURN_DRIBBLE: {
      AC::Body body;
      body.actionType = b.actionType == KICK ? AC::ActionType::KICK : AC::ActionType::DRIBBLE;
      body.power = std::clamp(b.power, 0.f, 1.f);
      body.bend = b.turn; // their kick's direction, rad, + left: our swing direction
      body.foot = b.foot == FOOT_RIGHT ? AC::Foot::RIGHT : AC::Foot::LEFT;
      return body;
    }
    case GOALIE_DIVE_LEFT:
    case GOALIE_DIVE_RIGHT: {
      // Our dive (robot DiveDef: their 2.4 s, a body length sideways); it latches in motion.
      AC::Body body;
      body.actionType = b.actionType == GOALIE_DIVE_LEFT ? AC::ActionType::GOALIE_DIVE_LEFT : AC::ActionType::GOALIE_DIVE_RIGHT;
      return body;
    }
    default:
      return AC::stand();
  }
}

api::ActionCommand::Head convert_head(const HeadCommand& h) {
  AC::Head head;
  head.yaw = h.yaw;
  head.pitch = h.pitch;
  head.isRelative = h.isRelative;
  head.yawSpeed = h.yawSpeed;
  head.pitchSpeed = h.pitchSpeed;
  return head;
}

int32_t led_colour(const Rgb& rgb) { return (rgb.red ? 0xff0000 : 0) | (rgb.green ? 0x00ff00 : 0) | (rgb.blue ? 0x0000ff : 0); }

bool is_simulated(int type) {
  return type == NONE || type == STAND || type == WALK || type == KICK || type == TURN_DRIBBLE ||
         type == GOALIE_DIVE_LEFT || type == GOALIE_DIVE_RIGHT;
}

double action_duration_s(int type) {
  switch (type) {
    case GETUP_FRONT: return 7.0;
    case GETUP_BACK: return 5.05;
    case TIP_OVER: return 0.8;
    case INITIAL: return 2.0;
    case GOALIE_SIT: return 0.7;
    case GOALIE_FAST_SIT: return 0.35;
    case GOALIE_CENTRE: return 2.1;
    case GOALIE_UNCENTRE: return 4.6;
    case GOALIE_INITIAL: return 1.2;
    case GOALIE_STAND: return 0.2;
    case DEFENDER_CENTRE: return 1.9;
    case STAND_STRAIGHT: return 1.0;
    case TEST_ARMS: return 25.5;
    case RAISE_ARM: return 2.5;
    case UKEMI_FRONT: return 1.6;
    case UKEMI_BACK: return 0.9;
    case SIT: return 3.05;
    case REF_PICKUP: return 8.7;
    case SIGNAL_FULL_TIME: return 252.0;
    default: return 1.0; // the other signals take 1 s; LIMP, LINE_UP, MOTION_CALIBRATE have no key frames
  }
}

namespace {

void require_finite(float value, const char* field) {
  if (std::isfinite(value)) return;
  std::ostringstream out;
  out << "BehaviourRequest.actions." << field << " is " << value << ", not a finite number";
  throw RequestError(out.str());
}

} // namespace

void validate(const BehaviourRequest& r) {
  const BodyCommand& b = r.actions.body;
  if (b.actionType < 0 || b.actionType >= NUM_ACTION_TYPES)
    throw RequestError("BehaviourRequest.actions.body.actionType is " + std::to_string(b.actionType) +
                       ", not a robot.ActionType");
  if (b.foot != FOOT_LEFT && b.foot != FOOT_RIGHT)
    throw RequestError("BehaviourRequest.actions.body.foot is " + std::to_string(b.foot) + ", not a robot.Foot");
  require_finite(b.turn, "body.turn");
  require_finite(b.power, "body.power");
  require_finite(b.speed, "body.speed");
  require_finite(b.bend, "body.bend");
  const HeadCommand& h = r.actions.head;
  require_finite(h.yaw, "head.yaw");
  require_finite(h.pitch, "head.pitch");
  require_finite(h.yawSpeed, "head.yawSpeed");
  require_finite(h.pitchSpeed, "head.pitchSpeed");
}

RequestConverter::RequestConverter(std::function<void(const std::string&)> warn, RunswiftWalkLimits limits)
    : warn_(std::move(warn)), limits_(limits) {}

api::ActionCommand::All RequestConverter::convert(const BehaviourRequest& request, int64_t utime_us) {
  validate(request);
  AC::All all;
  all.head = convert_head(request.actions.head);
  all.leds.chest = led_colour(request.actions.leds.chestButton);
  // Standing through a special action (time going backwards is a new run: it is over).
  if (busy_until_us_ >= 0 && utime_us >= busy_since_us_ && utime_us < busy_until_us_) {
    all.body = AC::stand();
    return all;
  }
  busy_until_us_ = -1;
  const int type = request.actions.body.actionType;
  if (is_simulated(type)) {
    all.body = convert_body(request.actions.body, limits_);
    return all;
  }
  const double duration_s = action_duration_s(type);
  busy_type_ = type;
  busy_since_us_ = utime_us;
  busy_until_us_ = utime_us + static_cast<int64_t>(std::llround(duration_s * 1e6));
  all.body = AC::stand();
  if (warned_.insert(type).second && warn_) {
    std::ostringstream out;
    out << "action " << action_type_name(type) << " is not simulated: the robot stands for " << duration_s
        << " s (its duration on the robot)";
    warn_(out.str());
  }
  return all;
}

} // namespace touchline::python::runswift
