"""A mechanisms teacher's review of the sweep's diagrams: legible scale symbols, curves closed over the cycle,
notes beside the axes (never over the data), positions 0 and 0′ marked and explained, no panel of zeros,
the crank's law in angular words."""

from __future__ import annotations

import math

import numpy as np
import pytest

import plans
from plans.drawing.diagrams import draw_cycle_diagrams
from plans.i18n import term
from plans.motion import driver_cycle, strokes


def _drawn(name, steps=72, lang="en"):
    scene = plans.load(plans.example_path(name))
    cycle = driver_cycle(scene, steps)
    analytic = cycle.solve(warn_condition=math.inf)
    found = strokes(scene, None, analytic.structure)
    return cycle, dict(draw_cycle_diagrams(analytic, lang=lang, cycle=cycle, extremes=found))


@pytest.fixture(scope="module")
def four_bar():
    return _drawn("four-bar")


def _curves(ax):
    return [line for line in ax.get_lines() if not line.get_label().startswith("_")]


def test_a_turn_is_closed_at_360_degrees(four_bar):
    _, figures = four_bar
    for name in ("links", "points"):
        for ax in figures[name].axes:
            for line in _curves(ax):
                x, y = (np.asarray(a, dtype=float) for a in line.get_data())
                assert x[-1] == pytest.approx(360.0)  # not 355°: the cycle repeats
                assert x[-2] == pytest.approx(355.0)
                assert y[-1] == pytest.approx(y[0], abs=1e-9 * max(1.0, float(np.nanmax(np.abs(y)))))


def test_a_swing_is_closed_at_its_period():
    cycle, figures = _drawn("rocker-limit")
    period = 2 * math.pi / cycle.law.frequency
    for ax in figures["links"].axes:
        for line in _curves(ax):
            x, y = (np.asarray(a, dtype=float) for a in line.get_data())
            assert x[-1] == pytest.approx(period)
            assert y[-1] == pytest.approx(y[0])


def test_the_constant_notes_stand_beside_the_axes(four_bar):
    _, figures = four_bar
    omega = figures["links"].axes[-2]
    notes = [t for t in omega.texts if "ω₂" in t.get_text()]
    assert notes, "ω₂ = 10 rad/s is written in the ω panel"
    for note in notes:
        x, _ = note.get_position()
        assert note.get_transform() == omega.transAxes and x > 1.0  # in the legend's column, right of the plotting area


def test_positions_0_and_0_prime_are_marked_and_explained(four_bar):
    _, figures = four_bar
    ax = figures["links"].axes[0]
    lines = [line for line in ax.get_lines() if line.get_linestyle() in ("--", ":") and len(line.get_xdata()) == 2
             and line.get_xdata()[0] == line.get_xdata()[1]]
    xs = sorted(float(line.get_xdata()[0]) for line in lines)
    assert xs[0] == pytest.approx(0.0)  # position 0, where the sweep starts (the output's extreme)
    assert len(xs) == 2 and 150.0 < xs[1] < 250.0  # 0′: the four-bar's other extreme, after ~200° of the crank
    labels = [t.get_text() for legend in figures["links"].legends for t in legend.get_texts()]
    assert "0, 0′ — extreme positions of the output link" in labels
    assert [t.get_text() for t in ax.texts if t.get_text() in ("0", "0′")] == ["0", "0′"]


def test_a_coriolis_panel_of_zeros_is_dropped_with_a_note():
    _, figures = _drawn("slider-crank", lang="sr")
    sliders = figures["sliders"]
    assert len(sliders.axes) == 3  # s, vʳ, aʳ: the slider's guide is the frame, aᵏ ≡ 0
    assert not any("ᵏ" in ax.get_ylabel() for ax in sliders.axes)
    page = " ".join(t.get_text() for t in sliders.texts)
    assert "Кориолисово убрзање aᵏ = 0 у сваком положају" in page
    assert "Клизни парови: положај на вођици, релативна брзина и убрзање" in page  # not "… и Кориолисово убрзање"
    assert "положај на вођици" in sliders.axes[0].get_ylabel()  # s named alike on the page and its axis


def test_the_near_dead_centre_hatch_says_the_sine_of_what():
    # rocker-limit over a whole turn (the scene's ω held): intervals near a dead centre
    scene = plans.load(plans.example_path("rocker-limit"))
    analytic = plans.solve(scene, scene.driver.phi + 2 * np.pi * np.arange(73) / 72, allow_partial=True)
    links = dict(draw_cycle_diagrams(analytic, lang="sl"))["links"]
    labels = " ".join(t.get_text() for legend in links.legends for t in legend.get_texts())
    assert "|sin γ| < 0,1" in labels and "γ — kot med konstrukcijskima premicama skupine" in labels


@pytest.mark.parametrize("lang, crank, linear", [
    ("sr", "константна угаона брзина", "константна брзина"),
    ("ru", "постоянная угловая скорость", "постоянная скорость"),
    ("bg", "постоянна ъглова скорост", "постоянна скорост"),
    ("sl", "konstantna kotna hitrost", "konstantna hitrost"),
    ("en", "constant angular velocity", "constant speed"),
])
def test_a_crank_at_constant_rate_turns_at_constant_angular_velocity(lang, crank, linear):
    four_bar = driver_cycle(plans.load(plans.example_path("four-bar")), 12).law
    arm = driver_cycle(plans.load(plans.example_path("linear-arm")), 12).law
    assert arm.kind == "constant" and four_bar.kind == "constant"
    assert f": {crank}:" in four_bar.describe(lang, "2")
    assert f": {linear}:" in arm.describe(lang, "2") and crank not in arm.describe(lang, "2")
    assert term("law_constant", lang) == linear


def test_a_swings_law_is_stated_as_plotted():
    # the stated law, read back from its words, gives the plotted positions and rates at the plotted times
    import re

    cycle, figures = _drawn("rocker-limit")
    law = cycle.law.describe("en", "2", phase=float(cycle.phase[0]))
    found = re.search(r"φ₂ = φc − A·cos Ω\(t \+ t₀\), t₀ = ([0-9.]+) s, φc = (−?[0-9.]+)°, A = ([0-9.]+)°, Ω = ([0-9.]+) rad/s", law)
    assert found, law
    t0, centre, amplitude, omega = (float(g.replace("−", "-")) for g in found.groups())
    t = np.asarray(cycle.t)
    phi = np.radians(centre) - np.radians(amplitude) * np.cos(omega * (t + t0))
    assert np.allclose(phi, cycle.positions, atol=2e-3)  # to the 4 digits stated
    rate = np.radians(amplitude) * omega * np.sin(omega * (t + t0))
    assert rate[0] == pytest.approx(cycle.rate[0], rel=2e-3) and abs(rate[0]) > 5.0  # at t = 0 the input moves
    assert "the scene's instant: |ω₂| = 10 rad/s at φ₀ = 30°" in law
    page = " ".join(t.get_text() for t in figures["links"].texts)
    assert "Ω(t + t₀)" in page


def test_a_swings_angles_are_drawn_as_they_are():
    cycle, figures = _drawn("rocker-limit")
    labels = [line.get_label() for ax in figures["links"].axes for line in _curves(ax)]
    assert not any("°" in label for label in labels)  # no "φ₂ − 360.0°": no offsets on a swing, for every link alike
    phi2 = next(line for ax in figures["links"].axes for line in _curves(ax) if line.get_label() == "φ₂")
    x, y = (np.asarray(a, dtype=float) for a in phi2.get_data())
    assert np.allclose(y[:len(cycle.positions)], np.degrees(cycle.positions))  # −56° … 56°, as the law states it


def test_a_swings_input_stops_at_its_limit_positions():
    # the sweep's diagrams sample the limit positions at their times: |v_A| of the swinging input reaches 0 there
    scene = plans.load(plans.example_path("rocker-limit"))
    cycle = driver_cycle(scene, 72, limits=True)
    assert len(cycle.positions) == 74  # the two limit positions added, at ψ = kπ
    limit = np.abs(np.sin(np.asarray(cycle.phase))) < 1e-3
    assert limit.sum() == 2 and np.all(np.abs(cycle.rate[limit]) < 2e-4 * np.max(np.abs(cycle.rate)))  # (1e-4 of phase past them)
    figures = dict(draw_cycle_diagrams(cycle.solve(warn_condition=math.inf), cycle=cycle))
    v_a = next(line for line in _curves(figures["points"].axes[0]) if "A" in line.get_label())
    assert float(np.nanmin(v_a.get_ydata())) < 1e-3  # not ~0.05 m/s: the limit positions are sampled exactly


def test_the_cranks_rate_reads_the_same_in_the_panel_and_the_law():
    _, figures = _drawn("slider-crank", lang="sr")
    points = figures["points"]
    page = " ".join(t.get_text() for t in points.texts)
    assert "ω₂ = 209,4 rad/s" in page  # the law under the title: 2000 rpm = 209.44 rad/s
    links = figures["links"]
    notes = " ".join(t.get_text().replace("\n", " ").replace("\u00a0", " ") for ax in links.axes for t in ax.texts)  # (no-break spaces)
    assert "ω₂ = 209,4 rad/s" in notes and "209 rad/s" not in notes


def test_five_digit_numbers_are_grouped_with_a_thin_space():
    from matplotlib.figure import Figure

    from plans.drawing.diagrams import _Ticks, _number

    ax = Figure().add_subplot()
    ax.set_ylim(-5000.0, 16000.0)
    ticks = _Ticks("sr")
    ax.yaxis.set_major_formatter(ticks)
    ticks.set_locs([-5000.0, 0.0, 15000.0])
    assert ticks(15000.0) == "15\u2009000"
    assert ticks(-5000.0) == "−5000"  # four digits stay whole
    assert _number(15000.0, "sr", 4) == "15\u2009000" and _number(0.123456, "en", 4) == "0.1235"


@pytest.fixture(scope="module")
def sheets():
    from plans.differentiation import kinematic_diagrams

    return {name: kinematic_diagrams(plans.load(plans.example_path(name)), 12) for name in ("four-bar", "rocker-limit", "slider-crank")}


def test_the_kinematic_sheet_defines_its_displacement(sheets):
    from plans.drawing.kinematic_diagrams import header_lines

    rocker = " ".join(header_lines(sheets["four-bar"], "en"))
    assert "ψ₄ = φ₄ − φ₄(0): measured from position 0, an extreme position of the output link, counter-clockwise positive" in rocker
    assert "Δt = T/12 = 0.05236 s" in rocker and "equal time steps" in rocker  # 2π/10 rad/s over 12
    slider = " ".join(header_lines(sheets["slider-crank"], "sr"))
    assert "мери се од положаја 0, крајњег положаја излазног члана, позитивно у смеру вођице" in slider
    swing = " ".join(header_lines(sheets["rocker-limit"], "en"))
    assert "Ω(t + t₀)" in swing and "the scene's instant" in swing


def test_the_kinematic_table_is_numbered_in_the_readers_words(sheets):
    from plans.drawing.kinematic_diagrams import diagrams_table

    assert diagrams_table(sheets["four-bar"], "en")[0][0] == "No."
    assert diagrams_table(sheets["four-bar"], "ru")[0][0] == "№ п/п"


def test_the_swings_diagrams_fill_one_page(sheets):
    """The three diagrams of each output, at the scales that draw them at least 40 mm tall, take one A4 page's
    room under the data lines (the table flows on with the page's words)."""
    from plans.drawing.kinematic_diagrams import PAGE_ROOM, diagram_svgs, page_diagrams

    for name in ("four-bar", "rocker-limit", "slider-crank"):
        blocks = diagram_svgs(page_diagrams(sheets[name], 175.0), "en")
        assert len(blocks) == 3 and sum(b.height for b in blocks.values()) <= PAGE_ROOM + 3.0, name


@pytest.mark.parametrize("lo, hi", [(-6.8, 4.3), (-3.5, 7.0), (-120.0, 110.0)])
def test_an_ordinate_across_0_has_a_tick_on_each_side(lo, hi):
    from plans.drawing.kinematic_diagrams import _ticks

    values = _ticks(lo, hi, 28.0)
    assert (values > 0).any() and (values < 0).any()
    assert np.min(np.diff(values)) / (hi - lo) * 28.0 >= 4.0  # still legible: 4 mm apart at least


def test_a_single_diagrams_note_stands_above_it():
    # the lecture page's diagrams (plot_cycle) have no legend column: the note goes above the axes, not over the data
    from plans.drawing.diagrams import plot_cycle

    scene = plans.load(plans.example_path("four-bar"))
    cycle = driver_cycle(scene, 72)
    ax = plot_cycle(cycle.solve(), "omega", cycle=cycle, marked=driver_cycle(scene, 6))[0].axes
    notes = [t for t in ax.texts if "ω₂" in t.get_text()]
    assert len(notes) == 1
    ax.figure.canvas.draw()
    box = notes[0].get_window_extent().transformed(ax.transAxes.inverted())
    assert box.y0 > 1.0  # above the plotting area
    numbers = [t for t in ax.texts if t.get_text() in {"0", "1", "2", "3", "4", "5"}]
    assert len(numbers) == 6 and all(not box.overlaps(n.get_window_extent().transformed(ax.transAxes.inverted())) for n in numbers)


def test_a_sliders_name_in_the_diagrams_is_its_coincident_points_not_a_word(tmp_path):
    # linear-arm's pair "sleeve" (rod 3 in sleeve 4 through F): a Bulgarian legend says s_F3F4, no word in a subscript
    from plans.drawing.diagrams import draw_cycle_diagrams

    scene = plans.load(plans.example_path("linear-arm"))
    run = plans.solve(scene, np.linspace(*scene.driver.stroke, 9), allow_partial=True)
    texts = []
    for name, fig in draw_cycle_diagrams(run, lang="bg"):
        texts += [t.get_text() for t in fig.findobj(lambda a: hasattr(a, "get_text"))]
    joined = " ".join(texts)
    assert "F3F4" in joined and "втулка" not in joined and "sleeve" not in joined
