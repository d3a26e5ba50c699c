"""Label placement by geometry.

A label is tried at candidate positions around its anchor: a few rings of
increasing gap, sixteen directions each.  Its text box (measured from the
font, see :func:`plans.drawing._canvas.text_size`) is scored by its
clearance from everything already drawn (vectors, bars, pins, other labels,
as shapely geometries) against its distance from the anchor: up to
``CLEAR_MM`` of clearance is worth four times its length in distance, an
overlap costs as much as 3 mm of distance, and the preferred direction breaks
ties.  A label therefore moves a few millimetres to get clear, but not so far
that it could be read as another point's.  The best box becomes
an obstacle for the labels placed after it, so labels never sit on each other
when there is room for them.  The scoring is a pure function of the
geometry, so placement is deterministic.
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import shapely
from shapely.geometry import box

from ._canvas import Sketch, text_size

__all__ = ["CLEAR_MM", "LABEL_SPACE_MM", "place_label"]

#: Clearance [mm] a label should keep from every other mark.
CLEAR_MM = 0.8
#: Extra space [mm] kept around a placed label.
LABEL_SPACE_MM = 0.9
_SEPARATOR = ", "


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

    Returns
    -------
    list of matplotlib.text.Text
    """
    texts = [t for t, _ in pieces]
    full = _SEPARATOR.join(texts)
    w, h = text_size(full, size, weight, mathtext)
    obstacles = np.array(sketch.obstacles, dtype=object) if sketch.obstacles else None

    def clearance(center: complex) -> float:
        if obstacles is None:
            return math.inf
        candidate = box(center.real - w / 2, center.imag - h / 2, center.real + w / 2, center.imag + h / 2)
        return float(shapely.distance(candidate, obstacles).min())

    best = None
    order = 0
    candidates: list[tuple[complex, float, float]] = [(c, 0.0, 0.0) for c in first]
    base_angle = cmath.phase(prefer) if prefer else math.radians(45)
    for gap in gaps:
        for k in range(16):
            theta = base_angle + 2 * math.pi * k / 16
            u = cmath.exp(1j * theta)
            reach = gap + abs(u.real) * w / 2 + abs(u.imag) * h / 2
            turn = 1 - math.cos(theta - base_angle)
            candidates.append((anchor + u * reach, gap, turn))
    for center, gap, turn in candidates:
        c = clearance(center)
        score = 4.0 * min(c, CLEAR_MM) - (3.0 if c <= 0.0 else 0.0) - gap - 0.15 * turn - 1e-6 * order
        order += 1
        if best is None or score > best[0]:
            best = (score, center)
    center = best[1]

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
