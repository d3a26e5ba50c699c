"""The plan of positions: the mechanism in every position of a run, superimposed, with the paths of its points.

Position 0 is drawn in full (the kinematic scheme of :mod:`plans.drawing.mechanism`);
the others in thin grey lines, their joints as small circles.  The path of
every reported point over the driver's cycle (a coupler curve) is drawn from
the run's analytic sweep, broken where the mechanism cannot assemble.  The
positions are numbered 0, 1, 2, … at the driver's moving point and at every
moving reported point, as the course numbers them, where a number has room:
beside its mark, else at the end of a short leader line, else not at all
(no number is ever drawn over another mark or label).  Paths are drawn only
where the mechanism assembles, and the caption names the positions that are
not drawn and why.

Gids: ``pos-link-<k>-<body>``, ``pos-path-<point>``, ``pos-position-<k>-<point>`` (a number; ``…-leader`` its leader line), ``pos-mark-<k>-<point>``,
and the ``mech-…`` gids of the scheme of position 0 (prefix ``pos``).
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import shapely
from shapely.geometry import LineString, box

from .._text import SUPERSCRIPT
from ..i18n import term
from ..sweep import line_travel
from ._canvas import Sketch, fmt_number, sketch_on, text_size, unit
from .labels import LABEL_SPACE_MM
from .mechanism import FRAME, MechanismDrawing, mechanism_labels
from .numerals import localised
from .style import CAPTION_PT, HEADING_PT, SMALL_PT

__all__ = ["draw_positions_plan", "draw_positions_into", "numbered_points", "place_number", "number_ranges"]

GHOST = "#8c8c8c"
PATH_COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9")
GHOST_PT = 0.8
PATH_PT = 0.9
#: Radius [mm] of the mark at a numbered point of a position.
MARK_R = 0.45
#: Size [pt] of a position number.
NUMBER_PT = SMALL_PT + 0.5
#: Clearance [mm] a position number keeps from every other mark and label.
NUMBER_CLEAR_MM = 0.25
#: Gaps [mm] between mark and number tried beside the mark, then at the end of a leader line.
NEAR_GAPS = (0.5, 1.1, 1.8)
LEADER_GAPS = (3.5, 5.0, 7.0, 9.5)
LEADER_PT = 0.35
#: Marks closer than this [mm] are all but one (a number beside one is beside the other): no rival to each other.
SAME_MARK_MM = 1.0
#: How many directions round its mark a number tries at each gap.
DIRECTIONS = 32
#: The most of a leader line that may run inside what its mark sits in (a pin, a block), as a fraction of its length.
LEADER_INSIDE = 0.6
#: A line or pin within this [mm] of a mark's edge is what the mark sits on: its leader may cross it.
OWN_MM = 0.6
#: Lines thinner than this [mm] (a guide at 1.1 pt) may be crossed by a leader; a mark (0.45 mm) may not ...
THIN_MM = 0.42
#: ... and longer than this [mm] (a driver's arrow, 0.9 pt, is shorter).
LONG_MM = 30.0


def numbered_points(scene) -> list[str]:
    """The points the positions are numbered at: the driver's moving point, then every moving reported point."""
    driver = scene.driver
    body = scene.bodies[driver.link]
    if hasattr(driver, "pivot"):
        moving = [n for n in body.points if n != driver.pivot and len(scene.bodies_with(n)) > 1]
        moving = moving or [n for n in body.points if n != driver.pivot]
    else:
        moving = [driver.point]
    out = moving[:1]
    frame = scene.bodies[FRAME].points
    out += [p for p in scene.report if p not in frame and p not in out]
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


def draw_positions_into(sketch: Sketch, positions_run, *, lang: str = "en", k_l: float | None = None, law: bool = False,
                        heading: bool = True, extremes: dict | None = None) -> None:
    """Draw the plan of positions into a sketch (one data unit = 1 mm); *heading* False leaves out the heading and
    k_l (a page that states them), keeping the legend of the paths; *law* states the driver's law under it;
    *extremes* (label -> GraphicalSolution, ``{"0′": …}``) adds the output's other extreme position, dash-dotted,
    its points numbered with the label (``E⁰′``)."""
    runs = [r for r in positions_run.runs if r.ok]
    if not runs:
        raise ValueError("no position of the run could be solved: there is nothing to draw")
    scene = positions_run.scene
    k_l = float(k_l if k_l is not None else runs[0].graphical.scales["k_l"])
    first = runs[0]
    base = first.graphical
    if k_l != base.scales["k_l"]:
        base = _rescaled(base, k_l)

    # paths first (under everything), only where the mechanism assembles
    cycle = positions_run.cycle
    assembled = np.asarray(cycle.valid, dtype=bool)
    frame = scene.bodies[FRAME].points
    moving = [p for p in scene.report if p not in frame and p in cycle.points]
    for n, name in enumerate(moving):
        colour = PATH_COLOURS[n % len(PATH_COLOURS)]
        track = np.where(assembled, np.asarray(cycle.points[name].r), np.nan + 0j)
        for seg in _segments(track / k_l):
            pts = [complex(z) for z in seg]
            # over the blocks and slots of the scheme (a point's path runs through its block), under pins and labels
            sketch.line(pts, color=colour, lw=PATH_PT, dashes=(4.0, 1.5), gid=f"path-{name}", zorder=3.1, obstacle=False)

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

    # the output's other extreme position (0′), dash-dotted over the thin ones
    for label, g in (extremes or {}).items():
        for body_name, body in scene.bodies.items():
            if body_name == FRAME:
                continue
            pts = [complex(g.positions[p]) / k_l for p in body.points if p in g.positions]
            if len(pts) >= 2:
                ring = pts if len(pts) == 2 else _hull(pts) + _hull(pts)[:1]
                sketch.line(ring, color="#000000", lw=GHOST_PT, dashes=(5.0, 1.2, 1.0, 1.2), gid=f"link-extreme-{body_name}", zorder=1.3, obstacle=False)

    # a mark at every numbered point of every position, all of them obstacles before any label is placed
    numbered = numbered_points(scene)
    marks = []
    for run in runs:
        for p in numbered:
            if p in run.graphical.positions:
                at = complex(run.graphical.positions[p]) / k_l
                sketch.circle(at, MARK_R, fc="#000000", lw=0, gid=f"mark-{run.index}-{p}", zorder=4.5, obstacle=True)
                marks.append((run.index, p, at))

    # position 0 in full (its labels keep clear of the marks)
    mech = MechanismDrawing(sketch, base, lang=lang, caption=False, slots=line_travel(cycle))  # guides over the stroke
    mech.draw()

    # numbers where they have room: beside the mark, else on a short leader line, else left out;
    # position 0 of every point first, then the others in order
    centres = {p: (complex(np.nanmean(np.asarray(cycle.points[p].r)[assembled])) / k_l if p in cycle.points and assembled.any() else mech.centroid) for p in numbered}
    labelled = set(mechanism_labels(base))
    # (a number nearer its own mark than any other: a reader takes a number for the nearest point's)
    extreme_marks = [(label, p, complex(g.positions[p]) / k_l) for label, g in (extremes or {}).items() for p in numbered if p in g.positions]
    every = np.array([at for _, _, at in marks] + [at for _, _, at in extreme_marks], dtype=complex)
    left_out = []
    for index, p, at in sorted(marks, key=lambda m: (m[0] != runs[0].index, m[0], numbered.index(m[1]))):
        if index == runs[0].index and p in labelled:
            continue  # position 0 is the one drawn in full: its points are labelled once, by the scheme
        away = unit(at - centres[p]) if abs(at - centres[p]) > 1e-9 else None
        # position 0 (the scheme drawn in full) numbered first, wherever it has room; the others nearest their marks
        rivals = None if index == runs[0].index else every
        if place_number(sketch, at, f"{p}{_sub(index)}", gid=f"position-{index}-{p}", size=NUMBER_PT, prefer=away, rivals=rivals) is None:
            left_out.append(f"{p}{_sub(index)}")
    for label, p, at in extreme_marks:
        sketch.circle(at, MARK_R, fc="#000000", lw=0, gid=f"mark-extreme-{p}", zorder=4.5, obstacle=True)
        away = unit(at - centres[p]) if abs(at - centres[p]) > 1e-9 else None
        if place_number(sketch, at, f"{p}{label.translate(SUPERSCRIPT)}", gid=f"position-extreme-{p}", size=NUMBER_PT, prefer=away, rivals=every) is None:
            left_out.append(f"{p}{label.translate(SUPERSCRIPT)}")

    # caption
    b = sketch.bounds
    x, y = b.xmin, b.ymin - 2.5
    if heading:
        sketch.text(complex(x, y), term("positions_plan", lang), size=HEADING_PT, ha="left", va="top", weight="bold", gid="heading", obstacle=False)
        y -= 5.0
        sketch.text(complex(x, y), f"$k_l$ = {localised(fmt_number(k_l), lang)} m/mm", size=CAPTION_PT, ha="left", va="top", gid="scale", obstacle=False, math=True)
    else:
        y += 5.0
    motion = getattr(positions_run, "motion", None)
    if law and motion is not None:  # the driver's law over the cycle (the handout's cover states it in its header)
        import textwrap

        for n, line in enumerate(textwrap.wrap(motion.law.describe(lang, positions_run.scene.driver.link), 100, subsequent_indent="    ")):
            y -= 4.5
            sketch.text(complex(x, y), line, size=CAPTION_PT, ha="left", va="top",
                        gid=f"law-{n}", obstacle=False)
    skipped = positions_run.skipped
    if skipped:
        for cause in ("no_assembly", "dead_centre"):
            numbers = [r.index for r in skipped if r.cause == cause]
            if numbers:
                y -= 4.5
                sketch.text(
                    complex(x, y), f"{term('not_drawn', lang)} ({term(cause, lang)}): {number_ranges(numbers)}",
                    size=CAPTION_PT, ha="left", va="top", gid=f"skipped-{cause}", obstacle=False,
                )
    if left_out:  # the marks whose number found no room of its own, said (never silently left out)
        words, lines = f"{term('not_numbered', lang)}:", []
        for item in left_out:  # lines as wide as the drawing (a caption never widens it)
            if text_size(f"{words} {item},", CAPTION_PT)[0] > max(b.width, 60.0) and words.strip():
                lines.append(words)
                words = "    "
            words += f" {item},"
        lines.append(words.rstrip(","))
        for n, line in enumerate(lines):
            y -= 4.5
            sketch.text(complex(x, y), line, size=CAPTION_PT, ha="left", va="top", gid=f"unnumbered-{n}", obstacle=False)
    y -= 5.0
    # the paths' legend in words (the path of point A), in rows no wider than the drawing
    row_width = max(b.xmax - b.xmin, 60.0)
    xx, yy = x, y
    for n, name in enumerate(moving):
        colour = PATH_COLOURS[n % len(PATH_COLOURS)]
        words = f"{term('path', lang)} {name}"
        width = 9.5 + text_size(words, CAPTION_PT)[0] + 5.0
        if xx > x and xx + width > x + row_width:
            xx, yy = x, yy - 4.5
        sketch.line([complex(xx, yy - 1.4), complex(xx + 8.0, yy - 1.4)], color=colour, lw=PATH_PT, dashes=(4.0, 1.5), gid=f"legend-path-{name}", obstacle=False)
        sketch.text(complex(xx + 9.5, yy - 1.4), words, size=CAPTION_PT, ha="left", va="center", gid="legend-path", obstacle=False)
        xx += width


def number_ranges(numbers: list[int]) -> str:
    """``[1, 2, 3, 5, 7, 8]`` → ``"1–3, 5, 7, 8"`` (runs of three or more joined by an en dash)."""
    out, k = [], 0
    while k < len(numbers):
        j = k
        while j + 1 < len(numbers) and numbers[j + 1] == numbers[j] + 1:
            j += 1
        out.append(f"{numbers[k]}–{numbers[j]}" if j - k >= 2 else ", ".join(str(n) for n in numbers[k : j + 1]))
        k = j + 1
    return ", ".join(out)


def _closer_than(geoms, shapes, limit: float):
    """For each of *geoms*: whether some of *shapes* lies closer than *limit* [mm] (``distance < limit``).

    Only pairs whose bounding boxes come within *limit* can, and of those only
    the ones ``dwithin`` finds are measured (both far cheaper than measuring
    every pair).
    """
    out = np.zeros(len(geoms), dtype=bool)
    if not len(geoms) or not len(shapes):
        return out
    gb, sb = shapely.bounds(geoms), shapely.bounds(shapes)
    near = (
        (sb[None, :, 0] <= (gb[:, 2] + limit)[:, None])
        & (sb[None, :, 2] >= (gb[:, 0] - limit)[:, None])
        & (sb[None, :, 1] <= (gb[:, 3] + limit)[:, None])
        & (sb[None, :, 3] >= (gb[:, 1] - limit)[:, None])
    )
    i, j = np.nonzero(near)
    if len(i):
        within = shapely.dwithin(shapes[j], geoms[i], limit)  # (this order is the faster)
        i, j = i[within], j[within]
    if len(i):
        close = shapely.distance(geoms[i], shapes[j]) < limit
        out[i[close]] = True
    return out


def place_number(sketch: Sketch, at: complex, text: str, *, gid: str, size: float, prefer: complex | None = None, rivals=None):
    """A position number beside its mark where it has room; else at the end of a short leader line; else none.

    Room means its box keeps :data:`NUMBER_CLEAR_MM` from every obstacle
    (marks, the scheme, its labels, the numbers already placed) and a leader
    crosses no other label; and, with *rivals* (the other marks [mm]), its
    centre is nearer its own mark than any rival.  Returns the Text, or None
    when there is no room.
    """
    w, h = text_size(text, size)
    base = cmath.phase(prefer) if prefer else math.radians(45)
    candidates = []  # (centre, unit direction, on a leader), in the order they are preferred
    for gap, leader in [(g, False) for g in NEAR_GAPS] + [(g, True) for g in LEADER_GAPS]:
        for k in range(DIRECTIONS):
            theta = base + 2 * math.pi * (k // 2 + 1) / DIRECTIONS * (1 if k % 2 else -1) if k else base
            u = cmath.exp(1j * theta)
            candidates.append((at + u * (gap + abs(u.real) * w / 2 + abs(u.imag) * h / 2), u, leader))
    # only what lies within reach of the farthest candidate can be in the way
    reach = max(LEADER_GAPS) + w + h + NUMBER_CLEAR_MM
    shapes = np.array(sketch.obstacles, dtype=object) if sketch.obstacles else np.array([], dtype=object)
    if len(shapes):
        x0, y0, x1, y1 = shapely.bounds(shapes).T
        shapes = shapes[(x0 <= at.real + reach) & (x1 >= at.real - reach) & (y0 <= at.imag + reach) & (y1 >= at.imag - reach)]
    boxes = np.array([box(c.real - w / 2, c.imag - h / 2, c.real + w / 2, c.imag + h / 2) for c, _, _ in candidates], dtype=object)
    crowded = _closer_than(boxes, shapes, NUMBER_CLEAR_MM)
    if rivals is not None and len(rivals):
        others_at = np.asarray(rivals, dtype=complex)
        others_at = others_at[np.abs(others_at - at) > SAME_MARK_MM]  # (marks all but on one another: no label tells them apart)
        if len(others_at):
            centres_c = np.array([c for c, _, _ in candidates], dtype=complex)
            nearest = np.min(np.abs(centres_c[:, None] - others_at[None, :]), axis=1)
            crowded |= nearest <= np.abs(centres_c - at)
    # what the mark sits in (the pin of position 0's scheme, a block, the ring of a slot): a leader starts inside
    # it and may cross it on its way out, as long as most of the leader is outside (never along a link)
    mark = shapely.Point(at.real, at.imag)
    own = np.zeros(len(shapes), dtype=bool)
    if len(shapes):
        # (a line it lies on, within OWN_MM: not a label beside it, thicker than any line)
        width = 2 * shapely.area(shapes) / np.maximum(shapely.length(shapes), 1e-12)
        own = (shapely.distance(shapes, mark) <= 1e-9) | ((shapely.distance(shapes, mark) <= MARK_R + OWN_MM) & (width < 1.0))
        rings = shapely.get_exterior_ring(shapes)  # a ring drawn around the mark (a slot's edge, a plate's outline)
        filled = np.array([r is not None and shapely.contains(shapely.Polygon(r), mark) for r in rings], dtype=bool)
        own |= filled
        # never a label (an upright box): a leader goes round the labels
        label = (shapely.get_num_coordinates(shapes) == 5) & np.isclose(shapely.area(shapes), shapely.area(shapely.envelope(shapes)))
        own &= ~label
    others, around = shapes[~own], shapes[own]
    # a leader may cross the strokes of a hatching (bare segments) and long thin lines (a guide), not a link,
    # a pin, a mark, an arrow or a label: a line's area is its length times its width (under THIN_MM)
    if len(others):
        area, half_round = shapely.area(others), shapely.length(others) / 2
        guide = (2 * area / np.maximum(2 * half_round, 1e-12) < THIN_MM) & (half_round >= LONG_MM)
        others = others[(area > 0) & ~guide]

    for (centre, u, leader), label, no_room in zip(candidates, boxes, crowded):
        if no_room:
            continue
        if leader:
            start = at + u * (MARK_R + 0.3)
            end = centre - u * (abs(u.real) * w / 2 + abs(u.imag) * h / 2 + 0.3)
            line = LineString([(start.real, start.imag), (end.real, end.imag)])
            if len(others) and _closer_than(np.array([line], dtype=object), others, NUMBER_CLEAR_MM)[0]:  # the leader crosses nothing either
                continue
            if len(around) and float(shapely.intersection(line, shapely.union_all(around)).length) > LEADER_INSIDE * line.length:
                continue
            sketch.line([start, end], color=GHOST, lw=LEADER_PT, gid=f"{gid}-leader", zorder=4.4, obstacle=True)
        artist = sketch.text(centre, text, size=size, ha="center", va="center", gid=gid, obstacle=False, zorder=6.0)
        sketch.obstacles.append(label.buffer(LABEL_SPACE_MM, join_style=2))
        return artist
    return None


def _sub(k: int) -> str:
    """Position *k*'s number as the plan of positions writes it beside a point's mark: a superscript (``E¹``), apart
    from a subscript, which names the point of a link (``E₁``, point E of link 1: ``v_E = v_E1 + v_EE1``, domain.md
    §4) on the same page."""
    return str(k).translate(SUPERSCRIPT)


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
    return sketch_on(ax, "pos", lambda sketch: draw_positions_into(sketch, positions_run, lang=lang, k_l=k_l, law=True))
