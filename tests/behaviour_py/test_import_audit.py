"""behaviour_py imports only the robot API (`robot`, `actioncommand`), its own modules and a
few pure standard-library modules: no lcm, no numpy, no simulator. Checked with `ast`."""
import ast
import pathlib

import pytest

BEHAVIOUR_PY = pathlib.Path(__file__).resolve().parents[2] / "behaviour_py"
API = {"robot", "actioncommand"}
PURE_STDLIB = {"__future__", "math", "typing", "enum", "dataclasses", "functools", "itertools"}


def own_modules(root):
    """Top-level names behaviour_py provides: its modules and packages."""
    names = {path.stem for path in root.glob("*.py")}
    names |= {path.parent.name for path in root.glob("*/__init__.py")}
    return names


def forbidden_imports(source, allowed):
    """(line, name) of every import outside `allowed`, and every dynamic import."""
    bad = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            bad += [(node.lineno, alias.name) for alias in node.names if alias.name.split(".")[0] not in allowed]
        elif isinstance(node, ast.ImportFrom):
            if node.level == 0 and node.module.split(".")[0] not in allowed:
                bad.append((node.lineno, node.module))
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "__import__":
            bad.append((node.lineno, "__import__"))
    return bad


def test_behaviour_py_has_modules():
    assert {"behaviour", "actioncommand", "skills"} <= own_modules(BEHAVIOUR_PY)


@pytest.mark.parametrize("path", sorted(BEHAVIOUR_PY.rglob("*.py")), ids=lambda p: str(p.relative_to(BEHAVIOUR_PY)))
def test_imports_only_the_robot_api(path):
    allowed = API | own_modules(BEHAVIOUR_PY) | PURE_STDLIB
    assert forbidden_imports(path.read_text(), allowed) == []


def test_the_audit_catches_the_simulator_and_friends():
    allowed = API | {"skills"} | PURE_STDLIB
    source = "import math\nimport lcm\nfrom numpy import array\nimport sim.world as w\nos = __import__('os')\nfrom .x import y\n"
    assert forbidden_imports(source, allowed) == [(2, "lcm"), (3, "numpy"), (4, "sim.world"), (5, "__import__")]
