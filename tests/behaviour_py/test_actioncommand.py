"""actioncommand: the request builders (same defaults as the C++ port)."""
import pytest
import robot

import actioncommand


def test_walk_sets_velocities_and_speed():
    body = actioncommand.walk(120.0, -30.0, 0.5, speed=0.5)
    assert body.actionType == robot.ActionType.WALK
    assert (body.forward, body.left, body.turn, body.speed) == (120.0, -30.0, 0.5, 0.5)


def test_stand_is_the_body_default():
    body = actioncommand.stand()
    assert body.actionType == robot.ActionType.STAND
    assert (body.forward, body.left, body.turn) == (0.0, 0.0, 0.0)


def test_kick_and_dribble_defaults():
    kick = actioncommand.kick()
    assert (kick.actionType, kick.power, kick.foot, kick.bend) == (robot.ActionType.KICK, 1.0, robot.Foot.LEFT, 0.0)
    dribble = actioncommand.dribble(foot=robot.Foot.RIGHT)
    assert dribble.actionType == robot.ActionType.DRIBBLE
    assert dribble.power == pytest.approx(0.3)
    assert dribble.foot == robot.Foot.RIGHT


def test_head_and_leds():
    head = actioncommand.head(0.5, -0.25, isRelative=True, yawSpeed=0.5)
    assert (head.yaw, head.pitch, head.isRelative, head.yawSpeed, head.pitchSpeed) == (0.5, -0.25, True, 0.5, 1.0)
    assert actioncommand.leds().chest == 0x00ff00
    assert actioncommand.leds(0xff0000).chest == 0xff0000


def test_compose_keeps_defaults_for_missing_parts():
    command = actioncommand.compose(body=actioncommand.walk(100.0))
    assert command.body.forward == 100.0
    assert (command.head.yaw, command.head.pitch) == (0.0, 0.0)
    assert command.leds.chest == 0x00ff00
    command = actioncommand.compose(head=actioncommand.head(1.0), leds=actioncommand.leds(0x0000ff))
    assert command.body.actionType == robot.ActionType.STAND
    assert (command.head.yaw, command.leds.chest) == (1.0, 0x0000ff)
