#pragma once
// LearnedGoToPose: walk to a field pose with a learned policy (TilePolicy); the port of
// behaviour_py/skills/learned_go_to_pose.py.
//
// Each tick the target is turned into the robot-relative state (x forward, y left, heading
// error) from localisation.robotPos, in double as docs/learning/policy_format.md gives it;
// inside the policy's success tolerances the robot stands, else it walks with the greedy
// action. The policy file (relative to the robot's data directory) is read once per path.
#include <memory>
#include <string>

#include "touchline/behaviour/skills/tile_policy.hpp"
#include "touchline/robot_api/behaviour.hpp"

namespace touchline::behaviour::skills {

/// The robot-relative state of the learned policy: the target as the robot sees it.
struct RelativeTarget {
  double x = 0;     ///< mm forward
  double y = 0;     ///< mm left
  double theta = 0; ///< rad: target heading - robot heading, not wrapped
};

/// The field pose (x, y, theta) seen from the robot at pos, in double.
RelativeTarget relativeTarget(const api::AbsCoord& pos, double x, double y, double theta);

class LearnedGoToPose : public api::Behaviour {
 public:
  /// Target (x, y) in mm and heading theta in rad, field frame; policy: the policy file,
  /// relative to the robot's data directory. Throws BehaviourError for a bad file.
  explicit LearnedGoToPose(double x = 0, double y = 0, double theta = 0, const std::string& policy = DEFAULT_POLICY);
  void setTarget(double x, double y, double theta);
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;

  const TilePolicy& policy() const { return *policy_; }

 private:
  double x_ = 0, y_ = 0, theta_ = 0;
  std::shared_ptr<const TilePolicy> policy_;
};

} // namespace touchline::behaviour::skills
