"""The robot module: the ActionCommand carries a team message as bytes; data_path finds the
robot's files in its data directory."""
import pathlib

import robot


def test_team_message_is_bytes_both_ways():
    request = robot.All()
    assert request.teamMessage == b""
    request.teamMessage = b"\x00\xffball at 1200"
    assert request.teamMessage == b"\x00\xffball at 1200"


def test_data_path_is_in_the_data_directory(tmp_path):
    previous = robot.data_dir()
    try:
        robot.set_data_dir(str(tmp_path))
        assert robot.data_path("policies/go_to_pose.policy") == str(tmp_path / "policies" / "go_to_pose.policy")
        assert robot.data_path("/abs/x.policy") == "/abs/x.policy"  # an absolute name as it is
    finally:
        robot.set_data_dir(previous)


def test_the_default_data_directory_is_the_source_trees_config():
    assert robot.data_dir().endswith("/config")
    assert (pathlib.Path(robot.data_dir()) / "spl2011.ini").is_file()
