"""Issue 20, the teachers' review of the A3 sheets' scheme (minor findings):

1. a label's leader line crosses no hatching stroke, no link (a bar, a slot's edge, a block) and no other label: the
   quick-return's "E" and "6" stood on leaders across the guideway's hatching, the slider-crank's "B" across its guide's;
2. the driver's ω arc (and ε arc) crosses no link: at some crank angles the slider-crank's ω₂ arc ran over rod 3.

Geometry is read back from the drawn artists by their gids (leaders ``mech-leader``, hatching ``mech-hatch``, links
``mech-link-…``, ``mech-slot-…``, ``mech-block-…``, ``mech-sleeve-…``, ``mech-line-…``, arcs ``mech-omega``,
``mech-epsilon``), and the labels' boxes measured by matplotlib's renderer, never from the placement's own scores.
A leader starts at its point: the marks at the point (its pin, the links meeting there: within 1 mm of the leader's
start) and a closed outline around it (the block it sits in, the slot that block slides in) are its own, which any
leader from there has to leave; the frame's number "1" is the hatching's, its leader starting in it.
"""

from __future__ import annotations

import math

import pytest
from matplotlib.collections import LineCollection
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon
from shapely.geometry import LineString, Point, box
from shapely.geometry import Polygon as ShapelyPolygon

from plans.drawing import draw_mechanism
from plans.graphical import construct
from plans.scene import example_names, example_path, load

from plandraw_overlaps import measured

LINKS = ("mech-link-", "mech-slot-", "mech-block-", "mech-sleeve-", "mech-line-")
OWN_MM = 1.0  # marks this near a leader's start are its point's own

# (example, k_l [m/mm] or None for the scene's own, crank angles [deg] or None for the scene's own position): the
# bundled examples at their own scale, and the slider-crank and quick-return over a turn at the scale of their sheets
CASES = [(name, None, None) for name in example_names()] + [
    ("slider-crank", 0.0025, tuple(range(0, 360, 30)) + (190,)),  # (at 190° the ω₂ arc ran over rod 3)
    ("quick-return", 0.005, tuple(range(0, 360, 30)) + (70,)),  # (at 70° over the slot of rocker 4)
    ("scotch-yoke", 0.0025, tuple(range(0, 360, 30))),
]


def _strokes(artist) -> list[LineString]:
    """The strokes of a drawn line, line collection or polygon outline [mm]."""
    if isinstance(artist, Line2D):
        xs, ys = artist.get_data()
        return [LineString(list(zip(xs, ys)))] if len(xs) >= 2 else []
    if isinstance(artist, LineCollection):
        return [LineString(seg) for seg in artist.get_segments() if len(seg) >= 2]
    if isinstance(artist, Polygon):
        xy = [tuple(p) for p in artist.get_xy()]
        return [LineString(xy + [xy[0]])]
    return []


def _label_boxes(fig) -> list[tuple[str, object]]:
    """(gid:text, box [mm, the drawing's own coordinates]) of every non-empty text, measured by matplotlib's renderer."""

    def measure(renderer, k):
        out = []
        for ax in fig.axes:
            to_data = ax.transData.inverted()
            for t in ax.texts:
                if not t.get_text().strip(" ,"):
                    continue
                e = t.get_window_extent(renderer)
                (x0, y0), (x1, y1) = to_data.transform([(e.x0, e.y0), (e.x1, e.y1)])
                out.append((f"{t.get_gid()}:{t.get_text()}", box(x0, y0, x1, y1)))
        return out

    return measured(fig, measure)


def _drawings(name, k_l, angles):
    scene = load(example_path(name))
    if angles is None:
        yield None, draw_mechanism(construct(scene, k_l=k_l))
        return
    for deg in angles:
        yield deg, draw_mechanism(construct(scene.at(math.radians(deg)), k_l=k_l))


def _gid(artist) -> str:
    return artist.get_gid() or ""


def _leader_crossings(artists, exempt=()) -> list[str]:
    """What every leader crosses that is not its point's own, as text (but the leaders of the labels *exempt*, by gid)."""
    hatch = [s for a in artists if _gid(a).startswith("mech-hatch") for s in _strokes(a)]
    links = [(_gid(a), s) for a in artists if _gid(a).startswith(LINKS) for s in _strokes(a)]
    boxes = _label_boxes(artists[0].figure)
    found = []
    for leader in (a for a in artists if _gid(a).startswith("mech-leader")):
        (line,) = _strokes(leader)
        start, end = Point(line.coords[0]), Point(line.coords[-1])

        def own(stroke) -> bool:
            closed = stroke.is_closed and len(stroke.coords) >= 4
            return stroke.distance(start) <= OWN_MM or (closed and ShapelyPolygon(stroke.coords).contains(start))

        # its own label is the one it leads to (nearest its end)
        mine, *theirs = sorted(boxes, key=lambda lb: lb[1].distance(end))
        if mine[0].split(":")[0] in exempt:
            continue
        if not mine[0].startswith("mech-frame-number-"):  # (the frame's number is the hatching's: it starts in it)
            found += [f"{mine[0]}: leader crosses hatching" for s in hatch if s.intersects(line)][:1]
        found += [f"{mine[0]}: leader crosses {gid}" for gid, s in links if s.intersects(line) and not own(s)]
        found += [f"{mine[0]}: leader crosses label {label}" for label, b in theirs if b.intersects(line) and not b.contains(start)]
    return found


def _arc_crossings(artists) -> list[str]:
    arcs = [(_gid(a), s) for a in artists if _gid(a) in ("mech-omega", "mech-epsilon") for s in _strokes(a)]
    links = [(_gid(a), s) for a in artists if _gid(a).startswith(LINKS) for s in _strokes(a)]
    return [f"{arc} crosses {gid}" for arc, s in arcs for gid, link in links if s.intersects(link)]


#: A rod lying in a guideway between its two hatched lines (the quick-return's 5, 6 mm of room for a 3.4 mm numeral
#: beside a 0.8 mm bar) has no room for its number in it: the number stands outside, its leader across the guideway.
IN_GUIDEWAY = {"quick-return": ("mech-number-5",)}


@pytest.mark.parametrize("name, k_l, angles", CASES)
def test_no_leader_crosses_hatching_a_link_or_another_label(name, k_l, angles):
    found = {deg: _leader_crossings(artists, IN_GUIDEWAY.get(name, ())) for deg, artists in _drawings(name, k_l, angles)}
    assert {deg: f for deg, f in found.items() if f} == {}


@pytest.mark.parametrize("name, k_l, angles", CASES)
def test_the_driver_arcs_cross_no_link(name, k_l, angles):
    found = {deg: _arc_crossings(artists) for deg, artists in _drawings(name, k_l, angles)}
    assert {deg: f for deg, f in found.items() if f} == {}


def test_the_arcs_turn_the_drivers_way_about_its_pivot():
    """Wherever the arc goes, it stays an arc about the crank's pivot, its head at the end the crank turns to."""
    scene = load(example_path("slider-crank"))
    for deg in range(0, 360, 30):
        solution = construct(scene.at(math.radians(deg)), k_l=0.0025)
        artists = draw_mechanism(solution)
        o = complex(solution.positions[scene.driver.pivot]) / solution.scales["k_l"]
        arc = next(a for a in artists if _gid(a) == "mech-omega")
        head = next(a for a in artists if _gid(a) == "mech-omega-head")
        pts = [complex(x, y) - o for x, y in zip(*arc.get_data())]
        radii = [abs(p) for p in pts]
        assert max(radii) - min(radii) < 1e-6
        tip = complex(*head.get_xy()[0]) - o
        assert abs(abs(tip) - radii[0]) < 1e-6
        turn = sum(math.remainder(math.atan2(b.imag, b.real) - math.atan2(a.imag, a.real), 2 * math.pi) for a, b in zip(pts, pts[1:]))
        assert math.copysign(1.0, turn) == math.copysign(1.0, scene.driver.omega)
