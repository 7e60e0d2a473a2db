"""LearnedGoToPose and the skills that walk to the ball with it (GoToBall, LineUpAndKick,
Striker, Team with a policy); the same cases as
tests/behaviour_cpp/skills/test_learned_go_to_pose.cpp. The worked states are those of
test_tile_policy.py, with the test policy of policy_files.py."""
import math

import pytest
import robot
from boards import board
from policy_files import dataDir, writePolicy  # noqa: F401 (dataDir: a fixture)

import behaviour
from skills.go_to_ball import GoToBall
from skills.learned_go_to_pose import LearnedGoToPose, relativeTarget
from skills.line_up_and_kick import LineUpAndKick
from skills.striker import Striker
from skills.team import Team
from skills.team_comm import ROLE_STRIKER

POLICY = "policies/go_to_pose.policy"
WALK = robot.ActionType.WALK
STAND = robot.ActionType.STAND
FORWARD = (300.0, 0.0, 0.0)
LEFT = (0.0, 0.0, 1.0)
RIGHT = (0.0, 0.0, -1.0)


def body(command):
    return command.body.actionType, (command.body.forward, command.body.left, command.body.turn)


def test_relative_target_turns_the_field_into_the_robot_frame():
    x, y, theta = relativeTarget(robot.AbsCoord(0.0, 0.0, math.pi / 2), -500.0, 1000.0, math.pi / 2 + 0.5)
    assert (x, y, theta) == pytest.approx((1000.0, 500.0, 0.5), abs=1e-4)
    x, y, theta = relativeTarget(robot.AbsCoord(1000.0, 1000.0, math.pi), 0.0, 1000.0, 0.0)
    assert (x, y) == pytest.approx((1000.0, 0.0), abs=1e-4)
    assert theta == pytest.approx(-math.pi)  # not wrapped: the policy wraps it


def test_walks_with_the_greedy_action(dataDir):
    assert body(LearnedGoToPose(1000.0, 500.0, 0.5).tick(board((0.0, 0.0, 0.0)))) == (WALK, FORWARD)
    assert body(LearnedGoToPose(-200.0, 800.0, 0.0).tick(board((0.0, 0.0, 0.0)))) == (WALK, LEFT)
    assert body(LearnedGoToPose(-300.0, -600.0, 0.0).tick(board((0.0, 0.0, 0.0)))) == (WALK, RIGHT)


def test_target_in_the_team_frame(dataDir):
    # Facing +y, the target 1000 mm ahead and 500 mm left is the worked state (1000, 500, 0.5).
    skill = LearnedGoToPose(-500.0, 1000.0, math.pi / 2 + 0.5)
    assert body(skill.tick(board((0.0, 0.0, math.pi / 2)))) == (WALK, FORWARD)
    skill.setTarget(-800.0, -200.0, math.pi / 2)  # (-200, 800) seen from the robot: turn left
    assert body(skill.tick(board((0.0, 0.0, math.pi / 2)))) == (WALK, LEFT)


def test_stands_inside_the_success_tolerances(dataDir):
    assert body(LearnedGoToPose(1030.0, -20.0, 0.1).tick(board((1000.0, 0.0, 0.0))))[0] == STAND
    assert body(LearnedGoToPose(1030.0, -20.0, 0.2).tick(board((1000.0, 0.0, 0.0))))[0] == WALK


def test_the_policy_file_is_read_once(dataDir):
    assert LearnedGoToPose().policy is LearnedGoToPose(100.0, 0.0, 0.0).policy


def test_policy_path_is_relative_to_the_data_directory(dataDir):
    writePolicy(dataDir / "other" / "short.policy", "touchline-policy 1\n")
    with pytest.raises(ValueError) as error:
        LearnedGoToPose(policy="other/short.policy")
    assert str(error.value) == str(dataDir / "other" / "short.policy") + ": missing 'features'"


def test_a_missing_policy_is_named_at_construction(dataDir):
    with pytest.raises(ValueError) as error:
        LearnedGoToPose(policy="policies/none.policy")
    assert str(error.value) == str(dataDir / "policies" / "none.policy") + (
        ": cannot read the policy (No such file or directory)")


def test_go_to_ball_walks_behind_the_ball_with_the_policy(dataDir):
    skill = GoToBall(policy=POLICY)
    # Behind the ball (1000, 0) facing the goal is (800, 0, 0).
    assert body(skill.tick(board((0.0, 0.0, 0.0), ball=(1000.0, 0.0)))) == (WALK, FORWARD)
    assert body(skill.tick(board((1100.0, 600.0, 0.0), ball=(1000.0, 0.0)))) == (WALK, RIGHT)  # (-300, -600)
    assert body(skill.tick(board((800.0, 0.0, 0.0), ball=(1000.0, 0.0))))[0] == STAND
    assert body(GoToBall().tick(board((1100.0, 600.0, 0.0), ball=(1000.0, 0.0)))) != (WALK, RIGHT)  # hand walker


def test_line_up_and_kick_striker_and_team_approach_with_the_policy(dataDir):
    blackboard = board((1100.0, 600.0, 0.0), ball=(1000.0, 0.0))
    assert body(LineUpAndKick(policy=POLICY).tick(blackboard)) == (WALK, RIGHT)
    assert body(Striker(POLICY).tick(blackboard)) == (WALK, RIGHT)
    assert body(Team(ROLE_STRIKER, POLICY).tick(blackboard)) == (WALK, RIGHT)


def test_behaviour_params_pick_the_learned_walker(dataDir):
    blackboard = board((1100.0, 600.0, 0.0), ball=(1000.0, 0.0))
    for skill in ("GoToBall", "LineUpAndKick", "Striker", "Team"):
        command = behaviour.makeBehaviour({"skill": skill, "walker": "learned"}).tick(blackboard)
        assert body(command) == (WALK, RIGHT), skill
        command = behaviour.makeBehaviour({"skill": skill, "walker": "learned", "policy": POLICY}).tick(blackboard)
        assert body(command) == (WALK, RIGHT), skill
    command = behaviour.makeBehaviour({"skill": "LearnedGoToPose", "x": "-200", "y": "800"}).tick(board())
    assert body(command) == (WALK, LEFT)


@pytest.mark.parametrize("params, message", [
    ({"skill": "GoToBall", "walker": "neural"}, "GoToBall: parameter walker must be hand or learned (got 'neural')"),
    ({"skill": "Team", "policy": POLICY}, "Team: parameter policy needs walker=learned"),
    ({"skill": "LearnedGoToPose", "walker": "learned"}, "LearnedGoToPose: unknown parameter 'walker'"),
    ({"skill": "LearnedGoToPose", "x": "1m"}, "LearnedGoToPose: parameter x must be a number (got '1m')"),
])
def test_bad_walker_parameters_are_rejected(dataDir, params, message):
    with pytest.raises(behaviour.BehaviourError) as error:
        behaviour.makeBehaviour(params)
    assert str(error.value) == message
