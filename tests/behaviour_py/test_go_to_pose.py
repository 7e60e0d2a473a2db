"""GoToPose: forward-first, then thesis Algorithm 4.3; the same cases as
tests/behaviour_cpp/skills/test_go_to_pose.cpp."""
import math

import pytest
import robot
from boards import board

from skills.field import FIELD_EDGE_SLACK
from skills.go_to_pose import GoToPose, forwardFirstSpeedScale

WALK = robot.ActionType.WALK
STAND = robot.ActionType.STAND


def velocities(command):
    return command.body.forward, command.body.left, command.body.turn


def test_target_far_behind_is_walked_backwards_when_the_robot_must_end_facing_away():
    # Backwards at 200 mm/s: 10 s; turning round, 300 mm/s forward and turning back: 10.9 s.
    skill = GoToPose(-2000.0, -100.0, 0.0)
    command = skill.tick(board((0.0, 0.0, 0.0)))
    assert command.body.actionType == WALK
    assert velocities(command) == pytest.approx((-200.0, -10.0, 0.0))
    assert skill.near


def test_far_target_ahead_walks_forward_at_full_speed_steering():
    # Ahead, both ways take as long: forward-first (Algorithm 4.3 only when 0.25 s faster),
    # 0.05 rad off: cos^2 of it, 99.75 % of full speed.
    command = GoToPose(2000.0, 100.0, 0.0).tick(board((0.0, 0.0, 0.0)))
    assert velocities(command) == pytest.approx((299.2519, 0.0, 0.09992), abs=1e-4)


def test_forward_first_walks_slower_the_further_the_target_is_off_its_heading():
    assert forwardFirstSpeedScale(0.0) == 1.0
    assert forwardFirstSpeedScale(math.radians(45)) == pytest.approx(0.5)
    assert forwardFirstSpeedScale(math.radians(-60)) == pytest.approx(0.25)
    assert forwardFirstSpeedScale(math.radians(100)) == 0.0
    # 2 m at 45 degrees, ending facing there: walks at half speed while turning at full rate.
    x, y = at(2000.0, math.radians(45))
    command = GoToPose(x, y, math.radians(45)).tick(board((0.0, 0.0, 0.0)))
    assert velocities(command) == pytest.approx((150.0, 0.0, 1.5))


def at(distance, bearing):
    return distance * math.cos(bearing), distance * math.sin(bearing)


def test_forward_first_where_it_is_faster():
    # 2 m at 80 degrees, ending facing +x: sideways 9.9 s; turn, walk forward, turn back 8.5 s.
    # It turns at full rate, walking on at cos^2(80 degrees) = 3 % of full speed.
    x, y = at(2000.0, math.radians(80))
    skill = GoToPose(x, y, 0.0)
    command = skill.tick(board((0.0, 0.0, 0.0)))
    assert velocities(command) == pytest.approx((9.0459, 0.0, 1.5), abs=1e-3)
    assert not skill.near


def test_algorithm_4_3_within_the_threshold():
    x, y = at(390.0, math.radians(20))  # same bearing, inside: step there diagonally
    skill = GoToPose(x, y, 0.0)
    command = skill.tick(board((0.0, 0.0, 0.0)))
    assert velocities(command) == pytest.approx((300.0, 109.1911, 0.0), abs=1e-3)
    assert skill.near


def test_algorithm_4_3_until_forward_first_is_clearly_faster():
    # A target to the left, ending facing +x: sideways takes d/200 s, turning twice and forward
    # 2.09 s + d/300: Algorithm 4.3 is 0.25 s faster under 1107 mm, and kept until 0.5 s slower (1557 mm).
    skill = GoToPose(0.0, 0.0, 0.0)
    skill.tick(board((0.0, -390.0, 0.0)))
    assert skill.near
    skill.tick(board((0.0, -1400.0, 0.0)))  # 0.24 s slower: still Algorithm 4.3
    assert skill.near
    command = skill.tick(board((0.0, -1600.0, 0.0)))  # 0.57 s slower: forward-first
    assert not skill.near
    assert command.body.forward == pytest.approx(0.0, abs=1e-6) and command.body.turn > 0.0  # at 90 degrees
    fresh = GoToPose(0.0, 0.0, 0.0)
    fresh.tick(board((0.0, -1400.0, 0.0)))
    assert not fresh.near


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


def test_a_target_off_the_field_is_walked_to_only_just_beyond_the_line():
    # Behind a ball on the touchline the target lies out; the referee penalises 200 mm out.
    beside = GoToPose(0.0, 2300.0, 0.0)
    assert beside.tick(board((0.0, 2000.0 + FIELD_EDGE_SLACK, 0.0))).body.actionType == STAND
    behind = GoToPose(3400.0, -100.0, 0.0)
    assert behind.tick(board((3000.0 + FIELD_EDGE_SLACK, -100.0, 0.0))).body.actionType == STAND
