#include "touchline/sim/sonar.hpp"

#include <gtest/gtest.h>

#include "touchline/angles.hpp"

using namespace touchline;

TEST(Sonar, ObstacleAheadInTheCorridorSetsTheNearerSide) {
  sim::SonarReading r;
  sim::sonar_update({}, {0, 0, 0}, 400, 50, r); // 400 mm ahead, 50 mm left
  EXPECT_FLOAT_EQ(r.left, 0.4f);
  EXPECT_FLOAT_EQ(r.right, 1.f);
  sim::sonar_update({}, {0, 0, 0}, 700, -30, r); // right side
  EXPECT_FLOAT_EQ(r.right, 0.7f);
  sim::sonar_update({}, {0, 0, 0}, 300, 20, r);  // nearer on the left: minimum wins
  EXPECT_FLOAT_EQ(r.left, 0.3f);
}

TEST(Sonar, IgnoresWhatIsBehindOutOfRangeOrOutsideTheCorridor) {
  sim::SonarReading r;
  sim::sonar_update({}, {0, 0, 0}, -300, 0, r);   // behind
  sim::sonar_update({}, {0, 0, 0}, 1000, 0, r);   // at the range limit
  sim::sonar_update({}, {0, 0, 0}, 500, 100, r);  // on the corridor edge
  EXPECT_FLOAT_EQ(r.left, 1.f);
  EXPECT_FLOAT_EQ(r.right, 1.f);
}

TEST(Sonar, WorksInTheRobotFrame) {
  // Robot at (1000, 1000) facing +y: an obstacle at (1080, 1600) is 600 ahead, 80 to the right.
  sim::SonarReading r;
  sim::sonar_update({}, {1000, 1000, kPi / 2}, 1080, 1600, r);
  EXPECT_NEAR(r.right, 0.6f, 1e-5f);
  EXPECT_FLOAT_EQ(r.left, 1.f);
}
