#include "touchline/learning/multi_robot_sim.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "touchline/learning/observation.hpp"

using namespace touchline;
using learning::MultiRobotSim;

namespace {

/// Two robots a team, a short match: INITIAL 1 s, READY 2 s, SET 1 s, 5 s halves.
learning::MultiRobotDef short_match() {
  learning::MultiRobotDef def;
  def.world.match.team_size = 2;
  def.world.rules.initial_s = 1;
  def.world.rules.ready_s = 2;
  def.world.rules.set_s = 1;
  def.world.rules.half_s = 5;
  return def;
}

void act_all(MultiRobotSim& sim, const learning::AgentAction& action) {
  for (size_t i = 0; i < sim.robots().size(); ++i) sim.set_action(i, action);
}

const learning::AgentAction kWalk{250, 0, 0.1f, 0, 0};

Pose2D truth_pose(const sim::TruthFrame& t, size_t index) { return t.robots.at(index).truth.body; }

float moved_mm(const Pose2D& a, const Pose2D& b) { return std::hypot(a.x_mm - b.x_mm, a.y_mm - b.y_mm); }

float element(const MultiRobotSim& sim, size_t index, const std::string& name) {
  std::vector<float> obs(static_cast<size_t>(sim.observation_size()));
  sim.observe(index, obs.data());
  const auto names = learning::observation_names(sim.def().world.match.team_size);
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return obs[i];
  throw std::out_of_range(name);
}

} // namespace

TEST(MultiRobotSim, EveryRobotOfBothTeamsInTeamAndPlayerOrder) {
  MultiRobotSim sim(short_match());
  const std::vector<RobotId> want{{0, 1}, {0, 2}, {1, 1}, {1, 2}};
  EXPECT_EQ(sim.robots(), want);
  sim.reset(1);
  EXPECT_EQ(sim.game().state, GameState::kInitial);
  EXPECT_EQ(sim.frame(), 0);
}

TEST(MultiRobotSim, StepBeforeResetIsALogicError) {
  MultiRobotSim sim(short_match());
  EXPECT_THROW(sim.step(), std::logic_error);
}

// The referee's states: robots asked to walk all match long move only in READY and PLAYING
// and not while penalised; their observations say which state the game is in.
TEST(MultiRobotSim, RobotsMoveOnlyWhenTheRefereeLetsThem) {
  MultiRobotSim sim(short_match());
  sim.reset(2);
  act_all(sim, kWalk);
  std::map<GameState, float> moved;
  int penalised_frames = 0;
  while (!sim.game_over()) {
    const sim::TruthFrame before = sim.truth();
    sim.step();
    const sim::TruthFrame after = sim.truth();
    if (before.game.state != after.game.state) continue; // a change of state may place robots
    for (size_t i = 0; i < sim.robots().size(); ++i) {
      const bool penalised = before.robots[i].penalised && after.robots[i].penalised;
      const float d = moved_mm(truth_pose(before, i), truth_pose(after, i));
      if (penalised) {
        ++penalised_frames;
        EXPECT_EQ(d, 0.f) << "penalised robot " << i << " moved at frame " << sim.frame();
        EXPECT_EQ(element(sim, i, "penalised"), 1.f);
      } else {
        moved[after.game.state] += d;
      }
    }
    const char* state_flag[] = {"state_initial", "state_ready", "state_set", "state_playing", "state_finished"};
    EXPECT_EQ(element(sim, 0, state_flag[static_cast<int>(after.game.state)]), 1.f);
  }
  EXPECT_EQ(moved[GameState::kInitial], 0.f);
  EXPECT_EQ(moved[GameState::kSet], 0.f);
  EXPECT_GT(moved[GameState::kReady], 1000.f);
  EXPECT_GT(moved[GameState::kPlaying], 1000.f);
  EXPECT_GT(penalised_frames, 0) << "no robot was penalised: the check above was not exercised";
}

TEST(MultiRobotSim, TheSameSeedAndActionsGiveTheSameMatchBitForBit) {
  std::vector<uint64_t> hashes;
  for (uint64_t seed : {7, 7, 8}) {
    MultiRobotSim sim(short_match());
    sim.reset(seed);
    for (int frame = 0; frame < 300; ++frame) {
      // Each turns by where it believes the ball is: what its camera saw steers the world.
      for (size_t i = 0; i < sim.robots().size(); ++i)
        sim.set_action(i, {200.f, 0, 1e-3f * element(sim, i, "ball_rel_y_mm"), 0, 0.5f});
      sim.step();
    }
    hashes.push_back(sim.state_hash());
  }
  EXPECT_EQ(hashes[0], hashes[1]);
  EXPECT_NE(hashes[0], hashes[2]); // another seed: another camera, another match
}

TEST(MultiRobotSim, TeammatesHearEachOthersPoseEstimates) {
  learning::MultiRobotDef def = short_match();
  def.world.comm.loss_probability = 0;
  MultiRobotSim sim(def);
  sim.reset(3);
  for (int frame = 0; frame < 30; ++frame) sim.step(); // standing, in INITIAL
  EXPECT_EQ(element(sim, 0, "mate1_heard"), 1.f);
  const api::AbsCoord told = sim.blackboard(1).localisation.robotPos;
  EXPECT_NEAR(element(sim, 0, "mate1_x_mm"), told.x, 50.f);
  EXPECT_NEAR(element(sim, 0, "mate1_y_mm"), told.y, 50.f);
  EXPECT_LE(element(sim, 0, "mate1_age_s"), 0.2f + 0.1f + 0.04f); // the radio's gap and latency, a frame
}

TEST(MultiRobotSim, ANonFiniteActionIsNoRequest) {
  learning::MultiRobotDef def = short_match();
  def.world.rules.initial_s = 0;
  MultiRobotSim sim(def);
  sim.reset(4);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  act_all(sim, {nan, nan, std::numeric_limits<float>::infinity(), nan, nan});
  const Pose2D start = truth_pose(sim.truth(), 0);
  for (int frame = 0; frame < 30; ++frame) sim.step();
  EXPECT_EQ(sim.game().state, GameState::kReady);
  EXPECT_LT(moved_mm(start, truth_pose(sim.truth(), 0)), 1.f);
}
