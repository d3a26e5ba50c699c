"""Sweeps through trouble: lost assembly, dead centres crossed, one branch throughout.

* a crank-rocker whose rocker is too short for part of the turn, and a
  non-Grashof four-bar (a triple rocker): over a turn of given angles the
  analysis marks the interval where assembly is lost, reports where it
  stopped and resumed (with the limit positions interpolated, checked against
  their closed forms) and resumes on the same branch; ``plans sweep`` (a
  cycle under the driver's law, issue 19) swings such an input between its
  limit positions instead, every row assembled;
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
    status = main(["sweep", str(scene), "--steps", str(steps), "-o", str(target), "--start", "scene", *extra])
    out, err = capsys.readouterr()
    assert status == 0 and out.startswith("driver law: ") and "Traceback" not in err  # the law beside the file written
    rows = list(csv.DictReader(io.StringIO(target.read_text())))
    return rows, err.splitlines()


def check_rows(rows):
    """Cells are numbers or empty, never NaN or inf; unsolved rows are empty but for the driver."""
    for row in rows:
        for key, cell in row.items():
            assert cell == "" or math.isfinite(float(cell)), (key, cell)
        if row["assembled"] == "0":
            assert all(cell == "" for key, cell in row.items() if key not in ("driver_phi_deg", "driver_s", "t", "assembled"))


@pytest.mark.parametrize(
    "text, start, stop, resume, limits",
    [
        (SHORT_ROCKER, 0.0, 56.0, 304.0, (limit_deg(0.7, 0.1, 0.65), 360 - limit_deg(0.7, 0.1, 0.65))),
        (NON_GRASHOF, 60.0, 137.0, 223.0, (limit_deg(0.5, 0.3, 0.75), 360 - limit_deg(0.5, 0.3, 0.75))),
    ],
    ids=["short-rocker", "non-grashof"],
)
def test_a_sweep_marks_where_assembly_is_lost_and_where_it_resumes(text, start, stop, resume, limits):
    """Over a turn of given angles (the API; plans sweep swings such an input instead, see the next test)."""
    scene = loads(text)
    phis = np.radians(start + np.arange(360.0))
    solution = solve(scene, phis, allow_partial=True)
    assembled = np.asarray(solution.valid)
    degrees = np.degrees(phis) % 360
    inside = (degrees > stop + 0.5) & (degrees < resume - 0.5)
    assert np.array_equal(~assembled, inside)
    (lost,) = analyse_sweep(solution).lost
    assert (lost.group, lost.cause) == (GROUP, "cannot assemble")
    assert math.degrees(lost.stop) % 360 == pytest.approx(stop) and math.degrees(lost.resume) % 360 == pytest.approx(resume)
    assert [math.degrees(lost.stop_limit) % 360, math.degrees(lost.resume_limit) % 360] == pytest.approx(list(limits), abs=0.02)
    # one branch throughout: B stays left of A → D (sign +1) on both sides of the gap
    A = np.asarray(solution.points["A"].r)[assembled]
    B = np.asarray(solution.points["B"].r)[assembled]
    D = complex(float(text.split("D = [")[1].split(",")[0]), 0)
    assert np.all((np.conj(D - A) * (B - A)).imag > 0)


@pytest.mark.parametrize("text, limit", [(SHORT_ROCKER, limit_deg(0.7, 0.1, 0.65)), (NON_GRASHOF, limit_deg(0.5, 0.3, 0.75))],
                         ids=["short-rocker", "non-grashof"])
def test_plans_sweep_swings_an_input_that_cannot_turn_fully(capsys, tmp_path, text, limit):
    """Issue 19 §2: the input swings between its limit positions and back, every row assembled, ω through zero."""
    rows, lines = sweep(capsys, tmp_path, text, 360)
    check_rows(rows)
    assert all(r["assembled"] == "1" for r in rows)
    assert not any("cannot assemble" in line for line in lines)
    phis = np.array([math.remainder(float(r["driver_phi_deg"]), 360.0) for r in rows])
    assert phis.max() < limit and phis.min() > -limit
    assert phis.max() > limit - 1.5 and phis.min() < -limit + 1.5  # the grid comes near both limits
    omega = np.array([float(r["2.omega"]) for r in rows])
    assert np.count_nonzero(np.sign(omega) != np.roll(np.sign(omega), 1)) == 2
    # the sine falls towards the limits, and the condition is at least 1
    sines = [float(r[f"{GROUP}.sine"]) for r in rows]
    assert min(sines) < 0.2 and all(0 < x <= 1 for x in sines)
    assert all(float(r[f"{GROUP}.condition"]) >= 1 for r in rows)


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


def test_a_gap_at_the_end_of_a_turn_resumes_at_its_start():
    scene = loads(SHORT_ROCKER.replace('angle = "0 deg"', 'angle = "304 deg"'))
    solution = solve(scene, np.radians(304.0 + np.arange(360.0)), allow_partial=True)
    assert not solution.valid[-1] and solution.valid[0]
    (lost,) = analyse_sweep(solution).lost
    text = str(lost)
    assert "RRR(3,4) cannot assemble from φ = 57.0° to φ = 303.0°: the sweep stops after φ = 56.0° (limit ≈ φ = 56.39" in text
    assert "resumes at φ = 304.0° (limit ≈ φ = 303.6" in text


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
