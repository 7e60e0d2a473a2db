"""The `robot` module's game controller view: every state and set play under the
GameController's own numbers, and an empty board's defaults."""
import math

import robot


def test_game_states_have_the_gamecontrollers_numbers_standby_included():
    states = {s.name: int(s) for s in robot.GameState.__members__.values()}
    assert states == {"INITIAL": 0, "READY": 1, "SET": 2, "PLAYING": 3, "FINISHED": 4, "STANDBY": 5}


def test_set_plays_have_the_gamecontrollers_numbers():
    set_plays = {s.name: int(s) for s in robot.SetPlay.__members__.values()}
    assert set_plays == {"NONE": 0, "GOAL_KICK": 1, "PUSHING_FREE_KICK": 2, "CORNER_KICK": 3, "KICK_IN": 4,
                         "PENALTY_KICK": 5}


def test_an_empty_board_has_no_set_play_and_its_fields_are_read_only():
    gc = robot.Blackboard().gameController
    assert gc.setPlay == robot.SetPlay.NONE and gc.setPlayTeam == -1
    assert gc.firstHalf is True and gc.kickOffTeam == 0  # the C++ Blackboard's defaults, as it has them
    assert gc.dropInTeam == -1 and gc.dropInTime == -1  # no ball put back yet
    try:
        gc.setPlayTeam = 1
    except AttributeError:
        return
    raise AssertionError("gameController.setPlayTeam is writable")


def test_enums_compare_by_type_and_value_only():
    state = robot.Blackboard().gameController.state
    assert state == robot.GameState.INITIAL and not state != robot.GameState.INITIAL
    assert state != robot.GameState.READY and not state == robot.GameState.READY
    assert state != 0 and not state == 0  # no int is a game state
    assert robot.SetPlay.NONE != robot.GameState.INITIAL  # nor is another enum's value of the same number
    assert {robot.GameState.INITIAL: "initial"}[state] == "initial"


def test_an_empty_boards_parts_are_read_only_and_nested_values_are_copies():
    board = robot.Blackboard()
    for part, field in (("motion", "fallen"), ("localisation", "ballLostCount"), ("vision", "ballSeen"),
                        ("receiver", "messages"), ("behaviour", "skill")):
        try:
            setattr(getattr(board, part), field, None)
        except AttributeError:
            continue
        raise AssertionError(part + "." + field + " is writable")
    pos = board.localisation.robotPos
    pos.x = 5.0
    assert board.localisation.robotPos.x == 0.0
    assert board.receiver.messages == [] and board.behaviour.skill == ""
    covariance = board.localisation.robotPosCovariance  # the pose's 3x3, row-major, a copy
    assert covariance == [0.0] * 9
    covariance[0] = 1.0
    assert board.localisation.robotPosCovariance[0] == 0.0


def test_requests_are_built_field_by_field_and_take_no_constructor_arguments():
    body = robot.Body()
    body.forward = 120  # an int converts as to a C float
    body.actionType = robot.ActionType.WALK
    request = robot.All()
    request.body = body
    request.body.turn = 0.5  # a reference into the request, as pybind11's def_readwrite gives
    assert (request.body.forward, request.body.turn, request.body.actionType) == (120.0, 0.5, robot.ActionType.WALK)
    for bad in (lambda: setattr(body, "forward", "fast"), lambda: setattr(body, "actionType", 2),
                lambda: robot.Body(1), lambda: setattr(robot.LED(), "chest", 1.5)):
        try:
            bad()
        except TypeError:
            continue
        raise AssertionError("accepted a wrong value")


def test_geometry_reads_and_converts_as_pybind11_did():
    pos = robot.AbsCoord(100.0, -50.0, 0.5)
    fast = robot.toRobotRelative(pos, 1000.0, 700)  # floats and ints: the C fast path
    slow = robot.toRobotRelative(robot=pos, x=1000.0, y=700.0)  # keywords: pybind11's function
    assert (fast.distance, fast.heading) == (slow.distance, slow.heading)
    assert abs(fast.distance - math.hypot(900.0, 750.0)) < 1e-3
    assert abs(fast.heading - (math.atan2(750.0, 900.0) - 0.5)) < 1e-6
    assert (fast.x(), fast.y()) == (slow.x(), slow.y())
    assert abs(fast.x() - 900.0 * math.cos(0.5) - 750.0 * math.sin(0.5)) < 1e-2
    pos.theta = 1  # fields write as C floats, ints included
    assert (pos.x, pos.y, pos.theta) == (100.0, -50.0, 1.0)
    for bad in (lambda: robot.toRobotRelative(pos, "1", 2.0), lambda: robot.toRobotRelative((0, 0, 0), 1.0, 2.0),
                lambda: robot.toRobotRelative(pos, 1.0), lambda: robot.RRCoord.x(pos),
                lambda: setattr(pos, "x", "far"), lambda: robot.toRobotRelative(pos, 10 ** 400, 1.0)):
        try:
            bad()
        except TypeError:
            continue
        raise AssertionError("accepted a wrong argument")
