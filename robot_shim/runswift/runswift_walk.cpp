// The ONE source of ours that includes rUNSWift's headers: their Walk2014Generator behind
// our WalkEngine seam. Per tick, in the order their own MotionAdapter keeps: sensors into
// their Kinematics, the DH chain, BodyModel (which turns the foot pressure into the
// support foot), then makeJoints. Their macros (MIN, MAX, DEG2RAD, ...) and their Joints
// namespace stay in this file.
#include "touchline/robot/runswift_walk.hpp"

#include <algorithm>
#include <cmath>

#include "runswift_compat.hpp"
#include "touchline/robot/nao/joints.hpp"

// Theirs, from the clone (-I <clone>/robot).
#include "motion/MotionDefs.hpp"
#include "motion/generator/BodyModel.hpp"
#include "motion/generator/Walk2014Generator.hpp"
#include "perception/kinematics/Kinematics.hpp"
#include "types/ActionCommand.hpp"
#include "types/MotionDebugInfo.hpp"
#include "types/Odometry.hpp"
#include "types/SensorValues.hpp"

namespace touchline::robot {

namespace {

namespace nao = touchline::robot::nao;
using OurAction = api::ActionCommand::ActionType;

/// Our joint index -> theirs (both in LoLA's V6 order; by name, so a layout change of
/// theirs shows as a compile error, not a silent shuffle).
constexpr int kTheirJoint[nao::kJointCount] = {
    Joints::HeadYaw,        Joints::HeadPitch,     Joints::LShoulderPitch, Joints::LShoulderRoll,
    Joints::LElbowYaw,      Joints::LElbowRoll,    Joints::LWristYaw,      Joints::LHipYawPitch,
    Joints::LHipRoll,       Joints::LHipPitch,     Joints::LKneePitch,     Joints::LAnklePitch,
    Joints::LAnkleRoll,     Joints::RHipRoll,      Joints::RHipPitch,      Joints::RKneePitch,
    Joints::RAnklePitch,    Joints::RAnkleRoll,    Joints::RShoulderPitch, Joints::RShoulderRoll,
    Joints::RElbowYaw,      Joints::RElbowRoll,    Joints::RWristYaw,      Joints::LHand,
    Joints::RHand};
static_assert(Joints::NUMBER_OF_JOINTS == nao::kJointCount, "a V6 build of theirs has 25 joints");

constexpr int kTheirFsr[nao::kFsrCount] = {
    Sensors::LFoot_FSR_FrontLeft, Sensors::LFoot_FSR_FrontRight, Sensors::LFoot_FSR_RearLeft,
    Sensors::LFoot_FSR_RearRight, Sensors::RFoot_FSR_FrontLeft,  Sensors::RFoot_FSR_FrontRight,
    Sensors::RFoot_FSR_RearLeft,  Sensors::RFoot_FSR_RearRight};

/// Our body command as theirs. Walking (and standing: walking at zero, ready in their
/// crouch) passes bend 1, which their walk expects of a WALK; our speed scale is applied
/// to the velocity, theirs left at 1.
ActionCommand::Body their_body(const api::ActionCommand::Body& ours) {
  const float speed = std::clamp(std::isfinite(ours.speed) ? ours.speed : 0.f, 0.f, 1.f);
  auto finite = [](float v) { return std::isfinite(v) ? v : 0.f; };
  const auto foot = ours.foot == api::ActionCommand::Foot::LEFT ? ActionCommand::Body::LEFT : ActionCommand::Body::RIGHT;
  if (ours.actionType == OurAction::KICK || ours.actionType == OurAction::DRIBBLE)
    return ActionCommand::Body(ActionCommand::Body::KICK, 0, 0, 0, std::clamp(finite(ours.power), 0.f, 1.f), 1, 1, foot);
  if (ours.actionType != OurAction::WALK) return ActionCommand::Body(ActionCommand::Body::WALK, 0, 0, 0, 1, 1, 1);
  return ActionCommand::Body(ActionCommand::Body::WALK, static_cast<int>(std::lround(finite(ours.forward) * speed)),
                             static_cast<int>(std::lround(finite(ours.left) * speed)), finite(ours.turn) * speed, 1, 1,
                             1);
}

class RunswiftWalk : public WalkEngine {
 public:
  explicit RunswiftWalk(const RunswiftWalkDef& def) : sensors_(true) {
    walk_.readOptions(runswift::options(def.config_file));
    body_model_.kinematics = &kinematics_;
  }
  std::string name() const override { return "runswift"; }
  int64_t period_us() const override { return std::lround(MOTION_DT * 1e6); }
  EngineOutputKind output_kind() const override { return EngineOutputKind::kJoints; }

  void start(WalkEngineOutput& out) override {
    // Their start-up reads its previous joints: the robot standing with legs straight.
    for (int j = 0; j < nao::kJointCount; ++j) out.joints[static_cast<size_t>(j)] = sensors_.joints.angles[kTheirJoint[j]];
  }

  void tick(const api::ActionCommand::Body& request, const nao::Sensors& sensors, WalkEngineOutput& out) override {
    for (int j = 0; j < nao::kJointCount; ++j) sensors_.joints.angles[kTheirJoint[j]] = sensors.joints[static_cast<size_t>(j)];
    for (int f = 0; f < nao::kFsrCount; ++f) sensors_.sensors[kTheirFsr[f]] = sensors.fsr_kg[static_cast<size_t>(f)];
    sensors_.sensors[Sensors::InertialSensor_GyroscopeX] = sensors.gyro_x_rad_s;
    sensors_.sensors[Sensors::InertialSensor_GyroscopeY] = sensors.gyro_y_rad_s;
    // Their code reads yaw rate clockwise-positive (the V5's sense; their MotionAdapter flips a
    // V6's reading into it, and their odometry negates it back): ours is anticlockwise-positive.
    sensors_.sensors[Sensors::InertialSensor_GyroscopeZ] = -sensors.gyro_z_rad_s;
    sensors_.sensors[Sensors::InertialSensor_AngleX] = sensors.angle_x_rad;
    sensors_.sensors[Sensors::InertialSensor_AngleY] = sensors.angle_y_rad;

    kinematics_.setSensorValues(sensors_);
    kinematics_.updateDHChain();
    body_model_.update(&odometry_, sensors_);
    ActionCommand::All all;
    all.body = their_body(request);
    MotionDebugInfo debug;
    const JointValues joints = walk_.makeJoints(&all, &odometry_, sensors_, body_model_, 0.f, 0.f, debug);
    for (int j = 0; j < nao::kJointCount; ++j) out.joints[static_cast<size_t>(j)] = joints.angles[kTheirJoint[j]];

    status_.active = request;
    status_.standing = walk_.walk2014Option != Walk2014Generator::WALK && walk_.walk2014Option != Walk2014Generator::KICK;
    status_.kick_phase = walk_.walk2014Option == Walk2014Generator::KICK ? 2 : 0;
  }

  WalkEngineStatus status() const override { return status_; }
  std::optional<Pose2D> own_odometry() const override {
    return Pose2D{odometry_.forward, odometry_.left, odometry_.turn};
  }

 private:
  Walk2014Generator walk_;
  Kinematics kinematics_;
  BodyModel body_model_;
  Odometry odometry_;
  SensorValues sensors_;
  WalkEngineStatus status_;
};

} // namespace

std::unique_ptr<WalkEngine> make_runswift_walk(const RunswiftWalkDef& def) {
  return std::make_unique<RunswiftWalk>(def);
}

} // namespace touchline::robot
