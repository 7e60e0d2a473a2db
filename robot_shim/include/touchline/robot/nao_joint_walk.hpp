#pragma once
// NaoJointWalk: a small joint-space walk of our own, the proof that the seam and the
// kinematics carry a joint engine (CI has no team's code). Each tick it takes the feet
// our GaitFeet plans (WalkCycle and kick), lifts the swing foot on a sine over the step's
// single support (the kicking foot likewise over the kick's swing, so the weight is on
// the other foot while it strikes), puts the torso at sole_below_torso_mm above the feet's midpoint headed
// their mean heading, and turns each sole's pose into leg joints with our inverse
// kinematics (HipYawPitch: the mean of what each leg alone would need). Arms hang still;
// head joints are left at 0 (the MotionAdapter points the head). Reads: the body command.
// Writes: 25 joint angles.
#include "touchline/robot/gait_feet.hpp"
#include "touchline/robot/nao/leg_kinematics.hpp"
#include "touchline/robot/walk_engine.hpp"

namespace touchline::robot {

struct NaoJointWalkDef {
  int64_t period_us = 10000;          ///< control period, simulated microseconds (the plan counts its kick in 10 ms ticks)
  float sole_below_torso_mm = 300.f;  ///< torso height above the soles while walking (knees bent; legs straight: 333.09)
  float swing_height_mm = 20.f;       ///< the swing sole's highest lift, mm
  float kick_lift_mm = 10.f;          ///< the kicking sole's highest lift during the swing, mm (so the weight is on the other)
  nao::LegDimensions legs;            ///< the robot's leg dimensions
};

class NaoJointWalk : public WalkEngine {
 public:
  NaoJointWalk(const NaoJointWalkDef& def, const WalkDef& walk, const KickDef& kick);
  std::string name() const override { return "nao-joints"; }
  int64_t period_us() const override { return def_.period_us; }
  EngineOutputKind output_kind() const override { return EngineOutputKind::kJoints; }
  void start(WalkEngineOutput& out) override;
  void tick(const api::ActionCommand::Body& request, const nao::Sensors& sensors, WalkEngineOutput& out) override;
  WalkEngineStatus status() const override { return gait_.status(); }
  const GaitFeet* gait() const override { return &gait_; }

  /// The swing (or kicking) sole's lift now, mm (0 standing and in double support).
  float swing_lift_mm() const;
  /// Whether the lifted sole (if any) is the left one.
  bool left_lifted() const;

 private:
  void joints_for_plan(nao::JointAngles& joints) const;

  NaoJointWalkDef def_;
  GaitFeet gait_;
};

} // namespace touchline::robot
