"""The server's command line: a bad log, a corrupt log, a port in use and bad options each give
one line on stderr and exit code 2."""
import socket

import pytest

from conftest import ViewerServer, run_module

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


def test_a_bad_config_is_one_line_and_exit_2(known_log, tmp_path):
    config = tmp_path / "bad.ini"
    config.write_text("[field]\nlength_mm = long\n")
    assert_one_line_exit_2(run_module(VIEWER, "--log", known_log, "--config", config), "length_mm")


def test_it_listens_on_127_0_0_1_and_stops_cleanly_on_sigterm(known_log):
    server = ViewerServer("--log", known_log)
    assert server.url.startswith("http://127.0.0.1:")
    assert server.stop() == 0
