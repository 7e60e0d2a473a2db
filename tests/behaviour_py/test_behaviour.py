"""behaviour.py: skills picked and parameterised by robot.params, composed with the head
skill and LEDs; the same cases as tests/behaviour_cpp/skills/test_skill_behaviour.cpp."""
import pytest
import robot
from boards import board

from policy_files import dataDir  # noqa: F401 (a fixture)

import behaviour
from skills.ball import BALL_LOST_FRAMES
from skills.head_scan import SCAN_PITCH, SCAN_YAW_STEP


@pytest.fixture(autouse=True)
def fresh_behaviour(monkeypatch):
    monkeypatch.delattr(robot, "params", raising=False)
    behaviour.reset()
    yield
    behaviour.reset()


def use_params(monkeypatch, **params):
    monkeypatch.setattr(robot, "params", params, raising=False)


def test_default_is_go_to_ball_with_the_head_on_the_ball():
    command = behaviour.tick(board((0.0, 0.0, 0.0), ball=(1000.0, 0.0)))
    assert isinstance(command, robot.All)
    assert command.body.actionType == robot.ActionType.WALK
    assert command.body.forward == pytest.approx(300.0)
    assert command.head.yaw == pytest.approx(0.0)
    assert command.head.pitch == pytest.approx(0.313333, abs=1e-5)
    assert command.leds.chest == behaviour.BALL_SEEN_CHEST


def test_lost_ball_stands_scans_and_shows_red():
    command = behaviour.tick(board((0.0, 0.0, 0.0), ball=(1000.0, 500.0), seen=False, lost=BALL_LOST_FRAMES + 1))
    assert command.body.actionType == robot.ActionType.STAND
    assert (command.head.yaw, command.head.pitch) == pytest.approx((SCAN_YAW_STEP, SCAN_PITCH))
    assert command.leds.chest == behaviour.BALL_LOST_CHEST


def test_keeps_one_skill_instance_across_ticks(monkeypatch):
    use_params(monkeypatch, skill="HeadScan")
    blackboard = board((0.0, 0.0, 0.0), ball=(1000.0, 500.0))
    yaws = [behaviour.tick(blackboard).head.yaw for _ in range(3)]
    assert yaws == pytest.approx([SCAN_YAW_STEP, 2 * SCAN_YAW_STEP, 3 * SCAN_YAW_STEP])
    assert behaviour.tick(blackboard).body.actionType == robot.ActionType.STAND


def test_go_to_pose_takes_its_parameters(monkeypatch):
    use_params(monkeypatch, skill="GoToPose", x="-2000", y="-100", theta="0")
    command = behaviour.tick(board((0.0, 0.0, 0.0)))
    assert (command.body.forward, command.body.turn) == pytest.approx((-200.0, 0.0))  # behind, ending facing +x
    use_params(monkeypatch, skill="GoToPose", x="0", y="0", face_ball="1")  # new params: a new skill
    command = behaviour.tick(board((0.0, 0.0, 0.0), ball=(0.0, 1000.0)))
    assert command.body.turn == pytest.approx(1.5)


def test_line_up_and_kick_and_track_ball_by_name(monkeypatch):
    use_params(monkeypatch, skill="LineUpAndKick", dribble="1")
    assert behaviour.tick(board((0.0, 0.0, 0.0), ball=(130.0, -50.0))).body.actionType == robot.ActionType.DRIBBLE
    use_params(monkeypatch, skill="TrackBall")
    command = behaviour.tick(board((0.0, 0.0, 0.0), ball=(1000.0, 0.0), seen=False, lost=100))
    assert command.body.actionType == robot.ActionType.STAND
    assert command.head.pitch == pytest.approx(0.313333, abs=1e-5)  # tracks even when lost


def test_every_skill_is_made_with_its_defaults(dataDir):
    for name in behaviour.SKILL_NAMES:
        assert behaviour.makeBehaviour({"skill": name}).tick(board()) is not None
    assert set(behaviour.SKILL_NAMES) == set(behaviour.SKILLS)


def test_unknown_skill_lists_the_known_ones():
    with pytest.raises(behaviour.BehaviourError) as error:
        behaviour.makeBehaviour({"skill": "Striker9000"})
    assert str(error.value) == ("unknown skill 'Striker9000' (known: GoToPose, LearnedGoToPose, GoToBall, LineUpAndKick, "
                                "TrackBall, HeadScan, Team, Goalie, Striker, Midfielder, Defender)")


@pytest.mark.parametrize("params", [
    {"skill": "GoToPose", "x": "12abc"},
    {"skill": "GoToPose", "z": "1"},
    {"skill": "GoToBall", "goal_x": ""},
    {"skill": "GoToBall", "goal_x": "nan"},
    {"skill": "LineUpAndKick", "power": "1 "},
    {"skill": "TrackBall", "x": "1"},
])
def test_bad_parameters_are_rejected(params):
    with pytest.raises(behaviour.BehaviourError):
        behaviour.makeBehaviour(params)
    with pytest.raises(behaviour.BehaviourError):  # the shim's check before the match says the same
        behaviour.check_params(params)


def test_check_params_passes_what_the_skills_take(dataDir):
    behaviour.check_params({"skill": "Team", "supporters": "thesis", "walker": "learned"})
    behaviour.check_params({})  # the default skill
