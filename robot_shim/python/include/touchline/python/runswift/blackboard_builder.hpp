#pragma once
// Their Blackboard, built each frame from Touchline's (what the robot's adapters wrote):
// - stateEstimation: localisation's pose and ball, their uncertainties (the covariances'
//   ellipse-sigma products, as their filters report them), ball velocity (field and robot
//   frame), obstacles from the robots seen. The team ball is the most recent sighting, our
//   own or a teammate's broadcast one (hadTeamBallUpdate: a teammate's arrived this frame).
// - vision: timestamp (simulated us), the ball seen (BallInfo), robots and goal posts seen.
// - motion: head joint angles, sonars (m), fallen (as a body angle), isStiff.
// - gameController: state, first half, kicking team, score, time, our penalty
//   (PENALTY_MANUAL: the kind is not sensed); set play NONE, game phase NORMAL.
// - receiver: teammates' decoded broadcasts (team_message.hpp) by player number, our own
//   in our slot (as a robot hears itself), incapacitated = not heard for
//   `incapacitated_after_us`, or penalised.
// - behaviour: skill, head skill, positioning names; the shared data of our last request.
// What it cannot know gets the robot's defaults (docs/runswift_behaviour.md lists them).
#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "touchline/python/runswift/team_message.hpp"
#include "touchline/python/runswift/types.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::python::runswift {

struct BlackboardBuilderDef {
  std::string skill = "Game";                                  ///< their default body skill
  std::string headskill = "HeadCentre";                        ///< their default head skill
  std::string positioning = "PositioningAgainstKickingTeam";   ///< their default positioning
  int players_per_team = 5;                                    ///< RoboCupGameControlData.playersPerTeam
  std::array<int, 2> team_numbers{{1, 2}};                     ///< GameController team numbers of team 0, 1
  int64_t incapacitated_after_us = 5000000;                    ///< a teammate unheard this long is incapacitated
  float obstacle_radius_mm = 250.f;                            ///< a robot's radius for the obstacle's tangents
};

class BlackboardBuilder {
 public:
  explicit BlackboardBuilder(BlackboardBuilderDef def = {}) : def_(std::move(def)) {}

  /// Their Blackboard for this frame.
  Blackboard build(const api::Blackboard& touchline);
  /// What we broadcast this frame (also our own receiver slot): our beliefs and the
  /// shared data of our last request.
  Broadcast own_broadcast(const api::Blackboard& touchline) const;
  /// The behaviour's request this frame: its shared data is broadcast and shown next frame.
  void remember(const BehaviourRequest& request);

 private:
  BlackboardBuilderDef def_;
  BehaviourSharedData shared_;   ///< of the last request
  int last_action_ = NONE;       ///< of the last request
  /// The most recent ball sighting, ours or a teammate's (field frame, when seen).
  struct Sighting {
    float x = 0, y = 0;   ///< mm
    float vx = 0, vy = 0; ///< mm/s
    int64_t utime = -1;   ///< -1: none yet
  };
  Sighting team_ball_;
  std::array<int64_t, kRobotsPerTeam> heard_utime_{}; ///< each teammate's newest message already read
};

/// Product of the sigmas of the 2x2 covariance's ellipse axes (sqrt of its determinant), mm^2.
float ellipse_sigma_product(float xx, float xy, float yy);

} // namespace touchline::python::runswift
