"""Every edge arrow points at its centre (teacher's review of the bg linear-arm and sr quick-return handouts: "P₁₃ 182 мм"
drawn 22° above horizontal while P₁₃ lay straight above F, 73° from the arrow's tip).

Read from the drawings' SVG alone: the arrow's tail (its shaft's first point) and tip (its head's point), and the
marks of the centres drawn where they are.  The true centres come from the analytic solution (not from Kennedy's
construction): P_jk is the point whose velocity is the same as a point of body j and of body k,
v_Oj + iω_j (r − O_j) = v_Ok + iω_k (r − O_k); at infinity, perpendicular to v_j − v_k, where ω_j = ω_k.  The marks give
the drawing's placement (a least-squares fit of the scale and the offset, every near centre within 0.3 mm of it), so
the far centre's place on the paper follows, and with it the bearing from the arrow to it.
"""

from __future__ import annotations

import cmath
import math
import re

import numpy as np
import pytest
from shapely.geometry import LineString, Point

from plans.centres import instant_centres
from plans.drawing.centres import centres_svg
from plans.positions import cycle_positions
from plans.scene import example_path, load

from analytic_centres import true_centres
from review_handouts import built

MM = 72 / 25.4  # SVG units (pt) per mm
EXAMPLES = ["four-bar", "six-bar", "slider-crank", "quick-return", "linear-arm", "scotch-yoke", "wedge", "ladder", "rocker-limit"]


def _paths(svg: str, prefix: str) -> dict[str, list[complex]]:
    """gid suffix -> the points of the first path in the group ``prefix…`` [SVG units, y down]."""
    out = {}
    for gid, d in re.findall(r'<g id="%s([^"]+)">\s*<path d="([^"]+)"' % re.escape(prefix), svg):
        out[gid] = [complex(float(x), float(y)) for x, y in re.findall(r"([-0-9.e]+) ([-0-9.e]+)", d)]
    return out


def _placement(svg: str, truth: dict) -> tuple[float, complex]:
    """(SVG units per metre, the SVG point of the scene's origin) fitted to the near centres' marks: svg = s·(x, −y) + o."""
    marks = {label: sum(p) / len(p) for label, p in ((lab, [complex((min(q.real for q in pts) + max(q.real for q in pts)) / 2,
                                                                       (min(q.imag for q in pts) + max(q.imag for q in pts)) / 2)])
                                                       for lab, pts in _paths(svg, "centres-mark-").items())}
    pairs = [(truth[label][0].conjugate(), at) for label, at in marks.items() if truth[label][0] is not None]
    assert len(pairs) >= 2, marks
    z = np.array([p[0] for p in pairs])
    w = np.array([p[1] for p in pairs])
    # w = s·z + o (s real): least squares
    A = np.column_stack([np.concatenate([z.real, z.imag]), np.concatenate([np.ones(len(z)), np.zeros(len(z))]),
                         np.concatenate([np.zeros(len(z)), np.ones(len(z))])])
    s, ox, oy = np.linalg.lstsq(A, np.concatenate([w.real, w.imag]), rcond=None)[0]
    residual = max(abs(s * zz + complex(ox, oy) - ww) for zz, ww in zip(z, w))
    assert residual < 0.3 * MM, (residual / MM, marks)
    return s, complex(ox, oy)


def _check_arrows(svg: str, truth: dict, where: str) -> int:
    """Every edge arrow of *svg* points along the bearing from its tail to its centre's true place (within 2°), or
    along the centre's direction at infinity; returns how many were checked."""
    heads = _paths(svg, "centres-edge-")
    if any(truth[label][0] is not None for label in heads if not label.endswith("-head")):
        s, o = _placement(svg, truth)
    shafts = {label: pts for label, pts in heads.items() if not label.endswith("-head")}
    checked = 0
    for label, pts in shafts.items():
        tail, tip = pts[0], heads[f"{label}-head"][0]
        drawn = cmath.phase(tip - tail)
        point, direction = truth[label]
        if point is None and direction is None:
            continue
        if point is None:
            d = direction.conjugate()  # y down on the SVG
            off = abs(math.degrees((drawn - cmath.phase(d) + math.pi / 2) % math.pi - math.pi / 2))
        else:
            far = s * point.conjugate() + o
            off = abs(math.degrees((cmath.phase(far - tail) - drawn + math.pi) % (2 * math.pi) - math.pi))
            # the centre lies ahead of the tip, not behind it
            assert abs(far - tip) < abs(far - tail), (where, label)
        assert off <= 2.0, (where, label, round(off, 1))
        checked += 1
    return checked


@pytest.fixture(scope="module")
def reviewed():
    """(where, svg, truth) of every centres drawing of the two reviewed handouts."""
    out = []
    for name, n, lang in (("linear-arm", 8, "bg"), ("quick-return", 12, "sr")):
        scene = load(example_path(name))
        doc = built(name, n, lang, centres=True)  # (built once per test run: tests/review_handouts.py)
        for k, position in enumerate(cycle_positions(scene, n)):
            svg = doc.images[f"centres-{k}"].decode()
            out.append((f"{name} {lang} position {k}", svg, true_centres(scene.at(position))))
    return out


def test_every_edge_arrow_of_the_reviewed_handouts_points_at_its_centre(reviewed):
    assert sum(_check_arrows(svg, truth, where) for where, svg, truth in reviewed) >= 100


@pytest.mark.parametrize("name", EXAMPLES)
def test_every_edge_arrow_of_plans_centres_points_at_its_centre(name):
    scene = load(example_path(name))
    svg = centres_svg(instant_centres(scene)).decode()
    _check_arrows(svg, true_centres(scene), name)


def test_a_far_centre_arrow_continues_one_of_its_kennedy_lines(reviewed):
    """Where a far centre's Kennedy line is drawn to the edge of the room towards it, its arrow lies on that line
    (the student joins them with a ruler): the arrow's tail within 0.3 mm of the line's extension, on most
    arrows (a few move along the edge to keep clear of another arrow)."""
    on, total = 0, 0
    for where, svg, truth in reviewed:
        lines = [LineString([(p.real, p.imag) for p in pts]) for gid, pts in _paths(svg, "centres-kennedy-").items()]
        heads = _paths(svg, "centres-edge-")
        for label, pts in heads.items():
            if label.endswith("-head") or truth[label][0] is None:
                continue
            tail, tip = pts[0], heads[f"{label}-head"][0]
            u = (tip - tail) / abs(tip - tail)
            # the lines that end just behind the tail, along the arrow
            behind = [line for line in lines if line.distance(Point((tail - 3.0 * MM * u).real, (tail - 3.0 * MM * u).imag)) < 1.2 * MM]
            if not behind:
                continue
            total += 1
            ray = LineString([((tail - 30 * MM * u).real, (tail - 30 * MM * u).imag), (tail.real, tail.imag)])
            if any(ray.buffer(0.3 * MM).contains(Point(line.coords[0])) or ray.buffer(0.3 * MM).contains(Point(line.coords[-1]))
                   for line in behind):
                on += 1
    assert total >= 20 and on >= 0.8 * total, (on, total)


def test_the_linear_arm_p36_arrow_at_the_top_edge_over_it(reviewed):
    """la-bg position 0: P₃₆ lies 63 mm above the drawing's room, over Q; its arrow is at the top edge, its tip no
    more than 10 mm farther from P₃₆ than the room's top edge is (the review's "P₃₆ 93 мм" pointed left from the
    top-right corner)."""
    _, svg, truth = next(r for r in reviewed if r[0] == "linear-arm bg position 0")
    s, o = _placement(svg, truth)
    far = s * truth["P36"][0].conjugate() + o
    heads = _paths(svg, "centres-edge-")
    tail, tip = heads["P36"][0], heads["P36-head"][0]
    marks = [sum(p) / len(p) for p in _paths(svg, "centres-mark-").values()]
    room_top = min(p.imag for pts in _paths(svg, "centres-kennedy-").values() for p in pts)  # the lines end at the room's edge
    assert tail.imag < min(m.imag for m in marks) and tail.imag < room_top, "at the top edge"
    assert abs(far - tip) <= (room_top - far.imag) + 10 * MM, (abs(far - tip) / MM, (room_top - far.imag) / MM)


def test_a_centre_at_a_joint_leaves_its_pin_visible(reviewed):
    """Fifth review: the quick-return's P₃₅, P₃₆, P₄₅, P₄₆ one red blob hiding joint D, P₁₂ … P₂₆ covering O: a
    centre's mark within 1 mm of a joint's pin is open (no fill), so that the pin reads through it."""
    found = 0
    for where, svg, truth in reviewed:
        pins = []
        for _, group in re.findall(r'<g id="(mech-pin-[^"]+)">(.*?)</g>', svg, re.S):
            xs, ys = zip(*[(float(x), float(y)) for x, y in re.findall(r"([-0-9.]+) ([-0-9.]+)", group)])
            pins.append(complex((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2))
        for label, d, style in re.findall(r'<g id="centres-mark-(P[0-9]+)">\s*<path d="([^"]+)"[^>]*?style="([^"]*)"', svg):
            xy = [complex(float(x), float(y)) for x, y in re.findall(r"([-0-9.]+) ([-0-9.]+)", d)]
            q = complex((min(z.real for z in xy) + max(z.real for z in xy)) / 2, (min(z.imag for z in xy) + max(z.imag for z in xy)) / 2)
            dot = max(z.real for z in xy) - min(z.real for z in xy) < 3.2 * MM  # a dot (Kennedy's), not a pair's 4.4 mm ring
            if dot and any(abs(q - p) < 1.0 * MM for p in pins):
                found += 1
                assert "fill: none" in style, (where, label, style)
    assert found >= 5, found
