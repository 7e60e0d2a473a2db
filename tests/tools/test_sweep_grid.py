"""A sweep's grid: team specs, seeds, config values and variants expand to every match."""
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
import sweep_grid  # noqa: E402
from sweep_grid import GridError  # noqa: E402


def test_team_specs_split_where_a_new_language_starts():
    assert sweep_grid.split_specs("py:Striker,cpp:Team,walker=learned") == ["py:Striker", "cpp:Team,walker=learned"]
    assert sweep_grid.split_specs("py:Team") == ["py:Team"]
    with pytest.raises(GridError, match="py:SKILL"):
        sweep_grid.split_specs("java:Team")
    with pytest.raises(GridError):
        sweep_grid.split_specs("walker=learned,py:Team")


def test_seeds_ranges_and_lists():
    assert sweep_grid.parse_seeds("1-3,7") == [1, 2, 3, 7]
    assert sweep_grid.parse_seeds("2,2,1-2") == [2, 1]
    for bad in ("", "a", "3-1", "1-"):
        with pytest.raises(GridError):
            sweep_grid.parse_seeds(bad)


def test_set_values():
    assert sweep_grid.parse_set("rules.half_s=300,600") == ("rules.half_s", ["300", "600"])
    for bad in ("half_s=300", "rules.half_s", "rules.half_s=", "rules.half_s=300,"):
        with pytest.raises(GridError):
            sweep_grid.parse_set(bad)


def test_the_grid_is_the_product_of_its_axes_times_the_seeds():
    matches = sweep_grid.expand(["py:Team"], ["py:Striker", "cpp:Team"], {"rules.half_s": ["300", "600"]},
                                ["", "--walk-engine nao-joints"], [1, 2, 3], ["--duration", "10"])
    assert len(matches) == 1 * 2 * 2 * 2 * 3
    assert len({m["cell"] for m in matches}) == 8
    cells = {}
    for m in matches:
        cells.setdefault(m["cell"], set()).add((m["team1"], tuple(m["settings"]), m["variant"]))
    assert all(len(settings) == 1 for settings in cells.values())  # a cell is one combination
    assert len(set.union(*cells.values())) == 8                     # every combination once
    last = matches[-1]
    assert sweep_grid.launcher_args(last) == ["--team0", "py:Team", "--team1", "cpp:Team", "--set", "rules.half_s=600",
                                              "--seed", "3", "--duration", "10", "--walk-engine", "nao-joints"]
    assert sweep_grid.cell_label(last) == "py:Team v cpp:Team rules.half_s=600 [--walk-engine nao-joints]"


def test_teams_left_out_are_the_launchers_default():
    (match,) = sweep_grid.expand([], [], {}, [], [5], [])
    assert sweep_grid.launcher_args(match) == ["--seed", "5"]
    with pytest.raises(GridError, match="seeds"):
        sweep_grid.expand([], [], {}, [], [], [])


def test_grid_file(tmp_path):
    path = tmp_path / "grid.toml"
    path.write_text('seeds = "1-2"\nteam1 = ["py:Striker,cpp:Team"]\nvariants = ["", "--in-process"]\n'
                    'launch = ["--duration", "10"]\n[set]\n"rules.half_s" = [300, 600]\n')
    grid = sweep_grid.from_file(path)
    assert grid == {"team0": [], "team1": ["py:Striker", "cpp:Team"], "set": {"rules.half_s": ["300", "600"]},
                    "variants": ["", "--in-process"], "launch": ["--duration", "10"], "seeds": [1, 2]}
    path.write_text('seed = "1"\n')
    with pytest.raises(GridError, match="unknown key"):
        sweep_grid.from_file(path)
    path.write_text('team0 = "py:Team"\n')
    with pytest.raises(GridError, match="list of strings"):
        sweep_grid.from_file(path)
    path.write_text('team0 = [\n')
    with pytest.raises(GridError, match="grid file"):
        sweep_grid.from_file(path)
