#pragma once
// What a Nao's sensors tell its walk engine each control tick, as the robot would have
// them: joint positions (the last command: the motors are position-controlled and the
// sim has no load to lag them), the eight foot pressure sensors (foot_pressure.hpp), and
// the inertial unit (inertial.hpp). Sonar stays where it is today (the Blackboard).
#include <array>

#include "touchline/robot/nao/joints.hpp"

namespace touchline::robot::nao {

/// The FSRs' order: the left foot's four, then the right's.
enum Fsr : int {
  kLFrontLeft, kLFrontRight, kLRearLeft, kLRearRight,
  kRFrontLeft, kRFrontRight, kRRearLeft, kRRearRight,
  kFsrCount
};

struct Sensors {
  JointAngles joints{};                  ///< joint positions, rad: the last command
  std::array<float, kFsrCount> fsr_kg{}; ///< foot pressure, kg on each sensor
  float gyro_x_rad_s = 0;                ///< roll rate, rad/s
  float gyro_y_rad_s = 0;                ///< pitch rate, rad/s
  float gyro_z_rad_s = 0;                ///< yaw rate, rad/s, + anticlockwise
  float angle_x_rad = 0;                 ///< torso roll, rad (0 upright)
  float angle_y_rad = 0;                 ///< torso pitch, rad (0 upright, + leaning forward)
};

} // namespace touchline::robot::nao
