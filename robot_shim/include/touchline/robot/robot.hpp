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
#include "touchline/robot_api/behaviour.hpp"

namespace touchline::robot {

/// How the robot runs its behaviour.
struct BehaviourTimingDef {
  /// Charge the behaviour's CPU time to simulated time, as on the robot, where a
  /// behaviour that overruns its 33.3 ms frame misses camera frames: after a tick that
  /// used `cpu` microseconds the behaviour next runs behaviour_frames_used(cpu) frames
  /// later. The previous request stays in force meanwhile; motion ticks every frame.
  bool charge_cpu = false;
  /// The clock a tick is measured with, microseconds: this thread's CPU time (tests
  /// inject their own).
  CpuClock cpu_clock = thread_cpu_us;
};

/// The transport's bound on one team message; the league's (config [comm], default 128
/// bytes) is enforced by the world, which refuses what exceeds it.
constexpr size_t kMaxTeamMessageBytes = 4096;

/// Where the robot's beliefs about its pose and the ball come from.
struct LocalisationModeDef {
  localisation::LocalisationDef filters; ///< the field the robot knows, the filters' noise models
  bool perfect = false;                  ///< the robot's pose from the truth (the ball still from the camera)
};

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
  Robot(RobotId id, const WalkDef& walk, std::unique_ptr<api::Behaviour> behaviour,
        BehaviourTimingDef timing = {}, const KickDef& kick = {}, const LocalisationModeDef& localisation = {});

  /// Runs one camera frame. `sense` is this robot's entry of `frame`.
  RobotAct step(const SenseFrame& frame, const RobotSense& sense);

  RobotId id() const { return id_; }
  const api::Blackboard& blackboard() const { return blackboard_; }
  const MotionAdapter& motion() const { return motion_; }
  /// CPU time of the last behaviour tick, microseconds (thread CPU clock).
  int64_t behaviour_cpu_us() const { return behaviour_adapter_.last_cpu_us(); }
  const BehaviourStats& behaviour_stats() const { return stats_; }

  /// What behaviour.skill on the Blackboard says is running (e.g. "py skill=GoToBall").
  void set_behaviour_name(std::string name) { blackboard_.behaviour.skill = std::move(name); }

  /// Keep a copy of the Blackboard as the behaviour saw it (adapters written, request
  /// returned, before the frame's motion ticks), for snapshots. Off by default: it copies.
  void keep_behaviour_view(bool keep) { keep_behaviour_view_ = keep; }
  /// That copy, as of the last frame the behaviour ran.
  const api::Blackboard& behaviour_view() const { return behaviour_view_; }

 private:
  /// Whether the behaviour runs this frame (false while charged CPU time is being paid).
  bool behaviour_due(int64_t frame) const;
  void run_behaviour(int64_t frame);

  RobotId id_;
  std::unique_ptr<api::Behaviour> behaviour_;
  api::Blackboard blackboard_;
  bool charge_cpu_;
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
