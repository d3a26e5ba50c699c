"""``plans bench``: its 50-digit reference, its yardstick, and a smoke run.

No timing is asserted anywhere: the machine decides those numbers.  What is
asserted: the reference reproduces domain.md's worked examples E1 and E2 and
an independent closed form to 40 digits; the yardstick agrees with the
analytic solver; a quick run covers every case and method, with finite
errors below sane bounds, a CSV that parses and an SVG that is produced
deterministically.
"""

from __future__ import annotations

import argparse
import csv
import io
import math
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

mpmath = pytest.importorskip("mpmath")

from plans.analytic import solve  # noqa: E402
from plans.bench import add_parser, run_command  # noqa: E402
from plans.bench.cases import TOGGLE_ANGLE, slider_crank_scene, suite, toggle_four_bar_scene  # noqa: E402
from plans.bench.reference import Reference, ReferenceError, reference  # noqa: E402
from plans.bench.run import CSV_FIELDS, QUICK, Settings, markdown, relative_errors, run_bench, to_csv  # noqa: E402
from plans.bench.yardstick import offset_slider_crank  # noqa: E402
from plans.scene import example_path, load  # noqa: E402

from tolerances import MPMATH_REL, WORKED_EXAMPLE_REL  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent

#: The reference against a closed form evaluated at 50 digits: both carry ~45
#: good digits (Newton stops at 1e-47 relative steps).
REFERENCE_DIGITS_REL = 1e-40

#: Sane upper bounds on the relative errors of the smoke run, per method.
#: Double precision: a few ε_mach times the condition number squared
#: (the four-bar near its toggle reaches ~1e-6, see plans.limits).
BOUND_DOUBLE = 1e-13
BOUND_TOGGLE = 1e-4
#: Polygon arcs with ≥ 4 segments per quarter circle misplace a joint by
#: ≲ (1 − cos(π/8))·radius ≈ 8 % of a link; drafting precision 0.5 mm on a
#: figure 60–120 mm long reads ≲ 1 %.
BOUND_ARCS = 1.0
BOUND_DRAFTING = 0.05


def _seed(solution, k=0):
    return {name: (float(phi[k]), complex(origin[k])) for name, (phi, origin) in solution.poses.items()}


def _ref(scene, position=None) -> Reference:
    solution = solve(scene) if position is None else solve(scene, [position])
    return reference(scene, float(solution.driver[0]), _seed(solution))


def _close(got, want, rel):
    got, want = mpmath.mpmathify(got), mpmath.mpmathify(want)
    assert abs(got - want) <= rel * max(abs(want), 1e-300), (got, want)


# --- the reference ------------------------------------------------------------------------


def test_reference_reproduces_e1_ladder():
    ref = _ref(load(example_path("ladder")))
    phi, omega, epsilon = ref.links["3"]
    r, v, a = ref.points["B"]
    # domain.md E1 (exact): ω_AB = 4, v_B = (0, 1.7320508), ε_AB = −27.7128129, a_B = (0, −16)
    assert abs(float(omega) - 4.0) <= 4.0 * WORKED_EXAMPLE_REL
    assert abs(float(epsilon) + 16 * math.sqrt(3)) <= 27.8 * WORKED_EXAMPLE_REL
    assert abs(complex(v) - 1j * math.sqrt(3)) <= 1.8 * WORKED_EXAMPLE_REL
    assert abs(complex(a) + 16j) <= 16 * WORKED_EXAMPLE_REL
    assert abs(complex(r) - (0.5 * math.cos(math.pi / 6) + 0.25j)) <= 1e-15


def test_reference_reproduces_e2_offset_slider_crank():
    ref = _ref(load(example_path("slider-crank")))
    printed = {  # domain.md E2, to the digits printed there
        "A": (None, -14.8096098 + 14.8096098j, -3101.71742 - 3101.71742j),
        "B": (0.3198513 + 0.05j, -16.0407098 + 0j, -3730.28395 + 0j),
    }
    for name, values in printed.items():
        for got, want in zip(ref.points[name], values):
            if want is not None:
                assert abs(complex(got) - want) <= 5e-8 * abs(want) + 1e-7
    phi, omega, epsilon = ref.links["3"]
    assert abs(math.degrees(float(phi)) + 4.7519838) < 1e-7
    assert abs(float(omega) + 59.4427657) < 1e-7
    assert abs(float(epsilon) - 12155.93412) < 1e-5
    assert abs(float(ref.links["2"][1]) - 209.4395102) < 1e-7


def _closed_form_slider_crank(r, l, e, omega, phi):
    """The offset slider-crank by hand at 50 digits (the yardstick's formulas, in mpmath)."""
    with mpmath.workdps(50):
        r, l, e, omega, phi = (mpmath.mpf(x) for x in (r, l, e, omega, phi))
        sin_t = (e - r * mpmath.sin(phi)) / l
        cos_t = mpmath.sqrt(1 - sin_t**2)
        w3 = -r * omega * mpmath.cos(phi) / (l * cos_t)
        e3 = (r * omega**2 * mpmath.sin(phi) + l * w3**2 * sin_t) / (l * cos_t)
        xb = r * mpmath.cos(phi) + l * cos_t
        vb = -r * omega * mpmath.sin(phi) - l * w3 * sin_t
        ab = -r * omega**2 * mpmath.cos(phi) - l * e3 * sin_t - l * w3**2 * cos_t
        return {"B": (mpmath.mpc(xb, e), mpmath.mpc(vb, 0), mpmath.mpc(ab, 0)), "3": (None, w3, e3)}


@pytest.mark.parametrize("length, rate", [(1.0, 1.0), (1e-5, 1e4), (1e3, 1e-5)])
@pytest.mark.parametrize("degrees", [45.0, 100.0, 250.0])
def test_reference_matches_closed_form_to_40_digits_at_any_scale(length, rate, degrees):
    scene = slider_crank_scene(length, rate)
    phi = math.radians(degrees)
    ref = _ref(scene, phi)
    cylinder = scene.frame.lines["cylinder"]
    want = _closed_form_slider_crank(
        abs(scene.bodies["2"].points["A"]), abs(scene.bodies["3"].points["B"]), cylinder.origin.imag,
        scene.driver.omega, phi,
    )
    with mpmath.workdps(50):
        for got, expected in zip(ref.points["B"], want["B"]):
            assert abs(got - expected) <= REFERENCE_DIGITS_REL * abs(expected)
        for got, expected in zip(ref.links["3"][1:], want["3"][1:]):
            assert abs(got - expected) <= REFERENCE_DIGITS_REL * abs(expected)
    assert ref.residual < 1e-45


def test_reference_does_not_take_its_digits_from_the_seed():
    scene = load(example_path("six-bar"))
    solution = solve(scene)
    exact = reference(scene, float(solution.driver[0]), _seed(solution))
    rough = {name: (phi * (1 + 1e-4), origin * (1 + 1e-4)) for name, (phi, origin) in _seed(solution).items()}
    again = reference(scene, float(solution.driver[0]), rough)
    assert again.iterations > exact.iterations
    with mpmath.workdps(50):
        for name in exact.points:
            for x, y in zip(exact.points[name], again.points[name]):
                assert abs(x - y) <= 1e-44 * (1 + abs(x))


def test_reference_refuses_a_seed_far_from_any_solution():
    scene = load(example_path("slider-crank"))
    seed = {name: (phi + 2.0, origin + 0.3) for name, (phi, origin) in _seed(solve(scene)).items()}
    with pytest.raises(ReferenceError):
        reference(scene, math.radians(45), seed)


def test_analytic_solver_agrees_with_reference_on_every_example():
    for name in ("four-bar", "six-bar", "quick-return", "linear-arm", "wedge", "scotch-yoke"):
        scene = load(example_path(name))
        solution = solve(scene)
        ref = reference(scene, float(solution.driver[0]), _seed(solution))
        values = {p: (m.r[0], m.v[0], m.a[0]) for p, m in solution.points.items()}
        assert max(relative_errors(ref, values)) < MPMATH_REL, name


def test_relative_errors_follow_their_definition():
    ref = _ref(load(example_path("slider-crank")))
    exact = {name: ref.complex(name) for name in ref.points}
    assert relative_errors(ref, exact) == pytest.approx((0.0, 0.0, 0.0), abs=1e-16)
    moved = dict(exact)
    r, v, a = moved["A"]
    largest_v = max(abs(ref.complex(name)[1]) for name in ref.points)
    moved["A"] = (r, v + 0.5, a)
    assert relative_errors(ref, moved)[1] == pytest.approx(0.5 / largest_v, rel=1e-12)
    moved["A"] = (r, complex(math.nan, 0), a)
    assert all(math.isnan(e) for e in relative_errors(ref, moved))


# --- the yardstick and the cases -----------------------------------------------------------


def test_yardstick_agrees_with_the_general_solver():
    scene = load(example_path("slider-crank"))
    phi = np.linspace(0, 2 * np.pi, 721)
    general = solve(scene, phi)
    points, (theta, w3, e3) = offset_slider_crank(phi, 0.1, 0.25, 0.05, scene.driver.omega)
    for name in ("A", "B"):
        for k, key in enumerate(("r", "v", "a")):
            want = getattr(general.points[name], key)
            assert np.max(np.abs(points[name][k] - want)) <= 1e-12 * np.max(np.abs(want))
    assert np.allclose(w3, general.links["3"].omega, rtol=1e-12, atol=1e-12 * 60)
    assert np.allclose(e3, general.links["3"].epsilon, rtol=1e-10, atol=1e-12 * 3e4)


def test_suite_has_every_example_and_the_stiff_cases():
    cases = suite(samples=4)
    names = [case.name for case in cases]
    from plans.scene import example_names

    assert names == example_names() + ["four-bar-toggle", "slider-crank-micro", "slider-crank-large"]
    for case in cases:
        assert len(case.samples) == 4
        positions, index = case.grid(1000)
        assert np.array_equal(positions[index], np.asarray(case.samples))
        few, first = case.grid(2)
        assert np.array_equal(few, np.asarray(case.samples[:2])) and list(first) == [0, 1]


def test_toggle_case_approaches_its_dead_centre():
    scene = toggle_four_bar_scene(1e-9)
    solution = solve(scene, allow_partial=True)
    sine = float(next(iter(solution.sines.values()))[0])
    assert 1e-6 < sine < 1e-3  # near, but not at, the dead centre
    beyond = solve(scene, [TOGGLE_ANGLE + 1e-6], allow_partial=True)
    assert not beyond.valid[0]


# --- the smoke run ---------------------------------------------------------------------------

TINY = Settings(ns=(1, 64), yardstick_ns=(64,), samples=2, arc_segments=(8,), precisions=(0.5,), budget=0.0, processes=False)


@pytest.fixture(scope="module")
def tiny():
    return run_bench(TINY)


def _bound(row):
    if row.method == "graphical arcs":
        return BOUND_ARCS
    if row.method == "graphical drafting":
        return BOUND_DRAFTING
    return BOUND_TOGGLE if row.case == "four-bar-toggle" else BOUND_DOUBLE


def test_smoke_run_covers_every_case_and_method_with_sane_errors(tiny):
    cases = [case.name for case in suite(2)]
    methods = {"analytic", "graphical exact", "graphical arcs", "graphical drafting"}
    for case in cases:
        found = {row.method for row in tiny.rows if row.case == case}
        want = methods | ({"yardstick"} if case.startswith("slider-crank") else set())
        assert found == want, case
    for row in tiny.rows:
        assert row.compared >= 1, row
        assert row.seconds > 0 and math.isfinite(row.seconds), row
        for error in (row.err_r, row.err_v, row.err_a):
            assert math.isfinite(error) and 0 <= error < _bound(row), row
    # exact methods are exact: positions to double precision, away from the toggle
    for row in tiny.rows:
        if row.method in ("analytic", "yardstick", "graphical exact") and row.case != "four-bar-toggle":
            assert row.err_r < 1e-14, row


def test_smoke_run_markdown_and_csv(tiny):
    text = markdown(tiny)
    for row in tiny.rows:
        assert f"| {row.case} | {row.method} | {row.setting} |" in text
    assert "Ran on:" in text and "Python" in text
    assert "| target | goal | measured |" in text
    table = list(csv.DictReader(io.StringIO(to_csv(tiny))))
    assert len(table) == len(tiny.rows)
    assert tuple(table[0]) == CSV_FIELDS
    for line in table:
        assert float(line["seconds_per_position"]) > 0
        assert math.isfinite(float(line["err_v"]))


def test_svg_is_deterministic_and_has_a_series_per_case(tiny):
    from plans.bench.plot import render_svg

    first, second = render_svg(tiny), render_svg(tiny)
    assert first == second
    root = ET.fromstring(first)
    assert root.tag.endswith("svg")
    text = first.decode("utf-8")
    assert "<dc:date>" not in text
    for case in {row.case for row in tiny.rows}:
        assert case in text


def _parse(argv):
    parser = argparse.ArgumentParser(prog="plans")
    add_parser(parser.add_subparsers(dest="command"))
    return parser.parse_args(["bench", *argv])


def test_command_writes_csv_md_and_svg(tmp_path, capsys):
    status = run_command(_parse(["--quick", "--case", "slider-crank", "--case", "four-bar-toggle", "-o", str(tmp_path)]))
    assert status == 0
    out = capsys.readouterr().out
    assert "| slider-crank | yardstick |" in out and "four-bar-toggle" in out
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bench.csv", "bench.md", "error_vs_time.svg"]
    assert (tmp_path / "bench.md").read_text(encoding="utf-8") == out
    rows = list(csv.DictReader((tmp_path / "bench.csv").open(encoding="utf-8")))
    assert {row["case"] for row in rows} == {"slider-crank", "four-bar-toggle"}
    ET.parse(tmp_path / "error_vs_time.svg")


def test_command_names_an_unknown_case(capsys):
    assert run_command(_parse(["--quick", "--case", "nine-bar"])) == 2
    assert "no bench case nine-bar" in capsys.readouterr().err


def test_command_without_mpmath_says_so(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "mpmath", None)
    assert run_command(_parse(["--quick"])) == 2
    assert "needs mpmath" in capsys.readouterr().err


def test_quick_settings_stay_small():
    assert max(QUICK.ns) <= 3600 and QUICK.samples <= 3 and not QUICK.processes


def test_declaring_the_command_imports_nothing_heavy():
    code = (
        "import sys, argparse; import plans.bench as b; "
        "b.add_parser(argparse.ArgumentParser().add_subparsers()); "
        "print(sorted(m for m in ('mpmath', 'matplotlib', 'shapely', 'numpy') if m in sys.modules))"
    )
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "[]"
