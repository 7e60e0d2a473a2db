#pragma once
// Avoid: walk around robots instead of into them, never through the own goal box, and back
// off when blocked, staying on the field; the port of behaviour_py/skills/avoid.py. GoToPose
// passes every walk it asks for through Avoid::tick.
//
// Reads: motion.sonarLeft/sonarRight/sonarRange_mm, motion.touch* (the foot bumpers and arms),
// vision.robots, receiver.messages (the teammates' poses), localisation.robotPos,
// gameController.playerNumber, utime. Writes nothing.
//
// Obstacles, robot frame (x forward, y left), from what a robot really has:
// - the sonars (thesis Algorithm 2.4): a reading under 1 is a body that far ahead in the left
//   or right half of the sonars' corridor, taken SONAR_SIDE_Y off the centre line;
// - the robots the camera saw, remembered in the field frame for SEEN_MEMORY_US (the head
//   follows the ball, so a robot beside the walk is seen now and then); a sighting replaces
//   those remembered within SEEN_MERGE_DIST of it;
// - the teammates' own poses from their team messages (fresh, not penalised);
// - a touch (a robot against the foot bumpers or an arm, which the camera may never have seen:
//   it looks at the ball, and most robots walked into are beside or behind), a body TOUCH_DIST
//   away at its sector's middle: TOUCH_FRONT_BEARING either side ahead, beside, behind.
//
// Off a touch: a sensor only tells the sector (TOUCH_FRONT_HALF_WIDTH, TOUCH_SIDE_HALF_WIDTH
// either side of its middle), and a robot at its edge is pushed by a walk that passes its
// middle. So a walk that closes on any bearing of a touched sector (less than 90 deg from it)
// turns, its speed kept, to the nearest direction that closes on none; it stops if every
// direction does. This comes after the steering and the backing off, before the own goal box
// and the field; a walk that those turn back onto a touched sector stops (a defender beside
// its box, sidestepping towards it with an opponent ahead, was sent round the box's front
// into the opponent: half the Python supporters' pushing fouls).
//
// Around robots (a tangent rule): the nearest obstacle ahead on the walk's line, within
// AVOID_LOOKAHEAD and nearer than the target, and less than AVOID_CLEARANCE off the line,
// turns the walk's direction onto the tangent of the AVOID_CLEARANCE circle around it, on the
// side the line already passes it (right when dead ahead, so two robots meeting both keep
// right). The speed is kept; the turn is not touched.
//
// The own goal box (every player but the goalie): a walk that would bring the robot into the
// box grown by BOX_AVOID_MARGIN within BOX_LOOKAHEAD loses its part into the box: the robot
// slides along it (beside the box, that part becomes a step towards the field, so a walk
// across the box goes round its front). A robot already in it walks as asked (its target
// takes it out).
//
// The field (every player): a walk that within FIELD_LOOKAHEAD would take the body centre more
// than FIELD_EDGE_SLACK beyond a line loses its part further out over that line; it may still
// walk along the line or back in. The referee penalises a robot 200 mm beyond a line (leaving
// the field, 45 s out): walks to a stale ball on the touchline, round a crowd or backing off
// took four strikers out 12-14 times a match.
//
// Make way: a robot standing at its target steps back from an obstacle ahead of it nearer
// than YIELD_DIST (sonar, this frame's sightings, teammates) at YIELD_SPEED (a robot facing
// another at contact counts as pushing it).
//
// Back off: a walk that for BLOCKED_FRAMES frames in a row has an obstacle within
// BLOCKED_OBSTACLE_DIST in the way and gets less than BLOCKED_PROGRESS closer to its target
// becomes BACK_OFF_FRAMES frames of stepping back and aside, away from that obstacle. Frames
// count while the walk is asked for every frame (utime at most FRAME_GAP_US apart). Backing off
// and making way are steered round the obstacles too, so neither steps into a robot behind.
#include <cstdint>
#include <optional>
#include <vector>

#include "touchline/behaviour/skills/field.hpp"
#include "touchline/behaviour/skills/robot_limits.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::behaviour::skills {

inline constexpr float SONAR_SIDE_Y = 50.f;            ///< mm: a sonar's obstacle this far off the centre line
inline constexpr float AVOID_LOOKAHEAD = 800.f;        ///< mm: obstacles farther along the walk are left alone
inline constexpr float AVOID_CLEARANCE = 400.f;        ///< mm: pass obstacle centres this far (bodies touch at 300)
inline constexpr float MIN_WALK_SPEED = 1.f;           ///< mm/s: slower walks are not steered
inline constexpr float BOX_AVOID_MARGIN = 100.f;       ///< mm: the own goal box grown by this ...
inline constexpr float BOX_LOOKAHEAD = 300.f;          ///< mm: ... is not entered within this along the walk
inline constexpr float FIELD_LOOKAHEAD = 150.f;        ///< mm: no walk takes the body centre FIELD_EDGE_SLACK beyond a line within this
inline constexpr float BLOCKED_OBSTACLE_DIST = 450.f;  ///< mm: an obstacle this near and in the way can block
inline constexpr int BLOCKED_FRAMES = 45;              ///< frames (1.5 s) without progress before backing off
inline constexpr float BLOCKED_PROGRESS = 100.f;       ///< mm: nearer to the target than this is progress
inline constexpr int BACK_OFF_FRAMES = 30;             ///< frames (1 s) of backing off ...
inline constexpr float BACK_OFF_FORWARD = -150.f;      ///< mm/s: ... stepping back ...
inline constexpr float BACK_OFF_LEFT = 150.f;          ///< mm/s: ... and aside, away from the obstacle
inline constexpr int FRAME_GAP_US = 50000;             ///< us: ticks farther apart start the count again
inline constexpr int SEEN_MEMORY_US = 1500000;         ///< us: a robot the camera saw stays an obstacle this long
inline constexpr float SEEN_MERGE_DIST = 400.f;        ///< mm: a sighting replaces remembered robots this near it
inline constexpr float YIELD_DIST = 400.f;             ///< mm: a standing robot makes way for one ahead this near ...
inline constexpr float YIELD_SPEED = 150.f;            ///< mm/s: ... stepping straight away from it
inline constexpr float TOUCH_DIST = 200.f;             ///< mm: a robot felt by touch is this far ...
inline constexpr float TOUCH_FRONT_BEARING = api::kPi / 8; ///< rad: ... at this bearing either side ahead (a foot bumper's middle)
inline constexpr float TOUCH_FRONT_HALF_WIDTH = api::kPi / 8; ///< rad: a foot bumper feels this far either side of its middle
inline constexpr float TOUCH_SIDE_HALF_WIDTH = api::kPi / 4;  ///< rad: an arm (beside, behind) this far

/// A point in the robot frame, mm (x forward, y left).
struct Obstacle {
  float x = 0;
  float y = 0;
};

/// A sector of the robot in which another robot touches it, rad, robot frame.
struct TouchedSector {
  float middle = 0;
  float halfWidth = 0;
};

/// A robot the camera saw, field frame.
struct Sighting {
  int64_t utime = 0; ///< when, us
  float x = 0;       ///< mm
  float y = 0;       ///< mm
};

/// seen with this frame's sightings in and the old ones out.
std::vector<Sighting> remember(const std::vector<Sighting>& seen, const api::Blackboard& blackboard);
/// The obstacles the robot knows of, robot frame; seen: the remembered sightings (remember()).
std::vector<Obstacle> obstacles(const api::Blackboard& blackboard, const std::vector<Sighting>& seen = {});
/// Whether the field point (x, y) is in the own goal box grown by BOX_AVOID_MARGIN.
bool inOwnBox(float x, float y);
/// The walk (forward, left) turned onto the tangent past the nearest obstacle in its way.
WalkVelocity steer(float forward, float left, const std::vector<Obstacle>& found, float targetDist);
/// The sectors in which a robot touches this one (motion.touch*).
std::vector<TouchedSector> touchedSectors(const api::MotionBlackboard& motion);
/// Whether a walk in `direction` (rad, robot frame) closes on one of `sectors`
/// (touchedSectors()): less than 90 deg from some bearing in it.
bool closesOnTouch(const std::vector<TouchedSector>& sectors, float direction);
/// The walk (forward, left) turned to the nearest direction that closes on no touched sector,
/// its speed kept; (0, 0) when every direction closes on one.
WalkVelocity keepOffTouches(const api::MotionBlackboard& motion, float forward, float left);
/// The walk (forward, left) less its part into the own goal box when it would enter it.
WalkVelocity keepOutOfOwnBox(const api::AbsCoord& pos, float forward, float left);
/// (forward, left) less its part further out over a line when within FIELD_LOOKAHEAD along it
/// the body centre would be more than FIELD_EDGE_SLACK beyond that line.
WalkVelocity keepOnField(const api::AbsCoord& pos, float forward, float left);
/// (forward, left) out of the own goal box (all but the goalie: keepOutOfOwnBox) and on the
/// field (keepOnField).
WalkVelocity keepInBounds(const api::Blackboard& blackboard, float forward, float left);
/// (forward, left) off the touched sectors, then keepInBounds: the last word on every walk
/// Avoid makes. A walk that the box or a line turns back onto a touched sector becomes (0, 0):
/// waiting, not pushing.
WalkVelocity keepClear(const api::Blackboard& blackboard, float forward, float left);
/// The nearest obstacle within BLOCKED_OBSTACLE_DIST that the walk heads towards, if any.
std::optional<Obstacle> blocker(const std::vector<Obstacle>& found, float forward, float left);

class Avoid {
 public:
  /// The walk to do for `body` (a walk request) on the way to a target targetDist mm away.
  api::ActionCommand::Body tick(const api::Blackboard& blackboard, const api::ActionCommand::Body& body,
                                float targetDist);
  /// Stand, or step away from the nearest obstacle ahead nearer than YIELD_DIST.
  api::ActionCommand::Body stand(const api::Blackboard& blackboard);

 private:
  /// Whether the walk (forward, left) has been blocked for BLOCKED_FRAMES: then backing off
  /// starts (this frame is its first).
  bool blocked(const std::vector<Obstacle>& found, float forward, float left, float targetDist);

  std::optional<int64_t> lastUtime_;
  int blockedFrames_ = 0;
  float bestDist_ = 0;
  int backOffFrames_ = 0;
  float backOffLeft_ = 0;
  std::vector<Sighting> seen_; ///< robots the camera saw, field frame
};

} // namespace touchline::behaviour::skills
