#include "touchline/learning/tile_q.hpp"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

using namespace touchline;
using namespace touchline::learning;

namespace {

TileCodingDef small_coding() {
  TileCodingDef coding;
  coding.tilings = 4;
  coding.tiles_distance = 6;
  coding.tiles_bearing = 8;
  coding.tiles_heading = 8;
  return coding;
}

const std::vector<WalkAction> kActions = {{0, 0, 0}, {300, 0, 0}, {0, 0, 1.5f}, {0, 0, -1.5f}, {60, 0, 0}};

} // namespace

TEST(TileCoding, OneCellPerTilingEachInItsOwnBlock) {
  const TileCoding coding(small_coding());
  const size_t per_tiling = coding.cells() / 4;
  EXPECT_EQ(coding.cells(), 4u * 7 * 8 * 8);
  int cells[4];
  coding.active(1234, -567, 2.5, cells);
  for (int k = 0; k < 4; ++k) {
    EXPECT_GE(static_cast<size_t>(cells[k]), k * per_tiling);
    EXPECT_LT(static_cast<size_t>(cells[k]), (k + 1) * per_tiling);
  }
}

TEST(TileCoding, NearbyTargetsShareCellsAndFarOnesDoNot) {
  const TileCoding coding(small_coding());
  int a[4], b[4], c[4];
  coding.active(1000, 0, 0, a);
  coding.active(1010, 5, 0.01, b);
  coding.active(-1000, 0, 3.0, c);
  int shared_near = 0, shared_far = 0;
  for (int k = 0; k < 4; ++k) shared_near += a[k] == b[k], shared_far += a[k] == c[k];
  EXPECT_GE(shared_near, 3);
  EXPECT_EQ(shared_far, 0);
}

TEST(TileCoding, HeadingWrapsAroundTheCircle) {
  const TileCoding coding(small_coding());
  int a[4], b[4];
  coding.active(500, 200, 0.3, a);
  coding.active(500, 200, 0.3 + 2 * 3.14159265358979323846, b);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(a[k], b[k]);
}

TEST(TileCoding, RefusesEmptySizes) {
  TileCodingDef coding = small_coding();
  coding.tiles_bearing = 0;
  EXPECT_THROW(TileCoding{coding}, std::invalid_argument);
}

TEST(TileQ, GreedyIsTheArgmaxWithTiesToTheLowestIndex) {
  TileQ q(small_coding(), kActions);
  EXPECT_EQ(q.greedy(800, 0, 0), 0); // all zero: the first action
  std::vector<int> cells(4);
  q.coding().active(800, 0, 0, cells.data());
  for (int cell : cells) q.weights()[static_cast<size_t>(cell) * kActions.size() + 4] = 0.25f;
  EXPECT_EQ(q.greedy(800, 0, 0), 4);
  EXPECT_DOUBLE_EQ(q.value(cells, 4), 1.0);
  EXPECT_THROW(TileQ(small_coding(), {}), std::invalid_argument);
}

TEST(TileQ, RelativeTargetAndReached) {
  const Pose2D relative = relative_target({100, 100, 1.5707963f}, {100, 600, 0});
  EXPECT_NEAR(relative.x_mm, 500, 1e-3);   // straight ahead
  EXPECT_NEAR(relative.y_mm, 0, 1e-3);
  EXPECT_NEAR(relative.theta_rad, -1.5707963, 1e-6);
  const EpisodeDef episode;
  EXPECT_TRUE(reached({30, -30, 0.1f}, episode));
  EXPECT_FALSE(reached({30, -40, 0.1f}, episode)); // 50 mm: not within
  EXPECT_FALSE(reached({0, 0, 0.2f}, episode));     // over 10 degrees
}

TEST(SarsaLambda, LearnsToWalkToAPoseAhead) {
  // A target 600 mm ahead: standing never gets there, walking does. The greedy policy
  // before learning picks action 0 (stand); after a few hundred episodes it arrives.
  SingleRobotSim sim(SingleRobotDef{});
  TileQ q(small_coding(), kActions);
  for (float& w : q.weights()) w = -30.f / 4;
  EpisodeDef episode;
  episode.max_frames = 150;
  const Pose2D start{0, 0, 0}, target{600, 0, 0};
  EXPECT_FALSE(greedy_episode(q, sim, start, target, episode, 1).success);
  SarsaLambda learner(q, SarsaLambdaDef{}, 1);
  for (uint64_t i = 0; i < 300; ++i) learner.episode(sim, start, target, 0.1, episode, i);
  const EpisodeResult after = greedy_episode(q, sim, start, target, episode, 1);
  EXPECT_TRUE(after.success);
  EXPECT_LT(after.frames, 120); // the lower bound is 60 frames
}

TEST(SarsaLambda, TheSameSeedLearnsTheSameWeights) {
  auto learn = [](uint64_t seed) {
    SingleRobotSim sim(SingleRobotDef{});
    TileQ q(small_coding(), kActions);
    SarsaLambda learner(q, SarsaLambdaDef{}, seed);
    EpisodeDef episode;
    episode.max_frames = 60;
    for (uint64_t i = 0; i < 5; ++i) learner.episode(sim, {0, 0, 0}, {400, 200, 1}, 0.3, episode, i);
    return q.weights();
  };
  EXPECT_EQ(learn(3), learn(3));
  EXPECT_NE(learn(3), learn(4));
}
