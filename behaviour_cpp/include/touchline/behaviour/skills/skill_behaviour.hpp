#pragma once
// SkillBehaviour: a body skill and a head skill ticked together, with the chest LED; the
// port of SkillBehaviour in behaviour_py/behaviour.py (its skill table is registry.cpp).
#include <cstdint>
#include <memory>
#include <utility>

#include "touchline/robot_api/behaviour.hpp"

namespace touchline::behaviour::skills {

inline constexpr int32_t BALL_SEEN_CHEST = 0x00ff00; ///< green: the ball was seen recently
inline constexpr int32_t BALL_LOST_CHEST = 0xff0000; ///< red: searching

class SkillBehaviour : public api::Behaviour {
 public:
  SkillBehaviour(std::unique_ptr<api::Behaviour> body, std::unique_ptr<api::Behaviour> head)
      : body_(std::move(body)), head_(std::move(head)) {}
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;

 private:
  std::unique_ptr<api::Behaviour> body_, head_;
};

} // namespace touchline::behaviour::skills
