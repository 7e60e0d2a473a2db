#pragma once
// The perception pipeline: from the world's truth (every robot's body pose and head
// angles, the ball) to what each robot's camera reports (Observations, thesis Algorithm
// 2.3 through sim::sight) and what its sonar reads (Algorithm 2.4), with the noise and
// faults of a PerceptionDef. Pure computation: no transport, no wall time.
//
// Determinism: one seeded mt19937_64, turned into numbers by this library's own
// arithmetic (not std:: distributions, whose algorithms differ between standard
// libraries). Every candidate object costs the same draws whether or not it is seen, so
// the same seed, the same calls and the same world give the same observations bit for
// bit, and one robot turning its head never shifts the noise of another's view.
#include <cstdint>
#include <random>
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
};

class Perception {
 public:
  Perception(const Field& field, const PerceptionDef& def, uint64_t seed);

  /// What `me`'s camera reports, robot frame, noise applied. Candidates, in this order:
  /// the ball (or, if it is not reported, possibly a phantom ball), the field landmarks
  /// (field_landmarks() order), then every robot in `robots` except `me` (matched by id),
  /// labelled kTeammate or kOpponent by `me`'s team with id = player number. A candidate
  /// is reported if Algorithm 2.3 sees it, no other robot's body hides it (ball and
  /// landmarks only) and no false negative drops it.
  std::vector<Observation> observe(const Viewer& me, const std::vector<Viewer>& robots, const BallTruth& ball);

  /// `me`'s sonar (Algorithm 2.4) against every other robot's body centre and, if
  /// configured, the goal posts; Gaussian noise on readings that see something.
  SonarReading sonar(const Viewer& me, const std::vector<Viewer>& robots);

  /// observe() then sonar() for each robot in `robots`, in that order.
  std::vector<Percept> perceive(const std::vector<Viewer>& robots, const BallTruth& ball);

  const std::vector<Landmark>& landmarks() const { return landmarks_; }
  const PerceptionDef& def() const { return def_; }

 private:
  double uniform();  ///< [0, 1), 53 random bits
  double gaussian(); ///< standard normal (Box-Muller, one pair of draws per number)
  bool hidden(const Viewer& me, const std::vector<Viewer>& robots, float x_mm, float y_mm) const;
  /// Draws this candidate's miss and noise numbers, then reports it into `out` if seen.
  bool consider(const Viewer& me, const std::vector<Viewer>& robots, ObjectKind kind, int id, float x_mm,
                float y_mm, float miss_probability, bool can_be_hidden, std::vector<Observation>& out);

  Field field_;
  PerceptionDef def_;
  std::vector<Landmark> landmarks_;
  std::mt19937_64 rng_;
};

} // namespace touchline::sim
