#include "touchline/robot/nao/foot_pressure.hpp"

namespace touchline::robot::nao {

std::array<float, kFsrCount> foot_pressure(Side stance, const FootPressureDef& def) {
  std::array<float, kFsrCount> fsr{};
  const int first = stance == Side::kLeft ? kLFrontLeft : kRFrontLeft;
  for (int i = 0; i < 4; ++i) fsr[static_cast<size_t>(first + i)] = def.robot_mass_kg / 4;
  return fsr;
}

} // namespace touchline::robot::nao
