"""The trained policy committed at config/policies/go_to_pose.policy, deployed: the C++
LearnedGoToPose and GoToBall walker=learned behaviours reading it walk where they should.
A regression guard for the file (retrained policies must still pass)."""
import math
import pathlib

import pytest

from touchline_rl.evaluation import behaviour_runner, evaluate, fixed_starts
from touchline_rl.native import touchline_sim
from touchline_rl.policy_file import read_policy

POLICY = pathlib.Path(__file__).resolve().parents[2] / "config" / "policies" / "go_to_pose.policy"


def test_the_policy_file_reads():
    q, distance_mm, heading_rad = read_policy(POLICY)
    assert (distance_mm, round(math.degrees(heading_rad))) == (50.0, 10)
    assert len(q.actions) > 1


def test_the_deployed_skill_reaches_poses_across_the_field():
    sim = touchline_sim.SingleRobotSim()
    starts = fixed_starts(30, sim.field, seed=99)  # not the evaluation's starts
    run = behaviour_runner(sim, "LearnedGoToPose", 50.0, math.radians(10), 1200)
    summary, _ = evaluate(run, starts, sim.walk_limits)
    assert summary["success_rate"] >= 0.9


@pytest.mark.parametrize("heading, ball", [(0.0, (1500.0, 800.0)), (math.pi, (-1000.0, -500.0))])
def test_go_to_ball_with_the_learned_walker_gets_behind_the_ball(heading, ball):
    sim = touchline_sim.SingleRobotSim()
    sim.reset(1, (0.0, 0.0, heading), ball=ball, behaviour="GoToBall", params={"walker": "learned"})
    for _ in range(30 * 20):
        sim.step_behaviour()
    x, y, _ = sim.pose
    assert math.hypot(sim.ball[0] - x, sim.ball[1] - y) < 400  # behind the ball, near it
