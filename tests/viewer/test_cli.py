"""The server's command line: a bad log, a corrupt log, a log without the match's geometry
(TL_MATCH) or of other LCM types, a port in use and bad options each give one line on stderr
and exit code 2."""
import socket

import pytest

from conftest import ViewerServer, run_module
from known_log import known_messages, match_config
from touchline_viewer.field import TYPES_VERSION

VIEWER = "touchline_viewer"


def assert_one_line_exit_2(result, *words):
    assert result.returncode == 2, result.stderr
    assert result.stderr.count("\n") == 1, result.stderr
    for word in words:
        assert word in result.stderr
    assert result.stdout == ""


def test_a_missing_log_is_one_line_and_exit_2(tmp_path):
    assert_one_line_exit_2(run_module(VIEWER, "--log", tmp_path / "nope.lcmlog"), "nope.lcmlog", "no such file")


@pytest.mark.parametrize("content", [b"", b"not a log at all" * 100], ids=["empty", "garbage"])
def test_a_corrupt_log_is_one_line_and_exit_2(tmp_path, content):
    log = tmp_path / "bad.lcmlog"
    log.write_bytes(content)
    assert_one_line_exit_2(run_module(VIEWER, "--log", log), "not an lcm-logger log")


def test_a_log_without_truth_is_one_line_and_exit_2(tmp_path):
    import lcm
    log = tmp_path / "other.lcmlog"
    writer = lcm.EventLog(str(log), "w", overwrite=True)
    writer.write_event(0, "SOMETHING_ELSE", b"\x00" * 16)
    writer.close()
    assert_one_line_exit_2(run_module(VIEWER, "--log", log), "no TL_TRUTH")


def test_a_port_in_use_is_one_line_and_exit_2(known_log):
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        assert_one_line_exit_2(run_module(VIEWER, "--log", known_log, "--port", port), f"port {port}", "in use")


@pytest.mark.parametrize("args", [["--port", "70000"], ["--speed", "2"], ["--log", "a", "--lcm-url", "memq://"]],
                         ids=["bad-port", "unknown-option", "log-and-live"])
def test_bad_options_are_one_line_and_exit_2(args):
    assert_one_line_exit_2(run_module(VIEWER, *args))


def write_log(path, replace_match):
    """The known log with each TL_MATCH replaced by `replace_match` bytes (None: left out)."""
    import lcm
    writer = lcm.EventLog(str(path), "w", overwrite=True)
    for utime, channel, message in known_messages():
        data = message.encode() if channel != "TL_MATCH" else replace_match
        if data is not None:
            writer.write_event(utime, channel, data)
    writer.close()
    return path


def test_a_log_without_the_match_s_geometry_is_one_line_and_exit_2(tmp_path):
    log = write_log(tmp_path / "old.lcmlog", None)  # as sim_world wrote them before TL_MATCH
    assert_one_line_exit_2(run_module(VIEWER, "--log", log), "no TL_MATCH", f"version {TYPES_VERSION}")


def test_a_log_of_other_lcm_types_names_their_version(tmp_path):
    other = bytearray(match_config().encode())
    other[:8] = b"\x01" * 8  # another fingerprint: another match_config_t
    other[16:18] = (TYPES_VERSION + 1).to_bytes(2, "big")
    log = write_log(tmp_path / "newer.lcmlog", bytes(other))
    assert_one_line_exit_2(run_module(VIEWER, "--log", log), f"types version {TYPES_VERSION + 1}",
                           f"reads version {TYPES_VERSION}")


def test_it_listens_on_127_0_0_1_and_stops_cleanly_on_sigterm(known_log):
    server = ViewerServer("--log", known_log)
    assert server.url.startswith("http://127.0.0.1:")
    assert server.stop() == 0
