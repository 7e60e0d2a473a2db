"""LineUpAndKick: approach, line up the foot, kick when aligned; the same cases as
tests/behaviour_cpp/skills/test_line_up_and_kick.cpp."""
import pytest
import robot
from boards import board, relative

from skills.ball import BALL_LOST_FRAMES
from skills.go_to_ball import GoToBall
from skills.line_up_and_kick import LineUpAndKick

ORIGIN = (0.0, 0.0, 0.0)
KICK = robot.ActionType.KICK
WALK = robot.ActionType.WALK


def velocities(command):
    return command.body.forward, command.body.left, command.body.turn


def test_ball_in_front_of_the_left_foot_kicks_left():
    skill = LineUpAndKick()
    body = skill.tick(board(ORIGIN, ball=(130.0, 50.0))).body
    assert (body.actionType, body.foot) == (KICK, robot.Foot.LEFT)
    assert body.power == pytest.approx(1.0)
    assert skill.liningUp


def test_ball_in_front_of_the_right_foot_kicks_right():
    body = LineUpAndKick().tick(board(ORIGIN, ball=(130.0, -50.0))).body
    assert (body.actionType, body.foot) == (KICK, robot.Foot.RIGHT)


def test_not_facing_the_goal_turns_instead_of_kicking():
    pos = (0.0, 0.0, 0.3)  # ball in front of the left foot, goal 0.33 rad to the right
    command = LineUpAndKick().tick(board(pos, ball=relative(pos, 130.0, 50.0)))
    assert command.body.actionType == WALK
    assert velocities(command) == pytest.approx((0.0, 0.0, -0.5), abs=1e-3)


def test_ball_too_far_takes_small_steps():
    command = LineUpAndKick().tick(board(ORIGIN, ball=(250.0, 40.0)))
    assert command.body.actionType == WALK
    assert velocities(command) == pytest.approx((100.0, -20.0, -0.02909), abs=1e-3)


def test_foot_is_kept_while_lining_up():
    skill = LineUpAndKick()
    skill.tick(board(ORIGIN, ball=(250.0, 40.0)))
    assert skill.foot == robot.Foot.LEFT
    command = skill.tick(board(ORIGIN, ball=(130.0, -10.0)))  # now right of centre: left foot still
    assert skill.foot == robot.Foot.LEFT
    assert velocities(command) == pytest.approx((0.0, -100.0, 0.00697), abs=1e-3)
    fresh = LineUpAndKick()
    command = fresh.tick(board(ORIGIN, ball=(130.0, -10.0)))
    assert fresh.foot == robot.Foot.RIGHT
    assert velocities(command) == pytest.approx((0.0, 80.0, 0.00697), abs=1e-3)


def test_far_ball_approaches_like_go_to_ball():
    blackboard = board(ORIGIN, ball=(1000.0, 300.0))
    skill = LineUpAndKick()
    assert velocities(skill.tick(blackboard)) == velocities(GoToBall().tick(blackboard))
    assert not skill.liningUp


def test_lining_up_ends_when_the_ball_goes():
    skill = LineUpAndKick()
    skill.tick(board(ORIGIN, ball=(250.0, 40.0)))
    skill.tick(board(ORIGIN, ball=(450.0, 0.0)))  # within the leave distance
    assert skill.liningUp
    skill.tick(board(ORIGIN, ball=(600.0, 0.0)))
    assert not skill.liningUp


def test_lost_ball_stands():
    skill = LineUpAndKick()
    skill.tick(board(ORIGIN, ball=(250.0, 40.0)))
    command = skill.tick(board(ORIGIN, ball=(250.0, 40.0), seen=False, lost=BALL_LOST_FRAMES + 1))
    assert command.body.actionType == robot.ActionType.STAND
    assert not skill.liningUp


def test_dribble_variant_and_power():
    body = LineUpAndKick(dribble=True).tick(board(ORIGIN, ball=(130.0, 50.0))).body
    assert body.actionType == robot.ActionType.DRIBBLE
    assert body.power == pytest.approx(1.0)
    body = LineUpAndKick(power=0.7).tick(board(ORIGIN, ball=(130.0, 50.0))).body
    assert (body.actionType, body.power) == (KICK, pytest.approx(0.7))
