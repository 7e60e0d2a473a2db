// Robot with BehaviourTimingDef::charge_cpu: a behaviour that overruns its frame misses
// frames, as on the robot. The CPU cost is injected (a fake CPU clock the behaviour
// advances), so the frames it runs on are exact.
#include <gtest/gtest.h>

#include "touchline/robot/robot.hpp"

using namespace touchline;
using namespace touchline::api;

namespace {

SenseFrame frame_for_robot_0_1(int64_t index) {
  SenseFrame frame;
  frame.frame = index;
  frame.utime = frame_start_utime(index);
  frame.motion_ticks = ticks_in_frame(index);
  RobotSense sense;
  sense.id = {0, 1};
  frame.robots.push_back(sense);
  return frame;
}

/// Costs `cost_us` of (fake) CPU per tick, records the frames it ran on, and asks for a
/// walk whose forward speed is its tick count, so a stale request can be told apart.
class Costly : public Behaviour {
 public:
  Costly(int64_t& cpu_clock_us, int64_t cost_us) : clock_(cpu_clock_us), cost_(cost_us) {}
  ActionCommand::All tick(const Blackboard& blackboard) override {
    clock_ += cost_;
    frames.push_back(blackboard.vision.frame);
    ActionCommand::All all;
    all.body = ActionCommand::walk(static_cast<float>(frames.size()), 0, 0);
    return all;
  }
  std::vector<int64_t> frames;

 private:
  int64_t& clock_;
  int64_t cost_;
};

struct Outcome {
  std::vector<int64_t> ticked_frames;
  std::vector<float> forward_per_frame; ///< the request in force in each frame
  std::vector<int> motion_ticks_per_frame;
  robot::BehaviourStats stats;
};

Outcome play(int64_t cost_us, bool charge_cpu, int frames) {
  int64_t cpu_us = 0;
  auto owned = std::make_unique<Costly>(cpu_us, cost_us);
  Costly& behaviour = *owned;
  robot::RobotDef def;
  def.timing.charge_cpu = charge_cpu;
  def.timing.cpu_clock = [&cpu_us] { return cpu_us; };
  robot::Robot robot(def, std::move(owned));
  Outcome out;
  for (int64_t f = 0; f < frames; ++f) {
    const SenseFrame frame = frame_for_robot_0_1(f);
    const RobotAct act = robot.step(frame, frame.robots[0]);
    out.forward_per_frame.push_back(robot.blackboard().behaviour.request.body.forward);
    out.motion_ticks_per_frame.push_back(act.motion_ticks);
    EXPECT_EQ(robot.blackboard().motion.ticks, first_tick_of_frame(f + 1)) << "motion ticks every frame";
  }
  out.ticked_frames = behaviour.frames;
  out.stats = robot.behaviour_stats();
  return out;
}

} // namespace

TEST(ChargeCpu, FramesUsedIsTheCpuTimeInFramesRoundedUp) {
  EXPECT_EQ(robot::behaviour_frames_used(0), 1);
  EXPECT_EQ(robot::behaviour_frames_used(33333), 1); // within one 33.3 ms frame: nothing missed
  EXPECT_EQ(robot::behaviour_frames_used(33334), 2);
  EXPECT_EQ(robot::behaviour_frames_used(66666), 2);
  EXPECT_EQ(robot::behaviour_frames_used(66667), 3);
  EXPECT_EQ(robot::behaviour_frames_used(70000), 3);
  EXPECT_EQ(robot::behaviour_frames_used(100000), 3);
  EXPECT_EQ(robot::behaviour_frames_used(100001), 4);
}

TEST(ChargeCpu, A70msBehaviourRunsEveryThirdFrameAndItsRequestStaysInForce) {
  const Outcome r = play(70000, true, 12);
  EXPECT_EQ(r.ticked_frames, (std::vector<int64_t>{0, 3, 6, 9}));
  EXPECT_EQ(r.forward_per_frame, (std::vector<float>{1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4}));
  EXPECT_EQ(r.stats.ticks, 4);
  EXPECT_EQ(r.stats.skipped_frames, 8);
  EXPECT_EQ(r.stats.max_cpu_us, 70000);
  EXPECT_DOUBLE_EQ(r.stats.mean_cpu_us(), 70000);
  for (int64_t f = 0; f < 12; ++f) EXPECT_EQ(r.motion_ticks_per_frame[f], ticks_in_frame(f));
}

TEST(ChargeCpu, WithoutChargingTheSameBehaviourRunsEveryFrame) {
  const Outcome r = play(70000, false, 12);
  EXPECT_EQ(r.ticked_frames, (std::vector<int64_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
  EXPECT_EQ(r.stats.skipped_frames, 0);
  EXPECT_EQ(r.stats.last_cpu_us, 70000); // still measured
}

TEST(ChargeCpu, ABehaviourWithinItsFrameMissesNothing) {
  EXPECT_EQ(play(33333, true, 9).ticked_frames, (std::vector<int64_t>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
}

TEST(ChargeCpu, JustOverOneFrameMissesEveryOtherFrame) {
  EXPECT_EQ(play(34000, true, 9).ticked_frames, (std::vector<int64_t>{0, 2, 4, 6, 8}));
}

TEST(ChargeCpu, FrameIndicesThatSkipAheadDoNotOweMore) {
  // A robot the world treated as crashed comes back many frames later: it ticks at once.
  int64_t cpu_us = 0;
  auto owned = std::make_unique<Costly>(cpu_us, 70000);
  Costly& behaviour = *owned;
  robot::RobotDef def;
  def.timing.charge_cpu = true;
  def.timing.cpu_clock = [&cpu_us] { return cpu_us; };
  robot::Robot robot(def, std::move(owned));
  for (int64_t f : {0, 1, 50, 51, 52, 53}) {
    const SenseFrame frame = frame_for_robot_0_1(f);
    robot.step(frame, frame.robots[0]);
    EXPECT_EQ(robot.behaviour_stats().ticked_last_step, f == 0 || f == 50 || f == 53) << f;
  }
  EXPECT_EQ(behaviour.frames, (std::vector<int64_t>{0, 50, 53}));
}
