#pragma once
// LineUpAndKick: approach the ball (GoToBall), line the kicking foot up behind it facing the
// goal (or along the line a ball on it lies on: ball.hpp's kickAim) with small steps, and kick
// (or dribble) once aligned. The foot is chosen on the ball's side when lining up starts and
// kept until it ends. The aim may be off by KICK_FAR_ANGLE_TOLERANCE while the goal is far;
// while a robot (avoid.hpp's obstacles) is within CONTEST_DIST of the ball, the robot kicks at
// once wherever the kick gains ground (CONTEST_ANGLE_TOLERANCE) instead of turning slowly
// under its feet, the ball placed as for any kick (KICK_X/Y_TOLERANCE): the swing reaches 200
// mm ahead of the body centre (the toe 80 plus the strike's 120), so a contested kick once
// allowed 80 mm beyond the kicking spot (210) met the ball at the end of the swing, and one
// 70 mm off the foot's line with its edge: kicks that glanced off or missed (a goalie kicked
// four times in 7 s without clearing the ball). A contest in which the ball has not moved
// STALL_BALL_MOVE for STALL_FRAMES (kicks into an opponent's feet, the ball wedged) makes the
// robot step sideways round the ball, away from the nearest robot, for SIDESTEP_FRAMES, so
// the next kick has a clear line. Lining-up
// steps and sidesteps go through avoid's keepClear: off touched sectors (they were most of the
// pushing fouls left once Avoid's walks kept off them), out of the own goal box (stepping into
// it while lining up was most of the illegal-defender calls with balls put back on the
// throw-in line: 16 C++ matches, 1.44 a match for both teams, 0.63 through keepClear) and on
// the field.
// With `carry`, a ball lined up within CARRY_ANGLE, ahead and near the body's centre line, is
// walked into at CARRY_SPEED instead of kicked (closing on a ball further ahead faster, up to
// MAX_FORWARD: carrySpeed): the feet push it on and the walk follows it,
// turning towards the aim, with no kick's stop (about 2.2 s of the ball lying still under a
// standing robot). A robot ahead does not stop it: a kick into a robot at the ball often
// rebounds, sometimes out of the field. keepClear stops the walk at a touch, but in a contest
// the carrier leans on at up to CONTEST_LEAN_SPEED (the rules call no pushing while both
// robots are at the ball): two robots that stopped at each other's feet held the ball
// between them.
// A carrier starts lining up with the aim up to CARRY_ANGLE off, beyond a right angle: it
// turns with the ball towards the aim, the ball moving all the while, rather than walking
// round the ball first (at 1.2 rad, where the ball still gains ground, it moved 1.2 % less of
// the play, 16 matches). In a contest a carrier also steps sideways at CONTEST_DODGE_SPEED,
// away from the robot nearest the ball: two carriers walking into one ball from both sides
// wedge it between their feet, and the sideways step rolls it off the pair. Carrying walks go
// through avoid's keepClear, as Avoid's do. The port of behaviour_py/skills/line_up_and_kick.py.
#include <optional>
#include <string>

#include <vector>

#include "touchline/behaviour/skills/avoid.hpp"
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/go_to_ball.hpp"

namespace touchline::behaviour::skills {

inline constexpr float FOOT_OFFSET = 50.f;           ///< mm: each foot's centre left/right of the body centre
inline constexpr float KICK_BALL_X = 130.f;          ///< mm: ball centre ahead of the body centre to kick (toe 80 + radius 32.5 + gap)
inline constexpr float KICK_X_TOLERANCE = 40.f;      ///< mm
inline constexpr float KICK_Y_TOLERANCE = 40.f;      ///< mm: ball centre from the kicking foot's centre line
inline constexpr float KICK_ANGLE_TOLERANCE = 10.f * api::kPi / 180.f; ///< rad: heading error to the goal ...
inline constexpr float KICK_FAR_DIST = 2500.f;       ///< mm: ... or, the ball farther than this from it, ...
inline constexpr float KICK_FAR_ANGLE_TOLERANCE = 0.45f; ///< rad: ... this (the kick still gains ground)
inline constexpr float CONTEST_DIST = 500.f;         ///< mm: an obstacle this near the ball contests it: then ...
inline constexpr float CONTEST_ANGLE_TOLERANCE = 1.2f; ///< rad: ... kick this far off the goal
inline constexpr int STALL_FRAMES = 60;                ///< frames (2 s) contested without the ball moving ...
inline constexpr float STALL_BALL_MOVE = 100.f;        ///< mm: ... this far: then ...
inline constexpr int SIDESTEP_FRAMES = 30;             ///< frames (1 s) of stepping sideways round the ball
inline constexpr float LINE_UP_ENTER_DIST = 300.f;   ///< mm: start lining up when the ball is this close ...
inline constexpr float LINE_UP_ENTER_ANGLE = 1.2f;   ///< rad: ... ahead (steps sideways to it: at 0.6 the ball moved 0.6 % less of the play), and the goal this well in line
inline constexpr float LINE_UP_LEAVE_DIST = 500.f;   ///< mm: back to approaching beyond this ...
inline constexpr float LINE_UP_LEAVE_ANGLE = 1.5f;   ///< rad: ... or this far off
inline constexpr float LINE_UP_GAIN = 2.f;           ///< 1/s: step request (mm/s) per mm of error
inline constexpr float LINE_UP_MAX_SPEED = 250.f;    ///< mm/s: steps, either axis (at 150 the ball moved 1.4 % less of the play)
inline constexpr float LINE_UP_MAX_TURN = 1.0f;      ///< rad/s
inline constexpr float KICK_POWER = 1.f;             ///< default power of a kick ...
inline constexpr float DRIBBLE_POWER = 1.0f;         ///< ... and of a dribble (about 1 m)
inline constexpr float CARRY_ANGLE = 1.8f;           ///< rad: with carry, the aim this well in line (lining up starts so too), ...
inline constexpr float CARRY_BALL_X = 400.f;         ///< mm: ... the ball ahead within this ...
inline constexpr float CARRY_BALL_Y = 120.f;         ///< mm: ... and this near the body's centre line: ...
/// mm/s: ... walk into the ball at this (at full speed the feet strike it away; 64 C++ matches,
/// seeds 1-64: at 180 the ball moved 51.0 % of the play, at 140 52.2 %; 100-230 on seeds 1-16:
/// 46.6, 51.2, 52.6 (140), 52.0, 52.3, 51.0 (180), 49.8 %) ...
inline constexpr float CARRY_SPEED = 140.f;
inline constexpr float CARRY_CLOSING_GAIN = 2.f;     ///< 1/s: ... plus this per mm it lies beyond KICK_BALL_X, up to MAX_FORWARD
/// mm/s: a carrier in a contest steps this much sideways, away from the robot nearest the ball
/// (64 C++ matches, seeds 1-64: the ball still between both teams 13.1 -> 11.0 % of the play,
/// moving 50.2 -> 51.0 %; at 80 and 250 mm/s, seeds 1-16, 50.3 and 50.4 % against 51.0 %)
inline constexpr float CONTEST_DODGE_SPEED = 150.f;
/// mm/s: a carrier in a contest that a touch would stop leans on into it at up to this (the
/// rules call no pushing while both robots are at the ball); two that stopped at each other's
/// feet held the ball between them (16 C++ matches on each of seeds 1-16, 17-32 and 33-48, with
/// a trial build whose lean skipped keepInBounds: the ball moving 55.0, 55.3 and 55.4 -> 59.5 %
/// of the play on each, pushing 0.2-0.6 -> 1.1-1.6 calls a team a match; at 70 mm/s 58.1 and
/// 58.4 % on the first two, at 100 59.2 and 59.1 %, at 140 59.9 % on seeds 1-16, where the four
/// strikers gained most on the supporters; as committed, 58.7 % on seeds 1-16: within a
/// 16-match run's spread of the trial's, as without keepInBounds again 59.4-59.7 % and with 150
/// mm of slack beyond the lines 58.7 %)
inline constexpr float CONTEST_LEAN_SPEED = 85.f;

/// The forward speed of a carry with the ball `ballX` mm ahead of the body centre: CARRY_SPEED
/// at the foot (KICK_BALL_X), faster further out (CARRY_CLOSING_GAIN), up to MAX_FORWARD; at
/// a constant 180 mm/s (CARRY_SPEED then: 1.5 s to a ball 400 mm ahead) the ball moved 1.6 %
/// less of the play.
float carrySpeed(float ballX);

class LineUpAndKick : public api::Behaviour {
 public:
  /// goalX, goalY: where to kick (mm); dribble: dribble instead of kicking; power: [0, 1],
  /// nullopt for KICK_POWER or DRIBBLE_POWER; policy: GoToBall's (nullopt: GoToPose);
  /// carry: walk the ball on instead of kicking it, past a robot ahead too.
  explicit LineUpAndKick(float goalX = OPPONENT_GOAL_X, float goalY = OPPONENT_GOAL_Y, bool dribble = false,
                         std::optional<float> power = std::nullopt,
                         const std::optional<std::string>& policy = std::nullopt, bool carry = false);
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;

  bool liningUp() const { return liningUp_; }
  /// Whether the last tick found a robot within CONTEST_DIST of the ball.
  bool contested() const { return contested_; }
  api::ActionCommand::Foot foot() const { return foot_; }
  float power() const { return power_; }

 private:
  void updateLiningUp(const api::RRCoord& ballRR, float aimError);
  float footY() const;
  /// Kick when the ball is in front of the foot and the goal ahead; else step closer.
  api::ActionCommand::Body lineUp(const api::RRCoord& ballRR, float aimError) const;

  float goalX_, goalY_;
  bool dribble_;
  float power_;
  bool carry_;
  GoToBall goToBall_;
  bool liningUp_ = false;
  api::ActionCommand::Foot foot_ = api::ActionCommand::Foot::LEFT;
  std::vector<Sighting> seen_; ///< the robots the camera saw (remember())
  bool contested_ = false;
  float aimTolerance_ = KICK_ANGLE_TOLERANCE; ///< this tick's: normal, far or contested
  int stalledFrames_ = 0;   ///< contested frames without the ball moving STALL_BALL_MOVE from stallBall
  float stallBallX_ = 0.f, stallBallY_ = 0.f;
  int sidestepFrames_ = 0;  ///< sidestep frames left, at sidestepLeft_ mm/s
  float sidestepLeft_ = 0.f;
};

} // namespace touchline::behaviour::skills
