#pragma once
// A match without transport: the world, the roster of robots and the camera-frame clock.
// Each frame the match hands out a SenseFrame, takes the robots' RobotActs and steps the
// world through the frame's 3-4 motion ticks. sim_world drives it over LCM; tests and the
// in-process mode call it directly.
#include <cstdint>
#include <deque>
#include <map>
#include <vector>

#include "touchline/frame.hpp"
#include "touchline/sim/config.hpp"
#include "touchline/sim/roster.hpp"
#include "touchline/sim/world.hpp"

namespace touchline::sim {

/// Ground truth at the end of a frame.
struct TruthFrame {
  int64_t utime = 0; ///< simulated time at the end of the frame, microseconds
  int64_t frame = 0; ///< the frame just completed
  BallTruth ball;
  struct Robot {
    RobotTruth truth;
    bool active = true;
    float head_yaw_rad = 0, head_pitch_rad = 0;
  };
  std::vector<Robot> robots; ///< sorted by (team, player)
};

enum class ActOutcome {
  kApplied,  ///< taken for this frame
  kRejoined, ///< taken, and the robot is active again after a timeout
  kStale,    ///< for an earlier frame in lockstep (or a later one): ignored
  kUnknown,  ///< from a robot or instance that has not joined: ignored
};

class Match {
 public:
  explicit Match(const WorldConfig& config);

  /// A shim asks to play `id`. Before start() accepted robots wait off the field; after
  /// it, a new robot is placed at its initial pose at once.
  JoinReply join(RobotId id, int64_t instance, int pid);
  /// Puts every joined robot on the field in (team, player) order (deterministic
  /// whatever order they joined in) and the ball on the centre spot.
  void start();
  bool started() const { return started_; }

  /// What the robots sense at the start of the current frame.
  SenseFrame sense() const;
  /// Robots that must answer the current frame.
  std::vector<RobotId> active_robots() const;

  /// Takes a robot's answer. `accept_late`: free-running mode, where an answer for an
  /// earlier frame still moves the robot, late.
  ActOutcome apply(const RobotAct& act, int64_t instance, bool accept_late = false);
  /// The robot did not answer in time: it stands still and is inactive until it answers.
  void time_out(RobotId id);

  /// Steps the world through the current frame's motion ticks; the next frame begins.
  void advance();
  TruthFrame truth() const;

  bool finished() const;
  int64_t frame() const { return frame_; }
  int64_t utime() const { return frame_start_utime(frame_); }
  const Roster& roster() const { return roster_; }
  const World& world() const { return world_; }
  World& world() { return world_; }
  const WorldConfig& config() const { return config_; }

 private:
  struct OnField {
    int world_index = 0;
    float head_yaw_rad = 0, head_pitch_rad = 0;
    std::deque<TickMotion> pending; ///< motions not yet stepped, oldest first
  };
  void place(RobotId id);

  WorldConfig config_;
  World world_;
  Roster roster_;
  std::map<RobotId, OnField> on_field_;
  int64_t frame_ = 0;
  bool started_ = false;
};

} // namespace touchline::sim
