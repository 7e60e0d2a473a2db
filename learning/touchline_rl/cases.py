"""Uniform cases for case-based Q-learning [SSR96]: each case is a point of an evenly
spaced grid over the state space, not an interval. A continuous state is represented by
the 2^d cases at the corners of the grid cell around it, weighted by multilinear
interpolation (a normalised tent kernel): the weights are positive, sum to 1, and a state
on a case point has that case alone, with weight 1.
"""
import itertools
import math


class UniformCases:
    def __init__(self, lows, highs, counts, periodic=None):
        """Per dimension: cases at lows[i] + j * spacing, j = 0 .. counts[i]-1. An open
        dimension's cases span [low, high] end to end (spacing (high-low)/(count-1)); a
        periodic one wraps, high == low (spacing (high-low)/count), e.g. a heading."""
        periodic = tuple(periodic or (False,) * len(lows))
        if not len(lows) == len(highs) == len(counts) == len(periodic):
            raise ValueError("lows, highs, counts and periodic need one entry per dimension")
        if any(c < 2 for c in counts) or any(h <= lo for lo, h in zip(lows, highs)):
            raise ValueError("each dimension needs high > low and at least 2 cases")
        self.lows, self.counts, self.periodic = tuple(lows), tuple(counts), periodic
        self.spacings = tuple((h - lo) / (c if p else c - 1) for lo, h, c, p in zip(lows, highs, counts, periodic))
        self.n_cases = math.prod(counts)
        self._corners = tuple(itertools.product((0, 1), repeat=len(counts)))

    def point(self, index):
        """The state at case `index` (row-major, last dimension fastest)."""
        coords = []
        for count, low, spacing in zip(reversed(self.counts), reversed(self.lows), reversed(self.spacings)):
            index, j = divmod(index, count)
            coords.append(low + j * spacing)
        return tuple(reversed(coords))

    def encode(self, state):
        """(case indices, weights) of the cases around `state`; open dimensions clamp."""
        cells, fractions = [], []
        for x, low, spacing, count, periodic in zip(state, self.lows, self.spacings, self.counts, self.periodic):
            u = (x - low) / spacing
            if abs(u - round(u)) < 1e-9:  # on a case, up to rounding: that case alone
                u = float(round(u))
            if periodic:
                j = math.floor(u)
                cells.append(j % count)
                fractions.append(u - j)
            else:
                u = min(max(u, 0.0), count - 1.0)
                j = min(int(u), count - 2)
                cells.append(j)
                fractions.append(u - j)
        indices, weights = [], []
        for corner in self._corners:
            index, weight = 0, 1.0
            for j, f, up, count in zip(cells, fractions, corner, self.counts):
                index = index * count + (j + up) % count
                weight *= f if up else 1.0 - f
            if weight > 0.0:  # a state on a case plane skips the zero-weight corners
                indices.append(index)
                weights.append(weight)
        return tuple(indices), tuple(weights)
