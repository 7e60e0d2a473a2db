"""The `robot` module's game controller view: every state and set play under the
GameController's own numbers, and an empty board's defaults."""
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
    try:
        gc.setPlayTeam = 1
    except AttributeError:
        return
    raise AssertionError("gameController.setPlayTeam is writable")
