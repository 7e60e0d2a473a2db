"""Our rUNSWift-style test behaviour imports only their API (`robot`), its own modules and
pure standard-library modules: it proves the runswift profile, not a side door."""
import pathlib

import pytest

from test_import_audit import forbidden_imports  # tests/behaviour_py's ast audit

BEHAVIOUR = pathlib.Path(__file__).resolve().parent / "behaviour"
PURE_STDLIB = {"math"}


def own_modules(root):
    names = {path.stem for path in root.glob("*.py")}
    names |= {path.parent.name for path in root.glob("*/__init__.py")}
    return names


def test_the_behaviour_has_its_tree():
    assert {"behaviour", "task", "world", "skills", "head"} <= own_modules(BEHAVIOUR)


@pytest.mark.parametrize("path", sorted(BEHAVIOUR.rglob("*.py")), ids=lambda p: str(p.relative_to(BEHAVIOUR)))
def test_imports_only_robot_and_its_own_modules(path):
    allowed = {"robot"} | own_modules(BEHAVIOUR) | PURE_STDLIB
    assert forbidden_imports(path.read_text(), allowed) == []


def test_the_audit_would_catch_touchlines_own_api():
    allowed = {"robot"} | own_modules(BEHAVIOUR) | PURE_STDLIB
    assert forbidden_imports("import actioncommand\nimport lcm\n", allowed) == [(1, "actioncommand"), (2, "lcm")]
