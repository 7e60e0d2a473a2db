// The per-frame localisation: odometry poses in, Blackboard out.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "synthetic.hpp"
#include "touchline/frame.hpp"
#include "touchline/robot/localisation/localiser.hpp"

namespace touchline::robot::localisation {
namespace {

TEST(Localiser, StartsWhereTheRulesPlaceTheRobot) {
  const Pose2D start{-1500.f, -2000.f, 1.5708f};
  Localiser localiser(LocalisationDef{}, start);
  api::LocalisationBlackboard out;
  localiser.write(out);
  EXPECT_FLOAT_EQ(out.robotPos.x, -1500.f);
  EXPECT_FLOAT_EQ(out.robotPos.y, -2000.f);
  EXPECT_FLOAT_EQ(out.robotPos.theta, 1.5708f);
  EXPECT_NEAR(localiser.pose_filter().sigma_x_mm(), PoseFilterDef{}.initial_sigma_xy_mm, 1e-9);
}

TEST(Localiser, FollowsOdometryChangesNotTheOdometryFrame) {
  // The walk's odometry frame starts wherever it likes; only its changes move the estimate.
  const Pose2D start{0.f, 0.f, 0.f};
  Localiser localiser(LocalisationDef{}, start);
  const Pose2D odo0{500.f, 200.f, 1.0f};
  localiser.frame(0, odo0, {});
  // 100 mm forward and 0.2 rad left in the odometry's own robot frame.
  const Pose2D odo1 = synthetic::compose(odo0, {100.0, 0.0, 0.2});
  localiser.frame(33333, odo1, {});
  api::LocalisationBlackboard out;
  localiser.write(out);
  EXPECT_NEAR(out.robotPos.x, 100.f, 1e-2f);
  EXPECT_NEAR(out.robotPos.y, 0.f, 1e-2f);
  EXPECT_NEAR(out.robotPos.theta, 0.2f, 1e-5f);
}

TEST(Localiser, TurnsByTheGyroNotByTheOdometry) {
  // Its foot caught on a post, the robot turned 0.4 rad while the walk thought it walked straight.
  Localiser localiser(LocalisationDef{}, Pose2D{});
  const Pose2D odo0{500.f, 200.f, 1.0f};
  localiser.frame(0, odo0, {}, 0.f);
  localiser.frame(33333, synthetic::compose(odo0, {100.0, 0.0, 0.0}), {}, 0.4f);
  api::LocalisationBlackboard out;
  localiser.write(out);
  EXPECT_NEAR(out.robotPos.x, 100.f, 1e-2f); // the steps still come from the odometry
  EXPECT_NEAR(out.robotPos.theta, 0.4f, 1e-5f);
}

TEST(Localiser, AHeadingFromTheGyroIsAsSureAsTheGyro) {
  // 3 s of walking: with the gyro's turn the heading is unsure only as the gyro makes it.
  Localiser with_gyro(LocalisationDef{}, Pose2D{}), walk_only(LocalisationDef{}, Pose2D{});
  Pose2D odometry{};
  for (int frame = 0; frame <= 90; ++frame) {
    with_gyro.frame(frame * 33333, odometry, {}, 0.f);
    walk_only.frame(frame * 33333, odometry, {});
    odometry = synthetic::compose(odometry, {7.0, 0.0, 0.0});
  }
  const double initial_var = std::pow(PoseFilterDef{}.initial_sigma_theta_rad, 2);
  const double gyro_growth = std::pow(with_gyro.pose_filter().sigma_theta_rad(), 2) - initial_var;
  const double walk_growth = std::pow(walk_only.pose_filter().sigma_theta_rad(), 2) - initial_var;
  const PoseFilterDef def;
  EXPECT_NEAR(gyro_growth, 90 * (def.gyro_theta_var_per_call + 7.0 * def.gyro_theta_var_per_mm), 1e-9);
  EXPECT_GT(walk_growth, 2 * gyro_growth);
}

TEST(Localiser, ARobotPutDownIsWhereItWasPutInThatFrame) {
  // The frame it was put down in moved it by nothing: its walk's steps and the referee's
  // turning it are in the pose it was put down at already.
  Localiser localiser(LocalisationDef{}, Pose2D{});
  const Pose2D odo0{0.f, 0.f, 0.f};
  localiser.frame(0, odo0, {});
  const Pose2D put{-2000.f, 2000.f, -1.5708f};
  localiser.reset(put);
  const Pose2D odo1 = synthetic::compose(odo0, {50.0, 0.0, 0.1});
  localiser.frame(33333, odo1, {}, 1.5f);
  api::LocalisationBlackboard out;
  localiser.write(out);
  EXPECT_FLOAT_EQ(out.robotPos.x, put.x_mm);
  EXPECT_FLOAT_EQ(out.robotPos.theta, put.theta_rad);
  localiser.frame(66666, synthetic::compose(odo1, {100.0, 0.0, 0.0}), {}, 0.f); // then on from there
  localiser.write(out);
  EXPECT_NEAR(out.robotPos.y, put.y_mm - 100.f, 1e-2f); // facing -y
}

TEST(Localiser, WritesTheBallFromThePoseEstimate) {
  const Pose2D truth{-1000.f, 0.f, 0.f};  // facing team 1's goal from our half
  Localiser localiser(LocalisationDef{}, truth);
  const FieldMap map;
  std::mt19937 rng(1);
  const Pose2D odometry{};
  api::LocalisationBlackboard out;
  for (int frame = 0; frame < 30; ++frame) {
    std::vector<Observation> seen = synthetic::see_landmarks(map, synthetic::Camera{}, truth, 0.0, rng);
    seen.push_back(synthetic::observe(truth, 0.0, 300.0, ObjectKind::kBall, 0, {}, rng));
    seen.push_back(synthetic::observe(truth, 500.0, -300.0, ObjectKind::kOpponent, 2, {}, rng));
    localiser.frame(frame_start_utime(frame), odometry, seen);
  }
  localiser.write(out);
  EXPECT_NEAR(out.ballPos.x, 0.f, 60.f);
  EXPECT_NEAR(out.ballPos.y, 300.f, 60.f);
  EXPECT_EQ(out.ballLostCount, 0);
  EXPECT_FLOAT_EQ(out.teamBallPos.x, out.ballPos.x);
  EXPECT_FLOAT_EQ(out.teamBallPos.y, out.ballPos.y);
  const api::RRCoord expected = api::toRobotRelative(out.robotPos, out.ballPos.x, out.ballPos.y);
  EXPECT_FLOAT_EQ(out.ballPosRR.distance, expected.distance);
  EXPECT_FLOAT_EQ(out.ballPosRR.heading, expected.heading);
  EXPECT_NEAR(out.ballPosRR.distance, std::hypot(1000.f, 300.f), 80.f);

  // Three frames without the ball.
  for (int frame = 30; frame < 33; ++frame) localiser.frame(frame_start_utime(frame), odometry, {});
  localiser.write(out);
  EXPECT_EQ(out.ballLostCount, 3);
}

TEST(Localiser, ABallRollingFromAnUnsureRobotIsFollowedRelativeToIt) {
  // A carry: the robot's pose estimate is 200 mm off and unsure (no landmark in view), and a
  // ball rolls away from its feet at 450 mm/s. What the robot needs is where the ball is from
  // it, and the camera tells that as well as ever: the pose's error is common to every
  // sighting. (Counted as each sighting's own noise it made the track lag the rolling ball.)
  const Pose2D truth{0.f, 0.f, 0.f};
  Localiser localiser(LocalisationDef{}, Pose2D{-150.f, 130.f, 0.f});
  std::mt19937 rng(2);
  const Pose2D odometry{};
  double x_mm = 130.0, speed_mm_s = 0.0;
  double sum_sq_mm = 0.0, sum_sq_sighting_mm = 0.0;
  int samples = 0;
  api::LocalisationBlackboard out;
  for (int frame = 0; frame < 75; ++frame) {
    if (frame == 30) speed_mm_s = 450.0;  // struck by the foot
    x_mm += speed_mm_s * synthetic::kFrameS;
    speed_mm_s = std::max(0.0, speed_mm_s - (300.0 + 0.2 * speed_mm_s) * synthetic::kFrameS);
    const Observation sighting = synthetic::observe(truth, x_mm, 0.0, ObjectKind::kBall, 0, {}, rng);
    localiser.frame(frame_start_utime(frame), odometry, {sighting});
    localiser.write(out);
    if (frame >= 40) {  // from a third of a second after the strike
      sum_sq_mm += std::pow(out.ballPosRR.x() - x_mm, 2) + std::pow(out.ballPosRR.y(), 2);
      const double seen_x = sighting.distance_mm * std::cos(sighting.heading_rad);
      const double seen_y = sighting.distance_mm * std::sin(sighting.heading_rad);
      sum_sq_sighting_mm += std::pow(seen_x - x_mm, 2) + std::pow(seen_y, 2);
      ++samples;
    }
  }
  const double rms_mm = std::sqrt(sum_sq_mm / samples);
  const double sighting_rms_mm = std::sqrt(sum_sq_sighting_mm / samples);
  std::cout << "[ figures  ] ball rolling from an unsure robot's feet (pose sigma "
            << localiser.pose_filter().sigma_x_mm() << " mm): relative to the robot, the track RMS " << rms_mm
            << " mm off, the camera's sightings " << sighting_rms_mm << " mm\n";
  // No worse than the camera itself (the pose's error counted as each sighting's noise: 76 mm).
  EXPECT_LT(rms_mm, 1.3 * sighting_rms_mm);
}

TEST(Localiser, ALandmarkCorrectionKeepsTheBallWhereTheRobotSawIt) {
  // The pose estimate starts 250 mm off; landmarks come into view and correct it. The ball,
  // seen from the robot all along, stays where it is relative to the robot, and on the
  // field it moves with the pose towards where it really is.
  const Pose2D truth{-1000.f, 0.f, 0.f};
  Localiser localiser(LocalisationDef{}, Pose2D{-1200.f, 150.f, 0.f});
  const FieldMap map;
  std::mt19937 rng(3);
  const Pose2D odometry{};
  api::LocalisationBlackboard out;
  for (int frame = 0; frame < 30; ++frame) {
    localiser.frame(frame_start_utime(frame), odometry,
                    {synthetic::observe(truth, -700.0, 100.0, ObjectKind::kBall, 0, {}, rng)});
  }
  localiser.write(out);
  const api::RRCoord before = out.ballPosRR;
  const float off_before_mm = std::hypot(out.ballPos.x + 700.f, out.ballPos.y - 100.f);
  EXPECT_GT(off_before_mm, 200.f);  // off on the field as the pose is
  // One frame of landmarks (no ball): the pose moves, the ball relative to it does not.
  localiser.frame(frame_start_utime(30), odometry, synthetic::see_landmarks(map, synthetic::Camera{}, truth, 0.0, rng));
  localiser.write(out);
  EXPECT_GT(std::hypot(out.robotPos.x + 1200.f, out.robotPos.y - 150.f), 50.f);
  EXPECT_NEAR(out.ballPosRR.x(), before.x(), 2.f);
  EXPECT_NEAR(out.ballPosRR.y(), before.y(), 2.f);
  for (int frame = 31; frame < 90; ++frame) {
    std::vector<Observation> seen = synthetic::see_landmarks(map, synthetic::Camera{}, truth, 0.0, rng);
    seen.push_back(synthetic::observe(truth, -700.0, 100.0, ObjectKind::kBall, 0, {}, rng));
    localiser.frame(frame_start_utime(frame), odometry, seen);
  }
  localiser.write(out);
  EXPECT_NEAR(out.ballPosRR.x(), 300.f, 30.f);
  EXPECT_NEAR(out.ballPosRR.y(), 100.f, 30.f);
  EXPECT_LT(std::hypot(out.ballPos.x + 700.f, out.ballPos.y - 100.f), 0.5f * off_before_mm);
}

TEST(Localiser, ResetReplacesTheRobot) {
  Localiser localiser(LocalisationDef{}, Pose2D{});
  localiser.reset(Pose2D{-2000.f, 2000.f, -1.5708f});
  api::LocalisationBlackboard out;
  localiser.write(out);
  EXPECT_FLOAT_EQ(out.robotPos.x, -2000.f);
  EXPECT_FLOAT_EQ(out.robotPos.theta, -1.5708f);
}

} // namespace
} // namespace touchline::robot::localisation
