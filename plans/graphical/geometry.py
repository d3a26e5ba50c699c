"""Ruler-and-compass primitives: the intersections a draftsman makes.

Everything here works on points of one drawing given as complex numbers
(x + iy, in whatever unit the drawing uses: mm on a plan, mm on the
mechanism drawing).  The functions know nothing about mechanisms; they only
intersect circles (compass arcs) and straight lines (ruler lines).

* Two straight lines meet where a ruler finds them: their crossing, in
  closed form (:func:`line_line`), unless it lies further than
  :data:`MAX_EXTENSION` drawing sizes away (then they count as parallel).
* A compass arc is either exact (``arc_segments=None``: the closed-form
  intersection of the circle) or a shapely polygon with ``arc_segments``
  segments per quarter circle, which trades accuracy for speed.

Misses are reported with :class:`Miss` (carrying the gap by which the
figures fail to meet) and parallel lines with :class:`Parallel`; the callers
turn them into :class:`plans.errors.AssemblyError` or
:class:`plans.errors.SingularPositionError` with the mechanism's names.
"""

from __future__ import annotations

import math

import shapely

from ..limits import REFUSE_SINE

__all__ = [
    "Miss",
    "Parallel",
    "MAX_EXTENSION",
    "offset",
    "circle_circle",
    "circle_line",
    "line_line",
]

#: Two lines whose intersection lies further than this many times the
#: drawing's size from their construction points are treated as parallel.
MAX_EXTENSION = 1e9

#: Figures that miss each other by less than this fraction of their size
#: (REFUSE_SINE², ~1e-14: rounding) touch: a stretched or folded dyad is a
#: dead centre, not a failed assembly (the analytic method's rule too).
TOUCH = REFUSE_SINE**2

#: Lines whose |sin| of the angle between them is below this are parallel:
#: the dead-centre threshold :data:`plans.limits.REFUSE_SINE` both methods share.
PARALLEL_SINE = REFUSE_SINE


class Miss(Exception):
    """Two figures do not meet; ``gap`` is by how much (drawing units)."""

    def __init__(self, gap: float, what: str):
        self.gap = gap
        self.what = what
        super().__init__(f"{what} miss by {gap:g}")


class Parallel(Exception):
    """Two lines are parallel, or meet further than :data:`MAX_EXTENSION` sizes away."""

    def __init__(self, sine: float):
        self.sine = sine
        super().__init__(f"lines are parallel (|sin| = {sine:.3g})")


def offset(point: complex, origin: complex, direction: complex) -> float:
    """Signed distance of *point* from the line (origin, unit direction), left positive."""
    return ((point - origin) * direction.conjugate()).imag


def _points(geometry) -> list[complex]:
    coords = shapely.get_coordinates(geometry)
    return [complex(x, y) for x, y in coords]


def _ring(center: complex, radius: float, arc_segments: int):
    return shapely.get_exterior_ring(
        shapely.buffer(shapely.points(center.real, center.imag), radius, quad_segs=int(arc_segments))
    )


def _segment(through: complex, direction: complex, half: float):
    a = through - half * direction
    b = through + half * direction
    return shapely.linestrings([[a.real, a.imag], [b.real, b.imag]])


def circle_circle(
    c1: complex, r1: float, c2: complex, r2: float, arc_segments: int | None = None
) -> tuple[complex, complex]:
    """Intersect the compass arcs (c1, r1) and (c2, r2).

    Returns
    -------
    (left, right) : tuple[complex, complex]
        The intersection to the left of the directed line c1 → c2, then the
        one to its right (equal when the circles touch).

    Raises
    ------
    Miss
        The circles do not meet; ``gap`` = d − (r1 + r2) when they are apart,
        |r1 − r2| − d when one lies inside the other.
    """
    chord = c2 - c1
    d = abs(chord)
    if d > r1 + r2:
        if d - (r1 + r2) > 0.5 * TOUCH * r1 * r2 / (r1 + r2):
            raise Miss(d - (r1 + r2), "arcs")
        chord, d = chord * ((r1 + r2) / d), r1 + r2  # touching from outside, to rounding
    if d < abs(r1 - r2) or d == 0.0:
        if d == 0.0 or abs(r1 - r2) - d > 0.5 * TOUCH * r1 * r2 / abs(r1 - r2):
            raise Miss(abs(r1 - r2) - d, "arcs")
        chord, d = chord * (abs(r1 - r2) / d), abs(r1 - r2)  # touching from inside, to rounding
    e = chord / d
    if arc_segments is None:
        a = (d * d + r1 * r1 - r2 * r2) / (2.0 * d)
        h = math.sqrt(max(r1 * r1 - a * a, 0.0))
        base = c1 + a * e
        return base + 1j * h * e, base - 1j * h * e
    found = _points(shapely.intersection(_ring(c1, r1, arc_segments), _ring(c2, r2, arc_segments)))
    if not found:
        raise Miss(0.0, "arcs (as polygons)")
    sides = [offset(z, c1, e) for z in found]
    return found[sides.index(max(sides))], found[sides.index(min(sides))]


def circle_line(
    center: complex, radius: float, through: complex, direction: complex, arc_segments: int | None = None
) -> tuple[complex, complex]:
    """Intersect the compass arc (center, radius) with the line (through, unit direction).

    Returns
    -------
    (further, nearer) : tuple[complex, complex]
        The intersection further along *direction*, then the other one.

    Raises
    ------
    Miss
        The line passes the circle by ``gap`` = distance − radius.
    """
    distance = offset(center, through, direction)
    along = ((center - through) * direction.conjugate()).real
    foot = through + along * direction
    if abs(distance) > radius and abs(distance) - radius > 0.5 * TOUCH * radius:
        raise Miss(abs(distance) - radius, "arc and line")
    if arc_segments is None:
        h = math.sqrt(max(radius * radius - distance * distance, 0.0))
        return foot + h * direction, foot - h * direction
    found = _points(
        shapely.intersection(_ring(center, radius, arc_segments), _segment(foot, direction, 2.0 * radius))
    )
    if not found:
        raise Miss(0.0, "arc (as polygon) and line")
    ts = [((z - foot) * direction.conjugate()).real for z in found]
    return found[ts.index(max(ts))], found[ts.index(min(ts))]


def line_line(p1: complex, d1: complex, p2: complex, d2: complex, size: float) -> tuple[complex, float]:
    """Intersect two ruler lines (point, unit direction): the point where they cross.

    The crossing ``p1 + t·d1`` with ``t = ((p2 − p1) × d2) / (d1 × d2)``
    (× the plane cross product ``Im(conj(a)·b)``): what a ruler gives by
    drawing both lines, in closed form.  (It was found by intersecting the
    two lines drawn as shapely segments; the same point to round-off, at a
    fifth of the cost of a construction.)  ``size`` is the drawing's extent
    so far: a crossing further than :data:`MAX_EXTENSION` × size away is off
    any drawing and counts as parallel.

    Returns
    -------
    (point, sine) : tuple[complex, float]
        The intersection and |sin| of the angle between the lines.

    Raises
    ------
    Parallel
        |sin| below :data:`PARALLEL_SINE`, or no intersection within
        :data:`MAX_EXTENSION` × size.
    """
    cross = (d1.conjugate() * d2).imag
    sine = abs(cross)
    if not sine >= PARALLEL_SINE:
        raise Parallel(sine)
    size = max(size, abs(p1 - p2))
    if not size > 0.0:  # an empty drawing (everything at rest): any reach will do
        size = 1.0
    t = ((p2 - p1).conjugate() * d2).imag / cross
    if not abs(t) <= 2.0 * MAX_EXTENSION * size:
        raise Parallel(sine)
    return p1 + t * d1, sine