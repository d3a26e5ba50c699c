"""Label placement by geometry.

A label is tried at candidate positions around its anchor: a few rings of
increasing gap, sixteen directions each.  Its text box (measured from the
font, see :func:`plans.drawing._canvas.text_size`) is scored by its
clearance from everything already drawn (vectors, bars, pins, other labels,
as shapely geometries) against its distance from the anchor: up to
``CLEAR_MM`` of clearance is worth four times its length in distance, an
overlap costs as much as ``OVERLAP_MM`` of distance, and the preferred direction breaks
ties.  A label therefore moves off to get clear, with a leader line when it
goes further than a glance would join it to its point.  Asked to (``clear_leaders``, the mechanism's labels), the
leader is scored too: one that would cross a mark (a hatching stroke, a link, a slot's edge, another label) costs
distance, so the label goes where its leader is clear.  The best box becomes
an obstacle for the labels placed after it, so labels never sit on each other
when there is room for them.  The scoring is a pure function of the
geometry, so placement is deterministic.
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import shapely
from shapely.geometry import LineString, Point, box

from ._canvas import Sketch, text_size
from .style import LEADER_STYLE

__all__ = ["CLEAR_MM", "LABEL_SPACE_MM", "RING_TURNS", "label_boxes", "place_label", "place_ring_name"]

#: Clearance [mm] a label should keep from every other mark.
CLEAR_MM = 0.8
#: Extra space [mm] kept around a placed label.
LABEL_SPACE_MM = 0.9
#: An overlap costs as much as this much distance [mm]: a label moves up to
#: about this much further (with a leader line) rather than cover a mark.
OVERLAP_MM = 12.0
#: How far [mm] a label may be moved off its point, with a leader line, when nothing nearer is free.
FARTHEST_MM = 30.0
#: A label across a line moves at most this far [mm] off its point (with a leader) to a clear place.
FREE_GAP_MM = 8.0
_SEPARATOR = ", "


def _to_segment(z: complex, segment: tuple[complex, complex]) -> float:
    """Distance [mm] from *z* to the segment."""
    a, b = segment
    d = b - a
    if abs(d) == 0:
        return abs(z - a)
    t = min(1.0, max(0.0, ((z - a) * d.conjugate()).real / abs(d) ** 2))
    return abs(z - (a + t * d))


def _to_box(z: complex, center: complex, w: float, h: float) -> float:
    """Distance [mm] from *z* to the box *w* × *h* centred at *center* (0 inside)."""
    dx = max(abs(z.real - center.real) - w / 2, 0.0)
    dy = max(abs(z.imag - center.imag) - h / 2, 0.0)
    return math.hypot(dx, dy)


#: A leader line stops this far [mm] short of its label's box...
LEADER_GAP_MM = 0.6
#: ...and meets it on a side, this fraction of the side in from the corners, where a prime or a subscript
#: stands ("e₅′": a leader to the corner ran into the prime and read as its stroke).
LEADER_INSET = 0.3


def _leader_segment(anchor: complex, center: complex, w: float, h: float) -> tuple[complex, complex] | None:
    """The leader line [mm] that joins *anchor* to a label box *w* × *h* centred at *center*: from just off *anchor*
    towards the nearest side of the box (away from its corners), stopping :data:`LEADER_GAP_MM` short of it; None
    where it would be too short to draw."""
    from shapely.geometry import MultiLineString
    from shapely.ops import nearest_points

    x0, x1, y0, y1 = center.real - w / 2, center.real + w / 2, center.imag - h / 2, center.imag + h / 2
    ix, iy = LEADER_INSET * w, LEADER_INSET * h
    sides = MultiLineString([[(x0 + ix, y0), (x1 - ix, y0)], [(x0 + ix, y1), (x1 - ix, y1)], [(x0, y0 + iy), (x0, y1 - iy)], [(x1, y0 + iy), (x1, y1 - iy)]])
    _, near = nearest_points(Point(anchor.real, anchor.imag), sides)
    end = complex(near.x, near.y)
    u = (end - anchor) / abs(end - anchor) if abs(end - anchor) > 0 else 1.0
    # where it meets the box's outline grown by the gap
    grown = box(x0, y0, x1, y1).buffer(LEADER_GAP_MM)
    hit = grown.exterior.intersection(LineString([(anchor.real, anchor.imag), (end.real, end.imag)]))
    if hit.is_empty:
        return None
    pts = [complex(g.x, g.y) for g in getattr(hit, "geoms", [hit]) if g.geom_type == "Point"]
    if not pts:
        return None
    stop = min(pts, key=lambda z: abs(z - anchor))
    if abs(stop - anchor) < 1.2:
        return None
    return anchor + u * 0.5, stop


def _leader(sketch: Sketch, anchor: complex, center: complex, w: float, h: float) -> None:
    """A thin line from just off *anchor* towards the nearest side of the label's box (:func:`_leader_segment`)."""
    segment = _leader_segment(anchor, center, w, h)
    if segment is None:
        return
    color, lw = LEADER_STYLE
    sketch.line(list(segment), color=color, lw=lw, gid="leader", zorder=5.0, obstacle=True, bound=False)


#: Marks within this distance [mm] of a label's point are its own (its pin, the links meeting there): a leader leaves
#: them without crossing anything.
LEADER_OWN_MM = 0.3


def _leader_crossings(sketch: Sketch, anchor: complex, center: complex, w: float, h: float) -> int:
    """How many marks drawn so far (:attr:`Sketch.obstacles`: a hatching stroke, a link, a slot's edge, another label
    or leader) the leader joining *anchor* to a label box *w* × *h* [mm] centred at *center* would cross.

    The point's own marks do not count: what passes within :data:`LEADER_OWN_MM` of *anchor* (its pin, the links
    meeting there) and a closed outline around it (the block it sits in, the slot that block slides in), which any
    leader from the point has to leave; another label always counts.  0 when no leader would be drawn (:func:`_leader_segment`).
    """
    segment = _leader_segment(anchor, center, w, h)
    if segment is None:
        return 0
    a, b = segment
    near = sketch.obstacles.near(min(a.real, b.real), min(a.imag, b.imag), max(a.real, b.real), max(a.imag, b.imag))
    if not near:
        return 0
    shapes = np.array(near, dtype=object)
    shapes = shapes[shapely.intersects(shapes, LineString([(a.real, a.imag), (b.real, b.imag)]))]
    if not len(shapes):
        return 0
    point = Point(anchor.real, anchor.imag)
    own = shapely.dwithin(shapes, point, LEADER_OWN_MM)
    rings = shapely.get_exterior_ring(shapes)  # None for a line (a hatching stroke)
    closed = np.array([r is not None and not r.is_empty for r in rings], dtype=bool)
    if closed.any():
        around = np.zeros(len(shapes), dtype=bool)
        around[closed] = shapely.contains(shapely.polygons(rings[closed]), point)
        own |= around
    # never another label (an upright box), however near the point it stands: round 20's ring name "I" ran its leader
    # through the pole's "π, d′, q′, a′, f′", whose box came within reach of the ring's edge
    return int((~own | label_boxes(shapes)).sum())


def label_boxes(shapes) -> np.ndarray:
    """Which of *shapes* (an array of obstacles) are labels: upright boxes (a label's box, grown with mitred corners,
    is a rectangle of 4 corners filling its own envelope), not lines, pins or marks."""
    return (shapely.get_num_coordinates(shapes) == 5) & np.isclose(shapely.area(shapes), shapely.area(shapely.envelope(shapes)))


#: A leader crossing a mark costs as much as this much distance [mm] (less than a box over a mark, :data:`OVERLAP_MM`:
#: a thin line across a stroke reads, a name on it does not)...
LEADER_CROSSING_MM = 6.0
#: ...and each further mark crossed this much more (a leader across a hatching crosses several strokes), up to five.
LEADER_MORE_MM = 1.5


def _leader_cost(crossings: int) -> float:
    """What a leader crossing *crossings* marks costs, in distance [mm] (:data:`LEADER_CROSSING_MM`, :data:`LEADER_MORE_MM`)."""
    return 0.0 if crossings <= 0 else LEADER_CROSSING_MM + LEADER_MORE_MM * (min(crossings, 5) - 1)


#: the places round a detail's ring its name is tried at, in eighths of a turn: up and right first, up and left, down
#: and right, down and left, then up, down, right, left
RING_TURNS = (1, 3, 7, 5, 2, 6, 0, 4)


def place_ring_name(sketch: Sketch, centre: complex, r: float, pieces: list[tuple[str, str | None]], *, size: float,
                    gaps: tuple[float, ...] = (0.4, 1.2, 2.4, 4.0), leader_from: float = 3.0) -> list:
    """The name of a detail's ring (centre *centre*, radius *r* [mm]: "I") beside the ring, placed as
    :func:`place_label` places a label of a point on the ring: up and right of it first, then round it, the first
    place whose box is clear and whose leader crosses no mark or label; else the one whose leader crosses fewest.
    (Round 20: the linear-arm's pole crowd left no clear place up and right, and "I" went 12 mm off on a leader
    through the pole's "π, d′, q′, a′, f′".)  Returns the label's Text artists."""
    w, h = text_size(_SEPARATOR.join(t for t, _ in pieces), size)
    tried = []
    for k in RING_TURNS:
        u = cmath.exp(1j * math.pi * k / 4)
        anchor = centre + r * u
        state = sketch.checkpoint()
        artists = place_label(sketch, anchor, pieces, size=size, gaps=gaps, prefer=u, leader_from=leader_from, clear_leaders=True)
        x, y = artists[0].get_position()
        sketch.restore(state)
        at = complex(x + w / 2, y)
        label = box(at.real - w / 2, at.imag - h / 2, at.real + w / 2, at.imag + h / 2)
        covered = any(shape.intersects(label) for shape in sketch.obstacles.near(*label.bounds))
        cost = (int(covered), _leader_crossings(sketch, anchor, at, w, h) if _to_box(anchor, at, w, h) >= leader_from else 0)
        if cost == (0, 0):
            return place_label(sketch, anchor, pieces, size=size, gaps=gaps, prefer=u, leader_from=leader_from, clear_leaders=True)
        tried.append((cost, len(tried), anchor, u))
    _, _, anchor, u = min(tried)
    return place_label(sketch, anchor, pieces, size=size, gaps=gaps, prefer=u, leader_from=leader_from, clear_leaders=True)


def place_label(
    sketch: Sketch,
    anchor: complex,
    pieces: list[tuple[str, str | None]],
    *,
    size: float,
    gaps: tuple[float, ...] = (0.6, 1.4, 2.4, 3.6, 5.5, 8.0),
    prefer: complex | None = None,
    first: tuple[complex, ...] = (),
    color: str = "#000000",
    style: str = "normal",
    weight: str = "normal",
    zorder: float = 6.0,
    mathtext: bool = False,
    leader_from: float | None = None,
    rivals: tuple[complex, ...] = (),
    own: tuple[complex, complex] | None = None,
    rival_segments: tuple[tuple[complex, complex], ...] = (),
    by_box: bool = False,
    leader_ok: bool = False,
    clear_leaders: bool = False,
    beyond: bool = False,
) -> list:
    """Place one label (several names written ``"p, o, d"``) near *anchor*.

    Parameters
    ----------
    sketch : Sketch
        Its obstacles are avoided; the label's box is added to them.
    anchor : complex
        The point labelled [mm].
    pieces : list of (text, gid)
        The names, each drawn as its own text element with its own gid,
        separated by commas.
    size : float
        Font size [pt].
    gaps : tuple of float
        Gaps [mm] between the anchor and the nearest side of the box, tried in turn.
    prefer : complex, optional
        A direction to favour when clearances tie (away from the vectors).
    first : tuple of complex
        Extra candidate centres tried before the rings (a plate's centroid).
    mathtext : bool
        The text is matplotlib mathtext (``"$v_A$"``), measured as such.
    leader_from : float, optional
        A label placed at a gap of at least this [mm] is joined to its point
        by a thin leader line (where points crowd, a label may sit further off).
    rivals : tuple of complex
        Other labelled points [mm]: a place whose centre is nearer one of them
        than *anchor* costs as much as an overlap (a label must read as its
        own point's, not its neighbour's).
    own, rival_segments : segments (tail, tip) [mm]
        A vector's label: a place nearer one of *rival_segments* than its own
        vector *own* costs as much as an overlap.
    by_box : bool
        *rivals* are measured to the label's box (its nearest side, as the eye
        joins a name to the nearest point: a long label "p, o, d, e"), not to
        its centre.
    leader_ok : bool
        A place far enough off to get a leader line (*leader_from*) is never
        astray: the leader joins the label to its point (a long label of
        coincident images kept off a neighbour's label).
    clear_leaders : bool
        A leader line is scored as the box is: one that would cross a mark
        drawn so far (a hatching stroke, a link, a slot's edge, another label
        or leader; not the point's own pin, links or block) costs
        :data:`LEADER_CROSSING_MM` of distance and :data:`LEADER_MORE_MM` more
        for each further mark, among the clear places near the point (the
        rings of *gaps*), so the label goes where its leader is clear (the
        mechanism's labels).  Off, leaders are not looked at (the plans'
        labels, placed as they were).
    beyond : bool
        Where every place near the point within the drawing as drawn so far
        lies across a line, the nearest clear place beyond the drawing's edge
        (within :data:`FREE_GAP_MM`, its leader crossing nothing) is taken
        (the plans' labels: a long label of coincident images beside a narrow
        plan, linear-arm position 2's "π, d′, q′, a′, f′").

    Returns
    -------
    list of matplotlib.text.Text
    """
    texts = [t for t, _ in pieces]
    full = _SEPARATOR.join(texts)
    w, h = text_size(full, size, weight, mathtext)
    base_angle = cmath.phase(prefer) if prefer else math.radians(45)

    directions = []  # (unit vector, its turn from the preferred direction, the box's half extents along it)
    for k in range(16):
        theta = base_angle + 2 * math.pi * k / 16
        u = cmath.exp(1j * theta)
        directions.append((u, 1 - math.cos(theta - base_angle), abs(u.real) * w / 2, abs(u.imag) * h / 2))

    def ring_at(gap: float) -> list[tuple[complex, float, float]]:
        return [(anchor + u * (gap + across + up), gap, turn) for u, turn, across, up in directions]

    # Rings in turn: a candidate scores at most 4·CLEAR_MM − gap, so once the
    # best so far beats that bound for the next ring, the rest cannot win
    # (the result is the one an exhaustive search gives, at a fraction of the
    # cost).  When every ring overlaps something, rings further out are tried
    # (up to FARTHEST_MM) and the label gets a leader line.
    rings = ([[(c, 0.0, 0.0) for c in first]] if first else []) + [ring_at(g) for g in gaps]
    extra = gaps[-1] if gaps else 1.0
    nearest_only = extra  # the rings asked for (further rings: every place nearer is covered)
    best = None  # (score, centre, gap, clearance (0 when astray), clearance)
    bounds = sketch.bounds
    free = None  # the nearest place, within the drawing as drawn so far (its scale kept), clear of every mark, its own point's or joined to it by a leader: (cost, centre, gap)
    free_out = None  # the same beyond the drawing's edge, its leader crossing nothing (``beyond``)
    order = 0
    while rings:
        ring = rings.pop(0)
        gap = ring[0][1]
        if best is not None and best[0] > 4.0 * CLEAR_MM - gap and (best[4] > 0.0 or free is not None):
            break  # (a best across a line looks on for a clear place)
        xs = np.array([c.real for c, _, _ in ring])
        ys = np.array([c.imag for c, _, _ in ring])
        boxes = shapely.box(xs - w / 2, ys - h / 2, xs + w / 2, ys + h / 2)
        # only what lies within CLEAR_MM of a candidate can change its score
        near = sketch.obstacles.near(
            xs.min() - w / 2 - CLEAR_MM, ys.min() - h / 2 - CLEAR_MM, xs.max() + w / 2 + CLEAR_MM, ys.max() + h / 2 + CLEAR_MM
        )
        clear = np.full(len(ring), math.inf)
        if near:
            # measure only the pairs whose bounding boxes come within CLEAR_MM
            shapes = np.array(near, dtype=object)
            ob = shapely.bounds(shapes)
            hit = (
                (ob[None, :, 0] <= (xs + w / 2 + CLEAR_MM)[:, None])
                & (ob[None, :, 2] >= (xs - w / 2 - CLEAR_MM)[:, None])
                & (ob[None, :, 1] <= (ys + h / 2 + CLEAR_MM)[:, None])
                & (ob[None, :, 3] >= (ys - h / 2 - CLEAR_MM)[:, None])
            )
            i, j = np.nonzero(hit)
            if len(i):
                # a clearance beyond CLEAR_MM scores as CLEAR_MM: measure only the pairs within it
                # (dwithin stops early; distance is far dearer, most of the time of placing labels)
                within = shapely.dwithin(shapes[j], boxes[i], CLEAR_MM)  # (this order is twice as fast)
                i, j = i[within], j[within]
            if len(i):
                np.minimum.at(clear, i, shapely.distance(boxes[i], shapes[j]))
        for (center, gap, turn), c in zip(ring, clear):
            c = float(c)
            if by_box:
                mine = _to_box(anchor, center, w, h)
                astray = any(_to_box(q, center, w, h) < mine for q in rivals)
            else:
                mine = _to_segment(center, own) if own is not None else abs(center - anchor)
                astray = any(abs(center - q) < mine for q in rivals) or any(_to_segment(center, seg) < mine for seg in rival_segments)
            led = leader_from is not None and gap >= leader_from
            inside = bounds.empty or (bounds.xmin - 1.0 <= center.real - w / 2 and center.real + w / 2 <= bounds.xmax + 1.0
                                      and bounds.ymin - 1.0 <= center.imag - h / 2 and center.imag + h / 2 <= bounds.ymax + 1.0)
            if c >= CLEAR_MM / 2 and gap <= FREE_GAP_MM and (led or not astray) and (free is None or gap + 0.15 * turn < free[0]):
                # (a free place gets a leader: one across a mark costs)
                if inside:
                    cost = gap + 0.15 * turn + (_leader_cost(_leader_crossings(sketch, anchor, center, w, h)) if clear_leaders else 0.0)
                    if free is None or cost < free[0]:
                        free = (cost, center, gap)
                elif beyond and free is None and (free_out is None or gap + 0.15 * turn < free_out[0]) and not _leader_crossings(sketch, anchor, center, w, h):
                    free_out = (gap + 0.15 * turn, center, gap)
            if astray and leader_ok and led:
                astray = False
            score = 4.0 * min(c, CLEAR_MM) - (OVERLAP_MM if c <= 0.0 else 0.0) - (OVERLAP_MM if astray else 0.0) - gap - 0.15 * turn - 1e-6 * order
            order += 1
            if best is not None and score <= best[0]:
                continue  # (a leader's cost only lowers a score: measured only where it could still win)
            # a leader across a mark costs where the label has a choice: a clear box near its point (the rings asked
            # for); further out (every near place covered) any leader is better than a name on a mark
            crossed = (_leader_crossings(sketch, anchor, center, w, h) if clear_leaders and led and c > 0.0 and not astray and gap <= nearest_only
                       else 0)
            score -= _leader_cost(crossed)
            if best is None or score > best[0]:
                best = (score, center, gap, 0.0 if astray else c, c)  # astray: as bad as an overlap, look further out
        if not rings and (best[3] <= 0.0 or (best[4] <= 0.0 and free is None)) and extra * 1.4 <= FARTHEST_MM:
            extra *= 1.4
            rings.append(ring_at(extra))
            if leader_from is None:
                leader_from = extra
    if free is None and beyond:
        free = free_out
    if best[4] <= 0.0 and free is not None:
        # the best place lies across a line (every place near enough to read as its point's is covered): rather the
        # nearest clear place, with a leader line (linear-arm position 5: "π, d′, q′, a′, f₃′" over four lines from the pole)
        best = (free[0], free[1], free[2], CLEAR_MM, CLEAR_MM)
        if leader_from is None:
            leader_from = free[2]
    center = best[1]
    if leader_from is not None and best[2] >= leader_from:
        _leader(sketch, anchor, center, w, h)

    artists = []
    x = center.real - w / 2
    for index, (text, gid) in enumerate(pieces):
        if index:
            artists.append(sketch.text(complex(x, center.imag), _SEPARATOR, size=size, ha="left", color=color, obstacle=False, zorder=zorder))
            x += text_size(_SEPARATOR + text, size, weight)[0] - text_size(text, size, weight)[0]
        artists.append(
            sketch.text(complex(x, center.imag), text, size=size, ha="left", color=color, style=style, weight=weight, gid=gid, obstacle=False, zorder=zorder, math=mathtext)
        )
        x += text_size(text, size, weight, mathtext)[0]
    # a label keeps other labels a little further off than lines, so that two
    # names never read as one ("b" under "a" is not "bᵃ")
    sketch.obstacles.append(box(center.real - w / 2, center.imag - h / 2, center.real + w / 2, center.imag + h / 2).buffer(LABEL_SPACE_MM, join_style=2))
    sketch.bounds.add_box(center.real - w / 2, center.imag - h / 2, center.real + w / 2, center.imag + h / 2)
    return artists
