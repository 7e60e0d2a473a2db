#pragma once
// What a joint-space walk engine of a Nao reads and writes each control tick, as plain
// structs with units in their names and no dependency on any team's code: the sensors
// (as a Nao V6 reports them), the walk request, and the joint command with the engine's
// odometry. An adapter for a team's engine (robot_shim/runswift/) converts these to and
// from that team's own types; whatever drives the engine (the MotionAdapter) fills the
// sensors from the simulated robot and turns the joints into foot motion.
//
// Axes are the torso's: x forward, y left, z up; rates and angles are right-handed about
// them (gyro_z_rad_s > 0 turning anticlockwise seen from above, angle_y_rad > 0 leaning
// forward, angle_x_rad > 0 leaning right), as the V6's inertial unit reports them.
#include <cstdint>

#include "touchline/robot/nao/nao_joints.hpp"

namespace touchline::robot::nao {

/// One foot's four force-sensitive resistors, in kilograms of load (what the V6 reports).
struct FootPressure {
  float front_left_kg = 0;
  float front_right_kg = 0;
  float rear_left_kg = 0;
  float rear_right_kg = 0;

  float total_kg() const { return front_left_kg + front_right_kg + rear_left_kg + rear_right_kg; }
};

/// The sensors an engine reads, once per control tick.
struct NaoSensorFrame {
  JointArray joint_angles_rad{}; ///< measured joint positions, Joint order (hands 0..1)
  FootPressure left_foot;        ///< left sole's FSRs
  FootPressure right_foot;       ///< right sole's FSRs
  float gyro_x_rad_s = 0;        ///< roll rate, + rolling right
  float gyro_y_rad_s = 0;        ///< pitch rate, + pitching forward
  float gyro_z_rad_s = 0;        ///< yaw rate, + anticlockwise from above
  float angle_x_rad = 0;         ///< torso roll, + leaning right
  float angle_y_rad = 0;         ///< torso pitch, + leaning forward
};

/// What the walk is asked to do this tick (a behaviour's body request, engine-neutral).
struct WalkCommand {
  enum class Kind : uint8_t {
    stand,  ///< stand still, knees straight (a team's engine may stand up from its crouch first)
    crouch, ///< stand still in the walking crouch, ready to step at once
    walk,   ///< walk at the velocity below
    kick,   ///< kick with kick_foot at kick_power, the ball at ball_x_mm/ball_y_mm
  };
  enum class Foot : uint8_t { left, right };

  Kind kind = Kind::stand;
  float forward_mm_s = 0;   ///< + forward
  float left_mm_s = 0;      ///< + left
  float turn_rad_s = 0;     ///< + anticlockwise
  float speed_fraction = 1; ///< fraction of the engine's speed limits, [0, 1]
  Foot kick_foot = Foot::left;
  float kick_power = 1;     ///< [0, 1]
  float ball_x_mm = 0;      ///< where the robot believes the ball is, robot-relative, + forward
  float ball_y_mm = 0;      ///< + left
};

/// What an engine commands for one control tick.
struct NaoJointFrame {
  JointArray joint_angles_rad{}; ///< target positions, Joint order, inside kJointLimits
  float odometry_forward_mm = 0; ///< the engine's own odometry: this tick's increment, + forward
  float odometry_left_mm = 0;    ///< + left
  float odometry_turn_rad = 0;   ///< + anticlockwise
  /// The engine returned NaN or a joint beyond its limits (or threw): the angles are the last
  /// good frame's and the odometry is zero. The adapter says which joint.
  bool engine_fault = false;
};

} // namespace touchline::robot::nao
