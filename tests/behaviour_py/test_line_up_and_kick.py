"""LineUpAndKick: approach, line up the foot, kick when aligned; the same cases as
tests/behaviour_cpp/skills/test_line_up_and_kick.cpp."""
import math

import pytest
import robot
from boards import board, relative, seenRobot

from skills.ball import BALL_LOST_FRAMES, BEHIND_BALL_DIST, kickAim, pointBehindBall
from skills.field import FIELD_EDGE_SLACK, FIELD_HALF_LENGTH, FIELD_HALF_WIDTH, OWN_BOX_FRONT_X, clampToField
from skills.go_to_ball import GoToBall
from skills.line_up_and_kick import (CARRY_CLOSING_GAIN, CARRY_SPEED, CONTEST_DODGE_SPEED, CONTEST_LEAN_SPEED,
                                     KICK_BALL_X, LINE_UP_MAX_SPEED, LINE_UP_MAX_TURN, SIDESTEP_FRAMES, STALL_FRAMES,
                                     LineUpAndKick, carrySpeed)
from skills.robot_limits import MAX_FORWARD

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



def test_lining_up_never_steps_into_a_robot_it_touches():
    # Lining up, the ball ahead and to the left: a step forward and left, unless a robot
    # against the left arm is there; then forward and right (avoid.py's keepOffTouches).
    free = LineUpAndKick().tick(board(ORIGIN, ball=(250.0, 150.0))).body
    assert free.actionType == WALK and free.forward > 0.0 and free.left > 0.0
    touched = LineUpAndKick().tick(board(ORIGIN, ball=(250.0, 150.0), touch=("Left",))).body
    assert touched.actionType == WALK and touched.forward > 0.0 and touched.left < 0.0

def test_lining_up_never_steps_into_the_own_goal_box():
    # Lining up with the ball short of the kicking spot and to the left: a step back and
    # left; in front of the own goal box, where a field player is an illegal defender, the
    # step back is dropped (avoid.py's keepOutOfOwnBox, through keepClear).
    def step(pos):
        return LineUpAndKick().tick(board(pos, ball=relative(pos, 60.0, 120.0))).body  # player 2

    free = step((0.0, 0.0, 0.0))
    assert free.actionType == WALK and free.forward < 0.0 and free.left > 0.0
    byTheBox = step((OWN_BOX_FRONT_X + 150.0, 0.0, 0.0))
    assert byTheBox.actionType == WALK and byTheBox.forward >= 0.0 and byTheBox.left > 0.0


def test_not_facing_the_goal_turns_instead_of_kicking():
    pos = (1500.0, 0.0, 0.3)  # ball in front of the left foot, goal 0.36 rad to the right
    command = LineUpAndKick().tick(board(pos, ball=relative(pos, 130.0, 50.0)))
    assert command.body.actionType == WALK
    assert velocities(command) == pytest.approx((0.0, 0.0, -0.72380), abs=1e-3)  # TURN_GAIN x the 0.36 rad to the goal


def test_far_from_the_goal_a_kick_off_its_line_is_taken():
    pos = (0.0, 0.0, 0.3)  # the goal 3 km away, 0.33 rad to the right
    body = LineUpAndKick().tick(board(pos, ball=relative(pos, 130.0, 50.0))).body
    assert (body.actionType, body.foot) == (KICK, robot.Foot.LEFT)



def test_a_ball_on_the_touchline_is_kicked_along_it():
    # The goal 1.1 rad to the right: facing it, the robot would stand beyond the line. Facing
    # along the line (turned inwards as far as the slack lets it stand out) it kicks.
    theta = math.asin((FIELD_HALF_WIDTH - (FIELD_HALF_WIDTH + FIELD_EDGE_SLACK)) / BEHIND_BALL_DIST)
    ball = (2000.0, FIELD_HALF_WIDTH)
    pos = (ball[0] - 130.0 * math.cos(theta) + 50.0 * math.sin(theta),
           ball[1] - 130.0 * math.sin(theta) - 50.0 * math.cos(theta), theta)
    assert relative(pos, 130.0, 50.0) == pytest.approx(ball)
    body = LineUpAndKick().tick(board(pos, ball=ball)).body
    assert (body.actionType, body.foot) == (KICK, robot.Foot.LEFT)


def test_a_ball_in_the_own_corner_is_lined_up_from_where_the_approach_ends():
    # The approach's target, behind the ball, lies beyond both lines; the walk stops at the
    # slack. From there the ball must be ahead and the aim in line, or nobody kicks it.
    ball = robot.AbsCoord(-FIELD_HALF_LENGTH + 20.0, -FIELD_HALF_WIDTH + 20.0)
    x, y, theta = pointBehindBall(ball, *kickAim(ball.x, ball.y, 3000.0, 0.0, BEHIND_BALL_DIST), BEHIND_BALL_DIST)
    skill = LineUpAndKick()
    assert skill.tick(board((*clampToField(x, y, -FIELD_EDGE_SLACK), theta), ball=(ball.x, ball.y))).body.actionType == WALK
    assert skill.liningUp


# The goal 1.04 rad to the right, the ball 38 mm beyond the kicking spot and 38 mm off the
# left foot's line (within a kick's tolerances): an approach alone, a kick at once when a
# robot is near the ball.
CONTEST_POS = (1500.0, 0.0, 0.9)


def contest_board(ballX=168.0, ballY=88.0, **kwargs):
    return board(CONTEST_POS, ball=relative(CONTEST_POS, ballX, ballY), **kwargs)


def test_a_contested_ball_is_kicked_at_once_wherever_it_gains_ground():
    alone = LineUpAndKick()
    body = alone.tick(contest_board()).body
    assert body.actionType == WALK and body.turn < 0.0  # turns to the goal, on its right, before kicking
    far = contest_board(robots=[seenRobot(1200.0, 0.0)])  # over 500 mm from the ball
    assert LineUpAndKick().tick(far).body.actionType == WALK
    contested = LineUpAndKick()
    body = contested.tick(contest_board(robots=[seenRobot(450.0, 120.0)])).body  # across the ball
    assert contested.contested
    assert (body.actionType, body.foot) == (KICK, robot.Foot.LEFT)


@pytest.mark.parametrize("ballX, ballY", [(190.0, 88.0), (168.0, 100.0)])
def test_a_contested_kick_waits_for_the_ball_within_the_swings_reach(ballX, ballY):
    # 60 mm beyond the kicking spot the swing (to 200 mm ahead) meets the ball at its end, and
    # 50 mm off the foot's line with the foot's edge: a step closer first.
    contested = LineUpAndKick()
    assert contested.tick(contest_board(ballX, ballY, robots=[seenRobot(450.0, 120.0)])).body.actionType == WALK
    assert contested.contested


def test_a_stalled_contest_steps_round_the_ball_away_from_the_robot_then_kicks_again():
    skill = LineUpAndKick()
    contested = contest_board(robots=[seenRobot(450.0, 120.0)])  # left of the ball: step right
    bodies = [skill.tick(contested).body for _ in range(1 + STALL_FRAMES + SIDESTEP_FRAMES + 1)]
    assert all(b.actionType == KICK for b in bodies[:1 + STALL_FRAMES])  # kicks, and the ball stays
    for b in bodies[1 + STALL_FRAMES:-1]:
        # turning to the ball, TURN_GAIN x its bearing
        assert (b.actionType, b.forward, b.left, b.turn) == (WALK, 0.0, pytest.approx(-LINE_UP_MAX_SPEED),
                                                             pytest.approx(0.96503, abs=1e-4))
    assert bodies[-1].actionType == KICK  # then kicks again from there


def test_a_contested_ball_that_moves_starts_the_stall_count_again():
    skill = LineUpAndKick()
    for _ in range(STALL_FRAMES):
        skill.tick(contest_board(robots=[seenRobot(450.0, 120.0)]))
    moved = contest_board(92.0, 12.0, robots=[seenRobot(450.0, 120.0)])  # 107 mm
    assert all(skill.tick(moved).body.actionType == KICK for _ in range(STALL_FRAMES))


def test_a_robot_the_sonar_finds_at_the_ball_contests_it():
    body = LineUpAndKick().tick(contest_board(sonar=(0.4, 1.0))).body  # 400 mm ahead
    assert body.actionType == KICK


def test_with_carry_a_clear_ball_is_walked_on_not_kicked():
    # The ball in front of the left foot, lined up: a kick without carry, a walk into the
    # ball with it, steering its 50 mm off the centre line back under the body.
    assert LineUpAndKick().tick(board(ORIGIN, ball=(130.0, 50.0))).body.actionType == KICK
    skill = LineUpAndKick(carry=True)
    body = skill.tick(board(ORIGIN, ball=(130.0, 50.0))).body
    assert (body.actionType, body.forward) == (WALK, CARRY_SPEED)
    assert (body.left, body.turn) == pytest.approx((100.0, 2.0 * math.atan2(-50.0, 2870.0)), abs=1e-4)
    assert skill.liningUp


def test_a_carrier_walks_a_ball_on_from_an_aim_a_kicker_would_walk_round_to():
    pos = (0.0, 0.0, 1.45)  # the goal 1.5 rad to the right of the ball ahead: beyond a right angle
    ball = relative(pos, 130.0, 0.0)
    kicker = LineUpAndKick()
    assert kicker.tick(board(pos, ball=ball)).body.forward < CARRY_SPEED and not kicker.liningUp
    carrier = LineUpAndKick(carry=True)
    body = carrier.tick(board(pos, ball=ball)).body
    assert (body.actionType, body.forward, body.turn) == (WALK, CARRY_SPEED, pytest.approx(-LINE_UP_MAX_TURN))
    assert carrier.liningUp


def test_a_carrier_walks_on_past_a_robot_ahead_and_leans_into_one_it_touches():
    # A kick into a robot at the ball often rebounds (in full matches, sometimes out of the field):
    # the carrier walks on. A robot against both foot bumpers contests the ball: the carrier leans
    # into it at CONTEST_LEAN_SPEED rather than stop (two that stop hold the ball between them).
    ahead = board(ORIGIN, ball=(130.0, 50.0), robots=[seenRobot(550.0, 150.0)])  # 460 mm beyond the ball
    body = LineUpAndKick(carry=True).tick(ahead).body
    assert (body.actionType, body.forward) == (WALK, CARRY_SPEED)
    touching = board(ORIGIN, ball=(130.0, 50.0), touch=("FrontLeft", "FrontRight"))
    leaning = LineUpAndKick(carry=True)
    body = leaning.tick(touching).body
    assert leaning.contested
    # the ball under the body, away from the left bumper's robot
    assert (body.actionType, body.forward) == (WALK, CONTEST_LEAN_SPEED)
    assert body.left == pytest.approx(2.0 * 50.0 - CONTEST_DODGE_SPEED, abs=1e-3)
    # Lining up to kick (no carry), the ball short of the foot: the step on is never into the robot.
    short_of_foot = board(ORIGIN, ball=(250.0, 50.0), touch=("FrontLeft", "FrontRight"))
    assert LineUpAndKick().tick(short_of_foot).body.forward <= 0.0


def test_a_leaning_carrier_keeps_to_the_field():
    # Lined up 40 mm beyond the touchline, turned 0.1 rad further out, a robot against both
    # bumpers: the lean, like any carry, goes along the line, not further out.
    pos = (0.0, FIELD_HALF_WIDTH + 40.0, 0.1)
    touching = board(pos, ball=relative(pos, 130.0, 0.0), touch=("FrontLeft", "FrontRight"))
    body = LineUpAndKick(carry=True).tick(touching).body
    assert body.actionType == WALK and body.forward > 0.0
    assert body.forward * math.sin(pos[2]) + body.left * math.cos(pos[2]) == pytest.approx(0.0, abs=1e-3)


def test_a_contested_carrier_steps_sideways_away_from_the_robot_at_the_ball():
    # The ball ahead on the centre line, a robot 280 mm beyond it: two carriers walking into one
    # ball wedge it between their feet; the sideways step rolls it off the pair.
    clear = LineUpAndKick(carry=True).tick(board(ORIGIN, ball=(130.0, 0.0))).body
    assert (clear.actionType, clear.forward, clear.left) == (WALK, CARRY_SPEED, pytest.approx(0.0))
    for robotY, left in ((100.0, -CONTEST_DODGE_SPEED), (-100.0, CONTEST_DODGE_SPEED)):
        skill = LineUpAndKick(carry=True)
        body = skill.tick(board(ORIGIN, ball=(130.0, 0.0), robots=[seenRobot(400.0, robotY)])).body
        assert skill.contested
        assert (body.actionType, body.forward, body.left) == (WALK, CARRY_SPEED, pytest.approx(left))


def test_a_carrier_does_not_walk_the_ball_off_the_field():
    # Lined up 40 mm beyond the touchline, turned 0.1 rad further out: walking straight on
    # would take it further out; keepClear keeps the walk along the line.
    pos = (0.0, FIELD_HALF_WIDTH + 40.0, 0.1)
    body = LineUpAndKick(carry=True).tick(board(pos, ball=relative(pos, 130.0, 0.0))).body
    assert body.actionType == WALK and body.forward > 0.0
    assert body.forward * math.sin(pos[2]) + body.left * math.cos(pos[2]) == pytest.approx(0.0, abs=1e-3)


def test_ball_too_far_steps_closer():
    command = LineUpAndKick().tick(board(ORIGIN, ball=(250.0, 40.0)))
    assert command.body.actionType == WALK
    # LINE_UP_GAIN x the errors (120 mm, -10 mm)
    assert velocities(command) == pytest.approx((240.0, -20.0, -0.02909), abs=1e-3)


def test_a_carrier_closes_on_a_ball_ahead_faster_and_meets_it_at_carry_speed():
    assert carrySpeed(KICK_BALL_X) == CARRY_SPEED  # at the foot
    assert carrySpeed(KICK_BALL_X - 50.0) == CARRY_SPEED
    assert carrySpeed(KICK_BALL_X + 30.0) == CARRY_SPEED + 30.0 * CARRY_CLOSING_GAIN
    assert carrySpeed(400.0) == MAX_FORWARD
    # The skill: the ball 250 mm ahead, lined up with the goal, walked up to at full speed.
    body = LineUpAndKick(carry=True).tick(board(ORIGIN, ball=(250.0, 0.0))).body
    assert (body.actionType, body.forward) == (WALK, MAX_FORWARD)


def test_foot_is_kept_while_lining_up():
    skill = LineUpAndKick()
    skill.tick(board(ORIGIN, ball=(250.0, 40.0)))
    assert skill.foot == robot.Foot.LEFT
    command = skill.tick(board(ORIGIN, ball=(130.0, -20.0)))  # now right of centre: left foot still
    assert skill.foot == robot.Foot.LEFT
    assert velocities(command) == pytest.approx((0.0, -140.0, 0.01394), abs=1e-3)
    fresh = LineUpAndKick()
    body = fresh.tick(board(ORIGIN, ball=(130.0, -20.0))).body
    assert (fresh.foot, body.actionType, body.foot) == (robot.Foot.RIGHT, KICK, robot.Foot.RIGHT)


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
