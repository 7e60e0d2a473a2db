"""Touchline learning: Gymnasium environments over the in-process simulator (the
`touchline_sim` extension), the thesis's tabular learners (chapter 3), a tile-coded
learner and the evaluation of go-to-pose skills.

Importing registers the environments:
  Touchline/GoToPose-v0            the thesis's 9 discrete actions
  Touchline/GoToPoseContinuous-v0  Box([-1, 1]^3) scaled to the walk's limits
"""
import gymnasium

from touchline_rl.envs import GoToPoseEnv  # noqa: F401  (re-exported)

gymnasium.register(id="Touchline/GoToPose-v0", entry_point="touchline_rl.envs:GoToPoseEnv")
gymnasium.register(id="Touchline/GoToPoseContinuous-v0", entry_point="touchline_rl.envs:GoToPoseEnv",
                   kwargs={"continuous": True})
