"""Rewards for the multi-agent match environment (touchline_rl.multi_agent.MatchEnv).

A reward is any callable `reward(before, after) -> sequence of floats`, one per robot in
MatchEnv.possible_agents order, given the ground truth before and after a step (MatchState).
Rewards may read the truth (the referee's score, the world's ball); observations never do.
"""
from dataclasses import dataclass

import numpy as np

PLAYING = 3  # GameState's number for PLAYING (robot_api blackboard.hpp)


@dataclass(frozen=True)
class MatchState:
    """The match's truth after a frame (all positions in the world frame: team 0 attacks +x)."""
    frame: int          # camera frames since reset
    state: int          # the referee's game state: 0 INITIAL, 1 READY, 2 SET, 3 PLAYING, 4 FINISHED, 5 STANDBY
    score: tuple        # (team 0's goals, team 1's)
    ball: tuple         # (x mm, y mm)
    robots: np.ndarray  # (n, 5): x mm, y mm, theta rad, penalised (0/1), fallen (0/1) per robot
    teams: np.ndarray   # (n,): each robot's team, 0 or 1


class GoalReward:
    """Per robot: `goal` for each goal its team scores, minus `goal` for each it concedes, plus
    `ball_progress_per_m` for every metre the ball moves towards the opponents' goal (minus
    towards its own) while the game is PLAYING. A ball the referee puts back (a jump of more
    than `max_ball_step_mm` in one frame, faster than any kick) moves nobody's reward."""

    def __init__(self, goal=1.0, ball_progress_per_m=0.01, max_ball_step_mm=500.0):
        self.goal = goal
        self.ball_progress_per_m = ball_progress_per_m
        self.max_ball_step_mm = max_ball_step_mm

    def __call__(self, before, after):
        # +1 for team 0 (attacks +x), -1 for team 1.
        sign = np.where(after.teams == 0, 1.0, -1.0)
        goals = (after.score[0] - before.score[0]) - (after.score[1] - before.score[1])
        reward = self.goal * goals * sign
        dx_mm = after.ball[0] - before.ball[0]
        dy_mm = after.ball[1] - before.ball[1]
        rolled = (dx_mm * dx_mm + dy_mm * dy_mm) <= self.max_ball_step_mm ** 2
        if before.state == PLAYING and after.state == PLAYING and rolled:
            reward = reward + self.ball_progress_per_m * 1e-3 * dx_mm * sign
        return reward
