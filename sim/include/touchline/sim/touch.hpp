#pragma once
// Touch: where other robots and the goal posts touch a robot, as its foot bumpers and arm
// contact feel it. A robot whose body centre is nearer than TouchDef::distance_mm touches,
// in the sector of its bearing (frame.hpp's Touch); the referee counts the same distance as
// contact (rules.contact_distance_mm), so a robot feels every contact it could be penalised
// for. A goal post touches nearer than TouchDef::post_distance_mm: a robot that walks into a
// post feels it, as a NAO's bumpers would, instead of stepping on against it unaware.
#include "touchline/frame.hpp"

namespace touchline::sim {

struct TouchDef {
  /// Another robot's body centre this near touches, mm: a NAO's feet and arms span about
  /// 300 mm (rules.contact_distance_mm's default). 0: no robot feels a touch.
  float distance_mm = 300.f;
  /// A goal post's centre this near touches, mm: the feet reach 80-95 mm from the body's
  /// centre, the post's radius is 50 mm, so it is felt from about 60 mm before contact.
  /// 0: no post is felt.
  float post_distance_mm = 200.f;
};

/// Folds another robot's body centre at (x, y) into `touch` for a robot at `body`.
void touch_update(const TouchDef& def, const Pose2D& body, float x_mm, float y_mm, Touch& touch);

/// Folds a goal post's centre at (x, y) into `touch` for a robot at `body`.
void touch_post_update(const TouchDef& def, const Pose2D& body, float x_mm, float y_mm, Touch& touch);

} // namespace touchline::sim
