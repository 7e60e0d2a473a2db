#include "touchline/sim/lockstep.hpp"

#include <algorithm>

namespace touchline::sim {

void FrameBarrier::begin(int64_t frame, const std::vector<RobotId>& expected, int64_t now_us,
                         int64_t timeout_us) {
  frame_ = frame;
  deadline_us_ = now_us + timeout_us;
  waiting_ = std::set<RobotId>(expected.begin(), expected.end());
}

bool FrameBarrier::answer(RobotId id, int64_t frame) {
  if (frame != frame_) return false;
  waiting_.erase(id);
  return true;
}

void FrameBarrier::give_up(RobotId id) { waiting_.erase(id); }

void FrameBarrier::wait_until(int64_t deadline_us) { deadline_us_ = deadline_us; }

bool FrameBarrier::complete(int64_t now_us) const {
  return waiting_.empty() || now_us >= deadline_us_;
}

std::vector<RobotId> FrameBarrier::missing() const {
  return {waiting_.begin(), waiting_.end()};
}

int64_t FrameBarrier::remaining_us(int64_t now_us) const {
  return std::max<int64_t>(0, deadline_us_ - now_us);
}

} // namespace touchline::sim
