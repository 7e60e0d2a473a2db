#pragma once
// The physical world: a Box2D 2.4 world with the field's static parts (boundary walls,
// goal posts and nets), a ball, and robots modelled as two feet (thesis 2.2.1). Feet
// are dynamic bodies driven by velocity = displacement / dt (thesis 2.2.2), so contacts
// with the ball and other robots' feet are physical. No I/O, no transport.
// Reads: per-tick foot motions. Writes: the physical state (truth).
#include <cstdint>
#include <memory>
#include <vector>

#include "touchline/frame.hpp"
#include "touchline/sim/field.hpp"

namespace touchline::sim {

/// Physics constants, read from the [physics] section of a world config.
struct PhysicsDef {
  float ball_diameter_mm = 65.f;         ///< SPL 2011 orange ball
  float ball_mass_kg = 0.055f;
  float ball_restitution = 0.5f;         ///< bounce off posts, walls, feet (Box2D takes the max of the pair)
  float ball_rolling_decel_mm_s2 = 300.f;///< constant rolling-resistance deceleration on the carpet
  float ball_linear_damping = 0.2f;      ///< extra velocity-proportional drag, 1/s
  float foot_length_mm = 160.f;          ///< foot rectangle along the robot's x
  float foot_width_mm = 90.f;            ///< foot rectangle along the robot's y
  float foot_mass_kg = 2.5f;             ///< half the robot: feet barely yield to the ball
  float foot_friction = 0.6f;
  float wall_restitution = 0.3f;
  float post_restitution = 0.5f;
  float net_restitution = 0.1f;
  int substeps = 2;                      ///< Box2D steps per 10 ms motion tick
  int velocity_iterations = 8;
  int position_iterations = 3;
};

/// Ground truth of one robot.
struct RobotTruth {
  RobotId id;
  Pose2D body;       ///< midpoint of the feet, mean heading of the feet
  Pose2D left_foot;  ///< foot centres, field frame
  Pose2D right_foot;
};

struct BallTruth {
  float x_mm = 0, y_mm = 0;
  float vx_mm_s = 0, vy_mm_s = 0;
};

/// One robot's foot motions for one motion tick (body frame at the tick start).
struct TickMotion {
  FootMotion left;
  FootMotion right;
};

class World {
 public:
  World(const FieldDef& field, const PhysicsDef& physics, float foot_separation_mm = 100.f);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Adds a robot standing at `body` with its feet foot_separation_mm apart; returns its index.
  int add_robot(RobotId id, const Pose2D& body);
  /// Puts a robot down at `body`, feet at rest (re-entry, tests).
  void place_robot(int index, const Pose2D& body);
  void place_ball(float x_mm, float y_mm, float vx_mm_s = 0, float vy_mm_s = 0);

  /// Advances one 10 ms motion tick. motions[i] drives robot i (size must equal robot_count()).
  void step(const std::vector<TickMotion>& motions);

  int robot_count() const;
  RobotTruth robot(int index) const;
  BallTruth ball() const;
  const Field& field() const;
  int64_t ticks() const; ///< motion ticks stepped so far

  /// FNV-1a over the exact bytes of every body's position, angle and velocities: equal
  /// hashes mean bit-identical worlds (the determinism tests compare these).
  uint64_t state_hash() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace touchline::sim
