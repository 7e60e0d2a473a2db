"""The same seed gives the same match bit for bit, whatever the load and whatever order the
robots' answers arrive in: 4 v 4 Team v Team, nine processes, team messages with loss."""
import subprocess
import sys

import pytest

from touchline_harness import start_robot, start_world

RUNS = 3
DURATION_S = 20.0  # simulated; the radio carries and loses hundreds of messages in it
HOG_S = 120  # the hog ends itself by then even if the test is killed
MATCH = ("--seed", "9", "--set", "match.team_size=4",
         "--set", "rules.referee=false")  # PLAYING from the start: the teams talk at once
BEHAVIOURS = {"cpp": {"behaviour": "Team"}, "py": {"behaviour": "py", "skill": "Team"}}


@pytest.fixture
def cpu_hog():
    """A busy loop beside the match: it takes turns on the CPUs with the nine processes, so
    the answers arrive in a different order each run."""
    hog = subprocess.Popen([sys.executable, "-c",
                            f"import time\nend = time.monotonic() + {HOG_S}\nwhile time.monotonic() < end: pass"])
    yield hog
    hog.kill()
    hog.wait()


@pytest.mark.parametrize("language", ["cpp", "py"])
def test_same_seed_same_truth_under_load_in_any_arrival_order(tmp_path, cpu_hog, language):
    hashes = []
    for _ in range(RUNS):
        match = start_world(tmp_path, 8, DURATION_S, *MATCH)
        for team in (0, 1):
            for player in range(1, 5):
                start_robot(match, team, player, **BEHAVIOURS[language])
        summary = match.finish()
        assert cpu_hog.poll() is None, "the hog ended before the match"
        # A robot that timed out stood still for a frame: another match, but not for the
        # reason this test is about.
        for r in summary["robots"]:
            assert r["frames_answered"] == summary["frames"] and r["frames_missed"] == 0, r
        comm = summary["comm"]
        assert comm["delivered"] > 100 and comm["lost"] > 10, comm  # the lossy radio was used
        hashes.append(summary["truth_hash"])
    assert len(set(hashes)) == 1, f"{language}:Team v {language}:Team, seed 9, {RUNS} runs: {hashes}"
