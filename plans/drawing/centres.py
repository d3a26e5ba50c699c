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
from .style import CAPTION_PT, CONSTRUCTION_STYLE, HEADING_PT, INK, MARGIN_MM, SMALL_PT, TITLE_PT
from .svg import new_figure, render_svg

__all__ = ["draw_centres", "draw_centres_into", "draw_circle_diagram_into", "centres_svg", "centre_text", "undetermined_text", "CENTRE_COLOUR"]

CENTRE_COLOUR = "#C0392B"
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
#: room around the mechanism where centres are drawn where they are [mm]
ROOM_MIN = 25.0
ROOM_FRACTION = 0.35
#: centres within this fraction of the mechanism's drawn size beyond it are drawn where they are
NEAR_FRACTION = 1.0
EDGE_ARROW = 9.0  # mm
EDGE_GAP = 3.0  # mm between the room and an edge arrow's tail
EDGE_SPACING = 13.0  # mm between the tails of two edge arrows
LONE_LINE = 25.0  # mm each side of the one finite centre on a Kennedy line
DIAGRAM_R = 22.0  # mm
LABEL_PT = SMALL_PT + 1.5
#: Gaps tried for a centre's label, in units of its mark's clearance; from LEADER_RING on, with a leader line.
LABEL_RINGS = (1, 2, 3, 4.5, 6.5)
LEADER_RING = 2.5
#: Room [mm] a centre's label keeps from what is drawn (the font's box is an estimate of the ink's).
LABEL_CLEAR_MM = 0.3


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


class _CentresDrawing:
    def __init__(self, sketch: Sketch, result, k_l: float, lo: complex, hi: complex, lang: str = "en"):
        self.lang = lang
        self.s = sketch
        self.r = result
        self.k_l = k_l
        self.lo, self.hi = lo, hi
        self.middle = (lo + hi) / 2
        self.edges: list[complex] = []
        self.soft: list = []  # the Kennedy lines: a label may cross one, at a cost

    def mm(self, z: complex) -> complex:
        return z / self.k_l

    def inside(self, q: complex) -> bool:
        return self.lo.real <= q.real <= self.hi.real and self.lo.imag <= q.imag <= self.hi.imag

    def edge_point(self, u: complex) -> complex:
        """Just outside where the ray from the middle in direction u leaves the room, moved across it off earlier arrows.

        Returns the tail of the arrow; its tip is EDGE_ARROW further along u.
        """
        span = _clip(self.middle, u, self.lo, self.hi)
        base = self.middle + span[1] * u + EDGE_GAP * u
        q, step = base, 0
        while any(abs(q - e) < EDGE_SPACING for e in self.edges) and step < 24:
            step += 1
            q = base + (1j * u) * EDGE_SPACING * ((step + 1) // 2) * (1 if step % 2 else -1)
        self.edges.append(q)
        return q

    def label(self, at: complex, text: str, gid: str, away: complex, clear: float) -> None:
        """Text near *at*, at the first of eight places around it that overlaps nothing drawn before."""
        w, h = text_size(text, LABEL_PT)
        start = cmath.phase(away) if abs(away) > 1e-9 else math.pi / 4
        best = None
        for k in range(16 * len(LABEL_RINGS)):
            turn = (k % 16 + 1) // 2 * (1 if k % 2 else -1) * math.pi / 8
            d = cmath.exp(1j * (start + turn))
            ring = LABEL_RINGS[k // 16]
            gap = clear * ring + 0.6 + 0.5 * (abs(d.real) * w + abs(d.imag) * h)
            c = at + d * gap
            shape = box(c.real - w / 2, c.imag - h / 2, c.real + w / 2, c.imag + h / 2).buffer(LABEL_CLEAR_MM, join_style=2)
            hits = 10 * sum(1 for o in self.s.obstacles if shape.intersects(o)) + sum(1 for o in self.soft if shape.intersects(o))
            leader = None
            if ring >= LEADER_RING:  # away from a crowd, a leader line joins the label to its centre
                a = at + d * clear
                b = c - d * (0.5 * (abs(d.real) * w + abs(d.imag) * h) + 0.3)
                leader = (a, b)
                line = LineString([(a.real, a.imag), (b.real, b.imag)])
                hits += 10 * sum(1 for o in self.s.obstacles if line.intersects(o))
            if best is None or hits < best[0]:
                best = (hits, c, leader)
            if hits == 0:
                break
        _, c, leader = best
        if leader is not None:
            self.s.line(list(leader), color=CENTRE_COLOUR, lw=0.4, gid=f"{gid}-leader", zorder=4.9)
        self.s.text(c, text, size=LABEL_PT, color=CENTRE_COLOUR, gid=gid)

    def kennedy_lines(self) -> None:
        """Each Kennedy line that gave a centre, through its three centres, inside the room."""
        by_label = {c.label: c for c in self.r.centres}
        done = set()
        colour, lw, dashes = CONSTRUCTION_STYLE
        for centre in self.r.centres:
            for pair in centre.lines:
                three = [by_label[pair[0]], by_label[pair[1]], centre]
                bodies = tuple(sorted({b for c in three for b in c.bodies}, key=list(self.r.numbers).index))
                if bodies in done:
                    continue
                done.add(bodies)
                finite = [self.mm(c.point) for c in three if c.point is not None]
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
                span = _clip(a, u, self.lo, self.hi)
                if span is None:
                    continue
                t0, t1 = max(t0, span[0]), min(t1, span[1])
                if t1 <= t0:
                    continue
                names = "-".join(self.r.numbers[b] for b in bodies)
                self.s.line([a + t0 * u, a + t1 * u], color=colour, lw=lw * 0.8, dashes=dashes, gid=f"kennedy-{names}", zorder=1.2, obstacle=False)
                ends = a + t0 * u, a + t1 * u
                self.soft.append(LineString([(z.real, z.imag) for z in ends]))

    def centres(self) -> None:
        for centre in self.r.centres:
            if not centre.determined:
                continue  # named in the caption
            text = centre_text(centre.label)
            if centre.point is not None and self.inside(self.mm(centre.point)):
                q = self.mm(centre.point)
                if centre.found_by.startswith("revolute"):
                    self.s.circle(q, 2.2, fc="none", ec=CENTRE_COLOUR, lw=0.9, gid=f"mark-{centre.label}", zorder=5.0)
                    clear = 2.4
                else:
                    self.s.circle(q, 1.0, fc=CENTRE_COLOUR, ec=CENTRE_COLOUR, lw=0.5, gid=f"mark-{centre.label}", zorder=5.0)
                    clear = 1.2
                self.label(q, text, f"label-{centre.label}", q - self.middle, clear)
                continue
            if centre.point is not None:
                tail = self.edge_point(unit(self.mm(centre.point) - self.middle))
                u = unit(self.mm(centre.point) - tail)  # the arrow points at the centre
                tip = tail + EDGE_ARROW * u
                beyond = abs(self.mm(centre.point) - tip) * self.k_l
                text = decimal_comma(f"{text} +{beyond:.3g} m", self.lang)
            else:
                u = centre.direction
                tail = self.edge_point(u)
                tip = tail + EDGE_ARROW * u
                text = f"{text} ∞"
            self.s.arrow(tail, tip, color=CENTRE_COLOUR, lw=1.0, head=2.4, gid=f"edge-{centre.label}")
            self.label(tip, text, f"label-{centre.label}", u, 0.8)


def _circle_diagram(s: Sketch, result, centre: complex, lang: str = "en") -> None:
    """Bodies on a circle (1 at the top, clockwise), primary centres as sides, Kennedy ones as dashed diagonals."""
    names = list(result.numbers)
    n = len(names)
    at = {name: centre + DIAGRAM_R * cmath.exp(1j * (math.pi / 2 - 2 * math.pi * k / n)) for k, name in enumerate(names)}
    s.circle(centre, DIAGRAM_R, fc="none", ec="#b0b0b0", lw=0.5, gid="diagram-circle", zorder=1.0, obstacle=False)
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
    s.text(centre - 1j * (DIAGRAM_R + 8.0), term("circle_diagram", lang), size=CAPTION_PT, weight="bold", gid="diagram-heading", obstacle=False)
    lines = []
    for part in term("circle_diagram_legend", lang).split("\n"):  # each part wrapped to the diagram's width
        current = ""
        for word in part.split():
            trial = f"{current} {word}".strip()
            if current and text_size(trial, CAPTION_PT)[0] > 2 * DIAGRAM_R + 6.0:
                lines.append(current)
                current = word
            else:
                current = trial
        lines.append(current)
    for k, line in enumerate(lines):
        s.text(centre - 1j * (DIAGRAM_R + 12.5 + 4.0 * k), line, size=CAPTION_PT, gid="diagram-legend", obstacle=False)


def _shapes(artists) -> list:
    """Obstacles for the labels from the mechanism's artists: lines, circles, polygons, text boxes [mm]."""
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
                shapes.append(LineString(xy).buffer(0.4))
        elif isinstance(artist, Circle):
            x, y = artist.center
            shapes.append(Point(x, y).buffer(artist.radius))
        elif isinstance(artist, Polygon):
            xy = artist.get_xy()
            if len(xy) >= 3:
                shapes.append(ShapelyPolygon(xy).buffer(0.2))
        elif isinstance(artist, Text) and artist.get_text():
            w, h = text_size(artist.get_text(), artist.get_fontsize())
            x, y = artist.get_position()
            x0 = {"left": x, "center": x - w / 2, "right": x - w}.get(artist.get_ha(), x - w / 2)
            y0 = {"bottom": y, "center": y - h / 2, "top": y - h}.get(artist.get_va(), y - h / 2)
            shapes.append(box(x0, y0, x0 + w, y0 + h))
    return shapes


def draw_centres_into(ax, result, k_l: float, lang: str = "en", *, title: str | None = None, legend: bool = True, diagram: bool = True,
                      room_min: float = ROOM_MIN):
    """The mechanism at k_l with every instant centre, and the circle diagram beside it, drawn into *ax*.

    One data unit is one millimetre of paper.  *title* (plain text), when
    given, goes above; *legend* adds the two lines that say what rings,
    dots, dashed lines and edge arrows mean; *diagram* False leaves the circle
    diagram out (a page puts it elsewhere: :func:`draw_circle_diagram_into`).
    *room_min* [mm] is the least room kept around the mechanism for the
    Kennedy lines and labels (far centres' arrows go outside it).
    The axes' limits are set to the ink plus the margin.

    Returns
    -------
    (width, height) [mm] of the drawing.
    """
    scene = result.scene
    # the centres' marks are there before the mechanism's labels are placed: a link number or a point's
    # name keeps clear of them (the six-bar's "2" touched P₂₆)
    marks = [Point(c.point.real / k_l, c.point.imag / k_l).buffer((2.2 if c.found_by.startswith("revolute") else 1.0) + 0.4)
             for c in result.centres if c.determined and c.point is not None]
    drawn = _Drawn(scene, {"k_l": k_l}, result.positions, result.poses)
    artists = sketch_on(ax, "mech", lambda sketch: (sketch.obstacles.extend(marks), MechanismDrawing(sketch, drawn, lang=lang).draw()))
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    lo, hi = complex(x0 + MARGIN_MM, y0 + MARGIN_MM), complex(x1 - MARGIN_MM, y1 - MARGIN_MM)
    room = max(room_min, ROOM_FRACTION * max(hi.real - lo.real, hi.imag - lo.imag))
    reach = NEAR_FRACTION * max(hi.real - lo.real, hi.imag - lo.imag)
    near = [c.point / k_l for c in result.centres if c.point is not None]
    near = [q for q in near if lo.real - reach <= q.real <= hi.real + reach and lo.imag - reach <= q.imag <= hi.imag + reach]
    lo, hi = lo - room * (1 + 1j), hi + room * (1 + 1j)
    for q in near:  # a centre up to one mechanism's size away is drawn where it is, with some room around it
        lo = complex(min(lo.real, q.real - 12.0), min(lo.imag, q.imag - 8.0))
        hi = complex(max(hi.real, q.real + 12.0), max(hi.imag, q.imag + 8.0))
    s = Sketch(ax, "centres")
    s.obstacles.extend(_shapes(artists))
    drawing = _CentresDrawing(s, result, k_l, lo, hi, lang)
    drawing.kennedy_lines()
    drawing.centres()
    if diagram:
        _circle_diagram(s, result, complex(max(s.bounds.xmax, x1) + 14.0 + DIAGRAM_R, (lo.imag + hi.imag) / 2 + 6.0), lang)
    top = s.bounds.ymax + 4.0
    if legend:
        words = decimal_comma(f"$k_l$ = {fmt_number(k_l)} m/mm;  n(n−1)/2 = {len(result.centres)};  ", lang)
        s.text(complex(lo.real, top + 2.0), words + term("centres_legend", lang), size=CAPTION_PT, ha="left", va="bottom", gid="legend", obstacle=False, math=True)
        s.text(complex(lo.real, top - 2.0), term("centres_edge_legend", lang), size=CAPTION_PT, ha="left", va="bottom", gid="legend-edge", obstacle=False)
        top += 5.0
    if title is not None:
        s.text(complex(lo.real, top + 2.0), user_text(title), size=TITLE_PT - 3, ha="left", va="bottom", weight="bold", gid="title", obstacle=False)
    missing = [c for c in result.centres if not c.determined]
    for k, c in enumerate(missing):
        s.text(complex(lo.real, min(s.bounds.ymin, y0) - 3.0), undetermined_text(c, lang),
               size=CAPTION_PT, ha="left", va="top", color=CENTRE_COLOUR, gid=f"undetermined-{c.label}", obstacle=False)
    b = s.bounds
    xmin, xmax = min(b.xmin, x0), max(b.xmax, x1)
    ymin, ymax = min(b.ymin, y0), max(b.ymax, y1)
    ax.set_xlim(xmin - MARGIN_MM, xmax + MARGIN_MM)
    ax.set_ylim(ymin - MARGIN_MM, ymax + MARGIN_MM)
    ax.set_aspect("auto")
    ax.set_axis_off()
    return xmax - xmin + 2 * MARGIN_MM, ymax - ymin + 2 * MARGIN_MM


def draw_circle_diagram_into(ax, result, lang: str = "en") -> tuple[float, float]:
    """The circle diagram alone, drawn into *ax* (one data unit a millimetre); returns its (width, height) [mm]."""
    s = Sketch(ax, "centres")
    _circle_diagram(s, result, 0j, lang)
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
    width, height = draw_centres_into(ax, result, k_l, lang, title=f"{term('instant_centres', lang)} — {user_text(scene.title)}")
    fig.set_size_inches(width / 25.4, height / 25.4)
    ax.set_position([0.0, 0.0, 1.0, 1.0])
    return fig


def centres_svg(result, k_l: float | None = None, lang: str = "en") -> bytes:
    """``centres.svg`` as bytes (deterministic); see :func:`draw_centres`."""
    return render_svg(draw_centres(result, k_l, lang))
