"""MatchEnv: PettingZoo's own API and seed tests, and what a multi-agent learner relies on,
on the real in-process match."""
import warnings

import numpy as np
import pytest
from pettingzoo.test import parallel_api_test, parallel_seed_test

from touchline_rl.multi_agent import MatchEnv

# A short match: INITIAL 0.2 s, READY 2 s, SET 1 s, two 5 s halves: about 500 frames.
SHORT = ["rules.initial_s=0.2", "rules.ready_s=2", "rules.set_s=1", "rules.half_s=5"]


def short_env(**kwargs):
    return MatchEnv(team_size=2, overrides=SHORT, **kwargs)


def names(env):
    return {name: i for i, name in enumerate(env.observation_names)}


def test_passes_pettingzoos_parallel_api_test_to_the_end_of_a_match():
    env = short_env()
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the test's warnings (a live agent given nothing, ...) fail it
        parallel_api_test(env, num_cycles=2000)
    assert env.agents == [] and env.sim.game_over  # the match ended inside the cycles


def test_passes_pettingzoos_parallel_seed_test():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        parallel_seed_test(short_env)


def test_one_agent_per_robot_with_its_spaces():
    env = MatchEnv(team_size=3)
    assert env.possible_agents == ["team0_p1", "team0_p2", "team0_p3", "team1_p1", "team1_p2", "team1_p3"]
    observations, infos = env.reset(seed=1)
    assert set(observations) == set(infos) == set(env.possible_agents)
    for agent in env.possible_agents:
        assert env.observation_space(agent).shape == (len(env.observation_names),)
        assert env.observation_space(agent).contains(observations[agent])
        assert env.action_space(agent).shape == (5,)


def test_observations_are_each_robots_own_belief_in_its_teams_frame():
    env = short_env(perfect_localisation=True)  # beliefs equal to the truth, to compare
    observations, _ = env.reset(seed=2)
    at = names(env)
    robots = env.match_state.robots
    for i, agent in enumerate(env.possible_agents):
        sign = 1.0 if agent.startswith("team0") else -1.0  # team 1's frame is the world turned half round
        assert observations[agent][at["self_x_mm"]] == pytest.approx(sign * robots[i, 0], abs=1.0)
        assert observations[agent][at["self_y_mm"]] == pytest.approx(sign * robots[i, 1], abs=1.0)
        assert observations[agent][at["state_initial"]] == 1.0


def test_actions_scale_to_the_walks_limits():
    env = short_env()
    limits = env.sim.walk_limits
    commands = env.commands([[1, -1, 0.5, -0.3, 1], [-1, 0, 0, 0.7, -2]])
    assert commands[0] == pytest.approx([limits["max_forward_mm_s"], -limits["max_left_mm_s"],
                                         0.5 * limits["max_turn_rad_s"], 0.0, limits["max_head_yaw_rad"]])
    assert commands[1] == pytest.approx([-limits["max_backward_mm_s"], 0, 0, 0.7, -limits["max_head_yaw_rad"]])


def test_walking_moves_a_robot_in_ready_and_standing_in_set_does_not():
    env = short_env(perfect_localisation=True)
    env.reset(seed=3)
    at = names(env)
    walk = {agent: np.array([1, 0, 0, -1, 0], dtype=np.float32) for agent in env.agents}
    moved = {1: 0.0, 2: 0.0}  # READY, SET
    while env.agents and env.match_state.state != 3:
        before = env.match_state
        observations, *_ = env.step(walk)
        after = env.match_state
        if before.state == after.state and after.state in moved:
            moved[after.state] += float(np.abs(after.robots[:, :2] - before.robots[:, :2]).sum())
        # The robots sensed the game at the start of the step: the state before it.
        state_flag = ["state_initial", "state_ready", "state_set", "state_playing"][before.state]
        assert all(observations[a][at[state_flag]] == 1.0 for a in observations)
    assert moved[1] > 1000.0 and moved[2] == 0.0


def test_the_same_seed_plays_the_same_match_and_another_seed_another():
    def play(seed):
        env = short_env()
        observations, _ = env.reset(seed=seed)
        at = names(env)
        trace = []
        while env.agents:
            # Turn towards the ball each believes in: what the cameras saw steers the match.
            actions = {a: np.array([1, 0, np.clip(o[at["ball_rel_y_mm"]] / 1000, -1, 1), -1, 0], dtype=np.float32)
                       for a, o in observations.items()}
            observations, rewards, *_ = env.step(actions)
            trace.append((env.state_hash(), tuple(rewards.values())))
        return trace

    first = play(11)
    assert play(11) == first
    assert play(12) != first


def test_the_match_ends_terminated_and_max_cycles_truncates():
    env = short_env()
    env.reset(seed=4)
    stand = {agent: np.zeros(5, dtype=np.float32) for agent in env.agents}
    steps = 0
    while env.agents:
        _, _, terminations, truncations, _ = env.step(stand)
        steps += 1
    assert all(terminations.values()) and not any(truncations.values())
    assert env.match_state.state == 4  # FINISHED

    env = short_env(max_cycles=50)
    env.reset(seed=4)
    for step in range(50):
        _, _, terminations, truncations, _ = env.step(stand)
    assert env.agents == [] and all(truncations.values()) and not any(terminations.values())


def test_the_reward_is_pluggable():
    seen = []

    def reward(before, after):
        seen.append((before.frame, after.frame))
        return after.teams * 2.0 - 1.0  # -1 for team 0, +1 for team 1

    env = short_env(reward=reward)
    env.reset(seed=5)
    _, rewards, *_ = env.step({})
    assert seen == [(0, 1)]
    assert rewards == {"team0_p1": -1.0, "team0_p2": -1.0, "team1_p1": 1.0, "team1_p2": 1.0}


def test_bad_config_is_one_clear_value_error():
    with pytest.raises(ValueError, match="team_size"):
        MatchEnv(team_size=0)
