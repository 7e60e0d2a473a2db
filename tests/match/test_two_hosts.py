"""One match across two hosts: the world and team 0 on one, team 1's robot processes on the
other, over LCM multicast with ttl=1 (what a real network between machines needs).

Two network namespaces stand in for the hosts: this test's own (tools/netns, "host A") and
a second one it makes ("host B"), joined by a veth pair (the cable) with a multicast route
over it on each side (the LAN). Nothing leaves the namespaces this test made. The match must
play and give the same truth hash as the same match with every process on one host.
"""
from __future__ import annotations

import json
import os
import subprocess
import time

import pytest

from touchline_harness import ROBOT_SHIM, SIM_WORLD, WAIT_S, WALK_INI, Proc

ONE_HOST_URL = "udpm://239.255.76.67:7667?ttl=0"
TWO_HOSTS_URL = "udpm://239.255.76.67:7667?ttl=1"
HOST_A_ADDRESS, HOST_B_ADDRESS = "10.231.0.1/30", "10.231.0.2/30"
TEAM_SIZE = 2
TEAMS = ("Team", "py")  # team 0 plays the C++ team, team 1 the Python one

pytestmark = pytest.mark.skipif(os.geteuid() != 0 or os.environ.get("TOUCHLINE_IN_NETNS") != "1",
                                reason="needs root inside tools/netns to make a second namespace")


def run(*args: str) -> None:
    subprocess.run(args, check=True, capture_output=True, text=True)


class HostB:
    """A second network namespace, held open by a sleeping process, joined to this one by a
    veth pair with a multicast route on both ends."""

    def __init__(self):
        own = os.readlink("/proc/self/ns/net")
        self.holder = subprocess.Popen(["unshare", "--net", "--", "sleep", "infinity"])
        self.ns = f"/proc/{self.holder.pid}/ns/net"
        deadline = time.monotonic() + WAIT_S
        while os.readlink(self.ns) == own:  # until unshare has made the namespace
            assert self.holder.poll() is None and time.monotonic() < deadline, "unshare --net failed"
            time.sleep(0.01)  # polling another process's state, not hiding a race
        run("ip", "link", "add", "tl_host_a", "type", "veth", "peer", "name", "tl_host_b",
            "netns", str(self.holder.pid))
        run("ip", "addr", "add", HOST_A_ADDRESS, "dev", "tl_host_a")
        run("ip", "link", "set", "tl_host_a", "up")
        run("ip", "route", "replace", "224.0.0.0/4", "dev", "tl_host_a")
        for command in (["ip", "link", "set", "lo", "up"], ["ip", "addr", "add", HOST_B_ADDRESS, "dev", "tl_host_b"],
                        ["ip", "link", "set", "tl_host_b", "up"], ["ip", "route", "add", "224.0.0.0/4", "dev", "tl_host_b"]):
            run(*self.prefix(), *command)

    def prefix(self) -> list[str]:
        return ["nsenter", f"--net={self.ns}", "--"]

    def packets_received(self) -> int:
        """Packets host A received from host B over the cable."""
        shown = subprocess.run(["ip", "-json", "-stats", "link", "show", "tl_host_a"], check=True,
                               capture_output=True, text=True).stdout
        return json.loads(shown)[0]["stats64"]["rx"]["packets"]

    def close(self) -> None:
        self.holder.kill()
        self.holder.wait()
        # The veth pair goes with host B's namespace; the multicast route back to loopback.
        subprocess.run(["ip", "route", "replace", "224.0.0.0/4", "dev", "lo"], check=False)


def play(tmp_path, url: str, host_b: HostB | None) -> dict:
    """A 2 v 2 match of 10 s; team 1's robots on host B when there is one."""
    summary = tmp_path / f"summary-{time.monotonic_ns()}.json"
    world = Proc("sim_world", [SIM_WORLD, "--set", f"match.team_size={TEAM_SIZE}", "--duration", 10, "--seed", 5,
                               "--quiet", "--summary", summary, "--lcm-url", url])
    robots = []
    for team in (0, 1):
        prefix = host_b.prefix() if host_b and team == 1 else []
        for player in range(1, TEAM_SIZE + 1):
            behaviour = ["--behaviour", "py", "--param", "skill=Team"] if TEAMS[team] == "py" else \
                        ["--behaviour", TEAMS[team]]
            robots.append(Proc(f"robot_shim {team}/{player}", [
                *prefix, ROBOT_SHIM, "--team", team, "--player", player, "--walk-config", WALK_INI,
                "--lcm-url", url, "--world-timeout", 20, *behaviour]))
    try:
        assert world.wait() == 0, "sim_world failed:\n" + "\n".join(world.stderr)
        for robot in robots:
            assert robot.wait() == 0, f"{robot.name} failed:\n" + "\n".join(robot.stderr)
    finally:
        for p in [world, *robots]:
            p.kill()
    return json.loads(summary.read_text())


def test_a_match_across_two_hosts_is_the_match_on_one(tmp_path):
    one_host = play(tmp_path, ONE_HOST_URL, None)
    host_b = HostB()
    try:
        two_hosts = play(tmp_path, TWO_HOSTS_URL, host_b)
        # Team 1's answers crossed the cable: two robots, one answer a frame each at least.
        assert host_b.packets_received() >= 2 * 300
    finally:
        host_b.close()
    for summary in (one_host, two_hosts):
        assert all(r["active"] and r["frames_missed"] == 0 for r in summary["robots"]), summary["robots"]
    assert two_hosts["frames"] == one_host["frames"] == 300
    assert two_hosts["truth_hash"] == one_host["truth_hash"]
