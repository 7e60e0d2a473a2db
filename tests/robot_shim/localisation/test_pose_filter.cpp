// The pose EKF on synthetic data: convergence, covariance growth, gating, angle wrapping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "synthetic.hpp"
#include "touchline/robot/localisation/pose_filter.hpp"

namespace touchline::robot::localisation {
namespace {

using synthetic::kPiD;
using synthetic::wrap;

double position_error(const PoseFilter& f, const Pose2D& truth) {
  const Pose2D p = f.pose();
  return std::hypot(p.x_mm - truth.x_mm, p.y_mm - truth.y_mm);
}
double heading_error(const PoseFilter& f, const Pose2D& truth) {
  return std::fabs(wrap(static_cast<double>(f.pose().theta_rad) - truth.theta_rad));
}
double trace(const PoseCovariance& c) { return c[0] + c[4] + c[8]; }

TEST(OdometryDelta, IsTheMotionInTheRobotFrameOfTheStart) {
  const Pose2D before{100.f, -50.f, 3.0f};
  const OdometryDelta d{80.0, -20.0, 0.4};
  const Pose2D after = synthetic::compose(before, d);  // crosses +pi
  const OdometryDelta back = odometry_delta(before, after);
  EXPECT_NEAR(back.dx_mm, 80.0, 1e-3);
  EXPECT_NEAR(back.dy_mm, -20.0, 1e-3);
  EXPECT_NEAR(back.dtheta_rad, 0.4, 1e-5);
}

/// Stands at `truth` seeing both posts of the goal in front, starting `offset` off.
int frames_to_converge(const Pose2D& truth, const Pose2D& offset, unsigned seed) {
  PoseFilter filter(FieldMap{}, PoseFilterDef{},
                    Pose2D{truth.x_mm + offset.x_mm, truth.y_mm + offset.y_mm,
                           static_cast<float>(wrap(truth.theta_rad + offset.theta_rad))});
  std::mt19937 rng(seed);
  const FieldMap map;
  const synthetic::Camera camera;
  int converged_since = -1;
  for (int frame = 0; frame < 300; ++frame) {
    filter.predict({});  // standing still
    for (const Observation& o : synthetic::see_landmarks(map, camera, truth, 0.0, rng))
      if (o.kind == ObjectKind::kGoalPost) filter.update(o);  // the posts alone (the penalty mark is in view too)
    const bool close = position_error(filter, truth) < 100.0 && heading_error(filter, truth) < 0.05;
    if (!close) converged_since = -1;
    else if (converged_since < 0) converged_since = frame + 1;
  }
  EXPECT_EQ(filter.stats().inflations, 0) << "the initial error is within the initial covariance";
  return converged_since;
}

TEST(PoseFilter, ConvergesFrom500mmAnd0_3RadSeeingPosts) {
  // 2 m in front of team 1's goal, facing it: both its posts (2 and 3) in view, nothing else.
  const Pose2D truth{1000.f, 0.f, 0.05f};
  const Pose2D offsets[] = {{500.f, 0.f, 0.3f},   {0.f, 500.f, -0.3f},    {-400.f, 300.f, 0.3f},
                            {-500.f, 0.f, -0.3f}, {354.f, -354.f, 0.3f},  {0.f, -500.f, -0.3f}};
  int worst = 0;
  unsigned seed = 1;
  for (const Pose2D& offset : offsets) {
    const int frames = frames_to_converge(truth, offset, seed++);
    ASSERT_GE(frames, 0) << "never converged from offset " << offset.x_mm << ", " << offset.y_mm;
    std::cout << "[ figures  ] from (" << offset.x_mm << " mm, " << offset.y_mm << " mm, " << offset.theta_rad
              << " rad) off: " << frames << " frames\n";
    worst = std::max(worst, frames);
  }
  std::cout << "[ figures  ] converged to < 100 mm / 0.05 rad (and stayed) within " << worst
            << " frames (worst of 6 starts)\n";
  RecordProperty("worst_convergence_frames", worst);
  // Measured: 1-25 frames. Ahead-only posts pin range and bearing fast; a sideways
  // offset traded against heading shows only in the posts' range difference, which takes
  // most of a second of sightings. 45 frames (1.5 s) leaves room for tuning.
  EXPECT_LE(worst, 45);
}

TEST(PoseFilter, NearLandmarkSeenFromAPoorGuessDoesNotMakeItOverconfident) {
  // Team 1's penalty mark 200 mm ahead, seen from a guess 500 mm and 0.3 rad off: at the
  // guess it would be 400 mm away at 2 rad. A single linearisation there left a plain
  // EKF 340 mm off with a 27 mm sigma; the iterated update must stay consistent.
  const Pose2D truth{1000.f, 0.f, 0.05f};
  const FieldMap map;
  const synthetic::Camera camera;
  for (int iterations : {1, PoseFilterDef{}.update_iterations}) {
    PoseFilterDef def;
    def.update_iterations = iterations;
    PoseFilter filter(map, def, Pose2D{1354.f, -354.f, 0.35f});
    std::mt19937 rng(5);
    filter.predict({});
    for (const Observation& o : synthetic::see_landmarks(map, camera, truth, 0.0, rng)) filter.update(o);
    const Pose2D p = filter.pose();
    // Normalised errors per axis (3 sigma: 99.7 % for a consistent filter).
    const double nx = std::fabs(p.x_mm - truth.x_mm) / filter.sigma_x_mm();
    const double ny = std::fabs(p.y_mm - truth.y_mm) / filter.sigma_y_mm();
    const double nt = heading_error(filter, truth) / filter.sigma_theta_rad();
    if (iterations == 1) {
      EXPECT_GT(std::max({nx, ny, nt}), 3.0) << "the plain EKF's failure this guards against";
    } else {
      EXPECT_LT(std::max({nx, ny, nt}), 3.0);
      EXPECT_LT(position_error(filter, truth), 100.0);
    }
  }
}

TEST(PoseFilter, RecoversFromAKidnapByWideningItsCovariance) {
  // Believes it is 2 m away from where it stands: the gate rejects everything at first,
  // then the covariance inflation lets the landmarks pull it back.
  const Pose2D truth{1000.f, 0.f, 0.05f};
  PoseFilter filter(FieldMap{}, PoseFilterDef{}, Pose2D{-1000.f, 300.f, 0.05f});
  std::mt19937 rng(7);
  const FieldMap map;
  const synthetic::Camera camera;
  for (int frame = 0; frame < 150; ++frame) {
    filter.predict({});
    for (const Observation& o : synthetic::see_landmarks(map, camera, truth, 0.0, rng)) filter.update(o);
  }
  EXPECT_GE(filter.stats().inflations, 1);
  EXPECT_LT(position_error(filter, truth), 100.0);
  EXPECT_LT(heading_error(filter, truth), 0.05);
}

/// A well-localised robot at `at` that a contact turned by `turn` rad, unseen by odometry:
/// the filter after `frames` frames of the landmarks in view (heading_jump_votes 0: no re-aim).
PoseFilter turned_by_a_contact(const Pose2D& at, double turn, int frames, int heading_jump_votes) {
  PoseFilterDef def;
  def.heading_jump_votes = heading_jump_votes;
  PoseFilter filter(FieldMap{}, def, at);
  filter.reset(at, diagonal_covariance(40, 40, 0.03));
  const Pose2D truth{at.x_mm, at.y_mm, static_cast<float>(wrap(at.theta_rad + turn))};
  std::mt19937 rng(5);
  const FieldMap map;
  const synthetic::Camera camera;
  for (int frame = 0; frame < frames; ++frame) {
    filter.predict({});
    for (const Observation& o : synthetic::see_landmarks(map, camera, truth, 0.0, rng)) filter.update(o);
  }
  return filter;
}

TEST(PoseFilter, ReAimsAHeadingAContactTurnedOnTheLandmarksWithoutMovingThePosition) {
  // 2 m in front of team 1's goal, believing it faces the touchline, turned 1.2 rad by a
  // push to face the goal: it sees the posts' ranges as it expects and their bearings
  // 1.2 rad off, so its heading is wrong, not its position.
  const Pose2D at{1000.f, 0.f, 1.25f};
  const double turn = -1.2;
  const Pose2D truth{at.x_mm, at.y_mm, static_cast<float>(wrap(at.theta_rad + turn))};
  const PoseFilter filter = turned_by_a_contact(at, turn, 3, PoseFilterDef{}.heading_jump_votes);
  EXPECT_EQ(filter.stats().heading_jumps, 1);
  EXPECT_LT(heading_error(filter, truth), 0.05);
  EXPECT_LT(position_error(filter, truth), 100.0);
  // Without it, the filter waits for 10 rejections in a row before widening its covariance.
  const PoseFilter widened = turned_by_a_contact(at, turn, 3, 0);
  EXPECT_EQ(widened.stats().heading_jumps, 0);
  EXPECT_GT(heading_error(widened, truth), 1.0);
}

TEST(PoseFilter, AKidnapIsNoHeadingJump) {
  // Carried 1.5 m: the ranges disagree too, so no landmark votes for a heading error.
  const Pose2D truth{1000.f, 0.f, 0.05f};
  PoseFilter filter(FieldMap{}, PoseFilterDef{}, Pose2D{-500.f, 0.f, 0.05f});
  filter.reset(Pose2D{-500.f, 0.f, 0.05f}, diagonal_covariance(40, 40, 0.03));
  std::mt19937 rng(9);
  const FieldMap map;
  const synthetic::Camera camera;
  for (int frame = 0; frame < 5; ++frame) {
    filter.predict({});
    for (const Observation& o : synthetic::see_landmarks(map, camera, truth, 0.0, rng)) filter.update(o);
  }
  EXPECT_GT(filter.stats().rejected, 0);
  EXPECT_EQ(filter.stats().heading_jumps, 0);
}

TEST(PoseFilter, WithTheGyroTheHeadingGrowsAsTheGyroMakesItNotAsTheWalk) {
  // 10 s walking round a bend. The walk's heading noise (feet slipping, contacts turning the
  // body) is the gyro's to feel, so with the gyro's turn only the gyro's own noise is left.
  // A heading sure to 0.09 rad, not 0.23, keeps a landmark whose bearing a position dragged
  // off by a blocked walk explains from re-aiming the heading instead (seed 80 of the team
  // results: 0.4 rad that way, then 30 s lost).
  PoseFilter gyro, walk;
  gyro.reset(Pose2D{}, diagonal_covariance(50, 50, 0.01));
  walk.reset(Pose2D{}, diagonal_covariance(50, 50, 0.01));
  for (int frame = 0; frame < 300; ++frame) {
    gyro.predict({7.0, 0.0, 0.01, true});
    walk.predict({7.0, 0.0, 0.01, false});
  }
  std::cout << "[ figures  ] heading sigma after 10 s: " << gyro.sigma_theta_rad() << " rad with the gyro's turn, "
            << walk.sigma_theta_rad() << " rad with the walk's\n";
  const PoseFilterDef def;
  const double gyro_var = 0.01 * 0.01 + 300 * (def.gyro_theta_var_per_call + def.gyro_theta_var_per_mm * 7.0 +
                                                def.gyro_theta_var_per_rad * 0.01);
  EXPECT_NEAR(gyro.sigma_theta_rad(), std::sqrt(gyro_var), 1e-6);
  EXPECT_LT(gyro.sigma_theta_rad(), 0.5 * walk.sigma_theta_rad());
  EXPECT_GT(gyro.sigma_x_mm(), 100.0) << "the steps' own noise still grows the position's";
  EXPECT_NEAR(gyro.pose().theta_rad, walk.pose().theta_rad, 1e-9) << "the same turn";
}

TEST(PoseFilter, CovarianceGrowsWithoutObservations) {
  PoseFilter filter;
  filter.reset(Pose2D{0.f, 0.f, 0.f}, diagonal_covariance(10, 10, 0.01));
  double previous = trace(filter.covariance());
  // Standing still: slowly.
  for (int i = 0; i < 30; ++i) {
    filter.predict({});
    EXPECT_GT(trace(filter.covariance()), previous);
    previous = trace(filter.covariance());
  }
  const double still_growth = filter.sigma_x_mm() - 10.0;
  // Walking and turning: faster, and heading uncertainty spreads into position.
  for (int i = 0; i < 300; ++i) {
    filter.predict({7.0, 0.0, 0.02});
    EXPECT_GT(trace(filter.covariance()), previous);
    previous = trace(filter.covariance());
  }
  EXPECT_GT(filter.sigma_x_mm() - 10.0, 10 * still_growth);
  EXPECT_GT(filter.sigma_theta_rad(), 0.05);
  // The estimate moved with the odometry: 300 steps of 7 mm round a circle of radius 350 mm.
  EXPECT_NEAR(filter.pose().theta_rad, wrap(300 * 0.02), 1e-3);
}

TEST(PoseFilter, RejectsAWrongLandmarkIdByGating) {
  const Pose2D truth{1200.f, 300.f, 0.1f};
  PoseFilter filter(FieldMap{}, PoseFilterDef{}, truth);
  filter.reset(truth, diagonal_covariance(50, 50, 0.03));  // well localised
  std::mt19937 rng(3);
  const FieldMap map;
  // Team 1's left post (id 2) reported as its right post (id 3): 1.4 m off.
  const FieldPoint left = *map.landmark(ObjectKind::kGoalPost, 2);
  Observation wrong = synthetic::observe(truth, left.x_mm, left.y_mm, ObjectKind::kGoalPost, 3, {}, rng);
  const Pose2D before = filter.pose();
  EXPECT_EQ(filter.update(wrong), UpdateResult::kRejected);
  EXPECT_EQ(filter.stats().rejected, 1);
  EXPECT_GT(filter.stats().last_mahalanobis_sq, PoseFilterDef{}.gate_mahalanobis_sq);
  EXPECT_EQ(filter.pose().x_mm, before.x_mm);
  EXPECT_EQ(filter.pose().theta_rad, before.theta_rad);
  // The right id is accepted.
  wrong.id = 2;
  EXPECT_EQ(filter.update(wrong), UpdateResult::kAccepted);
  EXPECT_EQ(filter.stats().accepted, 1);
}

TEST(PoseFilter, IgnoresBallsRobotsAndUnknownIds) {
  PoseFilter filter;
  Observation o;
  o.distance_mm = 1000;
  o.kind = ObjectKind::kBall;
  EXPECT_EQ(filter.update(o), UpdateResult::kIgnored);
  o.kind = ObjectKind::kOpponent;
  EXPECT_EQ(filter.update(o), UpdateResult::kIgnored);
  o.kind = ObjectKind::kGoalPost;
  o.id = 9;
  EXPECT_EQ(filter.update(o), UpdateResult::kIgnored);
  o.id = 0;
  o.distance_mm = 10;  // on top of it: the bearing means nothing
  EXPECT_EQ(filter.update(o), UpdateResult::kIgnored);
  EXPECT_EQ(filter.stats().ignored, 4);
}

TEST(PoseFilter, BearingInnovationWrapsAcrossPi) {
  // Team 0's left post (-3000, -700) dead behind a robot at (-2000, -700) facing +x:
  // seen at +3.13 rad while predicted at -pi. Unwrapped, that is a 6.2 rad innovation.
  const Pose2D truth{-2000.f, -700.f, 0.f};
  PoseFilter filter(FieldMap{}, PoseFilterDef{}, truth);
  Observation o;
  o.kind = ObjectKind::kGoalPost;
  o.id = 0;
  o.distance_mm = 1000;
  o.heading_rad = 3.13f;
  EXPECT_EQ(filter.update(o), UpdateResult::kAccepted);
  EXPECT_LT(filter.stats().last_mahalanobis_sq, 1.0);
  EXPECT_LT(heading_error(filter, truth), 0.02);
  o.heading_rad = -3.13f;
  EXPECT_EQ(filter.update(o), UpdateResult::kAccepted);
  EXPECT_LT(heading_error(filter, truth), 0.02);
}

TEST(PoseFilter, HeadingWrapsAcrossPiWhileTurningAndUpdating) {
  // Facing -x (theta ~ pi) in front of team 0's goal, turning on the spot through +-pi
  // with the estimate on the other side of the seam from the truth.
  Pose2D truth{-1500.f, 0.f, static_cast<float>(kPiD - 0.2)};
  PoseFilter filter(FieldMap{}, PoseFilterDef{}, Pose2D{-1500.f, 0.f, static_cast<float>(-kPiD + 0.05)});
  std::mt19937 rng(11);
  const FieldMap map;
  const synthetic::Camera camera;
  for (int frame = 0; frame < 60; ++frame) {
    const OdometryDelta turn{0.0, 0.0, 0.4 / 30};  // 0.4 rad/s, left
    truth = synthetic::compose(truth, turn);
    filter.predict(turn);
    for (const Observation& o : synthetic::see_landmarks(map, camera, truth, 0.0, rng)) filter.update(o);
    const float theta = filter.pose().theta_rad;
    EXPECT_GE(theta, -synthetic::kPiD);
    EXPECT_LT(theta, synthetic::kPiD);
    if (frame >= 20) {
      EXPECT_LT(heading_error(filter, truth), 0.05) << "frame " << frame;
    }
  }
  EXPECT_LT(truth.theta_rad, 0.f) << "the truth crossed the seam";
  EXPECT_LT(position_error(filter, truth), 100.0);
  EXPECT_EQ(filter.stats().rejected, 0);
}

} // namespace
} // namespace touchline::robot::localisation
