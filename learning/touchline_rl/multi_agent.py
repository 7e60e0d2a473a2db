"""MatchEnv: a whole refereed match as a PettingZoo ParallelEnv, on the in-process
simulator (touchline_sim.MultiRobotSim: the real world, referee, walk, kick and localisation).

Agents: "team0_p1", "team0_p2", ..., "team1_p1", ... (2 x team_size robots). One step is one
camera frame (1/30 s) for every robot at once.

Observation (per agent): a float32 vector of what the robot's own code believes, read from
its Blackboard after the frame (never the truth), in its team's frame (own goal at -x, mm,
rad): its pose, the ball, what its motion is doing, the game as its GameController adapter
sees it, its teammates' last pose messages and the robots its camera saw. Every element is
named in `observation_names` and documented in
learning/core/include/touchline/learning/observation.hpp; values are clipped to the space's
(generous) bounds.

Action (per agent): Box([-1, 1]^5) float32:
  0 forward, 1 left, 2 turn: walk velocity as fractions of the walk's limits (forward < 0 uses
    the backward limit);
  3 kick: > 0 kicks at that power (the foot on the ball's side) instead of walking;
  4 head yaw: fraction of the head's yaw limit, + left.
An agent left out of an action dict keeps its previous action.

The referee's states are the world's to enforce, as in any match: a robot in INITIAL, SET or
FINISHED, penalised, or fallen does not move whatever it asks (its observation says which).
Rewards: a pluggable callable (touchline_rl.match_rewards; default GoalReward). Episode end:
every agent terminated when the referee ends the match (FINISHED after the second half),
truncated when match.duration_s or max_cycles steps run out. reset() runs the match's first
frame with every robot standing, so the first observations are real. Deterministic by seed.
"""
import gymnasium
import numpy as np
from pettingzoo import ParallelEnv

from touchline_rl.match_rewards import GoalReward, MatchState
from touchline_rl.native import touchline_sim

# Observation bounds by unit suffix: beyond any field, kick or clock.
_BOUNDS = {"_mm": 1e5, "_mm_s": 1e5, "_rad": 2 * np.pi, "_rad_s": 100.0}
_COUNTS = {"our_score": 1000.0, "their_score": 1000.0, "secs_remaining": 1e5}


def _bounds(names):
    low, high = [], []
    for name in names:
        if name.endswith("_s") and not name.endswith(("_mm_s", "_rad_s")):
            lo, hi = 0.0, 1e5                       # ages, seconds
        elif name in _COUNTS:
            lo, hi = 0.0, _COUNTS[name]
        else:
            limit = next((v for k, v in _BOUNDS.items() if name.endswith(k)), None)
            lo, hi = (-limit, limit) if limit else (0.0, 1.0)  # no unit: a 0/1 flag
        low.append(lo)
        high.append(hi)
    return np.array(low, dtype=np.float32), np.array(high, dtype=np.float32)


class MatchEnv(ParallelEnv):
    metadata = {"name": "touchline_match_v0", "render_modes": [], "is_parallelizable": True}

    def __init__(self, team_size=2, world_config="", overrides=(), walk_config="", kick_config="",
                 perfect_localisation=False, reward=None, max_cycles=None, render_mode=None):
        """world_config, overrides ('section.key=value'), walk_config, kick_config: as the
        single-robot env's; team_size overrides match.team_size. reward: a callable (see
        touchline_rl.match_rewards), default GoalReward(). max_cycles: truncate after this many
        steps (None: only match.duration_s)."""
        overrides = [f"match.team_size={team_size}", *overrides]
        self.sim = touchline_sim.MultiRobotSim(world_config=world_config, overrides=overrides,
                                               walk_config=walk_config, kick_config=kick_config,
                                               perfect_localisation=perfect_localisation)
        self.robots = list(self.sim.robots)
        self.possible_agents = [f"team{t}_p{p}" for t, p in self.robots]
        self.agents = []
        self.observation_names = list(self.sim.observation_names)
        self._index = {agent: i for i, agent in enumerate(self.possible_agents)}
        self._teams = np.array([t for t, _ in self.robots])
        limits = self.sim.walk_limits
        self._scale_forward = (limits["max_forward_mm_s"], limits["max_backward_mm_s"])
        self._scale = np.array([1.0, limits["max_left_mm_s"], limits["max_turn_rad_s"], 1.0,
                                limits["max_head_yaw_rad"]], dtype=np.float32)
        self._low, self._high = _bounds(self.observation_names)
        self._observation_spaces = {a: gymnasium.spaces.Box(self._low, self._high, dtype=np.float32)
                                    for a in self.possible_agents}
        self._action_spaces = {a: gymnasium.spaces.Box(-1.0, 1.0, shape=(5,), dtype=np.float32)
                               for a in self.possible_agents}
        self.reward = reward if reward is not None else GoalReward()
        self.max_cycles = max_cycles
        self.render_mode = render_mode
        self._actions = np.zeros((len(self.robots), 5), dtype=np.float32)
        self._rng = np.random.default_rng()
        self._steps = 0
        self._state = None

    # The same space object every call, one per agent (PettingZoo seeds them one by one); kept
    # on the env, not in a class-wide lru_cache that would keep every env ever made alive.
    def observation_space(self, agent):
        return self._observation_spaces[agent]

    def action_space(self, agent):
        return self._action_spaces[agent]

    def reset(self, seed=None, options=None):
        """A new match seeded with `seed` (None: drawn from the previous seed's stream)."""
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        self.sim.reset(int(self._rng.integers(2**63)))
        self.agents = list(self.possible_agents)
        self._actions[:] = 0.0
        self._steps = 0
        self._state = self._match_state()
        return self._observations(), {agent: {} for agent in self.agents}

    def commands(self, actions):
        """The robot API requests, (n, 5): forward mm/s, left mm/s, turn rad/s, kick power, head
        yaw rad, for actions (n, 5) in [-1, 1] (clipped there first)."""
        # The ufuncs, not np.clip: on a few rows its wrapper costs more than the simulator's step.
        a = np.minimum(np.maximum(np.asarray(actions, dtype=np.float32).reshape(-1, 5), -1.0), 1.0) * self._scale
        a[:, 0] *= np.where(a[:, 0] >= 0, self._scale_forward[0], self._scale_forward[1])
        np.maximum(a[:, 3], 0.0, out=a[:, 3])
        return a

    def step(self, actions):
        given = [agent for agent in actions if agent in self._index]
        if given:
            rows = [self._index[agent] for agent in given]
            self._actions[rows] = self.commands([actions[agent] for agent in given])
        self.sim.step(self._actions)
        self._steps += 1
        before, self._state = self._state, self._match_state()
        rewards = np.asarray(self.reward(before, self._state), dtype=np.float64)
        observations = self._observations()
        ended = self.sim.game_over
        cut = not ended and (self.sim.out_of_time or (self.max_cycles is not None and self._steps >= self.max_cycles))
        live = self.agents
        rewards = {agent: float(rewards[self._index[agent]]) for agent in live}
        terminations = {agent: ended for agent in live}
        truncations = {agent: cut for agent in live}
        infos = {agent: {} for agent in live}
        observations = {agent: observations[agent] for agent in live}
        if ended or cut:
            self.agents = []
        return observations, rewards, terminations, truncations, infos

    @property
    def match_state(self):
        """The truth after the last step (MatchState)."""
        return self._state

    def state_hash(self):
        return self.sim.state_hash()

    def close(self):
        pass

    def _observations(self):
        obs = np.minimum(np.maximum(self.sim.observations(), self._low), self._high)
        return {agent: obs[i] for i, agent in enumerate(self.possible_agents)}

    def _match_state(self):
        game = self.sim.game
        ball, robots = self.sim.truth()
        return MatchState(self.sim.frame, game["state"], tuple(game["score"]), tuple(ball), robots, self._teams)
