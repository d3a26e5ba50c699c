"""The plan of positions as a teacher reviewed it (issue 20): a frame guide's hatching crosses no path and no link of any
position, no number stands on hatching or in a guideway, no two labels overlap (the slider-crank's B₂ and B₀′), and a
crowd of marks too close for their numbers is numbered in an enlarged detail whose stated ratio is true.

Expected values come from the scene's geometry (the analytic positions of the run and the cycle's paths, divided by
k_l), not from the drawing code: the drawn hatching, numbers and detail dots are read back from the figure."""

from __future__ import annotations

import re

import numpy as np
import pytest
import shapely
import shapely.ops
from matplotlib.backends.backend_agg import FigureCanvasAgg
from shapely.geometry import LineString, Point, box

import plans
from plans.drawing._canvas import sketch_on
from plans.drawing.positions_plan import draw_positions_into
from plans.i18n import term
from plans.positions import run_positions

from position_numbers import Number, read_texts

_DIGITS = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")
#: How close [mm] a hatch stroke may come to a path or a link before it counts as crossing it.
TOUCH_MM = 0.05

CASES = {  # example, positions, k_l [m/mm] (as the reviewed handouts and sheet draw them), language
    "quick-return": (12, 0.006, "sr"),
    "linear-arm": (8, 0.006, "bg"),
    "slider-crank": (4, 0.0015, "sr"),
}


@pytest.fixture(scope="module", params=sorted(CASES))
def drawn(request):
    name = request.param
    n, k_l, lang = CASES[name]
    run = run_positions(plans.load(plans.example_path(name)), n)
    extremes = run.other_extreme()
    artists = sketch_on(None, "pos", lambda sketch: draw_positions_into(sketch, run, lang=lang, k_l=k_l, extremes=extremes))
    fig = artists[0].figure
    FigureCanvasAgg(fig)
    return name, run, extremes, k_l, lang, fig


def _segments(fig, gid: str) -> list[LineString]:
    out = []  # (a gid drawn again is numbered: pos-hatch-2, …)
    for a in fig.findobj(lambda a: re.fullmatch(rf"{re.escape(gid)}(-\d+)?", a.get_gid() or "") is not None):
        if hasattr(a, "get_segments"):
            out += [LineString(s) for s in a.get_segments() if len(s) >= 2]
        elif hasattr(a, "get_xydata"):
            out.append(LineString(a.get_xydata()))
    return out


def _geometry(run, extremes, k_l) -> list[LineString]:
    """Every point's path over the cycle where it assembles and every link of every position (and the other extreme) [mm]."""
    scene = run.scene
    out = []
    ok = np.asarray(run.cycle.valid, dtype=bool)
    frame = scene.bodies["frame"].points
    for p in scene.report:
        if p in frame or p not in run.cycle.points:
            continue
        r = np.where(ok, np.asarray(run.cycle.points[p].r), np.nan) / k_l
        good = np.isfinite(r)
        runs, cur = [], []
        for z, g in zip(r, good):
            if g:
                cur.append((z.real, z.imag))
            elif cur:
                runs.append(cur)
                cur = []
        runs.append(cur)
        out += [LineString(c) for c in runs if len(c) >= 2]
    poses = [r.graphical.positions for r in run.runs if r.ok] + [g.positions for g in extremes.values()]
    for positions in poses:
        for body_name, body in scene.bodies.items():
            pts = [complex(positions[p]) / k_l for p in body.points if p in positions]
            if body_name == "frame" or len(pts) < 2:
                continue
            out += [LineString([(a.real, a.imag), (b.real, b.imag)]) for i, a in enumerate(pts) for b in pts[i + 1:]]
    return out


def _guide_strokes(fig, scene) -> list[LineString]:
    """The hatch strokes of the frame guides (each starts on a drawn guide line), less their first 0.3 mm: what lies
    beyond the line (a slider's link that meets the line at its pin does not cross the hatching)."""
    lines = [g for name in scene.bodies["frame"].lines for g in _segments(fig, f"pos-guide-{name}")]
    out = []
    for s in _segments(fig, "pos-hatch"):
        start = Point(s.coords[0])
        if any(start.distance(g) < 0.01 for g in lines):
            out.append(shapely.ops.substring(s, 0.3, s.length))
    return out


def test_no_hatch_stroke_crosses_a_path_or_a_link_of_any_position(drawn):
    name, run, extremes, k_l, _, fig = drawn
    strokes = _guide_strokes(fig, run.scene)
    assert strokes, name  # every case has a frame guide
    tree = shapely.STRtree(strokes)
    hits = []
    for geom in _geometry(run, extremes, k_l):
        for i in tree.query(geom, predicate="dwithin", distance=TOUCH_MM):
            hits.append(strokes[i].coords[0])
    assert not hits, (name, len(hits), hits[:3])


def _numbers(fig):
    """The numbers, each its letter and index read as one label (A₁₀)."""
    return [t for t in _texts(fig) if re.fullmatch(r"pos-(position|detail-[IVX]+-number)-.+", t.get_gid() or "")]


def _texts(fig):
    return read_texts([t for t in fig.findobj(lambda a: hasattr(a, "get_text") and (a.get_gid() or "").startswith("pos-")) if t.get_text().strip()])


def _box(t, renderer, fig):
    """A text's box in drawing millimetres (data units)."""
    ext = t.get_window_extent(renderer).transformed((t.letter if isinstance(t, Number) else t).axes.transData.inverted())
    return box(ext.x0, ext.y0, ext.x1, ext.y1)


def test_no_number_on_hatching_or_in_a_guideway(drawn):
    name, run, extremes, k_l, _, fig = drawn
    renderer = fig.canvas.get_renderer()
    strokes = _segments(fig, "pos-hatch")
    # the guideway: the band between a frame line's two drawn guide lines, over their length (from the scene's line)
    scene = run.scene
    channels = []
    for line_name, line in scene.bodies["frame"].lines.items():
        guides = _segments(fig, f"pos-guide-{line_name}")
        origin = complex(*line.origin) / k_l if not isinstance(line.origin, complex) else line.origin / k_l
        u = np.exp(1j * line.angle)
        offsets = {round(((complex(*g.coords[0]) - origin) * u.conjugate()).imag, 3) for g in guides}
        if len(offsets) == 2 and min(offsets) < 0 < max(offsets):
            ts = [((complex(*c) - origin) * u.conjugate()).real for g in guides for c in g.coords]
            lo, hi, w0, w1 = min(ts), max(ts), min(offsets), max(offsets)
            corners = [origin + u * complex(t, w) for t, w in ((lo, w0), (hi, w0), (hi, w1), (lo, w1))]
            channels.append(shapely.Polygon([(z.real, z.imag) for z in corners]))
    if name == "quick-return":
        assert channels, "the quick-return's ram runs in a guideway"
    for t in _numbers(fig):
        b = _box(t, renderer, fig)
        assert not any(b.intersects(s) for s in strokes), (name, t.get_text())
        assert not any(b.intersects(c) for c in channels), (name, t.get_text())


def test_no_label_overlaps_another(drawn):
    name, _, _, _, _, fig = drawn
    renderer = fig.canvas.get_renderer()
    texts = _texts(fig)
    boxes = [(t.get_text(), _box(t, renderer, fig)) for t in texts]
    for k, (ta, a) in enumerate(boxes):
        for tb, b in boxes[k + 1:]:
            assert a.intersection(b).area < 1e-6, (name, ta, tb)


def test_a_number_covers_no_mark(drawn):
    """The slider-crank's B₂ sat on B₀′: no number's box may hold a mark (its own or another)."""
    name, run, extremes, k_l, _, fig = drawn
    renderer = fig.canvas.get_renderer()
    from plans.drawing.positions_plan import numbered_points

    marks = [complex(r.graphical.positions[p]) / k_l for r in run.runs if r.ok for p in numbered_points(run.scene) if p in r.graphical.positions]
    marks += [complex(g.positions[p]) / k_l for g in extremes.values() for p in numbered_points(run.scene) if p in g.positions]
    for t in [t for t in _numbers(fig) if t.get_gid().startswith("pos-position-")]:
        b = _box(t, renderer, fig)
        assert not any(b.intersects(Point(z.real, z.imag).buffer(0.3)) for z in marks), (name, t.get_text())


def test_every_position_numbered_on_the_plan_or_in_a_detail(drawn):
    """The Bulgarian linear-arm's H and K: no mark left unnumbered (none stated under the plan)."""
    name, run, extremes, k_l, lang, fig = drawn
    if name != "linear-arm":
        pytest.skip("the crowded handout of the review")
    from plans.drawing.positions_plan import numbered_points

    texts = _texts(fig)
    assert not [t for t in texts if t.get_gid().startswith("pos-unnumbered")]
    written = {t.get_text().translate(_DIGITS) for t in _numbers(fig)}
    scheme = {t.get_text() for t in texts}
    for r in run.runs:
        for p in numbered_points(run.scene):
            if r.ok and p in r.graphical.positions:
                assert f"{p}{r.index}" in written or (r.index == 0 and p in scheme), f"{p}{r.index}"
    assert {"H3", "K2"} <= written  # (in the review, eight of H and K were only listed)


def test_a_detail_s_stated_ratio_is_true_and_in_the_reader_s_language(drawn):
    name, run, extremes, k_l, lang, fig = drawn
    if name != "linear-arm":
        pytest.skip("the crowded handout of the review")
    titles = [t for t in fig.findobj(lambda a: hasattr(a, "get_text") and re.fullmatch(r"pos-detail-[IVX]+-title", a.get_gid() or ""))]
    assert titles
    analytic = {f"{p}{r.index}": complex(r.graphical.positions[p]) / k_l for r in run.runs if r.ok for p in r.graphical.positions}
    checked = 0
    for t in titles:
        detail = t.get_gid().split("-")[2]
        m = re.fullmatch(rf"{term('detail', lang).capitalize()} {detail} \((\d+(?:,\d+)?) : 1\)", t.get_text())
        assert m, t.get_text()
        ratio = float(m.group(1).replace(",", "."))
        dots = {a.get_gid(): complex(*a.center) for a in fig.findobj(lambda a: hasattr(a, "center") and (a.get_gid() or "").startswith(f"pos-detail-{detail}-dot-"))}
        named = {}
        for gid, z in dots.items():
            key = gid[len(f"pos-detail-{detail}-dot-"):].translate(_DIGITS)
            if key in analytic:
                named[key] = z
        keys = sorted(named)
        assert keys, detail
        # the detail's circle is the ring on the plan enlarged as stated
        ring = next(a for a in fig.findobj(lambda a: a.get_gid() == f"pos-detail-ring-{detail}"))
        circle = next(a for a in fig.findobj(lambda a: a.get_gid() == f"pos-detail-{detail}"))
        assert circle.radius == pytest.approx(ratio * ring.radius, rel=1e-9)
        # and every two marks in it as far apart as on the plan (the analytic positions / k_l), times the ratio
        for i, a in enumerate(keys):
            for b in keys[i + 1:]:
                on_plan = abs(analytic[a] - analytic[b])
                if on_plan > 0.05:
                    assert abs(named[a] - named[b]) == pytest.approx(ratio * on_plan, rel=1e-6, abs=1e-6), (detail, a, b)
                    checked += 1
    assert checked


@pytest.mark.parametrize("lang", ["en", "sr", "ru", "bg", "sl"])
def test_the_word_detail_in_every_language(lang):
    words = {"en": "detail", "sr": "детаљ", "ru": "выносной элемент", "bg": "детайл", "sl": "detajl"}
    assert term("detail", lang) == words[lang]
