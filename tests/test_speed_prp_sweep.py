"""A PRP group whose guides turn through parallel during a sweep loses assembly (issue 12).

The crank 2 carries a rod through O along its own x axis; block 3 slides on
the rod, block 4 on the vertical frame guide x = 0.2 m, pinned together at C.
C = (0.2, 0.2·tan φ): the guides are parallel at φ = 90° and 270°, where C
goes to infinity and comes back from the other side.  That is a loss of
assembly between two rows, not a dead centre that the mechanism crosses.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from plans.analytic import solve
from plans.cli import main
from plans.scene import loads
from plans.sweep import analyse_sweep

SCENE = """
title = "crank with a block on its rod, pinned to a block on a vertical guide"
[frame]
points = {{ O = [0, 0], G = [0.2, 0] }}
lines = {{ guide = {{ through = "G", angle = "90 deg" }} }}
[link.2]
points = {{ O = [0, 0], A = [0.1, 0] }}
lines = {{ rod = {{ through = "O", angle = 0 }} }}
[[slider]]
pin = "C"
on = "2.rod"
name = "3"
[[slider]]
pin = "C"
on = "frame.guide"
name = "4"
[driver]
crank = "2"
angle = "{angle} deg"
omega = "10 rad/s"
"""


def test_the_pin_is_where_the_hand_solution_puts_it():
    scene = loads(SCENE.format(angle=0.5))
    phi = np.radians([30.0, 89.5, 90.5])
    C = solve(scene, phi).points["C"].r
    assert C == pytest.approx(0.2 + 0.2j * np.tan(phi), rel=1e-13)  # C jumps from +22.9 m to −22.9 m across 90°


def test_parallel_guides_between_two_rows_are_a_loss_of_assembly_not_a_dead_centre_crossed():
    scene = loads(SCENE.format(angle=0.5))
    phis = np.radians(0.5 + np.arange(360.0))  # 0.5°, 1.5°, …: no row at 90° or 270°
    report = analyse_sweep(solve(scene, phis, allow_partial=True, warn_condition=math.inf))
    assert report.crossed == ()
    assert [(x.group, x.cause, x.between) for x in report.lost] == [("PRP(3,4)", "guides parallel", True)] * 2
    assert [math.degrees(x.first) for x in report.lost] == pytest.approx([90.0, 270.0], abs=1e-6)
    assert [math.degrees(x.stop) for x in report.lost] == pytest.approx([89.5, 269.5])
    assert [math.degrees(x.resume) for x in report.lost] == pytest.approx([90.5, 270.5])
    assert str(report.lost[0]) == (
        "PRP(3,4) loses assembly at φ ≈ 90.00°: its two guides become parallel there and the pin joining its blocks goes "
        "to infinity: the sweep stops after φ = 89.5° and resumes at φ = 90.5°; the motion between those rows does not "
        "exist (not a dead centre that can be crossed)"
    )


def test_a_full_turn_also_looks_between_the_last_row_and_the_first(capsys):
    # rows from 270.5° round to 269.5°: the guides turn through parallel between the last row and the first
    scene = loads(SCENE.format(angle=270.5))
    phis = np.radians(270.5 + np.arange(360.0))
    lost = analyse_sweep(solve(scene, phis, allow_partial=True)).lost
    assert sorted(round(math.degrees(x.first) % 360, 6) for x in lost) == [90.0, 270.0]


def test_parallel_guides_on_a_row_are_a_loss_of_assembly_there(capsys, tmp_path):
    scene_file = tmp_path / "prp.toml"
    scene_file.write_text(SCENE.format(angle=0), encoding="utf-8")
    assert main(["sweep", str(scene_file), "--steps", "360", "-o", str(tmp_path / "prp.csv")]) == 0
    lines = capsys.readouterr().err.splitlines()
    assert lines[1:] == [
        "plans: warning: PRP(3,4) loses assembly at φ = 90.0°: its two guides are parallel and the pin joining its "
        "blocks is at infinity: the sweep stops after φ = 89.0° and resumes at φ = 91.0°; those rows have assembled = 0 "
        "and empty cells",
        "plans: warning: PRP(3,4) loses assembly at φ = 270.0°: its two guides are parallel and the pin joining its "
        "blocks is at infinity: the sweep stops after φ = 269.0° and resumes at φ = 271.0°; those rows have assembled = 0 "
        "and empty cells",
    ]
    assert not any("dead centre" in line for line in lines)
