// LandmarkGlance: glances at a landmark now and then, sooner when the pose is unsure, never
// with the ball hot; the same cases as tests/behaviour_py/test_landmark_glance.py.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "boards.hpp"
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/camera.hpp"
#include "touchline/behaviour/skills/head_scan.hpp"
#include "touchline/behaviour/skills/landmark_glance.hpp"

using namespace touchline::api;
using namespace touchline::behaviour::skills;
using touchline::behaviour::test::board;

namespace {

const float kPostYaw = std::atan2(700.f, 3000.f); // team 1's left post (3000, 700) from the centre spot

/// Position sigma sigmaMm (x and y together: half the variance on each), heading sigmaRad.
Blackboard ballAt(float distance, float heading, float sigmaMm = 0.f, float sigmaRad = 0.f, bool seen = true,
                  int lost = 0, float headYaw = 0.f) {
  Blackboard b = board({}, distance * std::cos(heading), distance * std::sin(heading), seen, lost, headYaw);
  const float half = sigmaMm * sigmaMm / 2;
  b.localisation.robotPosCovariance = {half, 0, 0, 0, half, 0, 0, 0, sigmaRad * sigmaRad};
  return b;
}

template <typename Skill>
std::vector<float> yaws(Skill& skill, const Blackboard& blackboard, int ticks) {
  std::vector<float> out;
  for (int i = 0; i < ticks; ++i) out.push_back(skill.tick(blackboard).head.yaw);
  return out;
}

void expectAll(const std::vector<float>& values, size_t from, size_t to, float expected, float tolerance) {
  for (size_t i = from; i < to; ++i) EXPECT_NEAR(values[i], expected, tolerance) << "tick " << i;
}

} // namespace

TEST(LandmarkGlanceSkill, TheLandmarksAreTheTwelveTheCameraReportsAndSymmetric) {
  const std::vector<FieldPoint> points = landmarks();
  ASSERT_EQ(points.size(), 12u);
  for (const FieldPoint& p : points)
    EXPECT_TRUE(
        std::any_of(points.begin(), points.end(), [&](const FieldPoint& q) { return q.x == -p.x && q.y == -p.y; }));
  auto has = [&](float x, float y) {
    return std::any_of(points.begin(), points.end(), [&](const FieldPoint& q) { return q.x == x && q.y == y; });
  };
  EXPECT_TRUE(has(3000.f, 700.f) && has(1200.f, 0.f) && has(0.f, -2000.f));
}

TEST(LandmarkGlanceSkill, TheTargetIsTheLandmarkInRangeNearestTheBallBearing) {
  auto target = glanceTarget({}, 0.f);
  ASSERT_TRUE(target);
  EXPECT_NEAR(target->distance, 1200.f, 1e-3f); // the penalty mark ahead
  EXPECT_NEAR(target->heading, 0.f, 1e-3f);
  target = glanceTarget({}, 0.5f);
  ASSERT_TRUE(target);
  EXPECT_NEAR(target->heading, kPostYaw, 1e-6f);
  target = glanceTarget({}, 1.4f);
  ASSERT_TRUE(target);
  EXPECT_NEAR(target->distance, 2000.f, 1e-3f); // a centre-line end
  EXPECT_NEAR(target->heading, kPi / 2, 1e-3f);
  // Corners 3606 mm away are out of range, and so is everything behind the head's reach.
  EXPECT_GT(std::hypot(3000.f, 2000.f), GLANCE_MAX_DIST);
  target = glanceTarget({}, -3.f);
  ASSERT_TRUE(target);
  EXPECT_NEAR(target->heading, -kPi / 2, 1e-6f);
}

TEST(LandmarkGlanceSkill, ALandmarkUnderfootIsNoTarget) {
  const auto target = glanceTarget({1200.f, 0.f, 0.f}, 0.1f); // on the penalty mark
  ASSERT_TRUE(target);
  EXPECT_NEAR(target->heading, std::atan2(700.f, 1800.f), 1e-6f);
}

TEST(LandmarkGlanceSkill, ThePoseIsUnsurePastEitherSigma) {
  EXPECT_FALSE(poseUnsure(ballAt(1000.f, 0.f, 0.9f * GLANCE_SIGMA_MM, 0.9f * GLANCE_SIGMA_RAD).localisation));
  EXPECT_TRUE(poseUnsure(ballAt(1000.f, 0.f, 1.1f * GLANCE_SIGMA_MM).localisation));
  EXPECT_TRUE(poseUnsure(ballAt(1000.f, 0.f, 0.f, 1.1f * GLANCE_SIGMA_RAD).localisation));
}

TEST(LandmarkGlanceSkill, ASureRobotGlancesEveryFewSecondsAndReturnsToTheBall) {
  LandmarkGlance skill;
  const Blackboard blackboard = ballAt(1000.f, 0.5f);
  expectAll(yaws(skill, blackboard, GLANCE_EVERY_FRAMES - 1), 0, GLANCE_EVERY_FRAMES - 1, 0.5f, 1e-5f); // on the ball
  const ActionCommand::Head head = skill.tick(blackboard).head;
  EXPECT_NEAR(head.yaw, kPostYaw, 1e-5f);
  EXPECT_NEAR(head.pitch, pitchToSee(std::hypot(3000.f, 700.f)), 1e-5f);
  // The head never gets there on this board: the glance gives up after GLANCE_MAX_FRAMES.
  expectAll(yaws(skill, blackboard, GLANCE_MAX_FRAMES - 1), 0, GLANCE_MAX_FRAMES - 1, kPostYaw, 1e-6f);
  EXPECT_LT(GLANCE_MAX_FRAMES, BALL_LOST_FRAMES); // the ball is not yet lost when it ends
  const std::vector<float> after = yaws(skill, blackboard, GLANCE_EVERY_FRAMES);
  expectAll(after, 0, GLANCE_EVERY_FRAMES - 1, 0.5f, 1e-5f);
  EXPECT_NEAR(after.back(), kPostYaw, 1e-6f); // the next glance
}

TEST(LandmarkGlanceSkill, AGlanceEndsAfterTheDwellOnceTheHeadIsOnTheLandmark) {
  LandmarkGlance skill;
  yaws(skill, ballAt(1000.f, 0.5f), GLANCE_EVERY_FRAMES); // the glance starts
  const Blackboard there = ballAt(1000.f, 0.5f, 0.f, 0.f, true, 0, kPostYaw + 0.05f);
  const std::vector<float> glance = yaws(skill, there, GLANCE_DWELL_FRAMES + 1);
  expectAll(glance, 0, GLANCE_DWELL_FRAMES, kPostYaw, 1e-6f);
  EXPECT_NEAR(glance.back(), 0.5f, 1e-5f);
}

TEST(LandmarkGlanceSkill, AnUnsureRobotGlancesSooner) {
  LandmarkGlance skill;
  const std::vector<float> seen = yaws(skill, ballAt(1000.f, 0.5f, 1.1f * GLANCE_SIGMA_MM), GLANCE_UNSURE_EVERY_FRAMES);
  expectAll(seen, 0, GLANCE_UNSURE_EVERY_FRAMES - 1, 0.5f, 1e-5f);
  EXPECT_NEAR(seen.back(), kPostYaw, 1e-6f);
}

TEST(LandmarkGlanceSkill, AHotBallKeepsTheHeadAndEndsAGlance) {
  LandmarkGlance skill;
  const Blackboard hot = ballAt(0.9f * GLANCE_HOT_BALL_DIST, 0.5f, 1.1f * GLANCE_SIGMA_MM);
  expectAll(yaws(skill, hot, 3 * GLANCE_EVERY_FRAMES), 0, 3 * GLANCE_EVERY_FRAMES, 0.5f, 1e-5f);
  LandmarkGlance glancing;
  EXPECT_NEAR(yaws(glancing, ballAt(1000.f, 0.5f), GLANCE_EVERY_FRAMES).back(), kPostYaw, 1e-6f);
  EXPECT_NEAR(glancing.tick(hot).head.yaw, 0.5f, 1e-5f);
}

TEST(LandmarkGlanceSkill, ThePoseIsLostPastItsPositionSigmaOnly) {
  EXPECT_FALSE(poseLost(ballAt(1000.f, 0.f, 0.9f * GLANCE_LOST_SIGMA_MM, 3.f).localisation));
  EXPECT_TRUE(poseLost(ballAt(1000.f, 0.f, 1.1f * GLANCE_LOST_SIGMA_MM).localisation));
}

TEST(LandmarkGlanceSkill, ALostRobotGlancesEvenWithTheBallHot) {
  // Toe to toe over the ball, a blocked walk's odometry runs the pose off: only a landmark
  // brings it back.
  LandmarkGlance skill;
  const Blackboard hot = ballAt(0.9f * GLANCE_HOT_BALL_DIST, 0.5f, 1.1f * GLANCE_LOST_SIGMA_MM);
  const std::vector<float> seen = yaws(skill, hot, GLANCE_UNSURE_EVERY_FRAMES + GLANCE_MAX_FRAMES - 1);
  expectAll(seen, 0, GLANCE_UNSURE_EVERY_FRAMES - 1, 0.5f, 1e-5f);
  expectAll(seen, GLANCE_UNSURE_EVERY_FRAMES - 1, seen.size(), kPostYaw, 1e-6f);
}

TEST(LandmarkGlanceSkill, ALostBallIsSearchedForNotGlancedAwayFrom) {
  LandmarkGlance skill;
  const Blackboard lost = ballAt(1000.f, 0.5f, 1.1f * GLANCE_SIGMA_MM, 0.f, false, BALL_LOST_FRAMES + 1);
  const std::vector<float> scan = yaws(skill, lost, 2 * GLANCE_EVERY_FRAMES);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(scan[i], static_cast<float>(i + 1) * SCAN_YAW_STEP, 1e-5f);
  LookForBall plain;
  EXPECT_EQ(scan, yaws(plain, lost, 2 * GLANCE_EVERY_FRAMES)); // LookForBall's scan, no glance
}
