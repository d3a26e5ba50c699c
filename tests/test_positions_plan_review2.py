"""The plan of positions, second review (issue 20): every fixed point the data lists is marked and lettered; position 0
is lettered A₀ like the others, with indices a student can read (set at the page's small text size, not as Unicode
subscript glyphs at half the size); details sized to their marks; no number on a path line; no mark of any bundled
example left unnumbered at 8 or 12 positions (the handout's k_l).

Expected values come from the scene (its frame points, the cycle's paths, the analytic positions divided by k_l) and
from the style's stated small text size; the drawing is read back from the figure's artists."""

from __future__ import annotations

import re

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from shapely.geometry import LineString, box

import plans
from plans.drawing._canvas import sketch_on
from plans.drawing.positions_plan import draw_positions_into
from plans.drawing.style import SMALL_PT
from plans.positions import run_positions

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
MM_PER_PT = 25.4 / 72


def _draw(name: str, n: int, k_l: float, lang: str = "en"):
    run = run_positions(plans.load(plans.example_path(name)), n)
    extremes = run.other_extreme()
    fig = sketch_on(None, "pos", lambda s: draw_positions_into(s, run, lang=lang, k_l=k_l, extremes=extremes))[0].figure
    FigureCanvasAgg(fig)
    return run, fig


def _texts(fig) -> dict:
    return {t.get_gid(): t for t in fig.findobj(lambda a: hasattr(a, "get_text") and a.get_gid()) if t.get_text().strip()}


def _numbers(fig) -> dict[str, tuple]:
    """gid -> (the number as read, letter then index: ``A₀′``, [its Text artists])."""
    texts = _texts(fig)
    out = {}
    for gid, t in texts.items():
        if re.fullmatch(r"pos-(position|detail-[IVX]+-number)-[^\s]+?", gid) and not gid.endswith(("-index", "-comma", "-leader")):
            index = texts.get(f"{gid}-index")
            parts = [t] + ([index] if index is not None else [])
            out[gid] = (t.get_text() + (index.get_text().translate(_SUB) if index is not None else ""), parts)
    return out


def _box_mm(t, fig):
    """A Text's box [mm] (data units of the sketch)."""
    r = fig.canvas.get_renderer()
    bb = t.get_window_extent(r).transformed(t.axes.transData.inverted())
    return box(bb.x0, bb.y0, bb.x1, bb.y1)


def test_every_fixed_point_the_data_lists_is_marked_and_lettered():
    """Linear-arm lists O (0, 0), D and Q as fixed points: each is lettered on the plan beside its place, and O (no
    pivot of the scheme: the origin of coordinates) is marked there too."""
    k_l = 0.006
    run, fig = _draw("linear-arm", 8, k_l, "bg")
    frame = run.scene.bodies["frame"].points
    assert set(frame) >= {"O", "D", "Q"}
    texts = list(_texts(fig).values())
    for name, z in frame.items():
        at = complex(z) / k_l  # [mm]
        near = [t for t in texts if t.get_text() == name and _box_mm(t, fig).distance(box(at.real, at.imag, at.real, at.imag)) < 6.0]
        assert near, name
    marks = fig.findobj(lambda a: (a.get_gid() or "") == "pos-fixed-O")
    assert marks and abs(complex(*marks[0].center) - complex(frame["O"]) / k_l) < 1e-6


def test_position_zero_is_lettered_like_the_others_and_its_index_is_legible():
    """The Serbian slider-crank A3 plan: position 0 reads A₀, B₀ (as 0′ reads A₀′), not a plain A, B; every position's
    index is set in digits at the page's small text size or more (a subscript glyph of an 8 pt label is 4.5 pt)."""
    run, fig = _draw("slider-crank", 4, 0.0015, "sr")
    numbers = _numbers(fig)
    read = {text for text, _ in numbers.values()}
    assert {"A₀", "B₀", "A₀′", "B₀′", "A₁", "B₃"} <= read, read
    letters = {id(parts[0]) for _, parts in numbers.values()}
    # (no plain A or B besides the numbers' letters: the scheme no longer letters position 0's points)
    assert not [t for t in _texts(fig).values() if t.get_text() in ("A", "B") and id(t) not in letters]
    indices = [parts[1] for _, parts in numbers.values() if len(parts) > 1]
    assert len(indices) == len(numbers)
    for t in indices:
        assert re.fullmatch(r"[0-9]+′?", t.get_text()), t.get_text()
        assert t.get_fontsize() >= SMALL_PT - 1e-9, t.get_text()


def test_a_number_stands_off_the_path_lines():
    """The slider-crank's B numbers sat on the B path: no number's box touches any point's path (its leader may)."""
    for name, n, k_l, lang in (("slider-crank", 4, 0.0015, "sr"), ("slider-crank", 12, 0.004, "en"), ("quick-return", 12, 0.006, "sr")):
        run, fig = _draw(name, n, k_l, lang)
        ok = np.asarray(run.cycle.valid, dtype=bool)
        paths = []
        for p in run.scene.report:
            if p in run.cycle.points and p not in run.scene.bodies["frame"].points:
                r = np.asarray(run.cycle.points[p].r)[ok] / k_l
                paths.append(LineString([(z.real, z.imag) for z in r]))
        for gid, (text, parts) in _numbers(fig).items():
            if "detail" in gid:
                continue
            for t in parts:
                b = _box_mm(t, fig).buffer(-0.1)
                assert not any(b.intersects(line) for line in paths), (name, n, text)


def test_details_are_sized_to_their_marks():
    """Six-bar at 12 positions: a detail's circle is no larger than its marks need (their spread enlarged, and room
    for their numbers): Detail III (10 : 1) was a 32 mm circle round three M marks 1 mm apart."""
    for name, n, k_l in (("six-bar", 12, 0.01), ("six-bar", 12, 0.012), ("linear-arm", 8, 0.006), ("quick-return", 12, 0.006)):
        run, fig = _draw(name, n, k_l)
        for circle in fig.findobj(lambda a: re.fullmatch(r"pos-detail-[IVX]+", a.get_gid() or "") is not None):
            detail = circle.get_gid()[len("pos-detail-"):]
            centre = complex(*circle.center)
            dots = [complex(*d.center) for d in fig.findobj(lambda a: (a.get_gid() or "").startswith(f"pos-detail-{detail}-dot-"))]
            assert dots, (name, detail)
            spread = max(abs(d - centre) for d in dots)
            assert circle.get_radius() <= max(spread + 9.0, 8.0), (name, n, detail, circle.get_radius(), spread)


def _handout_k_l(run) -> float:
    """The k_l the handout draws the plan of positions at (fitted to its box, as plans.pages.handout does)."""
    from plans.drawing.svgblocks import positions_svg
    from plans.pages.document import fitted
    from plans.pages.handout import POSITIONS_BOX

    solved = [r for r in run.runs if r.ok]
    zs = [complex(z) for r in solved for z in r.graphical.positions.values()]
    for p in run.scene.report:
        if p in run.cycle.points:
            path = np.asarray(run.cycle.points[p].r)
            zs += [complex(z) for z in path[np.isfinite(path.real) & np.isfinite(path.imag)]]
    extremes = run.other_extreme()
    zs += [complex(z) for g in extremes.values() for z in g.positions.values()]
    x, y = [z.real for z in zs], [z.imag for z in zs]
    k, _ = fitted(lambda k: positions_svg(run, k, "en", extremes), (max(x) - min(x), max(y) - min(y)), POSITIONS_BOX,
                  solved[0].graphical.scales["k_l"], None)
    return k


@pytest.mark.parametrize("n", [8, 12])
@pytest.mark.parametrize("name", plans.example_names())
def test_no_mark_of_a_bundled_example_is_left_unnumbered(name, n):
    """Scotch yoke's A₀′ (12 positions), six-bar's M₆, M₈, M₀′, M₁₀, slider-crank's B₀′ were listed "not numbered":
    every mark of every position is numbered, on the plan or in a detail, and none is listed under the plan."""
    run = run_positions(plans.load(plans.example_path(name)), n)
    if not any(r.ok for r in run.runs):
        pytest.skip("no position solved")
    k_l = _handout_k_l(run)
    _, fig = _draw(name, n, k_l)
    assert not [t for gid, t in _texts(fig).items() if gid.startswith("pos-unnumbered")], (name, n)
    read = {text for text, _ in _numbers(fig).values()}
    read = {one for text in read for one in text.split(", ")}
    # (every mark drawn, its number read back: pos-mark-<k>-<point>, pos-mark-extreme-<point>)
    for mark in fig.findobj(lambda a: re.fullmatch(r"pos-mark-.+", a.get_gid() or "") is not None):
        m = re.fullmatch(r"pos-mark-(\d+|extreme)-(.+?)(-\d+)?", mark.get_gid())
        text = m[2] + ("0′" if m[1] == "extreme" else m[1]).translate(_SUB)
        assert text in read, (name, n, text)
