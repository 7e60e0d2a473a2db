#pragma once
// Nao V6 leg kinematics of our own: forward (joint angles -> each sole's pose relative to
// the torso) and inverse (a sole pose -> the leg's joint angles). Frames: torso origin
// between the hips, HipOffsetZ above them; +x forward, +y left, +z up; millimetres.
// The sole frame sits FootHeight below the ankle joint, its z axis along the shin when the
// ankle is straight.
//
// Each leg, from the torso: translate to the hip (0, +-HipOffsetY, -HipOffsetZ), HipYawPitch
// about an axis tilted 45 degrees in the y-z plane (one motor for both legs; the axes
// mirror each other), HipRoll (x), HipPitch (y), thigh down, KneePitch (y), tibia down,
// AnklePitch (y), AnkleRoll (x), foot height down to the sole. Sign of HipYawPitch: a
// negative angle turns both toes outward (the left foot anticlockwise), as the joint's
// published range (-65.62..42.44 degrees: more outward than inward, where the legs meet)
// says and SPL walks (turn = -HipYawPitch) use.
#include <Eigen/Geometry>

#include "touchline/robot/nao/joints.hpp"

namespace touchline::robot::nao {

/// The leg's dimensions, millimetres (the NAO V6 published link lengths).
struct LegDimensions {
  double hip_offset_y_mm = 50.0;  ///< hip joint from the torso's mid-plane
  double hip_offset_z_mm = 85.0;  ///< hip joints below the torso origin
  double thigh_mm = 100.0;        ///< hip to knee
  double tibia_mm = 102.9;        ///< knee to ankle
  double foot_height_mm = 45.19;  ///< ankle to sole
  /// Torso origin to sole, legs straight: 333.09 mm.
  double straight_leg_mm() const { return hip_offset_z_mm + thigh_mm + tibia_mm + foot_height_mm; }
};

enum class Side { kLeft, kRight };
inline Side other(Side side) { return side == Side::kLeft ? Side::kRight : Side::kLeft; }

/// One leg's six joints, radians (hip_yaw_pitch shared with the other leg).
struct LegJoints {
  double hip_yaw_pitch = 0;
  double hip_roll = 0;
  double hip_pitch = 0;
  double knee_pitch = 0;
  double ankle_pitch = 0;
  double ankle_roll = 0;
};

/// The leg's joints out of the 25 (the right leg's hip_yaw_pitch is LHipYawPitch).
LegJoints leg_joints(const JointAngles& joints, Side side);
/// Writes a leg's joints into the 25 (hip_yaw_pitch into LHipYawPitch).
void set_leg_joints(JointAngles& joints, Side side, const LegJoints& leg);

/// Forward kinematics: the sole's pose in the torso frame.
Eigen::Isometry3d sole_in_torso(Side side, const LegJoints& leg, const LegDimensions& dims = {});

/// Inverse kinematics for a sole pose (torso frame) with HipYawPitch given (it is shared,
/// so a walk picks one for both legs): the ankle reaches the pose's position exactly when
/// it is within reach (beyond, the knee straightens and the leg points at it), the sole's
/// normal matches; the sole's yaw about its normal matches when hip_yaw_pitch is the one
/// hip_yaw_pitch_for() gives.
LegJoints leg_ik(Side side, const Eigen::Isometry3d& sole, double hip_yaw_pitch, const LegDimensions& dims = {});

/// The HipYawPitch that reaches `sole` exactly with this leg alone (six joints, six
/// degrees of freedom).
double hip_yaw_pitch_for(Side side, const Eigen::Isometry3d& sole, const LegDimensions& dims = {});

/// Yaw of a rotation about the vertical: the heading of its x axis projected on the ground.
double yaw_of(const Eigen::Matrix3d& rotation);

} // namespace touchline::robot::nao
