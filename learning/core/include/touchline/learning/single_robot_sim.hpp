#pragma once
// One robot alone on the field, for learning and skill evaluation: the in-process match
// (same World, Match, Robot, MotionAdapter and WalkCycle as a real match) with the referee
// off, so the game stays PLAYING and nothing but the robot's own walk moves it. A step is
// one camera frame (1/30 s: 3 or 4 motion ticks). The robot is driven either by a command
// set from outside (a learner's action) or by a C++ behaviour (the hand-coded skills, the
// deployed learned skill). Reads: a command or the behaviour's. Writes: nothing outside.
#include <cstdint>
#include <memory>
#include <optional>

#include "touchline/inprocess/inprocess_match.hpp"

namespace touchline::learning {

/// The learner's robot unless told otherwise: player 1 of team 0 with the built-in walk
/// and kick, its Blackboard pose the true pose (learning sees the truth).
robot::RobotDef default_learning_robot();

struct SingleRobotDef {
  sim::WorldConfig world;                        ///< field, physics, camera (the referee is switched off)
  robot::RobotDef robot = default_learning_robot(); ///< walk, kick, localisation (its field: world's); player 1
};

/// Where the ball goes when a reset names none: a field corner, out of a walking robot's way.
Pose2D default_ball_spot(const sim::FieldDef& field);

class SingleRobotSim {
 public:
  /// Throws ConfigError (touchline/ini.hpp) for a config validate() refuses.
  explicit SingleRobotSim(SingleRobotDef def);

  /// A new episode: a fresh match seeded with `seed` (camera noise), the robot standing at
  /// `pose` (field frame, mm, rad) with the walk at rest, the ball at `ball` (x, y; theta
  /// unused) or the default spot. The C++ behaviour `behaviour` names (behaviour_cpp's
  /// registry) drives the robot from now on; none: the command given to step() does.
  /// Throws behaviour::BehaviourError for an unknown behaviour or a bad parameter.
  void reset(uint64_t seed, const Pose2D& pose, std::optional<Pose2D> ball = std::nullopt,
             std::optional<robot::BehaviourDef> behaviour = std::nullopt);

  /// One camera frame with the robot executing `body` (robot API units: mm/s, rad/s).
  /// std::logic_error if a behaviour drives the robot or reset() was never called.
  void step(const api::ActionCommand::Body& body);
  /// One camera frame with the behaviour given to reset() deciding.
  void step_behaviour();

  Pose2D pose() const;                        ///< the robot's true body pose, field frame
  sim::BallTruth ball() const;
  const robot::WalkRequest& walk_velocity() const; ///< what the walk executes now (after its limits)
  const api::Blackboard& blackboard() const;  ///< as the behaviour saw it last
  int64_t frame() const;                      ///< frames stepped since reset
  double time_s() const;                      ///< simulated seconds since reset
  uint64_t state_hash() const;                ///< the world's (bit-identical worlds, equal hashes)
  const SingleRobotDef& def() const { return def_; }

 private:
  class Commanded;
  inprocess::InProcessMatch& match() const;

  SingleRobotDef def_;
  std::unique_ptr<inprocess::InProcessMatch> match_;
  Commanded* commanded_ = nullptr; ///< owned by the robot; null when a behaviour drives
  int64_t start_frame_ = 0;
};

} // namespace touchline::learning
