#pragma once
// JointFeet: the world's two feet from a Nao's leg joints. Each control tick forward
// kinematics gives both soles relative to the torso; the sole bearing the weight (the
// stance sole) stays where it is on the ground and the other is placed by the legs'
// relative pose projected on the ground (x, y, yaw in the stance sole's frame). So the
// world's feet do what the legs command, and the body (the feet's midpoint) moves as the
// stance leg pushes it. Which sole bears the weight: the lower one, with hysteresis. The
// other sole takes over when it touches down after having been lifted (it was more than
// lift_mm above the stance sole and is now within touchdown_mm of it: the landing tick's
// motion is still the landing foot's, the weight moves for the next), or when the stance
// sole rises lift_mm above it (at once: the rising foot is the one that moves). Reads:
// joint angles. Writes: feet poses (odometry frame).
#include "touchline/robot/nao/joints.hpp"
#include "touchline/robot/nao/leg_kinematics.hpp"
#include "touchline/robot/walk_cycle.hpp"

namespace touchline::robot::nao {

struct JointFeetDef {
  float lift_mm = 3.f;        ///< a sole this far above the stance sole has left the ground
  float touchdown_mm = 0.5f;  ///< a lifted sole back within this of the stance sole has landed
  LegDimensions legs;         ///< the robot's leg dimensions
};

class JointFeet {
 public:
  explicit JointFeet(const JointFeetDef& def = {});

  /// Both soles on the ground as `joints` place them, the body (feet midpoint, mean
  /// heading) at the origin; the lower sole (the left if level) bears the weight.
  void reset(const JointAngles& joints);
  /// The legs moved to `joints`: returns both feet (odometry frame).
  const FeetPose& update(const JointAngles& joints);

  const FeetPose& feet() const { return feet_; }
  Side stance() const { return stance_; }
  /// Whether the last update() landed the lifted sole, which now bears the weight.
  bool touched_down() const { return touched_down_; }
  /// Whether the last update() moved the weight to the other sole (a touchdown, or the
  /// stance sole lifting).
  bool stance_changed() const { return stance_changed_; }
  /// The swing sole's height above the stance sole in the last update, mm (before a
  /// touchdown handed the weight over).
  double swing_height_mm() const { return swing_height_mm_; }
  const JointFeetDef& def() const { return def_; }

 private:
  Pose2D& foot(Side side) { return side == Side::kLeft ? feet_.left : feet_.right; }

  JointFeetDef def_;
  FeetPose feet_;
  Side stance_ = Side::kLeft;
  bool lifted_ = false; ///< the other sole has left the ground since the last switch
  bool touched_down_ = false;
  bool stance_changed_ = false;
  double swing_height_mm_ = 0;
};

} // namespace touchline::robot::nao
