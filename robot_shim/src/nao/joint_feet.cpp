#include "touchline/robot/nao/joint_feet.hpp"

#include <cmath>

#include "touchline/angles.hpp"

namespace touchline::robot::nao {

namespace {

/// `base` moved by (dx, dy) in its own frame and turned by dtheta.
Pose2D compose(const Pose2D& base, double dx, double dy, double dtheta) {
  const double c = std::cos(base.theta_rad), s = std::sin(base.theta_rad);
  return {static_cast<float>(base.x_mm + c * dx - s * dy), static_cast<float>(base.y_mm + s * dx + c * dy),
          normalise_angle(static_cast<float>(base.theta_rad + dtheta))};
}

Eigen::Isometry3d sole(const JointAngles& joints, Side side, const LegDimensions& legs) {
  return sole_in_torso(side, leg_joints(joints, side), legs);
}

} // namespace

JointFeet::JointFeet(const JointFeetDef& def) : def_(def) {}

void JointFeet::reset(const JointAngles& joints) {
  const Eigen::Isometry3d left = sole(joints, Side::kLeft, def_.legs);
  const Eigen::Isometry3d right = sole(joints, Side::kRight, def_.legs);
  const float left_yaw = static_cast<float>(yaw_of(left.linear()));
  const float right_yaw = static_cast<float>(yaw_of(right.linear()));
  const Eigen::Vector3d mid = 0.5 * (left.translation() + right.translation());
  const float heading = mean_heading(left_yaw, right_yaw);
  // Each sole's ground pose relative to the body at the origin.
  auto relative = [&](const Eigen::Isometry3d& s, float yaw) {
    const double dx = s.translation().x() - mid.x(), dy = s.translation().y() - mid.y();
    const double c = std::cos(heading), sn = std::sin(heading);
    return Pose2D{static_cast<float>(c * dx + sn * dy), static_cast<float>(-sn * dx + c * dy),
                  normalise_angle(yaw - heading)};
  };
  feet_ = {relative(left, left_yaw), relative(right, right_yaw)};
  stance_ = right.translation().z() < left.translation().z() - def_.touchdown_mm ? Side::kRight : Side::kLeft;
  lifted_ = false;
  touched_down_ = false;
  stance_changed_ = false;
  swing_height_mm_ = 0;
}

const FeetPose& JointFeet::update(const JointAngles& joints) {
  const Eigen::Isometry3d left = sole(joints, Side::kLeft, def_.legs);
  const Eigen::Isometry3d right = sole(joints, Side::kRight, def_.legs);
  auto other_from_stance = [&] {
    return stance_ == Side::kLeft ? Eigen::Isometry3d(left.inverse() * right)
                                  : Eigen::Isometry3d(right.inverse() * left);
  };
  Eigen::Isometry3d relative = other_from_stance();
  double height = relative.translation().z();
  // The stance sole itself rose: the weight is already on the other, which stays put
  // while this one lifts.
  const bool lifted_off = height < -def_.lift_mm;
  if (lifted_off) {
    stance_ = other(stance_);
    lifted_ = false;
    relative = other_from_stance();
    height = relative.translation().z();
  }
  if (height > def_.lift_mm) lifted_ = true;
  swing_height_mm_ = height;
  const Pose2D stance_foot = foot(stance_);
  foot(other(stance_)) = compose(stance_foot, relative.translation().x(), relative.translation().y(),
                                 yaw_of(relative.linear()));
  // A lifted sole back on the ground takes the weight from the next tick on: this tick's
  // last bit of its motion is still its own.
  touched_down_ = lifted_ && height < def_.touchdown_mm;
  if (touched_down_) {
    stance_ = other(stance_);
    lifted_ = false;
  }
  stance_changed_ = lifted_off || touched_down_;
  return feet_;
}

} // namespace touchline::robot::nao
