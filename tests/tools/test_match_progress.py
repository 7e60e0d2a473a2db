"""The launcher's progress display on its own: its total is the match's planned length (grown
by each goal's stoppage, never past the match's duration), its ETA comes from the recent
real-time factor, plain lines come every tenth of the match, and the bar owns its line."""
import io
import logging
import sys

import pytest
from conftest import ROOT

sys.path.insert(0, str(ROOT / "tools"))
from launch import setup_logging  # noqa: E402
from match_progress import MatchProgress, clock  # noqa: E402


def test_the_total_is_the_planned_length_and_each_goal_adds_its_stoppage_up_to_the_duration():
    p = MatchProgress("none", planned_s=1302, goal_stoppage_s=50, duration_s=1800)
    assert p.total == 1302
    p.goal()
    assert p.total == 1352
    capped = MatchProgress("none", planned_s=1302, goal_stoppage_s=50, duration_s=1320)
    capped.goal()
    assert capped.total == 1320
    assert MatchProgress("none", planned_s=1302, goal_stoppage_s=50, duration_s=20).total == 20


def test_the_eta_is_what_is_left_over_the_recent_real_time_factor():
    p = MatchProgress("none", planned_s=1000, goal_stoppage_s=0, duration_s=1800)
    assert clock(p.eta_s()) == "?"
    p.update(0, "INITIAL", (0, 0), wall=100.0)     # the robots joined slowly: not in the window
    p.update(100, "PLAYING", (0, 0), wall=200.0)
    p.update(300, "PLAYING", (0, 0), wall=210.0)   # x20 over the last 10 s
    p.update(500, "PLAYING", (0, 0), wall=220.0)
    assert p.real_time_factor() == pytest.approx(20.0)
    assert p.eta_s() == pytest.approx(25.0) and clock(p.eta_s()) == "0:25"
    assert clock(3723) == "1:02:03"


def test_no_rate_until_the_window_spans_some_wall_time():
    # A launcher starved under load reads a backlog of TL_GAME messages in one burst: 20 s
    # simulated in a millisecond is no real-time factor (it printed x18869.8).
    p = MatchProgress("none", planned_s=1000, goal_stoppage_s=0, duration_s=1800)
    p.update(0, "PLAYING", (0, 0), wall=100.0)
    p.update(20, "PLAYING", (0, 0), wall=100.001)
    assert p.real_time_factor() != p.real_time_factor() and clock(p.eta_s()) == "?"  # nan
    p.update(40, "PLAYING", (0, 0), wall=101.0)
    assert p.real_time_factor() == pytest.approx(40.0)


def test_plain_lines_come_every_tenth_of_the_match(caplog):
    caplog.set_level(logging.INFO, logger="launch")
    p = MatchProgress("lines", planned_s=14, goal_stoppage_s=0, duration_s=1800)
    for frame in range(0, 14 * 30 + 1):
        p.update(frame / 30, "PLAYING", (1, 0), wall=frame / 300)
    lines = [r.getMessage() for r in caplog.records]
    assert [line.split(" %")[0].split()[-1] for line in lines] == [str(n) for n in range(10, 101, 10)]
    assert lines[-1].startswith("launch: 100 % of the match, 14 of 14 s simulated, x10.0 real time, PLAYING, "
                                "score 1:0, ETA 0:00"), lines[-1]


def rendered(progress) -> str:
    from rich.console import Console
    console = Console(width=120, file=io.StringIO())
    with console.capture() as capture:
        console.print(progress._bar.make_tasks_table(progress._bar.tasks))
    return capture.get()


def test_the_bar_owns_its_line_the_launchers_lines_print_above_it_and_its_columns_stay_put():
    from rich.console import Console
    out = io.StringIO()
    console = Console(file=out, width=120, force_terminal=True)
    p = MatchProgress("bar", planned_s=1302, goal_stoppage_s=50, duration_s=1800, console=console)
    try:
        before = rendered(p)
        p.update(651, "PLAYING", (10, 10), wall=0.0)
        p.update(701, "PLAYING", (10, 10), wall=1.0)
        after = rendered(p)
        setup_logging("info")
        logging.getLogger("launch").info("launch: a line of the launcher's")
        print("a plain print")
    finally:
        p.close()
    assert "0/1302 s sim" in before and "701/1302 s sim" in after and "x50.0" in after and "ETA 0:12" in after
    assert before.index(" %") == after.index(" %"), "columns move as their text changes:\n" + before + after
    text = out.getvalue()
    # Each line goes where the bar was (carriage return, line cleared), ends with its newline,
    # and the bar is drawn again below it.
    for line in ("launch: a line of the launcher's", "a plain print"):
        assert f"\r\x1b[2K{line}\n" in text, repr(text)
        assert "0/1302 s sim" in text[text.index(line):], "the bar is drawn again below the line"
