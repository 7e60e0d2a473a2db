"""Every skill constant has the same name and value in both ports: the C++ headers'
`inline constexpr` constants (numbers and strings) against the Python modules' UPPER_CASE ones."""
import ast
import math
import pathlib
import re

import pytest

import behaviour
from skills import (avoid, ball, camera, field, go_to_pose, goalie, head_scan, landmark_glance, learned_go_to_pose,
                    line_up_and_kick, robot_limits, search, striker, supporter, team, team_comm, tile_policy,
                    unstick)

ROOT = pathlib.Path(__file__).resolve().parents[2]
CPP_SKILLS = ROOT / "behaviour_cpp" / "include" / "touchline" / "behaviour" / "skills"
PY_SKILLS = ROOT / "behaviour_py" / "skills"
CONSTANT = re.compile(r"inline constexpr (?:float|int|int32_t|const char\*) (\w+) = ([^;]+);")
FLOAT_LITERAL = re.compile(r"\b(\d+(?:\.\d*)?)f\b")


def cpp_constants():
    """name -> value of every constant in the C++ skill headers, the expressions evaluated."""
    pending = {}
    for header in sorted(CPP_SKILLS.glob("*.hpp")):
        for name, expression in CONSTANT.findall(header.read_text()):
            pending[name] = FLOAT_LITERAL.sub(r"\1", expression).replace("api::kPi", "kPi")
    values = {}
    while pending:  # constants use constants of other headers: evaluate as they resolve
        resolved = {}
        for name, expression in pending.items():
            try:
                resolved[name] = eval(expression, {"kPi": math.pi}, values)  # our own headers' arithmetic
            except NameError:
                pass
        assert resolved, "unresolvable C++ constants: %s" % pending
        values.update(resolved)
        pending = {name: e for name, e in pending.items() if name not in resolved}
    return values


def python_constants():
    """name -> value of every module-level UPPER_CASE number in behaviour_py/skills and the
    chest colours of behaviour.py."""
    modules = {"avoid": avoid, "ball": ball, "camera": camera, "go_to_pose": go_to_pose, "head_scan": head_scan,
               "landmark_glance": landmark_glance,
               "line_up_and_kick": line_up_and_kick, "robot_limits": robot_limits, "field": field, "goalie": goalie,
               "search": search, "striker": striker, "supporter": supporter, "team": team, "team_comm": team_comm,
               "unstick": unstick, "learned_go_to_pose": learned_go_to_pose, "tile_policy": tile_policy}
    assert {path.stem for path in PY_SKILLS.glob("*.py")} - set(modules) <= {"__init__", "go_to_ball", "look_for_ball",
                                                                              "stand", "track_ball"}
    values = {}
    for name, module in modules.items():
        for node in ast.parse((PY_SKILLS / (name + ".py")).read_text()).body:
            if isinstance(node, ast.Assign) and node.targets[0].id.isupper():
                value = getattr(module, node.targets[0].id)
                if isinstance(value, (int, float, str)):  # not the SupporterDef presets: below
                    values[node.targets[0].id] = value
    values.update(BALL_SEEN_CHEST=behaviour.BALL_SEEN_CHEST, BALL_LOST_CHEST=behaviour.BALL_LOST_CHEST)
    return values


def test_the_same_constants_in_both_ports():
    assert sorted(cpp_constants()) == sorted(python_constants())


@pytest.mark.parametrize("name, value", sorted(cpp_constants().items()))
def test_the_same_values_in_both_ports(name, value):
    if isinstance(value, str):
        assert python_constants()[name] == value
    else:
        assert python_constants()[name] == pytest.approx(value, rel=1e-6)


# The supporters' numbers (SupporterDef): the C++ struct's defaults are the thesis's, and the
# tuned preset sets fields in tunedSupporters() as `d.NAME = VALUE;`.
CPP_FIELD = re.compile(r"^\s+float (\w+) = ([^;]+);", re.MULTILINE)
CPP_TUNED_FIELD = re.compile(r"\bd\.(\w+) = ([^;]+);")


def cpp_supporter_defs():
    header = (CPP_SKILLS / "supporter.hpp").read_text()
    struct = header[header.index("struct SupporterDef {"):]
    struct = struct[:struct.index("};")]
    thesis = {name: float(FLOAT_LITERAL.sub(r"\1", value)) for name, value in CPP_FIELD.findall(struct)}
    source = (ROOT / "behaviour_cpp" / "src" / "skills" / "supporter.cpp").read_text()
    tuned_body = source[source.index("const SupporterDef& tunedSupporters()"):]
    tuned_body = tuned_body[:tuned_body.index("return tuned;")]
    tuned = dict(thesis)
    tuned.update({name: float(FLOAT_LITERAL.sub(r"\1", value)) for name, value in CPP_TUNED_FIELD.findall(tuned_body)})
    return {"thesis": thesis, "tuned": tuned}


@pytest.mark.parametrize("preset", ["thesis", "tuned"])
def test_the_same_supporter_numbers_in_both_ports(preset):
    cpp = cpp_supporter_defs()[preset]
    python = vars(supporter.SUPPORTER_DEFS[preset])
    assert sorted(cpp) == sorted(python)
    for name, value in cpp.items():
        assert python[name] == pytest.approx(value, rel=1e-6), name
