"""The instant centres drawn on the mechanism, and the circle diagram beside it.

The mechanism is drawn at the length scale k_l (by :func:`plans.drawing.draw_mechanism`,
from the poses the instant-centre method found); on it every centre P_ij is
marked and labelled P₁₂, P₁₃, … (lower number first): a ring around a pin for
a centre given by a revolute pair, a dot for one found by Kennedy's theorem.
The Kennedy lines (each line through the three centres of three bodies) are
drawn thin and dashed.  Centres farther than the drawing's frame around the
mechanism are drawn at its edge as an arrow pointing to them, with their
distance beyond the arrow's tip; centres at infinity as an arrow in their
direction marked ∞.  The circle diagram shows the bodies on a circle, the
primary centres as solid sides and the centres found by Kennedy's theorem as
dashed diagonals.

Gids: ``centres-mark-P13``, ``centres-label-P13``, ``centres-edge-P13``,
``centres-kennedy-1-2-3`` (the line of bodies 1, 2, 3), ``centres-diagram-side-P12``,
``centres-diagram-diagonal-P13``, ``centres-diagram-body-3``.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

from shapely.geometry import LineString, Point, box

from .._text import decimal_comma, user_text
from ..graphical.scales import round_scale
from ..i18n import term
from ._canvas import Sketch, fmt_number, sketch_on, text_size, unit
from .mechanism import MechanismDrawing
from .numerals import scale_caption
from .style import CAPTION_PT, CONSTRUCTION_STYLE, HEADING_PT, INK, MARGIN_MM, SMALL_PT, TITLE_PT
from .svg import new_figure, render_svg

__all__ = ["draw_centres", "draw_centres_into", "draw_circle_diagram_into", "centres_svg", "centre_text", "undetermined_text", "CENTRE_COLOUR",
           "CentresFrame", "centres_frame", "CentresSizer", "edge_text"]

CENTRE_COLOUR = "#C0392B"
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
#: room around the mechanism's ink where centres are drawn where they are [mm]: the larger of
#: ROOM_MIN and ROOM_FRACTION of the ink's larger side.  A centre farther out is an arrow at the
#: edge with its distance, so that far centres never shrink the mechanism (issue 20 §4).
ROOM_MIN = 25.0
ROOM_FRACTION = 0.12
EDGE_ARROW = 9.0  # mm
EDGE_GAP = 2.0  # mm between the room and an edge arrow's tail
EDGE_LABEL_GAP = 0.8  # mm between an edge arrow's tip and its label's box
EDGE_SPACING = 13.0  # mm between the tails of two edge arrows, at least (wider for wide labels)
#: room [mm] kept on every side of the room for the labels of centres near its edge
LABEL_BAND = 7.0
#: room [mm] a centre's label keeps from the mechanism's names and numbers (so that "3" and "P₁₂" read as two)
TEXT_CLEAR_MM = 1.2
LONE_LINE = 25.0  # mm each side of the one finite centre on a Kennedy line
DIAGRAM_R = 22.0  # mm
LABEL_PT = SMALL_PT + 1.5
#: Gaps tried for a centre's label, in units of its mark's clearance; from LEADER_RING on, with a leader line.
LABEL_RINGS = (1, 2, 3, 4.5, 6.5, 9, 12)
LEADER_RING = 2.5
#: the cost of a ring farther out from a centre for its label, in Kennedy lines crossed
RING_COST = 1.5
#: Room [mm] a centre's label keeps from what is drawn (the font's box is an estimate of the ink's).
LABEL_CLEAR_MM = 0.3
#: centres closer than this on the drawing [mm] are one spot: one label names them all
CLUSTER_MM = 1.5
#: the least room [mm] between two centres' labels (beyond LABEL_CLEAR_MM around each)
LABEL_SPACING_MM = 2.0
#: the cost of a centre's label struck through by a link's bar, a slot or the ω arc (a Kennedy line costs 1)
STROKE_COST = 400
#: a centre's dot closer than this [mm] to a joint is under its pin: its label gets a leader
PIN_HIDES_MM = 1.8


#: a text set on white (matplotlib's bbox, pad in points): a Kennedy line through it is hidden under it
_ON_WHITE = {"facecolor": "white", "edgecolor": "none", "pad": 0.8}


def centre_text(label: str) -> str:
    """``P₁₃`` for ``P13``; a label with a comma (names longer than one character) stays as it is."""
    if "," in label:
        return label
    return "P" + label[1:].translate(_SUB)


@dataclass(frozen=True)
class _Drawn:
    """What draw_mechanism reads: the scene, the poses and points, and k_l."""

    scene: object
    scales: dict
    positions: dict
    poses: dict
    travel: dict | None = None  # the lines' travel over the cycle (slots, guides as on the plate's other drawings)
    cycle_poses: tuple | None = None  # the cycle's poses: every support turned as on the plate's other drawings
    fixed_supports: bool = True  # ... on every page, even where a crank lies over it


def _clip(p: complex, u: complex, lo: complex, hi: complex) -> tuple[float, float] | None:
    """The parameter range of the line p + t·u inside the box [lo, hi] (slab method)."""
    t0, t1 = -math.inf, math.inf
    for a, d, low, high in ((p.real, u.real, lo.real, hi.real), (p.imag, u.imag, lo.imag, hi.imag)):
        if abs(d) < 1e-15:
            if not low <= a <= high:
                return None
            continue
        s0, s1 = (low - a) / d, (high - a) / d
        t0, t1 = max(t0, min(s0, s1)), min(t1, max(s0, s1))
    return (t0, t1) if t0 <= t1 else None


def undetermined_text(centre, lang: str = "en") -> str:
    """``P₂₅ undetermined: …`` in *lang* (the method's own reason in English, which names the lines tried)."""
    why = centre.why if lang == "en" else term("centre_undetermined_why", lang)
    return f"{centre_text(centre.label)} {term('centre_undetermined', lang)}: {why}"


def edge_text(centre, distance_mm: float | None) -> str:
    """The label of an edge arrow: ``P₁₃ 245 mm`` (the centre lies 245 mm of the drawing beyond the
    arrow's tip, along it: × k_l in metres), ``P₁₄ ∞`` for a centre at infinity."""
    if distance_mm is None:
        return f"{centre_text(centre.label)} ∞"
    if round(distance_mm) == 0:  # just beyond the tip (a centre just outside the page's box): to 0.1 mm, never "0 mm"
        return f"{centre_text(centre.label)} {max(distance_mm, 0.1):.1f} mm"
    return f"{centre_text(centre.label)} {distance_mm:.0f} mm"


@dataclass(frozen=True)
class EdgeArrow:
    """An arrow at the drawing's edge pointing to a far centre [mm]: tail, tip, its label's text and centre."""

    label: str
    tail: complex
    tip: complex
    text: str
    at: complex


@dataclass(frozen=True)
class CentresFrame:
    """Where the centres drawing at k_l puts things, found from geometry alone [mm of paper, the scene's
    origin at 0, x and y as the scene's].

    ``lo``, ``hi``: the room around the mechanism's ink, where a centre is drawn where it is (``near``);
    every other determined centre is an :class:`EdgeArrow` just outside it (``edges``); ``outer_lo``,
    ``outer_hi``: all of it with the labels (the circle diagram, legend and title aside).
    """

    k_l: float
    lo: complex
    hi: complex
    near: tuple[str, ...]
    edges: tuple[EdgeArrow, ...]
    outer_lo: complex
    outer_hi: complex

    @property
    def width(self) -> float:
        """Across [mm], margins included: the width :func:`draw_centres_into` returns without diagram, legend or title."""
        return self.outer_hi.real - self.outer_lo.real + 2 * MARGIN_MM

    @property
    def height(self) -> float:
        """Up [mm], margins included."""
        return self.outer_hi.imag - self.outer_lo.imag + 2 * MARGIN_MM


def _label_box(tail: complex, tip: complex, u: complex, text: str) -> tuple[complex, float, float]:
    """Where an edge arrow's label goes, as its box's centre and (w, h) [mm]: just beyond the tip of an
    arrow pointing up or down; over (or under) the shaft of one pointing sideways, its end at the tip,
    so that a wide label does not widen the drawing."""
    w, h = text_size(text, LABEL_PT)
    if abs(u.imag) >= 0.6:  # the box's edge 0.8 mm from the tip along the arrow: at its own tip, never nearer another
        reach = min(w / (2 * abs(u.real)) if abs(u.real) > 1e-9 else math.inf, h / (2 * abs(u.imag)))
        return tip + u * (EDGE_LABEL_GAP + reach), w, h
    side = 1.0 if u.imag >= 0 else -1.0  # over an arrow rising a little, under one falling
    x = tip.real - w / 2 if u.real > 0 else tip.real + w / 2
    y = max(tip.imag, tail.imag) + h / 2 + EDGE_LABEL_GAP if side > 0 else min(tip.imag, tail.imag) - h / 2 - EDGE_LABEL_GAP
    return complex(x, y), w, h


def _within(at: complex, w: float, h: float, allowed) -> complex:
    """A label's box centre *at* moved the least into the box *allowed* (lower-left, upper-right) [mm]."""
    return complex(min(max(at.real, allowed[0].real + w / 2), allowed[1].real - w / 2),
                   min(max(at.imag, allowed[0].imag + h / 2), allowed[1].imag - h / 2))


def _box_at(at: complex, w: float, h: float):
    """The box of a label of size (w, h) [mm] centred at *at*."""
    return box(at.real - w / 2, at.imag - h / 2, at.real + w / 2, at.imag + h / 2)


@dataclass(frozen=True)
class _Segment:
    """A Kennedy line as the drawing draws it: its bodies' numbers (``"1-2-3"``), its three centres' labels and its two
    ends [mm] (within the room)."""

    names: str
    labels: tuple[str, ...]
    ends: tuple[complex, complex]


def _kennedy_segments(result, k_l: float, lo: complex, hi: complex) -> list[_Segment]:
    """Each Kennedy line that gave a centre, through its three centres, clipped to the room (*lo*, *hi*) [mm]: from 6 mm
    before its first finite centre to 6 mm beyond its last (so to the room's edge towards a centre outside it), or
    LONE_LINE each side of its one finite centre; none for the line at infinity."""
    by_label = {c.label: c for c in result.centres}
    done = set()
    out = []
    for centre in result.centres:
        for pair in centre.lines:
            three = [by_label[pair[0]], by_label[pair[1]], centre]
            bodies = tuple(sorted({b for c in three for b in c.bodies}, key=list(result.numbers).index))
            if bodies in done:
                continue
            done.add(bodies)
            finite = [c.point / k_l for c in three if c.point is not None]
            infinite = [c.direction for c in three if c.point is None]
            if not finite:
                continue  # the line at infinity
            if len(finite) >= 2:
                a, b = max(((p, q) for p in finite for q in finite), key=lambda pq: abs(pq[0] - pq[1]))
                if abs(b - a) < 1e-9:
                    continue
                u = unit(b - a)
                ts = [((q - a) * u.conjugate()).real for q in finite]
                t0, t1 = min(ts) - 6.0, max(ts) + 6.0
            else:
                a, u = finite[0], infinite[0]
                t0, t1 = -LONE_LINE, LONE_LINE
            span = _clip(a, u, lo, hi)
            if span is None:
                continue
            t0, t1 = max(t0, span[0]), min(t1, span[1])
            if t1 <= t0:
                continue
            out.append(_Segment("-".join(result.numbers[b] for b in bodies), tuple(c.label for c in three), (a + t0 * u, a + t1 * u)))
    return out


def _along(lo: complex, hi: complex, s: float) -> complex:
    """The point of the box (*lo*, *hi*)'s edge at arc length *s* [mm] from its lower-left corner, anticlockwise."""
    w, h = hi.real - lo.real, hi.imag - lo.imag
    s %= 2 * (w + h)
    if s <= w:
        return complex(lo.real + s, lo.imag)
    if s <= w + h:
        return complex(hi.real, lo.imag + s - w)
    if s <= 2 * w + h:
        return complex(hi.real - (s - w - h), hi.imag)
    return complex(lo.real, hi.imag - (s - 2 * w - h))


def _arc_of(lo: complex, hi: complex, q: complex) -> float:
    """The arc length [mm] (see :func:`_along`) of the point of the box's edge nearest *q*."""
    w, h = hi.real - lo.real, hi.imag - lo.imag
    x, y = min(max(q.real, lo.real), hi.real), min(max(q.imag, lo.imag), hi.imag)
    side = min((y - lo.imag, 0), (hi.real - x, 1), (hi.imag - y, 2), (x - lo.real, 3))[1]  # the nearest side
    return (x - lo.real, w + y - lo.imag, w + h + hi.real - x, 2 * w + h + hi.imag - y)[side]


def _on_edge(q: complex, lo: complex, hi: complex) -> bool:
    """Whether *q* lies on the box's edge (to 1 µm), as a line clipped to it ends."""
    return min(abs(q.real - lo.real), abs(q.real - hi.real), abs(q.imag - lo.imag), abs(q.imag - hi.imag)) < 1e-3


def _aimed(tail: complex, far: complex | None, direction: complex, allowed) -> tuple[complex, complex, complex]:
    """An edge arrow from about *tail* [mm] pointing at the centre *far* [mm] (None: at infinity in *direction*), kept
    within the page's box *allowed* (lower-left, upper-right; None: no box): (tail, tip, its unit direction).

    The direction is always the bearing from the arrow's final tail to the centre: a tail the box moves is aimed
    again (the linear-arm's edge arrows were moved after they were aimed and pointed 50° off their centres).  An
    arrow running out of the box is first drawn back along its own bearing (so it stays on the line it continues), up
    to 20 mm, else moved into the box and aimed anew."""
    def bearing(q: complex) -> complex:
        return unit(far - q) if far is not None else direction

    def outside(a: complex, b: complex) -> complex:
        """How far the segment a–b must move to lie within the box (0 inside)."""
        return complex(*(max(lo_a - min(p, r), 0.0) + min(hi_a - max(p, r), 0.0)
                         for p, r, lo_a, hi_a in ((a.real, b.real, allowed[0].real, allowed[1].real),
                                                  (a.imag, b.imag, allowed[0].imag, allowed[1].imag))))

    def length(q: complex) -> float:  # a centre just beyond the tail: the tip short of it
        return EDGE_ARROW if far is None else min(EDGE_ARROW, max(abs(far - q) - 1.0, 3.0))

    q = tail
    if allowed is not None:
        u = bearing(q)
        shift = outside(q, q + length(q) * u)
        if abs(shift) > 1e-9:
            # back along the bearing: the part of the shift along −u, where −u goes the shift's way on each axis
            need = [abs(s) / abs(c) for s, c in ((shift.real, u.real), (shift.imag, u.imag))
                    if abs(s) > 1e-9 and abs(c) > 1e-9 and s * c < 0]
            ok = all(not (abs(s) > 1e-9 and (abs(c) <= 1e-9 or s * c >= 0)) for s, c in ((shift.real, u.real), (shift.imag, u.imag)))
            if ok and need and max(need) <= 20.0:
                q = q - max(need) * u
            else:
                for _ in range(4):
                    u = bearing(q)
                    shift = outside(q, q + length(q) * u)
                    if abs(shift) < 1e-9:
                        break
                    q = q + shift
    u = bearing(q)
    return q, q + length(q) * u, u


def _edge_label(tail: complex, tip: complex, u: complex, text: str, allowed) -> tuple[complex, float, float]:
    """Where an edge arrow's label goes (:func:`_label_box`), slid into the page's box *allowed* and, where that put
    it over its own arrow, beside the tip on the side away from the shaft, else under or over it."""
    at, w, h = _label_box(tail, tip, u, text)
    if allowed is None:
        return at, w, h
    at = _within(at, w, h, allowed)
    shaft = LineString([(tail.real, tail.imag), (tip.real, tip.imag)])
    if _box_at(at, w, h).intersects(shaft):
        side = 1.0 if u.real >= 0 else -1.0
        for c in (tip + side * (w / 2 + EDGE_LABEL_GAP), tip - side * (w / 2 + EDGE_LABEL_GAP),
                  tip - 1j * (h / 2 + EDGE_LABEL_GAP), tip + 1j * (h / 2 + EDGE_LABEL_GAP)):
            c = _within(c, w, h, allowed)
            if not _box_at(c, w, h).intersects(shaft):
                return c, w, h
    return at, w, h


#: the cost of an edge arrow's place: each thing it or its label runs over, each EDGE_SLIDE [mm] along the edge from
#: where it starts, a start off its centre's Kennedy lines, each mm it is drawn back over the room
EDGE_HIT_COST = 10.0
EDGE_SLIDE = 6.5
EDGE_SLIDE_COST = 0.25
EDGE_OFF_LINE_COST = 1.0
EDGE_PULL_COST = 0.05
#: a Kennedy line's end this much farther [mm] from the centre than the drawing's nearest edge costs one EDGE_OFF_LINE_COST more
EDGE_LINE_DETOUR = 40.0


def _edge_arrow(centre, k_l: float, lo: complex, hi: complex, allowed, segments, edges, boxes) -> tuple[EdgeArrow, list]:
    """The edge arrow of the centre off the drawing, and the shapes it and its label take (for the arrows after it).

    Its tail starts (in the order they are preferred) where one of the centre's Kennedy lines reaches the room's
    edge towards it, so that the arrow continues the line (the linear-arm's P₁₃ straight above F: the arrow at the
    top edge over F); at the point of the edge nearest the centre (the linear-arm's P₃₆ just above Q: at the top
    edge over Q, not in a corner across the page); for a centre at infinity, where the ray from the room's middle
    in its direction leaves the room.  From each it slides along the edge, EDGE_SLIDE at a time, until it and its
    label run over nothing placed before (marks, arrows, labels); the cheapest place wins (see EDGE_HIT_COST …).
    Wherever it goes it points along the bearing from its tail to the centre (:func:`_aimed`)."""
    far = centre.point / k_l if centre.point is not None else None
    middle = (lo + hi) / 2
    ring = (lo - EDGE_GAP * (1 + 1j), hi + EDGE_GAP * (1 + 1j))
    starts: list[tuple[float, complex]] = []  # (cost of the start, tail)
    if far is not None:
        nearest = complex(min(max(far.real, ring[0].real), ring[1].real), min(max(far.imag, ring[0].imag), ring[1].imag))
        for seg in segments:
            if centre.label not in seg.labels:
                continue
            end = min(seg.ends, key=lambda z: abs(far - z))
            if not _on_edge(end, lo, hi) or abs(far - end) < 1e-6:
                continue  # the line stops short of the room's edge
            tail = end + EDGE_GAP * unit(far - end)
            starts.append((max(0.0, abs(far - tail) - abs(far - nearest)) / EDGE_LINE_DETOUR * EDGE_OFF_LINE_COST, tail))
        starts.append((EDGE_OFF_LINE_COST, nearest))
    else:
        u0 = centre.direction
        span = _clip(middle, u0, lo, hi)
        starts.append((0.0, middle + span[1] * u0 + EDGE_GAP * u0))
    perimeter = 2 * (ring[1].real - ring[0].real + ring[1].imag - ring[0].imag)
    steps = int(perimeter / 2 / EDGE_SLIDE)
    candidates = sorted(((cost + EDGE_SLIDE_COST * abs(k), n, k, tail) for n, (cost, tail) in enumerate(starts)
                         for k in range(-steps, steps + 1)), key=lambda c: (c[0], c[1], abs(c[2]), c[2]))
    best = None
    for bound, _, k, tail in candidates:
        if best is not None and best[0] <= bound:
            break  # nothing after this can cost less
        if k:
            tail = _along(ring[0], ring[1], _arc_of(ring[0], ring[1], tail) + k * EDGE_SLIDE)
        q, tip, u = _aimed(tail, far, centre.direction, allowed)
        text = edge_text(centre, abs(far - tip) if far is not None else None)
        at, w, h = _edge_label(q, tip, u, text, allowed)
        shape = box(at.real - w / 2 - 0.8, at.imag - h / 2 - 0.8, at.real + w / 2 + 0.8, at.imag + h / 2 + 0.8)
        shaft = LineString([(q.real, q.imag), (tip.real, tip.imag)])
        arrow = shaft.buffer(1.0)
        hits = sum(1 for e in edges if abs(q - e.tail) < EDGE_SPACING) + sum(1 for b in boxes if shape.intersects(b) or arrow.intersects(b))
        hits += int(_box_at(at, w, h).intersects(shaft))  # a label over its own arrow
        cost = bound + EDGE_HIT_COST * hits + EDGE_PULL_COST * abs(q - tail)
        if best is None or cost < best[0]:
            best = (cost, EdgeArrow(centre.label, q, tip, text, at), [shape, arrow])
    return best[1], best[2]


def centres_frame(result, k_l: float, ink: tuple[complex, complex], room_min: float = ROOM_MIN,
                  limit: tuple[float, float] | None = None) -> CentresFrame:
    """The frame of the centres drawing at *k_l* [m/mm] around the mechanism's *ink* (lower-left, upper-right [mm]).

    The room is the ink widened by ROOM_MIN [mm] or ROOM_FRACTION of its larger side; a centre
    inside is drawn where it is, every other one (and one at infinity) as an arrow just outside the
    room on the ray from its middle towards the centre, the arrows spread apart so that neither they
    nor their labels overlap.  Nothing here draws: the page finds its k_l from this.
    With *limit* (width, height) [mm], the drawing is that box around the ink's middle: the room shrinks
    (down to the ink) to leave the box's edge band to the edge arrows, every arrow and label is kept in
    the box (an arrow pulled back over the room where the band is narrower than it), and the room grows
    to hold a centre just outside it only within the box: a page draws at the plate's k_l whenever the
    mechanism's ink fits its box.
    """
    lo, hi = ink
    room = max(room_min, ROOM_FRACTION * max(hi.real - lo.real, hi.imag - lo.imag))
    # with a limit, the drawing is the page's box around the ink's middle: the room shrinks to leave the box's
    # edge band to the edge arrows and their labels (never inside the ink), so that the page keeps its k_l
    if limit is not None:
        middle = (lo + hi) / 2
        half = complex(limit[0] / 2 - MARGIN_MM, limit[1] / 2 - MARGIN_MM)
        allowed = (middle - half, middle + half)
        band = complex(EDGE_GAP + EDGE_ARROW + 1.5, EDGE_GAP + EDGE_ARROW + 2.5 + text_size("P₁₂ 99 mm", LABEL_PT)[1])
        most = (allowed[0] + band, allowed[1] - band)  # the largest room the box holds with its edge band
        lo = complex(min(lo.real, max(lo.real - room, most[0].real)), min(lo.imag, max(lo.imag - room, most[0].imag)))
        hi = complex(max(hi.real, min(hi.real + room, most[1].real)), max(hi.imag, min(hi.imag + room, most[1].imag)))
    else:
        allowed = most = None
        lo, hi = lo - room * (1 + 1j), hi + room * (1 + 1j)
    # a centre no farther out than an edge arrow would reach is drawn where it is, and the room grows to hold it
    reach = EDGE_GAP + EDGE_ARROW + 4.0
    for centre in (c for c in result.centres if c.determined and c.point is not None):
        q = centre.point / k_l
        if lo.real - reach <= q.real <= hi.real + reach and lo.imag - reach <= q.imag <= hi.imag + reach:
            new_lo = complex(min(lo.real, q.real - 3.0), min(lo.imag, q.imag - 3.0))
            new_hi = complex(max(hi.real, q.real + 3.0), max(hi.imag, q.imag + 3.0))
            if allowed is not None and not (allowed[0].real <= new_lo.real and allowed[0].imag <= new_lo.imag
                                            and new_hi.real <= allowed[1].real and new_hi.imag <= allowed[1].imag):
                if not (allowed[0].real <= q.real <= allowed[1].real and allowed[0].imag <= q.imag <= allowed[1].imag):
                    continue  # an arrow at the edge: the room stays within the page's
                # the centre itself within the page's box, nearer its edge than the room's 3 mm around it: the room
                # grows to the box's edge and holds it, a dot where it is (the six-bar's P₄₆ was an arrow "0 mm"
                # from its tip, the arrow pulled back over the room onto the centre)
                new_lo = complex(max(new_lo.real, allowed[0].real), max(new_lo.imag, allowed[0].imag))
                new_hi = complex(min(new_hi.real, allowed[1].real), min(new_hi.imag, allowed[1].imag))
            lo, hi = new_lo, new_hi

    def inside(q: complex) -> bool:
        return lo.real <= q.real <= hi.real and lo.imag <= q.imag <= hi.imag

    near: list[str] = []
    edges: list[EdgeArrow] = []
    # the marks of the centres drawn where they are: no edge arrow or its label over one (the quick-return's P₄₆ dot
    # covered "P₃₅ 2178 mm")
    boxes: list = [Point(c.point.real / k_l, c.point.imag / k_l).buffer(2.6) for c in result.centres
                   if c.determined and c.point is not None and inside(c.point / k_l)]
    outer_lo, outer_hi = lo - LABEL_BAND * (1 + 1j), hi + LABEL_BAND * (1 + 1j)
    if allowed is not None:  # the labels of the centres near the room's edge keep within the page's box
        outer_lo = complex(max(outer_lo.real, min(lo.real, allowed[0].real)), max(outer_lo.imag, min(lo.imag, allowed[0].imag)))
        outer_hi = complex(min(outer_hi.real, max(hi.real, allowed[1].real)), min(outer_hi.imag, max(hi.imag, allowed[1].imag)))
    segments = _kennedy_segments(result, k_l, lo, hi)
    far = []
    for centre in result.centres:
        if not centre.determined:
            continue
        if centre.point is not None and inside(centre.point / k_l):
            near.append(centre.label)
        else:
            far.append(centre)
    # the finite ones first: each has its few places at the ends of its Kennedy lines, where a centre at infinity
    # points the same way from anywhere
    for centre in sorted(far, key=lambda c: c.point is None):
        e, shapes = _edge_arrow(centre, k_l, lo, hi, allowed, segments, edges, boxes)
        boxes += shapes
        edges.append(e)
        w, h = text_size(e.text, LABEL_PT)
        for z in (e.tail, e.tip, complex(e.at.real - w / 2, e.at.imag - h / 2), complex(e.at.real + w / 2, e.at.imag + h / 2)):
            outer_lo = complex(min(outer_lo.real, z.real), min(outer_lo.imag, z.imag))
            outer_hi = complex(max(outer_hi.real, z.real), max(outer_hi.imag, z.imag))
    return CentresFrame(k_l, lo, hi, tuple(near), tuple(edges), outer_lo, outer_hi)


class _CentresDrawing:
    def __init__(self, sketch: Sketch, result, frame: CentresFrame, lang: str = "en"):
        self.lang = lang
        self.s = sketch
        self.r = result
        self.frame = frame
        self.k_l = frame.k_l
        self.lo, self.hi = frame.lo, frame.hi
        self.middle = (self.lo + self.hi) / 2
        self.soft: list = []  # the Kennedy lines: a label may cross one, at a cost
        self.words: list = []  # the boxes of the mechanism's names and numbers and of the labels placed so far
        self.marks: list = []  # the centres' marks and the joints [mm]: a label is nearer its own than any of these
        self.bodies: list = []  # the mechanism's blocks, supports and hatching: no label under one
        self.strokes: list = []  # the links' bars, slots and the ω arc: no label struck through by one
        self.placed: list = []  # the boxes of the centres' labels placed so far: the next keeps LABEL_SPACING_MM from them

    def mm(self, z: complex) -> complex:
        return z / self.k_l

    def inside(self, q: complex) -> bool:
        return self.lo.real <= q.real <= self.hi.real and self.lo.imag <= q.imag <= self.hi.imag

    def label(self, at: complex, text: str, gid: str, away: complex, clear: float, hidden: bool = False) -> None:
        """Text near *at*, at the first of eight places around it that overlaps nothing drawn before (*hidden*: the
        mark lies under a joint's pin, so the label is set out with a leader that shows where the centre is)."""
        w, h = text_size(text, LABEL_PT)
        start = cmath.phase(away) if abs(away) > 1e-9 else math.pi / 4
        best = None
        for k in range(16 * len(LABEL_RINGS)):
            if k % 16 == 0 and best is not None and best[0] <= RING_COST * (k // 16):
                break  # no place farther out can cost less
            turn = (k % 16 + 1) // 2 * (1 if k % 2 else -1) * math.pi / 8
            d = cmath.exp(1j * (start + turn))
            ring = LABEL_RINGS[k // 16]
            if hidden and ring < LEADER_RING:
                continue
            gap = clear * ring + 0.6 + 0.5 * (abs(d.real) * w + abs(d.imag) * h)
            c = at + d * gap
            shape = box(c.real - w / 2, c.imag - h / 2, c.real + w / 2, c.imag + h / 2).buffer(LABEL_CLEAR_MM, join_style=2)
            # beside its own mark: each ring farther out costs as much as crossing RING_COST dashed Kennedy lines (the
            # linear-arm's P₂₃ went 8 mm from F to keep off the thin lines through it)
            hits = RING_COST * (k // 16)
            hits += 10 * sum(1 for o in self.s.obstacles if shape.intersects(o)) + sum(1 for o in self.soft if shape.intersects(o))
            hits += 1000 * sum(1 for o in self.words if shape.intersects(o))  # never over another label or name
            # two centres' labels apart enough to read as two (the linear-arm's P₁₅ and P₁₄ side by side at D)
            hits += 1000 * sum(1 for o in self.placed if shape.distance(o) < LABEL_SPACING_MM)
            hits += 300 * sum(1 for o in self.bodies if shape.intersects(o))  # nor under a block, a support, its hatching
            hits += STROKE_COST * sum(1 for o in self.strokes if shape.intersects(o))  # nor struck through by a link
            # read as its own: nearer its own mark than any other centre's (or a joint's); a leader says it otherwise
            own = abs(c - at)
            if ring < LEADER_RING:
                hits += 200 * sum(1 for q in self.marks if abs(q - at) > 0.5 * CLUSTER_MM and abs(c - q) < own)
            f = self.frame
            if not (f.outer_lo.real <= c.real - w / 2 and c.real + w / 2 <= f.outer_hi.real and f.outer_lo.imag <= c.imag - h / 2 and c.imag + h / 2 <= f.outer_hi.imag):
                hits += 100  # within the drawing's frame, whose size the page found beforehand
            leader = None
            if ring >= LEADER_RING:  # away from a crowd, a leader line joins the label to its centre
                a = at + d * clear
                b = c - d * (0.5 * (abs(d.real) * w + abs(d.imag) * h) + 0.3)
                leader = (a, b)
                line = LineString([(a.real, a.imag), (b.real, b.imag)])
                hits += 10 * sum(1 for o in self.s.obstacles if line.intersects(o))
                hits += 300 * sum(1 for o in self.words if line.intersects(o))  # a leader across a name or a number
            if best is None or hits < best[0]:
                best = (hits, c, leader)
            if hits == RING_COST * (k // 16):
                break
        _, c, leader = best
        if leader is not None:
            self.s.line(list(leader), color=CENTRE_COLOUR, lw=0.4, gid=f"{gid}-leader", zorder=4.9)
        self.s.text(c, text, size=LABEL_PT, color=CENTRE_COLOUR, gid=gid)
        self.words.append(box(c.real - w / 2, c.imag - h / 2, c.real + w / 2, c.imag + h / 2))
        self.placed.append(self.words[-1])

    def kennedy_lines(self) -> None:
        """Each Kennedy line that gave a centre, through its three centres, inside the room (:func:`_kennedy_segments`)."""
        colour, lw, dashes = CONSTRUCTION_STYLE
        for seg in _kennedy_segments(self.r, self.k_l, self.lo, self.hi):
            self.s.line(list(seg.ends), color=colour, lw=lw * 0.8, dashes=dashes, gid=f"kennedy-{seg.names}", zorder=1.2, obstacle=False)
            self.soft.append(LineString([(z.real, z.imag) for z in seg.ends]))

    def centres(self) -> None:
        # the edge arrows first (their places are fixed): the labels of the near centres keep off them
        for e in self.frame.edges:
            self.s.arrow(e.tail, e.tip, color=CENTRE_COLOUR, lw=1.0, head=2.4, gid=f"edge-{e.label}")
            self.s.text(e.at, decimal_comma(e.text, self.lang), size=LABEL_PT, color=CENTRE_COLOUR, gid=f"label-{e.label}").set_bbox(_ON_WHITE)
        self.words += _edge_shapes(self.frame)  # no label over an edge arrow or its label
        # and a centre's label keeps LABEL_SPACING_MM from an edge arrow's label, as from another centre's (the
        # quick-return's "P₃₆" dot label 1 mm under "P₃₅ 360 mm")
        self.placed += [_box_at(e.at, *text_size(e.text, LABEL_PT)) for e in self.frame.edges]
        # every mark first (each an obstacle), then the labels: a label keeps off every mark, not only those before it
        near = [c for c in self.r.centres if c.determined and c.label in self.frame.near]
        self.marks += [self.mm(z) for z in self.r.positions.values()]
        placed = []
        for centre in near:
            q = self.mm(centre.point)
            if centre.found_by.startswith("revolute"):
                self.s.circle(q, 2.2, fc="none", ec=CENTRE_COLOUR, lw=0.9, gid=f"mark-{centre.label}", zorder=5.0)
                clear = 2.4
            elif any(abs(q - self.mm(z)) < PIN_HIDES_MM for z in self.r.positions.values()):
                # at a joint's pin: an open dot, through which the pin shows (the quick-return's four dots at D hid it)
                self.s.circle(q, 0.8, fc="none", ec=CENTRE_COLOUR, lw=0.8, gid=f"mark-{centre.label}", zorder=5.0)
                clear = 1.2
            else:
                self.s.circle(q, 1.0, fc=CENTRE_COLOUR, ec=CENTRE_COLOUR, lw=0.5, gid=f"mark-{centre.label}", zorder=5.0)
                clear = 1.2
            self.marks.append(q)
            placed.append((centre, q, clear))
        # centres at one spot of the drawing (the quick-return's P₃₅, P₃₆, P₄₅, P₄₆ at D) take one label, "P₃₅, P₃₆, …"
        groups: list[list] = []
        for item in placed:
            near_group = [g for g in groups if any(abs(item[1] - other[1]) < CLUSTER_MM for other in g)]
            merged = [item] + [x for g in near_group for x in g]
            groups = [g for g in groups if g not in near_group] + [sorted(merged, key=lambda x: placed.index(x))]
        labels = []
        for group in sorted(groups, key=lambda g: placed.index(g[0])):
            at = sum(x[1] for x in group) / len(group)
            spread = max(abs(x[1] - at) for x in group)
            text = ", ".join(centre_text(x[0].label) for x in group)
            gid = "label-" + "-".join(x[0].label for x in group)
            labels.append((at, text, gid, max(x[2] for x in group) + spread))  # (a ring's clearance 2.4, a dot's 1.2)
            if len(group) > 1:  # the marks of one spot count as one: a label is nearer it than any other
                self.marks = [m for m in self.marks if all(abs(m - x[1]) > 1e-9 for x in group)] + [at]

        # the most crowded first: a centre with marks close around it takes its place before its neighbours
        def crowd(item):
            return -sum(1 for other in self.marks if abs(other - item[0]) < 8.0)
        joints = [self.mm(z) for z in self.r.positions.values()]
        for at, text, gid, clear in sorted(labels, key=crowd):
            # a dot under a joint's pin (the quick-return's P₂₆ under O) is shown by a leader
            hidden = clear < 2.0 and any(abs(at - q) < PIN_HIDES_MM for q in joints)
            self.label(at, text, gid, at - self.middle, clear, hidden)


def _circle_diagram(s: Sketch, result, centre: complex, lang: str = "en", caption: bool = True, radius: float = DIAGRAM_R) -> None:
    """Bodies on a circle of *radius* [mm] (1 at the top, clockwise), primary centres as solid lines, Kennedy ones as
    dashed; *caption* False leaves its heading and legend to the page (set in the page's typeface)."""
    names = list(result.numbers)
    n = len(names)
    at = {name: centre + radius * cmath.exp(1j * (math.pi / 2 - 2 * math.pi * k / n)) for k, name in enumerate(names)}
    s.circle(centre, radius, fc="none", ec="#b0b0b0", lw=0.5, gid="diagram-circle", zorder=1.0, obstacle=False)
    colour, lw, dashes = CONSTRUCTION_STYLE
    for c in result.centres:
        a, b = at[c.bodies[0]], at[c.bodies[1]]
        if not c.determined:
            continue
        if c.found_by == "kennedy":
            s.line([a, b], color=CENTRE_COLOUR, lw=0.7, dashes=(3.0, 2.0), gid=f"diagram-diagonal-{c.label}", zorder=2.0, obstacle=False)
        else:
            s.line([a, b], color=INK, lw=1.2, gid=f"diagram-side-{c.label}", zorder=2.5, obstacle=False)
    for name, q in at.items():
        s.circle(q, 1.0, fc=INK, ec=INK, lw=0.3, gid=f"diagram-body-{result.numbers[name]}", zorder=4.0)
        s.text(q + 4.2 * unit(q - centre), result.numbers[name], size=HEADING_PT, gid=f"diagram-number-{result.numbers[name]}")
    if not caption:
        return
    s.text(centre - 1j * (radius + 8.0), term("circle_diagram", lang), size=CAPTION_PT, weight="bold", gid="diagram-heading", obstacle=False)
    lines = []
    for part in term("circle_diagram_legend", lang).split("\n"):  # each part wrapped to the diagram's width
        current = ""
        for word in part.split():
            trial = f"{current} {word}".strip()
            if current and text_size(trial, CAPTION_PT)[0] > 2 * radius + 6.0:
                lines.append(current)
                current = word
            else:
                current = trial
        lines.append(current)
    for k, line in enumerate(lines):
        s.text(centre - 1j * (radius + 12.5 + 4.0 * k), line, size=CAPTION_PT, gid="diagram-legend", obstacle=False)


def _text_shapes(artists) -> list:
    """The boxes of the texts among *artists* [mm], TEXT_CLEAR_MM wider on every side."""
    from matplotlib.text import Text

    return _shapes([a for a in artists if isinstance(a, Text)])


def _stroke_shapes(artists) -> list:
    """The links' bars, slots and guides' lines and the ω arc among *artists* [mm] (what a label must not be struck
    through by), each widened by half its stroke and a little."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Polygon

    strokes = ("mech-link", "mech-omega", "mech-slot", "mech-line", "mech-block", "mech-sleeve")
    return _shapes([a for a in artists if isinstance(a, (Line2D, Polygon)) and (a.get_gid() or "").startswith(strokes)
                    and not (a.get_gid() or "").startswith("mech-omega-label")], pad=0.5)


def _body_shapes(artists) -> list:
    """The mechanism's blocks and supports (polygons) and its ground's hatching among *artists* [mm]."""
    from matplotlib.collections import LineCollection
    from matplotlib.patches import Polygon

    return _shapes([a for a in artists if isinstance(a, (Polygon, LineCollection))])


def _shapes(artists, pad: float = 0.4) -> list:
    """Obstacles for the labels from the mechanism's artists: lines, circles, polygons, text boxes [mm]."""
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, Polygon
    from matplotlib.text import Text
    from shapely.geometry import LineString, Point
    from shapely.geometry import Polygon as ShapelyPolygon

    shapes = []
    for artist in artists:
        if isinstance(artist, Line2D):
            xy = list(zip(artist.get_xdata(), artist.get_ydata()))
            if len(xy) >= 2:
                shapes.append(LineString(xy).buffer(pad))
        elif isinstance(artist, Circle):
            x, y = artist.center
            shapes.append(Point(x, y).buffer(artist.radius))
        elif isinstance(artist, Polygon):
            xy = artist.get_xy()
            if len(xy) >= 3:
                shapes.append(ShapelyPolygon(xy).buffer(0.2))
        elif isinstance(artist, LineCollection):  # the ground's hatching
            for segment in artist.get_segments():
                if len(segment) >= 2:
                    shapes.append(LineString([tuple(xy) for xy in segment]).buffer(0.3))
        elif isinstance(artist, Text) and artist.get_text():
            w, h = text_size(artist.get_text(), artist.get_fontsize())
            x, y = artist.get_position()
            x0 = {"left": x, "center": x - w / 2, "right": x - w}.get(artist.get_ha(), x - w / 2)
            y0 = {"bottom": y, "center": y - h / 2, "top": y - h}.get(artist.get_va(), y - h / 2)
            shapes.append(box(x0, y0, x0 + w, y0 + h).buffer(TEXT_CLEAR_MM, join_style=2))
    return shapes


def _mechanism(ax, result, k_l: float, lang: str, cycle=None):
    """The mechanism at *k_l* drawn into *ax*: (its artists, its ink's (lower-left, upper-right) [mm]).

    *cycle*: ``(travel, cycle_poses)`` of the plate's drawings (:func:`plans.positions.cycle_poses`,
    :func:`plans.sweep.line_travel`): the guides over their travel and every support turned one way
    for the whole cycle, as on the plan of positions."""
    # the centres' marks are there before the mechanism's labels are placed: a link number or a point's
    # name keeps clear of them (the six-bar's "2" touched P₂₆)
    marks = [Point(c.point.real / k_l, c.point.imag / k_l).buffer((2.2 if c.found_by.startswith("revolute") else 1.0) + 0.4)
             for c in result.centres if c.determined and c.point is not None]
    travel, poses = cycle if cycle is not None else (None, None)
    drawn = _Drawn(result.scene, {"k_l": k_l}, result.positions, result.poses, travel, poses)
    # no heading or scale under the mechanism: the drawing states k_l in its frame (draw_centres_into)
    artists = sketch_on(ax, "mech", lambda sketch: (sketch.obstacles.extend(marks), MechanismDrawing(sketch, drawn, lang=lang, caption=False).draw()))
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    return artists, (complex(x0 + MARGIN_MM, y0 + MARGIN_MM), complex(x1 - MARGIN_MM, y1 - MARGIN_MM))


class CentresSizer:
    """The centres drawing's size [mm] at any k_l, found without drawing it there.

    The mechanism is drawn twice, alone (at *k0* and *k0*/2; *k0* by default the round value that
    draws it 60–120 mm): how far its ink reaches beyond its points on each side is a part fixed in
    millimetres (names, supports, arrows) and a part that scales (guides), a + b/k_l, which the two
    drawings give.  The rest (the room, which centres are drawn where they are, the edge arrows and
    their labels) is :func:`centres_frame`, geometry alone.  So the page tries any number of k_l for
    the price of two drawings of the mechanism (the six-position handout drew its centres page 114 times).
    """

    def __init__(self, result, lang: str = "en", room_min: float = ROOM_MIN, k0: float | None = None, cycle=None):
        from .svg import new_figure

        self.result, self.room_min = result, room_min
        xs = [z.real for z in result.positions.values()]
        ys = [z.imag for z in result.positions.values()]
        self.lo_m, self.hi_m = complex(min(xs), min(ys)), complex(max(xs), max(ys))
        k0 = k0 or round_scale(result.size)
        over = []
        for k in (k0, k0 / 2):
            ax = new_figure().add_axes([0, 0, 1, 1])
            _, (lo, hi) = _mechanism(ax, result, k, lang, cycle)
            over.append((self.lo_m / k - lo, hi - self.hi_m / k))  # (left, bottom), (right, top) beyond the points [mm]
        # o(k) = a + b/k per side, from o(k0) and o(k0/2)
        self.model = []
        for first, second in zip(over[0], over[1]):
            b = (second - first) * k0
            self.model.append((first - b / k0, b))

    def ink(self, k_l: float) -> tuple[complex, complex]:
        """The mechanism's ink at *k_l*: (lower-left, upper-right) [mm]."""
        (a_lo, b_lo), (a_hi, b_hi) = self.model
        return self.lo_m / k_l - (a_lo + b_lo / k_l), self.hi_m / k_l + (a_hi + b_hi / k_l)

    def frame(self, k_l: float, limit: tuple[float, float] | None = None) -> CentresFrame:
        return centres_frame(self.result, k_l, self.ink(k_l), self.room_min, limit)

    def size(self, k_l: float, limit: tuple[float, float] | None = None) -> tuple[float, float]:
        """(width, height) [mm] of :func:`draw_centres_into` at *k_l* with no diagram, legend or title (*limit*: see
        :func:`centres_frame`)."""
        frame = self.frame(k_l, limit)
        return frame.width, frame.height


def _edge_shapes(frame: CentresFrame) -> list:
    """The edge arrows and their labels [mm] as shapes (what the k_l caption and the near centres' labels keep off)."""
    shapes = []
    for e in frame.edges:
        w, h = text_size(e.text, LABEL_PT)
        shapes.append(LineString([(e.tail.real, e.tail.imag), (e.tip.real, e.tip.imag)]).buffer(1.2))
        shapes.append(box(e.at.real - w / 2, e.at.imag - h / 2, e.at.real + w / 2, e.at.imag + h / 2).buffer(0.5))
    return shapes


def _caption_corner(frame: CentresFrame, caption: str, obstacles: list) -> tuple[complex, str, str]:
    """Where the k_l caption goes: (anchor [mm], ha, va) of the first corner of the room, lower left first, whose box
    crosses no edge arrow or its label (an arrow pulled back over the room ran over it on the quick-return's page),
    and then the fewest of the mechanism's lines."""
    w, h = text_size(caption, CAPTION_PT, "normal", True)
    lo, hi = frame.lo, frame.hi
    edges = _edge_shapes(frame)
    best = None
    for k, (x, y, ha, va) in enumerate(((lo.real, lo.imag, "left", "bottom"), (hi.real, lo.imag, "right", "bottom"),
                                        (lo.real, hi.imag, "left", "top"), (hi.real, hi.imag, "right", "top"))):
        x0 = x if ha == "left" else x - w
        y0 = y if va == "bottom" else y - h
        shape = box(x0, y0, x0 + w, y0 + h)
        cost = (sum(1 for e in edges if shape.intersects(e)), sum(1 for o in obstacles if shape.intersects(o)), k)
        if best is None or cost < best[0]:
            best = (cost, complex(x, y), ha, va)
        if cost[:2] == (0, 0):
            break
    return best[1], best[2], best[3]


def draw_centres_into(ax, result, k_l: float, lang: str = "en", *, title: str | None = None, legend: bool = True, diagram: bool = True,
                      room_min: float = ROOM_MIN, limit: tuple[float, float] | None = None, cycle=None):
    """The mechanism at k_l with every instant centre, and the circle diagram beside it, drawn into *ax*.

    One data unit is one millimetre of paper.  *title* (plain text), when
    given, goes above; *legend* adds the two lines that say what rings,
    dots, dashed lines and edge arrows mean; *diagram* False leaves the circle
    diagram out (a page puts it elsewhere: :func:`draw_circle_diagram_into`).
    *room_min* [mm] is the least room kept around the mechanism for the
    Kennedy lines and labels (far centres' arrows go outside it): see
    :func:`centres_frame`, which gives the drawing's size without drawing it
    (with *diagram*, *legend* and *title* off, and every centre determined).
    The axes' limits are set to the frame plus the margin.  *cycle*: ``(travel, cycle_poses)``, the guides'
    travel and the cycle's poses of the plate's other drawings (see :func:`_mechanism`).

    Returns
    -------
    (width, height) [mm] of the drawing.
    """
    artists, ink = _mechanism(ax, result, k_l, lang, cycle)
    frame = centres_frame(result, k_l, ink, room_min, limit)
    lo, hi = frame.lo, frame.hi
    (x0, y0), (x1, y1) = (frame.outer_lo.real, frame.outer_lo.imag), (frame.outer_hi.real, frame.outer_hi.imag)
    s = Sketch(ax, "centres")
    s.obstacles.extend(_shapes(artists))
    # the scale, in a corner of the room (inside the frame the page sized) that no edge arrow or its label crosses
    caption = scale_caption("k_l", fmt_number(k_l), "m/mm", lang)
    at, ha, va = _caption_corner(frame, caption, s.obstacles)
    # on white, over the Kennedy lines that run through the room's corner (the quick-return's caption was struck through)
    s.text(at, caption, size=CAPTION_PT, ha=ha, va=va, gid="scale", math=True).set_bbox(_ON_WHITE)
    drawing = _CentresDrawing(s, result, frame, lang)
    drawing.words += _text_shapes(artists) + [s.obstacles[-1]]
    drawing.bodies += _body_shapes(artists)
    drawing.strokes += _stroke_shapes(artists)
    drawing.kennedy_lines()
    drawing.centres()
    if diagram:
        _circle_diagram(s, result, complex(max(s.bounds.xmax, x1) + 14.0 + DIAGRAM_R, (lo.imag + hi.imag) / 2 + 6.0), lang)
    top = s.bounds.ymax + 4.0
    if legend:
        words = f"n(n−1)/2 = {len(result.centres)};  "  # (k_l is stated in the frame, under the mechanism)
        s.text(complex(lo.real, top + 2.0), words + term("centres_legend", lang), size=CAPTION_PT, ha="left", va="bottom", gid="legend", obstacle=False)
        s.text(complex(lo.real, top - 2.0), term("centres_edge_legend", lang), size=CAPTION_PT, ha="left", va="bottom", gid="legend-edge", obstacle=False)
        top += 5.0
    if title is not None:
        s.text(complex(lo.real, top + 2.0), user_text(title), size=TITLE_PT - 3, ha="left", va="bottom", weight="bold", gid="title", obstacle=False)
    missing = [c for c in result.centres if not c.determined]
    for k, c in enumerate(missing):
        s.text(complex(lo.real, y0 - 3.0 - 4.6 * k), undetermined_text(c, lang),
               size=CAPTION_PT, ha="left", va="top", color=CENTRE_COLOUR, gid=f"undetermined-{c.label}", obstacle=False)
    b = s.bounds
    xmin, xmax = min(b.xmin, x0), max(b.xmax, x1)
    ymin, ymax = min(b.ymin, y0), max(b.ymax, y1)
    ax.set_xlim(xmin - MARGIN_MM, xmax + MARGIN_MM)
    ax.set_ylim(ymin - MARGIN_MM, ymax + MARGIN_MM)
    ax.set_aspect("auto")
    ax.set_axis_off()
    return xmax - xmin + 2 * MARGIN_MM, ymax - ymin + 2 * MARGIN_MM


def draw_circle_diagram_into(ax, result, lang: str = "en", caption: bool = True, radius: float = DIAGRAM_R) -> tuple[float, float]:
    """The circle diagram alone, drawn into *ax* (one data unit a millimetre); returns its (width, height) [mm]
    (*caption* False: without its heading and legend, which a page sets as its text; *radius* [mm] of its circle)."""
    s = Sketch(ax, "centres")
    _circle_diagram(s, result, 0j, lang, caption, radius)
    b = s.bounds
    ax.set_xlim(b.xmin - MARGIN_MM, b.xmax + MARGIN_MM)
    ax.set_ylim(b.ymin - MARGIN_MM, b.ymax + MARGIN_MM)
    ax.set_aspect("auto")
    ax.set_axis_off()
    return b.xmax - b.xmin + 2 * MARGIN_MM, b.ymax - b.ymin + 2 * MARGIN_MM


def draw_centres(result, k_l: float | None = None, lang: str = "en"):
    """The figure: the mechanism at k_l with every instant centre, and the circle diagram.

    Parameters
    ----------
    result : plans.centres.InstantCentres
    k_l : float, optional
        m per mm; default the scene's ``[scales] k_l``, else the round value
        (1, 2, 2.5, 5 × 10ⁿ) drawing the mechanism's larger side 60–120 mm long.
    lang : str
        Language of the words (see :mod:`plans.i18n`); decimal comma in sr, ru, bg, sl.

    Returns
    -------
    matplotlib.figure.Figure
        Sized so that one data unit is one millimetre of paper.
    """
    scene = result.scene
    k_l = k_l or scene.scales.k_l or round_scale(result.size)
    fig = new_figure()
    ax = fig.add_axes([0, 0, 1, 1])
    width, height = draw_centres_into(ax, result, k_l, lang, title=f"{term('instant_centres', lang)} — {user_text(scene.title_in(lang))}")
    fig.set_size_inches(width / 25.4, height / 25.4)
    ax.set_position([0.0, 0.0, 1.0, 1.0])
    return fig


def centres_svg(result, k_l: float | None = None, lang: str = "en") -> bytes:
    """``centres.svg`` as bytes (deterministic); see :func:`draw_centres`."""
    return render_svg(draw_centres(result, k_l, lang))
