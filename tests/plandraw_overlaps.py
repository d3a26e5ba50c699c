"""Overlaps of rendered labels, measured with matplotlib's own renderer.

A label's extent is ``text.get_window_extent(renderer, dpi=DPI)`` (the box the glyphs
are laid out in, as drawn); an arrowhead is its polygon in display
coordinates.  Two extents that share more than a sliver of area overlap.
"""

from __future__ import annotations

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.patches import Polygon

from plans.drawing.svg import drawing_rc
from shapely.geometry import Polygon as ShapelyPolygon
from shapely.geometry import box

__all__ = ["label_boxes", "arrowheads", "overlaps"]

#: Resolution the extents are measured at: high, so that the renderer's
#: rounding to whole pixels does not change them by more than a hair.
DPI = 720.0
#: Shared area [mm²] below which two extents only touch.
SLIVER_MM2 = 0.05
_MM_PER_PX = 25.4 / DPI


def label_boxes(fig) -> list[tuple[str, object]]:
    """(text, shapely box in display units) of every non-empty text drawn in *fig*."""
    if not hasattr(fig.canvas, "get_renderer"):
        FigureCanvasAgg(fig)
    out = []
    with drawing_rc():
        renderer = fig.canvas.get_renderer()
        for ax in fig.axes:
            for t in ax.texts:
                s = t.get_text()
                if not s.strip() or s.strip() == ",":
                    continue
                e = t.get_window_extent(renderer, dpi=DPI)
                k = _MM_PER_PX
                out.append((f"{t.get_gid()}:{s}", box(e.x0 * k, e.y0 * k, e.x1 * k, e.y1 * k)))
    return out


def arrowheads(fig) -> list[tuple[str, object]]:
    out = []
    for ax in fig.axes:
        for p in ax.patches:
            gid = p.get_gid() or ""
            if isinstance(p, Polygon) and gid.endswith("-head") and "legend" not in gid:
                xy = p.get_transform().transform(p.get_xy()) * (25.4 / fig.dpi)
                out.append((gid, ShapelyPolygon(xy).buffer(0)))
    return out


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
