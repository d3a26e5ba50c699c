"""Rendering made faster without changing what is drawn (issue 11 §6).

Each shortcut is checked against matplotlib doing the same work its own way:
math parses and text sizes
shared among parsers and renderers (the same numbers as a fresh parse), the
axes of plans' figures (the same SVG as matplotlib's Axes), and the clearance
tests of the positions plan (the same answers as measuring every pair).
"""

from __future__ import annotations


import numpy as np
import pytest
import shapely
from matplotlib.backends.backend_svg import FigureCanvasSVG
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties
from matplotlib.mathtext import MathTextParser
from matplotlib.textpath import TextToPath

from plans.drawing import svg
from plans.drawing.svg import drawing_rc, new_figure, render_svg

pypdf = pytest.importorskip("pypdf")


def _text_figure():
    fig = new_figure(120, 80)
    ax = fig.add_axes([0, 0, 1, 1])
    ax.set_axis_off()
    ax.text(0.05, 0.9, "A₀, B, C", fontsize=10)
    ax.text(0.05, 0.8, "Кривајни механизам 30,0°", fontsize=9, fontweight="bold")
    ax.text(0.05, 0.7, "ω₂ = −10 rad/s", fontsize=8, fontstyle="italic", color="#1f4e9a")
    ax.text(0.05, 0.6, r"$k_{v}$ = 0.02 (m/s)/mm", fontsize=8.5)  # math: matplotlib's own path
    ax.text(0.5, 0.3, "rotated", fontsize=8, rotation=30)  # rotated: matplotlib's own path
    ax.text(0.05, 0.4, "two\nlines", fontsize=8)
    ax.text(0.95, 0.1, "right, top", fontsize=7, ha="right", va="top")
    return fig


def test_a_math_string_is_parsed_once_for_every_parser_and_as_matplotlib_parses_it():
    text = r"$a^{n}_{\mathrm{CA}}$ = 0.47 mm"
    prop = FontProperties(family="DejaVu Sans", size=8.5)
    with drawing_rc():
        alone = MathTextParser("path").parse(text, 72, prop)  # matplotlib's own cache: not shared
    svg._MATH_PARSES.clear()
    original = MathTextParser.__dict__["_parse_cached"]
    with drawing_rc():
        first = MathTextParser("path").parse(text, 72, prop)
        second = MathTextParser("path").parse(text, 72, prop)
        assert MathTextParser.__dict__["_parse_cached"] is not original
        with drawing_rc():  # nested: still shared, put back only by the outermost
            third = MathTextParser("path").parse(text, 72, prop)
        bigger = MathTextParser("path").parse(text, 72, FontProperties(family="DejaVu Sans", size=12))
    assert first is second is third
    assert len(svg._MATH_PARSES) == 2 and bigger.width > first.width
    assert (first.width, first.height, first.depth) == (alone.width, alone.height, alone.depth)
    assert [g[1:] for g in first.glyphs] == [g[1:] for g in alone.glyphs]
    assert MathTextParser.__dict__["_parse_cached"] is original  # matplotlib's again outside drawing


def test_a_plain_string_is_measured_once_for_every_renderer_as_matplotlib_measures_it():
    prop = FontProperties(family="DejaVu Sans", size=9.0, weight="bold")
    expected = TextToPath().get_text_width_height_descent("Положај 3", prop, ismath=False)
    svg._TEXT_SIZES.clear()
    with drawing_rc():
        a = TextToPath().get_text_width_height_descent("Положај 3", prop, ismath=False)
        b = TextToPath().get_text_width_height_descent("Положај 3", prop, ismath=False)
        prop.set_size(18.0)  # the key holds a copy: a changed font is measured again
        c = TextToPath().get_text_width_height_descent("Положај 3", prop, ismath=False)
    assert a == b == pytest.approx(expected, rel=0, abs=0)
    assert c[0] == pytest.approx(2 * a[0], rel=1e-9)
    assert len([k for k in svg._TEXT_SIZES if k[0] == "TextToPath"]) == 2


def _axes_svg(fig) -> bytes:
    ax = fig.add_axes([0.15, 0.15, 0.75, 0.75])
    ax.plot([0, 1, 2, 3], [0, 1, 0.5, 2], lw=1.2)
    ax.grid(True)
    ax.tick_params(direction="in", labelsize=7)
    ax.set_xlabel("φ₂, °")
    ax.set_title("ω₃")
    return render_svg(fig)


def test_the_axes_of_plans_figures_draw_ticks_as_matplotlib_s_axes_do():
    reference = Figure(figsize=(100 / 25.4, 80 / 25.4), dpi=72)
    FigureCanvasSVG(reference)
    reference.patch.set_visible(False)
    assert _axes_svg(new_figure(100, 80)) == _axes_svg(reference)


def test_a_drawing_s_axes_make_no_ticks():
    from plans.drawing.mechanism import draw_mechanism
    from plans.graphical import construct
    from plans import example_path, load

    fig = new_figure()
    ax = fig.add_axes([0, 0, 1, 1])
    draw_mechanism(construct(load(example_path("slider-crank"))), ax)
    render_svg(fig)
    for axis in (ax.xaxis, ax.yaxis):
        assert "majorTicks" not in vars(axis) and "minorTicks" not in vars(axis)


def test_closer_than_answers_as_measuring_every_pair():
    from plans.drawing.positions_plan import _closer_than

    rng = np.random.default_rng(7)
    shapes = np.array(
        [shapely.buffer(shapely.linestrings(rng.uniform(0, 100, (2, 2)) * [1, 0.1] + rng.uniform(0, 100, 2)), 0.3) for _ in range(20)]
        + [shapely.buffer(shapely.points(rng.uniform(0, 100, 2)), rng.uniform(0.5, 2)) for _ in range(20)],
        dtype=object,
    )
    xs, ys = rng.uniform(0, 100, 300), rng.uniform(0, 100, 300)
    boxes = shapely.box(xs - 2.5, ys - 1.2, xs + 2.5, ys + 1.2)
    for limit in (0.3, 1.0, 2.5):
        expected = shapely.distance(boxes[:, None], shapes[None, :]).min(axis=1) < limit
        assert 10 < expected.sum() < 290  # both answers occur
        assert (_closer_than(boxes, shapes, limit) == expected).all()
    assert not _closer_than(boxes, np.array([], dtype=object), 1.0).any()
