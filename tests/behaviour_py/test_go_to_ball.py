"""GoToBall: behind the ball facing the goal, via GoToPose; the same cases as
tests/behaviour_cpp/skills/test_go_to_ball.cpp."""
import math

import pytest
import robot
from boards import board

from skills.ball import (BALL_LOST_FRAMES, GOAL_MOUTH_AIM_DEPTH, GOAL_MOUTH_AIM_DIST, GOAL_MOUTH_HALF_WIDTH, cornerAim,
                         goalMouthAim, kickAim, pointBehindBall)
from skills.field import FIELD_EDGE_SLACK, FIELD_HALF_LENGTH, FIELD_HALF_WIDTH
from skills.go_to_ball import GoToBall


def test_point_behind_ball_on_the_line_from_the_goal():
    assert pointBehindBall(robot.AbsCoord(1000.0, 0.0), 3000.0, 0.0, 200.0) == pytest.approx((800.0, 0.0, 0.0))
    x, y, theta = pointBehindBall(robot.AbsCoord(2000.0, 1000.0), 3000.0, 0.0, 200.0)
    assert (x, y, theta) == pytest.approx((1858.5786, 1141.4214, -math.pi / 4), abs=1e-3)
    assert pointBehindBall(robot.AbsCoord(0.0, 0.0), -3000.0, 0.0, 200.0) == pytest.approx((200.0, 0.0, math.pi))


def test_point_behind_ball_at_the_goal_aims_along_x():
    assert pointBehindBall(robot.AbsCoord(3000.0, 0.0), 3000.0, 0.0, 200.0) == pytest.approx((2800.0, 0.0, 0.0))



def test_in_the_open_the_aim_is_the_goal():
    assert kickAim(1000.0, 500.0, 3000.0, 0.0, 200.0) == (3000.0, 0.0)
    assert kickAim(0.0, 1900.0, 3000.0, 0.0, 200.0) == (3000.0, 0.0)  # behind it is still on the field


def test_near_a_goal_line_the_aim_moves_in_proportion_to_the_mouths_nearest_point():
    assert goalMouthAim(3000.0 - GOAL_MOUTH_AIM_DIST, -585.0, 3000.0, 0.0) == (3000.0, 0.0)
    halfway = goalMouthAim(3000.0 - GOAL_MOUTH_AIM_DIST / 2, -585.0, 3000.0, 0.0)
    assert halfway == pytest.approx((3000.0 + GOAL_MOUTH_AIM_DEPTH / 2, -585.0 / 2))
    beside_the_mouth = goalMouthAim(-3000.0, 1500.0, -3000.0, 0.0)  # the other goal too
    assert beside_the_mouth == pytest.approx((-3000.0 - GOAL_MOUTH_AIM_DEPTH, GOAL_MOUTH_HALF_WIDTH))
    assert kickAim(900.0, 400.0, 1000.0, 500.0, 200.0) == (1000.0, 500.0)  # not a goal: as given


def standing(ballX, ballY, aim):
    """(x, y, theta) of a robot 200 mm behind the ball at (ballX, ballY), facing the point aim."""
    return pointBehindBall(robot.AbsCoord(ballX, ballY), aim[0], aim[1], 200.0)


def test_a_ball_on_a_touchline_is_aimed_along_it_from_no_further_out_than_the_slack():
    # Facing the goal from behind a ball on the touchline would stand the robot 141 mm
    # beyond it; the aim turns towards the line until the robot stands FIELD_EDGE_SLACK out.
    x, y, theta = standing(1000.0, FIELD_HALF_WIDTH, kickAim(1000.0, FIELD_HALF_WIDTH, 3000.0, 0.0, 200.0))
    assert y == pytest.approx(FIELD_HALF_WIDTH + FIELD_EDGE_SLACK)
    assert -math.pi / 4 < theta < 0.0  # between the goal's heading and the line's, inwards
    x, y, theta = standing(1000.0, -FIELD_HALF_WIDTH, kickAim(1000.0, -FIELD_HALF_WIDTH, 3000.0, 0.0, 200.0))
    assert y == pytest.approx(-FIELD_HALF_WIDTH - FIELD_EDGE_SLACK)
    assert 0.0 < theta < math.pi / 4


def test_a_ball_in_the_mouth_on_the_goal_line_is_aimed_into_the_goal_from_clear_of_the_post():
    # Aimed at the goal's centre, along the line, the spot behind it was at the post (3000,
    # -700): the striker stood against the post for 28 s until the referee restarted the game.
    ball = (FIELD_HALF_LENGTH - 10.0, -585.0)
    x, y, theta = standing(*ball, kickAim(*ball, 3000.0, 0.0, 200.0))
    assert abs(theta) < 0.25  # into the goal
    # clear of the post by more than its radius (50) and a foot's reach (its corner 124 mm out)
    assert math.hypot(x - FIELD_HALF_LENGTH, y + 700.0) > 200.0
    assert x < FIELD_HALF_LENGTH  # on the field


def test_a_ball_on_the_own_goal_line_is_aimed_out_to_its_goal_side():
    x, y, theta = standing(-FIELD_HALF_LENGTH, 500.0, kickAim(-FIELD_HALF_LENGTH, 500.0, 3000.0, 0.0, 200.0))
    assert x == pytest.approx(-FIELD_HALF_LENGTH - FIELD_EDGE_SLACK)
    assert -math.pi / 2 < theta < -math.pi / 4  # along the line, towards the goal's side (-y)


def test_a_ball_in_a_corner_is_aimed_out_of_it_standing_as_far_beyond_both_lines():
    # Turning off the goal line stood the robot beyond the touchline again, facing along the
    # goal line with the ball beside it: 10 s stuck in the own corner.
    for ball in ((-FIELD_HALF_LENGTH + 10.0, -FIELD_HALF_WIDTH + 30.0), (-FIELD_HALF_LENGTH, FIELD_HALF_WIDTH)):
        x, y, theta = standing(*ball, kickAim(*ball, 3000.0, 0.0, 200.0))
        assert -x - FIELD_HALF_LENGTH == pytest.approx(abs(y) - FIELD_HALF_WIDTH)
        assert abs(y) > FIELD_HALF_WIDTH + FIELD_EDGE_SLACK  # no aim keeps it within both
        assert 0.0 < (theta if ball[1] < 0.0 else -theta) < math.pi / 2  # out of the corner, into the field


def test_the_corner_aim_meets_the_one_line_aim_where_the_corner_starts():
    # 120 mm and 160 mm of room to the lines' slack: aiming (0.6, 0.8), the robot stands on both.
    ball = (-(FIELD_HALF_LENGTH + FIELD_EDGE_SLACK - 120.0), -(FIELD_HALF_WIDTH + FIELD_EDGE_SLACK - 160.0))
    assert cornerAim(*ball, 200.0) == pytest.approx((0.6, 0.8))
    x, y, theta = standing(*ball, kickAim(*ball, 3000.0, 0.0, 200.0))
    assert (x, y) == pytest.approx((-FIELD_HALF_LENGTH - FIELD_EDGE_SLACK, -FIELD_HALF_WIDTH - FIELD_EDGE_SLACK))


def test_beside_a_ball_on_the_touchline_it_stands_facing_along_the_line():
    # Where it was: 100 mm short of a target out of its reach, the ball beside it, never lined up.
    ball = (1000.0, FIELD_HALF_WIDTH)
    x, y, theta = standing(*ball, kickAim(*ball, 3000.0, 0.0, 200.0))
    skill = GoToBall()
    assert skill.tick(board((x, y, theta), ball=ball)).body.actionType == robot.ActionType.STAND
    assert skill.goToPose.arrived

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
