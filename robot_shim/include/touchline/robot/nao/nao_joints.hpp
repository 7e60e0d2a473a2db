#pragma once
// The Nao V6's 25 joints: their order (the order the robot's LoLA interface sends and takes
// them in), their names, and their position limits from the robot's published joint
// specification. Header only, no dependency: what a walk engine that commands joints, and
// whatever turns joint angles into foot motion, share.
#include <array>
#include <cstddef>

namespace touchline::robot::nao {

/// The joints in the Nao V6's own order (LoLA's "Position" arrays). Hands are 0 (closed)
/// .. 1 (open), every other joint in radians.
enum Joint : int {
  HeadYaw = 0,
  HeadPitch,
  LShoulderPitch,
  LShoulderRoll,
  LElbowYaw,
  LElbowRoll,
  LWristYaw,
  LHipYawPitch,
  LHipRoll,
  LHipPitch,
  LKneePitch,
  LAnklePitch,
  LAnkleRoll,
  RHipRoll,
  RHipPitch,
  RKneePitch,
  RAnklePitch,
  RAnkleRoll,
  RShoulderPitch,
  RShoulderRoll,
  RElbowYaw,
  RElbowRoll,
  RWristYaw,
  LHand,
  RHand,
};

constexpr std::size_t kJointCount = 25;

/// One value per joint, indexed by Joint.
using JointArray = std::array<float, kJointCount>;

inline const char* joint_name(int joint) {
  constexpr const char* kNames[kJointCount] = {
      "HeadYaw",       "HeadPitch",      "LShoulderPitch", "LShoulderRoll", "LElbowYaw",
      "LElbowRoll",    "LWristYaw",      "LHipYawPitch",   "LHipRoll",      "LHipPitch",
      "LKneePitch",    "LAnklePitch",    "LAnkleRoll",     "RHipRoll",      "RHipPitch",
      "RKneePitch",    "RAnklePitch",    "RAnkleRoll",     "RShoulderPitch", "RShoulderRoll",
      "RElbowYaw",     "RElbowRoll",     "RWristYaw",      "LHand",         "RHand"};
  return joint >= 0 && joint < static_cast<int>(kJointCount) ? kNames[joint] : "?";
}

/// A joint's position range.
struct JointLimits {
  float min_rad;
  float max_rad;
};

namespace detail {
constexpr float deg(float d) { return d * 3.14159265358979f / 180.f; }
} // namespace detail

/// Position limits of the Nao V6 (published joint specification, in degrees there). Note
/// the elbow rolls: 0 is outside the range (LElbowRoll stops at -2 degrees, RElbowRoll at +2).
/// LHipYawPitch and RHipYawPitch are one motor on the robot; LoLA takes only the left one.
constexpr std::array<JointLimits, kJointCount> kJointLimits = {{
    {detail::deg(-119.5f), detail::deg(119.5f)},  // HeadYaw
    {detail::deg(-38.5f), detail::deg(29.5f)},    // HeadPitch
    {detail::deg(-119.5f), detail::deg(119.5f)},  // LShoulderPitch
    {detail::deg(-18.f), detail::deg(76.f)},      // LShoulderRoll
    {detail::deg(-119.5f), detail::deg(119.5f)},  // LElbowYaw
    {detail::deg(-88.5f), detail::deg(-2.f)},     // LElbowRoll
    {detail::deg(-104.5f), detail::deg(104.5f)},  // LWristYaw
    {detail::deg(-65.62f), detail::deg(42.44f)},  // LHipYawPitch
    {detail::deg(-21.74f), detail::deg(45.29f)},  // LHipRoll
    {detail::deg(-88.f), detail::deg(27.73f)},    // LHipPitch
    {detail::deg(-5.29f), detail::deg(121.04f)},  // LKneePitch
    {detail::deg(-68.15f), detail::deg(52.86f)},  // LAnklePitch
    {detail::deg(-22.79f), detail::deg(44.06f)},  // LAnkleRoll
    {detail::deg(-45.29f), detail::deg(21.74f)},  // RHipRoll
    {detail::deg(-88.f), detail::deg(27.73f)},    // RHipPitch
    {detail::deg(-5.9f), detail::deg(121.47f)},   // RKneePitch
    {detail::deg(-67.97f), detail::deg(53.4f)},   // RAnklePitch
    {detail::deg(-44.06f), detail::deg(22.8f)},   // RAnkleRoll
    {detail::deg(-119.5f), detail::deg(119.5f)},  // RShoulderPitch
    {detail::deg(-76.f), detail::deg(18.f)},      // RShoulderRoll
    {detail::deg(-119.5f), detail::deg(119.5f)},  // RElbowYaw
    {detail::deg(2.f), detail::deg(88.5f)},       // RElbowRoll
    {detail::deg(-104.5f), detail::deg(104.5f)},  // RWristYaw
    {0.f, 1.f},                                   // LHand
    {0.f, 1.f},                                   // RHand
}};

namespace detail {
/// A joint's top speed: its motor's no-load speed through its gear reduction.
constexpr float motor_rad_s(float no_load_rpm, float reduction) { return no_load_rpm * 2 * 3.14159265358979f / 60 / reduction; }
} // namespace detail

/// Top speed of each joint of the Nao V6, rad/s (hands: fraction per second), from the
/// published motor specification (motor type, no-load speed, reduction ratio). A joint
/// cannot follow a target that moves faster; legs: 4.5 rad/s (yaw-pitch, rolls), 7.0 rad/s
/// (pitches).
constexpr std::array<float, kJointCount> kJointMaxSpeed_rad_s = {{
    detail::motor_rad_s(10700.f, 150.27f), // HeadYaw: motor type 3, reduction A
    detail::motor_rad_s(10700.f, 173.22f), // HeadPitch: motor type 3, reduction B
    detail::motor_rad_s(11400.f, 150.27f), // LShoulderPitch: motor type 4
    detail::motor_rad_s(10700.f, 173.22f), // LShoulderRoll: motor type 3, reduction B
    detail::motor_rad_s(10700.f, 150.27f), // LElbowYaw: motor type 3, reduction A
    detail::motor_rad_s(10700.f, 173.22f), // LElbowRoll: motor type 3, reduction B
    detail::motor_rad_s(8400.f, 50.61f), // LWristYaw: motor type 2, reduction A
    detail::motor_rad_s(8700.f, 201.3f), // LHipYawPitch: motor type 1
    detail::motor_rad_s(8700.f, 201.3f), // LHipRoll: motor type 1
    detail::motor_rad_s(8700.f, 130.85f), // LHipPitch: motor type 5
    detail::motor_rad_s(8700.f, 130.85f), // LKneePitch: motor type 5
    detail::motor_rad_s(8700.f, 130.85f), // LAnklePitch: motor type 5
    detail::motor_rad_s(8700.f, 201.3f), // LAnkleRoll: motor type 1
    detail::motor_rad_s(8700.f, 201.3f), // RHipRoll: motor type 1
    detail::motor_rad_s(8700.f, 130.85f), // RHipPitch: motor type 5
    detail::motor_rad_s(8700.f, 130.85f), // RKneePitch: motor type 5
    detail::motor_rad_s(8700.f, 130.85f), // RAnklePitch: motor type 5
    detail::motor_rad_s(8700.f, 201.3f), // RAnkleRoll: motor type 1
    detail::motor_rad_s(11400.f, 150.27f), // RShoulderPitch: motor type 4
    detail::motor_rad_s(10700.f, 173.22f), // RShoulderRoll: motor type 3, reduction B
    detail::motor_rad_s(10700.f, 150.27f), // RElbowYaw: motor type 3, reduction A
    detail::motor_rad_s(10700.f, 173.22f), // RElbowRoll: motor type 3, reduction B
    detail::motor_rad_s(8400.f, 50.61f), // RWristYaw: motor type 2, reduction A
    detail::motor_rad_s(8400.f, 36.24f), // LHand: motor type 2, reduction B
    detail::motor_rad_s(8400.f, 36.24f), // RHand: motor type 2, reduction B
}};

} // namespace touchline::robot::nao
