"""The plan of positions: the mechanism in every position of a run, superimposed, with the paths of its points.

Position 0 is drawn in full (the kinematic scheme of :mod:`plans.drawing.mechanism`);
the others in thin grey lines, their joints as small circles.  The path of
every reported point over the driver's cycle (a coupler curve) is drawn from
the run's analytic sweep, broken where the mechanism cannot assemble.  The
positions are numbered 0, 1, 2, … beside the driver's moving point and beside
the last reported point, as the course numbers them.

Gids: ``pos-link-<k>-<body>``, ``pos-path-<point>``, ``pos-number-<k>``,
and the ``mech-…`` gids of the scheme of position 0 (prefix ``pos``).
"""

from __future__ import annotations


import numpy as np

from .._text import SUBSCRIPT
from ..i18n import term
from ._canvas import Sketch, fmt_number, sketch_on, unit
from .labels import place_label
from .mechanism import FRAME, MechanismDrawing
from .style import CAPTION_PT, HEADING_PT, SMALL_PT

__all__ = ["draw_positions_plan", "draw_positions_into", "numbered_points"]

GHOST = "#8c8c8c"
PATH_COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9")
GHOST_PT = 0.8
PATH_PT = 0.9


def numbered_points(scene) -> list[str]:
    """The points the positions are numbered at: the driver's moving point, and the last reported point."""
    driver = scene.driver
    body = scene.bodies[driver.link]
    if hasattr(driver, "pivot"):
        moving = [n for n in body.points if n != driver.pivot and len(scene.bodies_with(n)) > 1]
        moving = moving or [n for n in body.points if n != driver.pivot]
    else:
        moving = [driver.point]
    out = moving[:1]
    frame = scene.bodies[FRAME].points
    tail = [p for p in scene.report if p not in frame]
    if tail and tail[-1] not in out:
        out.append(tail[-1])
    return out


def _segments(values: np.ndarray) -> list[np.ndarray]:
    """Runs of finite complex values."""
    ok = np.isfinite(values.real) & np.isfinite(values.imag)
    runs, start = [], None
    for k, good in enumerate(ok):
        if good and start is None:
            start = k
        if not good and start is not None:
            runs.append(values[start:k])
            start = None
    if start is not None:
        runs.append(values[start:])
    return [r for r in runs if len(r) >= 2]


def draw_positions_into(sketch: Sketch, positions_run, *, lang: str = "en", k_l: float | None = None) -> None:
    """Draw the plan of positions into a sketch (one data unit = 1 mm)."""
    runs = [r for r in positions_run.runs if r.ok]
    if not runs:
        raise ValueError("no position of the run could be solved: there is nothing to draw")
    scene = positions_run.scene
    k_l = float(k_l if k_l is not None else runs[0].graphical.scales["k_l"])
    first = runs[0]
    base = first.graphical
    if k_l != base.scales["k_l"]:
        base = _rescaled(base, k_l)

    # paths first (under everything)
    cycle = positions_run.cycle
    frame = scene.bodies[FRAME].points
    moving = [p for p in scene.report if p not in frame and p in cycle.points]
    for n, name in enumerate(moving):
        colour = PATH_COLOURS[n % len(PATH_COLOURS)]
        for seg in _segments(np.asarray(cycle.points[name].r) / k_l):
            pts = [complex(z) for z in seg]
            sketch.line(pts, color=colour, lw=PATH_PT, dashes=(4.0, 1.5), gid=f"path-{name}", zorder=1.0, obstacle=False)

    # the other positions, thin
    for run in runs[1:]:
        g = run.graphical
        for body_name, body in scene.bodies.items():
            if body_name == FRAME:
                continue
            pts = [complex(g.positions[p]) / k_l for p in body.points if p in g.positions]
            if len(pts) < 2:
                continue
            if len(pts) == 2:
                sketch.line(pts, color=GHOST, lw=GHOST_PT, gid=f"link-{run.index}-{body_name}", zorder=1.2, obstacle=False)
            else:
                ring = _hull(pts)
                sketch.line(ring + ring[:1], color=GHOST, lw=GHOST_PT, gid=f"link-{run.index}-{body_name}", zorder=1.2, obstacle=False)
        for p, z in g.positions.items():
            if p in frame or len(scene.bodies_with(p)) < 2:
                continue
            sketch.circle(complex(z) / k_l, 0.55, fc="white", ec=GHOST, lw=0.5, gid=f"joint-{run.index}-{p}", zorder=1.4, obstacle=False)

    # position 0 in full
    mech = MechanismDrawing(sketch, base, lang=lang, caption=False)
    mech.draw()

    # numbers beside the numbered points of every position
    for run in runs:
        g = run.graphical
        for p in numbered_points(scene):
            if p not in g.positions:
                continue
            at = complex(g.positions[p]) / k_l
            centre = complex(np.nanmean(np.asarray(cycle.points[p].r))) / k_l if p in cycle.points else mech.centroid
            sketch.circle(at, 0.45, fc="#000000", lw=0, gid=f"mark-{run.index}-{p}", zorder=4.5, obstacle=True)
            away = unit(at - centre) if abs(at - centre) > 1e-9 else None
            place_label(sketch, at, [(f"{p}{_sub(run.index)}", f"number-{run.index}")], size=SMALL_PT + 0.5, prefer=away, gaps=(0.6, 1.2, 2.2, 3.5, 5.0, 7.0))

    # caption
    b = sketch.bounds
    x, y = b.xmin, b.ymin - 2.5
    sketch.text(complex(x, y), term("positions_plan", lang), size=HEADING_PT, ha="left", va="top", weight="bold", gid="heading", obstacle=False)
    y -= 5.0
    sketch.text(complex(x, y), f"k_l = {fmt_number(k_l)} m/mm", size=CAPTION_PT, ha="left", va="top", gid="scale", obstacle=False)
    y -= 5.0
    for n, name in enumerate(moving):
        colour = PATH_COLOURS[n % len(PATH_COLOURS)]
        xx = x + (n % 6) * 24.0
        yy = y - (n // 6) * 4.5
        sketch.line([complex(xx, yy - 1.4), complex(xx + 8.0, yy - 1.4)], color=colour, lw=PATH_PT, dashes=(4.0, 1.5), gid=f"legend-path-{name}", obstacle=False)
        sketch.text(complex(xx + 9.5, yy - 1.4), name, size=CAPTION_PT, ha="left", va="center", gid="legend-path", obstacle=False)


def _sub(k: int) -> str:
    return str(k).translate(SUBSCRIPT)


def _hull(pts: list[complex]) -> list[complex]:
    from shapely.geometry import MultiPoint

    hull = MultiPoint([(z.real, z.imag) for z in pts]).convex_hull
    if hull.geom_type != "Polygon":
        a, c = max(((q, r) for q in pts for r in pts), key=lambda qr: abs(qr[0] - qr[1]))
        return [a, c]
    return [complex(x, y) for x, y in list(hull.exterior.coords)[:-1]]


def _rescaled(graphical, k_l: float):
    """The same solution with another k_l (the mechanism drawing reads only k_l, poses and positions)."""
    import dataclasses

    return dataclasses.replace(graphical, scales={**graphical.scales, "k_l": k_l})


def draw_positions_plan(positions_run, ax=None, *, lang: str = "en", k_l: float | None = None) -> list:
    """Draw the plan of positions of a multi-position run.

    Parameters
    ----------
    positions_run : plans.positions.PositionsRun
    ax : matplotlib.axes.Axes, optional
        Drawn into (one data unit = 1 mm); a new figure true to scale when omitted.
    lang : str
    k_l : float, optional
        Another length scale than the run's.

    Returns
    -------
    list of matplotlib.artist.Artist
    """
    return sketch_on(ax, "pos", lambda sketch: draw_positions_into(sketch, positions_run, lang=lang, k_l=k_l))
