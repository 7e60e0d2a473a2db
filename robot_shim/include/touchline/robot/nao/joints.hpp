#pragma once
// The 25 joints of a Nao V6, in the order the robot's own interface (LoLA) and the SPL
// teams' code use: HipYawPitch is one motor shared by both legs, so it appears once (as
// LHipYawPitch). Angles in radians (LHand/RHand: 0 closed .. 1 open). Limits are the
// joints' published ranges (Aldebaran/SoftBank's NAO V6 joint documentation).
#include <array>
#include <optional>
#include <string>

namespace touchline::robot::nao {

enum Joint : int {
  kHeadYaw, kHeadPitch,
  kLShoulderPitch, kLShoulderRoll, kLElbowYaw, kLElbowRoll, kLWristYaw,
  kLHipYawPitch, kLHipRoll, kLHipPitch, kLKneePitch, kLAnklePitch, kLAnkleRoll,
  kRHipRoll, kRHipPitch, kRKneePitch, kRAnklePitch, kRAnkleRoll,
  kRShoulderPitch, kRShoulderRoll, kRElbowYaw, kRElbowRoll, kRWristYaw,
  kLHand, kRHand,
  kJointCount
};

/// One command (or reading) of every joint, indexed by Joint.
using JointAngles = std::array<float, kJointCount>;

/// "LKneePitch", ...: the names the robot's documentation uses.
const char* joint_name(int joint);

/// A joint's range, radians.
struct JointRange {
  float min_rad = 0;
  float max_rad = 0;
};
JointRange joint_range(int joint);

/// Whether `joint` moves a foot (HipYawPitch .. RAnkleRoll).
bool is_leg_joint(int joint);

/// What a walk engine may command: every joint finite, and every leg joint within its
/// range widened by `tolerance_rad` (a sign or unit error is far beyond; arms, head and
/// hands beyond their ranges only meet their stops, see clamp_to_ranges). Nothing when
/// fine, else one line naming the first bad joint: "LKneePitch = nan (range -0.092..2.113 rad)".
std::optional<std::string> check_joints(const JointAngles& joints, float tolerance_rad);

/// Where position-controlled motors end up when told `joints`: each within its range.
JointAngles clamp_to_ranges(const JointAngles& joints);

/// The fastest a leg joint turns, rad/s: its motor's no-load speed through its gear
/// (Aldebaran's NAO motor documentation: the leg motor runs at 8000 rpm unloaded, geared
/// 201.3:1 for HipYawPitch and the rolls, 130.85:1 for the pitches: 4.16 and 6.40 rad/s).
/// Infinity for the other joints: they move no foot.
float joint_max_speed_rad_s(int joint);

/// Where the motors are `dt_s` after being at `from` and told `target`: each leg joint moves
/// towards its target by at most joint_max_speed_rad_s * dt_s, the rest reach theirs; all
/// within their ranges. (A walk's request can move faster than its motors, as rUNSWift's kick
/// asks the ankle for about 49 rad/s; on the robot the motor lags, and so here.)
JointAngles follow(const JointAngles& from, const JointAngles& target, float dt_s);

} // namespace touchline::robot::nao
