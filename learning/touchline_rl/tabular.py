"""The thesis's learners (chapter 3): one-step Q-learning (eq. 3.1), Q-learning with the
eligibility trace of Algorithm 3.1, and uniform case-based Q-learning with that trace.

A learner sees states through `encode`-ed keys: an int for a table, or (case indices,
case weights) for the case-based learner. `learn(state, action, reward, next_state)` is
called once per transition (thesis.py: one walk step); next_state None means the episode
terminated there (its value is 0). Call `end_episode()` between episodes so a trace never
links two episodes. Tables are lists of lists: scalar indexing into them is several times
faster than into numpy arrays, and the trace replay is a strictly sequential loop.
"""
import random
from collections import deque


class QLearner:
    """One-step Q-learning (eq. 3.1) over int states, epsilon-greedy with random ties.

    initial_q 0 is optimistic when every reward is negative: untried actions look best,
    which is what explores."""

    def __init__(self, n_states, n_actions, alpha, gamma=1.0, epsilon=0.1, initial_q=0.0, seed=None):
        if not 0.0 < alpha <= 1.0 or not 0.0 <= gamma <= 1.0 or not 0.0 <= epsilon <= 1.0:
            raise ValueError(f"need 0 < alpha <= 1, 0 <= gamma <= 1, 0 <= epsilon <= 1 "
                             f"(got {alpha}, {gamma}, {epsilon})")
        self.n_actions = n_actions
        self.alpha, self.gamma, self.epsilon = alpha, gamma, epsilon
        self.q = [[float(initial_q)] * n_actions for _ in range(n_states)]
        self.rng = random.Random(seed)

    def values(self, state):
        return self.q[state]

    def act(self, state, greedy=False):
        if not greedy and self.rng.random() < self.epsilon:
            return self.rng.randrange(self.n_actions)
        values = self.values(state)
        best = max(values)
        ties = [a for a, v in enumerate(values) if v == best]
        return ties[0] if len(ties) == 1 else self.rng.choice(ties)

    def greedy_value(self, state):
        """max over actions of Q(state, .); 0 for the terminal state (None)."""
        return 0.0 if state is None else max(self.values(state))

    def _backup(self, state, action, reward, next_state):
        """Q(s, a) += alpha * (r + gamma * max_a' Q(s', a') - Q(s, a))."""
        row = self.q[state]
        row[action] += self.alpha * (reward + self.gamma * self.greedy_value(next_state) - row[action])

    def learn(self, state, action, reward, next_state):
        self._backup(state, action, reward, next_state)

    def end_episode(self):
        pass


class TraceQLearner(QLearner):
    """Algorithm 3.1: after the one-step update, keep the last `trace_length` (state,
    action, reward) triples and replay them backwards, newest first, each against the
    max over its successor's actions (the successor's Q just updated by the replay).
    The printed first line's Q[prevState] is Q[prevState + action], as the loop's pState
    shows. The newest triple is not replayed: the first line has just updated it."""

    def __init__(self, *args, trace_length=20, **kwargs):
        super().__init__(*args, **kwargs)
        self.trace = deque(maxlen=trace_length)  # (state, action, reward), oldest first

    def learn(self, state, action, reward, next_state):
        self._backup(state, action, reward, next_state)
        self.trace.append((state, action, reward))
        trace = self.trace
        for i in range(len(trace) - 2, -1, -1):
            s, a, r = trace[i]
            self._backup(s, a, r, trace[i + 1][0])

    def end_episode(self):
        self.trace.clear()


class CaseBasedTraceQLearner(TraceQLearner):
    """Uniform case-based Q-learning [SSR96] with Algorithm 3.1's trace. A state is
    (case indices, weights) from UniformCases; Q(s, a) = sum_k w_k q[k][a], and an
    update's error goes to each case by its weight: q[k][a] += alpha * w_k * error."""

    def values(self, state):
        indices, weights = state
        q = self.q
        total = [0.0] * self.n_actions
        for k, w in zip(indices, weights):
            total = [t + w * v for t, v in zip(total, q[k])]
        return total

    def _backup(self, state, action, reward, next_state):
        indices, weights = state
        q = self.q
        current = sum(w * q[k][action] for k, w in zip(indices, weights))
        step = self.alpha * (reward + self.gamma * self.greedy_value(next_state) - current)
        for k, w in zip(indices, weights):
            q[k][action] += step * w
