"""Builders for ActionCommand requests, as the robot code writes them.

Units: mm/s and rad/s for the walk, rad for the head. Imports only `robot`.
The C++ port is behaviour_cpp/.../skills/actioncommand.hpp (same names, same defaults).
"""
import robot


def walk(forward=0.0, left=0.0, turn=0.0, speed=1.0):
    """Walk at (forward, left) mm/s and turn rad/s, scaled by speed in (0, 1]."""
    body = robot.Body()
    body.actionType = robot.ActionType.WALK
    body.forward = forward
    body.left = left
    body.turn = turn
    body.speed = speed
    return body


def stand():
    """Stand still (the Body defaults)."""
    return robot.Body()


def _foot_action(actionType, power, foot, bend):
    body = robot.Body()
    body.actionType = actionType
    body.power = power
    body.foot = foot
    body.bend = bend
    return body


def kick(power=1.0, foot=robot.Foot.LEFT, bend=0.0):
    """Kick with `foot`; power in [0, 1], bend: direction offset in rad."""
    return _foot_action(robot.ActionType.KICK, power, foot, bend)


def dribble(power=0.3, foot=robot.Foot.LEFT, bend=0.0):
    """Push the ball along with `foot`; a gentle kick."""
    return _foot_action(robot.ActionType.DRIBBLE, power, foot, bend)


def head(yaw=0.0, pitch=0.0, isRelative=False, yawSpeed=1.0, pitchSpeed=1.0):
    """Point the head: yaw + left, pitch + down (rad); speeds are fractions of the maximum."""
    request = robot.Head()
    request.yaw = yaw
    request.pitch = pitch
    request.isRelative = isRelative
    request.yawSpeed = yawSpeed
    request.pitchSpeed = pitchSpeed
    return request


def leds(chest=0x00ff00):
    """Chest LED colour, 0xRRGGBB."""
    request = robot.LED()
    request.chest = chest
    return request


def compose(head=None, body=None, leds=None):
    """A whole request; a part left None keeps its default (head forward, stand, green)."""
    command = robot.All()
    if head is not None:
        command.head = head
    if body is not None:
        command.body = body
    if leds is not None:
        command.leds = leds
    return command
