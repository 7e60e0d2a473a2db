"""Search (issue #17: no turning on the spot for long when the ball is lost): the team ball,
the search cycle of turns and walks to search spots, a ball put back where the rules put it;
the same hand-worked cases as
tests/behaviour_cpp/skills/test_search.cpp."""
import math

import pytest
import robot
from boards import board, message

from skills.ball import BEHIND_BALL_DIST, OPPONENT_GOAL_X, OPPONENT_GOAL_Y, kickAim, pointBehindBall
from skills.field import FIELD_EDGE_SLACK, FIELD_HALF_LENGTH, FIELD_HALF_WIDTH
from skills.search import (BALL_AT_FEET_DIST, DROP_IN_FRESH_S, DROP_IN_SETBACK, HOME_NEAR_DIST, SEARCH_CYCLE_FRAMES,
                           SEARCH_TURN_FRAMES, SEARCH_TURN_LIMIT_FRAMES, SEARCH_TURN_SPEED, THROW_IN_LINE_END,
                           THROW_IN_LINE_INSET, Search, dropInSpot, searchSpot, teamBall, teamBallTarget)
from skills.supporter import THESIS
from skills.team import Team
from skills.team_comm import (MESSAGE_STALE_US, NO_BALL_DISTANCE, ROLE_DEFENDER, ROLE_MIDFIELDER, ROLE_STRIKER,
                              TeamInfo, encodeMessage)

WALK = robot.ActionType.WALK
STAND = robot.ActionType.STAND
NOW = 10000000


def sighting(number, distance, x, y, penalised=False, age=0):
    """Teammate `number`'s message: it sees the ball at (x, y) from `distance` mm
    (NO_BALL_DISTANCE: it does not)."""
    info = TeamInfo(number, ROLE_DEFENDER, distance != NO_BALL_DISTANCE, penalised, False, distance, x, y)
    return message(number, encodeMessage(info), NOW - age)


def test_the_team_ball_is_the_nearest_fresh_sighting():
    assert teamBall(2, [], NOW) is None
    assert teamBall(2, [sighting(3, 900, 100, 200), sighting(4, 700, -500, 300)], NOW) == (-500.0, 300.0)
    assert teamBall(2, [sighting(4, 700, -500, 300), sighting(3, 700, 100, 200)], NOW) == (100.0, 200.0)  # tie: lower
    assert teamBall(2, [sighting(3, 900, 100, 200), sighting(4, NO_BALL_DISTANCE, -500, 300)], NOW) == (100.0, 200.0)


def test_stale_penalised_and_own_sightings_do_not_count():
    assert teamBall(2, [sighting(3, 900, 100, 200, age=MESSAGE_STALE_US + 1)], NOW) is None
    assert teamBall(2, [sighting(3, 900, 100, 200, age=MESSAGE_STALE_US)], NOW) == (100.0, 200.0)
    assert teamBall(2, [sighting(3, 900, 100, 200, penalised=True)], NOW) is None
    assert teamBall(2, [sighting(2, 900, 100, 200)], NOW) is None


def test_the_roles_stand_for_the_team_ball_as_for_their_own():
    # Striker: 200 mm behind the ball on the goal-ball line, facing the goal.
    x, y, theta = teamBallTarget(ROLE_STRIKER, 1000.0, 0.0, 0.0, THESIS)
    assert (x, y, theta) == pytest.approx((800.0, 0.0, 0.0))
    # Defender (Algorithm 4.2): ball at 0 -> 1250 behind it on the goal line, facing it.
    x, y, theta = teamBallTarget(ROLE_DEFENDER, 0.0, 600.0, 0.0, THESIS)
    assert (x, y, theta) == pytest.approx((-1250.0, 350.0, math.atan2(250.0, 1250.0)))
    # Midfielder (Algorithm 4.1): ball beyond 2000 -> (2200, 0), off the shooting path, facing the ball behind.
    x, y, theta = teamBallTarget(ROLE_MIDFIELDER, 2100.0, 0.0, 100.0, THESIS)
    assert (x, y, theta) == pytest.approx((2200.0, 500.0, math.atan2(-500.0, -100.0)))


def test_for_a_team_ball_on_a_touchline_the_striker_stands_where_go_to_ball_would():
    # Facing the goal it would stand 120 mm beyond the line, where no walk takes it; kickAim
    # turns it along the line, FIELD_EDGE_SLACK out, as GoToBall does for its own ball.
    ballX, ballY = 1000.0, FIELD_HALF_WIDTH
    x, y, theta = teamBallTarget(ROLE_STRIKER, ballX, ballY, 0.0, THESIS)
    assert (x, y, theta) == pointBehindBall(robot.AbsCoord(ballX, ballY, 0.0),
                                            *kickAim(ballX, ballY, OPPONENT_GOAL_X, OPPONENT_GOAL_Y, BEHIND_BALL_DIST),
                                            BEHIND_BALL_DIST)
    assert y == pytest.approx(FIELD_HALF_WIDTH + FIELD_EDGE_SLACK)


def test_a_lost_robot_walks_to_the_team_ball_instead_of_turning():
    # Own ball last seen on the right: alone it would turn right; the teammate sees it ahead-left.
    lost = board((0.0, 0.0, 0.0), ball=(0.0, -1000.0), seen=False, lost=SEARCH_TURN_FRAMES + 1, utime=NOW,
                 messages=[sighting(3, 600, 1000, 1000)])
    body = Search().tick(lost, ROLE_STRIKER)
    assert body.actionType == WALK and body.turn > 0.0  # turning to face the team ball's spot, then walking
    body = Search().tick(board((0.0, 0.0, 0.0), seen=False, lost=SEARCH_TURN_FRAMES + 1, utime=NOW,
                               messages=[sighting(3, 600, 2000, 0)]), ROLE_STRIKER)
    assert body.actionType == WALK and body.forward > 0.0 and body.turn == pytest.approx(0.0)
    # Not lost for long enough: the role's own skill plays.
    assert Search().tick(board(seen=False, lost=SEARCH_TURN_FRAMES, utime=NOW,
                               messages=[sighting(3, 600, 2000, 0)]), ROLE_STRIKER) is None


def test_a_robot_that_lost_the_ball_at_its_feet_steps_away_from_it_before_turning():
    # A full match had a striker stand on a ball in a corner and turn on it for 10 s: there no
    # head turn sees it. Last seen 100 mm ahead-left: it steps back-right, not turning, ...
    body = Search().tick(board((0.0, 0.0, 0.0), ball=(60.0, 80.0), seen=False, lost=SEARCH_TURN_FRAMES + 1,
                               utime=NOW, messages=[sighting(3, 600, 1000, 1000)]), ROLE_STRIKER)
    assert body.actionType == WALK and body.turn == pytest.approx(0.0)
    assert math.atan2(body.left, body.forward) == pytest.approx(math.atan2(-80.0, -60.0))
    # ... and behind it, forwards; beside a line, not over it.
    body = Search().tick(board((0.0, 0.0, 0.0), ball=(-100.0, 0.0), seen=False, lost=SEARCH_TURN_FRAMES + 1),
                         ROLE_MIDFIELDER)
    assert body.forward > 0.0 and body.left == pytest.approx(0.0, abs=1e-3) and body.turn == pytest.approx(0.0)
    body = Search().tick(board((0.0, -FIELD_HALF_WIDTH, math.pi / 2), ball=(0.0, -FIELD_HALF_WIDTH + 100.0), seen=False,
                               lost=SEARCH_TURN_FRAMES + 1), ROLE_STRIKER)
    assert body.forward == pytest.approx(0.0, abs=1e-3)
    # Once it would be BALL_AT_FEET_DIST away, the search turns as before.
    body = Search().tick(board((0.0, 0.0, 0.0), ball=(0.0, BALL_AT_FEET_DIST), seen=False,
                               lost=SEARCH_TURN_FRAMES + 1), ROLE_STRIKER)
    assert body.turn == pytest.approx(SEARCH_TURN_SPEED) and body.forward == 0.0


def test_search_spots_cycle_round_the_centre_circle_from_each_roles_own():
    assert [searchSpot(ROLE_STRIKER, k) for k in range(5)] == [(1500.0, 0.0), (0.0, 1200.0), (-1500.0, 0.0),
                                                               (0.0, -1200.0), (1500.0, 0.0)]
    assert searchSpot(ROLE_MIDFIELDER, 0) == (0.0, 1200.0)
    assert searchSpot(ROLE_DEFENDER, 0) == (-1500.0, 0.0)


def test_the_striker_turns_briefly_then_walks_to_a_search_spot():
    def body(lost, pos=(0.0, 0.0, 0.0)):
        return Search().tick(board(pos, ball=(0.0, -1000.0), seen=False, lost=SEARCH_TURN_FRAMES + lost), ROLE_STRIKER)

    assert body(1).turn == pytest.approx(-SEARCH_TURN_SPEED)  # towards the side it was last seen on
    assert body(SEARCH_TURN_LIMIT_FRAMES).turn == pytest.approx(-SEARCH_TURN_SPEED)
    assert SEARCH_TURN_LIMIT_FRAMES / 30.0 * SEARCH_TURN_SPEED < 2 * math.pi  # never a full turn on the spot
    walk = body(SEARCH_TURN_LIMIT_FRAMES + 1)  # to (1500, 0), straight ahead
    assert walk.actionType == WALK and walk.forward > 0.0 and walk.turn == pytest.approx(0.0)
    assert body(SEARCH_CYCLE_FRAMES + 1).turn == pytest.approx(-SEARCH_TURN_SPEED)  # the next cycle's turn ...
    walk = body(SEARCH_CYCLE_FRAMES + SEARCH_TURN_LIMIT_FRAMES + 1, pos=(1500.0, 0.0, 0.0))  # ... then to (0, 1200)
    # behind-left, the spot faces +x: backwards and left, faster than turning round and back
    assert walk.actionType == WALK and walk.forward < 0.0 and walk.left > 0.0 and walk.turn == pytest.approx(0.0)


def test_a_supporter_goes_home_first_then_searches_from_spot_to_spot():
    def body(lost, pos):
        return Search().tick(board(pos, ball=(0.0, 1500.0), seen=False, lost=SEARCH_TURN_FRAMES + lost),
                             ROLE_MIDFIELDER)

    assert body(1, (0.0, 0.0, 0.0)) is None  # away from home (0, 800): the thesis walks home
    assert body(1, (0.0, 800.0 - HOME_NEAR_DIST + 1.0, 0.0)).turn == pytest.approx(SEARCH_TURN_SPEED)  # home: turns
    assert body(SEARCH_TURN_LIMIT_FRAMES + 1, (0.0, 800.0, 0.0)) is None  # then the thesis stands at home
    assert body(SEARCH_CYCLE_FRAMES + 1, (0.0, 0.0, 0.0)).turn == pytest.approx(SEARCH_TURN_SPEED)  # turns anywhere
    walk = body(SEARCH_CYCLE_FRAMES + SEARCH_TURN_LIMIT_FRAMES + 1, (0.0, 800.0, 0.0))  # to its first spot (0, 1200)
    assert walk.actionType == WALK and walk.left > 0.0 and walk.turn == pytest.approx(0.0)  # sideways, facing +x


def test_the_team_searches_but_the_goalie_keeps_its_box():
    lost = dict(ball=(0.0, -1000.0), seen=False, lost=SEARCH_TURN_FRAMES + 1)
    assert Team(ROLE_STRIKER).tick(board((0.0, 0.0, 0.0), **lost)).body.turn == pytest.approx(-SEARCH_TURN_SPEED)
    command = Team().tick(board((-2700.0, 0.0, 0.0), player=1, **lost))  # the goalie at home: stands
    assert command.body.actionType == STAND


def test_a_ball_put_back_lies_on_the_throw_in_line_where_the_spl_2011_rules_put_it():
    lineY, lineEndX = FIELD_HALF_WIDTH - THROW_IN_LINE_INSET, FIELD_HALF_LENGTH - THROW_IN_LINE_END
    # Over the touchline (it lies farther beyond it than beyond the goal line), by us: towards
    # our goal (-x); by them: towards theirs; not known: where it crossed.
    assert dropInSpot(500.0, FIELD_HALF_WIDTH + 80.0, 0, 0) == (500.0 - DROP_IN_SETBACK, lineY)
    assert dropInSpot(500.0, -FIELD_HALF_WIDTH - 80.0, 1, 0) == (500.0 + DROP_IN_SETBACK, -lineY)
    assert dropInSpot(500.0, FIELD_HALF_WIDTH - 30.0, -1, 0) == (500.0, lineY)  # last seen just inside
    assert dropInSpot(500.0, FIELD_HALF_WIDTH + 80.0, 1, 1) == (500.0 - DROP_IN_SETBACK, lineY)  # team 1's "us"
    # The setback stops at the throw-in line's end.
    assert dropInSpot(FIELD_HALF_LENGTH - 200.0, FIELD_HALF_WIDTH + 300.0, 1, 0) == (lineEndX, lineY)
    # Over a goal line by its attackers (we attack +x): to the halfway line, on its side's line; ...
    assert dropInSpot(FIELD_HALF_LENGTH + 100.0, 700.0, 0, 0) == (0.0, lineY)
    assert dropInSpot(-FIELD_HALF_LENGTH - 100.0, -2100.0, 1, 0) == (0.0, -lineY)
    # ... by its defenders, or not known: to the line's end by that goal line.
    assert dropInSpot(FIELD_HALF_LENGTH + 100.0, 700.0, 1, 0) == (lineEndX, lineY)
    assert dropInSpot(-FIELD_HALF_LENGTH - 100.0, -300.0, 0, 0) == (-lineEndX, -lineY)
    assert dropInSpot(FIELD_HALF_LENGTH + 100.0, -700.0, -1, 0) == (lineEndX, -lineY)


def test_a_robot_that_did_not_see_the_ball_put_back_walks_and_looks_to_where_the_rules_put_it():
    # Last seen rolling over the left touchline at x = 500; we put it out: it lies at x = -500,
    # behind the robot, which faces where the ball left.
    pos = (300.0, 1700.0, 0.5)
    out = dict(ball=(500.0, FIELD_HALF_WIDTH + 50.0), seen=False, lost=10)
    search = Search()
    assert search.tick(board(pos, dropIn=(-1, -1), **out), ROLE_MIDFIELDER) is None  # no drop-in yet
    body = search.tick(board(pos, dropIn=(0, 0), **out), ROLE_MIDFIELDER)
    assert search.dropIn == (500.0 - DROP_IN_SETBACK, FIELD_HALF_WIDTH - THROW_IN_LINE_INSET)
    assert body.actionType == WALK and body.turn > 0.0  # turning round to it
    # It keeps the spot while the drop-in is young and the ball unseen, ...
    assert search.tick(board(pos, dropIn=(0, DROP_IN_FRESH_S - 1), **out), ROLE_MIDFIELDER) is not None
    assert search.dropIn is not None
    # ... and forgets it once it sees the ball (the role's own skill plays), or when it is old.
    assert search.tick(board(pos, dropIn=(0, 1), ball=(-500.0, FIELD_HALF_WIDTH), lost=0), ROLE_MIDFIELDER) is None
    assert search.dropIn is None
    search = Search()
    search.tick(board(pos, dropIn=(0, 0), **out), ROLE_MIDFIELDER)
    assert search.tick(board(pos, dropIn=(0, DROP_IN_FRESH_S), **out), ROLE_MIDFIELDER) is None
    assert search.dropIn is None
    # The Team looks there too: the spot is behind-left, and so is the head.
    pos = (-200.0, 1300.0, 0.6)
    head = Team(ROLE_STRIKER).tick(board(pos, dropIn=(0, 0), **out)).head
    spot = robot.toRobotRelative(robot.AbsCoord(*pos), 500.0 - DROP_IN_SETBACK, FIELD_HALF_WIDTH - THROW_IN_LINE_INSET)
    assert head.yaw == pytest.approx(spot.heading) and head.yaw > 1.5


def test_a_robot_that_sees_the_ball_put_back_or_another_drop_in_plays_on():
    # It saw the ball as it was put back: its own skill plays the real ball.
    search = Search()
    assert search.tick(board(ball=(-500.0, FIELD_HALF_WIDTH), lost=0, dropIn=(0, 0)), ROLE_STRIKER) is None
    assert search.dropIn is None
    # The same drop-in told again (dropInTime not started again) keeps the spot latched from
    # the sighting before it, wherever the ball estimate goes since.
    search = Search()
    search.tick(board(seen=False, lost=10, dropIn=(1, 3)), ROLE_STRIKER)
    assert search.dropIn is not None
    search.tick(board(seen=False, lost=10, ball=(0.0, 0.0), dropIn=(1, 3)), ROLE_STRIKER)
    assert search.dropIn is not None  # the one it latched, kept
    assert search.dropIn == dropInSpot(1000.0, 0.0, 1, 0)
