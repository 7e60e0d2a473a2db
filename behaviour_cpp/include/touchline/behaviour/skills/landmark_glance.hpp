#pragma once
// LandmarkGlance: LookForBall, with short glances at a landmark so that localisation keeps a
// fix (issue #17 item 3); the port of behaviour_py/skills/landmark_glance.py. Following the
// ball keeps the head low and on the ball, so a robot may see no landmark for a minute while
// contacts turn it unseen by its odometry.
//
// Reads localisation.robotPos, robotPosCovariance, ballPosRR, ballLostCount and
// motion.headYaw. A glance starts, while the ball is tracked and not hot (seen within
// GLANCE_HOT_BALL_DIST), when GLANCE_EVERY_FRAMES have passed since the last one, or
// GLANCE_UNSURE_EVERY_FRAMES once the pose's position sigma exceeds GLANCE_SIGMA_MM or its
// heading sigma GLANCE_SIGMA_RAD. A hot ball keeps the head unless the pose is lost (position
// sigma past GLANCE_LOST_SIGMA_MM): robots toe to toe over a ball hold each other's heads on it
// for half a minute while the walk's odometry counts the steps the blocked feet did not take
// (2.3 m off in one match of 560). It points the head at the landmark (goal post, field
// corner, centre-line end or penalty mark, as the camera reports them) that the estimated
// pose places in camera range nearest the ball's bearing, holds it GLANCE_DWELL_FRAMES once
// the head is there (GLANCE_MAX_FRAMES at most, short of the ball counting as lost), then
// gives the head back to the ball. Frames are counted by its own ticks, never wall time.
#include <optional>
#include <vector>

#include "touchline/behaviour/skills/field.hpp"
#include "touchline/behaviour/skills/look_for_ball.hpp"

namespace touchline::behaviour::skills {

inline constexpr float GOAL_POST_HALF_SPAN = 700.f;        ///< mm: a goal post from the goal's centre line (SPL 2011)
inline constexpr float PENALTY_MARK_X = 1200.f;            ///< mm: penalty marks 1800 mm from the goal lines
inline constexpr int GLANCE_EVERY_FRAMES = 150;            ///< frames (5 s) between glances when the pose is sure
inline constexpr int GLANCE_UNSURE_EVERY_FRAMES = 45;      ///< frames (1.5 s) between glances when it is not ...
inline constexpr float GLANCE_SIGMA_MM = 150.f;            ///< mm: ... position sigma (x, y) past this ...
inline constexpr float GLANCE_SIGMA_RAD = 0.15f;           ///< rad: ... or its heading sigma above this
inline constexpr float GLANCE_HOT_BALL_DIST = 600.f;       ///< mm: a ball seen this close keeps the head ...
inline constexpr float GLANCE_LOST_SIGMA_MM = 400.f;       ///< mm: ... unless the position sigma (x, y) is past this
inline constexpr float GLANCE_MIN_DIST = 300.f;            ///< mm: landmarks closer than this are no use (bearing)
inline constexpr float GLANCE_MAX_DIST = 3500.f;           ///< mm: nor past the camera range less a margin
inline constexpr float GLANCE_ON_TARGET_RAD = 0.1f;        ///< rad: the head is on the landmark within this yaw
inline constexpr int GLANCE_DWELL_FRAMES = 6;              ///< frames on the landmark (the camera misses 1 in 10)
inline constexpr int GLANCE_MAX_FRAMES = 24;               ///< frames a glance lasts at most (ball lost: 30)

/// The landmarks the camera reports, in the team frame. The set is symmetric under the half
/// turn between the teams' frames, so the same list serves both teams.
std::vector<FieldPoint> landmarks();

/// The landmark to glance at from `robotPos`, robot-relative: in camera range and head reach,
/// nearest the ball's bearing `ballHeading` (the quickest there and back); none if none is.
std::optional<api::RRCoord> glanceTarget(const api::AbsCoord& robotPos, float ballHeading);

/// Whether the pose's covariance is past GLANCE_SIGMA_MM or GLANCE_SIGMA_RAD.
bool poseUnsure(const api::LocalisationBlackboard& localisation);
/// Whether the pose's position sigma (x and y together) is past GLANCE_LOST_SIGMA_MM.
bool poseLost(const api::LocalisationBlackboard& localisation);

class LandmarkGlance : public api::Behaviour {
 public:
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;

  bool glancing() const { return glancing_ > 0; }

 private:
  api::ActionCommand::All aim(const api::Blackboard& blackboard, const api::RRCoord& target);

  LookForBall lookForBall_;
  int sinceGlance_ = 0; ///< frames since the last glance ended
  int glancing_ = 0;    ///< frames into the glance under way, 0: none
  int dwell_ = 0;       ///< frames the head has been on the landmark
};

} // namespace touchline::behaviour::skills
