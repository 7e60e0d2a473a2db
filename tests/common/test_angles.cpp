// angles.hpp: the one angle wrap (the robot API's, in float and double) and the body
// heading of two feet, which the walk and the world must compute alike.
#include "touchline/angles.hpp"

#include <gtest/gtest.h>

namespace touchline {
namespace {

constexpr double kPiD = 3.14159265358979323846;

TEST(WrapAngle, WrapsIntoMinusPiToPiInFloatAndDouble) {
  EXPECT_EQ(normalise_angle(kPi), -kPi);
  EXPECT_EQ(normalise_angle(-kPi), -kPi);
  EXPECT_NEAR(normalise_angle(1.5f * kPi), -0.5f * kPi, 1e-6f);
  EXPECT_NEAR(normalise_angle(-7.f), -7.f + 2 * kPi, 1e-6f);
  EXPECT_EQ(api::wrapAngle(kPiD), -kPiD);
  EXPECT_NEAR(api::wrapAngle(0.5 + 6 * kPiD), 0.5, 1e-12);
  EXPECT_NEAR(api::wrapAngle(-0.5 - 4 * kPiD), -0.5, 1e-12);
}

TEST(WrapAngle, TheRobotApiWrapsAsTheWorldDoes) {
  for (float a = -20.f; a < 20.f; a += 0.37f) EXPECT_EQ(api::normaliseTheta(a), normalise_angle(a)) << a;
}

TEST(MeanHeading, IsTheBisectorOfTheShorterArc) {
  EXPECT_NEAR(mean_heading(0.2f, 0.4f), 0.3f, 1e-6f);
  EXPECT_NEAR(mean_heading(0.4f, 0.2f), 0.3f, 1e-6f);
  EXPECT_NEAR(mean_heading(-0.1f, 0.1f), 0.f, 1e-6f);
  EXPECT_NEAR(mean_heading(3.f, -3.f), -kPi, 1e-6f);                // across the seam
  EXPECT_NEAR(mean_heading(3.f, 3.4f - 2 * kPi), 3.2f - 2 * kPi, 1e-5f); // ... the bisector wrapped
  EXPECT_NEAR(mean_heading(1.25f, 1.25f + 4 * kPi), 1.25f, 1e-5f);      // Box2D's angles are not wrapped
}

TEST(MeanHeading, StaysInMinusPiToPiAtTheSeam) {
  // Feet either side of the seam: the body heading is in [-pi, pi) as every other heading
  // of the frame contract (the world's old atan2 mean gave +pi for feet at +pi and -pi).
  for (float d = -0.5f; d <= 0.5f; d += 0.01f) {
    const float heading = mean_heading(kPi - d, -kPi + d);
    EXPECT_GE(heading, -kPi) << d;
    EXPECT_LT(heading, kPi) << d;
  }
}

} // namespace
} // namespace touchline
