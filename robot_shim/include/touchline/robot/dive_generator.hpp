#pragma once
// DiveGenerator: the goalie dive (GOALIE_DIVE_LEFT / GOALIE_DIVE_RIGHT) in a world where a
// robot is two feet (thesis chapter 2). A falling Nao covers the ground with its body; here
// both feet slide sideways together (in the body frame at the dive's start) by reach_mm
// over fall_s, squaring up side by side as they go, so the feet lie where the body would
// block. The robot then lies still (the feet do not move, every request is ignored) until
// duration_s after the start, and stands again where it landed: the walk resumes from
// there. Like a kick, a dive latches: once started it runs to completion. Reads: the
// latched Body request and the walk's feet. Writes: feet poses, the walk's standing pose
// at the landing.
#include "touchline/frame.hpp"
#include "touchline/robot/walk_cycle.hpp"
#include "touchline/robot_api/action_command.hpp"

namespace touchline::robot {

/// The dive's figures. A Nao V6 is about 570 mm tall, so a sideways fall covers about its
/// body length; rUNSWift's dive key-frame files (goalieDive{Left,Right}.pos in their 2022
/// release) reach the dive pose in one 400 ms key frame, then hold the floor for 2000 ms.
struct DiveDef {
  float reach_mm = 500.f;  ///< sideways travel of both feet (and so the body), mm
  float fall_s = 0.4f;     ///< time to go down, s (at least one tick)
  float duration_s = 2.4f; ///< from the start to standing again (fall plus lying still), s
};

/// True for GOALIE_DIVE_LEFT and GOALIE_DIVE_RIGHT.
bool is_dive(api::ActionCommand::ActionType type);

class DiveGenerator {
 public:
  explicit DiveGenerator(const DiveDef& def = {});

  /// Latches `body` (a dive: its side) and starts falling on the next tick. A running dive,
  /// or any other action type, is ignored.
  void start(const api::ActionCommand::Body& body);
  bool running() const { return running_; }
  /// Stops the dive at once (the robot was picked up): not running from now on.
  void cancel() { running_ = false; }

  /// One 10 ms tick of the running dive; `walk` is the walk it interrupts, left as it was
  /// until the landing, then standing square around the landed body pose. Returns both
  /// feet after the tick, in the walk's odometry frame. When duration_s is over the dive
  /// stops running and the feet are the walk's.
  FeetPose tick(WalkCycle& walk);

  /// The body pose after the last tick (midpoint of the feet while falling), odometry frame.
  const Pose2D& odometry() const { return odometry_; }
  /// Whether the last tick was in the fall (false once lying).
  bool falling() const { return running_ && ticks_ < fall_ticks(); }
  /// Ticks run since the start.
  int ticks() const { return ticks_; }
  int fall_ticks() const;
  int total_ticks() const;
  const api::ActionCommand::Body& request() const { return request_; }
  const DiveDef& def() const { return def_; }

 private:
  DiveDef def_;
  api::ActionCommand::Body request_;
  bool running_ = false;
  int ticks_ = 0;
  FeetPose start_feet_, landed_feet_;
  Pose2D start_body_, landed_body_, odometry_;
};

} // namespace touchline::robot
