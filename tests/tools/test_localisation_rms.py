"""tools/localisation_rms.py: the seeds it plays and its per-match table of the robots'
localisation error (mean robot and worst robot), from real in-process matches."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
import localisation_rms  # noqa: E402


def test_seed_ranges_and_lists():
    assert localisation_rms.seeds_of("6-9") == [6, 7, 8, 9]
    assert localisation_rms.seeds_of("1,4-5") == [1, 4, 5]


def test_each_seed_is_a_row_and_the_worst_robot_is_at_least_the_mean(capsys):
    assert localisation_rms.main(["--seeds", "1-2", "--", "--duration", "20", "--team-size", "2"]) == 0
    lines = capsys.readouterr().out.splitlines()
    rows = [line.split() for line in lines[1:3]]
    assert [int(r[0]) for r in rows] == [1, 2]
    for _, mean, worst in rows:
        assert 0 < float(mean) <= float(worst)
    assert lines[3].split()[0] == "all"


def test_a_match_that_cannot_play_is_one_line_and_a_failure(capsys):
    assert localisation_rms.main(["--seeds", "1", "--team0", "cpp:NoSuchSkill", "--", "--duration", "5"]) == 1
    assert "seed 1:" in capsys.readouterr().err
