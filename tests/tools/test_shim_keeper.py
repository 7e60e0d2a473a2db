"""What the launcher does with a dead robot_shim, step by step, with stand-ins for the
processes and the watcher (the real thing, end to end: test_launch_faults.py)."""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
from match_processes import describe_exit  # noqa: E402
from shim_keeper import ShimKeeper  # noqa: E402


class FakeChild:
    def __init__(self, name, argv):
        self.name, self.argv, self.rc, self.pid, self.terminated = name, argv, None, 1000, False

    def poll(self):
        return self.rc

    def why(self):
        return describe_exit(self.rc)

    def terminate(self):
        self.terminated = True


class FakeChildren:
    logdir = Path("/tmp/logs")

    def __init__(self):
        self.started = []

    def start(self, name, argv, log_name=None):
        child = FakeChild(name, argv)
        self.started.append((child, log_name))
        return child


class FakeWatch:
    def __init__(self):
        self.sim_s, self.out = 0.0, set()

    def timed_out(self, team, player):
        return (team, player) in self.out

    def say(self, line, file=None):
        print(line, file=file)


def keeper(restart):
    children, watch = FakeChildren(), FakeWatch()
    k = ShimKeeper(children, watch, restart=restart)
    k.start(0, 1, ["robot_shim", "--team", 0, "--player", 1])
    k.start(1, 1, ["robot_shim", "--team", 1, "--player", 1])
    return k, children, watch


def test_a_shim_dead_before_kick_off_stops_the_match():
    k, children, _ = keeper(restart=True)
    children.started[1][0].rc = 2
    assert k.check(kicked_off=False) == "robot_shim 1/1 exited with code 2 (logs in /tmp/logs)"


def test_without_restart_the_match_goes_on_and_the_death_is_kept():
    k, children, watch = keeper(restart=False)
    watch.sim_s = 12.0
    children.started[1][0].rc = -9
    assert k.check(kicked_off=True) is None
    watch.out.add((1, 1))
    assert k.check(kicked_off=True) is None
    assert len(children.started) == 2, "nothing restarted"
    assert k.summary() == [{"team": 1, "player": 1, "sim_s": 12.0, "how": "was killed by SIGKILL",
                            "outcome": "not restarted (no --restart-dead): the robot stayed inactive",
                            "restarted_sim_s": None, "taken_back": False}]


def test_a_dead_shim_is_restarted_only_once_the_world_marks_its_robot_inactive():
    k, children, watch = keeper(restart=True)
    children.started[1][0].rc = -9
    watch.sim_s = 12.0
    assert k.check(kicked_off=True) is None
    assert len(children.started) == 2, "the world still counts the robot active: it would refuse a new shim"
    watch.sim_s = 13.0
    watch.out.add((1, 1))
    assert k.check(kicked_off=True) is None
    new, log_name = children.started[2]
    assert new.argv == ["robot_shim", "--team", 1, "--player", 1] and log_name == "robot_shim 1/1.restart1"
    assert k.check(kicked_off=True) is None and len(children.started) == 3, "started once"
    watch.out.clear()  # the new shim answered: the robot is active again
    k.check(kicked_off=True)
    [death] = k.summary()
    assert death["restarted_sim_s"] == 13.0 and death["taken_back"]
    assert k.lines() == [(12.0, "team 1 #1's robot_shim was killed by SIGKILL; restarted at 13.0 s; "
                                "the new shim took the robot back")]


def test_a_restarted_shim_that_dies_before_taking_its_robot_back_is_not_restarted_again():
    k, children, watch = keeper(restart=True)
    children.started[1][0].rc = -9
    watch.out.add((1, 1))
    k.check(kicked_off=True)
    k.check(kicked_off=True)
    children.started[2][0].rc = 2  # e.g. it could not start
    k.check(kicked_off=True)
    k.check(kicked_off=True)
    assert len(children.started) == 3, "no restart loop"
    first, second = k.summary()
    assert not first["taken_back"] and "the new shim died before it took the robot back" in first["outcome"]
    assert second["outcome"].startswith("not restarted again")


def test_after_the_match_a_restarted_shim_not_yet_back_is_stopped_and_a_failing_one_counts():
    k, children, watch = keeper(restart=True)
    children.started[1][0].rc = -9
    watch.out.add((1, 1))
    k.check(kicked_off=True)
    k.check(kicked_off=True)
    children.started[0][0].rc = 1  # robot 0/1 ends badly after the world's FINISHED
    k.after_match(timeout_s=0, stopping=lambda: False)
    assert children.started[2][0].terminated
    assert [(d["team"], d["outcome"]) for d in k.summary()] == [
        (1, "restarted at 0.0 s; the match ended before the new shim took the robot back"),
        (0, "after the end of the match")]
