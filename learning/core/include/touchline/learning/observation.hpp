#pragma once
// A learner's observation: a fixed-size float vector of what one robot's own code believes,
// read from its Blackboard after a frame (its pose and ball estimates, what its motion is
// doing, the game as its GameController adapter wrote it, its teammates as their pose
// messages told it, the robots its camera saw). Never the truth: a robot that is lost is
// lost here too. Positions in the robot's team frame (own goal at -x, field centre 0, mm),
// angles in rad. Elements, in order (observation_names() gives each one's name):
//
//   0  self_x_mm, 1 self_y_mm, 2 self_theta_rad   localisation.robotPos
//   3  ball_x_mm, 4 ball_y_mm                     localisation.ballPos
//   5  ball_rel_x_mm, 6 ball_rel_y_mm             localisation.ballPosRR (x forward, y left)
//   7  ball_vx_mm_s, 8 ball_vy_mm_s               localisation.ballVel
//   9  ball_lost_s                                frames since the ball was seen / 30, at most kMaxAge_s
//  10  walk_forward_mm_s, 11 walk_left_mm_s, 12 walk_turn_rad_s   motion.active (what the walk runs)
//  13  head_yaw_rad, 14 standing, 15 fallen, 16 kicking (0/1)     motion
//  17..22 state_initial, _ready, _set, _playing, _finished, _standby   one-hot gameController.state
//  23  penalised (0/1), 24 our_score, 25 their_score, 26 secs_remaining (of the half),
//  27  first_half (0/1), 28 our_kickoff (0/1), 29 set_play_ours (0/1), 30 set_play_theirs (0/1)
//  then per teammate (team_size - 1 slots, by player number, self left out), 5 each:
//      mate<n>_x_mm, _y_mm, _theta_rad (its last pose message), _age_s (at most kMaxAge_s), _heard (0/1)
//  then kSeenRobotSlots slots, the robots the camera saw this frame nearest first, 4 each:
//      seen<k>_rel_x_mm, _rel_y_mm (robot-relative), _teammate (0/1), _present (0/1)
// Empty slots are zeros, with _age_s at kMaxAge_s.
#include <string>
#include <vector>

#include "touchline/robot_api/blackboard.hpp"

namespace touchline::learning {

constexpr int kSelfAndGameElements = 31;
constexpr int kTeammateElements = 5;
constexpr int kSeenRobotSlots = 4;
constexpr int kSeenRobotElements = 4;
constexpr float kMaxAge_s = 10.f; ///< ages and ball_lost_s stop here (never seen/heard: this)

int observation_size(int team_size);
std::vector<std::string> observation_names(int team_size);
/// Writes observation_size(team_size) floats of `blackboard` to `out`.
void observe(const api::Blackboard& blackboard, int team_size, float* out);

} // namespace touchline::learning
