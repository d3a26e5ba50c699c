"""Cycle diagrams: spikes near a dead centre clipped and said, angles continuous and the CSV's, bands and curves
that read in black and white, nothing flat or drawn twice, marks off the grid, numbers and words in the page's language."""

from __future__ import annotations

import csv
import io
import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import plans
from plans.cli import main
from plans.drawing.diagrams import draw_cycle_diagrams, write_cycle_diagrams
from plans.positions import run_positions

SVG = "{http://www.w3.org/2000/svg}"


def _sweep(name, steps=360):
    scene = plans.load(plans.example_path(name))
    run = run_positions(scene, 12 if isinstance(scene.driver, plans.scene.Crank) else 6, cycle_steps=steps, start="scene")
    return run


class _Turn:
    """rocker-limit over a whole turn of given angles, the scene's ω and ε held (plans.solve without rates): the
    drawing's machinery for trouble (spikes near a dead centre, bands without assembly) over a sweep that has it.
    (plans' own cycle swings this input between its limit positions instead: issue 19, test_motion_*.)"""

    def __init__(self):
        scene = plans.load(plans.example_path("rocker-limit"))
        self.positions = list(scene.driver.phi + 2 * np.pi * np.arange(12) / 12)
        self.cycle = plans.solve(scene, scene.driver.phi + 2 * np.pi * np.arange(361) / 360, allow_partial=True)


@pytest.fixture(scope="module")
def rocker_limit():
    run = _Turn()
    return run, dict(draw_cycle_diagrams(run.cycle, marked=run.positions))


def _curves(ax):
    return {line.get_label(): line for line in ax.get_lines() if not line.get_label().startswith("_")}


def _notes(ax):
    return " ".join(t.get_text().replace("\n", " ") for t in ax.texts)  # (a note is broken into the legend column's lines)


def test_a_spike_near_a_dead_centre_does_not_set_the_axis(rocker_limit):
    run, figures = rocker_limit
    cycle = run.cycle
    eps4 = np.asarray(cycle.links["4"].epsilon)
    ok = np.asarray(cycle.valid)
    biggest = float(np.nanmax(np.where(ok, eps4, np.nan)))
    assert biggest > 3e4  # rocker-limit: ε₄ reaches 35 000 rad/s² at the limit positions
    ax = figures["links"].axes[2]
    low, high = ax.get_ylim()
    assert high < biggest / 10  # the working range is what the axis shows
    # every value where both construction lines are well apart (|sin| ≥ 0.3) is inside the axis
    well = ok & (np.asarray(cycle.sines["RRR(3,4)"]) >= 0.3)
    for name in ("3", "4"):
        values = np.asarray(cycle.links[name].epsilon)[well]
        assert low <= values.min() and values.max() <= high
    # what is clipped is marked at the edge and written with its extreme
    clipped = [line for line in ax.get_lines() if line.get_label() == "_clipped"]
    assert any(line.get_marker() == "^" and line.get_ydata()[0] == pytest.approx(high) for line in clipped)
    assert "beyond the axis near a dead centre" in _notes(ax)
    assert f"ε₄: {biggest:,.0f}".replace(",", "\u2009") in _notes(ax).replace("\u2212", "-")  # 35 000: grouped by a thin space


def test_angles_are_continuous_and_the_csvs_up_to_whole_turns(rocker_limit, capsys, tmp_path):
    run, figures = rocker_limit
    from plans.sweep import sweep_csv

    rows = list(csv.DictReader(io.StringIO(sweep_csv(run.cycle))))
    # φ₄ shares its panel with φ₃: drawn as its change from the middle of its swing, the middle in its name
    ((label, line),) = [(k, v) for ax in figures["links"].axes for k, v in _curves(ax).items() if k.startswith("φ₄")]
    middle = float(label.split("\u2212")[1].rstrip("°")) if "\u2212" in label else 0.0
    curve = np.asarray(line.get_ydata(), dtype=float) + middle
    # the diagram runs over the arc where it assembles (before position 0 negative): row k of the CSV is Δφ = k°
    rows_at = np.round(np.asarray(line.get_xdata(), dtype=float)).astype(int) % 360
    from_csv = np.array([float(r["4.phi_deg"]) if r["4.phi_deg"] else np.nan for r in rows])[rows_at]
    both = np.isfinite(curve) & np.isfinite(from_csv)
    assert both.sum() > 100
    turns = (curve[both] - from_csv[both]) / 360.0
    assert np.allclose(turns, np.round(turns), atol=1e-9)  # the same angle, up to whole turns
    steps = np.diff(curve[np.isfinite(curve)])
    assert np.max(np.abs(steps)) < 20.0  # continuous, across the interval without assembly too
    assert 0.0 <= curve[np.isfinite(curve)][0] < 360.0


def test_the_bands_read_in_black_and_white(rocker_limit):
    _, figures = rocker_limit
    ax = figures["links"].axes[1]
    hatches = {p.get_hatch() for p in ax.patches}
    assert "///" in hatches  # cannot assemble
    near = [p for p in ax.patches if p.get_hatch() and "\\" in p.get_hatch()]
    assert len(near) == 2  # entering and leaving the interval without assembly
    for patch in near:
        assert max(patch.get_edgecolor()[:3]) <= 0.45  # a dark hatch, not a pale fill (dark grey: the data stays visible)
        assert patch.get_facecolor()[3] == 0.0
        lo, hi = ax.get_xlim()
        assert patch.get_width() >= 0.008 * (hi - lo) - 1e-9  # wide enough to see (0.8 % of the axis)


def test_nothing_flat_and_nothing_twice_and_every_curve_its_own_style():
    for name in plans.example_names():
        scene = plans.load(plans.example_path(name))
        if not isinstance(scene.driver, plans.scene.Crank) and scene.driver.stroke is None:
            continue
        run = run_positions(scene, 2, cycle_steps=72)
        for page, fig in draw_cycle_diagrams(run.cycle, marked=run.positions):
            for ax in fig.axes:
                curves = list(_curves(ax).values())
                data = [np.asarray(c.get_ydata(), dtype=float) for c in curves]
                for k, y in enumerate(data):
                    finite = y[np.isfinite(y)]
                    assert np.ptp(finite) > 1e-9 * max(1.0, np.max(np.abs(finite))), (name, page, curves[k].get_label())
                    for other in data[k + 1 :]:
                        assert not np.allclose(y, other, equal_nan=True), (name, page, curves[k].get_label())
                styles = [(c.get_linestyle(), c.get_marker()) for c in curves]
                assert len(set(styles)) == len(styles), (name, page)


def test_constants_of_the_scene_are_written_not_drawn():
    six = _sweep("six-bar", 72)
    links = dict(draw_cycle_diagrams(six.cycle))["links"]
    omega_axis, epsilon_axis = links.axes[-2:]  # (the angles take one panel or more: ω and ε are the last two)
    assert "ω₂" not in _curves(omega_axis) and "ε₂" not in _curves(epsilon_axis) and not any(k.startswith("φ₂") for ax in links.axes[:-2] for k in _curves(ax))
    # (a constant's note joined by no-break spaces, so a wrapped note never breaks inside "ω₂ = −10 rad/s")
    assert "ω₂\u00a0=\u00a0\u221210\u00a0rad/s  (the same at every position)" in _notes(omega_axis)  # ω = −10 rad/s in six-bar.toml
    assert "φ₂ = 55.00° \u2212 Δφ" in _notes(links.axes[0])  # clockwise from 55°
    arm = _sweep("linear-arm", 40)
    figures = dict(draw_cycle_diagrams(arm.cycle))
    # the slide 2 translates: its angle is constant, not "φ₂ = 0" beside an arm AF drawn at 56.31° (round 12's review)
    assert "φ₂\u00a0=\u00a0const  (the same at every position)" in _notes(figures["links"].axes[0])
    assert not any("φ₂\u00a0=\u00a00" in note for note in _notes(figures["links"].axes[0]))
    # the rod 3 and the rocker 4 carrying its welded sleeve turn together: one curve, both names
    omega = _curves(figures["links"].axes[-2])
    assert "ω₃ = ω₄" in omega and "ω₃" not in omega and "ω₄" not in omega
    assert np.allclose(omega["ω₃ = ω₄"].get_ydata(), arm.cycle.links["4"].omega)
    # the quick-return's block E slides on a frame guide: no Coriolis acceleration, said once
    qr = _sweep("quick-return", 40)
    coriolis = dict(draw_cycle_diagrams(qr.cycle))["sliders"].axes[3]
    assert list(_curves(coriolis)) == [r"$|a^k_{\mathrm{A}}|$"]
    assert "$|a^k_{\\mathrm{E}}|$\u00a0=\u00a00" in _notes(coriolis)


def test_position_marks_are_not_grid_lines():
    run = _sweep("six-bar", 72)
    ax = dict(draw_cycle_diagrams(run.cycle, marked=run.positions))["links"].axes[0]
    assert not any(line.get_visible() for line in ax.xaxis.get_gridlines())  # grid: horizontal lines only
    marks = [line for line in ax.get_lines() if line.get_linestyle() == "--" and len(set(line.get_xdata())) == 1]
    assert sorted(float(m.get_xdata()[0]) for m in marks) == pytest.approx(30.0 * np.arange(12))
    triangles = [line for line in ax.get_lines() if line.get_label() == "_mark"]
    assert len(triangles) == 12 and all(t.get_marker() == "v" for t in triangles)


@pytest.mark.parametrize("lang", ["sr", "ru", "bg", "sl"])
def test_diagrams_have_decimal_commas_true_minus_signs_and_no_english(tmp_path, lang):
    run = _sweep("quick-return", 72)
    paths = write_cycle_diagrams(run.cycle, tmp_path, marked=run.positions, lang=lang)
    english = re.compile(r"\b(angle|velocity|acceleration|constant|position|positions|cannot|near|beyond|travel|relative|drawn|links|points|turned|crank|driver|sliders?|kinematic)\b", re.I)
    numbers = 0
    for path in paths:
        texts = ["".join(t.itertext()) for t in ET.parse(path).getroot().iter(f"{SVG}text")]
        title = plans.load(plans.example_path("quick-return")).title
        for text in texts:
            if text == title:
                continue
            assert not english.search(text), (path.name, text)
            assert not re.search(r"\d\.\d", text), (path.name, text)  # decimal comma
            assert not re.search(r"-\d", text), (path.name, text)  # a true minus sign before a number
            numbers += bool(re.search(r"\d,\d", text))
    assert numbers >= 3


def test_a_title_is_drawn_as_plain_text(tmp_path):
    source = plans.example_path("four-bar").read_text()
    source = re.sub(r'^title = .*$', lambda m: 'title = "Pump $\\\\alpha$ 50% {x}_1"', source, flags=re.M)
    scene = plans.loads(source)
    assert scene.title == "Pump $\\alpha$ 50% {x}_1"
    solution = plans.solve(scene, np.linspace(0, 2 * math.pi, 13))
    paths = write_cycle_diagrams(solution, tmp_path)
    texts = ["".join(t.itertext()) for t in ET.parse(paths[0]).getroot().iter(f"{SVG}text")]
    assert "Pump $\\alpha$ 50% {x}_1" in texts


def test_an_angle_panel_is_not_pulled_down_to_zero():
    """A rocker angle that runs within 30°…60° is drawn over that range, not from 0 (the zero line does not widen it)."""
    import plans
    from plans.drawing.diagrams import draw_cycle_diagrams

    # (the quick-return's φ₄, about 60°…120°, has a panel of its own: angles sharing a panel are drawn as their
    # change from the middle of the swing, which holds 0 by design)
    scene = plans.load(plans.example_path("quick-return"))
    sweep = plans.solve(scene, np.radians(np.arange(0.0, 360.0, 5.0)), allow_partial=True)
    phi = np.degrees(np.unwrap(np.asarray(sweep.links["4"].phi))) % 360.0
    figures = dict(draw_cycle_diagrams(sweep))
    (ax,) = [ax for ax in figures["links"].axes if list(_curves(ax)) == ["φ₄"]]
    bottom, top = ax.get_ylim()
    assert float(np.min(phi)) > 0.0 and bottom > 0.0  # 0 is in the range only when the angle reaches it


def test_curve_markers_sit_on_the_marked_positions():
    """With positions marked, a curve's markers are drawn only at those positions (not between their lines)."""
    import plans
    from plans.drawing.diagrams import cycle_axis, draw_cycle_diagrams

    scene = plans.load(plans.example_path("six-bar"))
    steps = np.radians(np.arange(0.0, 360.0, 2.0))
    sweep = plans.solve(scene, scene.driver.phi + np.sign(scene.driver.omega) * steps, allow_partial=True)
    marked = [scene.driver.phi + np.sign(scene.driver.omega) * np.radians(30.0 * k) for k in range(12)]
    x, _, marks = cycle_axis(sweep, marked)
    expected = sorted(30.0 * k for k in range(12))
    assert [round(m, 6) for _, m in sorted(marks, key=lambda m: m[1])] == expected
    figures = dict(draw_cycle_diagrams(sweep, marked=marked))
    for ax in figures["links"].axes:
        for line in ax.get_lines():
            if line.get_label().startswith("_") or line.get_marker() in (None, "None", ""):
                continue
            shown = np.asarray(line.get_xdata())[line.get_markevery()]
            assert sorted(np.round(shown, 6)) == expected, line.get_label()
