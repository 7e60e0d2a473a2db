"""The supporters' numbers (SupporterDef): the tuned defender against the thesis's
Algorithm 4.2, and the skill parameter supporters=tuned|thesis that picks them; the same
hand-worked cases as tests/behaviour_cpp/skills/test_supporter.cpp. (Algorithms 4.1 and 4.2
with the thesis's numbers: test_team.py.)"""
import math

import pytest
import robot
from boards import board, message

import behaviour
from skills.search import teamBallTarget
from skills.supporter import SUPPORTER_DEFS, THESIS, TUNED, Defender, SupporterDef, defenderTarget, midfielderTarget
from skills.team_comm import ROLE_DEFENDER, ROLE_STRIKER, encodeMessage, makeTeamInfo

STAND = robot.ActionType.STAND
WALK = robot.ActionType.WALK


def test_the_tuned_defender_stands_closer_behind_the_ball():
    # Ball at 0: 900 behind it (the thesis: 1250), y on the ball-own-goal line.
    assert defenderTarget(0.0, 600.0, TUNED) == pytest.approx((-900.0, 420.0))
    assert defenderTarget(0.0, 600.0, THESIS) == pytest.approx((-1250.0, 350.0))
    # Ball beyond 900: it stops at the -500 line (the thesis: beyond 1250, at -1200).
    assert defenderTarget(1500.0, -900.0, TUNED) == pytest.approx((-500.0, -500.0))
    assert defenderTarget(1500.0, -900.0, THESIS) == pytest.approx((-1200.0, -360.0))
    # Ball deep in the own half: the same fixed spot as the thesis's.
    assert defenderTarget(-1000.0, 400.0, TUNED) == pytest.approx((-1800.0, 0.0))


def test_the_tuned_midfielder_is_the_thesis_midfielder():
    for ball in ((2500.0, 300.0), (1500.0, 200.0), (-3000.0, 0.0), (0.0, -700.0)):
        assert midfielderTarget(*ball, 500.0, TUNED) == midfielderTarget(*ball, 500.0, THESIS)


def test_a_lost_defender_walks_to_its_presets_target_for_the_team_ball():
    x, y, theta = teamBallTarget(ROLE_DEFENDER, 0.0, 600.0, 0.0, TUNED)
    assert (x, y, theta) == pytest.approx((-900.0, 420.0, math.atan2(180.0, 900.0)))


def test_a_defender_stands_only_at_its_own_presets_target():
    thesisSpot = board((-1250.0, 350.0, math.atan2(250.0, 1250.0)), ball=(0.0, 600.0))
    tunedSpot = board((-900.0, 420.0, math.atan2(180.0, 900.0)), ball=(0.0, 600.0))
    assert Defender(THESIS).tick(thesisSpot).body.actionType == STAND
    assert Defender(TUNED).tick(tunedSpot).body.actionType == STAND
    walk = Defender(TUNED).tick(thesisSpot).body
    assert walk.actionType == WALK and walk.forward > 0.0  # 350 mm further up
    assert Defender(THESIS).tick(tunedSpot).body.actionType == WALK


@pytest.mark.parametrize("skill", ["Team", "Defender"])
def test_the_supporters_parameter_picks_the_numbers(skill):
    # Player 3, with player 2 nearer the ball: Team makes it the defender, as Defender is.
    nearer = message(2, encodeMessage(makeTeamInfo(2, ROLE_STRIKER, True, False, False, 100, 0, 600, -100, 600)))
    thesisSpot = board((-1250.0, 350.0, math.atan2(250.0, 1250.0)), ball=(0.0, 600.0), player=3, messages=[nearer])
    assert behaviour.makeBehaviour({"skill": skill, "supporters": "thesis"}).tick(thesisSpot).body.actionType == STAND
    assert behaviour.makeBehaviour({"skill": skill}).tick(thesisSpot).body.actionType == WALK  # tuned: the default


def test_the_default_is_tuned_and_both_are_named():
    assert list(SUPPORTER_DEFS) == ["tuned", "thesis"]
    assert SUPPORTER_DEFS["tuned"] is TUNED and SUPPORTER_DEFS["thesis"] is THESIS


@pytest.mark.parametrize("params, message", [
    ({"skill": "Team", "supporters": "best"}, "Team: parameter supporters must be tuned or thesis (got 'best')"),
    ({"skill": "Midfielder", "supporters": ""}, "Midfielder: parameter supporters must be tuned or thesis (got '')"),
    ({"skill": "GoToBall", "supporters": "thesis"}, "GoToBall: unknown parameter 'supporters'"),
])
def test_a_bad_supporters_parameter_is_one_line(params, message):
    with pytest.raises(behaviour.BehaviourError) as error:
        behaviour.makeBehaviour(params)
    assert str(error.value) == message


def test_a_misspelt_field_is_an_error():
    with pytest.raises(TypeError, match="defMaxY"):
        SupporterDef(defMaxY=0.0)
