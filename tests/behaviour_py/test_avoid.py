"""Avoid: around robots, out of the own goal box, backing off when blocked; the same cases
as tests/behaviour_cpp/skills/test_avoid.cpp."""
import math

import pytest
import robot
from boards import board, message, seenRobot

from skills.avoid import (AVOID_CLEARANCE, BACK_OFF_FRAMES, BLOCKED_FRAMES, SEEN_MEMORY_US, SONAR_SIDE_Y, TOUCH_DIST,
                          TOUCH_FRONT_BEARING, Avoid, keepClear, keepInBounds, keepOffTouches,
                          keepOnField, keepOutOfOwnBox, obstacles, remember, steer)
from skills.go_to_pose import GoToPose
from skills.team_comm import ROLE_DEFENDER, TeamInfo, encodeMessage

FRAME_US = 33333
NOW = 10_000_000


def passing(forward, left, x, y):
    """How far the walk's line passes the point (x, y), mm, + when the point is on its left."""
    speed = math.hypot(forward, left)
    return (forward * y - left * x) / speed


def walk(forward=300.0, left=0.0, turn=0.0):
    body = robot.Body()
    body.actionType = robot.ActionType.WALK
    body.forward, body.left, body.turn = forward, left, turn
    return body


def poseMessage(number, x, y, penalised=False, age=0):
    info = TeamInfo(number, ROLE_DEFENDER, False, penalised, False, 65535, 0, 0, x, y)
    return message(number, encodeMessage(info), NOW - age)


# Where the obstacles come from
def test_obstacles_from_sonar_camera_and_teammates():
    pos = (1000.0, 0.0, math.pi / 2)  # facing +y
    messages = [poseMessage(3, 1000, 600), poseMessage(4, 0, 0, penalised=True), poseMessage(5, 0, 0, age=3_000_000),
                poseMessage(2, 1000, 900)]  # 2 is this robot: its own message is no obstacle
    seeing = board(pos, sonar=(0.5, 1.0), robots=[seenRobot(700.0, -200.0)], messages=messages, utime=NOW)
    found = obstacles(seeing, remember([], seeing))
    assert len(found) == 3
    assert found[0] == pytest.approx((500.0, SONAR_SIDE_Y))
    assert found[1] == pytest.approx((700.0, -200.0), abs=1e-3)
    assert found[2] == pytest.approx((600.0, 0.0), abs=1e-3)  # the teammate 600 mm ahead
    assert obstacles(board(pos, sonar=(1.0, 0.25)))[0] == pytest.approx((250.0, -SONAR_SIDE_Y))
    assert obstacles(board(pos)) == []


def test_a_touch_is_a_robot_at_its_sectors_bearing():
    found = obstacles(board(touch=("FrontLeft", "Back")))
    assert len(found) == 2
    assert found[0] == pytest.approx((TOUCH_DIST * math.cos(TOUCH_FRONT_BEARING), TOUCH_DIST * math.sin(TOUCH_FRONT_BEARING)))
    assert found[1] == pytest.approx((-TOUCH_DIST, 0.0), abs=1e-3)
    assert obstacles(board(touch=("FrontRight",)))[0] == pytest.approx((found[0][0], -found[0][1]))
    sides = obstacles(board(touch=("Left", "Right")))
    assert sides[0] == pytest.approx((0.0, TOUCH_DIST), abs=1e-3) and sides[1] == pytest.approx((0.0, -TOUCH_DIST), abs=1e-3)


def test_robots_seen_are_remembered_for_a_while_where_they_were():
    seen = remember([], board((0.0, 0.0, 0.0), robots=[seenRobot(700.0, 0.0)], utime=NOW))
    later = board((100.0, 0.0, math.pi / 2), utime=NOW + SEEN_MEMORY_US)  # moved and turned, camera elsewhere
    seen = remember(seen, later)
    assert len(seen) == 1
    assert obstacles(later, seen)[0] == pytest.approx((0.0, -600.0), abs=1e-2)  # still at (700, 0): on the right
    assert remember(seen, board(utime=NOW + SEEN_MEMORY_US + 1)) == []


def test_a_new_sighting_replaces_the_remembered_ones_near_it():
    seen = remember([], board(robots=[seenRobot(700.0, 0.0), seenRobot(700.0, 1000.0)], utime=NOW))
    seen = remember(seen, board(robots=[seenRobot(700.0, 300.0)], utime=NOW + FRAME_US))
    assert sorted((round(x), round(y)) for _, x, y in seen) == [(700, 300), (700, 1000)]


# Around robots
def test_a_robot_dead_ahead_is_passed_on_the_right_at_the_clearance():
    forward, left = steer(300.0, 0.0, [(500.0, 0.0)], 2000.0)
    assert left < 0.0 and forward > 0.0
    assert passing(forward, left, 500.0, 0.0) == pytest.approx(AVOID_CLEARANCE, abs=1e-3)


def test_a_robot_left_of_the_line_is_passed_on_its_right_and_one_right_on_its_left():
    forward, left = steer(300.0, 0.0, [(600.0, 100.0)], 2000.0)
    assert passing(forward, left, 600.0, 100.0) == pytest.approx(AVOID_CLEARANCE, abs=1e-3)
    forward, left = steer(300.0, 0.0, [(600.0, -100.0)], 2000.0)
    assert left > 0.0
    assert passing(forward, left, 600.0, -100.0) == pytest.approx(-AVOID_CLEARANCE, abs=1e-3)


def test_the_nearest_robot_in_the_way_is_passed():
    forward, left = steer(0.0, 200.0, [(0.0, 700.0), (50.0, 450.0)], 2000.0)  # walking left
    assert passing(forward, left, 50.0, 450.0) == pytest.approx(-AVOID_CLEARANCE, abs=1e-3)


def test_a_touching_robot_is_stepped_past_sideways():
    forward, left = steer(300.0, 0.0, [(250.0, 10.0)], 2000.0)
    assert forward * 250.0 + left * 10.0 == pytest.approx(0.0, abs=1e-2)  # nothing towards it
    assert left < 0.0


def test_a_walk_into_a_robot_it_feels_but_never_saw_turns_away_from_it():
    # Walking forward and left into a robot against the left arm (45 to 135 deg): the walk keeps
    # its speed but turns to -45 deg, the nearest direction closing on no bearing of the arm's.
    free = Avoid().tick(board(utime=NOW), walk(200.0, 200.0), 2000.0)
    assert (free.forward, free.left) == pytest.approx((200.0, 200.0))
    body = Avoid().tick(board(touch=("Left",), utime=NOW), walk(200.0, 200.0), 2000.0)
    assert (body.forward, body.left) == pytest.approx((200.0, -200.0), abs=1e-2)


def test_a_walk_closing_on_no_touched_sector_is_left_alone():
    assert keepOffTouches(board(touch=("Left",)).motion, 300.0, 0.0) == pytest.approx((200.0, -200.0))  # clampWalk's
    assert keepOffTouches(board(touch=("Left",)).motion, 0.0, -200.0) == (0.0, -200.0)
    assert keepOffTouches(board(touch=("Back",)).motion, 300.0, 0.0) == (300.0, 0.0)
    assert keepOffTouches(board().motion, 0.0, 200.0) == (0.0, 200.0)


def test_pressed_on_both_foot_bumpers_it_steps_back_and_boxed_in_it_stops():
    forward, left = keepOffTouches(board(touch=("FrontLeft", "FrontRight")).motion, 200.0, 0.0)
    assert math.atan2(left, forward) == pytest.approx(3 * math.pi / 4)  # back left: the first of two equal turns
    assert math.hypot(forward, left) == pytest.approx(200.0)
    assert keepOffTouches(board(touch=("FrontLeft", "Left", "Right", "Back")).motion, 200.0, 0.0) == (0.0, 0.0)


def test_robots_out_of_the_way_are_left_alone():
    assert steer(300.0, 0.0, [(500.0, 450.0)], 2000.0) == (300.0, 0.0)   # off the line
    assert steer(300.0, 0.0, [(900.0, 0.0)], 2000.0) == (300.0, 0.0)     # beyond the lookahead
    assert steer(300.0, 0.0, [(-300.0, 0.0)], 2000.0) == (300.0, 0.0)    # behind
    assert steer(300.0, 0.0, [(500.0, 0.0)], 400.0) == (300.0, 0.0)      # beyond the target
    assert steer(0.0, 0.0, [(300.0, 0.0)], 2000.0) == (0.0, 0.0)         # turning on the spot


def test_go_to_pose_walks_around_a_robot_its_sonar_finds():
    clear = GoToPose(2000.0, 0.0, 0.0).tick(board((0.0, 0.0, 0.0)))
    assert (clear.body.forward, clear.body.left) == pytest.approx((300.0, 0.0))
    blocked = GoToPose(2000.0, 0.0, 0.0).tick(board((0.0, 0.0, 0.0), sonar=(0.5, 0.5)))
    assert blocked.body.left < 0.0
    assert blocked.body.turn == pytest.approx(clear.body.turn)


def test_a_robot_seen_once_is_walked_around_after_the_camera_looked_away():
    goToPose = GoToPose(2000.0, 0.0, 0.0)
    goToPose.tick(board((0.0, 0.0, 0.0), robots=[seenRobot(600.0, 0.0)], utime=NOW))
    command = goToPose.tick(board((0.0, 0.0, 0.0), utime=NOW + FRAME_US))
    assert command.body.left < 0.0


# Making way
def test_making_way_never_steps_back_into_a_robot_touching_the_back():
    goToPose = GoToPose(0.0, 0.0, 0.0)
    body = goToPose.tick(board((0.0, 0.0, 0.0), sonar=(0.3, 1.0), touch=("Back",), utime=NOW)).body
    assert body.actionType == robot.ActionType.WALK
    assert body.forward >= 0.0 and body.left < 0.0  # aside, away from the robot ahead on the left


def test_a_robot_at_its_target_steps_back_from_a_robot_ahead_of_it():
    goToPose = GoToPose(0.0, 0.0, 0.0)
    assert goToPose.tick(board((0.0, 0.0, 0.0), utime=NOW)).body.actionType == robot.ActionType.STAND
    body = goToPose.tick(board((0.0, 0.0, 0.0), sonar=(0.3, 1.0), utime=NOW + FRAME_US)).body
    assert body.actionType == robot.ActionType.WALK
    assert body.forward * 300.0 + body.left * SONAR_SIDE_Y == pytest.approx(-150.0 * math.hypot(300.0, SONAR_SIDE_Y))
    behind = board((0.0, 0.0, 0.0), robots=[seenRobot(-300.0, 0.0)], utime=NOW + 2 * FRAME_US)
    assert goToPose.tick(behind).body.actionType == robot.ActionType.STAND


# The own goal box
def test_a_walk_into_the_own_goal_box_slides_along_its_front():
    pos = robot.AbsCoord(-2200.0, 300.0, math.pi)  # in front of the box, facing the own goal
    assert keepOutOfOwnBox(pos, 300.0, 0.0) == pytest.approx((0.0, 0.0), abs=1e-3)
    forward, left = keepOutOfOwnBox(pos, 200.0, -200.0)  # back and to the field's +y: slides along +y
    assert forward == pytest.approx(0.0, abs=1e-3) and left == pytest.approx(-200.0, abs=1e-3)
    assert keepOutOfOwnBox(pos, -200.0, 50.0) == (-200.0, 50.0)  # away from it


def test_beside_the_box_a_walk_across_it_goes_round_by_the_front():
    pos = robot.AbsCoord(-2700.0, 1400.0, 0.0)  # beside the box, facing the field
    forward, left = keepOutOfOwnBox(pos, 0.0, -200.0)  # sideways across the box
    assert forward == pytest.approx(200.0, abs=1e-3) and left == pytest.approx(0.0, abs=1e-3)


def test_the_goalie_and_a_robot_in_the_box_walk_as_asked():
    inside = robot.AbsCoord(-2700.0, 0.0, math.pi)
    assert keepOutOfOwnBox(inside, 300.0, 0.0) == (300.0, 0.0)
    outside = (-2200.0, 0.0, math.pi)
    goalie = Avoid().tick(board(outside, player=1), walk(), 2000.0)
    assert goalie.forward == pytest.approx(300.0)
    player = Avoid().tick(board(outside, player=3), walk(), 2000.0)
    assert player.forward == pytest.approx(0.0, abs=1e-3)



def test_a_walk_the_box_turns_back_into_a_touching_robot_stops():
    # Beside the own box, sidestepping towards it: the box sends the walk round its front,
    # forward; with an opponent against the left foot bumper, forward is into it: wait instead.
    beside = (-2700.0, 1400.0, 0.0)
    free = Avoid().tick(board(beside, player=3, utime=NOW), walk(0.0, -200.0), 2000.0)
    assert (free.forward, free.left) == pytest.approx((200.0, 0.0), abs=1e-3)
    touched = Avoid().tick(board(beside, player=3, touch=("FrontLeft",), utime=NOW), walk(0.0, -200.0), 2000.0)
    assert (touched.forward, touched.left) == (0.0, 0.0)

# The field
def test_a_walk_over_a_touchline_loses_its_part_out_and_keeps_its_part_along():
    atLine = robot.AbsCoord(0.0, 1950.0, math.pi / 2)  # on the +y touchline's inside, facing out
    assert keepOnField(atLine, 300.0, 0.0) == pytest.approx((0.0, 0.0), abs=1e-3)  # straight out: stops
    assert keepOnField(atLine, 200.0, 200.0) == pytest.approx((0.0, 200.0), abs=1e-3)  # out and along -x: only along
    assert keepOnField(atLine, -300.0, 0.0) == pytest.approx((-300.0, 0.0), abs=1e-3)  # back in
    assert keepOnField(robot.AbsCoord(0.0, 1700.0, math.pi / 2), 300.0, 0.0) == (300.0, 0.0)  # not past the slack


def test_keep_in_bounds_keeps_the_box_and_the_lines_but_not_the_touches():
    # Beside the own box, sidestepping towards it, an opponent against the left foot bumper:
    # keepInBounds sends the walk round the box's front, into the robot (keepClear waits), and
    # for the goalie leaves it as asked; at the touchline it drops the part out, as keepClear does.
    touched = board((-2700.0, 1400.0, 0.0), player=3, touch=("FrontLeft",), utime=NOW)
    assert keepInBounds(touched, 0.0, -200.0) == pytest.approx((200.0, 0.0), abs=1e-3)
    assert keepClear(touched, 0.0, -200.0) == (0.0, 0.0)
    goalie = board((-2700.0, 1400.0, 0.0), player=1, touch=("FrontLeft",), utime=NOW)
    assert keepInBounds(goalie, 0.0, -200.0) == pytest.approx((0.0, -200.0), abs=1e-3)
    atLine = board((0.0, 1950.0, math.pi / 2), player=3, utime=NOW)  # facing out
    assert keepInBounds(atLine, 200.0, 200.0) == pytest.approx((0.0, 200.0), abs=1e-3)


def test_beyond_a_goal_line_a_robot_may_only_walk_back_in():
    beyond = robot.AbsCoord(-3100.0, 500.0, 0.0)  # behind the own goal line, facing the field
    assert keepOnField(beyond, -200.0, 0.0) == pytest.approx((0.0, 0.0), abs=1e-3)
    assert keepOnField(beyond, 200.0, 0.0) == pytest.approx((200.0, 0.0), abs=1e-3)
    assert keepOnField(beyond, -200.0, 100.0) == pytest.approx((0.0, 100.0), abs=1e-3)


def test_every_player_the_goalie_too_stays_on_the_field():
    atLine = (0.0, -1980.0, 0.0)  # on the -y touchline, facing along it
    for player in (1, 2):
        assert Avoid().tick(board(atLine, player=player), walk(0.0, -200.0), 2000.0).left == pytest.approx(0.0, abs=1e-3)


# Backing off
def run(avoid, frames, sonar=(0.3, 1.0), targetDist=2000.0, start=0, step=FRAME_US, touch=()):
    return [avoid.tick(board(sonar=sonar, touch=touch, utime=NOW + (start + i) * step), walk(), targetDist)
            for i in range(frames)]


def test_blocked_without_progress_backs_off_then_walks_again():
    avoid = Avoid()
    before = run(avoid, BLOCKED_FRAMES - 1)
    assert all(body.forward > 0.0 for body in before)
    backing = run(avoid, BACK_OFF_FRAMES, start=BLOCKED_FRAMES - 1)
    # back and away from an obstacle on the left
    assert all(body.forward < 0.0 and body.left < 0.0 and body.turn == 0.0 for body in backing)
    after = run(avoid, 1, start=BLOCKED_FRAMES - 1 + BACK_OFF_FRAMES)
    assert after[0].forward > 0.0


def test_an_obstacle_on_the_right_is_backed_off_to_the_left():
    bodies = run(Avoid(), BLOCKED_FRAMES, sonar=(1.0, 0.3))
    assert bodies[-1].forward < 0.0 and bodies[-1].left > 0.0


def test_backing_off_never_steps_back_into_a_robot_touching_the_back():
    bodies = run(Avoid(), BLOCKED_FRAMES, touch=("Back",))
    assert bodies[-1].forward >= 0.0 and bodies[-1].left < 0.0  # aside, still away from the left


def test_progress_or_a_clear_way_is_no_block():
    avoid = Avoid()
    bodies = [avoid.tick(board(sonar=(0.3, 1.0), utime=NOW + i * FRAME_US), walk(), 2000.0 - 5.0 * i)
              for i in range(3 * BLOCKED_FRAMES)]  # 5 mm a frame nearer
    assert all(body.forward > 0.0 for body in bodies)
    assert all(body.forward > 0.0 for body in run(Avoid(), 3 * BLOCKED_FRAMES, sonar=(1.0, 1.0)))


def test_a_gap_in_the_ticks_starts_the_count_again():
    avoid = Avoid()
    run(avoid, BLOCKED_FRAMES - 1)
    assert all(body.forward > 0.0 for body in run(avoid, BLOCKED_FRAMES - 1, start=BLOCKED_FRAMES + 10))
