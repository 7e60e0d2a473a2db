"""The layers of docs/ARCHITECTURE.md, checked against the tree: every #include of every C++
file and every target_link_libraries of every CMakeLists.txt of a layer folder may reach only
the folders that layer stands on. A header is owned by the folder whose include/ directory
holds it (lcm_types/ owns the headers lcm-gen makes of its .lcm files); a target by the folder
whose CMakeLists.txt adds it."""
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]

# Each layer folder and the folders it may use (docs/ARCHITECTURE.md, "The layers").
BELOW = {
    "robot_api": set(),
    "common": {"robot_api"},
    "sim": {"common", "robot_api"},
    "robot_shim": {"common", "robot_api"},
    "behaviour_cpp": {"robot_api"},
    "lcm_types": set(),
}
BELOW["bridge"] = set(BELOW) | {"lcm_types"}
BELOW["learning"] = BELOW["bridge"] | {"bridge"}

# Third-party headers only some layers may include: the transport in the bridges (and above),
# the physics engine in the world.
THIRD_PARTY_ONLY_IN = {
    "lcm/": {"bridge", "learning"},
    "box2d/": {"sim"},
}

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)
ADD_LIBRARY = re.compile(r"\b(?:add_library|add_executable|pybind11_add_module)\(\s*([\w:]+)")
LINK = re.compile(r"\btarget_link_libraries\(\s*(\w+)([^)]*)\)", re.S)
CXX = {".cpp", ".hpp", ".h", ".cc"}


def header_owners(root):
    """touchline/... header path -> the layer folder that provides it."""
    owners = {}
    for folder in BELOW:
        for include_dir in (root / folder).rglob("include"):
            if not include_dir.is_dir():
                continue
            for header in include_dir.rglob("*"):
                if header.suffix in CXX:
                    owners[header.relative_to(include_dir).as_posix()] = folder
        for message in (root / folder).glob("*.lcm"):
            package = re.search(r"^\s*package\s+(\w+)\s*;", message.read_text(), re.M)
            if package:
                owners[f"{package.group(1)}/{message.stem}.hpp"] = folder
    return owners


def target_owners(root):
    """CMake target (and its touchline:: alias) -> the layer folder that adds it."""
    owners = {}
    for folder in BELOW:
        for cmake in (root / folder).rglob("CMakeLists.txt"):
            for name in ADD_LIBRARY.findall(cmake.read_text()):
                owners[name] = folder
    return owners


def include_violations(root):
    owners = header_owners(root)
    found = []
    for folder, allowed in BELOW.items():
        for source in sorted((root / folder).rglob("*")):
            if source.suffix not in CXX:
                continue
            where = source.relative_to(root).as_posix()
            for header in INCLUDE.findall(source.read_text(errors="replace")):
                if (source.parent / header).exists():
                    continue  # a file beside it, in the same folder
                owner = owners.get(header)
                if owner is not None and owner != folder and owner not in allowed:
                    found.append(f"{where} includes {header}, from {owner}/, above or beside {folder}/")
                elif owner is None and header.startswith("touchline/"):
                    found.append(f"{where} includes {header}, which no layer's include/ holds")
                for prefix, layers in THIRD_PARTY_ONLY_IN.items():
                    if header.startswith(prefix) and folder not in layers:
                        found.append(f"{where} includes {header}: {prefix} belongs to {', '.join(sorted(layers))}")
    return found


def link_violations(root):
    owners = target_owners(root)
    found = []
    for folder, allowed in BELOW.items():
        for cmake in sorted((root / folder).rglob("CMakeLists.txt")):
            where = cmake.relative_to(root).as_posix()
            for target, libraries in LINK.findall(cmake.read_text()):
                for library in libraries.split():
                    owner = owners.get(library)
                    if owner is not None and owner != folder and owner not in allowed:
                        found.append(f"{where}: {target} links {library}, from {owner}/, above or beside {folder}/")
    return found


def test_no_include_runs_back_up_a_layer():
    assert include_violations(ROOT) == []


def test_no_link_runs_back_up_a_layer():
    assert link_violations(ROOT) == []


def test_every_layer_folder_exists_with_its_build():
    for folder in BELOW:
        assert (ROOT / folder / "CMakeLists.txt").is_file(), folder


# The checks themselves, on a tree made to break the rules.
def write(path, text):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


@pytest.fixture
def tree(tmp_path):
    write(tmp_path / "robot_api/include/touchline/robot_api/blackboard.hpp", "#pragma once\n")
    write(tmp_path / "robot_api/CMakeLists.txt", "add_library(touchline_robot_api INTERFACE)\n"
          "add_library(touchline::robot_api ALIAS touchline_robot_api)\n")
    write(tmp_path / "robot_shim/include/touchline/robot/robot.hpp",
          '#include "touchline/robot_api/blackboard.hpp"\n')
    write(tmp_path / "robot_shim/CMakeLists.txt", "add_library(touchline_robot STATIC src/robot.cpp)\n"
          "target_link_libraries(touchline_robot PUBLIC touchline::robot_api)\n"
          "add_library(touchline::robot ALIAS touchline_robot)\n")
    write(tmp_path / "sim/src/world.cpp", "#include <box2d/box2d.h>\n#include <vector>\n")
    write(tmp_path / "sim/CMakeLists.txt", "add_library(touchline_sim STATIC src/world.cpp)\n")
    write(tmp_path / "lcm_types/sense_t.lcm", "package touchline;\nstruct sense_t { int64_t utime; }\n")
    return tmp_path


def test_the_checks_pass_a_tree_that_keeps_the_rules(tree):
    assert include_violations(tree) == []
    assert link_violations(tree) == []


def test_the_include_check_catches_the_world_reaching_the_robot(tree):
    write(tree / "sim/src/match.cpp", '#include "touchline/robot/robot.hpp"\n')
    assert include_violations(tree) == [
        "sim/src/match.cpp includes touchline/robot/robot.hpp, from robot_shim/, above or beside sim/"]


def test_the_include_check_catches_a_message_type_and_lcm_below_the_bridges(tree):
    write(tree / "robot_shim/src/robot.cpp", '#include "touchline/sense_t.hpp"\n#include <lcm/lcm.h>\n')
    assert include_violations(tree) == [
        "robot_shim/src/robot.cpp includes touchline/sense_t.hpp, from lcm_types/, above or beside robot_shim/",
        "robot_shim/src/robot.cpp includes lcm/lcm.h: lcm/ belongs to bridge, learning"]


def test_the_link_check_catches_the_api_linking_the_robot(tree):
    write(tree / "robot_api/CMakeLists.txt", "add_library(touchline_robot_api INTERFACE)\n"
          "target_link_libraries(touchline_robot_api INTERFACE touchline::robot)\n")
    assert link_violations(tree) == [
        "robot_api/CMakeLists.txt: touchline_robot_api links touchline::robot, from robot_shim/, above or beside robot_api/"]
