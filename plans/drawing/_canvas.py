"""A thin recorder over a matplotlib Axes whose data unit is one millimetre of paper.

Every primitive a drawing makes goes through :class:`Sketch`, which creates
the artist, gives it a unique gid, widens the drawing's bounds (text boxes
included, measured with the same font the SVG names) and remembers the shape
as an obstacle for label placement.
"""

from __future__ import annotations

import cmath
import functools
import math
import re

from matplotlib.collections import LineCollection
from matplotlib.font_manager import FontProperties
from matplotlib.lines import Line2D
from matplotlib.text import Text
from matplotlib.transforms import TransformedPatchPath
from matplotlib.patches import Circle, Polygon
from matplotlib.textpath import TextToPath
from shapely.geometry import LineString, Point, box
from shapely.geometry import Polygon as ShapelyPolygon

from .style import ARROW_RATIO, FONT_FAMILY, HOLLOW_RATIO, INK, MARGIN_MM, MM_PER_PT

__all__ = ["Bounds", "Obstacles", "Sketch", "text_size", "fmt_number", "unit"]

_TEXT_TO_PATH = TextToPath()


#: a math string whose only math is its leading symbol (a caption: ``$k_{l}$ = 0.005 m/mm``)
_MATH_LEAD = re.compile(r"(\$[^$]+\$)([^$\\]*)")


@functools.lru_cache(maxsize=4096)
def text_size(text: str, size_pt: float, weight: str = "normal", math: bool = False) -> tuple[float, float]:
    """Width and height [mm] of the box matplotlib lays *text* out in.

    The height is that of a line of the font (ascent + descent), which is what
    ``va="center"`` centres, so single labels of different letters line up.
    """
    prop = FontProperties(family=FONT_FAMILY, size=size_pt, weight=weight)
    lead = _MATH_LEAD.fullmatch(text) if math else None
    if lead:  # "$k_{l}$ = 0.005 m/mm": the symbol parsed once for every value, the rest measured as plain text
        width = sum(_TEXT_TO_PATH.get_text_width_height_descent(part, prop, ismath=m)[0] for part, m in ((lead[1], True), (lead[2], False)) if part)
    else:
        width, _, _ = _TEXT_TO_PATH.get_text_width_height_descent(text, prop, ismath=math)
    _, height, _ = _TEXT_TO_PATH.get_text_width_height_descent("lp", prop, ismath=False)
    return width * MM_PER_PT, height * MM_PER_PT * 1.18


def unit(z: complex) -> complex:
    r = abs(z)
    return z / r if r > 0 else 1 + 0j


def fmt_number(value: float) -> str:
    """A scale factor as a textbook prints it: 0.005, 50, 2.5·10⁻⁶."""
    if value == 0:
        return "0"
    if 1e-3 <= abs(value) < 1e5:
        text = f"{value:.6g}"
        return text
    mantissa, exponent = f"{value:.4e}".split("e")
    mantissa = mantissa.rstrip("0").rstrip(".")
    exp = int(exponent)
    sup = str(exp).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))
    return f"10{sup}" if mantissa == "1" else f"{mantissa}·10{sup}"


class Bounds:
    """An axis-aligned box [mm] that grows."""

    def __init__(self):
        self.xmin = self.ymin = math.inf
        self.xmax = self.ymax = -math.inf

    def add(self, x: float, y: float) -> None:
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ValueError(f"non-finite coordinate in a drawing: ({x}, {y})")
        self.xmin = min(self.xmin, x)
        self.xmax = max(self.xmax, x)
        self.ymin = min(self.ymin, y)
        self.ymax = max(self.ymax, y)

    def add_box(self, x0: float, y0: float, x1: float, y1: float) -> None:
        self.add(x0, y0)
        self.add(x1, y1)

    @property
    def empty(self) -> bool:
        return self.xmin > self.xmax

    @property
    def width(self) -> float:
        return 0.0 if self.empty else self.xmax - self.xmin

    @property
    def height(self) -> float:
        return 0.0 if self.empty else self.ymax - self.ymin


class Obstacles(list):
    """The shapes labels keep clear of, as a list, with a uniform grid over their bounds.

    ``near(x0, y0, x1, y1)`` gives the shapes whose bounding boxes meet that
    box, in the order they were added, looking only at the grid cells it
    covers: placing one label costs what lies near it, not everything drawn,
    so a drawing with n labels is placed in about O(n) rather than O(n²).
    Shapes appended directly are indexed on the next query.
    """

    CELL_MM = 12.0
    #: a shape covering more cells than this (a guide drawn over a long stroke) is kept out of the grid
    WIDE_CELLS = 4096

    def __init__(self, *args):
        super().__init__(*args)
        self._cells: dict[tuple[int, int], list[int]] = {}
        self._bounds: list[tuple[float, float, float, float]] = []
        self._wide: list[int] = []
        self._indexed = 0

    def _index(self) -> None:
        c = self.CELL_MM
        for k in range(self._indexed, len(self)):
            x0, y0, x1, y1 = self[k].bounds
            self._bounds.append((x0, y0, x1, y1))
            if not all(map(math.isfinite, (x0, y0, x1, y1))):
                continue  # an empty shape has no bounds and is near nothing
            if (x1 - x0) * (y1 - y0) > self.WIDE_CELLS * c * c or max(x1 - x0, y1 - y0) > self.WIDE_CELLS * c:
                self._wide.append(k)  # a shape over very many cells is looked at by its bounds on every query
                continue
            for i in range(math.floor(x0 / c), math.floor(x1 / c) + 1):
                for j in range(math.floor(y0 / c), math.floor(y1 / c) + 1):
                    self._cells.setdefault((i, j), []).append(k)
        self._indexed = len(self)

    def near(self, x0: float, y0: float, x1: float, y1: float) -> list:
        """Shapes whose bounding box meets the box (x0, y0)–(x1, y1) [mm], in drawing order."""
        self._index()
        c = self.CELL_MM
        found: set[int] = set(self._wide)
        for i in range(math.floor(x0 / c), math.floor(x1 / c) + 1):
            for j in range(math.floor(y0 / c), math.floor(y1 / c) + 1):
                found.update(self._cells.get((i, j), ()))
        out = []
        for k in sorted(found):
            bx0, by0, bx1, by1 = self._bounds[k]
            if bx0 <= x1 and bx1 >= x0 and by0 <= y1 and by1 >= y0:
                out.append(self[k])
        return out


_GID_CHARS = re.compile(r"[^A-Za-z0-9_.-]+")


class Sketch:
    """Artists drawn in millimetres on *ax*, with bounds, gids and obstacles.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    prefix : str
        Prepended to every gid (``"mech"``, ``"vel"``, ``"acc"``).
    """

    def __init__(self, ax, prefix: str):
        self.ax = ax
        self.prefix = prefix
        self.artists: list = []
        self.bounds = Bounds()
        self.obstacles = Obstacles()  # shapely geometries, for label placement
        self._gids: dict[str, int] = {}
        self._clip = None

    # -- bookkeeping ---------------------------------------------------------

    def checkpoint(self) -> tuple:
        """What has been drawn so far, for :meth:`restore` (a placement tried and then undone)."""
        b = self.bounds
        return len(self.artists), len(self.obstacles), (b.xmin, b.ymin, b.xmax, b.ymax), dict(self._gids)

    def restore(self, state: tuple) -> None:
        """Undo everything drawn since :meth:`checkpoint` gave *state* (artists, obstacles, bounds and gids)."""
        artists, obstacles, (x0, y0, x1, y1), gids = state
        for artist in self.artists[artists:]:
            artist.remove()
        del self.artists[artists:]
        self.obstacles = Obstacles(self.obstacles[:obstacles])
        self.bounds.xmin, self.bounds.ymin, self.bounds.xmax, self.bounds.ymax = x0, y0, x1, y1
        self._gids = dict(gids)

    def gid(self, name: str) -> str:
        base = _GID_CHARS.sub("_", f"{self.prefix}-{name}").strip("_")
        count = self._gids.get(base, 0) + 1
        self._gids[base] = count
        return base if count == 1 else f"{base}-{count}"

    def _add(self, artist, gid: str | None):
        if gid is not None:
            artist.set_gid(self.gid(gid))
        artist.set_clip_on(False)
        # add_artist, not add_line/add_patch: those grow the data limits, a third of the cost of
        # drawing a sketch, and every sketch sets its limits from its own bounds
        self._unclipped(artist)
        self.ax.add_artist(artist)
        self.artists.append(artist)
        return artist

    def _unclipped(self, artist) -> None:
        """Give *artist* the axes' clip path, made once per sketch (not clipped: clip_on is False).

        Adding an artist without a clip path makes matplotlib derive one from
        the axes' patch, which cost as much as drawing the artist.
        """
        if self._clip is None:
            self._clip = TransformedPatchPath(self.ax.patch)
        artist.set_clip_path(self._clip)

    # -- primitives ----------------------------------------------------------

    def line(self, points, *, color=INK, lw=1.0, dashes=None, gid=None, zorder=2.0, obstacle=True, bound=True, capstyle="butt"):
        xs = [p.real for p in points]
        ys = [p.imag for p in points]
        artist = Line2D(xs, ys, color=color, linewidth=lw, zorder=zorder, solid_capstyle=capstyle, solid_joinstyle="round")
        if dashes:
            artist.set_dashes(dashes)
        if bound:
            for p in points:
                self.bounds.add(p.real, p.imag)
        if obstacle and len(points) >= 2:
            self.obstacles.append(LineString([(p.real, p.imag) for p in points]).buffer(lw * MM_PER_PT / 2))
        return self._add(artist, gid)

    def polygon(self, points, *, fc="none", ec=INK, lw=0.8, gid=None, zorder=2.0, obstacle=True, joinstyle="miter"):
        xy = [(p.real, p.imag) for p in points]
        artist = Polygon(xy, closed=True, facecolor=fc, edgecolor=ec, linewidth=lw, zorder=zorder, joinstyle=joinstyle)
        for x, y in xy:
            self.bounds.add(x, y)
        if obstacle:
            self.obstacles.append(ShapelyPolygon(xy).buffer(lw * MM_PER_PT / 2))
        return self._add(artist, gid)

    def circle(self, center: complex, radius: float, *, fc="white", ec=INK, lw=0.8, gid=None, zorder=4.0, obstacle=True):
        artist = Circle((center.real, center.imag), radius, facecolor=fc, edgecolor=ec, linewidth=lw, zorder=zorder)
        self.bounds.add_box(center.real - radius, center.imag - radius, center.real + radius, center.imag + radius)
        if obstacle:
            self.obstacles.append(Point(center.real, center.imag).buffer(radius))
        return self._add(artist, gid)

    def segments(self, pairs, *, color=INK, lw=0.5, gid=None, zorder=1.5, obstacle=True):
        segs = [[(a.real, a.imag), (b.real, b.imag)] for a, b in pairs]
        artist = LineCollection(segs, colors=color, linewidths=lw, zorder=zorder, capstyle="butt")
        for a, b in pairs:
            self.bounds.add(a.real, a.imag)
            self.bounds.add(b.real, b.imag)
            if obstacle:
                self.obstacles.append(LineString([(a.real, a.imag), (b.real, b.imag)]))
        return self._add(artist, gid)

    def arrow(self, tail: complex, tip: complex, *, color=INK, lw=1.0, dashes=None, head=3.0, gid=None, zorder=3.0, hollow=False):
        """A shaft from *tail* towards *tip* and a filled head whose point is exactly *tip* (*hollow*: an open head,
        white inside and outlined, a little wider, that tells the arrow from a filled one in black-and-white print).

        Returns ``[shaft, head]``; ``head.get_xy()[0]`` is the tip.
        """
        d = tip - tail
        length = abs(d)
        u = unit(d)
        head = min(head, 0.45 * length)
        # slender (ARROW_RATIO : 1), but never narrower than the shaft it ends
        half = max(head / ARROW_RATIO / 2, lw * MM_PER_PT * 0.8)
        if hollow:  # wide enough that its white inside reads
            half = max(half, head / HOLLOW_RATIO / 2)
        base = tip - u * head
        # the shaft stops inside the head, so its square end never shows past the point (at an open head's base:
        # nothing of it inside)
        shaft_end = tip - u * head * (1.0 if hollow else 0.6)
        name = gid or "arrow"
        shaft = self.line([tail, shaft_end], color=color, lw=lw, dashes=dashes, gid=name, zorder=zorder, obstacle=False)
        self.obstacles.append(LineString([(tail.real, tail.imag), (tip.real, tip.imag)]).buffer(lw * MM_PER_PT / 2))
        n = u * 1j
        head_artist = self.polygon(
            [tip, base + n * half, base - n * half], fc="white" if hollow else color, ec=color, lw=max(0.6, lw * 0.6) if hollow else 0.3,
            gid=f"{name}-head", zorder=zorder + 0.1
        )
        return [shaft, head_artist]

    def arc_arrow(self, center: complex, radius: float, start: float, sweep: float, *, color=INK, lw=0.9, dashes=None, head=2.6, gid=None, zorder=3.5):
        """A circular arc from angle *start* turning by *sweep* [rad] (sign = sense), head at its end."""
        n = max(8, int(abs(sweep) / math.radians(4)))
        head_angle = min(abs(sweep) * 0.4, head / radius) * (1 if sweep > 0 else -1)
        end = start + sweep
        pts = [center + radius * cmath.exp(1j * (start + (sweep - head_angle * 0.6) * k / n)) for k in range(n + 1)]
        name = gid or "arc"
        shaft = self.line(pts, color=color, lw=lw, dashes=dashes, gid=name, zorder=zorder)
        tip = center + radius * cmath.exp(1j * end)
        tangent = 1j * cmath.exp(1j * end) * (1 if sweep > 0 else -1)
        back = center + radius * cmath.exp(1j * (end - head_angle))
        # the head follows the chord of its own length, so it sits on the arc
        u = unit(tip - back)
        if abs(u) == 0:
            u = tangent
        half = max(head / ARROW_RATIO / 2, lw * MM_PER_PT * 0.8)
        base = tip - u * head
        head_artist = self.polygon([tip, base + u * 1j * half, base - u * 1j * half], fc=color, ec=color, lw=0.3, gid=f"{name}-head", zorder=zorder + 0.1)
        return [shaft, head_artist]

    def text(self, at: complex, s: str, *, size=10.0, ha="center", va="center", color=INK, weight="normal", style="normal", gid=None, zorder=6.0, math=False, obstacle=True):
        """Text whose box (estimated from the font) joins the bounds and the obstacles."""
        w, h = text_size(s, size, weight, math)
        x0 = {"left": at.real, "center": at.real - w / 2, "right": at.real - w}[ha]
        top = {"top": at.imag, "center": at.imag + h / 2, "bottom": at.imag + h, "baseline": at.imag + h * 0.78}[va]
        self.bounds.add_box(x0, top - h, x0 + w, top)
        if obstacle:
            self.obstacles.append(box(x0, top - h, x0 + w, top))
        artist = Text(
            at.real, at.imag, s, fontsize=size, ha=ha, va=va, color=color, fontweight=weight,
            fontstyle=style, zorder=zorder, family=FONT_FAMILY, transform=self.ax.transData, clip_on=False,
        )
        self._unclipped(artist)
        self.ax.add_artist(artist)
        if gid is not None:
            artist.set_gid(self.gid(gid))
        self.artists.append(artist)
        return artist


def fit_axes(ax, bounds: Bounds, margin: float, rect_mm: tuple[float, float] | None = None, page_mm: tuple[float, float] | None = None) -> tuple[float, float]:
    """Make one data unit one millimetre: limits = bounds ± margin, axes box of the same size.

    With *rect_mm* (lower-left corner on a page of *page_mm*), the axes is put
    there; otherwise the figure is resized to the drawing.  Returns the
    drawing's size [mm].
    """
    if bounds.empty:
        bounds.add(0.0, 0.0)
    width = bounds.width + 2 * margin
    height = bounds.height + 2 * margin
    fig = ax.figure
    if rect_mm is None:
        fig.set_size_inches(width / 25.4, height / 25.4)
        ax.set_position([0.0, 0.0, 1.0, 1.0])
    else:
        pw, ph = page_mm
        ax.set_position([rect_mm[0] / pw, rect_mm[1] / ph, width / pw, height / ph])
    ax.set_xlim(bounds.xmin - margin, bounds.xmax + margin)
    ax.set_ylim(bounds.ymin - margin, bounds.ymax + margin)
    ax.set_aspect("auto")
    ax.set_axis_off()
    return width, height


def sketch_on(ax, tag: str, draw) -> list:
    """Run ``draw(sketch)`` on *ax*, or on a new true-scale figure when *ax* is None.

    A new figure is sized to the drawing (1 data unit = 1 mm of paper); a
    caller's axes get limits with a margin, equal aspect and no axis lines.

    Returns
    -------
    list of matplotlib.artist.Artist
        Everything drawn; a new figure is ``artists[0].figure``.
    """
    from .svg import drawing_rc, new_figure

    with drawing_rc():
        own = ax is None
        if own:
            ax = new_figure().add_axes([0, 0, 1, 1])
        sketch = Sketch(ax, tag)
        draw(sketch)
        if own:
            fit_axes(ax, sketch.bounds, MARGIN_MM)
        else:
            b = sketch.bounds
            ax.set_xlim(b.xmin - MARGIN_MM, b.xmax + MARGIN_MM)
            ax.set_ylim(b.ymin - MARGIN_MM, b.ymax + MARGIN_MM)
            ax.set_aspect("equal")
            ax.set_axis_off()
    return sketch.artists
