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
/// Restitution: the ball bounces off a foot with ball_restitution; off a wall, post or
/// net with that part's own restitution (not Box2D's max of the pair, which would make a
/// net as lively as a foot). Friction: foot_friction for every contact.
struct PhysicsDef {
  float ball_diameter_mm = 65.f;         ///< SPL 2011 orange ball, mm
  float ball_mass_kg = 0.055f;           ///< kg
  float ball_restitution = 0.5f;         ///< bounce off feet, 0..1
  float ball_rolling_decel_mm_s2 = 300.f;///< constant rolling-resistance deceleration on the carpet, mm/s^2
  float ball_linear_damping = 0.2f;      ///< extra velocity-proportional drag, 1/s
  float foot_length_mm = 160.f;          ///< foot rectangle along the robot's x, mm
  float foot_width_mm = 90.f;            ///< foot rectangle along the robot's y, mm
  float foot_mass_kg = 2.5f;             ///< half the robot: feet barely yield to the ball
  float foot_friction = 0.6f;            ///< Coulomb friction of every contact
  /// The legs hold a robot together: its foot centres are never farther apart than this, mm.
  /// A Nao's hips are 100 mm apart and its largest step (a kick's swing) about 200 mm; a push
  /// moves the robot, not one foot away from the other.
  float max_foot_spread_mm = 300.f;
  /// The legs also hold the feet's headings together against contacts: a contact never turns
  /// one foot more than this from the other, rad (a Nao's hip yaw-pitch joint turns its feet
  /// apart by less than 1 rad). Without it a contact that spins one foot could turn the two pi
  /// apart, where their mean heading, the body's, flips by pi: a robot turned about in one
  /// frame, unseen by odometry. The walk's own commanded twist (a fast turn opens the feet
  /// ~0.83 rad) is never held. 0: no limit.
  float max_foot_twist_rad = 0.8f;
  /// The legs place a lifted foot where the walk's own steps put it beside the standing foot:
  /// a foot the walk moves also moves towards that place at up to these speeds, so a foot a
  /// contact shoved aside is back in the walk's stance within a step or two (0 and 0: never).
  float stance_return_mm_s = 300.f;      ///< mm/s
  float stance_return_rad_s = 2.f;       ///< rad/s
  float wall_restitution = 0.3f;         ///< ball off the boundary walls, 0..1
  float post_restitution = 0.5f;         ///< ball off the goal posts, 0..1
  float net_restitution = 0.f;           ///< ball off the nets, 0..1: nets absorb the ball, so a goal stays in
  int substeps = 2;                      ///< Box2D steps per 10 ms motion tick, >= 1
  int velocity_iterations = 8;           ///< Box2D solver iterations per step
  int position_iterations = 3;           ///< Box2D solver iterations per step
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

/// Notes on the physics: pressed contacts (feet against feet) rest overlapping by Box2D's
/// linear slop, 5 mm; a 10 m/s ball may overlap a wall or foot by up to 15 mm for the
/// step of impact. The ball does not spin about the vertical (a top-down spin is not a
/// real ball's), and rolls to a stop under ball_rolling_decel plus linear damping.
class World {
 public:
  World(const FieldDef& field, const PhysicsDef& physics, float foot_separation_mm = 100.f);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Adds a robot standing at `body` with its feet foot_separation_mm apart (left foot at
  /// body-frame y = +sep/2), both facing body.theta; returns its index (0, 1, ...).
  int add_robot(RobotId id, const Pose2D& body);
  /// Puts a robot down at `body`, feet at rest (re-entry, tests).
  void place_robot(int index, const Pose2D& body);
  /// The ball starts at rest on the centre spot; this moves it (and sets its velocity).
  void place_ball(float x_mm, float y_mm, float vx_mm_s = 0, float vy_mm_s = 0);

  /// Advances one 10 ms motion tick. motions[i] drives robot i (size must equal
  /// robot_count(), else std::invalid_argument): each foot moves by its command, in the
  /// body frame of the current feet, unless something is in its way. A foot with no
  /// command (zero motion) stays put.
  void step(const std::vector<TickMotion>& motions);
  /// The same, where legs[i] is what robot i's walk did with its legs this tick, moved or
  /// not: a motion the referee stopped (a fallen robot, a contest's loser stepping towards
  /// the winner) still moved the legs against each other, which sets the stance the legs
  /// return a lifted foot to (PhysicsDef::stance_return_mm_s).
  void step(const std::vector<TickMotion>& motions, const std::vector<TickMotion>& legs);

  int robot_count() const;
  /// Index of the robot whose foot touched the ball last, -1 if none has.
  int last_ball_touch() const;
  /// Indices of the robots whose feet began touching the ball during the last step(), in
  /// the order the contacts began (cleared when the next step() starts).
  const std::vector<int>& ball_touches() const;
  RobotTruth robot(int index) const; ///< std::out_of_range for a bad index
  BallTruth ball() const;
  const Field& field() const;
  const PhysicsDef& physics() const;
  int64_t ticks() const; ///< motion ticks stepped so far

  /// FNV-1a 64 over the exact float bytes of every dynamic body's position, angle and
  /// velocities (ball, then feet, in creation order) and the tick count: equal hashes
  /// mean bit-identical worlds (the determinism tests compare these).
  uint64_t state_hash() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace touchline::sim
