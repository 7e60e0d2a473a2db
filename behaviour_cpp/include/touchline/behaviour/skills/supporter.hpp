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
#include <string>
#include <vector>

#include "touchline/behaviour/skills/field.hpp"
#include "touchline/behaviour/skills/go_to_pose.hpp"

namespace touchline::behaviour::skills {

inline constexpr int SUPPORTER_BALL_LOST_FRAMES = 90; ///< frames (3 s) without the ball before walking home

/// Where the supporters stand: the numbers of Algorithms 4.1 and 4.2 and the homes (mm, team
/// frame). thesisSupporters() holds the thesis's own; tunedSupporters() (the default) those
/// that played better in our matches (README "Team results"); the skill parameter
/// supporters=thesis|tuned picks (supporterDef()).
struct SupporterDef {
  // Algorithm 4.1 (midfielder)
  float midFarBallX = 2000.f;        ///< mm: ball beyond this: go to the fixed spot ...
  float midFarX = 2200.f;            ///< mm: ... (midFarX, 0)
  float midParallelBallX = 1200.f;   ///< mm: ball beyond this: stand beside it ...
  float midParallelY = 1200.f;       ///< mm: ... this far away in y
  float midMaxDistFromBall = 2500.f; ///< mm: in front of a ball on the own goal line by this much
  // Algorithm 4.2 (defender)
  float defDeepBallX = -800.f;       ///< mm: ball at or below this: go to the fixed spot ...
  float defDeepX = -1800.f;          ///< mm: ... (defDeepX, 0)
  float defDistFromBall = -1250.f;   ///< mm: otherwise this far behind the ball ...
  float defMaxX = -1200.f;           ///< mm: ... but never beyond this
  // Home positions, walked to when the ball is lost
  float midHomeX = 0.f;              ///< mm
  float midHomeY = 800.f;            ///< mm
  float defHomeX = -1800.f;          ///< mm
  float defHomeY = 0.f;              ///< mm
};

/// Algorithms 4.1 and 4.2 with the thesis's numbers.
const SupporterDef& thesisSupporters();
/// The numbers our teams play by default.
const SupporterDef& tunedSupporters();
/// The SupporterDef the skill parameter supporters=NAME names ("tuned" or "thesis"), or nullptr.
const SupporterDef* supporterDef(const std::string& name);
/// The names supporterDef() knows, the default first: "tuned", "thesis".
const std::vector<std::string>& supporterDefNames();

/// Thesis Algorithm 4.1: (x, y) for the ball at (ballX, ballY) and the robot at y robotY, with
/// the numbers of `supporters`.
FieldPoint midfielderTarget(float ballX, float ballY, float robotY, const SupporterDef& supporters);
/// Thesis Algorithm 4.2: (x, y) for the ball at (ballX, ballY), y on the ball-own-goal line,
/// with the numbers of `supporters`.
FieldPoint defenderTarget(float ballX, float ballY, const SupporterDef& supporters);
/// An algorithm's (x, y) made safe: off the shooting path, out of the own box, on the field.
FieldPoint supporterTarget(float x, float y, float ballX, float ballY, float robotY);

/// A supporter: target(ballX, ballY, robotY) gives the raw algorithm's position, with the
/// numbers of the SupporterDef it was made with.
class Supporter : public api::Behaviour {
 public:
  Supporter(const SupporterDef& supporters, FieldPoint home);
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;
  virtual FieldPoint target(float ballX, float ballY, float robotY) const = 0;

 protected:
  SupporterDef supporters_;

 private:
  GoToPose goToPose_;
  GoToPose goHome_;
};

class Midfielder : public Supporter {
 public:
  explicit Midfielder(const SupporterDef& supporters = tunedSupporters())
      : Supporter(supporters, {supporters.midHomeX, supporters.midHomeY}) {}
  FieldPoint target(float ballX, float ballY, float robotY) const override;
};

class Defender : public Supporter {
 public:
  explicit Defender(const SupporterDef& supporters = tunedSupporters())
      : Supporter(supporters, {supporters.defHomeX, supporters.defHomeY}) {}
  FieldPoint target(float ballX, float ballY, float robotY) const override;
};

} // namespace touchline::behaviour::skills
