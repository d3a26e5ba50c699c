"""Positions that cannot be solved are named, with the reason, on stderr and on the page; runs go in the sense of ω."""

from __future__ import annotations

import csv
import io
import math
import re

import numpy as np
import pytest

import plans
from plans.cli import main
from plans.positions import run_positions


def _rocker_limit_assembles(phi: float) -> bool:
    """rocker-limit by hand: O = 0, OA = 0.1 m, D = (0.7, 0), AB = 0.45 m, BD = 0.2 m; B exists iff |AD| ≤ AB + BD."""
    a = 0.1 * complex(math.cos(phi), math.sin(phi))
    return abs(0.7 - a) <= 0.45 + 0.2


def _run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_draw_positions_names_every_skipped_position_and_why(capsys, tmp_path):
    status, out, err = _run(capsys, "draw", "--example", "rocker-limit", "--at", "30,90,120,150,-30 deg", "-o", str(tmp_path))
    assert status == 0
    expected = [k for k, phi in enumerate((30, 90, 120, 150, -30)) if not _rocker_limit_assembles(math.radians(phi))]
    assert expected == [1, 2, 3]  # the hand check itself: the input swings within ±56.39°
    said = [int(m) for m in re.findall(r"^plans: warning: position (\d+) \(φ₂ = [\d.]+°\) is skipped: RRR\(3,4\): joint B cannot assemble", err, re.M)]
    assert said == expected
    sheets = sorted(p.name for p in tmp_path.glob("sheet-*.svg"))
    assert sheets == ["sheet-00.svg", "sheet-04.svg"]
    # and the plan of positions says which positions it does not draw
    from sheet_pages import embedded_text

    svg = embedded_text(tmp_path / "positions.svg")  # the plan of positions, a drawing on its page
    assert "not drawn" in svg and "1–3" in svg


def test_draw_positions_of_a_swinging_input_draws_every_one(capsys, tmp_path):
    """Issue 19 §2: rocker-limit's 12 positions are spaced over its swing and back (9 of 12 were skipped over a turn)."""
    status, out, err = _run(capsys, "draw", "--example", "rocker-limit", "--positions", "12", "-o", str(tmp_path))
    assert status == 0
    assert "is skipped" not in err
    assert len(list(tmp_path.glob("sheet-*.svg"))) == 12
    import plans
    from plans.pages.sheet import positions_page
    from plans.positions import run_positions
    from sheet_pages import text

    # the law stated on the page of the plan of positions
    run = run_positions(plans.load(plans.example_path("rocker-limit")), 12)
    page = " ".join(text(positions_page(run, 0.005).pdf(), plain=False).split())
    assert "harmonic swing between −56.39° … 56.39°" in page, page


def test_handout_names_skipped_positions_on_stderr(capsys, tmp_path):
    status, _, err = _run(capsys, "handout", "--example", "rocker-limit", "--at", "30,90 deg", "-o", str(tmp_path / "h.pdf"))
    assert status == 0
    assert re.findall(r"position (\d+) \(φ₂ = 90.0°\) is skipped: RRR\(3,4\): joint B cannot assemble", err) == ["1"]
    assert "position 0 " not in err


def test_a_skipped_position_carries_its_reason():
    scene = plans.load(plans.example_path("rocker-limit"))
    run = run_positions(scene, "30,90 deg")
    solved, skipped = run.runs
    assert solved.ok and solved.reason == "" and solved.cause == ""
    assert not skipped.ok and skipped.cause == "no_assembly"
    # |AD| at φ = 90°: √(0.7² + 0.1²) = 0.7071 m against AB + BD = 0.65 m
    assert "|AD| = 0.707 m > AB + BD = 0.650 m" in skipped.reason
    assert [r.index for r in run.skipped] == [1]
    assert run.skipped_messages() == [f"position 1 (φ₂ = 90.0°) is skipped: {skipped.reason}"]


def test_sweep_and_positions_run_in_the_sense_of_omega(capsys, tmp_path):
    """six-bar: ω₂ = −10 rad/s from φ = 55°: the sweep, the run's cycle and its positions all go clockwise."""
    target = tmp_path / "sweep.csv"
    status, _, _ = _run(capsys, "sweep", "--example", "six-bar", "--steps", "360", "-o", str(target), "--start", "scene")
    assert status == 0
    phi = np.array([float(r["driver_phi_deg"]) for r in csv.DictReader(io.StringIO(target.read_text()))])
    assert phi[0] == pytest.approx(55.0)

    def turn(d):  # an angle difference in (−180°, 180°]: the CSV may write angles in [0, 360)
        return np.mod(np.asarray(d) + 180.0, 360.0) - 180.0

    assert np.allclose(turn(np.diff(phi)), -1.0)  # clockwise, one degree a step
    scene = plans.load(plans.example_path("six-bar"))
    run = run_positions(scene, 12, start="scene")
    assert np.allclose(turn(np.degrees(run.cycle.driver[:360]) - phi), 0.0)  # the handout's diagrams run through the same positions
    assert np.allclose(np.degrees(run.positions), 55.0 - 30.0 * np.arange(12))


def test_the_handout_lists_each_skipped_position_with_its_reason():
    import io

    from pypdf import PdfReader

    from plans.handout import handout

    scene = plans.load(plans.example_path("rocker-limit"))
    doc = handout(scene, positions="30,90 deg", lang="sr")
    text = "".join("".join(page.extract_text() for page in PdfReader(io.BytesIO(doc.pdf())).pages).split())
    # the list of positions says it is not solved (decimal comma of sr pages: compared without spaces)
    assert "".join("1: φ₂ = 90,0° (није решено у овом положају)".split()) in text
    # where its velocity plan would be: the solver's full reason, the group as the course names it
    assert "|AD|=0,707m>AB+BD=0,650m" in text and "група3–4" in text


def test_a_clockwise_sweep_that_loses_assembly_at_its_end_resumes_at_its_start():
    """rocker-limit turned clockwise from 55.5°: the interval without assembly runs into the end of the turn."""
    from plans.sweep import analyse_sweep

    source = plans.example_path("rocker-limit").read_text()
    source = source.replace('omega = "10 rad/s"', 'omega = "-10 rad/s"').replace('angle = "30 deg"', 'angle = "55.5 deg"')
    scene = plans.loads(source)
    # a turn of given angles (plans' cycle swings this input between its limits instead: issue 19)
    solution = plans.solve(scene, scene.driver.phi - 2 * np.pi * np.arange(360) / 360, allow_partial=True)
    (lost,) = analyse_sweep(solution).lost
    limit = math.degrees(math.acos((0.49 + 0.01 - 0.65**2) / 0.14))  # |AD| = AB + BD by the cosine rule: 56.39°
    assert math.degrees(lost.resume) % 360 == pytest.approx(55.5)
    assert math.degrees(lost.resume_limit) % 360 == pytest.approx(limit, abs=0.05)
    assert math.degrees(lost.stop_limit) % 360 == pytest.approx(360 - limit, abs=0.05)
