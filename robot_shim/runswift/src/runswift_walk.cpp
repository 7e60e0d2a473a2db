// The one source of ours that includes rUNSWift's headers: their macros (MIN, MAX, ABS,
// DEG2RAD) and their Joints/Sensors namespaces stay in this file. Converts Touchline's
// frames to their SensorValues and ActionCommand, runs one tick of their motion thread's
// walk path, and converts their JointValues and Odometry back.
#include "touchline/robot/runswift/runswift_walk.hpp"

#include <cmath>
#include <exception>
#include <iterator>
#include <sstream>
#include <utility>

#include "motion/MotionDefs.hpp"
#include "motion/generator/BodyModel.hpp"
#include "motion/generator/Walk2014Generator.hpp"
#include "perception/kinematics/Kinematics.hpp"
#include "types/ActionCommand.hpp"
#include "types/JointValues.hpp"
#include "types/MotionDebugInfo.hpp"
#include "types/Odometry.hpp"
#include "types/SensorValues.hpp"
#include "utils/body.hpp"

#include "touchline/robot/runswift/walk_options.hpp"

namespace touchline::robot::runswift {

namespace {

// Their period must be the one we announce: a clone built for another robot (CTC_2_1: a V5,
// 10 ms) fails here rather than walking at the wrong rate.
static_assert(static_cast<int64_t>(MOTION_DT * 1e6 + 0.5) == RunswiftWalk::kControlPeriodUs,
              "rUNSWift's MOTION_DT is not the V6's 12.2 ms");
static_assert(Joints::NUMBER_OF_JOINTS == static_cast<int>(nao::kJointCount),
              "rUNSWift's joint list is not the V6's 25 joints");

/// Ours to theirs by name, so a clone whose Joints order differs still maps right.
constexpr std::pair<nao::Joint, Joints::JointCode> kJointMap[] = {
    {nao::HeadYaw, Joints::HeadYaw},
    {nao::HeadPitch, Joints::HeadPitch},
    {nao::LShoulderPitch, Joints::LShoulderPitch},
    {nao::LShoulderRoll, Joints::LShoulderRoll},
    {nao::LElbowYaw, Joints::LElbowYaw},
    {nao::LElbowRoll, Joints::LElbowRoll},
    {nao::LWristYaw, Joints::LWristYaw},
    {nao::LHipYawPitch, Joints::LHipYawPitch},
    {nao::LHipRoll, Joints::LHipRoll},
    {nao::LHipPitch, Joints::LHipPitch},
    {nao::LKneePitch, Joints::LKneePitch},
    {nao::LAnklePitch, Joints::LAnklePitch},
    {nao::LAnkleRoll, Joints::LAnkleRoll},
    {nao::RHipRoll, Joints::RHipRoll},
    {nao::RHipPitch, Joints::RHipPitch},
    {nao::RKneePitch, Joints::RKneePitch},
    {nao::RAnklePitch, Joints::RAnklePitch},
    {nao::RAnkleRoll, Joints::RAnkleRoll},
    {nao::RShoulderPitch, Joints::RShoulderPitch},
    {nao::RShoulderRoll, Joints::RShoulderRoll},
    {nao::RElbowYaw, Joints::RElbowYaw},
    {nao::RElbowRoll, Joints::RElbowRoll},
    {nao::RWristYaw, Joints::RWristYaw},
    {nao::LHand, Joints::LHand},
    {nao::RHand, Joints::RHand},
};
static_assert(std::size(kJointMap) == nao::kJointCount);

/// A finite number, else 0 (a NaN request must not become an int's undefined behaviour).
float finite_or_zero(float v) { return std::isfinite(v) ? v : 0.f; }

/// mm/s as their ActionCommand's int, bounded far beyond their walk's own limits.
int to_mm_s(float v) { return static_cast<int>(std::lround(std::fmax(-10000.f, std::fmin(10000.f, finite_or_zero(v))))); }

/// Our walk command as their behaviour's helpers (actioncommand.py: stand, crouch, walk,
/// kick) build it: bend 1 keeps the walking crouch, bend 0 and no power stand up.
ActionCommand::Body to_body(const nao::WalkCommand& c) {
  using Body = ActionCommand::Body;
  const float speed = std::fmax(0.f, std::fmin(1.f, finite_or_zero(c.speed_fraction)));
  const float turn = finite_or_zero(c.turn_rad_s);
  switch (c.kind) {
    case nao::WalkCommand::Kind::walk:
      return Body(Body::WALK, to_mm_s(c.forward_mm_s), to_mm_s(c.left_mm_s), turn, /*power=*/0.f,
                  /*bend=*/1.f, speed);
    case nao::WalkCommand::Kind::crouch:
      return Body(Body::WALK, 0, 0, 0.f, /*power=*/0.4f, /*bend=*/1.f, 1.f);
    case nao::WalkCommand::Kind::kick: {
      const float power = std::fmax(0.f, std::fmin(1.f, finite_or_zero(c.kick_power)));
      return Body(Body::KICK, 0, 0, turn, power, /*bend=*/0.f, /*speed=*/0.f,
                  c.kick_foot == nao::WalkCommand::Foot::left ? Body::LEFT : Body::RIGHT);
    }
    case nao::WalkCommand::Kind::stand:
      break;
  }
  return Body(Body::WALK, 0, 0, 0.f, /*power=*/0.1f, /*bend=*/0.f, 1.f);
}

/// Our sensor frame as their SensorValues, as their MotionAdapter hands it on (gyro Z
/// negated on a V6 outside their simulator).
SensorValues to_sensor_values(const nao::NaoSensorFrame& in, bool negate_gyro_z) {
  SensorValues s(true);
  for (const auto& [ours, theirs] : kJointMap) s.joints.angles[theirs] = in.joint_angles_rad[ours];
  s.sensors[Sensors::LFoot_FSR_FrontLeft] = in.left_foot.front_left_kg;
  s.sensors[Sensors::LFoot_FSR_FrontRight] = in.left_foot.front_right_kg;
  s.sensors[Sensors::LFoot_FSR_RearLeft] = in.left_foot.rear_left_kg;
  s.sensors[Sensors::LFoot_FSR_RearRight] = in.left_foot.rear_right_kg;
  s.sensors[Sensors::RFoot_FSR_FrontLeft] = in.right_foot.front_left_kg;
  s.sensors[Sensors::RFoot_FSR_FrontRight] = in.right_foot.front_right_kg;
  s.sensors[Sensors::RFoot_FSR_RearLeft] = in.right_foot.rear_left_kg;
  s.sensors[Sensors::RFoot_FSR_RearRight] = in.right_foot.rear_right_kg;
  s.sensors[Sensors::InertialSensor_GyroscopeX] = in.gyro_x_rad_s;
  s.sensors[Sensors::InertialSensor_GyroscopeY] = in.gyro_y_rad_s;
  s.sensors[Sensors::InertialSensor_GyroscopeZ] = negate_gyro_z ? -in.gyro_z_rad_s : in.gyro_z_rad_s;
  s.sensors[Sensors::InertialSensor_AngleX] = in.angle_x_rad;
  s.sensors[Sensors::InertialSensor_AngleY] = in.angle_y_rad;
  return s;
}

/// Whether a joint moves a foot: hip, knee and ankle joints.
bool is_leg_joint(std::size_t joint) { return joint >= nao::LHipYawPitch && joint <= nao::RAnkleRoll; }

/// The one check of an engine's joints: NaN or infinity anywhere, or a leg joint further
/// than `leg_tolerance_rad` beyond its V6 limit, is a fault (returns its description);
/// every other joint beyond its limit is clipped to it. Returns "" when the frame is good.
/// `beyond` keeps, per joint, the furthest beyond its limit seen.
std::string check_and_clip(nao::JointArray& joints, float leg_tolerance_rad, nao::JointArray& beyond) {
  std::string fault;
  int faulty = 0;
  for (std::size_t i = 0; i < nao::kJointCount; ++i) {
    const auto [min, max] = nao::kJointLimits[i];
    float& a = joints[i];
    if (std::isfinite(a)) beyond[i] = std::fmax(beyond[i], std::fmax(min - a, a - max));
    const bool bad = !std::isfinite(a) ||
                     (is_leg_joint(i) && (a < min - leg_tolerance_rad || a > max + leg_tolerance_rad));
    if (bad) {
      if (faulty++ == 0) {
        std::ostringstream out;
        out << nao::joint_name(static_cast<int>(i)) << " = " << a << " rad (limits " << min << " .. " << max
            << ")";
        fault = out.str();
      }
      continue;
    }
    a = std::fmax(min, std::fmin(max, a));
  }
  if (faulty > 1) fault += " and " + std::to_string(faulty - 1) + " more joint" + (faulty > 2 ? "s" : "");
  return fault;
}

} // namespace

struct RunswiftWalk::Engine {
  Walk2014Generator walk;
  Kinematics kinematics;
  BodyModel body_model;
};

RunswiftWalk::RunswiftWalk(const RunswiftWalkDef& def)
    : engine_(std::make_unique<Engine>()), def_(def) {
  // As their MotionAdapter's constructor: the generator first, then its options.
  engine_->walk.readOptions(to_variables_map(load_walk_options(def.option_files)));
}

RunswiftWalk::~RunswiftWalk() = default;

nao::NaoJointFrame RunswiftWalk::step(const nao::WalkCommand& command, const nao::NaoSensorFrame& sensors) noexcept {
  nao::NaoJointFrame out;
  std::string fault; // why the tick is faulty, when it can be said (a message needs memory)
  bool faulty = false;
  try {
    Engine& e = *engine_;
    const SensorValues s = to_sensor_values(sensors, def_.negate_gyro_z);
    // Their MotionAdapter::tick, walk path: kinematics, DH chain, body model, generator.
    e.kinematics.setSensorValues(s);
    e.kinematics.updateDHChain();
    Odometry odometry; // zero: makeJoints adds this tick's increment
    e.body_model.kinematics = &e.kinematics;
    e.body_model.update(&odometry, s);
    ActionCommand::All request;
    request.body = to_body(command);
    MotionDebugInfo debug;
    const JointValues j = e.walk.makeJoints(&request, &odometry, s, e.body_model, finite_or_zero(command.ball_x_mm),
                                            finite_or_zero(command.ball_y_mm), debug);
    for (const auto& [ours, theirs] : kJointMap) out.joint_angles_rad[ours] = j.angles[theirs];
    out.odometry_forward_mm = odometry.forward;
    out.odometry_left_mm = odometry.left;
    out.odometry_turn_rad = odometry.turn;
    fault = check_and_clip(out.joint_angles_rad, def_.leg_limit_tolerance_rad, beyond_limit_rad_);
    if (fault.empty() && !(std::isfinite(odometry.forward) && std::isfinite(odometry.left) && std::isfinite(odometry.turn)))
      fault = "odometry is not finite";
    faulty = !fault.empty();
  } catch (const std::exception& ex) {
    faulty = true;
    try {
      fault = std::string("threw: ") + ex.what();
    } catch (...) {
    }
  } catch (...) {
    faulty = true;
    try {
      fault = "threw a non-standard exception";
    } catch (...) {
    }
  }
  if (!faulty) {
    if (def_.limit_joint_speed && have_last_good_) {
      constexpr float kDt_s = static_cast<float>(kControlPeriodUs) * 1e-6f;
      for (std::size_t i = 0; i < nao::kJointCount; ++i) {
        const float most = nao::kJointMaxSpeed_rad_s[i] * kDt_s;
        out.joint_angles_rad[i] = std::fmax(last_good_[i] - most, std::fmin(last_good_[i] + most, out.joint_angles_rad[i]));
      }
    }
    last_good_ = out.joint_angles_rad;
    have_last_good_ = true;
    return out;
  }
  // Hold the last good joints; before any, the measured ones (clipped, NaN as 0).
  nao::NaoJointFrame held;
  held.engine_fault = true;
  if (have_last_good_) {
    held.joint_angles_rad = last_good_;
  } else {
    for (std::size_t i = 0; i < nao::kJointCount; ++i) {
      const auto [min, max] = nao::kJointLimits[i];
      held.joint_angles_rad[i] = std::fmax(min, std::fmin(max, finite_or_zero(sensors.joint_angles_rad[i])));
    }
  }
  ++fault_ticks_;
  try {
    fault_message_ = "rUNSWift walk: " + fault;
  } catch (...) { // out of memory for the message: the flag still says it
  }
  return held;
}

bool RunswiftWalk::left_foot_swinging() const { return engine_->body_model.isLeftPhase; }

const char* RunswiftWalk::walk_option() const {
  switch (engine_->walk.walk2014Option) {
    case Walk2014Generator::STAND: return "STAND";
    case Walk2014Generator::STANDUP: return "STANDUP";
    case Walk2014Generator::CROUCH: return "CROUCH";
    case Walk2014Generator::WALK: return "WALK";
    case Walk2014Generator::READY: return "READY";
    case Walk2014Generator::KICK: return "KICK";
    case Walk2014Generator::NONE: return "NONE";
    default: return "?";
  }
}

} // namespace touchline::robot::runswift
