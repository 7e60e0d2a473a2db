// The ball's Kalman filter on synthetic sightings: a ball at rest, a rolling ball, a
// kicked ball, a ball lost from view, and a pose estimate that a landmark corrects.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "synthetic.hpp"
#include "touchline/robot/localisation/ball_filter.hpp"

namespace touchline::robot::localisation {
namespace {

/// The world's ball: rolling deceleration plus linear damping (its defaults), integrated
/// in 1 ms steps.
struct RollingBall {
  double x, y, vx, vy;
  void advance(double dt_s) {
    for (double t = 0; t < dt_s - 1e-9; t += 1e-3) {
      const double speed = std::hypot(vx, vy);
      if (speed <= 0) return;
      const double slowed = std::max(0.0, speed - (300.0 + 0.2 * speed) * 1e-3) / speed;
      x += vx * 1e-3;
      y += vy * 1e-3;
      vx *= slowed;
      vy *= slowed;
    }
  }
};

const Pose2D kRobot{-500.f, -300.f, 0.3f};

Observation sight(const RollingBall& ball, std::mt19937& rng) {
  return synthetic::observe(kRobot, ball.x, ball.y, ObjectKind::kBall, 0, synthetic::CameraNoise{}, rng);
}

double position_error(const BallFilter& f, const RollingBall& b) {
  return std::hypot(f.position().x_mm - b.x, f.position().y_mm - b.y);
}
double velocity_error(const BallFilter& f, const RollingBall& b) {
  return std::hypot(f.velocity().x_mm - b.vx, f.velocity().y_mm - b.vy);
}

constexpr int kSeeds = 20;

TEST(BallFilter, StationaryBallConverges) {
  // 20 runs of 2 s looking at a ball 1.4 m away (sightings ~90 mm sigma in range).
  double sum_sq_first = 0, sum_sq_position = 0, sum_sq_speed = 0;
  for (unsigned seed = 1; seed <= kSeeds; ++seed) {
    BallFilter filter;
    EXPECT_FALSE(filter.seen());
    const RollingBall ball{800, 400, 0, 0};
    std::mt19937 rng(seed);
    for (int frame = 0; frame < 60; ++frame) {
      filter.predict(synthetic::kFrameS);
      filter.update(sight(ball, rng), kRobot);
      if (frame == 0) sum_sq_first += std::pow(position_error(filter, ball), 2);
    }
    sum_sq_position += std::pow(position_error(filter, ball), 2);
    sum_sq_speed += std::pow(velocity_error(filter, ball), 2);
    EXPECT_TRUE(filter.seen());
    EXPECT_EQ(filter.lost_count(), 0);
    EXPECT_EQ(filter.stats().reinitialisations, 0);
  }
  const double first = std::sqrt(sum_sq_first / kSeeds), position = std::sqrt(sum_sq_position / kSeeds),
               speed = std::sqrt(sum_sq_speed / kSeeds);
  std::cout << "[ figures  ] stationary ball 1.4 m away, RMS of " << kSeeds << " runs: first sighting " << first
            << " mm, after 2 s " << position << " mm and " << speed << " mm/s\n";
  // Averaging: well under a single sighting's error. (Velocity is unknown at first, so
  // the end of 60 sightings is about twice as uncertain as their plain mean would be.)
  EXPECT_LT(position, 0.5 * first);
  EXPECT_LT(position, 40.0);
  EXPECT_LT(speed, 50.0);
}

TEST(BallFilter, RollingBallVelocityIsEstimated) {
  double sum_sq_v1 = 0, sum_sq_v15 = 0, sum_sq_position = 0;
  double speed_at_1s = 0;
  for (unsigned seed = 1; seed <= kSeeds; ++seed) {
    BallFilter filter;
    RollingBall ball{-200, -800, 1200, 600};
    std::mt19937 rng(seed);
    for (int frame = 0; frame < 45; ++frame) {
      if (frame > 0) ball.advance(synthetic::kFrameS);
      filter.predict(synthetic::kFrameS);
      filter.update(sight(ball, rng), kRobot);
      if (frame == 29) {
        sum_sq_v1 += std::pow(velocity_error(filter, ball), 2);
        speed_at_1s = std::hypot(ball.vx, ball.vy);
      }
    }
    sum_sq_v15 += std::pow(velocity_error(filter, ball), 2);
    sum_sq_position += std::pow(position_error(filter, ball), 2);
    EXPECT_EQ(filter.stats().reinitialisations, 0);
  }
  const double v1 = std::sqrt(sum_sq_v1 / kSeeds), v15 = std::sqrt(sum_sq_v15 / kSeeds),
               position = std::sqrt(sum_sq_position / kSeeds);
  std::cout << "[ figures  ] rolling ball (1342 mm/s at the start, " << speed_at_1s << " mm/s at 1 s), RMS of "
            << kSeeds << " runs: velocity " << v1 << " mm/s off after 1 s, " << v15 << " mm/s after 1.5 s; position "
            << position << " mm\n";
  EXPECT_LT(v1, 100.0);
  EXPECT_LT(v15, 100.0);
  EXPECT_LT(position, 50.0);
}

TEST(BallFilter, KickedBallIsFollowed) {
  BallFilter filter;
  RollingBall ball{500, 0, 0, 0};
  std::mt19937 rng(3);
  for (int frame = 0; frame < 30; ++frame) {
    filter.predict(synthetic::kFrameS);
    filter.update(sight(ball, rng), kRobot);
  }
  ball.vx = -1500;  // kicked back towards the robot's side
  ball.vy = 800;
  for (int frame = 0; frame < 30; ++frame) {
    ball.advance(synthetic::kFrameS);
    filter.predict(synthetic::kFrameS);
    filter.update(sight(ball, rng), kRobot);
  }
  std::cout << "[ figures  ] kicked ball: 1 s after the kick, " << position_error(filter, ball) << " mm and "
            << velocity_error(filter, ball) << " mm/s off; " << filter.stats().reinitialisations
            << " re-initialisations\n";
  EXPECT_LT(position_error(filter, ball), 100.0);
  EXPECT_LT(velocity_error(filter, ball), 300.0);
}

TEST(BallFilter, LostBallCountsFramesAndComesToRestAlongItsPath) {
  BallFilter filter;
  RollingBall ball{0, -600, 1000, 0};
  std::mt19937 rng(4);
  for (int frame = 0; frame < 30; ++frame) {
    if (frame > 0) ball.advance(synthetic::kFrameS);
    filter.predict(synthetic::kFrameS);
    filter.update(sight(ball, rng), kRobot);
  }
  const double sigma_seen = filter.position_sigma_mm();
  for (int frame = 1; frame <= 150; ++frame) {  // 5 s out of view
    ball.advance(synthetic::kFrameS);
    filter.predict(synthetic::kFrameS);
    EXPECT_EQ(filter.lost_count(), frame);
  }
  std::cout << "[ figures  ] ball lost for 5 s: the true ball rests at x " << ball.x << ", the estimate at "
            << filter.position().x_mm << " (" << position_error(filter, ball) << " mm off), sigma "
            << filter.position_sigma_mm() << " mm\n";
  // It rolled on and stopped: no velocity left, near where the ball really stopped.
  EXPECT_EQ(ball.vx, 0.0);
  EXPECT_NEAR(std::hypot(filter.velocity().x_mm, filter.velocity().y_mm), 0.0, 1e-9);
  EXPECT_LT(position_error(filter, ball), 300.0);
  // And it knows it does not know.
  EXPECT_GT(filter.position_sigma_mm(), 5 * sigma_seen);
  // Seen again: the count resets.
  filter.update(sight(ball, rng), kRobot);
  EXPECT_EQ(filter.lost_count(), 0);
}

TEST(BallFilter, LostBallAtRestHoldsItsPlace) {
  BallFilter filter;
  const RollingBall ball{-100, 700, 0, 0};
  std::mt19937 rng(5);
  for (int frame = 0; frame < 30; ++frame) {
    filter.predict(synthetic::kFrameS);
    filter.update(sight(ball, rng), kRobot);
  }
  const FieldPoint held = filter.position();
  for (int frame = 0; frame < 300; ++frame) filter.predict(synthetic::kFrameS);
  EXPECT_EQ(filter.lost_count(), 300);
  EXPECT_LT(std::hypot(filter.position().x_mm - held.x_mm, filter.position().y_mm - held.y_mm), 20.0);
}

TEST(BallFilter, SightingUsesTheRobotPoseAndReportsRobotRelative) {
  BallFilter filter;
  Observation o;
  o.kind = ObjectKind::kBall;
  o.distance_mm = 1000;
  o.heading_rad = static_cast<float>(synthetic::kPiD / 2);  // to the robot's left
  const Pose2D robot{1000.f, 0.f, static_cast<float>(synthetic::kPiD / 2)};  // facing +y
  filter.predict(synthetic::kFrameS);
  ASSERT_TRUE(filter.update(o, robot));
  EXPECT_NEAR(filter.position().x_mm, 0.0, 1e-3);  // left of facing +y is -x
  EXPECT_NEAR(filter.position().y_mm, 0.0, 1e-3);
  const api::RRCoord rr = filter.relative_to(robot);
  EXPECT_NEAR(rr.distance, 1000.f, 1e-2f);
  EXPECT_NEAR(rr.heading, synthetic::kPiD / 2, 1e-4);
  // A robot observation is not a ball.
  o.kind = ObjectKind::kOpponent;
  EXPECT_FALSE(filter.update(o, robot));
}

TEST(BallFilter, ACorrectedPoseTakesTheBallAlong) {
  // The ball was seen from the pose estimate: when a landmark moves that estimate, the ball
  // keeps its place relative to the robot, with its velocity and uncertainty turned too.
  BallFilter filter;
  RollingBall ball{300, 200, 400, -100};
  std::mt19937 rng(6);
  for (int frame = 0; frame < 20; ++frame) {
    if (frame > 0) ball.advance(synthetic::kFrameS);
    filter.predict(synthetic::kFrameS);
    filter.update(sight(ball, rng), kRobot);
  }
  const api::RRCoord seen = filter.relative_to(kRobot);
  const double speed = std::hypot(filter.velocity().x_mm, filter.velocity().y_mm);
  const double sigma = filter.position_sigma_mm();
  const double direction = std::atan2(filter.velocity().y_mm, filter.velocity().x_mm);
  const Pose2D corrected{kRobot.x_mm + 150.f, kRobot.y_mm - 80.f, kRobot.theta_rad + 0.4f};
  filter.move_with(kRobot, corrected);
  const api::RRCoord after = filter.relative_to(corrected);
  EXPECT_NEAR(after.distance, seen.distance, 1e-3f);
  EXPECT_NEAR(after.heading, seen.heading, 1e-5f);
  EXPECT_NEAR(std::hypot(filter.velocity().x_mm, filter.velocity().y_mm), speed, 1e-6);
  EXPECT_NEAR(filter.position_sigma_mm(), sigma, 1e-6);
  // Its direction on the field turned with the robot's heading.
  EXPECT_NEAR(std::atan2(filter.velocity().y_mm, filter.velocity().x_mm), direction + 0.4, 1e-5);
}

TEST(BallFilter, ABallNeverSeenStaysWhereItIsThoughtToBe) {
  BallFilter filter;
  filter.move_with(Pose2D{}, Pose2D{500.f, 0.f, 1.f});
  EXPECT_EQ(filter.position().x_mm, 0.0);
  EXPECT_EQ(filter.position().y_mm, 0.0);
}

TEST(BallFilter, OnTheFieldTheBallIsAsUncertainAsThePoseItIsSeenFrom) {
  BallFilter filter;
  Observation o;
  o.kind = ObjectKind::kBall;
  o.distance_mm = 2000;
  const Pose2D robot{};
  filter.update(o, robot);
  const std::array<double, 4> certain = filter.field_position_covariance(robot, {});
  const std::array<double, 16>& track = filter.covariance();
  EXPECT_DOUBLE_EQ(certain[0], track[0]);
  EXPECT_DOUBLE_EQ(certain[3], track[5]);
  const std::array<double, 4> uncertain =
      filter.field_position_covariance(robot, diagonal_covariance(200, 200, 0.2));
  // Ahead of the robot: x by its x sigma, y by its y sigma and the heading's 0.2 rad at 2 m.
  EXPECT_NEAR(uncertain[0], track[0] + 200.0 * 200.0, 1e-6);
  EXPECT_NEAR(uncertain[3], track[5] + 200.0 * 200.0 + std::pow(0.2 * 2000.0, 2), 1e-6);
  EXPECT_DOUBLE_EQ(uncertain[1], uncertain[2]);
}

} // namespace
} // namespace touchline::robot::localisation
