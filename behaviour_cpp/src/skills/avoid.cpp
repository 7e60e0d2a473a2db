#include "touchline/behaviour/skills/avoid.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/behaviour/skills/field.hpp"
#include "touchline/behaviour/skills/team_comm.hpp"

namespace touchline::behaviour::skills {

using namespace api;

namespace {

/// value, or 0 within 1e-3 of it: cos(pi / 2) is 6e-17 in a double and -4e-8 in a float, and
/// a touch beside must be neither ahead nor behind in both ports.
float exactZero(float value) { return std::fabs(value) < 1e-3f ? 0.f : value; }

/// A velocity along the field's axes, mm/s.
struct FieldVelocity {
  float vx = 0;
  float vy = 0;
};

/// The walk (forward, left) of a robot at pos along the field's axes.
FieldVelocity toFieldAxes(const AbsCoord& pos, float forward, float left) {
  const float cosT = std::cos(pos.theta);
  const float sinT = std::sin(pos.theta);
  return {forward * cosT - left * sinT, forward * sinT + left * cosT};
}

/// v along the field's axes as the walk (forward, left) of a robot at pos.
WalkVelocity toRobotAxes(const AbsCoord& pos, const FieldVelocity& v) {
  const float cosT = std::cos(pos.theta);
  const float sinT = std::sin(pos.theta);
  return {v.vx * cosT + v.vy * sinT, -v.vx * sinT + v.vy * cosT};
}

} // namespace

std::vector<Sighting> remember(const std::vector<Sighting>& seen, const Blackboard& blackboard) {
  const int64_t utime = blackboard.utime;
  const AbsCoord pos = blackboard.localisation.robotPos;
  const float cosT = std::cos(pos.theta);
  const float sinT = std::sin(pos.theta);
  std::vector<Sighting> kept;
  for (const Sighting& entry : seen)
    if (utime - entry.utime <= SEEN_MEMORY_US) kept.push_back(entry);
  for (const SeenObject& robotSeen : blackboard.vision.robots) {
    const float forward = robotSeen.rr.x();
    const float left = robotSeen.rr.y();
    const float x = pos.x + forward * cosT - left * sinT;
    const float y = pos.y + forward * sinT + left * cosT;
    kept.erase(std::remove_if(kept.begin(), kept.end(),
                              [&](const Sighting& e) { return std::hypot(e.x - x, e.y - y) < SEEN_MERGE_DIST; }),
               kept.end());
    kept.push_back({utime, x, y});
  }
  return kept;
}

std::vector<Obstacle> obstacles(const Blackboard& blackboard, const std::vector<Sighting>& seen) {
  std::vector<Obstacle> found;
  const MotionBlackboard& motion = blackboard.motion;
  if (motion.sonarLeft < 1.f) found.push_back({motion.sonarLeft * motion.sonarRange_mm, SONAR_SIDE_Y});
  if (motion.sonarRight < 1.f) found.push_back({motion.sonarRight * motion.sonarRange_mm, -SONAR_SIDE_Y});
  const AbsCoord pos = blackboard.localisation.robotPos;
  for (const Sighting& entry : seen) {
    const RRCoord rr = toRobotRelative(pos, entry.x, entry.y);
    found.push_back({rr.x(), rr.y()});
  }
  const int me = blackboard.gameController.playerNumber;
  for (const TeamMessage& message : blackboard.receiver.messages) {
    if (message.playerNumber == me || blackboard.utime - message.utime > MESSAGE_STALE_US) continue;
    const std::optional<TeamInfo> info = decodeMessage(message.data);
    if (!info || info->penalised) continue;
    const RRCoord rr = toRobotRelative(pos, static_cast<float>(info->robotX), static_cast<float>(info->robotY));
    found.push_back({rr.x(), rr.y()});
  }
  for (const TouchedSector& sector : touchedSectors(motion))
    found.push_back({exactZero(TOUCH_DIST * std::cos(sector.middle)), exactZero(TOUCH_DIST * std::sin(sector.middle))});
  return found;
}

std::vector<TouchedSector> touchedSectors(const MotionBlackboard& motion) {
  const std::pair<bool, TouchedSector> sectors[] = {
      {motion.touchFrontLeft, {TOUCH_FRONT_BEARING, TOUCH_FRONT_HALF_WIDTH}},
      {motion.touchFrontRight, {-TOUCH_FRONT_BEARING, TOUCH_FRONT_HALF_WIDTH}},
      {motion.touchLeft, {kPi / 2, TOUCH_SIDE_HALF_WIDTH}},
      {motion.touchRight, {-kPi / 2, TOUCH_SIDE_HALF_WIDTH}},
      {motion.touchBack, {kPi, TOUCH_SIDE_HALF_WIDTH}}};
  std::vector<TouchedSector> touched;
  for (const auto& [on, sector] : sectors)
    if (on) touched.push_back(sector);
  return touched;
}

bool closesOnTouch(const std::vector<TouchedSector>& sectors, float direction) {
  for (const TouchedSector& s : sectors)
    if (std::fabs(normaliseTheta(direction - s.middle)) < s.halfWidth + kPi / 2 - 1e-4f) return true;
  return false;
}

WalkVelocity keepOffTouches(const MotionBlackboard& motion, float forward, float left) {
  const float speed = std::hypot(forward, left);
  const std::vector<TouchedSector> sectors = touchedSectors(motion);
  if (speed < MIN_WALK_SPEED || sectors.empty()) return {forward, left};
  const auto reach = [](const TouchedSector& s) { return s.halfWidth + kPi / 2; }; // the directions closing on it
  const float direction = std::atan2(left, forward);
  if (!closesOnTouch(sectors, direction)) return {forward, left};
  bool any = false; // best: the edge turning the walk least; the first of equal turns (within 1e-4 rad) wins
  float best = 0, bestOff = 0;
  for (const TouchedSector& s : sectors) {
    for (const float side : {-1.f, 1.f}) {
      const float edge = s.middle + side * reach(s);
      if (closesOnTouch(sectors, edge)) continue;
      const float off = std::fabs(normaliseTheta(edge - direction));
      if (!any || off < bestOff - 1e-4f) {
        any = true;
        best = edge;
        bestOff = off;
      }
    }
  }
  if (!any) return {0.f, 0.f};
  return clampWalk(speed * std::cos(best), speed * std::sin(best));
}

bool inOwnBox(float x, float y) {
  return x < OWN_BOX_FRONT_X + BOX_AVOID_MARGIN && std::fabs(y) < OWN_BOX_HALF_WIDTH + BOX_AVOID_MARGIN;
}

WalkVelocity steer(float forward, float left, const std::vector<Obstacle>& found, float targetDist) {
  const float speed = std::hypot(forward, left);
  if (speed < MIN_WALK_SPEED) return {forward, left};
  const float dirX = forward / speed;
  const float dirY = left / speed;
  const float reach = std::min(AVOID_LOOKAHEAD, targetDist);
  bool any = false;
  float nearestDist = 0, nearestX = 0, nearestY = 0, nearestAcross = 0;
  for (const Obstacle& o : found) {
    const float along = o.x * dirX + o.y * dirY;
    const float across = dirX * o.y - dirY * o.x; // + : left of the walk's line
    if (along <= 0.f || along > reach || std::fabs(across) >= AVOID_CLEARANCE) continue;
    const float dist = std::hypot(o.x, o.y);
    if (!any || dist < nearestDist) {
      any = true;
      nearestDist = dist;
      nearestX = o.x;
      nearestY = o.y;
      nearestAcross = across;
    }
  }
  if (!any) return {forward, left};
  const float side = nearestAcross >= 0.f ? -1.f : 1.f; // pass an obstacle on the left on its right
  const float half = nearestDist <= AVOID_CLEARANCE ? kPi / 2 : std::asin(AVOID_CLEARANCE / nearestDist);
  const float angle = std::atan2(nearestY, nearestX) + side * half;
  return clampWalk(speed * std::cos(angle), speed * std::sin(angle));
}

WalkVelocity keepOutOfOwnBox(const AbsCoord& pos, float forward, float left) {
  const float speed = std::hypot(forward, left);
  if (speed < MIN_WALK_SPEED || inOwnBox(pos.x, pos.y)) return {forward, left};
  FieldVelocity v = toFieldAxes(pos, forward, left);
  if (!inOwnBox(pos.x + v.vx / speed * BOX_LOOKAHEAD, pos.y + v.vy / speed * BOX_LOOKAHEAD)) return {forward, left};
  if (pos.x >= OWN_BOX_FRONT_X + BOX_AVOID_MARGIN) {
    v.vx = std::max(v.vx, 0.f); // in front of the box: no nearer the goal line
  } else {
    // beside it: no nearer the centre line; that part goes to the field, round the front
    const float kept = pos.y > 0.f ? std::max(v.vy, 0.f) : std::min(v.vy, 0.f);
    v.vx += std::fabs(v.vy - kept);
    v.vy = kept;
  }
  return toRobotAxes(pos, v);
}

WalkVelocity keepOnField(const AbsCoord& pos, float forward, float left) {
  const float speed = std::hypot(forward, left);
  if (speed < MIN_WALK_SPEED) return {forward, left};
  FieldVelocity v = toFieldAxes(pos, forward, left);
  const float aheadX = pos.x + v.vx / speed * FIELD_LOOKAHEAD, aheadY = pos.y + v.vy / speed * FIELD_LOOKAHEAD;
  const float limitX = FIELD_HALF_LENGTH + FIELD_EDGE_SLACK, limitY = FIELD_HALF_WIDTH + FIELD_EDGE_SLACK;
  const bool outX = std::fabs(aheadX) > limitX && aheadX * v.vx > 0.f; // further out over a goal line ...
  const bool outY = std::fabs(aheadY) > limitY && aheadY * v.vy > 0.f; // ... or a touchline
  if (!outX && !outY) return {forward, left};
  if (outX) v.vx = 0.f;
  if (outY) v.vy = 0.f;
  return toRobotAxes(pos, v);
}

WalkVelocity keepInBounds(const Blackboard& blackboard, float forward, float left) {
  const AbsCoord& pos = blackboard.localisation.robotPos;
  WalkVelocity v{forward, left};
  if (blackboard.gameController.playerNumber != GOALIE_PLAYER) v = keepOutOfOwnBox(pos, v.forward, v.left);
  return keepOnField(pos, v.forward, v.left);
}

WalkVelocity keepClear(const Blackboard& blackboard, float forward, float left) {
  const WalkVelocity offTouches = keepOffTouches(blackboard.motion, forward, left);
  const WalkVelocity v = keepInBounds(blackboard, offTouches.forward, offTouches.left);
  if (std::hypot(v.forward, v.left) >= MIN_WALK_SPEED &&
      closesOnTouch(touchedSectors(blackboard.motion), std::atan2(v.left, v.forward)))
    return {0.f, 0.f}; // the box or a line turned the walk back into a robot: wait, do not push
  return v;
}

std::optional<Obstacle> blocker(const std::vector<Obstacle>& found, float forward, float left) {
  std::optional<Obstacle> best;
  float bestDist = 0;
  for (const Obstacle& o : found) {
    const float dist = std::hypot(o.x, o.y);
    if (dist < BLOCKED_OBSTACLE_DIST && o.x * forward + o.y * left > 0.f && (!best || dist < bestDist)) {
      best = o;
      bestDist = dist;
    }
  }
  return best;
}

ActionCommand::Body Avoid::tick(const Blackboard& blackboard, const ActionCommand::Body& body, float targetDist) {
  const int64_t utime = blackboard.utime;
  if (!lastUtime_ || !(utime - *lastUtime_ > 0 && utime - *lastUtime_ <= FRAME_GAP_US)) {
    blockedFrames_ = 0;
    bestDist_ = targetDist;
    backOffFrames_ = 0;
  }
  lastUtime_ = utime;
  seen_ = remember(seen_, blackboard);
  const std::vector<Obstacle> found = obstacles(blackboard, seen_);
  bool backing = backOffFrames_ > 0;
  WalkVelocity v{body.forward, body.left};
  if (backing) {
    --backOffFrames_;
  } else {
    backing = blocked(found, body.forward, body.left, targetDist);
    if (!backing) v = steer(body.forward, body.left, found, targetDist);
  }
  if (backing) v = steer(BACK_OFF_FORWARD, backOffLeft_, found, AVOID_LOOKAHEAD);
  v = keepClear(blackboard, v.forward, v.left);
  return actioncommand::walk(v.forward, v.left, backing ? 0.f : body.turn);
}

ActionCommand::Body Avoid::stand(const Blackboard& blackboard) {
  lastUtime_.reset(); // a walk after standing starts its count again
  seen_ = remember(seen_, blackboard);
  bool any = false;
  float nearestDist = 0, nearestX = 0, nearestY = 0;
  std::vector<Sighting> now; // not the remembered ones: they may have gone
  for (const Sighting& entry : seen_)
    if (entry.utime == blackboard.utime) now.push_back(entry);
  const std::vector<Obstacle> found = obstacles(blackboard, now);
  for (const Obstacle& o : found) {
    const float dist = std::hypot(o.x, o.y);
    if (o.x > 0.f && dist < YIELD_DIST && (!any || dist < nearestDist)) {
      any = true;
      nearestDist = dist;
      nearestX = o.x;
      nearestY = o.y;
    }
  }
  if (!any) return actioncommand::stand();
  WalkVelocity v = steer(-YIELD_SPEED * nearestX / nearestDist, -YIELD_SPEED * nearestY / nearestDist, found, YIELD_DIST);
  v = keepClear(blackboard, v.forward, v.left);
  return actioncommand::walk(v.forward, v.left);
}

bool Avoid::blocked(const std::vector<Obstacle>& found, float forward, float left, float targetDist) {
  const std::optional<Obstacle> block = blocker(found, forward, left);
  if (!block || targetDist < bestDist_ - BLOCKED_PROGRESS) {
    blockedFrames_ = 0;
    bestDist_ = targetDist;
    return false;
  }
  if (++blockedFrames_ < BLOCKED_FRAMES) return false;
  blockedFrames_ = 0;
  bestDist_ = targetDist;
  backOffFrames_ = BACK_OFF_FRAMES - 1;
  backOffLeft_ = block->y >= 0.f ? -BACK_OFF_LEFT : BACK_OFF_LEFT;
  return true;
}

} // namespace touchline::behaviour::skills
