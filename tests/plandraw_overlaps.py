"""Overlaps of rendered labels, measured with matplotlib's own renderer.

A label's extent is ``text.get_window_extent(renderer, dpi=DPI)`` (the box the glyphs
are laid out in, as drawn); an arrowhead is its polygon in display
coordinates.  Two extents that share more than a sliver of area overlap.
"""

from __future__ import annotations

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.patches import Polygon

from plans.drawing.svg import drawing_rc
from shapely.geometry import LineString, box
from shapely.geometry import Polygon as ShapelyPolygon

from plans.graphical.plan import KINDS

__all__ = ["label_boxes", "texts_in", "measured", "arrowheads", "shafts", "overlaps"]

#: Resolution the extents are measured at: high, so that the renderer's
#: rounding to whole pixels does not change them by more than a hair.
DPI = 720.0
#: Shared area [mm²] below which two extents only touch.
SLIVER_MM2 = 0.05
_MM_PER_PX = 25.4 / DPI


def measured(fig, measure):
    """Run ``measure(renderer, mm_per_px)`` with *fig* rendered at :data:`DPI` by Agg."""
    old_dpi, old_canvas = fig.dpi, fig.canvas
    try:
        fig.set_dpi(DPI)
        canvas = FigureCanvasAgg(fig)
        with drawing_rc():
            return measure(canvas.get_renderer(), 25.4 / DPI)
    finally:
        fig.set_dpi(old_dpi)
        fig.set_canvas(old_canvas)


def texts_in(ax, renderer, k: float) -> list[tuple[str, object]]:
    """(gid:text, box [mm]) of every non-empty text of *ax*, measured by *renderer* (*k*: mm per pixel)."""
    out = []
    for t in ax.texts:
        s = t.get_text()
        if not s.strip() or s.strip() == ",":
            continue
        e = t.get_window_extent(renderer)
        out.append((f"{t.get_gid()}:{s}", box(e.x0 * k, e.y0 * k, e.x1 * k, e.y1 * k)))
    return out


def label_boxes(fig) -> list[tuple[str, object]]:
    """(gid:text, box [mm from the figure's corner]) of every non-empty text drawn in *fig*."""
    return measured(fig, lambda renderer, k: [b for ax in fig.axes for b in texts_in(ax, renderer, k)])


def arrowheads(fig) -> list[tuple[str, object]]:
    """(gid, polygon [mm from the figure's corner]) of every arrowhead but the legend's."""

    def measure(renderer, k):
        out = []
        for ax in fig.axes:
            for p in ax.patches:
                gid = p.get_gid() or ""
                if isinstance(p, Polygon) and gid.endswith("-head") and "legend" not in gid:
                    xy = p.get_transform().transform(p.get_xy()) * k
                    out.append((gid, ShapelyPolygon(xy).buffer(0)))
        return out

    return measured(fig, measure)


def shafts(fig) -> list[tuple[str, object]]:
    """(gid, outline [mm]) of every vector shaft and link image on a plan (Line2D with a plan gid)."""

    def measure(renderer, k):
        out = []
        for ax in fig.axes:
            for line in ax.lines:
                gid = line.get_gid() or ""
                if "legend" in gid or not any(f"-{kind}-" in gid for kind in KINDS):
                    continue
                xy = ax.transData.transform(list(zip(*line.get_data()))) * k
                out.append((gid, LineString(xy).buffer(line.get_linewidth() * 25.4 / 72 / 2)))
        return out

    return measured(fig, measure)


def overlaps(fig) -> list[str]:
    """Every pair (label, label) and (label, arrowhead) that overlaps, as text."""
    labels = label_boxes(fig)
    heads = arrowheads(fig)
    found = []
    for i, (a, ba) in enumerate(labels):
        for b, bb in labels[i + 1:]:
            if ba.intersection(bb).area > SLIVER_MM2:
                found.append(f"label {a!r} overlaps label {b!r}")
        for h, bh in heads:
            if ba.intersection(bh).area > SLIVER_MM2:
                found.append(f"label {a!r} overlaps arrowhead {h!r}")
    return found
