#include "touchline/sim/camera.hpp"

#include <gtest/gtest.h>

#include "touchline/angles.hpp"

using namespace touchline;
using sim::CameraDef;

TEST(Camera, RangeFollowsTheThesisFormula) {
  const CameraDef camera;
  // maxCameraDist = (elevation - MINPITCH) * 3000 / (MAXPITCH - MINPITCH) + 1000, with
  // elevation = MINPITCH + MAXPITCH - pitch (pitch is + down).
  EXPECT_FLOAT_EQ(sim::max_camera_distance(camera, 0.51f), 1000.f);   // fully down
  EXPECT_FLOAT_EQ(sim::max_camera_distance(camera, -0.67f), 4000.f);  // fully up
  EXPECT_NEAR(sim::max_camera_distance(camera, 0.2f), (0.31f * 3000.f / 1.18f) + 1000.f, 1e-3f); // 1788 mm
  EXPECT_FLOAT_EQ(sim::max_camera_distance(camera, -2.f), 4000.f); // beyond the joint: clamped
}

TEST(Camera, ObjectStraightAheadIsInTheImageCentre) {
  const auto s = sim::sight(CameraDef{}, {0, 0, 0}, 0, -0.67f, 2000, 0);
  ASSERT_TRUE(s);
  EXPECT_FLOAT_EQ(s->distance_mm, 2000);
  EXPECT_NEAR(s->heading_rad, 0, 1e-6f);
  EXPECT_NEAR(s->image_x, 0.5f, 1e-6f);
}

TEST(Camera, FieldOfViewIsSixtyDegreesAroundHeadYaw) {
  const CameraDef camera;
  const Pose2D body{1000, 1000, kPi / 2}; // facing +y
  // 29 degrees left of the head direction: seen near the image edge; 31: not seen.
  const float yaw = 0.5f;
  auto at_angle = [&](float deg) {
    const float a = kPi / 2 + yaw + deg2rad(deg);
    return sim::sight(camera, body, yaw, -0.67f, 1000 + 1500 * std::cos(a), 1000 + 1500 * std::sin(a));
  };
  ASSERT_TRUE(at_angle(29));
  EXPECT_NEAR(at_angle(29)->image_x, (29.f + 30.f) / 60.f, 1e-4f);
  EXPECT_NEAR(at_angle(29)->heading_rad, yaw + deg2rad(29), 1e-4f);
  EXPECT_FALSE(at_angle(31));
  ASSERT_TRUE(at_angle(-29));
  EXPECT_NEAR(at_angle(-29)->image_x, 1.f / 60.f, 1e-4f);
  EXPECT_FALSE(at_angle(-31));
}

TEST(Camera, LookingDownLimitsTheRange) {
  const CameraDef camera;
  EXPECT_FALSE(sim::sight(camera, {0, 0, 0}, 0, 0.51f, 1500, 0)); // head down: 1000 mm
  EXPECT_TRUE(sim::sight(camera, {0, 0, 0}, 0, -0.67f, 1500, 0));
}

TEST(Camera, SeesAcrossThePiSeam) {
  // Facing -x (theta = pi): a point behind-left at angle -179 degrees is in view.
  const auto s = sim::sight(CameraDef{}, {0, 0, kPi}, 0, -0.67f, -1000, -17.45f);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->heading_rad, deg2rad(1), 1e-3f);
}
