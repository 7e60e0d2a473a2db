// The perception pipeline's noise and faults, statistically over many seeded frames:
// false-negative rates, the distance and bearing noise models, phantom balls, sonar
// noise; and determinism: the same seed gives the same observations bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include "perception_scenes.hpp"
#include "touchline/angles.hpp"
#include "touchline/sim/perception.hpp"

namespace touchline::sim {
namespace {

using testing::ball_at;
using testing::find;
using testing::exact;
using testing::viewer;

const Field kField; // SPL 2011


/// Mean and sample standard deviation.
struct Moments {
  double mean = 0, sd = 0;
};
Moments moments(const std::vector<double>& xs) {
  double sum = 0;
  for (double x : xs) sum += x;
  Moments m;
  m.mean = sum / static_cast<double>(xs.size());
  double ss = 0;
  for (double x : xs) ss += (x - m.mean) * (x - m.mean);
  m.sd = std::sqrt(ss / static_cast<double>(xs.size() - 1));
  return m;
}

/// Expects `hits` of `n` Bernoulli(p) trials within 3 sigma of n p.
void expect_rate(const char* what, int hits, int n, double p) {
  const double sigma = std::sqrt(n * p * (1 - p));
  std::printf("  %s: %d of %d (%.4f; configured %.4f, 3 sigma = %.4f)\n", what, hits, n,
              static_cast<double>(hits) / n, p, 3 * sigma / n);
  EXPECT_LE(std::fabs(hits - n * p), 3 * sigma) << what;
}

TEST(PerceptionNoise, FalseNegativeRatesMatchTheConfiguredProbabilities) {
  // In view and unhidden every frame: the ball, penalty mark 1 and an opponent.
  PerceptionDef def = exact();
  def.noise.ball_miss_probability = 0.1f;
  def.noise.landmark_miss_probability = 0.25f;
  def.noise.robot_miss_probability = 0.4f;
  Perception perception(kField, def, 2024);
  const Viewer me = viewer(0, 1, 0, 0, 0);
  const std::vector<Viewer> robots{me, viewer(1, 1, 2000, 400, kPi)};
  const int n = 10000;
  int ball = 0, mark = 0, robot = 0;
  for (int i = 0; i < n; ++i) {
    const auto seen = perception.observe(me, robots, ball_at(1000, -200), i);
    ball += !find(seen, ObjectKind::kBall);
    mark += !find(seen, ObjectKind::kPenaltyMark, 1);
    robot += !find(seen, ObjectKind::kOpponent, 1);
  }
  expect_rate("ball missed", ball, n, 0.1);
  expect_rate("landmark missed", mark, n, 0.25);
  expect_rate("robot missed", robot, n, 0.4);
}

TEST(PerceptionNoise, DistanceNoiseFollowsTheLinearSigmaModel) {
  // sigma = 10 mm + 5 % of the distance: 60 mm at 1000 mm, 160 mm at 3000 mm.
  PerceptionDef def = exact();
  def.noise.distance_sd_mm = 10;
  def.noise.distance_sd_fraction = 0.05f;
  Perception perception(kField, def, 5);
  const Viewer me = viewer(0, 1, -2000, 0, 0);
  const int n = 20000;
  for (float distance : {1000.f, 3000.f}) {
    std::vector<double> errors;
    for (int i = 0; i < n; ++i) {
      const auto seen = perception.observe(me, {me}, ball_at(-2000 + distance, 0), i);
      errors.push_back(find(seen, ObjectKind::kBall)->distance_mm - distance);
    }
    const double sigma = 10 + 0.05 * distance;
    const Moments m = moments(errors);
    std::printf("  distance %.0f mm: error mean %.2f mm, sd %.2f mm (model %.1f mm, %+.2f %%)\n", distance, m.mean,
                m.sd, sigma, 100 * (m.sd / sigma - 1));
    EXPECT_NEAR(m.sd / sigma, 1.0, 0.03);
    EXPECT_LT(std::fabs(m.mean), 4 * sigma / std::sqrt(n)); // unbiased
  }
}

TEST(PerceptionNoise, BearingNoiseGrowsWithDistance) {
  // sigma = 0.02 rad + 0.01 rad per metre: 0.03 rad at 1 m, 0.05 rad at 3 m.
  PerceptionDef def = exact();
  def.noise.bearing_sd_rad = 0.02f;
  def.noise.bearing_sd_rad_per_m = 0.01f;
  Perception perception(kField, def, 6);
  const Viewer me = viewer(0, 1, -2000, 0, 0);
  const int n = 20000;
  for (float distance : {1000.f, 3000.f}) {
    std::vector<double> headings;
    bool image_x_follows = true;
    for (int i = 0; i < n; ++i) {
      const auto seen = perception.observe(me, {me}, ball_at(-2000 + distance, 0), i);
      const Observation* ball = find(seen, ObjectKind::kBall);
      headings.push_back(ball->heading_rad);
      // The image coordinate moves with the bearing: 1/60 of the image per degree.
      image_x_follows &= std::fabs(ball->image_x - (0.5f + ball->heading_rad / (kPi / 3))) < 1e-5f;
      EXPECT_EQ(ball->distance_mm, distance); // distance noise is off
    }
    const double sigma = 0.02 + 0.01 * distance / 1000;
    const Moments m = moments(headings);
    std::printf("  distance %.0f mm: bearing mean %.5f rad, sd %.5f rad (model %.3f rad, %+.2f %%)\n", distance,
                m.mean, m.sd, sigma, 100 * (m.sd / sigma - 1));
    EXPECT_NEAR(m.sd / sigma, 1.0, 0.03);
    EXPECT_LT(std::fabs(m.mean), 4 * sigma / std::sqrt(n));
    EXPECT_TRUE(image_x_follows);
  }
}

TEST(PerceptionNoise, ImageXStaysInTheImageAtTheEdge) {
  // An object 29 degrees off the head axis with 3-degree bearing noise: noise often
  // pushes it past the edge, but image_x stays in [0, 1].
  PerceptionDef def = exact();
  def.noise.bearing_sd_rad = 0.05f;
  Perception perception(kField, def, 8);
  const Viewer me = viewer(0, 1, 0, 0, 0);
  const float a = deg2rad(29);
  int clamped = 0;
  for (int i = 0; i < 2000; ++i) {
    const auto seen = perception.observe(me, {me}, ball_at(1000 * std::cos(a), 1000 * std::sin(a)), i);
    const Observation* ball = find(seen, ObjectKind::kBall);
    ASSERT_TRUE(ball);
    EXPECT_GE(ball->image_x, 0.f);
    EXPECT_LE(ball->image_x, 1.f);
    clamped += ball->image_x == 1.f;
  }
  EXPECT_GT(clamped, 0);
}

TEST(PerceptionNoise, PhantomBallsAppearOnlyWithoutTheRealOneAndInView) {
  PerceptionDef def = exact();
  def.noise.phantom_ball_probability = 0.3f;
  def.noise.phantom_ball_max_distance_mm = 1500;
  Perception perception(kField, def, 11);
  const Viewer me = viewer(0, 1, 0, 0, 0, 0.3f, -0.2f);
  const float range = std::min(1500.f, max_camera_distance(def.camera, me.head_pitch_rad));
  const int n = 10000;
  int phantoms = 0;
  for (int i = 0; i < n; ++i) {
    const auto seen = perception.observe(me, {me}, ball_at(-1000, 0), i); // real ball behind
    const Observation* ball = find(seen, ObjectKind::kBall);
    if (!ball) continue;
    ++phantoms;
    EXPECT_LE(std::fabs(ball->heading_rad - me.head_yaw_rad), kPi / 6 + 1e-6f);
    EXPECT_GT(ball->distance_mm, 0.f);
    EXPECT_LE(ball->distance_mm, range);
  }
  expect_rate("phantom ball", phantoms, n, 0.3);
  // With the real ball in view and never missed, each frame has exactly one ball.
  for (int i = 0; i < 1000; ++i) {
    int balls = 0;
    for (const Observation& o : perception.observe(me, {me}, ball_at(800, 200), n + i))
      balls += o.kind == ObjectKind::kBall;
    ASSERT_EQ(balls, 1);
  }
}

TEST(PerceptionNoise, SonarNoiseHasTheConfiguredSigma) {
  PerceptionDef def = exact();
  def.sonar_noise_sd_mm = 20;
  def.sonar_sees_goal_posts = false;
  Perception perception(kField, def, 12);
  const Viewer me = viewer(0, 1, 0, 0, 0);
  const std::vector<Viewer> robots{me, viewer(1, 1, 500, 30, kPi)}; // 500 mm ahead, on the left
  std::vector<double> left;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const SonarReading r = perception.sonar(me, robots, i);
    left.push_back(r.left * 1000.0);
    ASSERT_EQ(r.right, 1.f); // nothing on the right: no noise
  }
  const Moments m = moments(left);
  std::printf("  sonar at 500 mm: mean %.2f mm, sd %.2f mm (model 20 mm, %+.2f %%)\n", m.mean, m.sd,
              100 * (m.sd / 20 - 1));
  EXPECT_NEAR(m.sd / 20, 1.0, 0.03);
  EXPECT_NEAR(m.mean, 500, 4 * 20 / std::sqrt(n));
}

TEST(PerceptionNoise, GyroNoiseHasTheConfiguredSigmaAndEachFrameItsOwnDraw) {
  PerceptionDef def = exact();
  def.gyro_turn_sd_rad = 0.01f;
  Perception perception(kField, def, 12);
  const Viewer me = viewer(0, 1, 0, 0, 0);
  std::vector<double> turns;
  const int n = 20000;
  for (int i = 0; i < n; ++i) turns.push_back(perception.gyro_turn(me, 0.1f, i));
  const Moments m = moments(turns);
  std::printf("  gyro turn of 0.1 rad: mean %.5f rad, sd %.5f rad (model 0.01 rad, %+.2f %%)\n", m.mean, m.sd,
              100 * (m.sd / 0.01 - 1));
  EXPECT_NEAR(m.sd / 0.01, 1.0, 0.03);
  EXPECT_NEAR(m.mean, 0.1, 4 * 0.01 / std::sqrt(n));
  EXPECT_EQ(perception.gyro_turn(me, 0.1f, 7), perception.gyro_turn(me, 0.1f, 7)); // keyed: asked again, the same
  EXPECT_NE(perception.gyro_turn(me, 0.1f, 7), perception.gyro_turn(viewer(0, 2, 0, 0, 0), 0.1f, 7));
  // A half turn and noise stay an angle; without noise the gyro is the turn.
  EXPECT_LE(std::fabs(perception.gyro_turn(me, kPi, 3)), kPi);
  EXPECT_EQ(Perception(kField, exact(), 12).gyro_turn(me, -0.25f, 3), -0.25f);
}

/// Every number of a frame's percepts, as bits.
std::vector<uint32_t> bits(const std::vector<Percept>& percepts) {
  std::vector<uint32_t> out;
  auto put = [&out](float f) {
    uint32_t u = 0;
    std::memcpy(&u, &f, sizeof u);
    out.push_back(u);
  };
  for (const Percept& p : percepts) {
    out.push_back(static_cast<uint32_t>(p.seen.size()));
    for (const Observation& o : p.seen) {
      out.push_back(static_cast<uint32_t>(o.kind) * 100u + static_cast<uint32_t>(o.id));
      put(o.distance_mm), put(o.heading_rad), put(o.image_x);
    }
    put(p.sonar.left), put(p.sonar.right);
  }
  return out;
}

/// A 2 v 2 scene that moves a little every frame, with every fault switched on.
std::vector<std::vector<uint32_t>> play(uint64_t seed, int frames) {
  PerceptionDef def;
  def.noise.phantom_ball_probability = 0.05f;
  def.sonar_noise_sd_mm = 15;
  Perception perception(kField, def, seed);
  std::vector<std::vector<uint32_t>> out;
  for (int f = 0; f < frames; ++f) {
    const float t = static_cast<float>(f) * 0.01f;
    const std::vector<Viewer> robots{viewer(0, 1, -1500 + 100 * t, 0, t), viewer(0, 2, -500, 600, -0.5f, t, 0.3f),
                                     viewer(1, 1, 900, -100, kPi - t), viewer(1, 2, 300, 300, kPi, -0.3f, 0.5f)};
    out.push_back(bits(perception.perceive(robots, ball_at(200 * t, -50), f)));
  }
  return out;
}

TEST(PerceptionNoise, SameSeedSameObservationsBitForBitOtherSeedOthers) {
  const auto a = play(42, 300), b = play(42, 300), c = play(43, 300);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  size_t values = 0;
  for (const auto& frame : a) values += frame.size();
  EXPECT_GT(values, 300u * 20); // the scene really sees things
}

TEST(PerceptionNoise, EachFramesDrawsAreTheSameInWhateverOrderFramesAreAsked) {
  // Keyed draws: frame f's noise is a function of (seed, f, viewer, object), not of what
  // was drawn before it.
  PerceptionDef def;
  def.noise.phantom_ball_probability = 0.2f;
  def.sonar_noise_sd_mm = 15;
  const Perception forwards(kField, def, 5), backwards(kField, def, 5);
  const std::vector<Viewer> robots{viewer(0, 1, -1000, 0, 0), viewer(1, 1, 1000, 300, kPi)};
  const BallTruth ball = ball_at(0, 100);
  std::vector<std::vector<uint32_t>> a, b(40);
  for (int f = 0; f < 40; ++f) a.push_back(bits(forwards.perceive(robots, ball, f)));
  for (int f = 39; f >= 0; --f) b[static_cast<size_t>(f)] = bits(backwards.perceive(robots, ball, f));
  EXPECT_EQ(a, b);
  EXPECT_NE(a[0], a[1]); // and frames differ
}

TEST(PerceptionNoise, OneRobotsHeadDoesNotShiftAnothersNoise) {
  // Robot 2 looking elsewhere (seeing other things) leaves robot 1's noisy view unchanged.
  PerceptionDef def;
  def.noise.phantom_ball_probability = 0.1f;
  Perception looking(kField, def, 77), away(kField, def, 77);
  const BallTruth ball = ball_at(500, 0);
  const Viewer first = viewer(0, 1, 0, 0, 0);
  int frames_robot2_saw_differently = 0;
  for (int f = 0; f < 50; ++f) {
    const std::vector<Viewer> robots_a{viewer(1, 2, 1000, 200, kPi), first};
    const std::vector<Viewer> robots_b{viewer(1, 2, 1000, 200, kPi, 1.5f, -0.6f), first};
    const auto a = looking.perceive(robots_a, ball, f), b = away.perceive(robots_b, ball, f);
    frames_robot2_saw_differently += bits({a[0]}) != bits({b[0]});
    EXPECT_EQ(bits({a[1]}), bits({b[1]}));
  }
  EXPECT_EQ(frames_robot2_saw_differently, 50); // it looks at the ball and robot 1, or away
}

TEST(PerceptionNoise, ARobotJoiningChangesNoOnesNoiseButWhatItAdds) {
  // A newcomer in robot 1's view, clear of its sight lines to the ball and the landmarks:
  // robot 1 sees one more object, and everything else exactly as before.
  PerceptionDef def;
  def.noise.phantom_ball_probability = 0.1f;
  def.sonar_noise_sd_mm = 15;
  Perception alone(kField, def, 31), joined(kField, def, 31);
  const BallTruth ball = ball_at(500, 0);
  const Viewer me = viewer(1, 2, 0, 0, 0);
  const Viewer newcomer = viewer(0, 3, 2000, -1000, 0); // 27 degrees right, 2.2 m off
  int newcomer_seen = 0;
  for (int f = 0; f < 50; ++f) {
    const Percept before = alone.perceive({me}, ball, f)[0];
    Percept after = joined.perceive({newcomer, me}, ball, f)[1]; // sorts before me, as in a match
    const auto it = std::find_if(after.seen.begin(), after.seen.end(),
                                 [](const Observation& o) { return o.kind == ObjectKind::kOpponent; });
    if (it != after.seen.end()) {
      EXPECT_EQ(it->id, 3);
      after.seen.erase(it);
      ++newcomer_seen;
    }
    EXPECT_EQ(bits({before}), bits({after})) << "frame " << f;
  }
  EXPECT_GT(newcomer_seen, 40); // seen but for the robot miss probability
}

} // namespace
} // namespace touchline::sim
