"""One short match with sim_world and robot_shim built with -fsanitize=address,undefined
(build-asan, which tools/test builds): every program must finish the match, exit 0 and
print no sanitizer report. C++ behaviours on both teams and one Python robot (the embedded
interpreter under AddressSanitizer too)."""
from touchline_harness import start_robot, start_world

SANITIZER_REPORT = ("ERROR: AddressSanitizer", "ERROR: LeakSanitizer", "runtime error:")


def test_a_2v2_match_runs_clean_under_address_and_undefined_behaviour_sanitizers(tmp_path):
    match = start_world(tmp_path, 4, 5.0)
    start_robot(match, 0, 1, "Team")
    start_robot(match, 0, 2, "Team")
    start_robot(match, 1, 1, "Team")
    start_robot(match, 1, 2, "py", skill="Team")
    summary = match.finish()
    for proc in [match.world, *match.robots.values()]:
        reports = [line for line in proc.stderr if any(mark in line for mark in SANITIZER_REPORT)]
        assert not reports, f"{proc.name}:\n" + "\n".join(proc.stderr)
    assert summary["frames"] == 150
    assert all(r["frames_answered"] == 150 for r in summary["robots"]), summary["robots"]
