"""TilePolicy: a learned go-to-pose policy read from a policy file (format v1,
docs/learning/policy_format.md): a tile-coded Q-function over the robot-relative target
and a table of walk actions, acted on greedily.

All arithmetic is in double and written in the order the format gives, as the C++ port
(behaviour_cpp/.../skills/tile_policy.hpp) does, so both pick the same action every frame.
"""
import math

POLICY_MAGIC = "touchline-policy"   # first word of a policy file ...
POLICY_VERSION = 1                  # ... and the format version after it
DEFAULT_POLICY = "policies/go_to_pose.policy"  # the trained policy, relative to the data directory
FEATURES_POLAR_LOG = "polar-log"    # the one feature kind of version 1
U_TILING_OFFSET = 1                 # tiling k is offset by k * this / tilings of a tile along u ...
B_TILING_OFFSET = 3                 # ... along the bearing ...
H_TILING_OFFSET = 5                 # ... and along the heading error
MAX_POLICY_WEIGHTS = 10000000       # more is not a policy this reader should hold in memory

_numberChars = frozenset("0123456789+-.eE")
_countKeys = ("tilings", "actions")
_realKeys = ("distance_scale_mm", "max_distance_mm", "success_distance_mm", "success_heading_rad")
_keys = ("features", "tiles") + _countKeys + _realKeys


def wrapAngle(angle):
    """angle in [-pi, pi), in double (the format's h)."""
    wrapped = math.fmod(angle + math.pi, 2.0 * math.pi)
    if wrapped < 0.0:
        wrapped += 2.0 * math.pi
    return wrapped - math.pi


class PolicyError(ValueError):
    """A bad policy file; the message is one line naming the file."""


def _real(name, token, what):
    """A decimal number, as the C++ reader accepts it (no nan, inf, hex or '_')."""
    value = math.nan
    if token and set(token) <= _numberChars:
        try:
            value = float(token)
        except ValueError:
            pass
    if not math.isfinite(value):
        raise PolicyError("%s: %s: '%s' is not a number" % (name, what, token))
    return value


def _weights(name, tokens):
    """The weights as numbers: all at once (a trained policy has 10^5 of them), then one by
    one to name a bad one."""
    if set("".join(tokens)) <= _numberChars:
        try:
            weights = [float(token) for token in tokens]
            if all(map(math.isfinite, weights)):
                return weights
        except ValueError:
            pass
    return [_real(name, token, "weight %d" % index) for index, token in enumerate(tokens)]


def _count(name, token, what):
    """A whole number >= 1 of at most 9 digits."""
    if not (token.isdigit() and token.isascii() and len(token) <= 9 and int(token) >= 1):
        raise PolicyError("%s: %s: '%s' is not a whole number >= 1" % (name, what, token))
    return int(token)


class TilePolicy:
    """A parsed policy: tilings, tiles (Tu, Tb, Th), actions [(forward, left, turn)], weights."""

    def __init__(self, name, fields, actions, weights):
        self.name = name
        self.distanceScale = fields["distance_scale_mm"]
        self.maxDistance = fields["max_distance_mm"]
        self.tilings = fields["tilings"]
        self.tilesU, self.tilesB, self.tilesH = fields["tiles"]
        self.successDistance = fields["success_distance_mm"]
        self.successHeading = fields["success_heading_rad"]
        self.actions = actions
        self.weights = weights
        self.uMax = math.log(1.0 + self.maxDistance / self.distanceScale)

    def cellIndices(self, x, y, theta):
        """Per tiling k, the weight index of action 0: (((k (Tu+1) + iu) Tb + ib) Th + ih) A."""
        d = math.sqrt(x * x + y * y)
        u = min(math.log(1.0 + d / self.distanceScale), self.uMax)
        b = 0.0 if (x == 0.0 and y == 0.0) else math.atan2(y, x)
        h = wrapAngle(theta)
        su = (u / self.uMax) * self.tilesU
        sb = ((b + math.pi) / (2.0 * math.pi)) * self.tilesB
        sh = ((h + math.pi) / (2.0 * math.pi)) * self.tilesH
        indices = []
        for k in range(self.tilings):
            iu = min(max(math.floor(su + (k * U_TILING_OFFSET) / self.tilings), 0), self.tilesU)
            ib = math.floor(sb + (k * B_TILING_OFFSET) / self.tilings) % self.tilesB
            ih = math.floor(sh + (k * H_TILING_OFFSET) / self.tilings) % self.tilesH
            cell = ((k * (self.tilesU + 1) + iu) * self.tilesB + ib) * self.tilesH + ih
            indices.append(cell * len(self.actions))
        return indices

    def values(self, x, y, theta):
        """Q(s, a) for every action a, summed over the tilings in order."""
        q = [0.0] * len(self.actions)
        for base in self.cellIndices(x, y, theta):
            for a in range(len(q)):
                q[a] += self.weights[base + a]
        return q

    def greedyAction(self, x, y, theta):
        """argmax_a Q(s, a), ties to the lowest index."""
        q = self.values(x, y, theta)
        best = 0
        for a in range(1, len(q)):
            if q[a] > q[best]:
                best = a
        return best

    def arrived(self, x, y, theta):
        """Within the success tolerances: the skill stands."""
        return math.sqrt(x * x + y * y) < self.successDistance and abs(wrapAngle(theta)) < self.successHeading


def parsePolicy(text, name):
    """The TilePolicy in `text`; name (the file) prefixes every error. Raises PolicyError."""
    lines = text.split("\n")
    first = lines[0].split() if lines else []
    if len(first) != 2 or first[0] != POLICY_MAGIC:
        raise PolicyError("%s: not a policy file (the first line must be '%s %d')" % (name, POLICY_MAGIC, POLICY_VERSION))
    if first[1] != str(POLICY_VERSION):
        raise PolicyError("%s: policy format version '%s' is not supported (this reader knows %d)"
                          % (name, first[1], POLICY_VERSION))
    fields = {}
    actions = []
    weightsLine = None
    for number, line in enumerate(lines[1:], start=2):
        words = line.split()
        if not words or words[0].startswith("#"):
            continue
        key, values = words[0], words[1:]
        where = "line %d (%s)" % (number, key)
        if key == "weights":
            if len(values) != 1:
                raise PolicyError("%s: %s: expected one count" % (name, where))
            fields["weights"] = _count(name, values[0], where)
            weightsLine = number
            break
        if key == "action":
            if len(values) != 3:
                raise PolicyError("%s: %s: expected forward, left, turn" % (name, where))
            actions.append(tuple(_real(name, v, where) for v in values))
            continue
        if key not in _keys:
            raise PolicyError("%s: %s: unknown key '%s'" % (name, where, key))
        if key in fields:
            raise PolicyError("%s: %s: '%s' given twice" % (name, where, key))
        expected = 3 if key == "tiles" else 1
        if len(values) != expected:
            raise PolicyError("%s: %s: expected %d value%s" % (name, where, expected, "s" if expected > 1 else ""))
        if key == "features":
            if values[0] != FEATURES_POLAR_LOG:
                raise PolicyError("%s: %s: unknown feature kind '%s' (known: %s)"
                                  % (name, where, values[0], FEATURES_POLAR_LOG))
            fields[key] = values[0]
        elif key == "tiles":
            fields[key] = tuple(_count(name, v, where) for v in values)
        elif key in _countKeys:
            fields[key] = _count(name, values[0], where)
        else:
            fields[key] = _real(name, values[0], where)
    for key in _keys + ("weights",):
        if key not in fields:
            raise PolicyError("%s: missing '%s'" % (name, key))
    for key in ("distance_scale_mm", "max_distance_mm"):
        if not fields[key] > 0.0:
            raise PolicyError("%s: '%s' must be > 0 (got %.9g)" % (name, key, fields[key]))
    for key in ("success_distance_mm", "success_heading_rad"):
        if not fields[key] >= 0.0:
            raise PolicyError("%s: '%s' must be >= 0 (got %.9g)" % (name, key, fields[key]))
    if len(actions) != fields["actions"]:
        raise PolicyError("%s: %d 'action' lines, but 'actions' says %d" % (name, len(actions), fields["actions"]))
    tilesU, tilesB, tilesH = fields["tiles"]
    expected = fields["tilings"] * (tilesU + 1) * tilesB * tilesH * fields["actions"]
    if expected > MAX_POLICY_WEIGHTS:
        raise PolicyError("%s: %d weights is more than %d" % (name, expected, MAX_POLICY_WEIGHTS))
    if fields["weights"] != expected:
        raise PolicyError("%s: 'weights' says %d, but %d tilings x %d x %d x %d cells x %d actions need %d"
                          % (name, fields["weights"], fields["tilings"], tilesU + 1, tilesB, tilesH,
                             fields["actions"], expected))
    tokens = " ".join(lines[weightsLine:]).split()
    if len(tokens) != expected:
        raise PolicyError("%s: %d weights after 'weights', expected %d" % (name, len(tokens), expected))
    return TilePolicy(name, fields, actions, _weights(name, tokens))


def policyText(distanceScale, maxDistance, tilings, tiles, successDistance, successHeading, actions, weights,
               comments=()):
    """The text of a policy file (format v1) holding these fields, actions [(forward, left,
    turn)] and weights (in the format's order), with `comments` as '#' lines after the
    magic line: the one writer of the format (training, tools/synthetic_policy.py and the
    tests write through it; the robots only read). Numbers as %.9g: a float32 weight
    reads back to the same float32."""
    lines = ["%s %d" % (POLICY_MAGIC, POLICY_VERSION)]
    lines += ["# %s" % comment for comment in comments]
    lines += ["features %s" % FEATURES_POLAR_LOG, "distance_scale_mm %.9g" % distanceScale,
              "max_distance_mm %.9g" % maxDistance, "tilings %d" % tilings, "tiles %d %d %d" % tuple(tiles),
              "success_distance_mm %.9g" % successDistance, "success_heading_rad %.9g" % successHeading,
              "actions %d" % len(actions)]
    lines += ["action %.9g %.9g %.9g" % tuple(action) for action in actions]
    lines.append("weights %d" % len(weights))
    lines += [" ".join("%.9g" % w for w in weights[row:row + 8]) for row in range(0, len(weights), 8)]
    return "\n".join(lines) + "\n"


def loadPolicy(path):
    """The TilePolicy in the file `path`. Raises PolicyError (a ValueError)."""
    try:
        with open(path, encoding="utf-8") as policyFile:
            text = policyFile.read()
    except (OSError, UnicodeDecodeError) as error:
        raise PolicyError("%s: cannot read the policy (%s)" % (path, getattr(error, "strerror", None) or error))
    return parsePolicy(text, path)


_cache = {}


def cachedPolicy(path):
    """loadPolicy(path), read once per path: skills are made often (params change, roles),
    the file is parsed once."""
    if path not in _cache:
        _cache[path] = loadPolicy(path)
    return _cache[path]
