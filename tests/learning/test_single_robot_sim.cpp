#include "touchline/learning/single_robot_sim.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <gtest/gtest.h>


using namespace touchline;
using learning::SingleRobotSim;

namespace {

SingleRobotSim default_sim() { return SingleRobotSim(learning::SingleRobotDef{}); }

void walk_for(SingleRobotSim& sim, float seconds, const api::ActionCommand::Body& body) {
  while (sim.time_s() < seconds - 1e-9) sim.step(body);
}

} // namespace

TEST(SingleRobotSim, ResetPutsTheRobotAtThePoseAndTheClockAtZero) {
  SingleRobotSim sim = default_sim();
  sim.reset(3, {500, -200, 1.0f});
  EXPECT_NEAR(sim.pose().x_mm, 500, 1e-3);
  EXPECT_NEAR(sim.pose().y_mm, -200, 1e-3);
  EXPECT_NEAR(sim.pose().theta_rad, 1.0, 1e-5);
  EXPECT_EQ(sim.frame(), 0);
  EXPECT_EQ(sim.time_s(), 0);
}

TEST(SingleRobotSim, AStepIsOneCameraFrame) {
  SingleRobotSim sim = default_sim();
  sim.reset(1, {0, 0, 0});
  for (int i = 0; i < 30; ++i) sim.step(api::ActionCommand::stand());
  EXPECT_EQ(sim.frame(), 30);
  EXPECT_NEAR(sim.time_s(), 1.0, 1e-9); // 30 frames of 3 or 4 motion ticks: 100 ticks
}

TEST(SingleRobotSim, WalksForwardAlongItsHeadingAsTheWalkPromises) {
  // 5 s at the forward limit from rest, accelerating at 600 mm/s^2: v (t - v / 2a).
  SingleRobotSim sim = default_sim();
  const float heading = 0.7f;
  sim.reset(1, {-1000, -1000, heading});
  walk_for(sim, 5, api::ActionCommand::walk(300, 0, 0));
  const float travelled = std::hypot(sim.pose().x_mm + 1000, sim.pose().y_mm + 1000);
  EXPECT_NEAR(travelled, 300 * (5 - 300.0 / 1200), 0.05 * 1425);
  EXPECT_NEAR(std::atan2(sim.pose().y_mm + 1000, sim.pose().x_mm + 1000), heading, 0.03);
  EXPECT_NEAR(sim.walk_velocity().forward_mm_s, 300, 1e-3);
}

TEST(SingleRobotSim, TheWalkClampsCommandsToItsLimits) {
  SingleRobotSim sim = default_sim();
  sim.reset(1, {0, 0, 0});
  walk_for(sim, 2, api::ActionCommand::walk(0, 0, 9));
  EXPECT_NEAR(sim.walk_velocity().turn_rad_s, learning::SingleRobotDef{}.robot.walk.max_turn_rad_s, 1e-5);
}

TEST(SingleRobotSim, TheSameSeedAndCommandsGiveTheSameWorldBitForBit) {
  auto run = [](uint64_t seed) {
    SingleRobotSim sim = default_sim();
    sim.reset(seed, {100, 200, -0.5f});
    for (int i = 0; i < 90; ++i) sim.step(api::ActionCommand::walk(200, i % 2 ? 50.f : -50.f, 0.4f));
    return sim.state_hash();
  };
  EXPECT_EQ(run(7), run(7));
  SingleRobotSim again = default_sim();
  again.reset(7, {0, 0, 0});
  const uint64_t fresh = again.state_hash();
  walk_for(again, 1, api::ActionCommand::walk(300, 0, 0));
  again.reset(7, {0, 0, 0});
  EXPECT_EQ(again.state_hash(), fresh); // a reset leaves nothing of the last episode
}

TEST(SingleRobotSim, ABehaviourCanDriveTheRobotInstead) {
  SingleRobotSim sim = default_sim();
  sim.reset(1, {0, 0, 0}, std::nullopt, robot::BehaviourDef{"goto", {{"x", "1000"}, {"y", "500"}, {"theta", "1"}}, {}});
  while (sim.time_s() < 12) sim.step_behaviour();
  EXPECT_NEAR(sim.pose().x_mm, 1000, 100);
  EXPECT_NEAR(sim.pose().y_mm, 500, 100);
  EXPECT_NEAR(sim.pose().theta_rad, 1.0, 0.2);
  EXPECT_THROW(sim.step(api::ActionCommand::stand()), std::logic_error);
}

TEST(SingleRobotSim, MisuseIsALogicError) {
  SingleRobotSim sim = default_sim();
  EXPECT_THROW(sim.step(api::ActionCommand::stand()), std::logic_error); // no reset yet
  sim.reset(1, {0, 0, 0});
  EXPECT_THROW(sim.step_behaviour(), std::logic_error); // no behaviour given
}

TEST(SingleRobotSim, TheBallStaysOutOfTheWayUnlessPlaced) {
  SingleRobotSim sim = default_sim();
  sim.reset(1, {0, 0, 0});
  const sim::FieldDef field;
  EXPECT_GT(std::abs(sim.ball().x_mm), 0.5f * field.length_mm);
  EXPECT_GT(std::abs(sim.ball().y_mm), 0.5f * field.width_mm);
  sim.reset(1, {0, 0, 0}, Pose2D{300, 100, 0});
  EXPECT_NEAR(sim.ball().x_mm, 300, 1e-3);
  EXPECT_NEAR(sim.ball().y_mm, 100, 1e-3);
}

TEST(SingleRobotSim, TheRefereeIsOffAndABadConfigIsRefused) {
  learning::SingleRobotDef def;
  def.world.match.team_size = 4; // whatever the file says, one robot plays
  SingleRobotSim sim(def);
  EXPECT_FALSE(sim.def().world.rules.referee);
  def.world.physics.substeps = 0;
  EXPECT_THROW(SingleRobotSim{def}, ConfigError);
}

TEST(SingleRobotSim, TheRobotKicksWithItsDefsKick) {
  // kick.ini reaches the learner's robot: a harder strike sends the ball further.
  auto ball_after_a_kick = [](float peak_speed_mm_s) {
    learning::SingleRobotDef def;
    def.robot.kick.kick.peak_speed_mm_s = peak_speed_mm_s;
    SingleRobotSim sim(def);
    sim.reset(1, {0, 0, 0}, Pose2D{300, 0, 0}, robot::BehaviourDef{"LineUpAndKick", {{"power", "1"}}, {}});
    for (int f = 0; f < 150; ++f) sim.step_behaviour(); // 5 s: line up, kick, the ball rolls
    return sim.ball().x_mm;
  };
  const float soft = ball_after_a_kick(800), hard = ball_after_a_kick(2400);
  std::printf("ball after 5 s: %.0f mm (peak 800 mm/s), %.0f mm (2400 mm/s)\n", soft, hard);
  EXPECT_GT(soft, 300);
  EXPECT_GT(hard, soft + 300);
}
