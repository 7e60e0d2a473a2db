"""The team behaviour: thesis Algorithms 4.1 and 4.2, the goal box, the shooting path, the
goalie, the striker, team messages and roles, game states; the same hand-worked cases as
tests/behaviour_cpp/skills/test_team.cpp."""
import pytest
import robot
from boards import board, message, seenRobot

from skills.field import clampOutOfOwnBox
from skills.goalie import Goalie, goalieTarget
from skills.line_up_and_kick import CARRY_SPEED, carrySpeed
from skills.striker import Striker
from skills.supporter import THESIS, Defender, Midfielder, defenderTarget, midfielderTarget, supporterTarget
from skills.search import SEARCH_CYCLE_FRAMES, SEARCH_TURN_FRAMES, SEARCH_TURN_LIMIT_FRAMES, SEARCH_TURN_SPEED
from skills.team import Team, readyPosition
from skills.team_comm import (MESSAGE_STALE_US, NO_BALL_DISTANCE, ROLE_DEFENDER, ROLE_GOALIE, ROLE_MIDFIELDER,
                              ROLE_STRIKER, TeamInfo, assignRole, decodeMessage, encodeMessage, makeTeamInfo)

WALK = robot.ActionType.WALK
STAND = robot.ActionType.STAND
GS = robot.GameState


# Algorithm 4.1: the midfielder's position from the ball's x (thesis numbers).
def test_midfielder_ball_beyond_2000_goes_to_2200_0():
    assert midfielderTarget(2500.0, 300.0, 500.0, THESIS) == pytest.approx((2200.0, 0.0))
    assert supporterTarget(2200.0, 0.0, 2500.0, 300.0, 500.0) == pytest.approx((2200.0, 0.0))  # behind the ball


def test_midfielder_ball_between_1200_and_2000_stands_1200_beside_it():
    assert midfielderTarget(1500.0, 200.0, -500.0, THESIS) == pytest.approx((1500.0, -1000.0))
    assert midfielderTarget(1500.0, 200.0, 800.0, THESIS) == pytest.approx((1500.0, 1400.0))


def test_midfielder_ball_on_own_goal_line_is_2500_in_front_of_it():
    assert midfielderTarget(-3000.0, 0.0, 1000.0, THESIS) == pytest.approx((-500.0, 1000.0))
    assert midfielderTarget(1200.0 - 4200.0 / 2, 0.0, 1000.0, THESIS) == pytest.approx((-900.0 + 1250.0, 1000.0))


# Algorithm 4.2: the defender's position from the ball's x (thesis numbers), y blocking the
# ball-own-goal line.
def test_defender_ball_below_minus_800_goes_to_minus_1800_0():
    assert defenderTarget(-1000.0, 400.0, THESIS) == pytest.approx((-1800.0, 0.0))


def test_defender_ball_at_0_is_1250_behind_it_on_the_goal_line():
    assert defenderTarget(0.0, 600.0, THESIS) == pytest.approx((-1250.0, 350.0))


def test_defender_ball_beyond_1250_stops_at_minus_1200():
    assert defenderTarget(1500.0, -900.0, THESIS) == pytest.approx((-1200.0, -360.0))


def test_goal_box_clamp():
    assert clampOutOfOwnBox(-2700.0, 300.0) == pytest.approx((-2200.0, 300.0))
    assert clampOutOfOwnBox(-2300.0, -1200.0) == pytest.approx((-2200.0, -1200.0))
    assert clampOutOfOwnBox(-2700.0, 1400.0) == pytest.approx((-2700.0, 1400.0))
    assert clampOutOfOwnBox(-2000.0, 0.0) == pytest.approx((-2000.0, 0.0))
    assert supporterTarget(-2900.0, 1000.0, -2950.0, -1500.0, 1000.0) == pytest.approx((-2200.0, 1000.0))


def test_shooting_path_avoidance_in_front_of_the_ball():
    # Midfielder at its far spot with the ball straight behind it: sideways to its own side.
    assert supporterTarget(2200.0, 0.0, 2100.0, 0.0, 100.0) == pytest.approx((2200.0, 500.0))
    assert supporterTarget(2200.0, 0.0, 2100.0, 0.0, -100.0) == pytest.approx((2200.0, -500.0))
    # Defender in front of a deep ball: off the line from (-2500, 100) to (3000, 0).
    assert supporterTarget(-1800.0, 0.0, -2500.0, 100.0, -300.0) == pytest.approx((-1800.0, -412.7273), abs=1e-3)
    # Already clear of the line, or behind the ball: unchanged.
    assert supporterTarget(-500.0, 1000.0, -3000.0, 0.0, 1000.0) == pytest.approx((-500.0, 1000.0))
    assert supporterTarget(-1250.0, 0.0, 0.0, 0.0, 0.0) == pytest.approx((-1250.0, 0.0))


def test_supporters_face_the_ball_and_go_home_when_it_is_lost():
    # Defender at its target, facing the ball: stands.
    assert Defender(THESIS).tick(board((-1250.0, 0.0, 0.0), ball=(0.0, 0.0))).body.actionType == STAND
    # Ball lost for long: the midfielder walks home to (0, 800), to its left: sideways, as it ends facing +x.
    command = Midfielder().tick(board((0.0, 0.0, 0.0), ball=(1000.0, 0.0), seen=False, lost=91))
    assert command.body.actionType == WALK and (command.body.left, command.body.turn) == pytest.approx((200.0, 0.0))
    assert Midfielder().tick(board((0.0, 800.0, 0.0), seen=False, lost=91)).body.actionType == STAND


# Goalie
def test_goalie_target_on_the_goal_ball_line():
    assert goalieTarget(0.0, 0.0) == pytest.approx((-2600.0, 0.0))
    assert goalieTarget(-2000.0, 1000.0) == pytest.approx((-2717.157, 282.843), abs=1e-3)
    assert goalieTarget(-2990.0, 1900.0) == pytest.approx((-2900.0, 399.9945), abs=1e-3)


def test_goalie_stays_in_its_box():
    for ballX in range(-3000, 3001, 500):
        for ballY in range(-2000, 2001, 500):
            x, y = goalieTarget(float(ballX), float(ballY))
            assert -3000.0 <= x <= -2400.0 and abs(y) <= 1100.0, (ballX, ballY)


def test_goalie_guards_then_clears_a_ball_near_its_box():
    goalie = Goalie()
    assert goalie.tick(board((-2600.0, 0.0, 0.0), ball=(1000.0, 0.0))).body.actionType == STAND
    assert not goalie.clearing
    goalie.tick(board((-2600.0, 0.0, 0.0), ball=(-2200.0, 0.0)))
    assert goalie.clearing
    goalie.tick(board((-2600.0, 0.0, 0.0), ball=(-1900.0, 0.0)))  # still within the leave margin
    assert goalie.clearing
    goalie.tick(board((-2600.0, 0.0, 0.0), ball=(-1700.0, 0.0)))
    assert not goalie.clearing
    command = Goalie().tick(board((-2600.0, 0.0, 0.0), ball=(-2470.0, 50.0)))  # lined up: carry it out
    assert (command.body.actionType, command.body.forward) == (WALK, CARRY_SPEED)


# Striker
def test_striker_carries_the_ball_past_a_robot_ahead_too_and_into_the_goal():
    body = Striker().tick(board((0.0, 0.0, 0.0), ball=(130.0, 50.0))).body
    assert (body.actionType, body.forward) == (WALK, CARRY_SPEED)
    ahead = board((0.0, 0.0, 0.0), ball=(130.0, 50.0), robots=[seenRobot(550.0, 150.0)])
    body = Striker().tick(ahead).body
    assert (body.actionType, body.forward) == (WALK, CARRY_SPEED)
    body = Striker().tick(board((2300.0, 0.0, 0.0), ball=(2430.0, 50.0))).body  # 570 mm from the goal's centre
    assert (body.actionType, body.forward) == (WALK, CARRY_SPEED)


# Team messages: the same bytes as the C++ port for the same inputs.
VECTOR_1 = bytes([0x02, 0x03, 0x02, 0x01, 0xD3, 0x04, 0x24, 0xFA, 0xD1, 0x07, 0x2E, 0xFB, 0x38, 0x02])
VECTOR_2 = bytes([0x02, 0x07, 0x03, 0x06, 0xFF, 0xFF, 0xFF, 0x7F, 0x00, 0x80, 0xFF, 0x7F, 0x00, 0x80])


def test_message_test_vectors():
    info = makeTeamInfo(3, ROLE_STRIKER, True, False, False, 1234.75, -1500.25, 2000.5, -1234.5, 567.5)
    assert encodeMessage(info) == VECTOR_1
    assert decodeMessage(VECTOR_1) == TeamInfo(3, ROLE_STRIKER, True, False, False, 1235, -1500, 2001, -1234, 568)
    info = makeTeamInfo(7, ROLE_DEFENDER, False, True, True, 999.0, 40000.0, -40000.0, 50000.0, -50000.0)
    assert encodeMessage(info) == VECTOR_2
    assert decodeMessage(VECTOR_2) == TeamInfo(7, ROLE_DEFENDER, False, True, True, NO_BALL_DISTANCE, 32767, -32768,
                                               32767, -32768)


def test_message_round_trip_and_rejects():
    info = TeamInfo(4, ROLE_MIDFIELDER, True, False, True, 65534, -32768, 12, 2999, -1999)
    assert decodeMessage(encodeMessage(info)) == info
    assert decodeMessage(VECTOR_1[:13]) is None
    assert decodeMessage(bytes([1]) + VECTOR_1[1:]) is None  # the version before robot poses


# Role assignment
NOW = 10_000_000


def msg(number, distance, role=ROLE_DEFENDER, penalised=False, age=0):
    info = TeamInfo(number, role, distance != NO_BALL_DISTANCE, penalised, False, distance, 0, 0)
    return message(number, encodeMessage(info), NOW - age)


def test_closest_field_player_is_striker_others_by_number():
    messages = [msg(1, 0, ROLE_GOALIE), msg(3, 800), msg(4, 1500)]
    assert assignRole(2, 1200, ROLE_DEFENDER, messages, NOW) == ROLE_DEFENDER
    assert assignRole(4, 1500, ROLE_DEFENDER, [msg(2, 1200), msg(3, 800)], NOW) == ROLE_MIDFIELDER
    assert assignRole(3, 800, ROLE_DEFENDER, [msg(2, 1200), msg(4, 1500)], NOW) == ROLE_STRIKER
    assert assignRole(2, 500, ROLE_DEFENDER, messages, NOW) == ROLE_STRIKER


def test_goalie_is_fixed_and_never_striker():
    assert assignRole(1, 0, ROLE_GOALIE, [msg(2, 3000)], NOW) == ROLE_GOALIE
    assert assignRole(2, 3000, ROLE_DEFENDER, [msg(1, 0, ROLE_GOALIE)], NOW) == ROLE_STRIKER


def test_penalised_and_stale_messages_are_ignored():
    assert assignRole(2, 1200, ROLE_DEFENDER, [msg(3, 800, penalised=True), msg(4, 1500)], NOW) == ROLE_STRIKER
    assert assignRole(2, 1200, ROLE_DEFENDER, [msg(3, 800, age=MESSAGE_STALE_US + 1)], NOW) == ROLE_STRIKER
    assert assignRole(2, 1200, ROLE_DEFENDER, [msg(3, 800, age=MESSAGE_STALE_US)], NOW) == ROLE_DEFENDER
    assert assignRole(2, 1200, ROLE_DEFENDER, [message(3, VECTOR_1[:9], NOW)], NOW) == ROLE_STRIKER


def test_ties_go_to_the_lower_number_and_strikers_keep_a_margin():
    assert assignRole(2, 1000, ROLE_DEFENDER, [msg(3, 1000)], NOW) == ROLE_STRIKER
    assert assignRole(3, 1000, ROLE_DEFENDER, [msg(2, 1000)], NOW) == ROLE_DEFENDER
    assert assignRole(2, 1000, ROLE_DEFENDER, [msg(3, 1200, ROLE_STRIKER)], NOW) == ROLE_DEFENDER
    assert assignRole(2, 1000, ROLE_DEFENDER, [msg(3, 1400, ROLE_STRIKER)], NOW) == ROLE_STRIKER
    assert assignRole(3, NO_BALL_DISTANCE, ROLE_DEFENDER, [msg(2, NO_BALL_DISTANCE)], NOW) == ROLE_DEFENDER


# The Team: game states, messages, roles
def test_ready_walks_to_the_formation():
    assert readyPosition(1) == pytest.approx((-2700.0, 0.0))
    assert readyPosition(2) == pytest.approx((-700.0, 0.0))
    assert readyPosition(2, kickingOff=True) == pytest.approx((-150.0, -50.0))  # inside the circle at the ball
    assert readyPosition(3, kickingOff=True) == pytest.approx((-1800.0, -600.0))
    assert readyPosition(3) == pytest.approx((-1800.0, -600.0))
    assert readyPosition(4) == pytest.approx((-1200.0, 900.0))
    assert readyPosition(5) == pytest.approx((-1800.0, 600.0))
    command = Team().tick(board((-2000.0, 0.0, 0.0), state=GS.READY, player=2, kickOffTeam=1))
    assert (command.body.actionType, command.body.forward, command.body.turn) == (WALK, pytest.approx(300.0), 0.0)



def test_the_kicker_of_a_kick_off_plays_the_ball_as_play_begins():
    # At its kick-off spot, the ball on the centre mark: it walks the ball on at once (the
    # opponents are outside the circle), where the striker of the other team walks to the ball.
    kicker = Team().tick(board((-150.0, -50.0, 0.0), ball=(0.0, 0.0), player=2, kickOffTeam=0))
    assert (kicker.body.actionType, kicker.body.forward) == (WALK, pytest.approx(carrySpeed(150.0)))  # the ball 150 mm ahead
    command = Team().tick(board((-150.0, -50.0, 0.0), state=GS.READY, player=2, kickOffTeam=0))
    assert command.body.actionType == STAND  # arrived: it stays there
    command = Team().tick(board((-150.0, -50.0, 0.0), state=GS.READY, player=2, kickOffTeam=1))
    assert command.body.actionType == WALK  # the other team kicks off: out of the circle

@pytest.mark.parametrize("state", [GS.INITIAL, GS.SET, GS.FINISHED])
def test_initial_set_finished_stand_with_the_head_on_the_ball(state):
    command = Team().tick(board((0.0, 0.0, 0.0), ball=(1000.0, 500.0), state=state))
    assert command.body.actionType == STAND
    assert command.head.yaw == pytest.approx(0.463648, abs=1e-5)


def test_penalised_and_fallen_stand():
    team = Team()
    command = team.tick(board((0.0, 0.0, 0.0), ball=(130.0, 50.0), penalised=True))
    assert command.body.actionType == STAND
    assert decodeMessage(command.teamMessage).penalised
    command = Team().tick(board((0.0, 0.0, 0.0), ball=(130.0, 50.0), fallen=True))
    assert command.body.actionType == STAND


def test_sends_a_message_every_sixth_frame():
    team = Team()
    sent = [len(team.tick(board((0.0, 0.0, 0.0), ball=(1000.0, 0.0), player=3)).teamMessage) for _ in range(13)]
    assert sent == [14, 0, 0, 0, 0, 0, 14, 0, 0, 0, 0, 0, 14]


def test_playing_takes_the_assigned_role():
    team = Team()
    command = team.tick(board((100.0, -200.0, 0.0), ball=(230.0, -150.0), player=3))  # alone: striker, carries
    assert team.role == ROLE_STRIKER and (command.body.actionType, command.body.forward) == (WALK, CARRY_SPEED)
    assert decodeMessage(command.teamMessage) == TeamInfo(3, ROLE_STRIKER, True, False, False, 139, 230, -150, 100,
                                                          -200)
    team = Team()
    team.tick(board((0.0, 0.0, 0.0), ball=(1000.0, 0.0), player=3, messages=[msg(2, 300)]))
    assert team.role == ROLE_DEFENDER
    team = Team()
    team.tick(board((-2600.0, 0.0, 0.0), ball=(1000.0, 0.0), player=1))
    assert team.role == ROLE_GOALIE


def test_a_lost_ball_makes_the_striker_turn_to_search():
    team = Team(ROLE_STRIKER)
    command = team.tick(board((0.0, 0.0, 0.0), ball=(0.0, -1000.0), seen=False, lost=SEARCH_TURN_FRAMES + 1))
    assert command.body.actionType == WALK and command.body.turn == pytest.approx(-SEARCH_TURN_SPEED)
    command = team.tick(board((0.0, 0.0, 0.0), ball=(0.0, -1000.0), seen=False, lost=SEARCH_TURN_FRAMES))
    assert command.body.actionType == STAND  # not yet: LineUpAndKick stands while the ball is lost
    after_turn = SEARCH_TURN_FRAMES + SEARCH_TURN_LIMIT_FRAMES + 1
    command = team.tick(board((0.0, 0.0, 0.0), ball=(0.0, -1000.0), seen=False, lost=after_turn))
    assert command.body.forward > 0.0 and command.body.turn == 0.0  # under a full turn, then off to a search spot
    command = team.tick(board((0.0, 0.0, 0.0), ball=(0.0, -1000.0), seen=False,
                              lost=SEARCH_TURN_FRAMES + SEARCH_CYCLE_FRAMES + 1))
    assert command.body.turn == pytest.approx(-SEARCH_TURN_SPEED)  # the next search turn


def test_a_supporter_turns_to_search_only_at_home():
    team = Team(ROLE_DEFENDER)
    command = team.tick(board((0.0, 0.0, 0.0), ball=(0.0, 1000.0), seen=False, lost=SEARCH_TURN_FRAMES + 1))
    assert (command.body.forward, command.body.turn) == pytest.approx((-200.0, 0.0))  # home (-1800, 0): backwards
    command = team.tick(board((-1800.0, 100.0, 0.0), ball=(0.0, 1000.0), seen=False, lost=SEARCH_TURN_FRAMES + 1))
    assert command.body.turn == pytest.approx(SEARCH_TURN_SPEED)
