#pragma once
// A whole refereed match for multi-agent learning: the in-process match (same World,
// Match, referee, Robot, MotionAdapter, walk, kick and localisation as a real match) with
// every robot driven from outside. A step is one camera frame (1/30 s). Before a step the
// learner sets each robot's action, which its behaviour returns as its request that frame;
// after it, each robot's Blackboard (what its own code believes) is its observation
// (observation.hpp): what it sensed at the start of the frame (so the game state is the one
// the frame began in, a frame behind the referee's, as on a real robot) and its motion after. The referee's states are the world's to enforce, as in any match: a
// robot in INITIAL, SET or FINISHED, penalised or fallen does not move, whatever it asks.
// Each robot also tells its teammates its pose estimate by team message (pose_message.hpp)
// as often as the league's radio allows. Reads: the actions. Writes: nothing outside.
#include <cstdint>
#include <memory>
#include <vector>

#include "touchline/inprocess/inprocess_match.hpp"

namespace touchline::learning {

struct MultiRobotDef {
  sim::WorldConfig world;  ///< field, physics, camera, radio, rules (the referee plays unless rules.referee = false)
  robot::RobotDef robot;   ///< every robot's walk, kick, head and localisation (id and behaviour set per robot)
};

/// One robot's request for a frame, in robot API units.
struct AgentAction {
  float forward_mm_s = 0; ///< walk, + forward (the walk applies its limits)
  float left_mm_s = 0;    ///< walk, + left
  float turn_rad_s = 0;   ///< walk, + counter-clockwise
  float kick_power = 0;   ///< (0, 1]: kick at this power instead of walking (the foot on the ball's side); 0: walk
  float head_yaw_rad = 0; ///< where the camera looks, + left (the head applies its limits)
};

class MultiRobotSim {
 public:
  /// Throws ConfigError (touchline/ini.hpp) for a config validate() refuses.
  explicit MultiRobotSim(MultiRobotDef def);

  /// A new match seeded with `seed` (camera noise, radio losses, falls): team 0's players
  /// 1..team_size then team 1's, at their initial poses, every action "stand". It runs the
  /// match's first frame (every robot standing), so each robot's Blackboard is written and
  /// there is a first observation; frame() counts from there.
  void reset(uint64_t seed);
  /// The robots in (team, player) order: the index every other call takes.
  const std::vector<RobotId>& robots() const { return ids_; }
  /// The request robot `index` makes from the next step on (until set again).
  void set_action(size_t index, const AgentAction& action);
  /// One camera frame. std::logic_error before reset().
  void step();

  int observation_size() const;
  /// Robot `index`'s observation (observation.hpp) to `out` (observation_size() floats).
  void observe(size_t index, float* out) const;
  const api::Blackboard& blackboard(size_t index) const;

  GameInfo game() const { return match().match().game(); }
  /// The referee ended the match (FINISHED after the second half).
  bool game_over() const { return game().state == GameState::kFinished; }
  /// The match's duration_s ran out before the referee ended it.
  bool out_of_time() const { return match().match().finished() && !game_over(); }
  sim::TruthFrame truth() const { return match().match().truth(); }
  int64_t frame() const;    ///< frames stepped since reset
  uint64_t state_hash() const { return match().match().world().state_hash(); }
  const MultiRobotDef& def() const { return def_; }

 private:
  class Commanded;
  const inprocess::InProcessMatch& match() const;

  MultiRobotDef def_;
  std::unique_ptr<inprocess::InProcessMatch> match_;
  std::vector<RobotId> ids_;
  std::vector<Commanded*> drivers_; ///< owned by the robots
  int64_t start_frame_ = 0;
};

} // namespace touchline::learning
