"""The scheme's frame is drawn the same way at every position (review 3, item 5): the hatched side of each
frame guide and the direction of each ground support are chosen once for the cycle.

Everything is measured on the drawn artists by gid, relative to the pins drawn at the solved positions:
a support's direction is from its pivot to the middle of its triangle's base; a guide's hatched side is
the side of the guide line its hatch strokes run to.  The examples' geometry, worked here:

* quick-return: the ram line is y = 520 mm; D runs on a circle of 550 mm about C, so D passes above the
  line (up to 30 mm, lever upright) and below it (φ₂ = 210°: D is 37.5 mm below, worked from the lever
  through A = O + 120 mm·e^{iφ₂}, O = (0, 250 mm)).  Link DE meets the ram's block on both sides of
  the line: no one side is clear, so the ram runs in a guideway hatched both ways at every position.
* six-bar: rocker 4 swings about D, the rod 5 through the sleeve about E: supports at D and E exist that
  clear them at every position; the crank 2 turns a full circle about O, so no direction is clear of it:
  its support stands below O and turns away only where the crank lies over it (issue 10 §4).
"""

from __future__ import annotations

import cmath
import math
import re
import xml.etree.ElementTree as ET
from dataclasses import replace

import pytest
from matplotlib.collections import LineCollection
from shapely.geometry import LineString, Point, Polygon
from shapely.ops import unary_union

from plans.cli import main
from plans.drawing import draw_mechanism
from plans.positions import run_positions
from plans.scene import example_path, load


def _pages(name, positions="12"):
    """The mechanism as each position page draws it (a position page keeps a frame guide around its block)."""
    run = run_positions(load(example_path(name)), positions)
    out = []
    for r in run.runs:
        assert r.ok
        g = r.graphical
        g = replace(g, travel={k: t for k, t in g.travel.items() if not k.startswith("frame.")})
        out.append((g, draw_mechanism(g)))
    return out


def _gid(artists, gid):
    return next(a for a in artists if a.get_gid() == gid)


def _pin(artists, name) -> complex:
    return complex(*_gid(artists, f"mech-pin-{name}").center)


def _support(artists, name) -> complex:
    """Unit direction from pivot *name* to its support's base, as drawn."""
    q, left, right = (complex(*xy) for xy in _gid(artists, f"mech-ground-{name}").get_xy()[:3])
    assert abs(q - _pin(artists, name)) < 1e-9  # the triangle's apex is the pin
    d = (left + right) / 2 - q
    return d / abs(d)


def _hatch_strokes(artists):
    return [(complex(*s[0]), complex(*s[1])) for a in artists if isinstance(a, LineCollection)
            and (a.get_gid() or "").startswith("mech-hatch") for s in a.get_segments()]


def _guide_sides(artists, guide: str, pin: str) -> set:
    """{(side of the pin's line the guide line is on, side its hatching runs to)}: (0, ±1) for a
    guide through the pin hatched on one side, (+1, +1) and (−1, −1) for a guideway either side."""
    e = _pin(artists, pin)
    lines = [a for a in artists if re.fullmatch(f"mech-guide-{guide}(-\\d+)?", a.get_gid() or "") and hasattr(a, "get_data")]
    assert lines
    out = set()
    strokes = _hatch_strokes(artists)
    for ln in lines:
        pts = [complex(x, y) for x, y in zip(*ln.get_data())]
        a, b = pts[0], pts[-1]
        u = (b - a) / abs(b - a)
        n = u * 1j
        off = ((a - e) * n.conjugate()).real
        where = 0 if abs(off) < 0.5 else (1 if off > 0 else -1)
        seg = LineString([(a.real, a.imag), (b.real, b.imag)])
        for s0, s1 in strokes:
            if seg.distance(Point(s0.real, s0.imag)) < 1e-6:
                out.add((where, 1 if ((s1 - s0) * n.conjugate()).real > 0 else -1))
    return out


def _bars(artists, skip=()):
    """The links' bars as drawn (Line2D pieces of mech-link-N), buffered to their width."""
    out = []
    for a in artists:
        gid = a.get_gid() or ""
        m = re.fullmatch(r"mech-link-(\w+?)(-\d+)?", gid)
        if m and m.group(1) not in skip and hasattr(a, "get_data"):
            xs, ys = a.get_data()
            out.append((m.group(1), LineString(list(zip(xs, ys))).buffer(a.get_linewidth() * 25.4 / 72 / 2)))
    return out


def _support_shape(artists, name) -> Polygon:
    """The support's triangle, its base and the base's hatch strokes, less a pin's width round the pivot."""
    q = _pin(artists, name)
    tri = Polygon(_gid(artists, f"mech-ground-{name}").get_xy())
    d = _support(artists, name)
    shapes = [tri]
    for a in artists:
        if re.fullmatch(r"mech-ground-base(-\d+)?", a.get_gid() or ""):
            xs, ys = a.get_data()
            mid = complex(sum(xs) / 2, sum(ys) / 2)
            if abs(((mid - q) * d.conjugate()).imag) < 1e-6 and ((mid - q) * d.conjugate()).real > 0:
                base = LineString(list(zip(xs, ys)))
                shapes.append(base)
                for s0, s1 in _hatch_strokes(artists):
                    if base.distance(Point(s0.real, s0.imag)) < 1e-6:
                        shapes.append(LineString([(s0.real, s0.imag), (s1.real, s1.imag)]))
    return unary_union(shapes).difference(Point(q.real, q.imag).buffer(2.0))


#: a crank's support may turn away where the crank lies over it (issue 10 §4: a crank never crosses its own
#: support): within this angle of the support's axis, measured from the pins
CRANK_OVER = math.radians(50)


def _crank_over(artists, d) -> bool:
    o, a = _pin(artists, "O"), _pin(artists, "A")
    return abs(cmath.phase((a - o) / d)) < CRANK_OVER


@pytest.mark.parametrize("name, pivots", [("quick-return", "OC"), ("six-bar", "ODE")])
def test_every_support_points_the_same_way_on_every_position_page(name, pivots):
    pages = _pages(name)
    assert len(pages) == 12
    for p in pivots:
        dirs = [_support(artists, p) for _, artists in pages]
        common = max(dirs, key=lambda d: sum(abs(e - d) < 1e-9 for e in dirs))
        turned = [k for k, d in enumerate(dirs) if abs(d - common) >= 1e-9]
        if p != "O":
            assert not turned, (p, turned)
        # the crank's pivot: the common direction, except where the crank lies over it
        for k in turned:
            assert _crank_over(pages[k][1], common), (p, k)
        assert len(turned) <= 4, (p, turned)


@pytest.mark.parametrize("name, pivot, links", [("quick-return", "C", ()), ("six-bar", "D", ()), ("six-bar", "E", ())])
def test_a_support_that_can_keep_clear_of_the_links_does_so_at_every_position(name, pivot, links):
    for _, artists in _pages(name):
        support = _support_shape(artists, pivot)
        for body, bar in _bars(artists, skip=links):
            assert not support.intersects(bar), (pivot, body)


def test_the_crank_s_support_stands_below_and_turns_away_only_where_the_crank_is_over_it():
    # six-bar: 12 positions of the crank every 30°; no one direction is clear of a crank at every position:
    # the support stands below O, and only where the crank lies over that it turns away from the crank
    turned = 0
    for _, artists in _pages("six-bar"):
        d = _support(artists, "O")
        if abs(d - (-1j)) < 1e-9:
            # the crank from O (its direction as the pins give it) is drawn over the support's triangle
            over = _gid(artists, "mech-link-2-at-O")
            ends = [complex(x, y) for x, y in zip(*over.get_data())]
            o, a = _pin(artists, "O"), _pin(artists, "A")
            assert abs(ends[0] - o) < 1e-9 and abs(((ends[1] - o) / (a - o)).imag) < 1e-9 and ((ends[1] - o) / (a - o)).real > 0
            assert over.get_zorder() > _gid(artists, "mech-ground-O").get_zorder()
        else:
            turned += 1
            assert _crank_over(artists, -1j)
            support = _support_shape(artists, "O")
            for body, bar in _bars(artists):
                if body == "2":
                    assert not support.intersects(bar)  # turned away: the crank clear of its support
    assert 1 <= turned <= 4, turned  # the crank passes below O at some of the 12 positions


def test_the_quick_return_ram_runs_in_one_guideway_at_every_position():
    pages = _pages("quick-return")
    # (the hand geometry behind it: D above the ram line at φ₂ = 90°, below at 210°)
    for phi, sign in ((90, 1), (210, -1)):
        a = complex(0, 0.25) + 0.12 * cmath.exp(1j * math.radians(phi))
        d = 0.55 * a / abs(a)
        assert (d.imag - 0.52) * sign > 0.02
    for _, artists in pages:
        assert _guide_sides(artists, "ram", "E") == {(1, 1), (-1, -1)}  # either side of E, hatched outward
        # and link DE, whichever side D is on, runs on no hatching
        strokes = [LineString([(a.real, a.imag), (b.real, b.imag)]) for a, b in _hatch_strokes(artists)]
        for body, bar in _bars(artists):
            if body == "5":
                assert not any(bar.intersects(s) for s in strokes)


def test_a_guide_the_links_keep_to_one_side_of_is_hatched_on_the_other_side_at_every_position():
    # offset slider-crank: B on y = 50 mm, A on the crank circle r = 100 mm about O: A runs from 150 mm below the
    # line to 50 mm above it: both sides (a cylinder hatched both ways).  With the line 150 mm up, A stays below.
    from plans.scene import loads

    text = example_path("slider-crank").read_text().replace('through = [0, "50 mm"]', 'through = [0, "150 mm"]').replace("B = [0.32, 0.05]", "B = [0.28, 0.15]")
    run = run_positions(loads(text), "12")
    sides = set()
    for r in run.runs:
        artists = draw_mechanism(r.graphical)
        found = _guide_sides(artists, "cylinder", "B")
        assert len(found) == 1
        sides |= found
    assert sides == {(0, 1)}  # hatched above, away from the crank below, at all 12 positions
    run = run_positions(load(example_path("slider-crank")), "12")
    for r in run.runs:
        assert _guide_sides(draw_mechanism(r.graphical), "cylinder", "B") == {(1, 1), (-1, -1)}


SVG = "{http://www.w3.org/2000/svg}"


def _svg_support(path, prefix, name) -> complex:
    for g in ET.parse(path).iter(f"{SVG}g"):
        if g.get("id") == f"{prefix}-ground-{name}":
            p = next(g.iter(f"{SVG}path"))
            nums = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", p.get("d", ""))]
            q, left, right = (complex(x, y) for x, y in list(zip(nums[0::2], nums[1::2]))[:3])
            d = (left + right) / 2 - q
            return d / abs(d)
    raise AssertionError(f"{prefix}-ground-{name} not in {path}")


def test_the_plan_of_positions_and_the_position_sheets_share_the_supports(tmp_path):
    import plans
    from plans.handout import handout

    positions = tmp_path / "positions.svg"  # the handout's plan of positions, as it places it
    doc = handout(plans.load(plans.example_path("six-bar")), positions=4)
    positions.write_bytes(doc.images["positions"])
    # the sheets at the plate's k_l: the frame is chosen over the cycle at one scale (the symbols' room depends on it)
    assert main(["draw", "--example", "six-bar", "--positions", "4", "--k-l", repr(doc.scales["k_l"]), "-o", str(tmp_path / "sheets")]) == 0
    sheets = sorted((tmp_path / "sheets").glob("sheet-*.svg"))
    assert len(sheets) == 4
    for name in "DE":  # (O turns away where the crank lies over its support: the test above)
        want = _svg_support(positions, "positions", name)
        for path in sheets:
            from sheet_pages import unpack

            assert abs(_svg_support(unpack(path, "mechanism"), "mech", name) - want) < 1e-6, (name, path.name)
