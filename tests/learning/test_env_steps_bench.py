"""bench/env_steps: prints a figure per case and writes them as JSON; refuses bad counts."""
import json
import pathlib
import subprocess

BENCH = pathlib.Path(__file__).resolve().parents[2] / "bench" / "env_steps"


def test_prints_and_writes_every_figure(tmp_path):
    out = tmp_path / "steps.json"
    result = subprocess.run([str(BENCH), "--steps", "300", "--repeat", "1", "--json", str(out)],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    figures = json.loads(out.read_text())["steps_per_s"]
    assert len(figures) == 9 and all(v > 0 for v in figures.values())
    assert len(result.stdout.strip().splitlines()) == 9


def test_refuses_a_zero_step_count():
    result = subprocess.run([str(BENCH), "--steps", "0"], capture_output=True, text=True)
    assert result.returncode == 2 and "at least 1" in result.stderr
