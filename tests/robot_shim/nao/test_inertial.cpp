#include "touchline/robot/nao/inertial.hpp"

#include <gtest/gtest.h>

using namespace touchline::robot::nao;

TEST(Inertial, UprightTheGyroZIsTheBodysTurnRate) {
  Sensors s;
  set_inertial(s, 0.012f, 0.012f, false);
  EXPECT_FLOAT_EQ(s.gyro_z_rad_s, 1.f);
  EXPECT_EQ(s.gyro_x_rad_s, 0.f);
  EXPECT_EQ(s.angle_y_rad, 0.f);
}

TEST(Inertial, FallenTheRobotLiesOnItsFrontAndIsStill) {
  Sensors s;
  set_inertial(s, 0.012f, 0.012f, true);
  EXPECT_EQ(s.gyro_z_rad_s, 0.f);
  EXPECT_NEAR(s.angle_y_rad, 1.5708f, 1e-4f);
}
