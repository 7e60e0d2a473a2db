#include "touchline/robot/nao/joints.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "touchline/angles.hpp"

namespace touchline::robot::nao {

namespace {

struct JointInfo {
  const char* name;
  float min_deg;
  float max_deg;
};

// The NAO V6 joint ranges as published by the maker, degrees (the hands: 0..1, not angles).
constexpr std::array<JointInfo, kJointCount> kJoints{{
    {"HeadYaw", -119.5f, 119.5f},
    {"HeadPitch", -38.5f, 29.5f},
    {"LShoulderPitch", -119.5f, 119.5f},
    {"LShoulderRoll", -18.f, 76.f},
    {"LElbowYaw", -119.5f, 119.5f},
    {"LElbowRoll", -88.5f, -2.f},
    {"LWristYaw", -104.5f, 104.5f},
    {"LHipYawPitch", -65.62f, 42.44f},
    {"LHipRoll", -21.74f, 45.29f},
    {"LHipPitch", -88.f, 27.73f},
    {"LKneePitch", -5.29f, 121.04f},
    {"LAnklePitch", -68.15f, 52.86f},
    {"LAnkleRoll", -22.79f, 44.06f},
    {"RHipRoll", -45.29f, 21.74f},
    {"RHipPitch", -88.f, 27.73f},
    {"RKneePitch", -5.9f, 121.47f},
    {"RAnklePitch", -67.97f, 53.4f},
    {"RAnkleRoll", -44.06f, 22.8f},
    {"RShoulderPitch", -119.5f, 119.5f},
    {"RShoulderRoll", -76.f, 18.f},
    {"RElbowYaw", -119.5f, 119.5f},
    {"RElbowRoll", 2.f, 88.5f},
    {"RWristYaw", -104.5f, 104.5f},
    {"LHand", 0.f, 0.f},
    {"RHand", 0.f, 0.f},
}};

} // namespace

const char* joint_name(int joint) {
  return joint >= 0 && joint < kJointCount ? kJoints[static_cast<size_t>(joint)].name : "?";
}

JointRange joint_range(int joint) {
  if (joint == kLHand || joint == kRHand) return {0.f, 1.f};
  const JointInfo& info = kJoints[static_cast<size_t>(joint)];
  return {deg2rad(info.min_deg), deg2rad(info.max_deg)};
}

bool is_leg_joint(int joint) { return joint >= kLHipYawPitch && joint <= kRAnkleRoll; }

std::optional<std::string> check_joints(const JointAngles& joints, float tolerance_rad) {
  for (int j = 0; j < kJointCount; ++j) {
    const float value = joints[static_cast<size_t>(j)];
    const JointRange range = joint_range(j);
    if (std::isfinite(value) &&
        (!is_leg_joint(j) || (value >= range.min_rad - tolerance_rad && value <= range.max_rad + tolerance_rad)))
      continue;
    char line[160];
    std::snprintf(line, sizeof line, "%s = %g (range %.3f..%.3f rad)", joint_name(j), static_cast<double>(value),
                  static_cast<double>(range.min_rad), static_cast<double>(range.max_rad));
    return std::string(line);
  }
  return std::nullopt;
}

float joint_max_speed_rad_s(int joint) {
  constexpr float kNoLoad_rad_s = 8000.f * 2.f * kPi / 60.f; // the leg motor, unloaded
  switch (joint) {
    case kLHipYawPitch:
    case kLHipRoll:
    case kLAnkleRoll:
    case kRHipRoll:
    case kRAnkleRoll: return kNoLoad_rad_s / 201.3f;
    case kLHipPitch:
    case kLKneePitch:
    case kLAnklePitch:
    case kRHipPitch:
    case kRKneePitch:
    case kRAnklePitch: return kNoLoad_rad_s / 130.85f;
    default: return std::numeric_limits<float>::infinity();
  }
}

JointAngles follow(const JointAngles& from, const JointAngles& target, float dt_s) {
  JointAngles at = clamp_to_ranges(target);
  for (int j = 0; j < kJointCount; ++j) {
    const float step = joint_max_speed_rad_s(j) * dt_s;
    const float start = from[static_cast<size_t>(j)];
    float& value = at[static_cast<size_t>(j)];
    value = std::clamp(value, start - step, start + step);
  }
  return at;
}

JointAngles clamp_to_ranges(const JointAngles& joints) {
  JointAngles clamped = joints;
  for (int j = 0; j < kJointCount; ++j) {
    const JointRange range = joint_range(j);
    float& value = clamped[static_cast<size_t>(j)];
    value = std::min(std::max(value, range.min_rad), range.max_rad);
  }
  return clamped;
}

} // namespace touchline::robot::nao
