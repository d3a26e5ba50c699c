"""The plan of positions: no label on another, paths only where the mechanism assembles, skipped positions said."""

from __future__ import annotations

import math

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg

import plans
from plans.drawing.numerals import localised
from plans.drawing.positions_plan import draw_positions_plan, number_ranges
from plans.positions import run_positions

from position_numbers import leader_says, read_texts


def _cases():
    for name in plans.example_names():
        scene = plans.load(plans.example_path(name))
        if isinstance(scene.driver, plans.scene.Crank) or scene.driver.stroke is not None:
            yield name


@pytest.fixture(scope="module", params=list(_cases()))
def drawn(request):
    scene = plans.load(plans.example_path(request.param))
    run = run_positions(scene, 12)
    artists = draw_positions_plan(run)
    fig = artists[0].figure
    FigureCanvasAgg(fig)
    renderer = fig.canvas.get_renderer()
    return request.param, run, fig, renderer


def _texts(fig):
    return read_texts([t for t in fig.findobj(lambda a: hasattr(a, "get_text") and a.get_gid()) if t.get_text().strip()])


def _overlap(a, b, shrink=0.0) -> bool:
    return min(a.x1, b.x1) - max(a.x0, b.x0) > shrink and min(a.y1, b.y1) - max(a.y0, b.y0) > shrink


def test_no_label_overlaps_another_or_a_mark(drawn):
    name, run, fig, renderer = drawn
    labels = [t for t in _texts(fig) if not t.get_gid().startswith(("pos-heading", "pos-scale", "pos-legend", "pos-skipped"))]
    numbers = [t for t in labels if t.get_gid().startswith("pos-position-")]
    assert numbers, name
    boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in labels]
    for k, (ta, a) in enumerate(boxes):
        for tb, b in boxes[k + 1 :]:
            assert not _overlap(a, b), (name, ta, tb)
    marks = [m.get_window_extent(renderer) for m in fig.findobj(lambda a: (a.get_gid() or "").startswith("pos-mark-"))]
    for t in numbers:
        box = t.get_window_extent(renderer)
        for m in marks:
            assert not _overlap(box, m, shrink=0.5), (name, t.get_text())


def test_every_drawn_number_is_beside_its_own_mark(drawn):
    """A number names the mark nearest to it (or the one its leader line comes from)."""
    name, run, fig, renderer = drawn
    k_l = run.scales["k_l"]
    solved = {r.index: r for r in run.runs if r.ok}
    numbered = set()
    for t in _texts(fig):
        if not t.get_gid().startswith("pos-position-"):
            continue
        text = t.get_text()
        point = text.rstrip("₀₁₂₃₄₅₆₇₈₉")
        index = int(text[len(point):].translate(str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")))
        assert index in solved, (name, text)
        mark = complex(solved[index].analytic.points[point].r[0]) / k_l  # [mm] by the analytic solution
        x, y = t.get_position()
        assert abs(complex(x, y) - mark) < 14.0 or leader_says(t, mark), (name, text)
        numbered.add(point)
    if name == "six-bar":  # the crank's A, the coupler's B, the rocker's C and the coupler point M all get numbers
        assert numbered == {"A", "B", "C", "M"}


def test_paths_are_not_drawn_where_the_mechanism_does_not_assemble():
    """rocker-limit: A moves on the full crank circle, but only about 26° + 57° of it assemble (hand check)."""
    scene = plans.load(plans.example_path("rocker-limit"))
    run = run_positions(scene, 12)
    fig = draw_positions_plan(run)[0].figure
    k_l = run.scales["k_l"]
    drawn = np.concatenate([np.asarray(line.get_xydata()) for line in fig.findobj(lambda a: (a.get_gid() or "").startswith("pos-path-A"))])
    angles = np.degrees(np.arctan2(drawn[:, 1], drawn[:, 0]))
    for phi in angles:  # O at the origin, OA = 0.1 m: A at φ assembles iff |AD| ≤ AB + BD, D = (0.7, 0)
        a = 0.1 * complex(math.cos(math.radians(phi)), math.sin(math.radians(phi)))
        assert abs(0.7 - a) <= 0.65 + 1e-3, phi
    assert np.ptp(np.hypot(drawn[:, 0], drawn[:, 1])) < 0.5 and np.hypot(*drawn[0]) == pytest.approx(0.1 / k_l, rel=1e-3)


def test_the_caption_names_the_positions_not_drawn():
    scene = plans.load(plans.example_path("rocker-limit"))
    run = run_positions(scene, ", ".join(str(30 + 30 * k) for k in range(12)) + " deg")  # a turn: the input swings ±56.39°
    for lang, words in (("en", "not drawn (cannot assemble): 1–9"), ("sr", "нису нацртани (механизам се не може саставити): 1–9")):
        fig = draw_positions_plan(run, lang=lang)[0].figure
        assert words in [t.get_text() for t in _texts(fig)]


def test_number_ranges_and_localised_numbers():
    assert number_ranges([1, 2, 3, 5, 7, 8]) == "1–3, 5, 7, 8"
    assert number_ranges([4]) == "4"
    assert localised("-0.01", "sr") == "−0,01" and localised("-0.01", "en") == "−0.01"
    assert [localised("1.5", lang) for lang in ("en", "sr", "ru", "bg", "sl")] == ["1.5", "1,5", "1,5", "1,5", "1,5"]
