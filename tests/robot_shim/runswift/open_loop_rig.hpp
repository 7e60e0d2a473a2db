#pragma once
// An open-loop rig for a joint-space walk engine, for the rUNSWift walk's test and bench:
// the robot is position-controlled (each tick's joints are the last command), upright and
// fixed in the air but for its soles, and a crude contact model of our own turns the legs'
// forward kinematics into foot pressure:
// - the lower sole (by more than kTouchMm) bears the robot's whole weight;
// - when the higher sole comes down to the other's height, it takes the weight (touchdown:
//   walking falls onto the landing foot); while both stay level the weight stays put.
//   "Level" is within kTouchMm, far below a millimetre: a touchdown is the swing sole back
//   at the stance sole's height, not a millimetre above it (which came 1.5 ticks earlier and
//   shortened every step to 20 ticks);
// - at the start, both level, the weight is split evenly.
// Each sole's load is spread evenly over its four sensors. The body's travel is measured
// from the stance sole, which does not slide: the body moves by minus the stance sole's
// motion relative to the torso.
//
// The forward kinematics is ours, from the Nao V6's published dimensions. It leaves the hip
// yaw-pitch joint out: the rig's users walk straight, and check that joint stays 0.
#include <cmath>
#include <vector>

#include "touchline/robot/nao/nao_frames.hpp"
#include "touchline/robot/runswift/runswift_walk.hpp"

namespace touchline::robot::runswift::testing {

// Nao V6 leg dimensions (published), mm.
constexpr double kHipOffsetYMm = 50;
constexpr double kHipOffsetZMm = 85;
constexpr double kThighMm = 100;
constexpr double kTibiaMm = 102.9;
constexpr double kFootHeightMm = 45.19;
constexpr double kRobotMassKg = 5.48; ///< Nao V6 (published)
constexpr double kTouchMm = 0.01;     ///< soles within this of each other are both down (float noise)
constexpr double kDtS = RunswiftWalk::kControlPeriodUs * 1e-6;

struct Vec3 {
  double x = 0, y = 0, z = 0;
};
struct Mat3 {
  double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Mat3 operator*(const Mat3& o) const {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j];
    return r;
  }
  Vec3 operator*(const Vec3& v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
};
inline Mat3 rot_x(double a) {
  Mat3 r;
  r.m[1][1] = std::cos(a), r.m[1][2] = -std::sin(a), r.m[2][1] = std::sin(a), r.m[2][2] = std::cos(a);
  return r;
}
inline Mat3 rot_y(double a) {
  Mat3 r;
  r.m[0][0] = std::cos(a), r.m[0][2] = std::sin(a), r.m[2][0] = -std::sin(a), r.m[2][2] = std::cos(a);
  return r;
}
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }

/// A sole's centre relative to the torso (x forward, y left, z up, mm) and how far it is
/// tilted from the torso's horizontal (rad).
struct Sole {
  Vec3 position_mm;
  double tilt_rad = 0;
};

/// Hip roll, hip pitch, knee, ankle pitch, ankle roll: the leg's chain below the hip.
inline Sole sole_in_torso(const nao::JointArray& q, bool left) {
  using namespace nao;
  const double side = left ? 1 : -1;
  const int hip_roll = left ? LHipRoll : RHipRoll, hip_pitch = left ? LHipPitch : RHipPitch;
  const int knee = left ? LKneePitch : RKneePitch, ankle_pitch = left ? LAnklePitch : RAnklePitch;
  const int ankle_roll = left ? LAnkleRoll : RAnkleRoll;
  Vec3 p{0, side * kHipOffsetYMm, -kHipOffsetZMm};
  Mat3 r = rot_x(q[hip_roll]) * rot_y(q[hip_pitch]);
  p = p + r * Vec3{0, 0, -kThighMm};
  r = r * rot_y(q[knee]);
  p = p + r * Vec3{0, 0, -kTibiaMm};
  r = r * rot_y(q[ankle_pitch]) * rot_x(q[ankle_roll]);
  p = p + r * Vec3{0, 0, -kFootHeightMm};
  return {p, std::acos(std::fmin(1.0, r.m[2][2]))};
}

/// Runs a RunswiftWalk open loop, tick by tick, and keeps what the tests measure.
class OpenLoopRig {
 public:
  enum class Load { both, left, right };

  /// `level_pressure`: both soles always loaded alike (the walk never feels a touchdown).
  explicit OpenLoopRig(RunswiftWalk& walk, bool level_pressure = false)
      : walk_(walk), level_pressure_(level_pressure) {}

  /// One control tick with `command`; returns what the engine commanded.
  nao::NaoJointFrame tick(const nao::WalkCommand& command) {
    update_contact();
    const bool was_left_swing = walk_.left_foot_swinging();
    const nao::NaoJointFrame out = walk_.step(command, sensors_);
    time_s += kDtS;
    if (walk_.left_foot_swinging() != was_left_swing) switch_times_s.push_back(time_s);
    odometry_forward_mm += out.odometry_forward_mm;
    odometry_left_mm += out.odometry_left_mm;
    faults += out.engine_fault ? 1 : 0;
    max_abs_hip_yaw_pitch_rad = std::fmax(max_abs_hip_yaw_pitch_rad, std::fabs(out.joint_angles_rad[nao::LHipYawPitch]));
    sensors_.joint_angles_rad = out.joint_angles_rad; // position control, one tick behind
    return out;
  }

  const nao::NaoSensorFrame& sensors() const { return sensors_; }
  Load load() const { return load_; }

  double time_s = 0;
  double odometry_forward_mm = 0; ///< the engine's own odometry, summed
  double odometry_left_mm = 0;
  double body_forward_mm = 0;     ///< the body's travel by forward kinematics from the stance sole
  double body_left_mm = 0;
  double max_swing_height_mm = 0; ///< highest a sole rose above the other
  double max_abs_hip_yaw_pitch_rad = 0;
  double max_sole_tilt_rad = 0;
  std::vector<double> switch_times_s; ///< when the engine's support foot changed
  int faults = 0;

 private:
  void update_contact() {
    const Sole l = sole_in_torso(sensors_.joint_angles_rad, true);
    const Sole r = sole_in_torso(sensors_.joint_angles_rad, false);
    max_sole_tilt_rad = std::fmax(max_sole_tilt_rad, std::fmax(l.tilt_rad, r.tilt_rad));
    const double lz = l.position_mm.z, rz = r.position_mm.z;
    max_swing_height_mm = std::fmax(max_swing_height_mm, std::fabs(lz - rz));
    const Load before = load_;
    if (lz < rz - kTouchMm) {
      load_ = Load::left, airborne_ = Load::right;
    } else if (rz < lz - kTouchMm) {
      load_ = Load::right, airborne_ = Load::left;
    } else if (airborne_ != Load::both) { // the raised sole came down: it takes the weight
      load_ = airborne_, airborne_ = Load::both;
    }
    if (level_pressure_) load_ = Load::both;
    // The stance sole does not slide: while it stays the stance sole, the body moves by
    // minus its motion relative to the torso.
    if (load_ == before && load_ != Load::both && have_soles_) {
      const Sole& now = load_ == Load::left ? l : r;
      const Sole& prev = load_ == Load::left ? prev_left_ : prev_right_;
      body_forward_mm -= now.position_mm.x - prev.position_mm.x;
      body_left_mm -= now.position_mm.y - prev.position_mm.y;
    }
    prev_left_ = l, prev_right_ = r, have_soles_ = true;
    const double left_kg = load_ == Load::left ? kRobotMassKg : load_ == Load::right ? 0 : kRobotMassKg / 2;
    const auto spread = [](double kg) {
      const auto each = static_cast<float>(kg / 4);
      return nao::FootPressure{each, each, each, each};
    };
    sensors_.left_foot = spread(left_kg);
    sensors_.right_foot = spread(kRobotMassKg - left_kg);
  }

  RunswiftWalk& walk_;
  bool level_pressure_;
  nao::NaoSensorFrame sensors_{}; // all joints 0: straight legs, as their SensorValues(true)
  Load load_ = Load::both;
  Load airborne_ = Load::both;
  Sole prev_left_, prev_right_;
  bool have_soles_ = false;
};

} // namespace touchline::robot::runswift::testing
