#pragma once
// Striker: to the ball, lined up at the opponent goal (LineUpAndKick); carries the ball on
// (LineUpAndKick's carry) or kicks, or dribbles while the ball is within STRIKER_DRIBBLE_DIST
// of the opponent goal's centre. The choice is made while neither is lining up and kept
// through a line-up. The port of behaviour_py/skills/striker.py.
#include <optional>
#include <string>

#include "touchline/behaviour/skills/line_up_and_kick.hpp"

namespace touchline::behaviour::skills {

inline constexpr float STRIKER_DRIBBLE_DIST = 1000.f; ///< mm: dribble this close to the opponent goal, else kick

bool shouldDribble(float ballX, float ballY);

class Striker : public api::Behaviour {
 public:
  /// policy: the learned walker's policy file to approach the ball with (nullopt: GoToPose).
  explicit Striker(const std::optional<std::string>& policy = std::nullopt);
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;
  bool dribbling() const { return dribbling_; }

 private:
  LineUpAndKick kick_;
  LineUpAndKick dribble_;
  bool dribbling_ = false;
};

} // namespace touchline::behaviour::skills
