#include "touchline/robot/nao/leg_kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace touchline::robot::nao {

namespace {

using Eigen::AngleAxisd;
using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double kQuarterPi = 0.78539816339744830962;

Matrix3d rot_x(double a) { return AngleAxisd(a, Vector3d::UnitX()).toRotationMatrix(); }
Matrix3d rot_y(double a) { return AngleAxisd(a, Vector3d::UnitY()).toRotationMatrix(); }
Matrix3d rot_z(double a) { return AngleAxisd(a, Vector3d::UnitZ()).toRotationMatrix(); }

/// The sign that mirrors the left leg's geometry onto the right.
double side_sign(Side side) { return side == Side::kLeft ? 1.0 : -1.0; }

/// HipYawPitch's rotation: about (0, 1, -1)/sqrt2 for the left leg, (0, 1, 1)/sqrt2 for the
/// right (the mirror image, with the angle's sign mirrored too).
Matrix3d hip_yaw_pitch_rotation(Side side, double q) {
  const double s = side_sign(side);
  return rot_x(s * kQuarterPi) * rot_z(-s * q) * rot_x(-s * kQuarterPi);
}

Vector3d hip_of(Side side, const LegDimensions& d) {
  return {0.0, side_sign(side) * d.hip_offset_y_mm, -d.hip_offset_z_mm};
}

double clamp_unit(double v) { return std::clamp(v, -1.0, 1.0); }

/// Into [-pi, pi]: differences of atan2 near +-pi must not jump by a full turn.
double wrap(double a) { return std::remainder(a, 2 * 3.14159265358979323846); }

/// The knee angle that puts the ankle `distance` from the hip (0 beyond reach).
double knee_for(double distance, const LegDimensions& d) {
  const double a = d.thigh_mm, b = d.tibia_mm;
  return std::acos(clamp_unit((distance * distance - a * a - b * b) / (2 * a * b)));
}

} // namespace

LegJoints leg_joints(const JointAngles& j, Side side) {
  auto at = [&](Joint joint) { return static_cast<double>(j[static_cast<size_t>(joint)]); };
  if (side == Side::kLeft)
    return {at(kLHipYawPitch), at(kLHipRoll), at(kLHipPitch), at(kLKneePitch), at(kLAnklePitch), at(kLAnkleRoll)};
  return {at(kLHipYawPitch), at(kRHipRoll), at(kRHipPitch), at(kRKneePitch), at(kRAnklePitch), at(kRAnkleRoll)};
}

void set_leg_joints(JointAngles& j, Side side, const LegJoints& leg) {
  auto set = [&](Joint joint, double v) { j[static_cast<size_t>(joint)] = static_cast<float>(v); };
  set(kLHipYawPitch, leg.hip_yaw_pitch);
  const bool left = side == Side::kLeft;
  set(left ? kLHipRoll : kRHipRoll, leg.hip_roll);
  set(left ? kLHipPitch : kRHipPitch, leg.hip_pitch);
  set(left ? kLKneePitch : kRKneePitch, leg.knee_pitch);
  set(left ? kLAnklePitch : kRAnklePitch, leg.ankle_pitch);
  set(left ? kLAnkleRoll : kRAnkleRoll, leg.ankle_roll);
}

Isometry3d sole_in_torso(Side side, const LegJoints& q, const LegDimensions& d) {
  Isometry3d t = Isometry3d::Identity();
  t.translate(hip_of(side, d));
  t.rotate(hip_yaw_pitch_rotation(side, q.hip_yaw_pitch) * rot_x(q.hip_roll) * rot_y(q.hip_pitch));
  t.translate(Vector3d(0, 0, -d.thigh_mm));
  t.rotate(rot_y(q.knee_pitch));
  t.translate(Vector3d(0, 0, -d.tibia_mm));
  t.rotate(rot_y(q.ankle_pitch) * rot_x(q.ankle_roll));
  t.translate(Vector3d(0, 0, -d.foot_height_mm));
  return t;
}

namespace {

/// The ankle's pose in the hip frame (after the hip translation, before HipYawPitch).
Isometry3d ankle_from_hip(Side side, const Isometry3d& sole, const LegDimensions& d) {
  Isometry3d ankle = sole;
  ankle.translate(Vector3d(0, 0, d.foot_height_mm));
  Isometry3d from_hip = Isometry3d::Identity();
  from_hip.translation() = ankle.translation() - hip_of(side, d);
  from_hip.linear() = ankle.linear();
  return from_hip;
}

/// Knee, ankle pitch and ankle roll from where the hip lies as seen from the ankle (this
/// does not depend on the hip's three joints).
void knee_and_ankle(const Isometry3d& ankle, const LegDimensions& d, LegJoints& q) {
  const Vector3d hip = ankle.inverse().translation(); // the hip, in the ankle frame
  q.knee_pitch = knee_for(hip.norm(), d);
  // hip = Rx(-roll) Ry(-pitch) v, v = (0, 0, tibia) + Ry(-knee) (0, 0, thigh).
  q.ankle_roll = std::atan2(hip.y(), hip.z());
  const double w_z = std::hypot(hip.y(), hip.z());
  const double v_x = -d.thigh_mm * std::sin(q.knee_pitch);
  const double v_z = d.tibia_mm + d.thigh_mm * std::cos(q.knee_pitch);
  q.ankle_pitch = wrap(std::atan2(v_x, v_z) - std::atan2(hip.x(), w_z));
}

} // namespace

double hip_yaw_pitch_for(Side side, const Isometry3d& sole, const LegDimensions& d) {
  const Isometry3d ankle = ankle_from_hip(side, sole, d);
  LegJoints q;
  knee_and_ankle(ankle, d, q);
  // The hip's rotation: HipYawPitch * Rx(roll) * Ry(pitch) = ankle * (Ry(knee + ankle pitch) Rx(ankle roll))^-1.
  const Matrix3d hip = ankle.linear() * rot_x(-q.ankle_roll) * rot_y(-(q.knee_pitch + q.ankle_pitch));
  // Rx(-s pi/4) * hip = Rz(-s q) * Rx(roll - s pi/4) * Ry(pitch): a z-x-y decomposition.
  const double s = side_sign(side);
  const Matrix3d m = rot_x(-s * kQuarterPi) * hip;
  return -s * std::atan2(-m(0, 1), m(1, 1));
}

LegJoints leg_ik(Side side, const Isometry3d& sole, double hip_yaw_pitch, const LegDimensions& d) {
  LegJoints q;
  q.hip_yaw_pitch = hip_yaw_pitch;
  const Isometry3d ankle = ankle_from_hip(side, sole, d);
  const Matrix3d undo_hyp = hip_yaw_pitch_rotation(side, hip_yaw_pitch).transpose();
  const Vector3d p = undo_hyp * ankle.translation(); // ankle in the frame after HipYawPitch
  q.knee_pitch = knee_for(p.norm(), d);
  // The leg below HipRoll lies in one plane: p = Rx(roll) Ry(pitch) u, u = (ux, 0, uz).
  q.hip_roll = std::atan2(p.y(), -p.z());
  const double u_z = -std::hypot(p.y(), p.z());
  // u = Ry(pitch) u0 with u0 = (0, 0, -thigh) + Ry(knee) (0, 0, -tibia).
  const double u0_x = -d.tibia_mm * std::sin(q.knee_pitch);
  const double u0_z = -d.thigh_mm - d.tibia_mm * std::cos(q.knee_pitch);
  q.hip_pitch = wrap(std::atan2(p.x(), u_z) - std::atan2(u0_x, u0_z));
  // What the ankle must still turn: Ry(ankle pitch) Rx(ankle roll) Rz(yaw left over).
  const Matrix3d rest = (rot_x(q.hip_roll) * rot_y(q.hip_pitch + q.knee_pitch)).transpose() * undo_hyp * ankle.linear();
  q.ankle_roll = std::asin(clamp_unit(-rest(1, 2)));
  q.ankle_pitch = std::atan2(rest(0, 2), rest(2, 2));
  return q;
}

double yaw_of(const Matrix3d& r) { return std::atan2(r(1, 0), r(0, 0)); }

} // namespace touchline::robot::nao
