#include "touchline/inprocess/inprocess_match.hpp"

#include <cstdlib>
#include <iostream>

#include <gtest/gtest.h>

#include "touchline/angles.hpp"
#include "touchline/behaviour/registry.hpp"

using namespace touchline;

namespace {

struct Target {
  RobotId id;
  float x, y, theta;
};

/// Four a side, each robot walking from the touchline to a spot of its own half. Targets
/// are in the team's own frame (+x towards the goal it attacks), as the robot API's are.
const std::vector<Target>& targets() {
  static const std::vector<Target> all = {
      {{0, 1}, -2700, 0, 0},      {{0, 2}, -1500, 800, 0},  {{0, 3}, -1500, -800, 0},
      {{0, 4}, -600, 0, 0.5f},    {{1, 1}, -2700, 0, 0},    {{1, 2}, -1500, -800, 0.6f},
      {{1, 3}, -1500, 800, -0.6f}, {{1, 4}, -600, -300, 0},
  };
  return all;
}

/// A target in the world's frame (team 0's).
Pose2D in_world(const Target& t) {
  return t.id.team == 0 ? Pose2D{t.x, t.y, t.theta} : Pose2D{-t.x, -t.y, normalise_angle(t.theta + kPi)};
}

std::unique_ptr<inprocess::InProcessMatch> four_a_side(float duration_s, uint64_t seed = 1) {
  sim::WorldConfig config;
  config.match.duration_s = duration_s;
  auto match = std::make_unique<inprocess::InProcessMatch>(config, seed);
  for (const Target& t : targets()) {
    robot::RobotDef def;
    def.id = t.id;
    def.behaviour = {"goto", {{"x", std::to_string(t.x)}, {"y", std::to_string(t.y)}, {"theta", std::to_string(t.theta)}}, {}};
    match->add_robot(def, behaviour::make_behaviour(def.behaviour.name, def.behaviour.params));
  }
  match->start();
  return match;
}

} // namespace

TEST(InProcessMatch, EveryRobotWalksToItsPoseAndStands) {
  auto match = four_a_side(25);
  match->run_to_end();
  for (const Target& t : targets()) {
    const auto& truth = match->match().truth();
    const auto it = std::find_if(truth.robots.begin(), truth.robots.end(),
                                 [&](const auto& r) { return r.truth.id == t.id; });
    ASSERT_NE(it, truth.robots.end());
    const Pose2D& body = it->truth.body;
    const Pose2D target = in_world(t);
    EXPECT_NEAR(body.x_mm, target.x_mm, 100) << sim::describe(t.id);
    EXPECT_NEAR(body.y_mm, target.y_mm, 100) << sim::describe(t.id);
    EXPECT_NEAR(normalise_angle(body.theta_rad - target.theta_rad), 0, 0.2) << sim::describe(t.id);
    EXPECT_TRUE(match->robot(t.id).blackboard().motion.standing) << sim::describe(t.id);
  }
}

TEST(InProcessMatch, SameMatchTwiceIsBitIdentical) {
  auto a = four_a_side(5), b = four_a_side(5);
  a->run_to_end();
  b->run_to_end();
  EXPECT_EQ(a->match().world().state_hash(), b->match().world().state_hash());
  EXPECT_EQ(a->match().frame(), 150);
}

TEST(InProcessMatch, AnotherSeedIsAnotherMatch) {
  // The camera's noise reaches the robots' localisation, and so where they walk.
  auto a = four_a_side(5, 1), b = four_a_side(5, 2);
  a->run_to_end();
  b->run_to_end();
  EXPECT_NE(a->match().world().state_hash(), b->match().world().state_hash());
}

// Golden hash: any change to the walk, the world or the scheduling that changes a
// match shows up here. When a change is intended, rerun with TOUCHLINE_PRINT_GOLDEN=1,
// check the change is the one you meant, and update the constant in the same commit.
TEST(InProcessMatch, GoldenHashOfAFiveSecondFourASideMatch) {
  constexpr uint64_t kGolden = 0xb4f67ea2015b0c00ull;
  auto match = four_a_side(5);
  match->run_to_end();
  const uint64_t hash = match->match().world().state_hash();
  if (std::getenv("TOUCHLINE_PRINT_GOLDEN")) std::cout << "golden hash: 0x" << std::hex << hash << "ull" << std::endl;
  EXPECT_EQ(hash, kGolden) << std::hex << "got 0x" << hash;
}

TEST(InProcessMatch, ARobotKnowsTheFieldItPlaysOn) {
  // Its landmark map is the match's [field] (as robot_shim's --field-config is the
  // world's config), not the SPL 2011 map a default RobotDef carries.
  sim::WorldConfig config;
  config.field.length_mm = 9000;
  config.field.width_mm = 6000;
  config.field.goal_width_mm = 1500;
  config.field.penalty_mark_distance_mm = 1300;
  inprocess::InProcessMatch match(config);
  robot::RobotDef def;
  def.id = {1, 3};
  def.kick.kick.peak_speed_mm_s = 2000; // and the rest of the def is the robot's
  const robot::Robot& robot = match.add_robot(def, behaviour::make_behaviour("stand", {}));
  const auto& field = robot.def().localisation.filters.field;
  EXPECT_FLOAT_EQ(field.length_mm, 9000);
  EXPECT_FLOAT_EQ(field.width_mm, 6000);
  EXPECT_FLOAT_EQ(field.goal_width_mm, 1500);
  EXPECT_FLOAT_EQ(field.penalty_mark_distance_mm, 1300);
  EXPECT_EQ(robot.id(), (RobotId{1, 3}));
  EXPECT_FLOAT_EQ(robot.motion().kick().def().kick.peak_speed_mm_s, 2000);
}
