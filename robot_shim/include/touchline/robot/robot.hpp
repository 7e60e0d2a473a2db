#pragma once
// One robot, as the robot's own process runs it: per camera frame the adapters write the
// Blackboard, the behaviour ticks (30 Hz perception), then the frame's 100 Hz motion
// ticks run and their foot motions become the answer to the world. No transport here:
// robot_shim carries frames over LCM, the in-process runner calls step() directly.
#include <memory>
#include <string>

#include "touchline/frame.hpp"
#include "touchline/robot/adapters.hpp"
#include "touchline/robot/localisation_adapter.hpp"
#include "touchline/robot/motion_adapter.hpp"
#include "touchline/robot/robot_def.hpp"
#include "touchline/robot_api/behaviour.hpp"

namespace touchline::robot {

/// The transport's bound on one team message; the league's (config [comm], default 128
/// bytes) is enforced by the world, which refuses what exceeds it.
constexpr size_t kMaxTeamMessageBytes = 4096;

/// Camera frames a behaviour tick of `cpu_us` occupies: ceil(cpu_us / 33.3 ms), at
/// least 1. 33.3 ms -> 1 (no frame missed), 33.4 ms -> 2, 70 ms -> 3.
int64_t behaviour_frames_used(int64_t cpu_us);

/// What the behaviour has cost so far (CPU times in microseconds).
struct BehaviourStats {
  int64_t ticks = 0;              ///< behaviour ticks run
  int64_t skipped_frames = 0;     ///< frames the behaviour missed by overrunning (charge_cpu)
  int64_t last_cpu_us = 0;        ///< the last tick's
  int64_t max_cpu_us = 0;
  int64_t total_cpu_us = 0;
  bool ticked_last_step = false;  ///< whether the last step() ran the behaviour
  double mean_cpu_us() const { return ticks ? static_cast<double>(total_cpu_us) / static_cast<double>(ticks) : 0.0; }
};

class Robot {
 public:
  /// The robot `def` describes, running `behaviour` (made by the caller from
  /// def.behaviour, which names it on the Blackboard). std::invalid_argument for none.
  Robot(RobotDef def, std::unique_ptr<api::Behaviour> behaviour);

  /// Runs one camera frame. `sense` is this robot's entry of `frame`.
  RobotAct step(const SenseFrame& frame, const RobotSense& sense);

  RobotId id() const { return def_.id; }
  const RobotDef& def() const { return def_; }
  const api::Blackboard& blackboard() const { return blackboard_; }
  const MotionAdapter& motion() const { return motion_; }
  /// CPU time of the last behaviour tick, microseconds (thread CPU clock).
  int64_t behaviour_cpu_us() const { return behaviour_adapter_.last_cpu_us(); }
  const BehaviourStats& behaviour_stats() const { return stats_; }

  /// Keep a copy of the Blackboard as the behaviour saw it (adapters written, request
  /// returned, before the frame's motion ticks), for snapshots. Off by default: it copies.
  void keep_behaviour_view(bool keep) { keep_behaviour_view_ = keep; }
  /// That copy, as of the last frame the behaviour ran.
  const api::Blackboard& behaviour_view() const { return behaviour_view_; }

 private:
  /// Whether the behaviour runs this frame (false while charged CPU time is being paid).
  bool behaviour_due(int64_t frame) const;
  void run_behaviour(int64_t frame);

  RobotDef def_;
  std::unique_ptr<api::Behaviour> behaviour_;
  api::Blackboard blackboard_;
  BehaviourAdapter behaviour_adapter_;
  MotionAdapter motion_;
  LocalisationAdapter localisation_;
  BehaviourStats stats_;
  bool keep_behaviour_view_ = false;
  api::Blackboard behaviour_view_;
  int64_t last_behaviour_frame_ = -1;
  int64_t next_behaviour_frame_ = 0;
};

} // namespace touchline::robot
