#pragma once
// A tile-coded action-value function over the robot-relative target, and the Sarsa(lambda)
// learner that trains it by walking the robot in a SingleRobotSim (Sutton & Barto, 2nd ed.,
// section 12.7: binary features, replacing traces). Reward -1 per camera frame, so -Q is
// the frames still to go. The greedy policy is what the behaviours deploy from the file.
#include <cstdint>
#include <random>
#include <vector>

#include "touchline/learning/single_robot_sim.hpp"
#include "touchline/learning/tile_coding.hpp"

namespace touchline::learning {

/// One discrete action: a walk command in robot API units.
struct WalkAction {
  float forward_mm_s = 0; ///< + forward
  float left_mm_s = 0;    ///< + left
  float turn_rad_s = 0;   ///< + counter-clockwise
};

/// What an episode is.
struct EpisodeDef {
  double success_distance_mm = 50;        ///< reached within this distance ...
  double success_heading_rad = 0.174533;  ///< ... and this heading error (10 degrees)
  int max_frames = 1200;                  ///< then truncated (40 s)
};

struct EpisodeResult {
  int frames = 0;        ///< camera frames walked
  bool success = false;  ///< reached the pose (else truncated)
};

class TileQ {
 public:
  /// std::invalid_argument for no actions.
  TileQ(const TileCodingDef& coding, std::vector<WalkAction> actions);

  const TileCoding& coding() const { return coding_; }
  const std::vector<WalkAction>& actions() const { return actions_; }
  int action_count() const { return static_cast<int>(actions_.size()); }
  std::vector<float>& weights() { return weights_; }
  const std::vector<float>& weights() const { return weights_; }

  /// Q for the active cells (double sum over the tilings, in order).
  double value(const std::vector<int>& cells, int action) const;
  /// argmax over the actions, ties to the lowest index (as the deployed skill).
  int greedy(double x_mm, double y_mm, double heading_rad) const;
  int greedy(const std::vector<int>& cells) const;

 private:
  TileCoding coding_;
  std::vector<WalkAction> actions_;
  std::vector<float> weights_; ///< cell * actions + action
};

struct SarsaLambdaDef {
  double alpha = 0.1;          ///< step size per update, split evenly among the tilings
  double lambda = 0.9;         ///< trace decay
  double gamma = 1.0;          ///< discount (episodic, undiscounted as the thesis's)
  double trace_cutoff = 0.01;  ///< traces below this are dropped (bounds the work per step)
  /// Potential-based shaping (Ng, Harada, Russell 1999; the optimal policy is unchanged):
  /// the potential is minus the lower bound on the frames still to go,
  /// 30 sqrt((d / forward)^2 + (heading / turn)^2), and 0 at the pose. Learning then starts
  /// from "the lower bound is reachable" instead of from nothing. Speeds <= 0: no shaping.
  double shaping_forward_mm_s = 300;  ///< the walk's forward limit
  double shaping_turn_rad_s = 1.5;    ///< the walk's turn limit
};

class SarsaLambda {
 public:
  SarsaLambda(TileQ& q, const SarsaLambdaDef& def, uint64_t seed);
  /// One learning episode from `start` to `target` (field frame) with epsilon-greedy
  /// exploration (random tie-breaks); `sim_seed` seeds the world.
  EpisodeResult episode(SingleRobotSim& sim, const Pose2D& start, const Pose2D& target, double epsilon,
                        const EpisodeDef& episode, uint64_t sim_seed);
  /// A new step size from now on (schedules).
  void set_alpha(double alpha) { def_.alpha = alpha; }

 private:
  int choose(const std::vector<int>& cells, double epsilon);
  void decay_traces(double factor);

  TileQ& q_;
  SarsaLambdaDef def_;
  std::mt19937_64 rng_;
  std::vector<float> trace_;       ///< per weight
  std::vector<int> traced_;        ///< weights with a trace
};

/// The greedy policy's episode, nothing learned (evaluation).
EpisodeResult greedy_episode(const TileQ& q, SingleRobotSim& sim, const Pose2D& start, const Pose2D& target,
                             const EpisodeDef& episode, uint64_t sim_seed);

/// The target as the robot at `pose` sees it: x forward, y left, heading error in [-pi, pi).
Pose2D relative_target(const Pose2D& pose, const Pose2D& target);
/// Whether `relative` is within the episode's tolerances.
bool reached(const Pose2D& relative, const EpisodeDef& episode);

} // namespace touchline::learning
