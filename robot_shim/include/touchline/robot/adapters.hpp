#pragma once
// The adapters that write the Blackboard from what the robot senses, one per
// sub-blackboard, each saying what it reads and what it writes. Behaviour never writes.
#include <cstdint>
#include <functional>

#include "touchline/frame.hpp"
#include "touchline/robot_api/behaviour.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::robot {

/// Reads: the frame's game info, whether we are penalised. Writes:
/// blackboard.gameController, blackboard.utime.
void write_game_controller(const SenseFrame& frame, const RobotSense& sense, api::Blackboard& blackboard);

/// Reads: the camera's observations this frame. Writes: blackboard.vision (the nearest
/// ball seen, if any; the goal posts, numbered in our own frame, and the robots seen).
void write_vision(const SenseFrame& frame, const RobotSense& sense, api::Blackboard& blackboard);

/// Reads: whether the robot lies on the ground, the sonars, the touch sensors. Writes:
/// blackboard.motion.fallen, sonarLeft, sonarRight, touchFrontLeft, touchFrontRight,
/// touchLeft, touchRight, touchBack.
void write_fall(const RobotSense& sense, api::Blackboard& blackboard);

/// Reads: teammates' messages arriving this frame. Writes: blackboard.receiver (the
/// latest message from each teammate, by player number).
void write_receiver(const RobotSense& sense, api::Blackboard& blackboard);

/// A CPU clock in microseconds.
using CpuClock = std::function<int64_t()>;

/// CPU time this thread has used, microseconds (CLOCK_THREAD_CPUTIME_ID).
int64_t thread_cpu_us();

/// Runs the behaviour once and measures its CPU time with `clock` (this thread's CPU
/// clock unless a test injects one). Reads: the whole Blackboard (const). Writes:
/// blackboard.behaviour.
class BehaviourAdapter {
 public:
  explicit BehaviourAdapter(api::Behaviour& behaviour, CpuClock clock = thread_cpu_us)
      : behaviour_(behaviour), clock_(clock ? std::move(clock) : CpuClock(thread_cpu_us)) {}
  void tick(api::Blackboard& blackboard);
  int64_t last_cpu_us() const { return last_cpu_us_; }

 private:
  api::Behaviour& behaviour_;
  CpuClock clock_;
  int64_t last_cpu_us_ = 0;
};

} // namespace touchline::robot
