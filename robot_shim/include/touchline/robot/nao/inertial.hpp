#pragma once
// The inertial unit as the sim can give it: the world moves robots on the ground plane
// only, so the torso is upright (roll and pitch 0, no roll or pitch rate) unless the
// robot has fallen (then it lies on its front, pitch +pi/2, still); the yaw rate is the
// body's turn over the last control tick, taken from the feet the robot hands the world.
#include "touchline/robot/nao/sensors.hpp"

namespace touchline::robot::nao {

/// Writes the gyro and the body angles into `sensors`: `turn_rad` is the body's heading
/// change over the last control tick of `dt_s` seconds.
void set_inertial(Sensors& sensors, float turn_rad, float dt_s, bool fallen);

} // namespace touchline::robot::nao
