#pragma once
// Lockstep bookkeeping for one camera frame, with wall time passed in (no clock, no
// transport, so tests drive it directly): which active robots must answer, which did, and
// who is late once the deadline passes.
#include <cstdint>
#include <set>
#include <vector>

#include "touchline/frame.hpp"

namespace touchline::sim {

class FrameBarrier {
 public:
  /// Starts frame `frame`: every robot in `expected` must answer by now_us + timeout_us.
  void begin(int64_t frame, const std::vector<RobotId>& expected, int64_t now_us, int64_t timeout_us);

  /// Records an answer; returns false (and ignores it) when it is not for this frame.
  bool answer(RobotId id, int64_t frame);

  /// Stops waiting for `id` (its answer to this frame no longer counts as awaited).
  void give_up(RobotId id);
  /// Moves the deadline to `deadline_us`: past the first one, the robots still missing are
  /// waited for longer (the world's lockstep waits for a robot whose process still runs).
  void wait_until(int64_t deadline_us);

  /// True when all expected robots answered, or the deadline has passed.
  bool complete(int64_t now_us) const;
  /// Expected robots that have not answered.
  std::vector<RobotId> missing() const;
  /// Microseconds until the deadline (0 when past).
  int64_t remaining_us(int64_t now_us) const;
  int64_t frame() const { return frame_; }

 private:
  int64_t frame_ = -1;
  int64_t deadline_us_ = 0;
  std::set<RobotId> waiting_;
};

} // namespace touchline::sim
