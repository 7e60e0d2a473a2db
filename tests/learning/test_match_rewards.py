"""GoalReward: goals for and against, the ball's progress towards the opponents' goal in play,
and nothing for a ball the referee puts back."""
import numpy as np
import pytest

from touchline_rl.match_rewards import PLAYING, GoalReward, MatchState

TEAMS = np.array([0, 0, 1, 1])
ROBOTS = np.zeros((4, 5), dtype=np.float32)


def state(frame, score=(0, 0), ball=(0.0, 0.0), game_state=PLAYING):
    return MatchState(frame, game_state, score, ball, ROBOTS, TEAMS)


def test_a_goal_rewards_the_scorers_and_costs_the_conceders():
    reward = GoalReward(goal=1.0, ball_progress_per_m=0.0)
    assert list(reward(state(0), state(1, score=(0, 1)))) == [-1.0, -1.0, 1.0, 1.0]
    assert list(reward(state(0), state(1, score=(1, 0)))) == [1.0, 1.0, -1.0, -1.0]


def test_the_ball_rolling_towards_a_teams_goal_costs_it():
    reward = GoalReward(goal=1.0, ball_progress_per_m=0.5)
    # 200 mm towards +x: team 0's attack (it attacks +x), team 1's defence.
    assert reward(state(0, ball=(100.0, 0.0)), state(1, ball=(300.0, 50.0))) == pytest.approx([0.1, 0.1, -0.1, -0.1])


def test_a_ball_put_back_or_moved_outside_play_rewards_nobody():
    reward = GoalReward(goal=1.0, ball_progress_per_m=0.5)
    assert list(reward(state(0, ball=(4000.0, 0.0)), state(1, ball=(0.0, 0.0)))) == [0.0] * 4  # placement
    ready = state(1, ball=(300.0, 0.0), game_state=1)
    assert list(reward(state(0, ball=(100.0, 0.0)), ready)) == [0.0] * 4
