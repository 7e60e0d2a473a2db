#pragma once
// The supporters (thesis 4.2): Midfielder (Algorithm 4.1) and Defender (Algorithm 4.2); the
// port of behaviour_py/skills/supporter.py.
//
// Both face the ball, never step into the own goal box, keep out of the ball's shooting path
// to the opponent goal when in front of it, and walk to their home position once the ball
// has been unseen for more than SUPPORTER_BALL_LOST_FRAMES. They walk with GoToPose
// (Algorithm 4.3 with the forward-first fix).
//
// Algorithm 4.2 keeps the robot's own y; as the thesis text says the defender blocks the
// path from the ball to its own goal, its y is the ball-own-goal line's at its target x.
#include "touchline/behaviour/skills/field.hpp"
#include "touchline/behaviour/skills/go_to_pose.hpp"

namespace touchline::behaviour::skills {

// Algorithm 4.1 (midfielder)
inline constexpr float MID_FAR_BALL_X = 2000.f;         ///< mm: ball beyond this: go to the fixed spot ...
inline constexpr float MID_FAR_X = 2200.f;              ///< mm: ... (MID_FAR_X, 0)
inline constexpr float MID_PARALLEL_BALL_X = 1200.f;    ///< mm: ball beyond this: stand beside it ...
inline constexpr float MID_PARALLEL_Y = 1200.f;         ///< mm: ... this far away in y
inline constexpr float MID_MAX_DIST_FROM_BALL = 2500.f; ///< mm: in front of a ball on the own goal line by this much
inline constexpr float MID_DIST_SPAN = 4200.f;          ///< mm: ball x from the own goal line to MID_PARALLEL_BALL_X
// Algorithm 4.2 (defender)
inline constexpr float DEF_DEEP_BALL_X = -800.f;        ///< mm: ball at or below this: go to the fixed spot ...
inline constexpr float DEF_DEEP_X = -1800.f;            ///< mm: ... (DEF_DEEP_X, 0)
inline constexpr float DEF_DIST_FROM_BALL = -1250.f;    ///< mm: otherwise this far behind the ball ...
inline constexpr float DEF_MAX_X = -1200.f;             ///< mm: ... but never beyond this
// Home positions, walked to when the ball is lost
inline constexpr int SUPPORTER_BALL_LOST_FRAMES = 90;   ///< frames (3 s) without the ball before walking home
inline constexpr float MID_HOME_X = 0.f;                ///< mm
inline constexpr float MID_HOME_Y = 800.f;              ///< mm
inline constexpr float DEF_HOME_X = -1800.f;            ///< mm
inline constexpr float DEF_HOME_Y = 0.f;                ///< mm

/// Thesis Algorithm 4.1: (x, y) for the ball at (ballX, ballY) and the robot at y robotY.
FieldPoint midfielderTarget(float ballX, float ballY, float robotY);
/// Thesis Algorithm 4.2: (x, y) for the ball at (ballX, ballY), y on the ball-own-goal line.
FieldPoint defenderTarget(float ballX, float ballY);
/// An algorithm's (x, y) made safe: off the shooting path, out of the own box, on the field.
FieldPoint supporterTarget(float x, float y, float ballX, float ballY, float robotY);

/// A supporter: target(ballX, ballY, robotY) gives the raw algorithm's position.
class Supporter : public api::Behaviour {
 public:
  Supporter(float homeX, float homeY);
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;
  virtual FieldPoint target(float ballX, float ballY, float robotY) const = 0;

 private:
  GoToPose goToPose_;
  GoToPose goHome_;
};

class Midfielder : public Supporter {
 public:
  Midfielder() : Supporter(MID_HOME_X, MID_HOME_Y) {}
  FieldPoint target(float ballX, float ballY, float robotY) const override;
};

class Defender : public Supporter {
 public:
  Defender() : Supporter(DEF_HOME_X, DEF_HOME_Y) {}
  FieldPoint target(float ballX, float ballY, float robotY) const override;
};

} // namespace touchline::behaviour::skills
