#include "touchline/robot/kick_generator.hpp"

#include <algorithm>
#include <cmath>

#include "touchline/angles.hpp"
#include "touchline/frame.hpp"

namespace touchline::robot {

namespace {

/// ceil() would turn 18.000002 ticks (float rounding of an exact 18) into 19.
constexpr float kTickRoundingSlack = 1e-4f;

/// Cosine ease in and out over s in [0, 1]: exactly 0 and 1 at the ends.
float ease(float s) {
  if (s <= 0) return 0.f;
  if (s >= 1) return 1.f;
  return 0.5f * (1 - std::cos(kPi * s));
}

/// Ticks an eased move of `distance` needs so its peak rate, pi * distance / (2 * n * dt),
/// stays within `peak_rate` (0 for no move).
int eased_ticks(float distance, float peak_rate) {
  if (!(distance > 0)) return 0;
  const float ticks = kPi * distance / (2 * peak_rate * kMotionTick_s);
  return std::max(1, static_cast<int>(std::ceil(ticks - kTickRoundingSlack)));
}

/// A NaN or infinite request field (a behaviour bug) counts as `fallback`.
float finite_or(float value, float fallback) { return std::isfinite(value) ? value : fallback; }

bool is_kick(api::ActionCommand::ActionType type) {
  return type == api::ActionCommand::ActionType::KICK || type == api::ActionCommand::ActionType::DRIBBLE;
}

} // namespace

int duration_ticks(float seconds) {
  return std::max(1, static_cast<int>(std::lround(seconds / kMotionTick_s)));
}

SwingPlan plan_swing(const SwingDef& def, float power, float bend_rad) {
  SwingPlan plan;
  plan.bend_rad = std::clamp(finite_or(bend_rad, 0.f), -def.max_bend_rad, def.max_bend_rad);
  plan.backswing_mm = def.backswing_mm;
  plan.swing_length_mm = def.swing_length_mm;
  plan.strike_speed_mm_s =
      def.peak_speed_mm_s * std::clamp(finite_or(power, 0.f), def.min_power, 1.f);
  const float turn = std::abs(plan.bend_rad);
  // The turn to bend rides on the wind-up and the turn back on the return: each segment
  // lasts as long as its slower part needs.
  plan.windup_ticks = std::max(eased_ticks(def.backswing_mm, def.reposition_speed_mm_s),
                               eased_ticks(turn, def.aim_speed_rad_s));
  plan.strike_ticks =
      std::max(1, eased_ticks(def.backswing_mm + def.swing_length_mm, plan.strike_speed_mm_s));
  plan.return_ticks = std::max({1, eased_ticks(def.swing_length_mm, def.reposition_speed_mm_s),
                                eased_ticks(turn, def.aim_speed_rad_s)});
  return plan;
}

SwingOffset swing_offset(const SwingPlan& plan, int tick) {
  const int strike_start = plan.windup_ticks;
  const int return_start = strike_start + plan.strike_ticks;
  if (tick <= 0 || tick >= plan.total_ticks()) return {}; // exactly the start pose
  auto progress = [](int done, int of) { return ease(static_cast<float>(done) / static_cast<float>(of)); };
  if (tick < strike_start) {
    const float s = progress(tick, plan.windup_ticks);
    return {-plan.backswing_mm * s, plan.bend_rad * s};
  }
  if (tick < return_start) {
    const float s = progress(tick - strike_start, plan.strike_ticks);
    return {-plan.backswing_mm + (plan.backswing_mm + plan.swing_length_mm) * s, plan.bend_rad};
  }
  const float s = progress(tick - return_start, plan.return_ticks);
  return {plan.swing_length_mm * (1 - s), plan.bend_rad * (1 - s)};
}

KickGenerator::KickGenerator(const KickDef& def) : def_(def) {}

const SwingDef& KickGenerator::swing_def() const {
  return request_.actionType == api::ActionCommand::ActionType::DRIBBLE ? def_.dribble : def_.kick;
}

void KickGenerator::start(const api::ActionCommand::Body& body) {
  if (running() || !is_kick(body.actionType)) return; // latched: a kick runs to completion
  request_ = body;
  plan_ = plan_swing(swing_def(), body.power, body.bend);
  phase_ = KickPhase::kPrepare;
  ticks_in_phase_ = 0;
}

FeetPose KickGenerator::swing_feet() const {
  const SwingOffset offset = swing_offset(plan_, ticks_in_phase_);
  FeetPose feet = swing_start_;
  Pose2D& foot = request_.foot == api::ActionCommand::Foot::LEFT ? feet.left : feet.right;
  const float direction = swing_heading_rad_ + plan_.bend_rad;
  foot.x_mm += offset.along_mm * std::cos(direction);
  foot.y_mm += offset.along_mm * std::sin(direction);
  foot.theta_rad = normalise_angle(foot.theta_rad + offset.turn_rad);
  return feet;
}

FeetPose KickGenerator::tick(WalkCycle& walk) {
  last_phase_ = phase_;
  switch (phase_) {
    case KickPhase::kNone:
      break;
    case KickPhase::kPrepare:
      if (!walk.standing()) {
        walk.tick({}, kMotionTick_s); // decelerate and land the feet square; the wait starts after
        break;
      }
      if (++ticks_in_phase_ >= duration_ticks(swing_def().prepare_s)) {
        phase_ = KickPhase::kSwing;
        ticks_in_phase_ = 0;
        swing_start_ = walk.feet();
        // Square feet: the odometry heading is the body x the swing is relative to.
        swing_heading_rad_ = walk.odometry().theta_rad;
      }
      break;
    case KickPhase::kSwing:
      if (++ticks_in_phase_ < plan_.total_ticks()) return swing_feet();
      phase_ = KickPhase::kRecover; // the foot is back: exactly the walk's feet again
      ticks_in_phase_ = 0;
      break;
    case KickPhase::kRecover:
      if (++ticks_in_phase_ >= duration_ticks(swing_def().recover_s)) phase_ = KickPhase::kNone;
      break;
  }
  return walk.feet();
}

} // namespace touchline::robot
