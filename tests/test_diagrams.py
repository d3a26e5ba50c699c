"""Cycle diagrams: the plotted curves are the analytic sweep, failures are shaded, sheet positions marked."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import plans
from plans.drawing.diagrams import NEAR_DEAD_CENTRE, cycle_axis, draw_cycle_diagrams, write_cycle_diagrams
from plans.positions import run_positions
from test_positions import STUCK

SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def six_bar():
    run = run_positions(plans.load(plans.example_path("six-bar")), 4)
    return run, dict(draw_cycle_diagrams(run.cycle, marked=run.positions))


@pytest.fixture(scope="module")
def stuck():
    """A turn of given angles (plans.solve, the scene's rates held) through the interval without assembly: the
    drawing's bands over a sweep that has one (plans' own cycle swings this input instead, issue 19)."""
    from types import SimpleNamespace

    scene = plans.loads(STUCK)
    positions = [math.radians(10), math.radians(350)]
    turn = plans.solve(scene, math.radians(10) + 2 * np.pi * np.arange(361) / 360, allow_partial=True)
    run = SimpleNamespace(cycle=turn, positions=positions)
    return run, dict(draw_cycle_diagrams(run.cycle, marked=run.positions))


def _lines(ax) -> dict[str, object]:
    return {line.get_label(): line for line in ax.get_lines() if not line.get_label().startswith("_")}


def test_links_points_and_sliders(six_bar):
    run, figures = six_bar
    assert list(figures) == ["links", "points", "sliders"]
    assert len(figures["links"].axes) == 4  # φ₃ and φ₄ together, φ₅ alone (it swings 20°, they 33° and 47°), ω, ε
    assert len(figures["points"].axes) == 2  # |v|, |a|
    assert len(figures["sliders"].axes) == 4  # s, v_rel, a_rel, |aᵏ|


def test_the_curves_are_the_analytic_values_over_the_turn(six_bar):
    run, figures = six_bar
    cycle = run.cycle
    omega_axis = figures["links"].axes[-2]
    curves = _lines(omega_axis)
    assert set(curves) == {"ω₃", "ω₄", "ω₅"}  # the sleeve 6 turns with the rod 5: not repeated; ω₂ is constant: a note
    x, y = curves["ω₄"].get_data()
    assert np.allclose(y, cycle.links["4"].omega)
    # the crank turns clockwise: x is the angle turned from position 0, 0 … 360°
    assert x[0] == 0.0 and x[-1] == pytest.approx(360.0)
    v_curves = _lines(figures["points"].axes[0])
    assert np.allclose(v_curves[r"$|v_{\mathrm{M}}|$"].get_data()[1], np.abs(cycle.points["M"].v))
    coriolis = _lines(figures["sliders"].axes[3])[r"$|a^k_{\mathrm{E}}|$"].get_data()[1]
    assert np.allclose(coriolis, np.abs(cycle.sliders["E"].coriolis))


def test_the_positions_with_sheets_are_marked_and_numbered(six_bar):
    run, figures = six_bar
    _, _, marks = cycle_axis(run.cycle, run.positions)
    assert [k for k, _ in marks] == [0, 1, 2, 3]
    assert [x for _, x in marks] == pytest.approx([0.0, 90.0, 180.0, 270.0])
    top = figures["links"].axes[0]
    vertical = [line for line in top.get_lines() if line.get_linestyle() == "--" and len(set(line.get_xdata())) == 1]
    assert sorted(float(line.get_xdata()[0]) for line in vertical) == pytest.approx([0.0, 90.0, 180.0, 270.0])
    assert [t.get_text() for t in top.texts if t.get_text().isdigit()] == ["0", "1", "2", "3"]


def _bands(ax, hatched: bool) -> list[tuple[float, float]]:
    return sorted((p.get_x(), p.get_x() + p.get_width()) for p in ax.patches if (p.get_hatch() == "///") == hatched)


def test_where_the_mechanism_cannot_assemble_is_shaded_and_not_plotted(stuck):
    run, figures = stuck
    cycle = run.cycle
    x, _, _ = cycle_axis(cycle)
    invalid_x = x[~np.asarray(cycle.valid)]
    assert invalid_x.size and 160.0 < np.median(invalid_x) < 180.0  # around φ = 180° (turned 170° from 10°)
    for fig in figures.values():
        for ax in fig.axes:
            hatched = _bands(ax, True)
            # the diagram shows the arc where it assembles (Δφ from about −65° to 45°, before position 0
            # negative) and a margin either side, hatched: the interval without assembly on both sides of the arc
            assert 1 <= len(hatched) <= 2
            lo, hi = ax.get_xlim()
            assert hi - lo < 180.0
            for line in _lines(ax).values():
                xs, ys = (np.asarray(v, dtype=float) for v in line.get_data())
                inside = np.array([any(a + 0.5 < xv < b - 0.5 for a, b in hatched) for xv in xs])
                assert not np.any(np.isfinite(ys) & inside)  # nothing plotted where it cannot assemble
                assert np.all(np.isnan(ys[inside]))
                covered = np.array([any(a - 0.5 <= xv <= b + 0.5 for a, b in hatched) for xv in xs])
                assert np.all(covered[np.isnan(ys)])  # and every position without assembly is shaded


def test_beside_an_interval_without_assembly_is_near_a_dead_centre(stuck):
    run, figures = stuck
    ax = figures["links"].axes[1]
    hatched = _bands(ax, True)
    light = _bands(ax, False)
    assert len(light) == 2  # either side of the interval where it cannot assemble (drawn at least BAND_MIN wide)
    lo, hi = ax.get_xlim()
    edges = [e for a, b in hatched for e in (a, b) if lo + 0.5 < e < hi - 0.5]  # where assembly is lost or found
    assert len(edges) == 2
    for edge in edges:
        assert any(a <= edge + 0.5 and b >= edge - 0.5 for a, b in light), (edge, light)


def test_small_sines_are_near_a_dead_centre(monkeypatch):
    import plans.drawing.diagrams as diagrams

    run = run_positions(plans.load(plans.example_path("four-bar")), 1)
    sines = np.asarray(run.cycle.sines["RRR(3,4)"])
    threshold = float(np.quantile(sines, 0.2))  # the fifth of the turn with the worst transmission angle
    monkeypatch.setattr(diagrams, "NEAR_DEAD_CENTRE", threshold)
    assert np.array_equal(diagrams._near_dead(run.cycle), sines < threshold)
    assert NEAR_DEAD_CENTRE == 0.1


def test_the_diagrams_as_svg_in_serbian(tmp_path):
    run = run_positions(plans.load(plans.example_path("four-bar")), 2)
    paths = write_cycle_diagrams(run.cycle, tmp_path, marked=run.positions, lang="sr")
    assert [p.name for p in paths] == ["links.svg", "points.svg"]  # no prismatic pair
    text = " ".join("".join(t.itertext()) for t in ET.parse(paths[0]).getroot().iter(f"{SVG}text"))
    assert "Кинематски дијаграми" in text and "угаона брзина" in text


def test_components_on_request():
    run = run_positions(plans.load(plans.example_path("slider-crank")), 2)
    figures = dict(draw_cycle_diagrams(run.cycle, components=True))
    assert len(figures["points"].axes) == 6
    labels = set(_lines(figures["points"].axes[1]))
    assert r"$v_{\mathrm{B,x}}$" in labels
    y = _lines(figures["points"].axes[1])[r"$v_{\mathrm{B,x}}$"].get_data()[1]
    assert np.allclose(y, run.cycle.points["B"].v.real)
    assert math.isfinite(float(np.nanmax(y)))
