"""Multi-position runs: which positions, one set of scale factors, paths that close, positions that fail."""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest

import plans
from plans.errors import AssemblyError, SceneError
from plans.graphical.scales import DRAWN_MAX, MANTISSAS
from plans.positions import CYCLE_STEPS, common_scales, parse_positions, position_text, run_positions
from tolerances import EXACT_REL

#: a crank-rocker whose crank cannot turn fully: it assembles for φ near 0 and not near 180°
#: (|AD| runs from 0.1 m to 0.5 m, and AB + BD = 0.25 m)
STUCK = """
title = "A crank that cannot turn"
[frame]
points = { O = [0, 0], D = [0.3, 0] }
[link.2]
points = { O = [0, 0], A = [0.2, 0] }
[link.3]
points = { A = [0, 0], B = [0.15, 0] }
[link.4]
points = { D = [0, 0], B = [0.1, 0] }
[driver]
crank = "2"
angle = "10 deg"
omega = "5 rad/s"
[assembly]
B = [0.25, 0.09]
"""


@pytest.fixture(scope="module")
def six_bar():
    return plans.load(plans.example_path("six-bar"))


@pytest.fixture(scope="module")
def six_bar_run(six_bar):
    return run_positions(six_bar, 4)


def _is_round(k: float) -> bool:
    exponent = math.floor(math.log10(k))
    return any(math.isclose(k, m * 10.0**e, rel_tol=1e-12) for m in MANTISSAS for e in (exponent - 1, exponent))


# --- which positions ---------------------------------------------------------------


def test_a_count_is_equally_spaced_from_the_scenes_angle_in_the_sense_of_omega(six_bar):
    # six-bar: φ = 55°, ω = −10 rad/s (clockwise): 55, 25, −5, … as the crank turns
    got = parse_positions(12, six_bar, start="scene")  # (by default from the output's extreme position: test_motion_strokes)
    assert len(got) == 12
    assert got[0] == six_bar.driver.phi
    steps = np.diff(got)
    assert np.allclose(steps, -math.radians(30), rtol=0, atol=1e-15)
    assert parse_positions("12", six_bar, start="scene") == got


def test_a_counter_clockwise_crank_is_numbered_counter_clockwise():
    scene = plans.load(plans.example_path("four-bar"))  # ω = +10 rad/s
    got = parse_positions(4, scene)
    assert np.allclose(np.degrees(np.diff(got)), 90.0)


@pytest.mark.parametrize(
    "text, degrees",
    [
        ("0,30,55,90 deg", [0, 30, 55, 90]),
        ("0, 30, 55, 90", [0, 30, 55, 90]),  # bare numbers are degrees for a crank, as --at
        ("10 deg, 0.5 rad", [10, math.degrees(0.5)]),
        ("-45°", [-45]),
    ],
)
def test_a_list_of_angles(six_bar, text, degrees):
    assert np.allclose(np.degrees(parse_positions(text, six_bar)), degrees, rtol=0, atol=1e-12)


def test_positions_of_a_linear_driver():
    ladder = plans.load(plans.example_path("ladder"))
    assert parse_positions("10, 20, 30 mm", ladder) == pytest.approx([0.01, 0.02, 0.03])
    start, end = ladder.driver.stroke
    got = parse_positions(5, ladder)
    assert got[0] == pytest.approx(start) and got[-1] == pytest.approx(end) and len(got) == 5


@pytest.mark.parametrize(
    "spec, message",
    [
        (0, "the count must be at least 1, got 0"),
        ("0, thirty deg", "positions: expected an angle such as"),
        ("1,,2", "expected numbers separated by commas"),
        ("10, 20 mm", "'10 mm' is not an angle"),
    ],
)
def test_bad_positions_are_a_scene_error(six_bar, spec, message):
    with pytest.raises(SceneError) as info:
        parse_positions(spec, six_bar)
    assert message in str(info.value)
    assert isinstance(info.value, ValueError)


def test_the_position_as_the_sheet_names_it(six_bar):
    assert position_text(six_bar, math.radians(-35)) == "φ₂ = 325.0°"
    assert position_text(plans.load(plans.example_path("ladder")), 0.12) == "s₂ = 120.0 mm"


# --- one set of scale factors ---------------------------------------------------------


def test_every_position_is_solved_both_ways_at_the_same_scale_factors(six_bar_run):
    run = six_bar_run
    assert len(run.runs) == 4 and [r.index for r in run.runs] == [0, 1, 2, 3]
    assert all(r.ok for r in run.runs)
    for r in run.runs:
        assert r.graphical.scales == run.scales
        assert r.graphical.velocity_plan.scale == run.scales["k_v"]
        assert r.graphical.acceleration_plan.scale == run.scales["k_a"]
        assert float(r.analytic.driver[0]) == r.position
        assert max(c.rel_error for c in r.comparisons) < 1e-9  # no drafting precision: the same numbers


def test_the_common_scale_fits_the_largest_plan_of_all_positions(six_bar_run):
    run = six_bar_run
    for key, plan_of in (("k_v", lambda g: g.velocity_plan), ("k_a", lambda g: g.acceleration_plan)):
        k = run.scales[key]
        assert _is_round(k)
        longest = max(v.length for r in run.runs for v in plan_of(r.graphical).vectors)
        assert longest <= DRAWN_MAX + 1e-9, key
        # and it is the smallest round factor that does: the next smaller one would draw it too long
        smaller = max(m * 10.0**e for m in MANTISSAS for e in range(-6, 6) if m * 10.0**e < k * (1 - 1e-12))
        assert longest * k / smaller > DRAWN_MAX, key


def test_common_scales_takes_the_largest_over_the_positions_and_keeps_what_is_given(six_bar_run):
    graphicals = [r.graphical for r in six_bar_run.runs]
    largest_v = max(v.length * g.velocity_plan.scale for g in graphicals for v in g.velocity_plan.vectors)
    scales = common_scales(graphicals, drawn_max=50.0, given={"k_a": 7.0})
    assert scales["k_a"] == 7.0
    assert largest_v / scales["k_v"] <= 50.0 + 1e-9
    assert largest_v / scales["k_v"] > 50.0 / 2.5


def test_given_scale_factors_are_kept(six_bar):
    run = run_positions(six_bar, "0,90 deg", k_v=0.05)
    assert run.scales["k_v"] == 0.05
    assert all(r.graphical.scales["k_v"] == 0.05 for r in run.runs)


# --- paths over the cycle -----------------------------------------------------------------


def test_the_path_of_every_point_closes_over_a_full_crank_turn(six_bar_run):
    cycle = six_bar_run.cycle
    assert len(cycle.driver) == CYCLE_STEPS + 1
    assert cycle.driver[-1] - cycle.driver[0] == pytest.approx(-2 * math.pi)  # clockwise crank
    for name in six_bar_run.scene.report:
        r = np.asarray(cycle.points[name].r)
        size = np.max(np.abs(r - r.mean()))
        assert abs(r[-1] - r[0]) <= EXACT_REL * size, name
        # and it is a closed curve, not a point: it moves between the ends
        assert np.max(np.abs(np.diff(r))) > 0


def test_the_graphical_construction_follows_the_analytic_branch_at_every_position(six_bar_run):
    for r in six_bar_run.runs:
        for name, z in r.graphical.positions.items():
            assert abs(z - r.analytic.points[name].r[0]) <= 1e-9, (r.index, name)


# --- positions that cannot be solved ------------------------------------------------------------


def test_a_position_that_cannot_assemble_is_kept_with_its_error():
    scene = plans.loads(STUCK)
    run = run_positions(scene, "10, 180, 350 deg")
    ok = [r.ok for r in run.runs]
    assert ok == [True, False, True]
    error = run.runs[1].error
    assert isinstance(error, AssemblyError)
    assert "RRR(3,4)" in str(error) and "φ = 180.0°" in str(error)
    assert run.runs[1].graphical is None and run.runs[1].analytic is None
    assert run.cycle.valid.all()  # the dense cycle: the input swings between its limit positions (issue 19)


def test_the_orchestration_modules_load_no_matplotlib():
    code = (
        "import sys, plans, plans.positions, plans.loops, plans.i18n, plans.handout\n"
        "run = plans.positions.run_positions(plans.load(plans.example_path('four-bar')), 2)\n"
        "plans.loops.loop_equations(run.runs[0].analytic)\n"
        "print('matplotlib' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"
