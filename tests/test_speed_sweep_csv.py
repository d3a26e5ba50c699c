"""The sweep CSV writes numbers as people write them (issue 9 §2), column by column.

Expected cells are typed here, not computed by plans.
"""

from __future__ import annotations

import csv
import io

import pytest

from plans.cli import main
from plans.sweep import format_column


@pytest.mark.parametrize(
    "values, degrees, cells",
    [
        # inputs come back as given: one or two ulps off a short decimal are that decimal
        ([57.00000000000001, 411.99999999999994, 0.30000000000000004], False, ["57", "412", "0.3"]),
        # round-off far below the column's scale prints as 0 (and never as -0)
        ([-6.77126e-18, 1.25, -0.0], False, ["0", "1.25", "0"]),
        # but a small value in a column of small values keeps its digits
        ([-6.77126e-18, 1e-17], False, ["-6.77126e-18", "1e-17"]),
        # 14 significant digits at the column's scale (the solver is right to ~1e-14 of the mechanism's scale)
        ([1.2345678901234567, 0.1, 3e-15], False, ["1.2345678901235", "0.1", "0"]),
        # angles in [0, 360): negative ones turned by a full turn, 360 and round-off below it are 0
        ([29.999999999999996, -90.0, 370.0, 359.99999999999994, 720.0000000000001], True, ["30", "270", "10", "0", "0"]),
        # NaN and infinity are empty cells
        ([float("nan"), float("inf"), 2.0], False, ["", "", "2"]),
    ],
)
def test_format_column(values, degrees, cells):
    assert format_column(values, degrees=degrees) == cells


def test_cells_not_shown_are_empty_and_do_not_set_the_scale():
    assert format_column([1e6, 1.0000000000000002, 2.5], shown=[False, True, True]) == ["", "1", "2.5"]


def _sweep(capsys, tmp_path, *argv):
    target = tmp_path / "sweep.csv"
    assert main(["sweep", *argv, "-o", str(target)]) == 0
    capsys.readouterr()
    return target.read_text(encoding="utf-8")


def test_a_crank_sweep_gives_the_scene_angle_as_typed_and_angles_from_0_to_360(capsys, tmp_path):
    # quick-return.toml: angle = "30 deg", ω = 6 rad/s; the ram (link 6) slides on a horizontal guide
    text = _sweep(capsys, tmp_path, "--example", "quick-return", "--steps", "12", "--start", "scene")
    rows = list(csv.DictReader(io.StringIO(text)))
    assert [row["driver_phi_deg"] for row in rows] == ["30", "60", "90", "120", "150", "180", "210", "240", "270", "300", "330", "0"]
    assert [row["2.phi_deg"] for row in rows] == [row["driver_phi_deg"] for row in rows]
    assert {row["2.omega"] for row in rows} == {"6"}
    assert {row["6.phi_deg"] for row in rows} == {"0"}
    for row in rows:
        for key, cell in row.items():
            if key.endswith("phi_deg"):
                assert 0 <= float(cell) < 360, (key, cell)
            assert "e-1" not in cell or key.endswith(("expected_rel_error", "sine")), (key, cell)  # no round-off noise
    # at φ = 90° the crank pin A = O + 0.12 m·(cos 90°, sin 90°) = (0, 0.37) m: typed from the scene's data
    assert (rows[2]["A.x"], rows[2]["A.y"]) == ("0", "0.37")
    # and it moves at ω·OA = 0.72 m/s to the left
    assert (rows[2]["A.vx"], rows[2]["A.vy"]) == ("-0.72", "0")


def test_a_linear_sweep_gives_the_stroke_as_typed(capsys, tmp_path):
    # wedge.toml: stroke = ["-100 mm", "100 mm"]
    text = _sweep(capsys, tmp_path, "--example", "wedge", "--steps", "5")
    rows = list(csv.DictReader(io.StringIO(text)))
    assert [row["driver_s"] for row in rows] == ["-0.1", "-0.05", "0", "0.05", "0.1"]


def test_the_csv_is_the_same_on_every_run(capsys, tmp_path):
    first = _sweep(capsys, tmp_path, "--example", "six-bar", "--steps", "90")
    assert _sweep(capsys, tmp_path, "--example", "six-bar", "--steps", "90") == first
    assert first.endswith("\n") and first.count("\n") == 91
