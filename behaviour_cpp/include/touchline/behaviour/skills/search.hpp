#pragma once
// Search: the body of a field player (not the goalie) that has not seen the ball for
// SEARCH_TURN_FRAMES, so that a lost robot never turns on the spot for long, or has not seen
// it since the referee put it back after it left the field. The port of
// behaviour_py/skills/search.py (which says what it does); reads the Blackboard's
// localisation, gameController, receiver and motion (its touches, through keepClear and
// GoToPose's Avoid), writes nothing.
#include <optional>
#include <vector>

#include "touchline/behaviour/skills/field.hpp"
#include "touchline/behaviour/skills/go_to_pose.hpp"
#include "touchline/behaviour/skills/supporter.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::behaviour::skills {

inline constexpr int SEARCH_TURN_FRAMES = 90;         ///< frames (3 s) without the ball before searching
inline constexpr float SEARCH_TURN_SPEED = 0.8f;      ///< rad/s
inline constexpr int SEARCH_TURN_LIMIT_FRAMES = 150;  ///< frames of turning (4 rad, well under a full turn) ...
inline constexpr int SEARCH_CYCLE_FRAMES = 520;       ///< ... of every cycle; the rest walks to a search spot
inline constexpr float HOME_NEAR_DIST = 300.f;        ///< mm: a supporter this close to home may turn to search
inline constexpr float SEARCH_SPOT_X = 1500.f;        ///< mm: the search spots are (X, 0), (0, Y), (-X, 0), (0, -Y) ...
inline constexpr float SEARCH_SPOT_Y = 1200.f;        ///< mm: ... in turn, each 1.9 m from the next
inline constexpr int SEARCH_SPOT_COUNT = 4;
inline constexpr int STRIKER_FIRST_SPOT = 0;          ///< the striker searches the opponent half first, ...
inline constexpr int MIDFIELDER_FIRST_SPOT = 1;       ///< ... the midfielder its own side ...
inline constexpr int DEFENDER_FIRST_SPOT = 2;         ///< ... and the defender the own half
inline constexpr float BALL_AT_FEET_DIST = 250.f;     ///< mm: a lost ball last seen this near lies at the feet, so ...
inline constexpr float SEARCH_BACK_OFF_SPEED = 150.f; ///< mm/s: ... the robot steps away from it this fast, not turning
inline constexpr float DROP_IN_SETBACK = 1000.f;      ///< mm: SPL 2011 puts a ball that left the field back this far
                                                      ///< towards the goal of the team that put it out, ...
inline constexpr float THROW_IN_LINE_INSET = 400.f;   ///< mm: ... on the throw-in line, this far inside the touchline, ...
inline constexpr float THROW_IN_LINE_END = 1000.f;    ///< mm: ... which ends this far short of each goal line
inline constexpr int DROP_IN_FRESH_S = 8;             ///< s: a ball put back this recently is looked for where it was put

/// (x, y) a role walks back to while the ball is lost; supporters: the SupporterDef played.
FieldPoint homePosition(int role, const SupporterDef& supporters);
/// (x, y) of the ball as the teammates see it, or nullopt: the sighting of the teammate
/// nearest to it among those whose message is fresh, says the ball was seen, and is not from
/// a penalised robot (ties: the lower player number).
std::optional<FieldPoint> teamBall(int playerNumber, const std::vector<api::TeamMessage>& messages, int64_t utime);
/// (x, y, theta): where the role stands for the ball at (ballX, ballY): the striker behind it
/// facing the opponent goal, a supporter at its algorithm's target (the numbers of
/// `supporters`) facing it.
api::AbsCoord teamBallTarget(int role, float ballX, float ballY, float robotY, const SupporterDef& supporters);
/// (x, y) of the role's walk-th search spot (0: its first).
FieldPoint searchSpot(int role, int walk);
/// (x, y) where the SPL 2011 rules put back a ball last seen at (ballX, ballY) that then left
/// the field over the line it lies farther beyond (or nearer inside), by the team dropInTeam
/// (ours, ourTeam, defends -x; -1: not known): on the throw-in line on its side. Over a
/// touchline, DROP_IN_SETBACK along x towards dropInTeam's goal (not known: not moved), within
/// the throw-in line's ends; over a goal line, at the halfway line if the goal's attackers
/// put it out, else at the throw-in line's end by that goal line.
FieldPoint dropInSpot(float ballX, float ballY, int dropInTeam, int ourTeam);

class Search {
 public:
  /// supporters: the SupporterDef whose targets and homes a lost supporter uses.
  explicit Search(const SupporterDef& supporters = tunedSupporters()) : supporters_(supporters) {}
  /// The body request of a field player of `role` searching, or nullopt while it has not lost
  /// the ball for long enough, or plays the role's own skill (a supporter walking home).
  std::optional<api::ActionCommand::Body> tick(const api::Blackboard& blackboard, int role);
  /// Where the ball was put back while this robot has not seen it since (the last tick's).
  const std::optional<FieldPoint>& dropIn() const { return dropIn_; }

 private:
  /// Latches dropIn_ when the GameController's dropInTime starts again (a ball put back)
  /// while this robot does not see the ball; clears it once the ball is seen, or the drop-in
  /// is DROP_IN_FRESH_S old.
  void updateDropIn(const api::Blackboard& blackboard);
  /// The walk to where the role stands for a ball at `ball` (teamBallTarget).
  api::ActionCommand::Body toBall(const api::Blackboard& blackboard, int role, FieldPoint ball);

  SupporterDef supporters_;
  int lastDropInTime_ = -1;          ///< dropInTime at the last tick
  std::optional<FieldPoint> dropIn_; ///< where the ball was put back, until it is seen
  GoToPose ballPose_;
  GoToPose spotPose_;
};

} // namespace touchline::behaviour::skills
