"""The robots' own Python skills that learning shares (behaviour_py/skills): the policy file's
one reader and writer and the one angle wrap, so training and play agree bit for bit."""
import pathlib
import sys

_BEHAVIOUR_PY = pathlib.Path(__file__).resolve().parents[2] / "behaviour_py"
if str(_BEHAVIOUR_PY) not in sys.path:
    sys.path.append(str(_BEHAVIOUR_PY))

from skills.tile_policy import loadPolicy, policyText, wrapAngle  # noqa: E402,F401 (re-exported)
