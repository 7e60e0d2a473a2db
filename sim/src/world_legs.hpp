#pragma once
// A robot's legs, as the world holds its two feet together (not part of its interface): a
// rope between the feet, a lifted foot returned to its place in the walk's stance, and the
// feet's twist held to what the walk and the hips allow. Reads the feet's bodies and the
// walk's commands; writes the feet's velocity commands and headings.
#include <box2d/box2d.h>

#include "touchline/angles.hpp"
#include "touchline/frame.hpp"
#include "touchline/sim/world.hpp"

namespace touchline::sim::detail {

/// One foot's velocity command for a motion tick, in Box2D's units (m/s, rad/s).
struct FootVelocity {
  b2Body* foot;
  b2Vec2 linear;
  float angular;
};

/// One robot's feet and where the walk's own commands alone would have put them since it was
/// placed (square, around the origin): the stance its legs hold the feet in. Their twist is
/// what hold_twist leaves alone; a foot the walk moves returns to its place beside the other
/// (return_to_stance).
struct Legs {
  b2Body* left = nullptr;
  b2Body* right = nullptr;
  Pose2D walk_left, walk_right;
  /// The twist (right foot's heading less the left's) the walk's own commands made, rad.
  float walk_twist_rad() const { return normalise_angle(walk_right.theta_rad - walk_left.theta_rad); }
};

/// Ties the feet with a rope, slack until they are max_foot_spread_mm apart (Box2D's distance
/// joint with only its upper limit): a push that would part the feet drags the other foot
/// along, as it drags a Nao's whole body.
void add_rope(b2World& world, const Legs& legs, float max_foot_spread_mm);

/// The legs place a lifted foot: the foot the walk moves this tick (the other stands) also
/// moves, at up to stance_return_mm_s and stance_return_rad_s, towards where the walk's own
/// steps put it beside the other foot (legs.walk_left, legs.walk_right). Contacts move feet
/// apart from where the walk put them (a foot blocked by another robot's, a foot dragged by
/// the rope); without this nothing brings them back, and a robot's stance drifts for the rest
/// of the match (a kick's foot 100 mm off where the walk put it misses the ball). A standing
/// foot is never moved: only the legs' swing corrects.
void return_to_stance(const PhysicsDef& physics, const Legs& legs, const TickMotion& motion, FootVelocity& left,
                      FootVelocity& right);

/// Turns both feet towards each other, equally (their mean heading stays where it was), until
/// one is at most max_foot_twist_rad from the other, or as far as the walk itself turned them
/// apart (legs.walk_twist_rad()): only a contact's twist is held, never the walk's own (a
/// turning walk's feet open ~0.83 rad). The bound is the walk's twist, not the twist before
/// the tick plus the walk's turn in it: that ratchets, a contact's excess kept whenever the
/// walk turned the same way, up to the feet pi apart. The legs' own limit holds even the
/// walk's twist: a Nao's hip yaw-pitch joint turns its feet apart by at most 65.6 deg (1.15
/// rad). A walk whose state parted from the feet (it was mid-turn when the referee put the
/// robot down) could otherwise twist them pi apart.
void hold_twist(const PhysicsDef& physics, const Legs& legs);

} // namespace touchline::sim::detail
