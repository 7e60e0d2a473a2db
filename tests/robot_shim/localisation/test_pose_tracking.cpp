// The pose EKF tracking a 60 s walk round the field with biased, drifting odometry and a
// scanning head: the accuracy figures the shim's localisation can be held to.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "synthetic.hpp"
#include "touchline/robot/localisation/pose_filter.hpp"

namespace touchline::robot::localisation {
namespace {

using synthetic::wrap;

struct WalkResult {
  double rms_position_mm = 0;
  double rms_heading_rad = 0;
  double max_position_mm = 0;
  double dead_reckoning_final_mm = 0;  ///< odometry alone, at the end
  double frames_seeing_landmarks = 0;  ///< fraction
  int longest_blind_frames = 0;        ///< longest run of frames without a landmark
  int64_t injected_outliers = 0;
  PoseFilterStats stats;
};

struct WalkSetup {
  bool scan_head = true;        ///< sweep the head +-1 rad; false: look straight ahead
  double max_range_mm = 4000.0; ///< camera range (the world's grows with head pitch, 1000..4000 mm)
  int outlier_every = 0;        ///< every n-th frame, one extra observation with a wrong landmark id
};

/// A 60 s walk from team 0's touchline through waypoints all over the field.
WalkResult walk(unsigned seed, const WalkSetup& setup = {}) {
  constexpr int kFrames = 60 * 30;
  const FieldMap map;
  synthetic::Camera camera;
  camera.max_range_mm = setup.max_range_mm;
  // 5 % long on translation, 5 % short on turns, 0.02 rad/s of heading drift, jitter.
  const synthetic::OdometryError odometry{1.05, 0.95, 0.02, 0.5, 0.002};
  synthetic::WaypointWalker walker({{-2000, 1000}, {1500, 1200}, {2200, -1000}, {-500, -1300}, {-2400, -300},
                                    {0, 500}, {2000, 0}});
  std::mt19937 rng(seed);

  // Where the rules place the robot: its touchline, facing into the field.
  Pose2D truth{-1500.f, -2000.f, static_cast<float>(synthetic::kPiD / 2)};
  PoseFilter filter(map, PoseFilterDef{}, truth);
  Pose2D dead_reckoned = truth;

  WalkResult r;
  double sum_sq_position = 0, sum_sq_heading = 0;
  int seeing = 0, blind = 0;
  for (int frame = 0; frame < kFrames; ++frame) {
    const OdometryDelta motion = walker.step(truth, synthetic::kFrameS);
    truth = synthetic::compose(truth, motion);
    const OdometryDelta reported = odometry.report(motion, synthetic::kFrameS, rng);
    dead_reckoned = synthetic::compose(dead_reckoned, reported);
    filter.predict(reported);

    const double head = setup.scan_head ? synthetic::head_yaw(frame * synthetic::kFrameS) : 0.0;
    auto seen = synthetic::see_landmarks(map, camera, truth, head, rng);
    if (!seen.empty()) {
      ++seeing;
      blind = 0;
    } else {
      r.longest_blind_frames = std::max(r.longest_blind_frames, ++blind);
    }
    if (setup.outlier_every > 0 && frame % setup.outlier_every == 0 && !seen.empty()) {
      Observation wrong = seen.front();
      wrong.id = (wrong.id + 1) % (wrong.kind == ObjectKind::kGoalPost || wrong.kind == ObjectKind::kFieldCorner ? 4 : 2);
      seen.push_back(wrong);
      ++r.injected_outliers;
    }
    for (const Observation& o : seen) filter.update(o);

    const Pose2D estimate = filter.pose();
    const double position = std::hypot(estimate.x_mm - truth.x_mm, estimate.y_mm - truth.y_mm);
    const double heading = wrap(static_cast<double>(estimate.theta_rad) - truth.theta_rad);
    sum_sq_position += position * position;
    sum_sq_heading += heading * heading;
    r.max_position_mm = std::max(r.max_position_mm, position);
  }
  r.rms_position_mm = std::sqrt(sum_sq_position / kFrames);
  r.rms_heading_rad = std::sqrt(sum_sq_heading / kFrames);
  r.dead_reckoning_final_mm = std::hypot(dead_reckoned.x_mm - truth.x_mm, dead_reckoned.y_mm - truth.y_mm);
  r.frames_seeing_landmarks = static_cast<double>(seeing) / kFrames;
  r.stats = filter.stats();
  return r;
}

void report(const char* name, unsigned seed, const WalkResult& r) {
  std::cout << "[ figures  ] " << name << " seed " << seed << ": RMS " << r.rms_position_mm << " mm / "
            << r.rms_heading_rad << " rad, max " << r.max_position_mm << " mm; odometry alone ends "
            << r.dead_reckoning_final_mm << " mm off; landmarks seen in " << 100 * r.frames_seeing_landmarks
            << " % of frames (longest gap " << r.longest_blind_frames << " frames); accepted " << r.stats.accepted << ", rejected " << r.stats.rejected
            << ", inflations " << r.stats.inflations;
  if (r.injected_outliers > 0) std::cout << "; wrong ids injected " << r.injected_outliers;
  std::cout << "\n";
}

// Bounds: the target is 150 mm / 0.1 rad RMS. Measured over seeds 1..5 (scanning head,
// 4 m range): 22-29 mm / 0.013-0.015 rad RMS, at most 142 mm off at any moment. The
// asserted 75 mm / 0.04 rad leave a 2.5x margin over the worst seed for noise and
// parameter tuning, yet would catch a filter that merely followed the odometry (it ends
// 2.6-2.9 m off) or one that mishandled the biased turns.
constexpr double kMaxRmsPositionMm = 75.0;
constexpr double kMaxRmsHeadingRad = 0.04;

TEST(PoseTracking, SixtySecondWalkWithBiasedOdometry) {
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    const WalkResult r = walk(seed);
    report("walk", seed, r);
    // Odometry alone is far worse: the filter is doing the work.
    EXPECT_GT(r.dead_reckoning_final_mm, 1000.0);
    EXPECT_GT(r.frames_seeing_landmarks, 0.8);
    EXPECT_LT(r.rms_position_mm, kMaxRmsPositionMm);
    EXPECT_LT(r.rms_heading_rad, kMaxRmsHeadingRad);
    EXPECT_EQ(r.stats.inflations, 0);
  }
}

TEST(PoseTracking, SixtySecondWalkLookingStraightAheadWithShortRange) {
  // Fewer sightings: no head scan and a 3 m camera range, so stretches of seconds see
  // nothing. Still well inside the target.
  WalkSetup setup;
  setup.scan_head = false;
  setup.max_range_mm = 3000.0;
  for (unsigned seed : {1u, 2u, 3u}) {
    const WalkResult r = walk(seed, setup);
    report("walk, head still, 3 m range", seed, r);
    EXPECT_LT(r.rms_position_mm, 150.0);
    EXPECT_LT(r.rms_heading_rad, 0.1);
  }
}

TEST(PoseTracking, WrongLandmarkIdsAreRejectedDuringTheWalk) {
  const unsigned seed = 1;
  const WalkResult clean = walk(seed);
  WalkSetup setup;
  setup.outlier_every = 10;
  const WalkResult r = walk(seed, setup);
  report("walk with outliers", seed, r);
  ASSERT_GT(r.injected_outliers, 100);
  // Nearly all wrong ids are rejected; one whose swapped landmark happens to lie in
  // nearly the same direction and distance cannot be told apart (and does little harm).
  EXPECT_GE(static_cast<double>(r.stats.rejected - clean.stats.rejected), 0.95 * static_cast<double>(r.injected_outliers));
  EXPECT_LT(r.rms_position_mm, kMaxRmsPositionMm);
  EXPECT_LT(r.rms_heading_rad, kMaxRmsHeadingRad);
}

} // namespace
} // namespace touchline::robot::localisation
