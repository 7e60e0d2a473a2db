#pragma once
// The rules the referee plays by (SPL 2011, simplified; with set_plays and standby_s the
// later rule books' set plays and STANDBY), read from the [rules] section of a world config. Every duration is simulated time; every switch turns one rule off
// without touching the others (experiments that want, say, no pushing penalties).
#include <string>

#include "touchline/ini.hpp"
#include "touchline/sim/collision.hpp"

namespace touchline::sim {

struct RulesDef {
  bool referee = true;     ///< play by these rules; false: no referee, the game stays PLAYING (calibration runs)

  // --- game states and the clock ---
  float initial_s = 1.f;   ///< INITIAL at the start of each half before READY, s (0: READY at once)
  float standby_s = 0.f;   ///< STANDBY between INITIAL and READY (SPL 2023 on: robots wait for the referee's signal), s (0: none)
  float ready_s = 45.f;    ///< READY: robots walk to their kick-off positions, s (SPL: 45)
  float set_s = 5.f;       ///< SET: robots stand still until the kick-off whistle, s
  float half_s = 600.f;    ///< playing time of one half, s; the clock runs only in PLAYING
  int first_kickoff_team = 0; ///< kicks off the first half (0 or 1); the other team kicks off the second

  // --- penalties ---
  float removal_s = 30.f;  ///< time a penalised robot spends off the field, s (SPL 2011: 30)
  bool pushing = true;           ///< penalise the pusher of an opponent (thesis figure 2.5)
  bool illegal_defender = true;  ///< penalise a field player in its own goal box while PLAYING
  bool leaving_field = true;     ///< penalise a robot whose body is off the field (READY, SET, PLAYING)
  CollisionDef collision;        ///< contact and contest distances of the pushing heuristic
  float pushing_cooldown_s = 5.f; ///< after a pushing penalty, the same pair gives no other for this long, s
  /// Who is penalised for pushing. "thesis": the robot Algorithms 2.1 and 2.2 name from the
  /// two headings alone, at the first frame of contact, even if it stands still and the
  /// other walked into it. "walking_into" (SPL: the robot that walks into an opponent
  /// pushes it; one standing or backing away does not): of those two robots, the first
  /// that walks into the other (collision.hpp walking_pusher), once the contact has lasted
  /// pushing_min_contact_s; neither walking in is no foul.
  std::string pushing_model = "walking_into";
  /// walking_into: a body speed towards the other above this is walking into it, mm/s.
  /// 50: a sixth of the walk's top speed (300 mm/s), above what standing, stepping on the
  /// spot or turning moves the body over the window (in measured matches the robots' body
  /// speeds pile up under 30 mm/s, 39 % of all samples under 10), and below the median
  /// speed of a robot named pusher that did walk into the other (about 100 mm/s). 100
  /// instead changed the calls of a match by under a tenth.
  float pushing_speed_mm_s = 50.f;
  /// walking_into: the body velocity is its displacement over this long, s. 0.5: one full
  /// gait cycle (WalkCycle period_s), one step of each foot, so the step's phase cancels out.
  float pushing_window_s = 0.5f;
  /// walking_into: a contact must have lasted this long before it is a foul, s (0: at once).
  /// 1: a brush is no push; walking into an opponent for a second at 50 mm/s or more would
  /// have moved it 50 mm or more, enough to unbalance it. Measured over 5 seeded matches of
  /// cpp:Team v cpp:Striker (pushing per team per match, thesis: 30 v 39): 0 s gave 25 v 43
  /// (scrambles keep walking robots into each other), 0.5 s 19 v 34, 1 s 14 v 19, 2 s 14 v
  /// 15, 3 s 8 v 9; 1 s is the shortest that halves them without forgiving a second of
  /// walking into an opponent.
  float pushing_min_contact_s = 1.f;
  float leave_field_margin_mm = 200.f; ///< body centre this far past a line's outer edge has left, mm
                                       ///< (200: both feet are then wholly off the field)

  // --- placements ---
  bool manual_placement = true; ///< at SET, robots not in a legal kick-off position are put on theirs
  bool ball_out = true;         ///< put back a ball that left the field (else it stays where it is)
  float ball_out_setback_mm = 1000.f; ///< ball put back this far towards the last toucher's own goal, mm
  /// The throw-in line: SPL 2011 puts a ball out back on an imaginary line this far inside
  /// the touchline on the side it left, mm (0: on the touchline); set plays do not use it.
  /// 400 as Cyberbotics' Robotstadium supervisor (SPL 2008-2011) and B-Human's SimRobot
  /// (drop-in lines) have it; on the touchline itself, 21 of 84 balls put back a match went
  /// out again within 3 s (4 C++ matches), the first step at the ball pushing them over.
  float ball_out_inset_mm = 400.f;
  float throw_in_line_end_mm = 1000.f; ///< the throw-in lines end this far short of each goal line, mm
  /// A ball put back (or on a set play's spot) is moved along x until every robot's body
  /// centre is this far from it, mm (0: never moved). A referee puts the ball beside a robot,
  /// not into its feet; one put into a foot was knocked out again at once (4 C++ matches:
  /// 52 of 345 placements out again within 1 s). 200: a foot's toe reaches about 120 mm
  /// from the body centre, plus the ball's radius and a margin.
  float ball_out_clearance_mm = 200.f;

  // --- set plays (SPL 2020 on; off: the 2011 ball-out rule above) ---
  /// A ball out gives the opponents of its last toucher a kick-in (over a touchline), the
  /// defenders a goal kick or the attackers a corner kick (over a goal line); a pushing foul
  /// gives the fouled team a pushing free kick, or a penalty kick when the pusher was in its
  /// own penalty area.
  bool set_plays = false;
  float set_play_s = 30.f; ///< a set play ends when its team touches the ball, or after this long, s

  // --- a stuck game (SPL: Global Game Stuck) ---
  /// No robot began touching the ball, or the ball stayed within game_stuck_radius_mm of
  /// one spot, for this long of PLAYING (outside set plays): the game is stuck and restarts
  /// with a kick-off (READY) for the opponents of the team that touched the ball last
  /// (unknown: the team that did not take the last kick-off), s; 0: never.
  float game_stuck_s = 30.f;
  /// A ball wedged between robots that push on is stuck even while they touch it, mm.
  float game_stuck_radius_mm = 500.f;

  // --- falls (beyond the thesis) ---
  float fall_probability = 0.3f; ///< chance that the robot pushed in a pushing foul falls, [0, 1]
  float getup_s = 5.f;           ///< a fallen robot lies this long before it stands again, s
};

/// Binds every RulesDef field to "rules.<name>".
void bind(IniSchema& schema, RulesDef& def);

/// Checks ranges (durations >= 0, half_s > 0, first_kickoff_team 0 or 1, distances > 0 or
/// >= 0, pushing_model thesis or walking_into, pushing_window_s in (0, 10]). Throws
/// ConfigError naming the key, e.g. "rules.ready_s must be >= 0 (got -1)".
void validate(const RulesDef& def);

/// The simulated seconds a match under these rules lasts if nobody scores: two halves, each
/// INITIAL, STANDBY, READY, SET and its PLAYING time (the second half's INITIAL is the
/// half-time break). A tool's progress bar takes it as the match's length. Without a
/// referee the game never ends by itself: infinity (the world's duration_s ends it).
double planned_length_s(const RulesDef& def);

/// The simulated seconds each goal adds to planned_length_s: READY and SET again before the
/// kick-off (the clock stops outside PLAYING).
double goal_stoppage_s(const RulesDef& def);

} // namespace touchline::sim
