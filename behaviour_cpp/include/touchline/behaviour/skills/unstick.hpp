#pragma once
// Unstick: stuck detection and recovery for a player in PLAYING (issue #17: no robot stuck
// more than 10 s). The port of behaviour_py/skills/unstick.py (which says what it does and
// why); reads motion.odometry, localisation, gameController and receiver, writes nothing.
#include <deque>
#include <optional>

#include "touchline/behaviour/skills/avoid.hpp"
#include "touchline/behaviour/skills/field.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::behaviour::skills {

inline constexpr int UNSTICK_WINDOW_FRAMES = 300;   ///< frames (10 s, the match statistics' window) looked back over ...
inline constexpr float UNSTICK_TURN_RAD = 3.5f;     ///< rad: ... turning more than this (they count a full turn as stuck) ...
inline constexpr float UNSTICK_MOVE_MM = 300.f;     ///< mm: ... while moving less than this net: stuck
inline constexpr int UNSTICK_RECOVER_FRAMES = 60;   ///< frames (2 s): the shortest walk without turning

class Unstick {
 public:
  /// Forget the window (outside PLAYING, penalised or fallen: the test counts play only).
  void reset();
  /// body, or while recovering the walk that replaces it; target: the field point to walk
  /// towards (the goalie's home), nullopt for the ball or the field's centre.
  api::ActionCommand::Body tick(const api::Blackboard& blackboard, const api::ActionCommand::Body& body,
                                std::optional<FieldPoint> target);

 private:
  bool stuck() const;
  static FieldPoint walkTarget(const api::Blackboard& blackboard, std::optional<FieldPoint> target);

  std::deque<api::AbsCoord> odometry_; ///< the window's odometry poses, oldest first
  std::deque<FieldPoint> positions_;   ///< the window's localised positions, oldest first
  std::deque<float> turned_;           ///< |heading change| (rad) between consecutive poses of the window
  int recovering_ = 0;                 ///< recovery ticks left
  Avoid avoid_;
};

} // namespace touchline::behaviour::skills
