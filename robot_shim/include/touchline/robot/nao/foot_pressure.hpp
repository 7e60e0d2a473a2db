#pragma once
// Foot pressure as a Nao's eight FSRs would read it: the robot's whole mass on the sole
// that bears it (JointFeet's stance sole), split evenly over that sole's four sensors; the
// other sole reads zero. The weight moves at once to the other sole at touchdown (no
// double-support shift of the centre of pressure: the sim has no dynamics to give one).
// Walk engines that switch support foot on the pressure balance (rUNSWift's) see the
// sign change at the touchdown tick.
#include <array>

#include "touchline/robot/nao/leg_kinematics.hpp"
#include "touchline/robot/nao/sensors.hpp"

namespace touchline::robot::nao {

struct FootPressureDef {
  float robot_mass_kg = 5.3f; ///< a NAO V6 weighs about 5.3 kg
};

/// The eight readings with `stance` bearing the weight.
std::array<float, kFsrCount> foot_pressure(Side stance, const FootPressureDef& def = {});

} // namespace touchline::robot::nao
