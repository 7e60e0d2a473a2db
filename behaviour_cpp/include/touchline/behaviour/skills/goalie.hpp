#pragma once
// Goalie: stays in the own goal box on the line from the goal centre to the ball,
// GOALIE_GUARD_DIST out, facing the ball; clears (LineUpAndKick at the opponent goal, carrying
// the ball as the striker does) while the ball is in or near the box, the only time it leaves
// the box. Lining up a kick instead, with a striker at the ball, held the ball still in the box
// with the goalie within 300 mm of it 2.1 % of the play (1.0 % carrying; 16 C++ matches, seeds
// 1-16); carrying, the ball moved 58.7 -> 60.4 % of the play on seeds 1-16 and 58.4 -> 60.7 % on
// 17-32, the four strikers scoring 7.9 -> 5.0 and 7.5 -> 4.8 goals a match. Ball lost: back
// to (GOALIE_HOME_X, 0) facing the field. The port of behaviour_py/skills/goalie.py.
#include "touchline/behaviour/skills/field.hpp"
#include "touchline/behaviour/skills/go_to_pose.hpp"
#include "touchline/behaviour/skills/line_up_and_kick.hpp"

namespace touchline::behaviour::skills {

inline constexpr float GOALIE_GUARD_DIST = 400.f;   ///< mm: from the goal centre towards the ball
inline constexpr float GOALIE_BOX_MARGIN = 100.f;   ///< mm: the goalie's targets stay this far inside the box
inline constexpr float GOALIE_HOME_X = -2700.f;     ///< mm: where it waits while the ball is lost (y 0)
inline constexpr float CLEAR_ENTER_MARGIN = 300.f;  ///< mm: clear when the ball is within this of the box ...
inline constexpr float CLEAR_LEAVE_MARGIN = 600.f;  ///< mm: ... until it is beyond this

/// (x, y) on the goal centre-ball line GOALIE_GUARD_DIST from the goal centre, clamped into
/// the box less GOALIE_BOX_MARGIN.
FieldPoint goalieTarget(float ballX, float ballY);
bool ballNearBox(float ballX, float ballY, float margin);

class Goalie : public api::Behaviour {
 public:
  Goalie();
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;
  bool clearing() const { return clearing_; }

 private:
  GoToPose goToPose_;
  GoToPose goHome_;
  LineUpAndKick clear_;
  bool clearing_ = false;
};

} // namespace touchline::behaviour::skills
