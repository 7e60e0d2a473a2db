#include "touchline/robot/nao/inertial.hpp"

#include "touchline/angles.hpp"

namespace touchline::robot::nao {

void set_inertial(Sensors& sensors, float turn_rad, float dt_s, bool fallen) {
  sensors.gyro_x_rad_s = 0;
  sensors.gyro_y_rad_s = 0;
  sensors.gyro_z_rad_s = fallen || !(dt_s > 0) ? 0.f : turn_rad / dt_s;
  sensors.angle_x_rad = 0;
  sensors.angle_y_rad = fallen ? kPi / 2 : 0.f;
}

} // namespace touchline::robot::nao
