#include "touchline/behaviour/skills/unstick.hpp"

#include <algorithm>
#include <cmath>

#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/go_to_pose.hpp"
#include "touchline/behaviour/skills/robot_limits.hpp"
#include "touchline/behaviour/skills/search.hpp"

namespace touchline::behaviour::skills {

using namespace api;

void Unstick::reset() {
  odometry_.clear();
  positions_.clear();
  turned_.clear();
  recovering_ = 0;
}

ActionCommand::Body Unstick::tick(const Blackboard& blackboard, const ActionCommand::Body& body,
                                  std::optional<FieldPoint> target) {
  const AbsCoord odometry = blackboard.motion.odometry;
  if (!odometry_.empty()) turned_.push_back(std::fabs(normaliseTheta(odometry.theta - odometry_.back().theta)));
  odometry_.push_back(odometry);
  positions_.push_back({blackboard.localisation.robotPos.x, blackboard.localisation.robotPos.y});
  if (odometry_.size() > static_cast<size_t>(UNSTICK_WINDOW_FRAMES)) {
    odometry_.pop_front();
    positions_.pop_front();
    turned_.pop_front();
  }
  if (recovering_ == 0 && stuck()) recovering_ = UNSTICK_RECOVER_FRAMES;
  if (recovering_ == 0) return body;
  --recovering_;
  const FieldPoint walkTo = walkTarget(blackboard, target);
  const RRCoord toTarget = toRobotRelative(blackboard.localisation.robotPos, walkTo.x, walkTo.y);
  const WalkVelocity v = clampWalk(WALK_GAIN * toTarget.x(), WALK_GAIN * toTarget.y());
  return avoid_.tick(blackboard, actioncommand::walk(v.forward, v.left, 0.f), toTarget.distance);
}

bool Unstick::stuck() const {
  const AbsCoord& last = odometry_.back();
  float turned = 0.f;
  for (size_t start = turned_.size(); start-- > 0;) { // back from the newest turn
    turned += turned_[start];
    if (turned <= UNSTICK_TURN_RAD) continue; // moves count only past the limit
    const AbsCoord& first = odometry_[start];
    // The smaller of the two: a walk against a robot steps on in odometry only.
    const float moved = std::min(std::hypot(last.x - first.x, last.y - first.y),
                                 std::hypot(positions_.back().x - positions_[start].x,
                                            positions_.back().y - positions_[start].y));
    if (moved < UNSTICK_MOVE_MM) return true;
  }
  return false;
}

FieldPoint Unstick::walkTarget(const Blackboard& blackboard, std::optional<FieldPoint> target) {
  if (target) return *target;
  if (ballRecentlySeen(blackboard)) return {blackboard.localisation.ballPos.x, blackboard.localisation.ballPos.y};
  const auto ball = teamBall(blackboard.gameController.playerNumber, blackboard.receiver.messages, blackboard.utime);
  return ball ? *ball : FieldPoint{0.f, 0.f};
}

} // namespace touchline::behaviour::skills
