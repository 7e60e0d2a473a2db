#pragma once
// The in-process mode: the world and the robots linked into one process, no transport.
// Same Match, same Robot, same frames as sim_world + robot_shim over LCM, so a run here
// is the lockstep run without the round trips (tests, learning, quick experiments).
#include <memory>
#include <vector>

#include "touchline/robot/robot.hpp"
#include "touchline/sim/match.hpp"

namespace touchline::inprocess {

class InProcessMatch {
 public:
  explicit InProcessMatch(const sim::WorldConfig& config, uint64_t seed = 1) : match_(config, seed) {}

  /// Adds the robot `def` describes (def.id its team and number), running `behaviour`
  /// (made by the caller from def.behaviour), before start(). The robot knows the field it
  /// plays on: its localisation's map is this match's [field], whatever def says, as the
  /// launcher gives every robot_shim the world's config as --field-config. Throws
  /// std::invalid_argument if the roster refuses it.
  robot::Robot& add_robot(robot::RobotDef def, std::unique_ptr<api::Behaviour> behaviour);
  void start() { match_.start(); }
  /// One camera frame: every robot senses, answers, and the world steps.
  void step_frame();
  /// Frames until the match's duration is over.
  void run_to_end();

  /// Wall seconds step_frame spent in the world (sensing, taking the answers, stepping),
  /// not in the robots: the fastest this match could run if robot code cost nothing.
  double world_wall_s() const { return static_cast<double>(world_ns_) * 1e-9; }

  /// The robots' answers in the last frame, in the order they were added (what robot_shims
  /// send on TL_ACT_<team>_<player>: touchline_match logs them so a log is the same shape).
  const std::vector<RobotAct>& acts() const { return acts_; }

  sim::Match& match() { return match_; }
  const sim::Match& match() const { return match_; }
  robot::Robot& robot(RobotId id);
  const robot::Robot& robot(RobotId id) const;

 private:
  sim::Match match_;
  std::vector<std::unique_ptr<robot::Robot>> robots_;
  std::vector<RobotAct> acts_;
  int64_t world_ns_ = 0;
};

} // namespace touchline::inprocess
