#pragma once
// GaitFeet: the feet our own walk plans: the WalkCycle for STAND and WALK, the
// KickGenerator for KICK and DRIBBLE, the DiveGenerator for GOALIE_DIVE_LEFT/RIGHT (other
// actions stand until their generators land). A kick or a dive latches: once started it
// runs to completion whatever the request says meanwhile; such a request seen after it
// completes starts another. Reads: the body command. Writes: both feet, the odometry, the
// status (active command, kick phase, standing: false through a dive).
#include "touchline/robot/dive_generator.hpp"
#include "touchline/robot/kick_generator.hpp"
#include "touchline/robot/walk_cycle.hpp"
#include "touchline/robot/walk_engine.hpp"
#include "touchline/robot_api/action_command.hpp"

namespace touchline::robot {

class GaitFeet {
 public:
  GaitFeet(const WalkDef& walk, const KickDef& kick, const DiveDef& dive = {});

  /// One tick of dt_s seconds (the kick counts 10 ms ticks whatever dt_s is).
  void tick(const api::ActionCommand::Body& request, float dt_s);

  /// The referee put the robot down: standing, feet square around the body, no kick or
  /// dive running (the world placed its feet so).
  void placed();

  /// Both feet after the last tick (the walk's, or the kick's mid-swing).
  const FeetPose& feet() const { return feet_; }
  Pose2D odometry() const { return dive_.running() ? dive_.odometry() : walk_.odometry(); }
  const WalkEngineStatus& status() const { return status_; }
  const WalkCycle& walk() const { return walk_; }
  const KickGenerator& kick() const { return kick_; }
  const DiveGenerator& dive() const { return dive_; }

 private:
  WalkCycle walk_;
  KickGenerator kick_;
  DiveGenerator dive_;
  FeetPose feet_;
  WalkEngineStatus status_;
};

/// The walk request a body command makes: WALK's forward/left/turn scaled by speed, zero
/// for anything else.
WalkRequest walk_request(const api::ActionCommand::Body& body);

} // namespace touchline::robot
