"""Sweeps through trouble: lost assembly, dead centres crossed, one branch throughout.

* a crank-rocker whose rocker is too short for part of the turn, and a
  non-Grashof four-bar (a triple rocker): the sweep marks the interval where
  assembly is lost, reports where it stopped and resumed (with the limit
  positions interpolated, checked against their closed forms), leaves those
  rows empty, and resumes on the same branch;
* a four-bar that passes through a dead centre without losing assembly: the
  sweep reports it with its driver position;
* a linear driver whose stroke starts where the mechanism cannot assemble.
"""

import csv
import io
import math

import numpy as np
import pytest

from plans.analytic import solve
from plans.cli import main
from plans.scene import example_path, loads
from plans.sweep import analyse_sweep

GROUP = "RRR(3,4)"


def four_bar(D, r, l3, l4, angle="0 deg", hint="B = 1"):
    return f"""
title = "four-bar"
[frame]
points = {{ O = [0, 0], D = [{D}, 0] }}
[link.2]
points = {{ O = [0, 0], A = [{r}, 0] }}
[link.3]
points = {{ A = [0, 0], B = [{l3}, 0] }}
[link.4]
points = {{ D = [0, 0], B = [{l4}, 0] }}
[driver]
crank = "2"
angle = "{angle}"
omega = "10 rad/s"
[assembly]
{hint}
"""


def limit_deg(D, r, reach):
    """Crank angle [deg] in (0, 180) where |AD| = reach."""
    return math.degrees(math.acos((D * D + r * r - reach * reach) / (2 * D * r)))


SHORT_ROCKER = four_bar(0.7, 0.1, 0.45, 0.2)  # |AD| ≤ 0.65 only for |φ| ≤ 56.39°
NON_GRASHOF = four_bar(0.5, 0.3, 0.35, 0.4, angle="60 deg", hint="B = [0.5, 0.4]")  # |AD| ≤ 0.75 for |φ| ≤ 137.87°
FLAT = four_bar(0.7, 0.1, 0.6, 0.2)  # |AD| reaches AB + BD = 0.8 at φ = 180° only


def sweep(capsys, tmp_path, text, steps, *extra):
    scene = tmp_path / "scene.toml"
    scene.write_text(text)
    target = tmp_path / "sweep.csv"
    status = main(["sweep", str(scene), "--steps", str(steps), "-o", str(target), *extra])
    out, err = capsys.readouterr()
    assert status == 0 and out == "" and "Traceback" not in err
    rows = list(csv.DictReader(io.StringIO(target.read_text())))
    return rows, err.splitlines()


def check_rows(rows):
    """Cells are numbers or empty, never NaN or inf; unsolved rows are empty but for the driver."""
    for row in rows:
        for key, cell in row.items():
            assert cell == "" or math.isfinite(float(cell)), (key, cell)
        if row["assembled"] == "0":
            assert all(cell == "" for key, cell in row.items() if key not in ("driver_phi_deg", "driver_s", "assembled"))


@pytest.mark.parametrize(
    "text, start, stop, resume, limits",
    [
        (SHORT_ROCKER, 0.0, 56.0, 304.0, (limit_deg(0.7, 0.1, 0.65), 360 - limit_deg(0.7, 0.1, 0.65))),
        (NON_GRASHOF, 60.0, 137.0, 223.0, (limit_deg(0.5, 0.3, 0.75), 360 - limit_deg(0.5, 0.3, 0.75))),
    ],
    ids=["short-rocker", "non-grashof"],
)
def test_a_sweep_marks_where_assembly_is_lost_and_where_it_resumes(capsys, tmp_path, text, start, stop, resume, limits):
    rows, lines = sweep(capsys, tmp_path, text, 360)
    check_rows(rows)
    phis = np.array([float(r["driver_phi_deg"]) for r in rows])
    assembled = np.array([r["assembled"] == "1" for r in rows])
    assert phis[0] == pytest.approx(start)
    # the rows between stop and resume are exactly the unassembled ones
    inside = ((phis % 360) > stop + 0.5) & ((phis % 360) < resume - 0.5)
    assert np.array_equal(~assembled, inside)
    lost = int(inside.sum())
    assert lines[0] == f"plans: warning: the mechanism is not solved at {lost} of 360 positions; their rows have assembled = 0 and empty cells"
    head = f"plans: warning: RRR(3,4) cannot assemble from φ = {stop + 1:.1f}° to φ = {resume - 1:.1f}°: the sweep stops after φ = {stop:.1f}° (limit ≈ φ = "
    assert lines[1].startswith(head), lines[1]
    assert f"resumes at φ = {resume:.1f}° (limit ≈ φ = " in lines[1] and lines[1].endswith("on the same branch; those rows have assembled = 0 and empty cells")
    estimates = [float(x) for x in __import__("re").findall(r"limit ≈ φ = ([\d.]+)°", lines[1])]
    assert estimates == pytest.approx(list(limits), abs=0.02)  # the limits interpolated between grid positions
    assert len(lines) == 2
    # one branch throughout: B stays left of A → D (sign +1) on both sides of the gap
    A = np.array([complex(float(r["A.x"]), float(r["A.y"])) for r in rows if r["assembled"] == "1"])
    B = np.array([complex(float(r["B.x"]), float(r["B.y"])) for r in rows if r["assembled"] == "1"])
    D = complex(float(text.split("D = [")[1].split(",")[0]), 0)
    assert np.all((np.conj(D - A) * (B - A)).imag > 0)
    # the sine and the condition are in the CSV, and the sine falls towards the limit
    sines = [float(r[f"{GROUP}.sine"]) for r in rows if r["assembled"] == "1"]
    assert min(sines) < 0.2 and all(0 < s <= 1 for s in sines)
    assert all(float(r[f"{GROUP}.condition"]) >= 1 for r in rows if r["assembled"] == "1")


def test_the_analysis_api_gives_the_same_intervals():
    scene = loads(SHORT_ROCKER)
    phis = np.radians(np.arange(0.0, 360.0, 1.0))
    report = analyse_sweep(solve(scene, phis, allow_partial=True))
    (lost,) = report.lost
    assert (lost.group, lost.cause) == (GROUP, "cannot assemble")
    assert math.degrees(lost.stop) == pytest.approx(56.0) and math.degrees(lost.resume) == pytest.approx(304.0)
    assert math.degrees(lost.stop_limit) == pytest.approx(limit_deg(0.7, 0.1, 0.65), abs=0.02)
    assert math.degrees(lost.resume_limit) == pytest.approx(360 - limit_deg(0.7, 0.1, 0.65), abs=0.02)
    assert report.crossed == ()


def test_a_gap_at_the_end_of_a_turn_resumes_at_its_start(capsys, tmp_path):
    rows, lines = sweep(capsys, tmp_path, SHORT_ROCKER.replace('angle = "0 deg"', 'angle = "304 deg"'), 360)
    check_rows(rows)
    assert rows[-1]["assembled"] == "0" and rows[0]["assembled"] == "1"
    assert "RRR(3,4) cannot assemble from φ = 57.0° to φ = 303.0°: the sweep stops after φ = 56.0° (limit ≈ φ = 56.39" in lines[1]
    assert "resumes at φ = 304.0° (limit ≈ φ = 303.6" in lines[1]


@pytest.mark.parametrize("steps", [361, 719])
def test_a_dead_centre_crossed_between_grid_positions_is_reported_with_its_position(capsys, tmp_path, steps):
    rows, lines = sweep(capsys, tmp_path, FLAT, steps)
    check_rows(rows)
    assert all(r["assembled"] == "1" for r in rows)
    (line,) = lines
    assert line.startswith("plans: warning: RRR(3,4) passes a dead centre at φ ≈ "), line
    where = float(line.split("φ ≈ ")[1].split("°")[0])
    assert where == pytest.approx(180.0, abs=0.02)
    assert "joint B" in line


def test_a_dead_centre_on_a_grid_position_is_refused_there_only(capsys, tmp_path):
    rows, lines = sweep(capsys, tmp_path, FLAT, 360)
    check_rows(rows)
    unassembled = [float(r["driver_phi_deg"]) for r in rows if r["assembled"] == "0"]
    assert unassembled == pytest.approx([180.0])
    assert lines[1] == (
        "plans: warning: RRR(3,4) is at a dead centre at φ = 180.0°: the sweep stops after φ = 179.0° and resumes at "
        "φ = 181.0° on the same branch; those rows have assembled = 0 and empty cells"
    )


def test_a_coarse_sweep_past_a_dead_centre_warns_only_above_the_threshold(capsys, tmp_path):
    _, lines = sweep(capsys, tmp_path, FLAT, 361, "--warn-condition", "1e6")
    assert lines == []


def test_a_linear_stroke_that_starts_out_of_reach(capsys, tmp_path):
    text = example_path("ladder").read_text().replace('stroke = ["-60 mm", "60 mm"]', 'stroke = ["-200 mm", "60 mm"]')
    rows, lines = sweep(capsys, tmp_path, text, 27)  # s = −200, −190, …, 60 mm
    check_rows(rows)
    # the ladder reaches the wall (x = 433.0 mm) from s ≥ −66.99 mm
    solved = [float(r["driver_s"]) for r in rows if r["assembled"] == "1"]
    assert min(solved) == pytest.approx(-0.06)
    assert lines[1].startswith("plans: warning: RRP(3,4) cannot assemble from s = -200.0 mm to s = -70.0 mm: the sweep starts there and resumes at s = -60.0 mm (limit ≈ s = -6")
