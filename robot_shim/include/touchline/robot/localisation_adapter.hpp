#pragma once
// The localisation adapter: where the robot believes it and the ball are. By default the
// filters (EKF pose, Kalman ball) fed by odometry and the camera's landmarks; with
// `perfect`, the robot's pose is the truth and the ball is placed from what the camera
// saw. Either way the filter starts where the robot was put down and restarts when it
// comes back from a penalty (robots know where the referee puts them).
// Reads: blackboard.motion.odometry, the sensed observations, the sensed truth (perfect
// mode; placements). Writes: blackboard.localisation.
#include <optional>

#include "touchline/frame.hpp"
#include "touchline/robot/localisation/localiser.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::robot {

class LocalisationAdapter {
 public:
  LocalisationAdapter(const localisation::LocalisationDef& def, bool perfect) : def_(def), perfect_(perfect) {}
  void tick(const SenseFrame& frame, const RobotSense& sense, api::Blackboard& blackboard);
  bool perfect() const { return perfect_; }

 private:
  void tick_perfect(const RobotSense& sense, api::Blackboard& blackboard);

  localisation::LocalisationDef def_;
  bool perfect_;
  std::optional<localisation::Localiser> localiser_;
  bool was_penalised_ = false;
};

} // namespace touchline::robot
