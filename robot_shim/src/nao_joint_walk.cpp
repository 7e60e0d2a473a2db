#include "touchline/robot/nao_joint_walk.hpp"

#include <algorithm>
#include <cmath>

#include "touchline/angles.hpp"

namespace touchline::robot {

namespace {

using nao::Side;

/// Arms hanging by the sides, within every joint's range.
void hang_arms(nao::JointAngles& j) {
  j[nao::kLShoulderPitch] = j[nao::kRShoulderPitch] = 1.5f;
  j[nao::kLShoulderRoll] = 0.1f;
  j[nao::kRShoulderRoll] = -0.1f;
  j[nao::kLElbowRoll] = -0.1f;
  j[nao::kRElbowRoll] = 0.1f;
}

/// A foot's ground pose as a sole pose in the frame of a torso standing upright at `torso`,
/// the sole `sole_z_mm` along the torso's z (negative: below it).
Eigen::Isometry3d sole_pose(const Pose2D& foot, const Pose2D& torso, double sole_z_mm) {
  const double dx = foot.x_mm - torso.x_mm, dy = foot.y_mm - torso.y_mm;
  const double c = std::cos(torso.theta_rad), s = std::sin(torso.theta_rad);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(c * dx + s * dy, -s * dx + c * dy, sole_z_mm);
  pose.linear() = Eigen::AngleAxisd(normalise_angle(foot.theta_rad - torso.theta_rad), Eigen::Vector3d::UnitZ())
                      .toRotationMatrix();
  return pose;
}

} // namespace

NaoJointWalk::NaoJointWalk(const NaoJointWalkDef& def, const WalkDef& walk, const KickDef& kick)
    : def_(def), gait_(walk, kick) {}

namespace {
/// Whether the kick's swing is what moves the feet now (its prepare still walks to a stop).
bool kick_swinging(const KickGenerator& kick) { return kick.running() && kick.last_phase() == KickPhase::kSwing; }
} // namespace

bool NaoJointWalk::left_lifted() const {
  const KickGenerator& kick = gait_.kick();
  if (kick_swinging(kick)) return kick.request().foot == api::ActionCommand::Foot::LEFT;
  return gait_.walk().left_swinging();
}

float NaoJointWalk::swing_lift_mm() const {
  const KickGenerator& kick = gait_.kick();
  if (kick_swinging(kick)) {
    const float s = static_cast<float>(kick.ticks_in_phase()) / static_cast<float>(kick.plan().total_ticks());
    // Up within the first ticks (the wind-up starts slowly), down as the foot comes back.
    return def_.kick_lift_mm * std::min(1.f, 4 * std::sin(kPi * std::clamp(s, 0.f, 1.f)));
  }
  const WalkCycle& walk = gait_.walk();
  if (walk.standing()) return 0.f;
  // Where the swing is within the step's single support, as WalkCycle moves the foot.
  const WalkDef& w = walk.def();
  const float step_s = 0.5f * w.period_s;
  const float into_step_s = walk.phase_s() - (walk.left_swinging() ? 0.f : step_s);
  const float single_support_s = std::max(1e-6f, (1 - w.double_support) * step_s);
  const float s = std::clamp((into_step_s - 0.5f * w.double_support * step_s) / single_support_s, 0.f, 1.f);
  return def_.swing_height_mm * std::sin(kPi * s);
}

void NaoJointWalk::joints_for_plan(nao::JointAngles& joints) const {
  const FeetPose& feet = gait_.feet();
  const Pose2D torso{0.5f * (feet.left.x_mm + feet.right.x_mm), 0.5f * (feet.left.y_mm + feet.right.y_mm),
                     mean_heading(feet.left.theta_rad, feet.right.theta_rad)};
  const float lift = swing_lift_mm();
  const bool left_up = lift > 0 && left_lifted();
  const double ground_z = -static_cast<double>(def_.sole_below_torso_mm);
  const Eigen::Isometry3d left = sole_pose(feet.left, torso, ground_z + (left_up ? lift : 0.f));
  const Eigen::Isometry3d right = sole_pose(feet.right, torso, ground_z + (left_up || lift <= 0 ? 0.f : lift));
  // One HipYawPitch for both legs: the feet's yaws about the torso are mirror images, so
  // each leg alone would need nearly the same one.
  const double hyp = 0.5 * (nao::hip_yaw_pitch_for(Side::kLeft, left, def_.legs) +
                            nao::hip_yaw_pitch_for(Side::kRight, right, def_.legs));
  joints.fill(0.f);
  hang_arms(joints);
  nao::set_leg_joints(joints, Side::kLeft, nao::leg_ik(Side::kLeft, left, hyp, def_.legs));
  nao::set_leg_joints(joints, Side::kRight, nao::leg_ik(Side::kRight, right, hyp, def_.legs));
}

void NaoJointWalk::start(WalkEngineOutput& out) { joints_for_plan(out.joints); }

void NaoJointWalk::tick(const api::ActionCommand::Body& request, const nao::Sensors&, WalkEngineOutput& out) {
  // A dive's feet half a metre apart sideways have no leg pose: this engine stands instead.
  const api::ActionCommand::Body body = is_dive(request.actionType) ? api::ActionCommand::stand() : request;
  gait_.tick(body, static_cast<float>(def_.period_us) * 1e-6f);
  joints_for_plan(out.joints);
}

} // namespace touchline::robot
