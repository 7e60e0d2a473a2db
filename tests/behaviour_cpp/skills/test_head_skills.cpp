// TrackBall, HeadScan and LookForBall; the same cases as tests/behaviour_py/test_head_skills.py.
#include <gtest/gtest.h>

#include <vector>

#include "boards.hpp"
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/camera.hpp"
#include "touchline/behaviour/skills/head_scan.hpp"
#include "touchline/behaviour/skills/look_for_ball.hpp"
#include "touchline/behaviour/skills/track_ball.hpp"

using namespace touchline::api;
using namespace touchline::behaviour::skills;
using touchline::behaviour::test::board;

namespace {

/// A board with the ball `distance` mm away at `heading` from the robot at the origin.
Blackboard ballAt(float distance, float heading, bool seen = true, int lost = 0, float headYaw = 0.f) {
  return board({0, 0, 0}, distance * std::cos(heading), distance * std::sin(heading), seen, lost, headYaw);
}

std::vector<float> scanYaws(Behaviour& scan, const Blackboard& blackboard, int ticks) {
  std::vector<float> yaws;
  for (int i = 0; i < ticks; ++i) yaws.push_back(scan.tick(blackboard).head.yaw);
  return yaws;
}

} // namespace

TEST(TrackBallSkill, PointsAtTheBallWithThePitchThatSeesIt) {
  const float distances[] = {1000.f, 2500.f}, pitches[] = {0.313333f, -0.276667f};
  for (int i = 0; i < 2; ++i) {
    const auto head = TrackBall().tick(ballAt(distances[i], 0.5f)).head;
    EXPECT_NEAR(head.yaw, 0.5f, 1e-5f);
    EXPECT_NEAR(head.pitch, pitches[i], 1e-5f);
    EXPECT_GT(visibleRange(head.pitch), distances[i]);
  }
}

TEST(TrackBallSkill, ClampsToTheJointLimits) {
  auto head = TrackBall().tick(ballAt(4000.f, 2.5f)).head;
  EXPECT_FLOAT_EQ(head.yaw, MAX_HEAD_YAW);
  EXPECT_FLOAT_EQ(head.pitch, MIN_HEAD_PITCH); // far: look up
  head = TrackBall().tick(ballAt(100.f, -2.5f)).head;
  EXPECT_FLOAT_EQ(head.yaw, -MAX_HEAD_YAW);
  EXPECT_FLOAT_EQ(head.pitch, MAX_HEAD_PITCH); // near: look down
}

TEST(TrackBallSkill, UsesLocalisationWhenVisionMissedIt) {
  Blackboard blackboard = ballAt(1000.f, 0.5f, false, 3);
  blackboard.vision.ball = {3000.f, -1.f}; // stale: ignored
  const auto head = TrackBall().tick(blackboard).head;
  EXPECT_NEAR(head.yaw, 0.5f, 1e-5f);
  EXPECT_NEAR(head.pitch, 0.313333f, 1e-5f);
}

TEST(HeadScanSkill, SweepsWithinTheJointLimitsAndReverses) {
  HeadScan scan;
  const Blackboard blackboard = ballAt(1000.f, 0.1f, true, 100);
  const std::vector<float> yaws = scanYaws(scan, blackboard, 200);
  EXPECT_NEAR(yaws[0], SCAN_YAW_STEP, 1e-6f); // towards the ball's side first
  EXPECT_NEAR(yaws[SCAN_STEPS - 1], MAX_HEAD_YAW, 1e-5f); // left limit after 40 frames
  EXPECT_NEAR(yaws[SCAN_STEPS], MAX_HEAD_YAW - SCAN_YAW_STEP, 1e-5f); // reversed
  EXPECT_NEAR(yaws[3 * SCAN_STEPS - 1], -MAX_HEAD_YAW, 1e-5f); // right limit
  EXPECT_NEAR(yaws[3 * SCAN_STEPS], -MAX_HEAD_YAW + SCAN_YAW_STEP, 1e-5f);
  for (size_t i = 0; i < yaws.size(); ++i) {
    EXPECT_LE(std::fabs(yaws[i]), MAX_HEAD_YAW + 1e-6f);
    if (i > 0) {
      EXPECT_NEAR(std::fabs(yaws[i] - yaws[i - 1]), SCAN_YAW_STEP, 1e-5f); // a steady pace
    }
  }
  EXPECT_NEAR(scan.tick(blackboard).head.pitch, SCAN_PITCH, 1e-6f);
  EXPECT_NEAR(SCAN_PITCH, -0.08f, 1e-6f);
}

TEST(HeadScanSkill, StartsTowardsTheBallSideFromTheHeadYaw) {
  EXPECT_NEAR(HeadScan().tick(ballAt(1000.f, -0.1f, true, 100)).head.yaw, -SCAN_YAW_STEP, 1e-6f);
  // From step round(1.0 / 0.052) = 19.
  EXPECT_NEAR(HeadScan().tick(ballAt(1000.f, 0.1f, true, 100, 1.f)).head.yaw, 20 * SCAN_YAW_STEP, 1e-5f);
}

TEST(HeadScanSkill, FromTheLimitTurnsBack) {
  HeadScan scan;
  const std::vector<float> yaws = scanYaws(scan, ballAt(1000.f, 0.1f, true, 100, MAX_HEAD_YAW), 2);
  EXPECT_NEAR(yaws[0], MAX_HEAD_YAW, 1e-5f);
  EXPECT_NEAR(yaws[1], MAX_HEAD_YAW - SCAN_YAW_STEP, 1e-5f);
}

TEST(HeadScanSkill, IsDeterministic) {
  const Blackboard blackboard = ballAt(1000.f, 0.1f, true, 100, 0.3f);
  HeadScan a, b;
  EXPECT_EQ(scanYaws(a, blackboard, 100), scanYaws(b, blackboard, 100));
}

TEST(LookForBallSkill, TracksThenScansThenRestartsTheScan) {
  LookForBall skill;
  const Blackboard seen = ballAt(1000.f, 0.5f);
  const Blackboard lost = ballAt(1000.f, 0.5f, false, BALL_LOST_FRAMES + 1);
  EXPECT_NEAR(skill.tick(seen).head.yaw, 0.5f, 1e-5f);
  const std::vector<float> yaws = scanYaws(skill, lost, 3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(yaws[i], static_cast<float>(i + 1) * SCAN_YAW_STEP, 1e-5f);
  skill.tick(seen);
  EXPECT_NEAR(skill.tick(lost).head.yaw, SCAN_YAW_STEP, 1e-6f); // a fresh scan
}
