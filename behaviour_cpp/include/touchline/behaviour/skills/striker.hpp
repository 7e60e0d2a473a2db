#pragma once
// Striker: to the ball, lined up at the opponent goal (LineUpAndKick), and carries the ball on
// (LineUpAndKick's carry), into the goal too. Before, it dribbled within 1000 mm of the goal's
// centre; a dribble stops the walk for its swing, with the ball still, while a carry walks it
// in (64 C++ matches, seeds 1-64: the ball moved 52.2 -> 53.0 % of the play). The port of
// behaviour_py/skills/striker.py.
#include <optional>
#include <string>

#include "touchline/behaviour/skills/line_up_and_kick.hpp"

namespace touchline::behaviour::skills {

class Striker : public api::Behaviour {
 public:
  /// policy: the learned walker's policy file to approach the ball with (nullopt: GoToPose).
  explicit Striker(const std::optional<std::string>& policy = std::nullopt);
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;

 private:
  LineUpAndKick kick_;
};

} // namespace touchline::behaviour::skills
