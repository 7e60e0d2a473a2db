"""GoToBall: behind the ball facing the goal, via GoToPose; the same cases as
tests/behaviour_cpp/skills/test_go_to_ball.cpp."""
import math

import pytest
import robot
from boards import board

from skills.ball import BALL_LOST_FRAMES, pointBehindBall
from skills.go_to_ball import GoToBall


def test_point_behind_ball_on_the_line_from_the_goal():
    assert pointBehindBall(robot.AbsCoord(1000.0, 0.0), 3000.0, 0.0, 200.0) == pytest.approx((800.0, 0.0, 0.0))
    x, y, theta = pointBehindBall(robot.AbsCoord(2000.0, 1000.0), 3000.0, 0.0, 200.0)
    assert (x, y, theta) == pytest.approx((1858.5786, 1141.4214, -math.pi / 4), abs=1e-3)
    assert pointBehindBall(robot.AbsCoord(0.0, 0.0), -3000.0, 0.0, 200.0) == pytest.approx((200.0, 0.0, math.pi))


def test_point_behind_ball_at_the_goal_aims_along_x():
    assert pointBehindBall(robot.AbsCoord(3000.0, 0.0), 3000.0, 0.0, 200.0) == pytest.approx((2800.0, 0.0, 0.0))


def test_walks_to_the_ball():
    command = GoToBall().tick(board((0.0, 0.0, 0.0), ball=(1000.0, 0.0)))
    assert command.body.actionType == robot.ActionType.WALK
    assert (command.body.forward, command.body.turn) == pytest.approx((300.0, 0.0))


def test_stands_behind_the_ball_facing_the_goal():
    skill = GoToBall()
    assert skill.tick(board((800.0, 0.0, 0.0), ball=(1000.0, 0.0))).body.actionType == robot.ActionType.STAND
    assert skill.goToPose.arrived


def test_goal_is_a_parameter():
    # Kicking towards our own half: behind the ball is on its +x side, facing -x.
    skill = GoToBall(goalX=-3000.0)
    assert skill.tick(board((200.0, 0.0, math.pi), ball=(0.0, 0.0))).body.actionType == robot.ActionType.STAND


def test_lost_ball_stands():
    command = GoToBall().tick(board((0.0, 0.0, 0.0), ball=(1000.0, 0.0), seen=False, lost=BALL_LOST_FRAMES + 1))
    assert command.body.actionType == robot.ActionType.STAND
    command = GoToBall().tick(board((0.0, 0.0, 0.0), ball=(1000.0, 0.0), seen=False, lost=BALL_LOST_FRAMES))
    assert command.body.actionType == robot.ActionType.WALK  # still recent
