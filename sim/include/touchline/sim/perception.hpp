#pragma once
// The perception pipeline: from the world's truth (every robot's body pose and head
// angles, the ball) to what each robot's camera reports (Observations, thesis Algorithm
// 2.3 through sim::sight) and what its sonar reads (Algorithm 2.4), with the noise and
// faults of a PerceptionDef. Pure computation: no transport, no wall time.
//
// Determinism: every draw is keyed (touchline/random.hpp) on the seed, the frame, the
// viewer and the object, and turned into numbers by this library's own arithmetic (not
// std:: distributions, whose algorithms differ between standard libraries). So the same
// seed, frame and world give the same observations bit for bit, whatever else is asked
// and in whatever order, and one robot turning its head or joining never shifts the noise
// of another's view.
#include <cstdint>
#include <vector>

#include "touchline/frame.hpp"
#include "touchline/sim/field.hpp"
#include "touchline/sim/landmarks.hpp"
#include "touchline/sim/perception_config.hpp"
#include "touchline/sim/sonar.hpp"
#include "touchline/sim/world.hpp"

namespace touchline::sim {

/// A robot as the perception sees it: where it stands and where its head points.
struct Viewer {
  RobotId id;
  Pose2D body;              ///< body centre and heading, field frame
  float head_yaw_rad = 0;   ///< + left
  float head_pitch_rad = 0; ///< + down (camera.hpp: looking up sees farther)
};

/// One robot's senses for a frame.
struct Percept {
  RobotId id;
  std::vector<Observation> seen; ///< observe()'s order
  SonarReading sonar;
  Touch touch;
};

class Perception {
 public:
  Perception(const Field& field, const PerceptionDef& def, uint64_t seed);

  /// What `me`'s camera reports in `frame`, robot frame, noise applied. Candidates, in this order:
  /// the ball (or, if it is not reported, possibly a phantom ball), the field landmarks
  /// (field_landmarks() order), then every robot in `robots` except `me` (matched by id),
  /// labelled kTeammate or kOpponent by `me`'s team with id = player number. A candidate
  /// is reported if Algorithm 2.3 sees it, no other robot's body hides it (ball and
  /// landmarks only) and no false negative drops it.
  std::vector<Observation> observe(const Viewer& me, const std::vector<Viewer>& robots, const BallTruth& ball,
                                   int64_t frame) const;

  /// `me`'s sonar (Algorithm 2.4) in `frame` against every other robot's body centre and,
  /// if configured, the goal posts; Gaussian noise on readings that see something.
  SonarReading sonar(const Viewer& me, const std::vector<Viewer>& robots, int64_t frame) const;

  /// Where the other robots in `robots` touch `me` (sim/touch.hpp): no noise, no misses.
  Touch touch(const Viewer& me, const std::vector<Viewer>& robots) const;

  /// `me`'s gyro over the frame before `frame`: the body's true turn `turn_rad` plus
  /// Gaussian noise (gyro_turn_sd_rad), normalised to [-pi, pi].
  float gyro_turn(const Viewer& me, float turn_rad, int64_t frame) const;

  /// observe(), sonar() and touch() for each robot in `robots`.
  std::vector<Percept> perceive(const std::vector<Viewer>& robots, const BallTruth& ball, int64_t frame) const;

  const std::vector<Landmark>& landmarks() const { return landmarks_; }
  const PerceptionDef& def() const { return def_; }

 private:
  bool hidden(const Viewer& me, const std::vector<Viewer>& robots, float x_mm, float y_mm) const;
  /// Reports this candidate into `out` if seen, with its own keyed miss and noise draws.
  bool consider(const Viewer& me, const std::vector<Viewer>& robots, int64_t frame, ObjectKind kind, int id,
                float x_mm, float y_mm, float miss_probability, bool can_be_hidden,
                std::vector<Observation>& out) const;

  Field field_;
  PerceptionDef def_;
  std::vector<Landmark> landmarks_;
  uint64_t seed_;
};

} // namespace touchline::sim
