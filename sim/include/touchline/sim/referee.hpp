#pragma once
// The referee: a built-in game controller playing the SPL 2011 rules, simplified (the
// rules and their switches: rules.hpp). Pure: the match hands it the truth once per
// camera frame, after the world advanced, and carries out what it decides (where robots
// and the ball go, whose motions to ignore); it sends nothing and reads no clock but the
// input's utime, so the same inputs give the same decisions, bit for bit.
//
// States: INITIAL (initial_s) -> [STANDBY (standby_s)] -> READY (ready_s) -> SET (set_s) ->
// PLAYING, timed exactly
// from the utime each state began, whatever the update rate. A goal gives READY again,
// kick-off to the conceding team. The clock (secs_remaining) runs only in PLAYING; after
// half_s of it the half ends: INITIAL of the second half, kick-off to the team that did
// not kick off the first, or FINISHED after the second.
//
// Simplifications of the SPL 2011 rules, on purpose:
// - SET lasts set_s (no human whistle); READY always lasts ready_s, even when everyone
//   is in place. Teams keep their sides at half time; the half-time break is INITIAL.
// - Half time ends every penalty: the second half starts with everyone on the field.
// - Penalties are given only in PLAYING, except leaving the field (READY, SET, PLAYING:
//   robots walking to their positions must stay on the field too). Penalty time runs in
//   every state. Crashed (inactive) robots are never penalised.
// - Pushing is judged by the thesis' heuristic (collision.hpp) between opponents only; by
//   default (rules.pushing_model = walking_into) only a robot walking into the other, its
//   body velocity taken from the poses the referee saw over rules.pushing_window_s.
// - Ball out: put back on the throw-in line as SPL 2011 has it (check_ball_out); the match
//   says who touched it last. A spot with a robot on it is moved along x until it is
//   clear (rules.ball_out_clearance_mm), set plays' spots too.
// - No kick-off restrictions in PLAYING (the defenders may enter the circle at once).
//
// Set plays (rules.set_plays, SPL 2020-2022): in PLAYING, a ball out over a touchline is a
// kick-in for the opponents of the team that touched it last, placed where it crossed the
// line; over a goal line it is a goal kick for the defenders (ball on the goal box's front
// corner on the side it left) or, when a defender touched it last, a corner kick for the
// attackers (ball on the field's corner on that side). A pushing foul is a pushing free kick
// for the fouled team (the ball stays where it is), or a penalty kick (ball on the penalty
// mark) when the pusher stood in its own penalty area. A set play ends when a robot of its
// team begins touching the ball, at the first update after set_play_s, or when PLAYING ends.
// Simplified: opponents are not kept 750 mm from the ball, a penalty kick moves no robot,
// and the set play's time is checked once per update (a frame), not timed to the microsecond.
#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "touchline/frame.hpp"
#include "touchline/sim/field.hpp"
#include "touchline/sim/rules.hpp"
#include "touchline/sim/world.hpp"

namespace touchline::sim {

/// One robot as the referee sees it.
struct RobotOnField {
  RobotId id;
  Pose2D body;        ///< field frame, truth
  bool active = true; ///< false while the match treats it as crashed: it is never penalised
};

/// What the match tells the referee each camera frame.
struct RefereeInput {
  int64_t utime = 0; ///< simulated time now, microseconds; never decreasing
  BallTruth ball;
  std::vector<RobotOnField> robots; ///< every robot the match has placed, penalised ones included
  int last_touch_team = -1;         ///< team whose robot touched the ball last, -1: unknown
  /// Teams whose robots began touching the ball since the last update (ends a set play).
  std::array<bool, 2> touched_by_team{{false, false}};
};

enum class PenaltyKind : int8_t {
  kNone = 0,
  kPushing = 1,         ///< pushed an opponent while not contesting the ball
  kIllegalDefender = 2, ///< field player in its own goal box while PLAYING
  kLeavingField = 3,    ///< body off the field by more than leave_field_margin_mm
};
const char* to_string(PenaltyKind kind);

struct Penalty {
  RobotId robot;
  PenaltyKind kind = PenaltyKind::kNone;
  int64_t since_utime = 0;
  int64_t until_utime = 0; ///< re-enters at the first update at or after this
};

struct StateChange {
  GameState from = GameState::kInitial, to = GameState::kInitial;
  int64_t utime = 0; ///< when it happened (a timed change: exactly when its state ran out)
};

struct GoalScored {
  int team = 0; ///< the scoring team
  int64_t utime = 0;
};

/// Put the robot down here, feet at rest (Match/World::place_robot).
struct RobotPlacement {
  RobotId robot;
  Pose2D pose;
};

/// Put the ball here at rest. kKickOff: on the centre spot after a goal, at half time, and
/// at SET if the robots moved it in READY (never for the first kick-off: the match puts
/// that ball where its config says). kBallOut: it left the field (see the notes above).
/// kSetPlay: where a set play is taken from (a ball out with set plays, a penalty kick).
struct BallPlacement {
  enum class Why : int8_t { kKickOff, kBallOut, kSetPlay };
  Why why = Why::kKickOff;
  float x_mm = 0, y_mm = 0;
};

/// The game was stuck (RulesDef::game_stuck_s): `kickoff_team` kicks off again.
struct GameStuck {
  int64_t utime = 0;
  int kickoff_team = 0;
  bool ball_untouched = true; ///< no robot touched the ball (else: it made no progress)
};

/// A set play began (`set_play` and its `team`) or ended (kNone, team -1).
struct SetPlayChange {
  SetPlay set_play = SetPlay::kNone;
  int team = -1;
  int64_t utime = 0;
};

/// A ball contest's loser, held for a frame (thesis 2.2.4).
struct ContestStop {
  RobotId robot;  ///< lost a ball contest: may not step towards ...
  RobotId winner; ///< ... this robot, nearer the ball
};

/// What one update decided, in the order it happened. Placements are in the order to
/// apply them (a robot may appear twice: the later wins).
struct RefereeDecision {
  std::vector<StateChange> state_changes;
  std::vector<GoalScored> goals;
  std::vector<Penalty> penalties;          ///< given in this update; each robot's removal is in placements
  std::vector<RobotId> released;           ///< served their time; each one's re-entry is in placements
  std::vector<RobotPlacement> placements;  ///< removals, re-entries, SET's manual placements
  std::optional<BallPlacement> ball;
  std::vector<SetPlayChange> set_plays;    ///< set plays begun and ended, in order
  std::optional<GameStuck> game_stuck;     ///< the game was stuck; a kick-off follows (state_changes)
  /// Contesting the ball, in contact with an opponent nearer it (the winner): the thesis'
  /// heuristic stops the loser (2.2.4); the match holds its steps towards the winner for the frame.
  std::vector<ContestStop> stopped;
  bool empty() const;
};

class Referee {
 public:
  /// `team_size` spaces the benches; `ball_diameter_mm` decides when the ball is wholly
  /// over a line. Throws ConfigError if `rules` do not validate.
  Referee(const Field& field, const RulesDef& rules, int team_size, float ball_diameter_mm);

  /// Once per camera frame, after the world advanced (any rate works: the rules are timed
  /// by utime, not by calls). The first call starts INITIAL. std::invalid_argument if
  /// utime goes back.
  RefereeDecision update(const RefereeInput& input);

  GameInfo info() const;
  GameState state() const { return state_; }
  bool penalised(RobotId id) const { return penalties_.count(id) != 0; }
  std::optional<Penalty> penalty(RobotId id) const;
  /// Whether the match should apply the robot's foot motions: READY or PLAYING and not
  /// penalised. (SPL robots stand still in INITIAL, STANDBY, SET and FINISHED.)
  bool may_move(RobotId id) const;

  /// The canonical kick-off position (READY's target; where manual placement puts a
  /// robot). Team 0 on the -x half facing +x, team 1 the same turned 180 degrees about
  /// the centre spot. Player 1, the goalie, in its goal box; player 2 just behind the
  /// centre spot when kicking off, else outside the centre circle; 3..7 between the goal
  /// box and the centre circle.
  Pose2D kickoff_position(RobotId id, bool kicking_off) const;
  /// Whether `body` is a legal place to stand at kick-off: inside the field on the own
  /// half, a field player outside its goal box, the defending team outside the circle.
  bool legal_kickoff_position(RobotId id, const Pose2D& body, bool kicking_off) const;
  /// Where a penalised robot waits: on the carpet beyond its own half's touchline
  /// (team 0: -y), one spot per player, facing the field.
  Pose2D bench_position(RobotId id) const;
  /// Where a robot re-enters (SPL): on the touchline of its own half, at the penalty
  /// mark's distance from its goal line, on the touchline farther from the ball, facing
  /// into the field.
  Pose2D reentry_position(RobotId id, float ball_x_mm, float ball_y_mm) const;

 private:
  using Robots = std::vector<RobotOnField>;

  // Clock and states (referee.cpp).
  void run_clock(int64_t now, const BallTruth& ball, Robots& robots, RefereeDecision& d);
  int64_t next_timed_event() const;
  void on_timer(int64_t at, const BallTruth& ball, Robots& robots, RefereeDecision& d);
  void enter(GameState to, int64_t at, RefereeDecision& d);
  void end_half(int64_t at, const BallTruth& ball, Robots& robots, RefereeDecision& d);
  int64_t half_us() const;

  // Ball (referee_ball.cpp).
  /// Where a ball that is wholly out crossed the line: which line, and the crossing point
  /// traced back along its velocity (the referee sees the ball once per frame).
  struct BallCrossing {
    bool over_touchline = false;
    float x_mm = 0, y_mm = 0; ///< on the line it crossed (clamped to the field)
  };
  std::optional<BallCrossing> ball_crossing(const BallTruth& ball) const;
  bool check_goal(const RefereeInput& in, RefereeDecision& d);
  void check_ball_out(const RefereeInput& in, RefereeDecision& d) const;
  /// `put` moved along x, `toward_x` (+1 or -1) first on a tie, the shortest way that keeps
  /// every robot's body centre rules_.ball_out_clearance_mm from it, within +-limit_x (the
  /// throw-in line's ends, or the goal lines for a set play's spot).
  void clear_of_robots(const RefereeInput& in, float toward_x, float limit_x, BallPlacement& put) const;
  void replace_ball_for_kickoff(const BallTruth& ball, RefereeDecision& d) const;
  /// Global Game Stuck: no touch, or no progress of the ball, for rules_.game_stuck_s.
  void check_game_stuck(const RefereeInput& in, RefereeDecision& d);

  // Set plays (referee_set_plays.cpp).
  void check_set_play_over(const RefereeInput& in, RefereeDecision& d);
  void award_ball_out(const RefereeInput& in, RefereeDecision& d);
  void award_foul(const RobotOnField& pusher, int64_t now, RefereeDecision& d);
  void start_set_play(SetPlay set_play, int team, int64_t at, RefereeDecision& d);
  void end_set_play(int64_t at, RefereeDecision& d);

  // Penalties and placements (referee_penalties.cpp, referee_positions.cpp).
  void release_served(int64_t now, const BallTruth& ball, Robots& robots, RefereeDecision& d);
  void release(RobotId id, const BallTruth& ball, Robots& robots, RefereeDecision& d);
  void penalise(RobotId id, PenaltyKind kind, int64_t now, RefereeDecision& d);
  void check_leaving_field(int64_t now, const Robots& robots, RefereeDecision& d);
  void check_illegal_defenders(int64_t now, const Robots& robots, RefereeDecision& d);
  void check_collisions(int64_t now, const BallTruth& ball, const Robots& robots, RefereeDecision& d);
  /// walking_into: the pusher of a kPushing verdict between a and b, 0 (a), 1 (b) or -1
  /// (no foul yet: in contact shorter than pushing_min_contact_s, or nobody walking in).
  int judge_walking_into(int64_t now, const RobotOnField& a, const RobotOnField& b, const CollisionVerdict& v,
                         const RefereeDecision& d) const;
  /// Appends each robot's pose to its track (velocity_of) and drops what the window no
  /// longer needs.
  void record_tracks(int64_t now, const Robots& robots);
  /// The robot's displacement from its oldest tracked pose within pushing_window_s (or the
  /// one just before it) to `body`, divided by the time between; zero without a track or
  /// when this update placed the robot (a placement is no walk).
  BodyVelocity velocity_of(const RobotOnField& r, int64_t now, const RefereeDecision& d) const;
  void place_for_kickoff(Robots& robots, RefereeDecision& d) const;
  Pose2D free_reentry_position(RobotId id, const BallTruth& ball, const Robots& robots) const;
  bool may_be_penalised(const RobotOnField& r) const;

  Field field_;
  RulesDef rules_;
  int team_size_;
  float ball_radius_mm_;

  bool started_ = false;
  GameState state_ = GameState::kInitial;
  bool first_half_ = true;
  int kickoff_team_ = 0;
  std::array<int, 2> score_{{0, 0}};
  bool first_kickoff_taken_ = false; ///< the match placed the first kick-off's ball; later ones are ours
  int64_t clock_utime_ = 0;          ///< the last update's utime
  int64_t state_since_utime_ = 0;
  int64_t played_us_ = 0;            ///< PLAYING time in this half
  SetPlay set_play_ = SetPlay::kNone;
  int set_play_team_ = -1;
  int64_t set_play_until_utime_ = 0;
  /// The last ball put back without a set play (GameInfo::drop_in_*): by whose touch, when.
  int drop_in_team_ = -1;
  int64_t drop_in_utime_ = -1;
  /// The stuck-game watch: when a robot last began touching the ball, and where the ball
  /// was when it last moved game_stuck_radius_mm (each restarted with PLAYING and set plays).
  int64_t last_ball_touch_utime_ = 0;
  float progress_x_mm_ = 0, progress_y_mm_ = 0;
  int64_t progress_utime_ = 0;

  std::map<RobotId, Penalty> penalties_;
  /// Last pushing penalty of each pair of opponents, (lower id, higher id): the cooldown.
  std::map<std::pair<RobotId, RobotId>, int64_t> last_push_utime_;
  /// When each pair of opponents now within contact distance came into contact, (lower id,
  /// higher id); a pair no longer in contact is dropped.
  std::map<std::pair<RobotId, RobotId>, int64_t> contact_since_utime_;
  /// Each robot's poses as the referee saw them, (utime, body), oldest first, covering
  /// pushing_window_s: its body velocity. Cleared when the referee places the robot.
  std::map<RobotId, std::deque<std::pair<int64_t, Pose2D>>> tracks_;
};

} // namespace touchline::sim
