"""A wrong -DTOUCHLINE_RUNSWIFT_DIR fails the configure at once with one line naming the path
and what is wrong (robot_shim/runswift/check_clone.cmake). Needs no code of theirs: the
trees here are empty placeholder files under their file names."""
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("TOUCHLINE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[3]))
CMAKE = os.environ.get("CMAKE_COMMAND", "cmake")

# What check_clone.cmake requires of a clone.
NEEDED = [
    "robot/motion/generator/Walk2014Generator.cpp",
    "robot/motion/generator/BodyModel.cpp",
    "robot/motion/MotionOdometry.cpp",
    "robot/perception/kinematics/Kinematics.cpp",
    "robot/perception/kinematics/Parameters.cpp",
    "robot/perception/kinematics/Pose.cpp",
    "robot/utils/options.cpp",
    "robot/utils/home_nao.cpp",
    "robot/motion/generator/Walk2014Generator.hpp",
    "robot/motion/generator/BodyModel.hpp",
    "robot/motion/MotionDefs.hpp",
    "robot/perception/kinematics/Kinematics.hpp",
    "robot/types/ActionCommand.hpp",
    "robot/types/MotionDebugInfo.hpp",
    "robot/types/Odometry.hpp",
    "robot/types/SensorValues.hpp",
    "robot/utils/Logger.hpp",
    "robot/utils/options.hpp",
    "robot/Eigen/Core",
]


def configure(tmp_path, runswift_dir):
    """Configures the tree with the given clone; returns (exit code, the error's text lines)."""
    result = subprocess.run(
        [CMAKE, "-S", str(SOURCE), "-B", str(tmp_path / "build"), f"-DTOUCHLINE_RUNSWIFT_DIR={runswift_dir}"],
        capture_output=True, text=True, timeout=120)
    lines = result.stderr.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("CMake Error at"))
    message = []
    for line in lines[start + 1:]:
        if not line.strip() or line.startswith("Call Stack"):
            break
        message.append(line.strip())
    return result.returncode, message


def placeholder_tree(root, files):
    for name in files:
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text("")
    return root


def test_a_path_that_does_not_exist(tmp_path):
    code, message = configure(tmp_path, "/nonexistent")
    assert code != 0
    assert message == ["TOUCHLINE_RUNSWIFT_DIR=/nonexistent: no such directory"]


def test_a_file_instead_of_their_folder(tmp_path):
    file = tmp_path / "runswift.tar"
    file.write_text("")
    code, message = configure(tmp_path, file)
    assert code != 0
    assert message == [f"TOUCHLINE_RUNSWIFT_DIR={file}: not a directory (give the top folder of a rUNSWift clone)"]


def test_a_folder_that_is_not_their_tree(tmp_path):
    other = placeholder_tree(tmp_path / "other", ["README.md"])
    code, message = configure(tmp_path, other)
    assert code != 0
    assert message == [
        f"TOUCHLINE_RUNSWIFT_DIR={other}: not a rUNSWift clone (no robot/motion/generator/Walk2014Generator.cpp)"]


def test_their_robot_folder_instead_of_the_clone(tmp_path):
    clone = placeholder_tree(tmp_path / "clone", NEEDED)
    code, message = configure(tmp_path, clone / "robot")
    assert code != 0
    assert message == [f"TOUCHLINE_RUNSWIFT_DIR={clone}/robot: this is their robot/ folder; "
                       f"give the clone's top folder ({clone})"]


@pytest.mark.parametrize("missing", ["robot/perception/kinematics/Kinematics.cpp", "robot/Eigen/Core"])
def test_a_clone_missing_one_file_names_it(tmp_path, missing):
    clone = placeholder_tree(tmp_path / "clone", [name for name in NEEDED if name != missing])
    code, message = configure(tmp_path, clone)
    assert code != 0
    assert message == [f"TOUCHLINE_RUNSWIFT_DIR={clone}: {missing} is missing"]


def test_a_clone_missing_several_names_the_first_and_counts_the_rest(tmp_path):
    clone = placeholder_tree(tmp_path / "clone", NEEDED[:-3])
    code, message = configure(tmp_path, clone)
    assert code != 0
    assert message == [f"TOUCHLINE_RUNSWIFT_DIR={clone}: {NEEDED[-3]} is missing (and 2 more of the files the walk needs)"]
