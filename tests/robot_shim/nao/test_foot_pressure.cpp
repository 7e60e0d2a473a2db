#include "touchline/robot/nao/foot_pressure.hpp"

#include <gtest/gtest.h>

#include <numeric>

using namespace touchline::robot::nao;

TEST(FootPressure, TheRobotsMassRestsOnTheStanceSolesFourSensors) {
  FootPressureDef def;
  def.robot_mass_kg = 5.2f;
  const auto left = foot_pressure(Side::kLeft, def);
  for (int i = kLFrontLeft; i <= kLRearRight; ++i) EXPECT_FLOAT_EQ(left[static_cast<size_t>(i)], 1.3f);
  for (int i = kRFrontLeft; i <= kRRearRight; ++i) EXPECT_EQ(left[static_cast<size_t>(i)], 0.f);
  const auto right = foot_pressure(Side::kRight, def);
  EXPECT_FLOAT_EQ(std::accumulate(right.begin() + kRFrontLeft, right.end(), 0.f), 5.2f);
  EXPECT_EQ(std::accumulate(right.begin(), right.begin() + kRFrontLeft, 0.f), 0.f);
}
