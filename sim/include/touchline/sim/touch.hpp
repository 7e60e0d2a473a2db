#pragma once
// Touch: where other robots touch a robot, as its foot bumpers and arm contact feel it. A
// robot whose body centre is nearer than TouchDef::distance_mm touches, in the sector of
// its bearing (frame.hpp's Touch). The referee counts the same distance as contact
// (rules.contact_distance_mm), so a robot feels every contact it could be penalised for.
#include "touchline/frame.hpp"

namespace touchline::sim {

struct TouchDef {
  /// Another robot's body centre this near touches, mm: a NAO's feet and arms span about
  /// 300 mm (rules.contact_distance_mm's default). 0: no robot feels a touch.
  float distance_mm = 300.f;
};

/// Folds another robot's body centre at (x, y) into `touch` for a robot at `body`.
void touch_update(const TouchDef& def, const Pose2D& body, float x_mm, float y_mm, Touch& touch);

} // namespace touchline::sim
