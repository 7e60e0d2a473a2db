#pragma once
// The localisation adapter: where the robot believes it and the ball are. By default the
// filters (EKF pose, Kalman ball) fed by odometry, the gyro's turn and the camera's landmarks; with
// `perfect`, the robot's pose is the truth and the ball is placed from what the camera
// saw. Either way the filter starts where the robot was put down and restarts when it
// comes back from a penalty or the referee places it (robots know where the rules put them).
// The Blackboard's field frame is the team's own, as on the robot: +x towards the
// opponent goal. The world's frame is team 0's, so team 1's beliefs are turned by pi.
// Reads: blackboard.motion.odometry, the sensed gyro turn and observations, the sensed truth (perfect
// mode; placements). Writes: blackboard.localisation.
#include <optional>

#include "touchline/frame.hpp"
#include "touchline/robot/localisation/localiser.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::robot {

/// A world-frame pose in `team`'s own field frame (+x towards the goal it attacks), and back.
Pose2D to_team_frame(const Pose2D& world, int team);
Pose2D to_world_frame(const Pose2D& own, int team);

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
