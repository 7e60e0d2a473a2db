#pragma once
// MotionAdapter: the 100 Hz motion thread of the robot. Each tick it reads the behaviour's
// request from the Blackboard, runs the generator chain (head, then walk for STAND and
// WALK, the KickGenerator for KICK and DRIBBLE; other actions stand until their
// generators land) and hands the feet to the effector. A kick latches: once started it
// runs to completion whatever the request says meanwhile; a KICK or DRIBBLE request seen
// after it completes starts another. Reads: blackboard.behaviour.request. Writes:
// blackboard.motion (active: the latched kick while one runs; kickPhase), the effector.
#include "touchline/frame.hpp"
#include "touchline/robot/head_def.hpp"
#include "touchline/robot/kick_generator.hpp"
#include "touchline/robot/walk_cycle.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::robot {

class MotionAdapter {
 public:
  MotionAdapter(const WalkDef& walk, const HeadDef& head = {}, const KickDef& kick = {});

  /// One 10 ms motion tick: how the feet move, for the world (frame.hpp).
  TickMotion tick(api::Blackboard& blackboard);

  const WalkCycle& walk() const { return walk_; }
  const KickGenerator& kick() const { return kick_; }
  float head_yaw() const { return yaw_; }
  float head_pitch() const { return pitch_; }

 private:
  void tick_head(const api::ActionCommand::Head& request);
  WalkRequest walk_request(const api::ActionCommand::Body& body) const;

  WalkCycle walk_;
  KickGenerator kick_;
  FeetPose feet_; ///< both feet after the last tick (the walk's, or the kick's mid-swing)
  HeadDef head_;
  float yaw_ = 0, pitch_ = 0;
};

} // namespace touchline::robot
