#pragma once
// Builders for ActionCommand requests: the port of behaviour_py/actioncommand.py (same
// names, same defaults). Units: mm/s and rad/s for the walk, rad for the head.
#include <cstdint>

#include "touchline/robot_api/action_command.hpp"

namespace touchline::behaviour::actioncommand {

namespace AC = api::ActionCommand;

/// Walk at (forward, left) mm/s and turn rad/s, scaled by speed in (0, 1].
AC::Body walk(float forward = 0.f, float left = 0.f, float turn = 0.f, float speed = 1.f);
/// Stand still (the Body defaults).
AC::Body stand();
/// Kick with `foot`; power in [0, 1], bend: direction offset in rad.
AC::Body kick(float power = 1.f, AC::Foot foot = AC::Foot::LEFT, float bend = 0.f);
/// Push the ball along with `foot`; a gentle kick.
AC::Body dribble(float power = 0.3f, AC::Foot foot = AC::Foot::LEFT, float bend = 0.f);
/// Point the head: yaw + left, pitch + down (rad); speeds are fractions of the maximum.
AC::Head head(float yaw = 0.f, float pitch = 0.f, bool isRelative = false, float yawSpeed = 1.f,
              float pitchSpeed = 1.f);
/// Chest LED colour, 0xRRGGBB.
AC::LED leds(int32_t chest = 0x00ff00);
/// A whole request; Python's compose(head=None, ...) keeps a part's default where C++ passes {}.
AC::All compose(const AC::Head& headRequest = {}, const AC::Body& bodyRequest = {},
                const AC::LED& ledsRequest = {});

} // namespace touchline::behaviour::actioncommand
