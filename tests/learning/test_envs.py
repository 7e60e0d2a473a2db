"""GoToPoseEnv: what a learner relies on, on the real in-process simulator."""
import math
import warnings

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import touchline_rl
from touchline_rl.actions import THESIS_ACTIONS_PER_STEP, scale_continuous, thesis_actions
from touchline_rl.envs import GoToPoseEnv
from touchline_rl.geometry import lower_bound_s, relative_target

IDS = ["Touchline/GoToPose-v0", "Touchline/GoToPoseContinuous-v0"]


@pytest.mark.parametrize("env_id", IDS)
def test_registered_and_env_checker_clean(env_id):
    env = gym.make(env_id)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a checker warning fails the test
        check_env(env.unwrapped, skip_render_check=True)


@pytest.mark.parametrize("env_id", IDS)
def test_seeded_resets_reproduce_the_episode(env_id):
    def episode(seed):
        env = gym.make(env_id)
        env.action_space.seed(seed)
        observations = [env.reset(seed=seed)[0]]
        for _ in range(60):
            observations.append(env.step(env.action_space.sample())[0])
        return np.array(observations)

    np.testing.assert_array_equal(episode(5), episode(5))
    assert not np.array_equal(episode(5)[0], episode(6)[0])


def test_observation_is_the_target_in_the_robot_frame():
    env = GoToPoseEnv()
    obs, info = env.reset(seed=0, options={"start": (0, 0, math.pi / 2), "target": (0, 1000, math.pi)})
    np.testing.assert_allclose(obs, [1000, 0, math.pi / 2], atol=1e-3)  # straight ahead, then turn left
    assert info["pose"] == pytest.approx((0, 0, math.pi / 2), abs=1e-3)


def test_reaching_the_pose_terminates():
    env = GoToPoseEnv()
    env.reset(seed=0, options={"start": (0, 0, 0), "target": (20, 0, 0.05)})
    _, reward, terminated, truncated, _ = env.step(2)  # the thesis's action 2: stand
    assert (reward, terminated, truncated) == (-1.0, True, False)


def test_the_heading_counts_unless_switched_off():
    env = GoToPoseEnv()
    env.reset(seed=0, options={"start": (0, 0, 0), "target": (20, 0, 1.0)})
    assert env.step(2)[2] is False
    env = GoToPoseEnv(success_heading_rad=None)
    env.reset(seed=0, options={"start": (0, 0, 0), "target": (20, 0, 1.0)})
    assert env.step(2)[2] is True


def test_time_limit_is_truncation_not_termination():
    env = GoToPoseEnv(max_steps=10)
    env.reset(seed=0, options={"start": (0, 0, 0), "target": (2000, 0, 0)})
    results = [env.step(2) for _ in range(10)]
    assert [r[3] for r in results] == [False] * 9 + [True]
    assert not any(r[2] for r in results)


def test_leaving_the_bounds_terminates_with_the_penalty():
    env = GoToPoseEnv(bounds=(0, 1000, 0, 1000), out_of_bounds_reward=-50.0)
    env.reset(seed=0, options={"start": (20, 500, math.pi), "target": (1000, 1000, 0)})
    for _ in range(60):
        obs, reward, terminated, truncated, info = env.step(4)  # full speed ahead: out of x >= 0
        if terminated:
            break
    assert terminated and reward == -50.0 and info["pose"][0] < 0


def test_continuous_actions_reach_the_walk_limits():
    env = GoToPoseEnv(continuous=True)
    env.reset(seed=0, options={"start": (0, 0, 0), "target": (3000, 0, 0)})
    for _ in range(60):
        env.step(np.array([1, 0, 0], dtype=np.float32))
    assert env.sim.walk_velocity[0] == pytest.approx(env.limits["max_forward_mm_s"])
    for _ in range(60):
        env.step(np.array([-1, 0, -1], dtype=np.float32))
    assert env.sim.walk_velocity[0] == pytest.approx(-env.limits["max_backward_mm_s"])
    assert env.sim.walk_velocity[2] == pytest.approx(-env.limits["max_turn_rad_s"])


def test_thesis_actions_convert_per_step_units():
    commands = thesis_actions(step_s=0.25)
    assert len(commands) == len(THESIS_ACTIONS_PER_STEP) == 9
    assert commands[4] == (320.0, 0.0, 0.0)
    assert commands[6] == (0.0, 160.0, 0.0)
    assert commands[8][2] == pytest.approx(math.radians(30) * 4)


def test_scale_continuous_clips_and_uses_each_limit():
    limits = {"max_forward_mm_s": 300, "max_backward_mm_s": 200, "max_left_mm_s": 200, "max_turn_rad_s": 1.5}
    assert scale_continuous((2, -0.5, 0.5), limits) == (300, -100, 0.75)
    assert scale_continuous((-0.5, 0, -3), limits) == (-100, 0, -1.5)


def test_geometry():
    assert relative_target((100, 0, math.pi), (0, 0, 0)) == pytest.approx((100, 0, -math.pi), abs=1e-9)
    limits = {"max_forward_mm_s": 300, "max_turn_rad_s": 1.5}
    assert lower_bound_s((0, 0, 0), (300, 400, 1.5), limits) == pytest.approx(math.hypot(500 / 300, 1.0))


def test_bad_config_is_a_value_error():
    with pytest.raises(ValueError, match="nope.ini"):
        GoToPoseEnv(world_config="/nope.ini")
