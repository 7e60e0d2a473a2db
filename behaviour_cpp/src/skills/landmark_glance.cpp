#include "touchline/behaviour/skills/landmark_glance.hpp"

#include <cmath>

#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/robot_limits.hpp"
#include "touchline/behaviour/skills/track_ball.hpp"

namespace touchline::behaviour::skills {

using namespace api;

std::vector<FieldPoint> landmarks() {
  std::vector<FieldPoint> points;
  for (const float x : {-FIELD_HALF_LENGTH, FIELD_HALF_LENGTH}) {
    points.push_back({x, -GOAL_POST_HALF_SPAN});
    points.push_back({x, GOAL_POST_HALF_SPAN});
    points.push_back({x, -FIELD_HALF_WIDTH});
    points.push_back({x, FIELD_HALF_WIDTH});
  }
  points.push_back({0.f, -FIELD_HALF_WIDTH});
  points.push_back({0.f, FIELD_HALF_WIDTH});
  points.push_back({-PENALTY_MARK_X, 0.f});
  points.push_back({PENALTY_MARK_X, 0.f});
  return points;
}

std::optional<RRCoord> glanceTarget(const AbsCoord& robotPos, float ballHeading) {
  std::optional<RRCoord> best;
  for (const FieldPoint& p : landmarks()) {
    const RRCoord rr = toRobotRelative(robotPos, p.x, p.y);
    if (rr.distance < GLANCE_MIN_DIST || rr.distance > GLANCE_MAX_DIST || std::fabs(rr.heading) > MAX_HEAD_YAW)
      continue;
    // In double, as the Python original subtracts the float32 values.
    if (!best || std::fabs(static_cast<double>(rr.heading) - ballHeading) <
                     std::fabs(static_cast<double>(best->heading) - ballHeading))
      best = rr;
  }
  return best;
}

namespace {
/// Whether the pose's position sigma (x and y together) is past sigmaMm.
bool positionSigmaPast(const LocalisationBlackboard& localisation, double sigmaMm) {
  const auto& c = localisation.robotPosCovariance;
  return static_cast<double>(c[0]) + c[4] > sigmaMm * sigmaMm;
}
} // namespace

bool poseUnsure(const LocalisationBlackboard& localisation) {
  const double sigmaRad = GLANCE_SIGMA_RAD;
  return positionSigmaPast(localisation, GLANCE_SIGMA_MM) ||
         static_cast<double>(localisation.robotPosCovariance[8]) > sigmaRad * sigmaRad;
}

bool poseLost(const LocalisationBlackboard& localisation) { return positionSigmaPast(localisation, GLANCE_LOST_SIGMA_MM); }

ActionCommand::All LandmarkGlance::tick(const Blackboard& blackboard) {
  const LocalisationBlackboard& loc = blackboard.localisation;
  const RRCoord& ball = loc.ballPosRR;
  const bool hot =
      blackboard.vision.ballSeen && blackboard.vision.ball.distance < GLANCE_HOT_BALL_DIST && !poseLost(loc);
  if (glancing_) {
    const std::optional<RRCoord> target = glanceTarget(loc.robotPos, ball.heading);
    if (target && !hot && glancing_ < GLANCE_MAX_FRAMES && dwell_ < GLANCE_DWELL_FRAMES) {
      ++glancing_;
      return aim(blackboard, *target);
    }
    glancing_ = 0;
    sinceGlance_ = 0;
  }
  ++sinceGlance_;
  const int every = poseUnsure(loc) ? GLANCE_UNSURE_EVERY_FRAMES : GLANCE_EVERY_FRAMES;
  if (ballRecentlySeen(blackboard) && !hot && sinceGlance_ >= every) {
    if (const std::optional<RRCoord> target = glanceTarget(loc.robotPos, ball.heading)) {
      glancing_ = 1;
      dwell_ = 0;
      return aim(blackboard, *target);
    }
  }
  return lookForBall_.tick(blackboard);
}

ActionCommand::All LandmarkGlance::aim(const Blackboard& blackboard, const RRCoord& target) {
  const double off = std::fabs(static_cast<double>(blackboard.motion.headYaw) - target.heading);
  if (off < static_cast<double>(GLANCE_ON_TARGET_RAD)) ++dwell_;
  return actioncommand::compose(lookAt(target)); // glanceTarget is within the head's yaw
}

} // namespace touchline::behaviour::skills
