"""The kinematic scheme of the mechanism at the length scale k_l.

One millimetre of drawing is k_l metres: a length L [m] is drawn L / k_l mm
long.  Symbols (pins, blocks, ground hatching, arrows) have drawing-office
sizes on paper whatever the scale, shrunk to no less than 70 % when the
links are drawn short, so that a block does not swallow a link.

What is drawn: links as bars between their extreme points, a link with three
or more points not on one line as a light plate; pins (points shared by two
bodies) as circles and other reported points as dots; frame pivots with the
ground symbol; frame guides that something slides on as hatched lines, on
the side away from the links (or a guideway hatched both ways when the links
pass to both sides in the cycle); given the mechanism over the cycle (the
solution's ``cycle_poses``), each guide's hatched side and each support's
direction are chosen once for the cycle, so every position stands on the same
frame; lines carried by moving links (slot, rod);
slider blocks and sleeves as rectangles along their lines; the driver's ω
(and ε when not zero) as curved arrows, or a linear driver's v (and a) as
straight ones; labels of the reported points and the frame pivots; link
numbers.  Gids: ``mech-link-3``, ``mech-block-4``, ``mech-pin-A``,
``mech-ground-O``, ``mech-guide-cylinder``, ``mech-line-4-slot``,
``mech-omega``, ``mech-point-A``, ``mech-number-3``, ``mech-scale``.
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import shapely
from shapely.geometry import LineString, MultiPoint, Point
from shapely.geometry import Polygon as ShapelyPolygon

from .._text import SUBSCRIPT, math_name
from ._canvas import Sketch, fmt_number, sketch_on, text_size, unit
from .numerals import scale_caption
from .labels import place_label
from ..i18n import term
from .style import CAPTION_PT, HEADING_PT, INK, LABEL_PT, MM_PER_PT, PLATE_FILL, SMALL_PT

__all__ = ["draw_mechanism", "mechanism_labels", "MechanismDrawing"]

FRAME = "frame"  # plans.scene.FRAME, repeated so drawing needs nothing but the solution

PIN_R = 1.25  # mm
DOT_R = 0.65  # mm, a point that is not a joint
BAR_PT = 2.2
PLATE_EDGE_PT = 1.4
BLOCK = (9.0, 5.4)  # mm, length along the guide × height
GROUND = 5.0  # mm, height of the ground triangle
HATCH_STEP = 2.2  # mm
HATCH_MAX = 2000  # strokes on one guide at most (4.4 m of paper)
HATCH_LEN = 2.4  # mm
OMEGA_R = 8.0  # mm
LEADER_FROM_MM = 4.5  # a label further than this from its point gets a leader line
EPSILON_R = 12.5  # mm
CLEAR_MM = 1.0  # mm a guide's hatching keeps from a path or link it is broken for


def _sub(symbol: str, name: str) -> tuple[str, bool]:
    """``ω₂`` for link 2; mathtext for other names."""
    if name.isdigit():
        return symbol + name.translate(SUBSCRIPT), False
    return rf"${symbol}_{{\mathrm{{{math_name(name)}}}}}$", True


def mechanism_labels(solution) -> list[str]:
    """The point names the mechanism drawing labels: the reported points and the frame pivots."""
    scene = solution.scene
    names = list(scene.report)
    for name in _frame_pivots(scene):
        if name not in names:
            names.append(name)
    return [n for n in names if n in solution.positions]


def _outside(a: complex, c: complex, spans) -> list[tuple[complex, complex]]:
    """The pieces of segment a–c outside the given collinear spans (each a pair of points)."""
    d = c - a
    if abs(d) == 0 or not spans:
        return [(a, c)]
    L = abs(d)
    u = d / L
    cuts = []
    for p0, p1 in spans:
        if max(abs(((p - a) * u.conjugate()).imag) for p in (p0, p1)) > 0.5:
            continue  # not along this segment
        t0, t1 = sorted(((p - a) * u.conjugate()).real for p in (p0, p1))
        cuts.append((max(0.0, t0), min(L, t1)))
    pieces, t = [], 0.0
    for t0, t1 in sorted(cuts):
        if t0 > t:
            pieces.append((a + u * t, a + u * t0))
        t = max(t, t1)
    if t < L:
        pieces.append((a + u * t, c))
    return pieces


def _on_segment(q: complex, a: complex, b: complex, tol: float) -> bool:
    """Whether *q* lies within *tol* [mm] of the segment a–b."""
    u = b - a
    if abs(u) == 0:
        return abs(q - a) <= tol
    t = min(1.0, max(0.0, ((q - a) * u.conjugate()).real / abs(u) ** 2))
    return abs(q - (a + u * t)) <= tol


def _frame_pivots(scene) -> list[str]:
    frame = scene.bodies[FRAME]
    return [p for p in frame.points if any(p in b.points for n, b in scene.bodies.items() if n != FRAME)]


def draw_mechanism(solution, ax=None, *, lang: str = "en", slots: dict | None = None, cycle=None) -> list:
    """Draw the kinematic scheme of *solution* (a GraphicalSolution) at k_l.

    Parameters
    ----------
    solution : plans.graphical.GraphicalSolution
    ax : matplotlib.axes.Axes, optional
        Drawn into, with one data unit taken as one millimetre of paper.  When
        omitted, a new figure sized to the drawing (true to scale) is made;
        reach it as ``artists[0].figure``.
    lang : str
        Language of the heading (see :mod:`plans.i18n`).
    slots : dict, optional
        ``"4.slot"`` -> (s_min, s_max) [m]: the stretch of a moving line that a
        block travels over in the cycle (along the line from its origin), as
        found by a sweep (:func:`plans.sweep.line_travel`); the slot, a frame
        guide or a rod is drawn over it.  The drawing solves nothing: when
        omitted, the solution's own ``travel`` is used (a caller attaches it);
        without either, a slot is drawn around the block's present place.
    cycle : tuple, optional
        The mechanism over the cycle, ``(positions, poses)`` pairs as the
        solution's own (:func:`plans.positions.cycle_poses`): the hatched side
        of each frame guide (or a guideway hatched both ways, when the links
        meeting its sliders pass to both sides) and the direction of each
        ground support are chosen once, clear of the links at every one of
        these positions, so that every position is drawn on the same frame.
        When omitted, the solution's own ``cycle_poses`` is used; without
        either (or where no one choice keeps clear), each drawing chooses for
        its own position.

    Returns
    -------
    list of matplotlib.artist.Artist
    """
    return sketch_on(ax, "mech", lambda sketch: MechanismDrawing(sketch, solution, lang=lang, slots=slots, cycle=cycle).draw())


#: choices made over a cycle (:meth:`MechanismDrawing._cycle_support_direction`), kept for the next drawing of the same cycle
_CYCLE_CHOICES: dict = {}

class _Pose:
    """The mechanism at one position of a cycle: the points' positions [m] and the bodies' poses."""

    def __init__(self, positions: dict, poses: dict):
        self.positions = positions
        self.poses = poses


def _box_within(bounds, centre: complex, reach: float) -> bool:
    """Whether the box ``(x0, y0, x1, y1)`` comes within *reach* [mm] of *centre* (an empty shape's never)."""
    x0, y0, x1, y1 = bounds
    if not (x0 <= x1 and y0 <= y1):
        return False
    dx = max(x0 - centre.real, 0.0, centre.real - x1)
    dy = max(y0 - centre.imag, 0.0, centre.imag - y1)
    return math.hypot(dx, dy) <= reach


class MechanismDrawing:
    """The kinematic scheme of a solution drawn into a :class:`Sketch`: ``MechanismDrawing(sketch, solution).draw()``.

    *caption* False leaves out the heading and the scale statement (a page that states them itself).
    *clear* (shapely geometries [mm]: the paths of the points and the links at the other positions of a plan of
    positions) is what a frame guide keeps off: a guide line and its hatching are broken where one of them passes
    through the band the hatching takes.  :attr:`guide_bands` holds the bands drawn (each line with its hatching)
    and :attr:`guideways` the room between the two lines of a guideway (numbers keep out of both).
    *names* (point -> label) letters a point otherwise than by its name, or (None) not at all: the plan of positions
    letters the points it numbers itself (A₀ as A₁, A₂, …).
    """

    def __init__(self, sketch: Sketch, solution, lang: str = "en", caption: bool = True, slots: dict | None = None, cycle=None,
                 clear=(), names: dict | None = None):
        self.names = dict(names or {})  # point -> the label it is lettered with, None: not lettered here
        self.clear = [g for g in clear if g is not None and not g.is_empty]
        self.guide_bands: list = []
        self.guideways: list = []
        self.slots = dict(slots if slots is not None else getattr(solution, "travel", None) or {})
        self.cycle = tuple(cycle if cycle is not None else getattr(solution, "cycle_poses", None) or ())
        self._plates: dict[str, bool] = {}  # body -> drawn as a plate (:meth:`_is_plate`)
        # a solution that says so keeps every support in the cycle's direction even where a crank lies over it (the
        # centres pages: a support drawn the same way on every page of the plate)
        self.fixed_supports = bool(getattr(solution, "fixed_supports", False))
        self.lang = lang
        self.show_caption = caption
        self.s = sketch
        self.sol = solution
        self.scene = solution.scene
        self.k_l = float(solution.scales["k_l"])
        if not (self.k_l > 0 and math.isfinite(self.k_l)):
            raise ValueError(f"k_l must be a positive number, got {self.k_l!r}")
        self.moving = [n for n in self.scene.bodies if n != FRAME]
        allpts = [self.p(n) for n in solution.positions]
        self.centroid = sum(allpts) / len(allpts) if allpts else 0j
        # symbols keep their drawing-office size, but shrink (to 70 % at most)
        # on a mechanism drawn small, so that blocks do not swallow short links
        lengths = sorted(
            max(abs(q - r) for q in pts for r in pts)
            for pts in (self.body_points(b) for b in self.moving)
            if len(pts) >= 2
        )
        typical = lengths[len(lengths) // 2] if lengths else 30.0
        k = min(1.0, max(0.7, typical / 30.0))
        self.symbol_scale = k
        self.block = (BLOCK[0] * k, BLOCK[1] * k)
        self.pin_r = PIN_R * max(k, 0.85)
        self.ground = GROUND * k
        self.omega_r = OMEGA_R * k
        self.epsilon_r = EPSILON_R * k
        #: where the frame's number is written: (the hatching's end [mm], the spots beside it, a name for its gid)
        self.frame_marks: list[tuple[complex, tuple[complex, ...], str]] = []

    # -- coordinates [mm on paper] -----------------------------------------

    def p(self, name: str) -> complex:
        return complex(self.sol.positions[name]) / self.k_l

    def g(self, body: str, z: complex) -> complex:
        if body == FRAME:
            return complex(z) / self.k_l
        phi, origin = self.sol.poses[body]
        return (complex(origin) + cmath.exp(1j * phi) * complex(z)) / self.k_l

    def angle(self, body: str) -> float:
        return 0.0 if body == FRAME else float(self.sol.poses[body][0])

    def body_points(self, body: str) -> list[complex]:
        pts = []
        for name, z in self.scene.bodies[body].points.items():
            pts.append(self.p(name) if name in self.sol.positions else self.g(body, z))
        return pts

    # -- what sits where ---------------------------------------------------

    def is_block(self, body: str) -> bool:
        b = self.scene.bodies[body]
        return b.block or len(b.points) == 1

    def block_angle(self, body: str) -> float:
        b = self.scene.bodies[body]
        driver = self.scene.driver
        if getattr(driver, "link", None) == body and hasattr(driver, "guide"):
            return self.scene.bodies[FRAME].lines[driver.guide].angle
        for pr in self.scene.prismatics:
            if pr.slider == body:
                return self.angle(body) + b.lines[pr.slider_line].angle
            if pr.guide == body:
                return self.angle(body) + b.lines[pr.guide_line].angle
        return self.angle(body)

    def riders(self, body: str, line: str) -> list[complex]:
        """Points [mm] of whatever slides on line *line* of *body*."""
        out = []
        for pr in self.scene.prismatics:
            if pr.guide == body and pr.guide_line == line:
                out.extend(self.body_points(pr.slider))
            if pr.slider == body and pr.slider_line == line:
                out.extend(self.body_points(pr.guide) if pr.guide != FRAME else [])
        driver = self.scene.driver
        if body == FRAME and getattr(driver, "guide", None) == line:
            out.extend(self.body_points(driver.link))
        return out

    # -- drawing -----------------------------------------------------------

    def draw(self) -> None:
        self.frame_guides()
        start = len(self.s.obstacles)
        self.moving_lines()
        self.links()
        self.link_marks = list(self.s.obstacles[start:])  # the links as drawn (slots, bars, plates, then blocks): what
        self.ground_pivots()                               # the driver's arcs never cross
        start = len(self.s.obstacles)
        self.blocks()
        self.link_marks += list(self.s.obstacles[start:])
        self.pins()
        self.driver_arrows()
        self.point_labels()
        self.link_labels()
        self.frame_numbers()
        self.caption()

    def _stack_side(self, body: str) -> float:
        """+1 or −1 along its own guide for a frame-guided block that shares its pin with a
        block on a moving line (a follower on a wedge): the side away from the moving
        line's body, where the follower and its guide are drawn; 0 for any other block."""
        if not self.is_block(body) or self._guide_of(body) != FRAME:
            return 0.0
        pin_name = next(iter(self.scene.bodies[body].points))
        for pr in self.scene.prismatics:
            if pr.slider != body and pr.guide != FRAME and pin_name in self.scene.bodies[pr.slider].points and self.is_block(pr.slider):
                pin = self.p(pin_name)
                u = cmath.exp(1j * self.block_angle(body))
                reach = sum(((q - pin) * u.conjugate()).real for q in self.body_points(pr.guide))
                return -1.0 if reach > 0 else 1.0
        return 0.0

    def frame_guides(self) -> None:
        self.guides: list[tuple[complex, complex]] = []
        frame = self.scene.bodies[FRAME]
        for name, line in frame.lines.items():
            riders = self.riders(FRAME, name)
            if not riders:
                continue
            bars = [pr.slider for pr in self.scene.prismatics if pr.guide == FRAME and pr.guide_line == name and not self.is_block(pr.slider)]
            if bars and len(bars) == len([pr for pr in self.scene.prismatics if pr.guide == FRAME and pr.guide_line == name]) and getattr(self.scene.driver, "guide", None) != name:
                for body in bars:
                    self._bearing(body, name, line)
                continue
            origin = self.g(FRAME, line.origin)
            u = cmath.exp(1j * line.angle)
            ts = [((r - origin) * u.conjugate()).real for r in riders]
            driver = self.scene.driver
            if getattr(driver, "guide", None) == name and getattr(driver, "stroke", None):
                self._check_stroke(driver)
                base = ((self.p(driver.point) - origin) * u.conjugate()).real - driver.s / self.k_l
                ts += [base + driver.stroke[0] / self.k_l, base + driver.stroke[1] / self.k_l]
            reach = self.block[0] + 8.0
            lo, hi = min(ts) - reach, max(ts) + reach
            # a follower on a moving incline: its guide is a stub on the follower's side only
            for pr in self.scene.prismatics:
                if pr.guide == FRAME and pr.guide_line == name:
                    side = self._stack_side(pr.slider)
                    # (the follower sits on the block under it: its guide reaches past it)
                    stack = self.block[0] + self.block[1]
                    if side > 0:
                        lo, hi = max(lo, min(ts)), hi + stack
                    elif side < 0:
                        lo, hi = lo - stack, min(hi, max(ts))
            # the stroke over the cycle (a ram's guideway); a follower's stub stays by the follower
            stacked = any(self._stack_side(pr.slider) for pr in self.scene.prismatics if pr.guide == FRAME and pr.guide_line == name)
            travel = self._travel(f"{FRAME}.{name}", origin, u)
            if travel and not stacked:
                end = self.block[0] / 2 + 3.0  # the block at either end of its stroke, and a little more
                lo, hi = min(lo, min(travel) - end), max(hi, max(travel) + end)
            # a rod lying along the guide (a ram's connecting link): the guide is a guideway,
            # two lines either side of the ram, hatched outward, over the rod's length and
            # past the block (the stroke it travels), so the rod runs between them, on no hatching
            # the frame chosen once over the cycle: one side hatched, or a guideway hatched both ways
            # when the links meeting its sliders pass to both sides of the line (the quick-return's DE)
            choice = self._cycle_guide_side(name, origin, u * 1j)
            channel = choice == "channel"
            for body in self.moving:
                if self.is_block(body) or choice is not None:
                    continue
                along = [((q - origin) * u.conjugate()) for q in self.body_points(body)]
                if len(along) < 2 or any(abs(z.imag) > 1.0 for z in along):
                    continue
                r0, r1 = min(z.real for z in along), max(z.real for z in along)
                if not [t for t in ts if not (r0 < t < r1)]:
                    continue
                channel = True
                lo, hi = min(lo, r0 - reach), max(hi, r1 + reach)
            n = u * 1j
            if channel:
                gap = self.block[1] / 2 + 0.35
                # (a link crossing a guideway line, the lever up to D, passes through a gap in it)
                crossing = []
                for body in self.moving:
                    pts = self.body_points(body)
                    if self.is_block(body) or len(pts) < 2:
                        continue
                    crossing.append(max(((q, r) for q in pts for r in pts), key=lambda qr: abs(qr[0] - qr[1])))
                for side in (1.0, -1.0):
                    a = origin + u * lo + n * side * gap
                    b = origin + u * hi + n * side * gap
                    spans = []
                    # the band the hatching takes on this side (its strokes lean back along the line)
                    out = n * side * (HATCH_LEN + 0.4)
                    ext = u * (HATCH_LEN + 0.5)
                    band = ShapelyPolygon([(z.real, z.imag) for z in (a - ext, b + ext, b + ext + out, a - ext + out)])
                    for q, r in crossing:
                        rod = LineString([(q.real, q.imag), (r.real, r.imag)])
                        hit = LineString([(a.real, a.imag), (b.real, b.imag)]).intersection(rod)
                        if hit.geom_type == "Point":
                            t = ((complex(hit.x, hit.y) - a) * u.conjugate()).real
                            # the gap reaches over where the link runs through the hatching beyond the line
                            across = rod.buffer(BAR_PT * MM_PER_PT / 2 + 0.3).intersection(band)
                            ts = [((complex(x, y) - a) * u.conjugate()).real for x, y in (across.exterior.coords if across.geom_type == "Polygon" else [])]
                            spans.append((a + u * (min([t] + ts) - 2.0), a + u * (max([t] + ts) + 2.0)))
                    spans += self._clear_spans(a, b, n * side)
                    for p0, p1 in _outside(a, b, spans):
                        if abs(p1 - p0) < 1.0:
                            continue
                        self.s.line([p0, p1], lw=1.1, gid=f"guide-{name}", zorder=1.2)
                        self._hatch(p0, p1, n * side) if side > 0 else self._hatch(p1, p0, n * side)
                        self.guide_bands.append(self._band(p0, p1, n * side))
                a, b = origin + u * lo, origin + u * hi
                self.guideways.append(ShapelyPolygon([(z.real, z.imag) for z in (a + n * gap, b + n * gap, b - n * gap, a - n * gap)]))
                self._frame_mark(origin + u * hi + n * (gap + HATCH_LEN / 2), u, n, name)
                self.guides.append((origin + u * lo, origin + u * hi))
                continue
            a = origin + u * lo
            b = origin + u * hi
            side = choice if choice is not None else (-1.0 if self._mechanism_side(FRAME, name, origin, n) > 0 else 1.0)
            for p0, p1 in _outside(a, b, self._clear_spans(a, b, n * side)):
                if abs(p1 - p0) < 1.0:
                    continue
                self.s.line([p0, p1], lw=1.1, gid=f"guide-{name}", zorder=1.2)
                self._hatch(p0, p1, n * side)
                self.guide_bands.append(self._band(p0, p1, n * side))
            self._frame_mark(b + n * side * HATCH_LEN / 2, u, n * side, name)
            self.guides.append((a, b))

    def _band(self, a: complex, b: complex, outward: complex):
        """The band [mm] a guide line a–b and its hatching (on the side *outward*, strokes leaning back) take."""
        u = unit(b - a)
        out = outward * (HATCH_LEN + 0.2)
        back = u * (HATCH_LEN * 0.8 + 0.2) * (1 if ((b - a) * (outward * 1j).conjugate()).real >= 0 else -1)
        pts = [a - back, b + back, b + back + out, a - back + out]
        return ShapelyPolygon([(z.real, z.imag) for z in pts]).convex_hull.buffer(0.3)

    def _clear_spans(self, a: complex, b: complex, outward: complex) -> list[tuple[complex, complex]]:
        """The stretches of guide line a–b to leave out so that neither it nor its hatching crosses what it keeps
        clear of (:attr:`clear`): each passage of a path or link through the band, and :data:`CLEAR_MM` more."""
        if not self.clear or abs(b - a) == 0:
            return []
        u = unit(b - a)
        out = outward * (HATCH_LEN + 0.2)
        ext = u * (HATCH_LEN + 0.5)
        off = unit(outward) * 0.3  # (a link or path that only meets the line, a slider's own, breaks nothing)
        band = ShapelyPolygon([(z.real, z.imag) for z in (a - ext + off, b + ext + off, b + ext + out, a - ext + out)]).convex_hull
        spans = []
        for geom in self.clear:
            if not geom.intersects(band):
                continue
            for part in shapely.get_parts(geom.intersection(band)):
                coords = shapely.get_coordinates(part)
                if not len(coords):
                    continue
                ts = [((complex(x, y) - a) * u.conjugate()).real for x, y in coords]
                spans.append((a + u * (min(ts) - CLEAR_MM - HATCH_LEN), a + u * (max(ts) + CLEAR_MM + HATCH_LEN)))
        return spans

    def _bearing(self, body: str, name: str, line) -> None:
        """A bar sliding along a frame line (a yoke on its rail): the prismatic pair with the frame
        as its standard symbol, a fixed slide bearing around the bar, hatched on both outer sides."""
        origin = self.g(FRAME, line.origin)
        u = cmath.exp(1j * line.angle)
        n = u * 1j
        ts = [((q - origin) * u.conjugate()).real for q in self.body_points(body)]
        t0, t1 = min(ts), max(ts)
        half = self.block[0] * 0.7
        centre = t0 + 0.72 * (t1 - t0)
        centre = min(max(centre, t0 + half), t1 - half) if t1 - t0 > 2 * half else (t0 + t1) / 2
        gap = BAR_PT * MM_PER_PT / 2 + 0.7
        for side in (1.0, -1.0):
            a = origin + u * (centre - half) + n * side * gap
            b = origin + u * (centre + half) + n * side * gap
            self.s.line([a, b], lw=1.1, gid=f"guide-{name}", zorder=2.2)
            self._hatch(a, b, n * side) if side > 0 else self._hatch(b, a, n * side)
        self._frame_mark(origin + u * (centre + half) + n * (gap + HATCH_LEN / 2), u, n, name)
        self.guides.append((origin + u * (centre - half), origin + u * (centre + half)))

    def _over_cycle(self, measure) -> list:
        """``measure()`` taken with the mechanism at every position of the cycle given (the drawing's own
        position is restored after)."""
        own = self.sol
        out = []
        try:
            for positions, poses in self.cycle:
                self.sol = _Pose(positions, poses)
                out.append(measure())
        finally:
            self.sol = own
        return out

    def _cycle_guide_side(self, name: str, origin: complex, n: complex):
        """The hatched side of frame line *name* for the whole cycle: +1 or −1 along *n* when the links
        meeting its sliders stay on the other side at every position of the cycle, ``"channel"`` (a
        guideway hatched both ways) when they pass to both sides; None without a cycle, or when they
        lie along the line throughout (the drawing's own position decides)."""
        if not self.cycle:
            return None
        riders = [pr.slider for pr in self.scene.prismatics if pr.guide == FRAME and pr.guide_line == name]
        driver = self.scene.driver
        if getattr(driver, "guide", None) == name:
            riders.append(driver.link)
        if any(not self.is_block(r) for r in riders) and getattr(driver, "guide", None) != name:
            return None  # a bar in a slide bearing, hatched both ways already

        def offsets():
            out = []
            for rider in riders:
                for point in self.scene.bodies[rider].points:
                    for other in self.scene.bodies_with(point):
                        if other not in (rider, FRAME):
                            out += [((q - origin) * n.conjugate()).real for q in self.body_points(other)]
            return out

        found = [t for ts in self._over_cycle(offsets) for t in ts]
        tol = 1.0  # mm: a point this near the line is on it
        above, below = any(t > tol for t in found), any(t < -tol for t in found)
        if above and below:
            return "channel"
        if above:
            return -1.0
        if below:
            return 1.0
        return None

    def _mechanism_side(self, body: str, line: str, origin: complex, n: complex) -> float:
        """Which side of a frame line the links attached to its sliders lie on (+ along *n*)."""
        riders = [pr.slider for pr in self.scene.prismatics if pr.guide == body and pr.guide_line == line]
        driver = self.scene.driver
        if getattr(driver, "guide", None) == line:
            riders.append(driver.link)
        total = 0.0
        for rider in riders:
            for point in self.scene.bodies[rider].points:
                for other in self.scene.bodies_with(point):
                    if other in (rider, FRAME):
                        continue
                    for q in self.body_points(other):
                        total += ((q - origin) * n.conjugate()).real
        if abs(total) < 1e-9:
            total = ((self.centroid - origin) * n.conjugate()).real
        return total

    def _hatch(self, a: complex, b: complex, outward: complex) -> None:
        u = unit(b - a)
        length = abs(b - a)
        count = min(HATCH_MAX, max(2, int(length / HATCH_STEP)))
        step = length / count
        pairs = []
        for k in range(count + 1):
            q = a + u * (k * step)
            pairs.append((q, q + outward * HATCH_LEN - u * HATCH_LEN * 0.8))
        self.s.segments(pairs, lw=0.5, gid="hatch", zorder=1.1)

    def moving_lines(self) -> None:
        self.slotted: set[str] = set()
        self.slot_spans: dict[str, list[tuple[complex, complex]]] = {}
        for body in self.moving:
            b = self.scene.bodies[body]
            if b.block:
                continue
            for name, line in b.lines.items():
                origin = self.g(body, line.origin)
                u = cmath.exp(1j * (self.angle(body) + line.angle))
                own = [((q - origin) * u.conjugate()).real for q in self.body_points(body)]
                reach = self.block[0] / 2 + 3.0
                rides = [((q - origin) * u.conjugate()).real for q in self.riders(body, name)]
                rides += self._travel(f"{body}.{name}", origin, u)  # the travel over the cycle
                ts = own + [t - reach for t in rides] + [t + reach for t in rides] + [0.0]
                a = origin + u * min(ts)
                c = origin + u * max(ts)
                # a block on a moving pin slides in a slot of this link when the scene names
                # the line a slot (quick-return "4.slot", the scotch yoke's "4.slot"); on a
                # rod ("3.rod") it is a block threaded on the rod; a block pivoted on the
                # frame is a swinging sleeve the link slides through (no slot)
                pivots = set(_frame_pivots(self.scene))
                blocks = [
                    pr.slider
                    for pr in self.scene.prismatics
                    if pr.guide == body and pr.guide_line == name and self.is_block(pr.slider)
                    and not (set(self.scene.bodies[pr.slider].points) & pivots)
                ]
                if blocks and not self._is_plate(body) and "slot" in name.lower():
                    pins = [((q - origin) * u.conjugate()).real for b in blocks for q in self.body_points(b)]
                    lo, hi = self._slot(body, name, origin, u, pins)
                    self.slotted.update(f"slot-{body}-{name}/{b}" for b in blocks)
                    self.slot_spans.setdefault(body, []).append((origin + u * lo, origin + u * hi))
                spans = [span for spans in self.slot_spans.values() for span in spans]
                for p0, p1 in _outside(a, c, spans):
                    self.s.line([p0, p1], lw=0.8, gid=f"line-{body}-{name}", zorder=1.6)

    def _check_stroke(self, driver) -> None:
        """Refuse a linear driver's stroke whose guide, drawn over it at this k_l, is longer than the largest
        sheet holds (the drawing's cost would grow with it): a :class:`plans.errors.SceneError` naming
        ``driver.stroke``, the length drawn and the longest stroke that fits."""
        from ..errors import SceneError
        from ..graphical.scales import DRAWN_LARGEST

        a, b = driver.stroke
        drawn = abs(b - a) / self.k_l
        if drawn <= DRAWN_LARGEST:
            return
        length = f"{drawn:.3g} mm" if math.isfinite(drawn) else "longer than any number"
        raise SceneError(
            f"the stroke from {a:g} m to {b:g} m would draw the driver's guide {length} long at k_l = {self.k_l:g} m/mm, "
            f"longer than the largest sheet (A0) holds ({DRAWN_LARGEST:g} mm): give a stroke of at most "
            f"{DRAWN_LARGEST * self.k_l:.3g} m at this scale, or a larger k_l (--k-l)",
            getattr(self.scene, "source", None),
            "driver.stroke",
        )

    def _travel(self, key: str, origin: complex, u: complex) -> list[float]:
        """The travel given for line *key* [mm along *u* from *origin*], cut to the mechanism's own reach: no
        further than its size beyond its points (a pin that runs off towards infinity near parallel guides
        is not followed)."""
        travel = self.slots.get(key)
        if not travel:
            return []
        pts = [self.p(n) for n in self.sol.positions]
        along = [((q - origin) * u.conjugate()).real for q in pts] or [0.0]
        size = abs(complex(max(q.real for q in pts) - min(q.real for q in pts), max(q.imag for q in pts) - min(q.imag for q in pts))) if pts else 0.0
        lo, hi = min(along) - size, max(along) + size
        return [min(max(float(t) / self.k_l, lo), hi) for t in travel if math.isfinite(t)]

    def _is_plate(self, body: str) -> bool:
        """A link with three or more points not on one line, drawn as a plate (a rigid body's shape: the same
        at every position, so found once)."""
        plates = self._plates
        if body not in plates:
            pts = self.body_points(body)
            if len(pts) < 3:
                plates[body] = False
            else:
                hull = MultiPoint([(q.real, q.imag) for q in pts]).convex_hull
                span = max(abs(q - r) for q in pts for r in pts)
                plates[body] = hull.geom_type == "Polygon" and hull.area > 0.02 * span * span
        return plates[body]

    def _in_slot(self, block: str) -> bool:
        return any(g.startswith("slot-") and g.endswith(f"/{block}") for g in self.slotted)

    def _slot(self, body: str, name: str, origin: complex, u: complex, rides: list[float]) -> None:
        """A slot a block slides in, drawn as the slot (two edges and ends) over the travel it uses.

        The travel is data (``slots`` of :func:`draw_mechanism`, metres along the
        line from its origin, e.g. from a sweep); without it, the slot covers the
        block's present place and a block length either side.
        """
        travel = self._travel(f"{body}.{name}", origin, u)
        L = self.block[0] / 2
        if travel:
            lo, hi = (min(travel) - L - 1.0, max(travel) + L + 1.0)
            lo, hi = min(lo, min(rides) - L - 1.0), max(hi, max(rides) + L + 1.0)
        else:
            lo, hi = min(rides) - 2.2 * L, max(rides) + 2.2 * L
        w = self.block[1] / 2 + 0.5
        n = u * 1j
        ring = [origin + u * lo + n * w, origin + u * hi + n * w, origin + u * hi - n * w, origin + u * lo - n * w]
        self.s.polygon(ring, fc="white", lw=1.2, gid=f"slot-{body}-{name}", zorder=2.1, joinstyle="round", obstacle=False)
        self.s.obstacles.append(ShapelyPolygon([(z.real, z.imag) for z in ring]).exterior.buffer(0.3))
        return lo, hi

    def links(self) -> None:
        start = len(self.s.obstacles)
        self._links()
        # the links' own shapes: a support keeps clear of links passing by (guides are judged apart)
        self.link_shapes = list(self.s.obstacles[start:])

    def _links(self) -> None:
        self.plates: dict[str, complex] = {}
        self.bars: dict[str, tuple[complex, complex]] = {}
        for body in self.moving:
            if self.is_block(body):
                continue
            pts = self.body_points(body)
            hull = MultiPoint([(q.real, q.imag) for q in pts]).convex_hull
            if self._is_plate(body):
                ring = [complex(x, y) for x, y in list(hull.exterior.coords)[:-1]]
                self.s.polygon(ring, fc=PLATE_FILL, lw=PLATE_EDGE_PT, gid=f"link-{body}", zorder=1.8, obstacle=False, joinstyle="round")
                self.s.obstacles.append(hull.exterior.buffer(PLATE_EDGE_PT * 0.2))
                c = hull.centroid
                self.plates[body] = complex(c.x, c.y)
            else:
                a, c = max(((q, r) for q in pts for r in pts), key=lambda qr: abs(qr[0] - qr[1]))
                # where the link is slotted, the slot is drawn instead of the bar
                for p0, p1 in _outside(a, c, self.slot_spans.get(body, [])):
                    self.s.line([p0, p1], lw=BAR_PT, gid=f"link-{body}", zorder=2.0, capstyle="round")
                self.bars[body] = (a, c)

    def ground_pivots(self) -> None:
        """Frame pivots: a triangle on hatched ground, turned away from the links that meet it.

        A pivot lying on a hatched frame guide is that ground already (no second
        hatching); a pivot under a swinging block gets a support tall enough to
        show beyond the block.
        """
        for name in _frame_pivots(self.scene):
            q = self.p(name)
            if any(_on_segment(q, a, b, 0.6) for a, b in getattr(self, "guides", [])):
                continue
            height = self.ground
            under_block = any(self.is_block(b) for b in self.scene.bodies_with(name) if b != FRAME)
            if under_block:
                height = max(height, math.hypot(*self.block) / 2 + 2.5)
            d = self._cycle_support_direction(name, q, height)  # one direction for the whole cycle
            if d is not None and not self.fixed_supports and self._link_over_support(name, q, d, height):
                d = None  # a crank over its support at this position turns it away here (issue 10 §4), only here
            if d is None:
                d = self._support_direction(name, q, height)
            n = d * 1j
            half = 3.2 * self.symbol_scale
            # a support that would stand in a hatched guide's hatching stands on the guide instead
            on_guide = None
            for g0, g1 in getattr(self, "guides", []):
                u = g1 - g0
                cross = (d.conjugate() * u).imag
                if abs(cross) < 1e-9:
                    continue
                t = ((g0 - q).conjugate() * u).imag / (d.conjugate() * u).imag
                hit = q + d * t
                if 0 < t <= height + HATCH_LEN + 1.0 and _on_segment(hit, g0, g1, 1e-6):
                    on_guide = t if on_guide is None else min(on_guide, t)
            if on_guide is not None:
                height = on_guide
            base = q + d * height
            left, right = base + n * half, base - n * half
            self.s.polygon([q, left, right], fc="white", lw=0.8, gid=f"ground-{name}", zorder=2.5)
            # a link from the pivot runs over its support (a crank turning over a support that stays put)
            reach = height + HATCH_LEN + 1.0
            for body in self.scene.bodies_with(name):
                end = getattr(self, "bars", {}).get(body)
                if body == FRAME or end is None or body in getattr(self, "slot_spans", {}):
                    continue
                far = end[1] if abs(end[0] - q) < abs(end[1] - q) else end[0]
                if abs(far - q) > 1e-9:
                    self.s.line([q, q + unit(far - q) * min(reach, abs(far - q))], lw=BAR_PT, gid=f"link-{body}-at-{name}", zorder=2.55, capstyle="round", obstacle=False)
            if under_block:
                # the support's sides reach the pin over the swinging block (the sleeve turns
                # about E): drawn under it, the triangle would seem to lean on the block's edge
                self.s.line([left, q, right], lw=0.8, gid=f"ground-{name}-sides", zorder=3.2, obstacle=False)
            if on_guide is not None:
                continue  # the guide's own hatching is its ground: not drawn twice
            a, b = base + n * (half + 2.0), base - n * (half + 2.0)
            self.s.line([a, b], lw=1.0, gid="ground-base", zorder=2.5)
            self._hatch(b, a, d)
            # the frame's number by the hatching, at either end of the base (the textbook's small "1")
            spots = tuple(base + e * (half + 2.0 + 2.2) + d * (HATCH_LEN * 0.5 + f) for f in (0.0, 1.5) for e in (n, -n))
            self.frame_marks.append((base + d * HATCH_LEN * 0.5, spots, name))

    def _frame_mark(self, end: complex, u: complex, out: complex, name: str) -> None:
        """Where the frame's number goes by a guide's hatching that ends at *end* [mm] (*u*: along the guide, *out*:
        towards its hatched side): beyond the end, or just off it on the hatched side."""
        # (over the hatching first, inside the guide's length: beyond its end the number would widen the drawing)
        spots = (end - u * 2.5 + out * (HATCH_LEN / 2 + 2.7), end - u * 5.0 + out * (HATCH_LEN / 2 + 2.7), end + u * 3.0,
                 end + u * 3.0 + out * 2.0)
        self.frame_marks.append((end, spots, f"guide-{name}"))

    def frame_numbers(self) -> None:
        """The frame's number (the scene's: 1 when the crank is 2, 0 when it is 1) written small by the hatching of
        every support and frame guide, as the textbook numbers the frame on a scheme (the equations name it: v_EE1)."""
        number = self.scene.frame_number
        for end, spots, name in self.frame_marks:
            self._label(end, number, gid=f"frame-number-{name}", size=SMALL_PT + 0.5, first=spots, gaps=(2.5, 3.5, 5.0))

    def _support_footprint(self, q: complex, d: complex, height: float):
        """The area a support of *height* turned along *d* covers (triangle, base, hatching), less the pin."""
        n = d * 1j
        half = 3.2 * self.symbol_scale + 2.0
        far = height + HATCH_LEN
        pts = [q + d * (self.pin_r + 0.3) + n * 0.5, q + d * (self.pin_r + 0.3) - n * 0.5, q + d * far - n * half, q + d * far + n * half]
        return ShapelyPolygon([(z.real, z.imag) for z in pts]).buffer(2.0)

    def _meeting_angles(self, name: str, q: complex) -> dict[str, list[float]]:
        """Per link meeting frame pivot *name* (at *q*), the directions [rad] in which it leaves the pivot at
        the drawing's present position: towards each of its points, and both ways along a block's guide
        (the rod through a swinging sleeve runs both ways through the pivot)."""
        out = {}
        for body in self.scene.bodies_with(name):
            if body == FRAME:
                continue
            angles = [cmath.phase(r - q) for r in self.body_points(body) if abs(r - q) > 1e-6]
            if self.is_block(body):
                phi = self.block_angle(body)
                angles += [phi, phi + math.pi]
            out[body] = angles
        return out

    def _link_over_support(self, name: str, q: complex, d: complex, height: float) -> bool:
        """Whether a link meeting pivot *name* lies, at the drawing's own position, within
        :meth:`_support_clearance` of a support turned along *d* (a crank passing over its support)."""
        need = self._support_clearance(height)
        return any(abs(cmath.phase(cmath.exp(1j * a) / d)) < need
                   for body, angles in self._meeting_angles(name, q).items() if not self.is_block(body) for a in angles)

    def _support_clearance(self, height: float) -> float:
        """The least angle [rad] between a support's axis and a link from its pivot that keeps the link
        off the support's base and hatching."""
        return math.atan2(3.2 * self.symbol_scale + 2.0 + 1.0, height)

    def _cycle_support_direction(self, name: str, q: complex, height: float) -> complex | None:
        """Unit direction from frame pivot *name* to its ground, one for the whole cycle given: at every
        position of the cycle at least :meth:`_support_clearance` from each link meeting the pivot, and clear
        of the other links; of those, as far from the links as can be (up to 75°), then down, then up, in
        preference to sideways (as :meth:`_support_direction`).  A link turning a full circle about the
        pivot (a crank) passes every direction: a crank's support keeps the direction the others decide, and
        :meth:`ground_pivots` turns it away at a position where the crank lies over it.
        None without a cycle, or when no one direction keeps clear (each position then chooses its own)."""
        if not self.cycle:
            return None
        # the same for every drawing of one cycle at one scale (every position page of a handout): found once
        key = ("support", id(self.cycle), name, q, height, self.k_l, self.symbol_scale)
        hit = _CYCLE_CHOICES.get(key)
        if hit is not None and hit[0] is self.cycle:
            return hit[1]
        found = self._find_cycle_support_direction(name, q, height)
        if len(_CYCLE_CHOICES) >= 256:
            _CYCLE_CHOICES.clear()
        _CYCLE_CHOICES[key] = (self.cycle, found)  # the cycle kept with it: its id cannot be reused meanwhile
        return found

    def _cycle_link_shapes(self) -> tuple:
        """The moving links that are not blocks, with their shapes over the cycle (a bar's buffered segment, a
        plate's hull): ``(names, STRtree of every shape, index into names of each shape)``, made once for
        every support of the drawing."""
        cached = getattr(self, "_link_shapes", None)
        if cached is not None and cached[0] == (id(self.cycle), self.k_l):
            return cached[1]
        bodies = [b for b in self.moving if not self.is_block(b)]

        def measure():
            shapes = {}
            for body in bodies:
                pts = self.body_points(body)
                if len(pts) < 2:
                    continue
                if self._is_plate(body):
                    shapes[body] = MultiPoint([(z.real, z.imag) for z in pts]).convex_hull
                else:
                    a, c = max(((z, r) for z in pts for r in pts), key=lambda zr: abs(zr[0] - zr[1]))
                    shapes[body] = LineString([(a.real, a.imag), (c.real, c.imag)]).buffer(BAR_PT * MM_PER_PT / 2)
            return shapes

        samples = self._over_cycle(measure)
        names = [body for body in bodies if any(body in shs for shs in samples)]
        shapes = [shs[body] for body in names for shs in samples if body in shs]
        owner = np.array([k for k, body in enumerate(names) for shs in samples if body in shs], dtype=int)
        out = (names, shapely.STRtree(shapes), owner)
        self._link_shapes = ((id(self.cycle), self.k_l), out)
        return out

    def _find_cycle_support_direction(self, name: str, q: complex, height: float) -> complex | None:
        need = self._support_clearance(height)
        meeting = [b for b in self.scene.bodies_with(name) if b != FRAME]
        samples = self._over_cycle(lambda: self._meeting_angles(name, q))
        thetas = np.array([-math.pi / 2 + 2 * math.pi * k / 24 for k in range(24)])
        feet = np.array([self._support_footprint(q, cmath.exp(1j * t), height) for t in thetas], dtype=object)
        # per link, the least angle from each candidate direction to the link over the cycle (meeting links),
        # or whether the support there meets the link at some position (links passing by)
        clearance, blocked = {}, {}
        for body in meeting:
            a = np.asarray([t for angles in samples for t in angles[body]], dtype=float)
            gap = np.abs(np.angle(np.exp(1j * (thetas[:, None] - a[None, :])))).min(axis=1) if a.size else np.full(len(thetas), math.pi)
            clearance[body] = gap
            blocked[body] = gap < need
        # links passing by: one spatial query finds which of their shapes over the cycle each support meets
        names, tree, owner = self._cycle_link_shapes()
        hit = np.zeros((len(names), len(thetas)), dtype=bool)
        feet_at, shapes_at = tree.query(feet, predicate="intersects")
        hit[owner[shapes_at], feet_at] = True
        for k, body in enumerate(names):
            if body not in meeting:
                blocked[body] = hit[k]
        # a link that meets the support whichever way it stands (a crank turning about its pivot, a lever
        # swinging through it) passes over it at some position: the support stays put, the others decide
        avoid = [b for b, hit in blocked.items() if not hit.all()]
        works = ~np.any([blocked[b] for b in avoid], axis=0) if avoid else np.full(len(thetas), True)
        clear = np.min([clearance[b] for b in avoid if b in clearance] or [np.full(len(thetas), math.pi)], axis=0)
        if not works.any():
            return None
        down = np.abs(np.angle(np.exp(1j * (thetas + math.pi / 2))))
        up = np.abs(np.angle(np.exp(1j * (thetas - math.pi / 2)))) + math.radians(10)
        score = np.minimum(clear, math.radians(75)) - 0.05 * np.minimum(down, up)
        score = np.where(works, score, -np.inf)
        best = int(np.flatnonzero(score > score.max() - 1e-12)[0])
        return cmath.exp(1j * thetas[best])

    def _support_direction(self, name: str, q: complex, height: float | None = None) -> complex:
        """Unit direction from a pivot to its ground: as far from every link meeting it as can be (up to 75°),
        clear of other links drawn near, then down, then up, in preference to sideways."""
        height = self.ground if height is None else height
        angles = [a for found in self._meeting_angles(name, q).values() for a in found]
        best = None
        hole = Point(q.real, q.imag).buffer(self.pin_r + 0.3)  # what meets the pivot itself is judged above
        near = [o for o in getattr(self, "link_shapes", []) if not o.intersects(hole)]
        near = np.array(near, dtype=object)
        for k in range(24):
            theta = -math.pi / 2 + 2 * math.pi * k / 24
            clear = min((abs(cmath.phase(cmath.exp(1j * (theta - a)))) for a in angles), default=math.pi)
            # the drawing-office habit: a support below its pivot, else above (hanging), else sideways
            down = abs(cmath.phase(cmath.exp(1j * (theta + math.pi / 2))))
            up = abs(cmath.phase(cmath.exp(1j * (theta - math.pi / 2)))) + math.radians(10)
            deviation = min(down, up)
            score = min(clear, math.radians(75)) - 0.05 * deviation
            # and clear of what is drawn near it (another link passing by)
            d = cmath.exp(1j * theta)
            foot = self._support_footprint(q, d, height)
            if len(near) and shapely.intersects(near, foot).any():
                score -= 1.0
            if best is None or score > best[0] + 1e-12:
                best = (score, theta)
        return cmath.exp(1j * best[1])

    def _guide_of(self, body: str) -> str | None:
        for pr in self.scene.prismatics:
            if pr.slider == body:
                return pr.guide
        return None

    def blocks(self) -> None:
        """Slider blocks and sleeves, rotated with their lines.

        Two blocks on one pin (a follower block on a frame guide pinned to a
        block on a moving incline) would hide each other: the one on the
        moving line is centred on the pin, the other is drawn beside it along
        its own guide, its end on the pin.
        """
        self.block_centres: dict[str, complex] = {}
        self.block_marks: dict[str, int] = {}  # body -> the index of its block among the sketch's obstacles
        L = self.block[0] / 2
        order = sorted(
            (b for b in self.moving if self.is_block(b)),
            key=lambda b: self._guide_of(b) == FRAME,
        )
        placed: list = []
        pins: dict[str, complex] = {}
        for body in order:
            pin = self.body_points(body)[0]
            u = cmath.exp(1j * self.block_angle(body))
            centre = pin
            guide = self._guide_of(body)
            if guide in getattr(self, "plates", {}):
                # a block on the edge of a plate (a wedge's incline) sits on the edge, outside
                # the plate, its pin at the middle of the side that slides
                n = u * 1j
                out = 1.0 if ((pin - self.plates[guide]) * n.conjugate()).real >= 0 else -1.0
                centre = pin + n * out * self.block[1] / 2
            if any(abs(p - pin) < 1e-9 for p in pins.values()):
                side = self._stack_side(body)
                options = [pin + u * L, pin - u * L] if side >= 0 else [pin - u * L, pin + u * L]
                if side:
                    # stacked on the block below it: moved along its own guide until clear of it
                    sense = options[0] - pin
                    t = 0.0
                    while t < 4 * L and any(self._rect(pin + sense * (1 + t / L), u).intersection(q).area > 1e-6 for q in placed):
                        t += 0.25
                    centre = pin + sense * (1 + t / L)
                    if t > 0:
                        # the follower's stem from its block down to its pin, over the block under it,
                        # so that the pin reads as the joint of the two blocks (not of block and incline)
                        self.s.line([pin, centre - unit(centre - pin) * L], lw=BAR_PT, gid=f"stem-{body}", zorder=3.05, capstyle="butt")
                else:
                    centre = min(options, key=lambda c: sum(self._rect(c, u).intersection(q).area for q in placed))
            rect = self._rect(centre, u)
            corners = [complex(x, y) for x, y in list(rect.exterior.coords)[:-1]]
            self.s.polygon(corners, fc="white", lw=1.1, gid=f"block-{body}", zorder=3.0)
            self.block_marks[body] = len(self.s.obstacles) - 1  # (its number may go on it: :meth:`link_labels`)
            placed.append(rect)
            self.block_centres[body] = centre
            pins[body] = pin
        # a bar pinned to a block reaches the pin over the block (linear-arm link 6 to H), rather than stopping at the
        # block's edge; to a block in a slot, over the slotted link too, from its other end (the quick-return's crank 2
        # stopped at the edge of rocker 4's slot, its pin A apart from it: the review of the sheet)
        reach = math.hypot(*self.block) / 2 + 0.3
        for bar, (a, c) in getattr(self, "bars", {}).items():
            for end, other in ((a, c), (c, a)):
                slotted = [self._in_slot(b) for b, q in pins.items() if b != bar and abs(end - q) < 1e-9]
                if not all(slotted) and abs(other - end) > reach:
                    self.s.line([end, end + unit(other - end) * reach], lw=BAR_PT, gid=f"link-{bar}-to-pin", zorder=3.05, capstyle="butt", obstacle=False)
                elif any(slotted):
                    self.s.line([other, end], lw=BAR_PT, gid=f"link-{bar}-over-slot", zorder=3.05, capstyle="butt", obstacle=False)
        # a linear driver that carries an arm still slides on its guide in a block
        driver = self.scene.driver
        if hasattr(driver, "guide") and not self.is_block(driver.link):
            u = cmath.exp(1j * self.scene.bodies[FRAME].lines[driver.guide].angle)
            rect = self._rect(self.p(driver.point), u)
            corners = [complex(x, y) for x, y in list(rect.exterior.coords)[:-1]]
            self.s.polygon(corners, fc="white", lw=1.1, gid=f"block-{driver.link}", zorder=3.0)
            self._rigid_joints(driver.link, self.p(driver.point), u, rect)
        # a sleeve of a moving link that a rod (not a block) slides through
        for pr in self.scene.prismatics:
            if pr.guide == FRAME or self.is_block(pr.guide) or self.is_block(pr.slider):
                continue
            line = self.scene.bodies[pr.guide].lines[pr.guide_line]
            centre = self.g(pr.guide, line.origin)
            u = cmath.exp(1j * (self.angle(pr.guide) + line.angle))
            rect = self._rect(centre, u, 0.8)
            corners = [complex(x, y) for x, y in list(rect.exterior.coords)[:-1]]
            self.s.polygon(corners, fc="white", lw=1.1, gid=f"sleeve-{pr.guide}", zorder=3.0)

    def _rigid_joints(self, body: str, centre: complex, u: complex, rect) -> None:
        """The sign of a rigid joint where an arm of *body* leaves its block (*rect*, centred at *centre*, along *u*):
        a solid triangle on the block's edge, its apex along the arm (the arm is welded to the block, not pinned)."""
        L, H = self.block[0] / 2, self.block[1] / 2
        for q in self.body_points(body):
            if abs(q - centre) <= math.hypot(L, H):
                continue  # a point inside the block (the block's own point)
            d = unit(q - centre)
            # where the arm leaves the block: the nearer of the block's sides it crosses
            along, across = (d * u.conjugate()).real, (d * u.conjugate()).imag
            t = min(L / abs(along) if abs(along) > 1e-9 else math.inf, H / abs(across) if abs(across) > 1e-9 else math.inf)
            hit = centre + d * t
            edge = u * 1j if abs(along) * H > abs(across) * L else u  # the side's direction
            half = min(2.2, 0.45 * self.block[0]) * self.symbol_scale
            apex = hit + d * 3.2 * self.symbol_scale
            self.s.polygon([hit + edge * half, hit - edge * half, apex], fc=INK, lw=0.6, gid=f"weld-{body}", zorder=3.1)

    def _rect(self, centre: complex, u: complex, scale: float = 1.0):
        L, H = self.block[0] / 2 * scale, self.block[1] / 2 * scale
        n = u * 1j
        pts = [centre + u * L + n * H, centre - u * L + n * H, centre - u * L - n * H, centre + u * L - n * H]
        return ShapelyPolygon([(p.real, p.imag) for p in pts])

    def pins(self) -> None:
        for name in self.sol.positions:
            bodies = self.scene.bodies_with(name)
            if not bodies:
                continue
            q = self.p(name)
            if len(bodies) >= 2:
                self.s.circle(q, self.pin_r, fc="white", lw=0.9, gid=f"pin-{name}", zorder=4.0)
            elif name in self.scene.report:
                self.s.circle(q, DOT_R, fc=INK, lw=0.0, gid=f"dot-{name}", zorder=4.0)

    def driver_arrows(self) -> None:
        driver = self.scene.driver
        if hasattr(driver, "omega"):
            self._crank_arrows(driver)
        else:
            self._linear_arrows(driver)

    #: the arc's radius tried at these multiples of its own, and its sweep at these fractions of its own, in turn
    ARC_RADII = (1.0, 0.85, 1.2, 0.7, 1.4)
    ARC_SWEEPS = (1.0, 0.8, 0.65)

    def _free_arc(self, centre: complex, radius: float, sweep: float, largest: float = math.inf) -> tuple[float, float, float]:
        """Where a driver's arc arrow about *centre* goes: ``(start, radius, sweep)`` [rad, mm, rad].

        Tried at 36 starts, at the radii :data:`ARC_RADII` × *radius* and the sweeps :data:`ARC_SWEEPS` × *sweep*
        (never within the pin, nor larger than *largest* [mm], the crank's reach): an arc that crosses no link (:attr:`link_marks`: a bar, a slot, a block, the crank
        itself outside its direction) first, then one that crosses nothing else drawn (a support's hatching), then
        the one furthest from everything drawn (up to 3 mm), the arc's own radius and sweep preferred (a smaller one
        costs as much as 3 mm of clearance per unit of its log-ratio, a shorter sweep 3 mm per unit of its
        fraction left out).  The first of equals in that order wins (deterministic)."""
        reach = radius * max(self.ARC_RADII) + 3.0
        # what passes through the pivot (its pin, the ground symbol) counts only away from it; a link counts wherever
        # the arc meets it (the crank, where the arc passes over its direction)
        hole = Point(centre.real, centre.imag).buffer(radius * min(self.ARC_RADII) * 0.6)
        near = [o for o in self.s.obstacles if _box_within(o.bounds, centre, reach)]
        links = np.array([o for o in getattr(self, "link_marks", []) if _box_within(o.bounds, centre, reach)], dtype=object)
        others = np.array([g for g in (o.difference(hole) for o in near) if not g.is_empty], dtype=object)
        least = self.pin_r + 1.0
        options = []  # (start, radius, sweep, cost of leaving the arc's own size)
        for rf in self.ARC_RADII:
            r = radius * rf
            if rf != 1.0 and not (least <= r <= largest):
                continue
            for sf in self.ARC_SWEEPS:
                for k in range(36):
                    options.append((2 * math.pi * k / 36, r, sweep * sf, 3.0 * abs(math.log(rf)) + 3.0 * (1.0 - sf)))
        steps = np.arange(13) / 12
        coords = np.array([[(centre + r * cmath.exp(1j * (start + sw * t))) for t in steps] for start, r, sw, _ in options])
        arcs = shapely.linestrings(np.stack([coords.real, coords.imag], axis=-1))

        def pairs(shapes, within):
            if not len(shapes):
                return np.array([], dtype=int), np.array([], dtype=int)
            i, j = np.divmod(np.arange(len(arcs) * len(shapes)), len(shapes))
            keep = shapely.dwithin(shapes[j], arcs[i], within)
            return i[keep], j[keep]

        crossed_link = np.zeros(len(arcs), dtype=bool)
        i, j = pairs(links, 0.0)
        crossed_link[i] = True
        clear = np.full(len(arcs), 3.0)
        i, j = pairs(others, 3.0)
        if len(i):
            np.minimum.at(clear, i, shapely.distance(arcs[i], others[j]))
        best = None
        for k, (start, r, sw, cost) in enumerate(options):
            score = (-100.0 if crossed_link[k] else 0.0) + (-10.0 if clear[k] <= 0.0 else 0.0) + min(float(clear[k]), 3.0) - cost
            if best is None or score > best[0] + 1e-9:
                best = (score, start, r, sw)
        return best[1], best[2], best[3]

    def _crank_arrows(self, driver) -> None:
        centre = self.p(driver.pivot)
        # the arcs stay within the crank they turn (a 10 mm crank gets a small ω)
        crank = max((abs(q - centre) for q in self.body_points(driver.link)), default=0.0)
        fit = 1.0 if crank <= 0 else min(1.0, max(0.35, 0.75 * crank / self.epsilon_r if driver.epsilon else 0.7 * crank / self.omega_r))
        for symbol, value, radius, largest, dashes, gid in (
            ("ω", driver.omega, self.omega_r * fit, 0.7 * crank, None, "omega"),
            ("ε", driver.epsilon, self.epsilon_r * fit, 0.75 * crank, (3.0, 1.5), "epsilon"),
        ):
            if not value:
                continue
            sweep = math.radians(120) * (1 if value > 0 else -1)
            start, radius, sweep = self._free_arc(centre, radius, sweep, largest=max(radius, largest))
            self.s.arc_arrow(centre, radius, start, sweep, lw=0.9, dashes=dashes, gid=gid)
            text, math_ = _sub(symbol, driver.link)
            mid = centre + radius * cmath.exp(1j * (start + sweep / 2))
            self._label(mid, text, gid=f"{gid}-label", size=LABEL_PT, prefer=mid - centre, math_=math_)

    def _linear_arrows(self, driver) -> None:
        q = self.p(driver.point)
        u = cmath.exp(1j * self.scene.bodies[FRAME].lines[driver.guide].angle)
        arr = np.array(self.s.obstacles, dtype=object)
        offset = self.block[1] / 2 + 4.5
        best = None
        for side in (1j, -1j):
            seg = LineString([((q + u * side * offset + u * t).real, (q + u * side * offset + u * t).imag) for t in (-8, 8)])
            d = float(shapely.distance(seg, arr).min()) if len(arr) else math.inf
            if best is None or d > best[0] + 1e-9:
                best = (d, side)
        side = best[1]
        labels = []
        # both given absolute vectors of the driver's point, solid as the plans' legend draws an absolute vector
        for k, (symbol, value, dashes, gid) in enumerate(
            (("v", driver.velocity, None, "velocity"), ("a", driver.acceleration, None, "acceleration"))
        ):
            if not value:
                continue
            sense = u if value > 0 else -u
            base = q + u * side * (offset + 4.5 * k)
            tail, tip = base - sense * 7.0, base + sense * 7.0
            self.s.arrow(tail, tip, lw=0.9, dashes=dashes, head=2.6, gid=gid)
            labels.append((tip, rf"${symbol}_{{{math_name(driver.point)}}}$", f"{gid}-label"))
        # labels after both arrows, so that neither label lands on the other arrow
        for tip, text, gid in labels:
            self._label(tip, text, gid=gid, size=LABEL_PT, prefer=u * side, math_=True)

    def _label(self, anchor, text, *, gid, size, prefer=None, math_=False, first=(), gaps=(0.6, 1.4, 2.4, 3.6, 5.5, 8.0), leader_from=LEADER_FROM_MM):
        return place_label(self.s, anchor, [(text, gid)], size=size, prefer=prefer, first=first, gaps=gaps, mathtext=math_, leader_from=leader_from,
                           clear_leaders=True)

    def point_labels(self) -> None:
        self.numbered = set()
        for body, centre in getattr(self, "block_centres", {}).items():
            if any(way.contains(Point(centre.real, centre.imag)) for way in self.guideways):
                self._number_in_guideway(body, centre)
                self.numbered.add(body)
        self._point_labels()

    def _number_in_guideway(self, body: str, centre: complex) -> None:
        """A block in a guideway: walled in by the guide lines and their hatching, its number goes on the block beside
        its pin (outside, its leader would cross a guide's hatching), placed before the points' letters."""
        r = math.hypot(*self.block) / 2
        u = cmath.exp(1j * self.block_angle(body))
        w = text_size(body, SMALL_PT + 1)[0]
        beside = self.pin_r + 0.6 + w / 2
        first = (centre + u * beside, centre - u * beside)
        # (its own block is an outline for its number, no longer the area it covers)
        k = self.block_marks[body]
        whole = self.s.obstacles[k]
        self.s.obstacles[k] = whole.exterior.buffer(0.3)
        try:
            self._label(centre, body, gid=f"number-{body}", size=SMALL_PT + 1, first=first, gaps=(r * 0.55, r * 0.8, r + 1.5, r + 4.0))
        finally:
            self.s.obstacles[k] = whole

    def _point_labels(self) -> None:
        for name in mechanism_labels(self.sol):
            if self.names.get(name, name) is None:
                continue  # (lettered by the caller)
            q = self.p(name)
            away = q - self.centroid
            r = self.pin_r + 0.5
            # the pin of a block in a guideway (numbered on the block, :meth:`_number_in_guideway`) is lettered beside the
            # block, in the guideway, without a leader: the block is the point to the eye (a leader would cross its number)
            walled = any(abs(self.block_centres[b] - q) < 1e-6 for b in self.numbered)
            gaps = (r, r + 0.8, r + 1.8, r + 3.0, r + 5.0)
            if walled:
                gaps += (self.block[0] / 2 + 1.5,)
            self._label(q, self.names.get(name, name), gid=f"point-{name}", size=LABEL_PT, prefer=away if abs(away) > 1e-9 else None, gaps=gaps,
                        leader_from=self.block[0] / 2 + LEADER_FROM_MM if walled else LEADER_FROM_MM)

    def link_labels(self) -> None:
        # every bar and block centre once, as geometry: each bar's label keeps away from all but its own
        bar_names = list(self.bars)
        marks = np.array([LineString([(p0.real, p0.imag), (p1.real, p1.imag)]) for p0, p1 in self.bars.values()]
                         + [Point(q.real, q.imag) for q in getattr(self, "block_centres", {}).values()], dtype=object)
        for body in self.moving:
            if body in self.plates:
                self._label(self.plates[body], body, gid=f"number-{body}", size=SMALL_PT + 1, first=(self.plates[body],))
            elif body in self.bars:
                a, c = self.bars[body]
                mid = (a + c) / 2
                n = unit(c - a) * 1j
                # beside its own bar, on the stretch furthest from every other link and
                # block (linear-arm: "3" on rod F–G, not by rocker D–K where the bar's middle is)
                others = np.delete(marks, bar_names.index(body))
                spots = [a + (c - a) * t + n * side * 2.8 for t in (0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8) for side in (1, -1)]
                if len(others):
                    far = shapely.distance(shapely.points([(z.real, z.imag) for z in spots])[:, None], others[None, :]).min(axis=1)
                    order = sorted(range(len(spots)), key=lambda k: -far[k])
                    spots = [spots[k] for k in order]
                self._label(mid, body, gid=f"number-{body}", size=SMALL_PT + 1, prefer=n, first=tuple(spots[:4]), gaps=(1.2, 2.5, 4.0, 7.0))
            elif body in self.block_centres:
                if body in self.numbered:
                    continue
                centre = self.block_centres[body]
                r = math.hypot(*self.block) / 2
                # beside its own block: away from another block on the same pin
                others = [c for b, c in self.block_centres.items() if b != body and abs(c - centre) < 2 * r]
                prefer = sum((centre - c for c in others), 0j) or None
                first = (centre + unit(prefer) * (r + 3.0),) if prefer else ()
                if prefer and self._guide_of(body) in self.plates:
                    # a block on a plate's edge: beside it along the edge, away from the block on it
                    u = cmath.exp(1j * self.block_angle(body))
                    along = -u if (prefer * u.conjugate()).real < 0 else u
                    first = (centre + along * (self.block[0] / 2 + 2.5),) + first
                if self._in_slot(body):
                    # in a slot: outside the slotted link, across from the block, joined to it by a
                    # leader (inside the slot it would read as the slotted link's number: scotch yoke)
                    u = cmath.exp(1j * self.block_angle(body))
                    across = self.block[1] / 2 + 0.5 + 3.8
                    self._label(centre, body, gid=f"number-{body}", size=SMALL_PT + 1, prefer=u * 1j, gaps=(across, across + 2.0, across + 4.0))
                    continue
                self._label(centre, body, gid=f"number-{body}", size=SMALL_PT + 1, prefer=prefer, first=first, gaps=(r * 0.55, r * 0.8, r + 1.5, r + 4.0))

    def caption(self) -> None:
        if not self.show_caption:
            return
        b = self.s.bounds
        x, y = b.xmin, b.ymin - 2.5
        self.s.text(complex(x, y), term("mechanism", self.lang), size=HEADING_PT, ha="left", va="top", weight="bold", gid="heading", obstacle=False)
        y -= 5.0
        self.s.text(complex(x, y), scale_caption("k_l", fmt_number(self.k_l), "m/mm", self.lang), size=CAPTION_PT, ha="left", va="top", gid="scale", obstacle=False, math=True)
