"""GoToPose: forward-first, then thesis Algorithm 4.3; the same cases as
tests/behaviour_cpp/skills/test_go_to_pose.cpp."""
import math

import pytest
import robot
from boards import board

from skills.go_to_pose import GoToPose

WALK = robot.ActionType.WALK
STAND = robot.ActionType.STAND


def velocities(command):
    return command.body.forward, command.body.left, command.body.turn


def test_target_behind_turns_on_the_spot_first():
    command = GoToPose(-2000.0, -100.0, 0.0).tick(board((0.0, 0.0, 0.0)))
    assert command.body.actionType == WALK
    assert velocities(command) == pytest.approx((0.0, 0.0, -1.5))


def test_far_target_ahead_walks_forward_at_full_speed_steering():
    command = GoToPose(2000.0, 100.0, 0.0).tick(board((0.0, 0.0, 0.0)))
    assert velocities(command) == pytest.approx((300.0, 0.0, 0.09992), abs=1e-4)


def at(distance, bearing):
    return distance * math.cos(bearing), distance * math.sin(bearing)


def test_forward_first_beyond_the_threshold():
    x, y = at(410.0, math.radians(20))  # 20 degrees off: face it first
    command = GoToPose(x, y, 0.0).tick(board((0.0, 0.0, 0.0)))
    assert velocities(command) == pytest.approx((0.0, 0.0, 0.69813), abs=1e-4)


def test_algorithm_4_3_within_the_threshold():
    x, y = at(390.0, math.radians(20))  # same bearing, inside: step there diagonally
    skill = GoToPose(x, y, 0.0)
    command = skill.tick(board((0.0, 0.0, 0.0)))
    assert velocities(command) == pytest.approx((300.0, 109.1911, 0.0), abs=1e-3)
    assert skill.near


def test_near_until_beyond_the_leave_distance():
    skill = GoToPose(0.0, 0.0, 0.0)
    skill.tick(board((-390.0, 0.0, 0.0)))
    assert skill.near
    skill.tick(board((-450.0, -100.0, 0.0)))  # 461 mm: still Algorithm 4.3
    assert skill.near
    command = skill.tick(board((-500.0, -200.0, 0.0)))  # 539 mm, 22 degrees off: forward-first again
    assert not skill.near
    assert command.body.forward == 0.0 and command.body.turn > 0.0


def test_algorithm_4_3_worked_example_clamped():
    # Robot (1000, 500, 0.3), target (1200, 700): fwd = 250.171, lft = -131.963 (4.3's
    # runswift angles); x2 gain -> (500.34, 263.93), scaled by 300/500.34 into the limits.
    command = GoToPose(1200.0, 700.0, 0.4).tick(board((1000.0, 500.0, 0.3)))
    assert velocities(command) == pytest.approx((300.0, 158.2475, 0.2), abs=1e-3)


def test_algorithm_4_3_worked_example_unclamped():
    # Target (1050, 480): fwd = 41.8564, lft = 33.8827 -> x2 gain.
    command = GoToPose(1050.0, 480.0, 0.35).tick(board((1000.0, 500.0, 0.3)))
    assert velocities(command) == pytest.approx((83.7128, -67.7655, 0.1), abs=1e-3)


def test_near_but_heading_off_turns_on_the_spot():
    command = GoToPose(100.0, 0.0, 1.0).tick(board((0.0, 0.0, 0.0)))
    assert velocities(command) == pytest.approx((0.0, 0.0, 1.5))


def test_arrived_stands_until_pushed_or_turned_away():
    skill = GoToPose(500.0, 500.0, 1.0)
    assert skill.tick(board((510.0, 495.0, 1.02))).body.actionType == STAND
    assert skill.arrived
    assert skill.tick(board((600.0, 500.0, 1.0))).body.actionType == STAND  # 100 mm: within hysteresis
    assert skill.tick(board((500.0, 500.0, 1.3))).body.actionType == STAND  # 0.3 rad: within hysteresis
    assert skill.tick(board((500.0, 500.0, 1.4))).body.actionType == WALK   # 0.4 rad: left
    assert not skill.arrived
    assert skill.tick(board((600.0, 500.0, 1.0))).body.actionType == WALK   # 100 mm: not yet arrived again


def test_face_ball_turns_to_the_ball_not_theta():
    skill = GoToPose(0.0, 0.0, 0.0, faceBall=True)
    assert velocities(skill.tick(board((0.0, 0.0, 0.0), ball=(0.0, 1000.0)))) == pytest.approx((0.0, 0.0, 1.5))
    assert skill.tick(board((0.0, 0.0, math.pi / 2), ball=(0.0, 1000.0))).body.actionType == STAND
