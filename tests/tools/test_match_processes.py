"""The launcher's child processes: how their end is described, and stopping them."""
import signal
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
from match_processes import Children, describe_exit  # noqa: E402

# Like sim_world and robot_shim: SIGTERM is handled (the program ends its run and exits).
HANDLES_SIGTERM = [sys.executable, "-c", "import signal, sys, time\n"
                   "signal.signal(signal.SIGTERM, lambda *_: sys.exit(7))\n"
                   "print('ready', flush=True)\n"
                   "time.sleep(120)"]


def test_an_end_is_described_by_code_or_signal():
    assert describe_exit(0) == "exited with code 0"
    assert describe_exit(2) == "exited with code 2"
    assert describe_exit(-signal.SIGKILL) == "was killed by SIGKILL"
    assert describe_exit(-signal.SIGSEGV) == "was killed by SIGSEGV"


def test_a_stopped_child_is_stopped_by_its_own_sigterm_handler_not_killed(tmp_path):
    children = Children(tmp_path, env={})
    child = children.start("sleeper", HANDLES_SIGTERM)
    deadline = time.monotonic() + 30
    while "ready" not in child.log.read_text():  # its own word that the handler is set
        assert time.monotonic() < deadline and child.poll() is None, child.log.read_text()
        time.sleep(0.01)
    child.popen.send_signal(signal.SIGSTOP)
    children.stop_all()
    assert child.poll() == 7, "it handled SIGTERM (a stopped process handles nothing until continued)"
    assert child.why() == "exited with code 7: ready"
