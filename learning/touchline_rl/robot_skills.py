"""The robots' own Python skills that learning shares (behaviour_py/skills): the policy file's
one reader and writer and the one angle wrap, so training and play agree bit for bit."""
import sys

from touchline_rl.home import touchline_paths

_BEHAVIOUR_PY = touchline_paths.behaviour_py()  # behaviour_py/, or its installed copy
if str(_BEHAVIOUR_PY) not in sys.path:
    sys.path.append(str(_BEHAVIOUR_PY))

from skills.tile_policy import loadPolicy, policyText, wrapAngle  # noqa: E402,F401 (re-exported)
