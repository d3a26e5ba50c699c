"""The plan of positions: the mechanism in every position of a run, superimposed, with the paths of its points.

Position 0 is drawn in full (the kinematic scheme of :mod:`plans.drawing.mechanism`);
the others in thin grey lines, their joints as small circles.  The path of
every reported point over the driver's cycle (a coupler curve) is drawn from
the run's analytic sweep, broken where the mechanism cannot assemble.  The
positions are numbered 0, 1, 2, … at the driver's moving point and at every
moving reported point, as the course numbers them, where a number has room:
beside its mark, else at the end of a short leader line (no number is ever
drawn over another mark or label, on a guide's hatching or in a guideway); marks
too close together for their numbers are ringed and drawn again, enlarged n : 1,
in a drafting detail ("detail I (5 : 1)", :func:`draw_details`) where each is
numbered; only a mark that finds room in neither is listed under the plan.  A number is
its point's letter and the position as an index in digits at the small text size
(:func:`number_parts`), position 0 too (``A₀``, as ``A₀′``); it stands off the path
lines (either side of a straight one in turn); marks on one another share one
number (``Y₄, Y₈``); a lone crowded mark is numbered on a longer leader rather than
in a detail of its own.  Every fixed point the scene lists is marked and lettered
(one the scheme does not draw, an origin of coordinates, as a ring with a cross).  The
frame guides keep off the paths and every position's links: their lines and
hatching are broken where one passes through.  Paths are drawn only where the
mechanism assembles, and the caption names the positions that are not drawn and why.

Gids: ``pos-link-<k>-<body>``, ``pos-path-<point>``, ``pos-position-<k>-<point>`` (a number; ``…-leader`` its leader line), ``pos-mark-<k>-<point>``,
``pos-detail-…`` (see :func:`draw_details`), and the ``mech-…`` gids of the scheme of position 0 (prefix ``pos``).
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import shapely
from shapely.geometry import LineString, box

from .._text import SUBSCRIPT
from ..i18n import term
from ..sweep import line_travel
from ._canvas import Sketch, fmt_number, sketch_on, text_size, unit
from .labels import LABEL_SPACE_MM, RING_TURNS, label_boxes
from .mechanism import BAR_PT, FRAME, MechanismDrawing, mechanism_labels
from .numerals import detail_title, localised
from .style import CAPTION_PT, HEADING_PT, LABEL_PT, SMALL_PT

__all__ = ["draw_positions_plan", "draw_positions_into", "numbered_points", "place_number", "number_ranges", "draw_details", "number_parts", "number_size"]

GHOST = "#8c8c8c"
PATH_COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9")
GHOST_PT = 0.8
PATH_PT = 0.9
#: Radius [mm] of the mark at a numbered point of a position.
MARK_R = 0.45
#: Size [pt] of a position number's letter ...
NUMBER_PT = SMALL_PT + 0.5
#: ... and of its index, set in ordinary digits (the page's small text: a student reads it), lowered by this
#: fraction of the letter's line; numbers side by side this far [mm] apart after their comma.
INDEX_PT = SMALL_PT
INDEX_DROP = 0.25
INDEX_GAP_MM = 0.8
#: Clearance [mm] a position number keeps from every other mark and label.
NUMBER_CLEAR_MM = 0.25
#: Gaps [mm] between mark and number tried beside the mark, then at the end of a leader line.
NEAR_GAPS = (0.5, 1.1, 1.8)
LEADER_GAPS = (3.5, 5.0, 7.0, 9.5)
#: Longer leaders [mm]: a lone mark numbered on the plan rather than in a detail of its own (its leader says whose it is).
FAR_GAPS = (12.0, 15.0, 19.0, 24.0, 30.0)
#: Radius [mm] of the ring marking a fixed point the scheme does not draw (an origin of coordinates).
FIXED_R = 0.9
LEADER_PT = 0.35
#: Marks closer than this [mm] are all but one (a number beside one is beside the other): no rival to each other.
SAME_MARK_MM = 1.0
#: How much [mm] nearer its own mark than any other a number's centre is.
RIVAL_MARGIN_MM = 0.6
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
#: A point with at least this many marks (besides position 0's) all within this span [mm] is numbered in a detail.
PACKED_COUNT, PACKED_MM = 4, 6.0
#: Marks left without a number within this [mm] of one another are one crowd, drawn again in one detail...
CROWD_MM = 3.0
#: ... enlarged n : 1 by the first of these drafting ratios that sets its two closest marks this far [mm] apart.
DETAIL_RATIOS = (2, 2.5, 4, 5, 10, 20)
DETAIL_APART_MM = 2.2
#: The largest radius [mm] of a detail (a crowd that needs more is stated under the plan).
DETAIL_MOST_MM = 32.0
#: A detail finds room within the drawing, or beside it within this fraction of its size.
DETAIL_GROW = 0.3
#: The least radius [mm] round a crowd within which its neighbours decide the ratio (their numbers share its detail).
RING_LEAST_MM = 3.5
#: The least radius [mm] of a detail (room for its marks' numbers): the ring on the plan is this over the ratio.
DETAIL_LEAST_MM = 7.0
#: Room [mm] a detail leaves round its crowd's outer marks (their numbers), at its own size.
DETAIL_MARGIN_MM = 6.0
#: Marks nearer than this [mm] on the plan are one place at any ratio (their numbers stand side by side).
ONE_PLACE_MM = 0.15
#: Room [mm] the ring on the plan leaves round the crowd's outer marks.
RING_MARGIN_MM = 0.8


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
    its points numbered with the label (``E₀′``)."""
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
    clear = []  # the paths and every position's links [mm]: a frame guide's hatching keeps off them
    figure = []  # (points [mm], colour, width [pt], dashes) of the lines a detail draws again, enlarged
    for n, name in enumerate(moving):
        colour = PATH_COLOURS[n % len(PATH_COLOURS)]
        track = np.where(assembled, np.asarray(cycle.points[name].r), np.nan + 0j)
        for seg in _segments(track / k_l):
            pts = [complex(z) for z in seg]
            clear.append(LineString([(z.real, z.imag) for z in pts]))
            # over the blocks and slots of the scheme (a point's path runs through its block), under pins and labels
            sketch.line(pts, color=colour, lw=PATH_PT, dashes=(4.0, 1.5), gid=f"path-{name}", zorder=3.1, obstacle=False)
            figure.append((pts, colour, PATH_PT, (4.0, 1.5)))

    n_paths = len(clear)
    # every position's links, as a guide keeps clear of them (position 0's are drawn in full below)
    for g in [r.graphical for r in runs] + list((extremes or {}).values()):
        for body_name, body in scene.bodies.items():
            pts = [complex(g.positions[p]) / k_l for p in body.points if p in g.positions]
            if body_name != FRAME and len(pts) >= 2:
                ring = pts if len(pts) == 2 else _hull(pts) + _hull(pts)[:1]
                clear.append(LineString([(z.real, z.imag) for z in ring]))
                first_one = g is runs[0].graphical
                figure.append((ring, "#000000" if first_one else GHOST, BAR_PT / 2 if first_one else GHOST_PT, None))

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
    # (the other extreme's too, before any number: a number is never set on a mark drawn after it)
    extreme_marks = [(label, p, complex(g.positions[p]) / k_l) for label, g in (extremes or {}).items() for p in numbered if p in g.positions]
    for label, p, at in extreme_marks:
        sketch.circle(at, MARK_R, fc="#000000", lw=0, gid=f"mark-extreme-{p}", zorder=4.5, obstacle=True)

    # position 0 in full (its labels keep clear of the marks), its guides over the stroke, broken where a path
    # or a link of any position passes through their hatching
    # (position 0's numbered points are lettered with the others, A₀ as A₁, A₂, … and A₀′, not by the scheme)
    names = {p: None for p in numbered}
    mech = MechanismDrawing(sketch, base, lang=lang, caption=False, slots=line_travel(cycle), clear=clear, names=names)
    mech.draw()
    # a number stands neither on a guide's hatching, nor in a guideway, nor on a path (its leader may cross them)
    paths = [g for g in clear[:n_paths]]
    keep_out = [g for g in mech.guide_bands + mech.guideways] + paths

    # every fixed point the data lists (the frame's points) marked and lettered: the scheme letters the pivots, the
    # rest (an origin of coordinates, a point a guide is given by) get a ring with a cross and their letter here
    labelled = set(mechanism_labels(base))
    for name, z in scene.bodies[FRAME].points.items():
        if name in labelled:
            continue
        at = complex(z) / k_l
        sketch.circle(at, FIXED_R, fc="white", ec="#000000", lw=0.6, gid=f"fixed-{name}", zorder=4.5, obstacle=True)
        for u in (FIXED_R * 1.6, FIXED_R * 1.6j):
            sketch.line([at - u, at + u], color="#000000", lw=0.5, gid=f"fixed-{name}-cross", zorder=4.6, obstacle=False)
        place_number(sketch, at, name, gid=f"fixed-{name}-label", size=LABEL_PT, prefer=complex(-1, 1), keep_out=keep_out,
                     gaps=NEAR_GAPS + LEADER_GAPS + FAR_GAPS)

    # numbers where they have room: beside the mark, else on a short leader line, else left out;
    # position 0 of every point first, then the others in order
    centres = {p: (complex(np.nanmean(np.asarray(cycle.points[p].r)[assembled])) / k_l if p in cycle.points and assembled.any() else mech.centroid) for p in numbered}
    tracks = {p: np.asarray(cycle.points[p].r)[assembled] / k_l for p in numbered if p in cycle.points and assembled.any()}

    def prefer(p: str, at: complex, turn: int) -> complex | None:
        """Off the point's path: across it, away from the path's middle, or (a straight path) either side in turn."""
        away = unit(at - centres[p]) if abs(at - centres[p]) > 1e-9 else None
        track = tracks.get(p)
        if track is None or len(track) < 3:
            return away
        k = int(np.argmin(np.abs(track - at)))
        tangent = track[min(k + 1, len(track) - 1)] - track[max(k - 1, 0)]
        if abs(tangent) < 1e-9:
            return away
        normal = unit(tangent) * 1j
        side = ((at - centres[p]) * normal.conjugate()).real
        if abs(side) < 0.2 * abs(at - centres[p]) + 0.5:  # (along a straight path: above and below it in turn)
            return normal * (1 if turn % 2 == 0 else -1)
        return normal * (1 if side > 0 else -1)

    def number_marks(pack: bool) -> list[tuple[str, complex]]:
        """Number every mark (*pack*: a packed point's in a detail); the marks left without a number."""
        # (a number nearer its own mark than any other: a reader takes a number for the nearest point's)
        every = np.array([at for _, _, at in marks] + [at for _, _, at in extreme_marks], dtype=complex)
        left_out, gids = [], {}
        # (every mark: its number's text, gid, place [mm], point, the index its side of the path alternates by, rivals)
        todo = []
        # a point whose marks are packed (the linear-arm's K: eight within 3 mm in its sleeve; H within 6 mm) is
        # numbered in a detail, its scheme position on the plan: numbers on leaders round a heap of dots do not say
        # which dot is which
        packed, in_detail = set(), set()
        for q in numbered:
            pts = [at for index, p, at in marks if p == q and index != runs[0].index]
            if pack and len(pts) >= PACKED_COUNT and max(abs(a - b) for a in pts for b in pts) <= PACKED_MM:
                packed.add(q)
        for index, p, at in sorted(marks, key=lambda m: (m[0] != runs[0].index, m[0], numbered.index(m[1]))):
            if p in packed and index != runs[0].index:
                left_out.append((f"{p}{_sub(index)}", at))
                gids[f"{p}{_sub(index)}"] = f"position-{index}-{p}"
                in_detail.add(f"{p}{_sub(index)}")
                continue
            # position 0 (the scheme drawn in full) numbered first; each number nearer its own mark than any other (the
            # linear-arm's H₀, numbered "wherever it had room", stood at the far end of H's path, beside H₇)
            todo.append((f"{p}{_sub(index)}", f"position-{index}-{p}", at, p, index, every))
        for label, p, at in extreme_marks:
            todo.append((f"{p}{label.translate(SUBSCRIPT)}", f"position-extreme-{p}", at, p, 1, every))
        # marks on one another (the scotch yoke's A and Y, its Y₄ and Y₈) are numbered together: "Y₄, Y₈"
        together = []
        for item in todo:
            group = next((g for g in together if abs(g[0][2] - item[2]) <= ONE_PLACE_MM), None)
            if group is None:
                together.append([item])
            else:
                group.append(item)
        for group in together:
            text, gid, at, p, turn, rivals = group[0]
            for t, g, *_ in group:
                gids[t] = g
            if place_number(sketch, at, ", ".join(t for t, *_ in group), gid=gid, size=NUMBER_PT, prefer=prefer(p, at, turn), rivals=rivals,
                            keep_out=keep_out, part_gids=[g for _, g, *_ in group]) is None:
                left_out.extend((t, q) for t, _, q, *_ in group)
        # marks all but on one another (the scotch yoke's A and Y, M₅ and M₀′ 0.1 mm apart: no detail parts them) share
        # one number, side by side, on the plan; a lone mark without room beside it is numbered on the plan too, at the
        # end of a longer leader (its leader says whose it is), not in a detail of its own
        def joined(group, attempts) -> bool:
            text, at = ", ".join(t for t, _ in group), sum(q for _, q in group) / len(group)
            named = [gids.get(t, _ascii(t)) for t, _ in group]
            # (beside the marks, nearer them than any other; on a leader, the leader says whose it is)
            return any(place_number(sketch, at, text, gid=named[0], size=NUMBER_PT, keep_out=out, gaps=gaps, cross_lines=cross,
                                    part_gids=named, rivals=every if gaps == NEAR_GAPS else None) is not None for out, gaps, cross in attempts)

        done = set()
        for group in _grouped(left_out):
            if any(t in in_detail for t, _ in group):
                continue  # (a packed point's: to its detail)
            at = group[0][1]
            lone = all(abs(at - other) > CROWD_MM for t, other in left_out if t not in {g for g, _ in group})
            if (lone or len(group) > 1) and joined(group, ((keep_out, NEAR_GAPS, False), (keep_out, LEADER_GAPS + FAR_GAPS, False),
                                                           (keep_out, LEADER_GAPS + FAR_GAPS, True), ((), LEADER_GAPS + FAR_GAPS, True))):
                done |= {t for t, _ in group}
        left_out = [(text, at) for text, at in left_out if text not in done]
        # the marks too close together for their numbers: drawn again, enlarged, in a detail, and numbered there
        if left_out:
            every_mark = [(f"{p}{_sub(index)}", at) for index, p, at in marks] + [(f"{p}{label.translate(SUBSCRIPT)}", at) for label, p, at in extreme_marks]
            left_out = draw_details(sketch, left_out, every_mark, figure, lang=lang, last=frozenset(in_detail))
        # a mark for which neither had room: a longer leader on the plan (its leader says whose it is)
        left_out = [m for group in _grouped(left_out)
                    if not joined(group, ((keep_out, LEADER_GAPS + FAR_GAPS, False), (keep_out, LEADER_GAPS + FAR_GAPS, True),
                                          ((), LEADER_GAPS + FAR_GAPS, True)))
                    for m in group]
        return left_out

    # a point whose marks are packed is numbered in a detail where the plan has room for it; where that leaves any mark
    # without a number (the linear-arm at 12 positions: the K detail takes the room of A₅, A₆), on leaders as the rest
    state = sketch.checkpoint()
    left_out = number_marks(True)
    if left_out:
        sketch.restore(state)
        left_out = number_marks(False)

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
        for item, _ in left_out:  # lines as wide as the drawing (a caption never widens it)
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


def draw_details(sketch: Sketch, left_out: list[tuple[str, complex]], every_mark: list[tuple[str, complex]], figure, *,
                 lang: str = "en", last: frozenset = frozenset()) -> list[tuple[str, complex]]:
    """Crowds of marks whose numbers found no room drawn again, enlarged n : 1, each in a drafting detail.

    The crowd is ringed on the plan and named (I, II, …); the detail, a circle in
    free room of the drawing (else below it), shows what the ring holds — the
    lines of *figure* (points [mm], colour, width [pt], dashes) and every mark of
    *every_mark* (number text, place [mm]) — at n times its size on the plan, so
    that its length scale is k_l / n, and numbers every mark there.  Its title
    says its name and ratio in the reader's language ("detail I (5 : 1)").
    The crowds holding a mark of *last* (numbers) find their room after the others (a packed point's, numbered in a
    detail rather than on leaders: where it finds no room, its numbers go on leaders after all).
    Returns the marks numbered neither on the plan nor in a detail.
    Gids: ``detail-ring-<name>``, ``detail-mark-<name>``, ``detail-<name>``, ``detail-<name>-line``,
    ``detail-<name>-dot-<number>``, ``detail-<name>-number-<number>`` (the number in ASCII: ``H3``, ``B0p`` for B₀′),
    ``detail-<name>-title``.
    """
    from shapely.geometry import Point

    # crowds: the left-out marks within CROWD_MM of one another, by one union of disks
    disks = shapely.union_all([Point(at.real, at.imag).buffer(CROWD_MM / 2) for _, at in left_out])
    crowds = []
    for part in sorted(shapely.get_parts(disks), key=lambda g: (-g.centroid.y, g.centroid.x)):
        crowds.append([(text, at) for text, at in left_out if part.contains(Point(at.real, at.imag))])
    crowds.sort(key=lambda crowd: any(text in last for text, _ in crowd))  # (stable: in place otherwise)
    still = []
    lines = [LineString([(z.real, z.imag) for z in pts]) for pts, _, _, _ in figure if len(pts) >= 2]  # (no detail over them)
    # the details find room within the drawing, or beside it within DETAIL_GROW of its size: under a wide drawing,
    # right of a tall one (a page is filled by the drawing's longer side: the other has room to spare)
    b = sketch.bounds
    grow = DETAIL_GROW * max(b.width, b.height)
    limit = (b.xmin, b.ymin - grow, b.xmax, b.ymax) if b.width > b.height else (b.xmin, b.ymin, b.xmax + grow, b.ymax)
    names = 0
    while crowds:
        crowd = crowds.pop(0)
        name = "I" * (names + 1) if names < 3 else ("IV", "V", "VI", "VII", "VIII", "IX", "X")[min(names - 3, 6)]
        pts = [at for _, at in crowd]
        centre = sum(pts) / len(pts)
        r = max(abs(q - centre) for q in pts) + RING_MARGIN_MM
        if len(crowd) > 1 and max(abs(q - w) for q in pts for w in pts) <= SAME_MARK_MM:
            still.extend(crowd)  # (marks all but on one another: no enlargement parts them, one number on the plan names them)
            continue
        if len(crowd) > 1 and r * DETAIL_RATIOS[0] > DETAIL_MOST_MM:
            # (a crowd strung out along a path, too long for one detail: its two halves along it, each a detail)
            ends = max(((q, w) for q in pts for w in pts), key=lambda qw: abs(qw[0] - qw[1]))
            along = unit(ends[1] - ends[0])
            order = sorted(crowd, key=lambda m: ((m[1] - centre) * along.conjugate()).real)
            crowds[:0] = [order[: len(order) // 2], order[len(order) // 2:]]
            continue
        inside = [(text, at) for text, at in every_mark if abs(at - centre) <= max(r, RING_LEAST_MM)]
        apart = [abs(q - w) for i, (_, q) in enumerate(inside) for _, w in inside[:i] if abs(q - w) > ONE_PLACE_MM]
        closest = min(apart) if apart else DETAIL_APART_MM  # (a lone mark: the least enlargement)
        fits = [n for n in DETAIL_RATIOS if r * n <= DETAIL_MOST_MM]
        if not fits:
            still.extend(crowd)  # (a crowd too wide for any detail: its marks are stated under the plan)
            continue
        ratio = next((n for n in fits if closest * n >= DETAIL_APART_MM), fits[-1])
        # a compact frame: the crowd and its margin, at least DETAIL_LEAST_MM round on the detail (its numbers' room)
        spread = max(abs(q - centre) for q in pts)
        r = min(max(spread + DETAIL_MARGIN_MM / ratio, DETAIL_LEAST_MM / ratio), DETAIL_MOST_MM / ratio)
        inside = [(text, at) for text, at in every_mark if abs(at - centre) <= r]
        big = r * ratio
        title = detail_title(name, fmt_number(ratio), lang)
        tw, th = text_size(title, CAPTION_PT)
        at = _free_spot(sketch, centre, big + 1.0, (tw + 1.0, th + 4.0), limit, lines)
        if at is None:
            still.extend(crowd)  # (no room for its detail: its marks are stated under the plan)
            continue
        names += 1
        sketch.circle(centre, r, fc="none", ec="#000000", lw=0.5, gid=f"detail-ring-{name}", zorder=4.6, obstacle=False)
        sketch.obstacles.append(Point(centre.real, centre.imag).buffer(r).exterior.buffer(0.2))
        # the ring's name beside it (up and right first, then round the ring), else on a leader, across a line if need
        # be: a detail is never left unnamed on the plan (the linear-arm's ring among the links and the H numbers had none)
        any(place_number(sketch, centre + r * u, name, gid=f"detail-mark-{name}", size=CAPTION_PT, prefer=u, gaps=gaps, cross_lines=cross)
            is not None
            for gaps, cross in ((None, False), (LEADER_GAPS + FAR_GAPS[:2], False), (LEADER_GAPS + FAR_GAPS[:2], True))
            for u in (cmath.exp(1j * math.pi * k / 4) for k in RING_TURNS))

        def f(z: complex) -> complex:
            return at + (z - centre) * ratio

        disk = Point(centre.real, centre.imag).buffer(r, quad_segs=32)
        sketch.circle(at, big, fc="white", ec="#000000", lw=0.6, gid=f"detail-{name}", zorder=0.9, obstacle=False)
        sketch.obstacles.append(Point(at.real, at.imag).buffer(big).exterior.buffer(0.3))
        sketch.bounds.add_box(at.real - big, at.imag - big, at.real + big, at.imag + big)
        for pts_line, colour, lw, dashes in figure:
            line = LineString([(z.real, z.imag) for z in pts_line]) if len(pts_line) >= 2 else None
            if line is None or not line.intersects(disk):
                continue
            for part in shapely.get_parts(line.intersection(disk)):
                xy = shapely.get_coordinates(part)
                if len(xy) >= 2:
                    sketch.line([f(complex(x, y)) for x, y in xy], color=colour, lw=lw, dashes=dashes, gid=f"detail-{name}-line",
                                zorder=1.0 if colour == GHOST else 1.1, obstacle=colour != GHOST and dashes is None)
        sketch.text(at - 1j * (big + 3.0), title, size=CAPTION_PT, gid=f"detail-{name}-title", zorder=6.0)  # (before its numbers)
        big_marks = [(text, f(q)) for text, q in inside]
        for text, q in big_marks:
            sketch.circle(q, MARK_R, fc="#000000", lw=0, gid=f"detail-{name}-dot-{_ascii(text)}", zorder=4.5, obstacle=True)
        rivals = np.array([q for _, q in big_marks], dtype=complex)
        # marks all but on one another even enlarged (B₇ and B₀′) share one number, side by side: "B₇, B₀′"
        joined = _grouped(big_marks)
        # the marks lie along a path: their numbers either side of it in turn, across it
        ends = max(((q, w) for _, q in big_marks for _, w in big_marks), key=lambda qw: abs(qw[0] - qw[1]))
        along = unit(ends[1] - ends[0]) if abs(ends[1] - ends[0]) > 1e-9 else 1.0
        order = sorted(range(len(joined)), key=lambda i: ((joined[i][0][1] - at) * along.conjugate()).real)
        # (either side in turn along the path; the middle ones numbered first, the ends have room outwards)
        side = {i: turn for turn, i in enumerate(order)}
        for i in sorted(order, key=lambda i: abs(side[i] - (len(order) - 1) / 2)):
            turn = side[i]
            text, q = ", ".join(t for t, _ in joined[i]), sum(w for _, w in joined[i]) / len(joined[i])
            named = [f"detail-{name}-number-{_ascii(t)}" for t, _ in joined[i]]
            away = along * (1j if turn % 2 == 0 else -1j)
            if all(place_number(sketch, q, text, gid=named[0], size=NUMBER_PT, prefer=away, rivals=others, part_gids=named, gaps=gaps,
                                cross_lines=cross) is None
                   # (beside its dot only where it is nearer that dot than any other: round 20's H₁ stood over H₀'s dot;
                   # else on a leader, which says whose it is)
                   for others, gaps, cross in ((rivals, None, False), (None, LEADER_GAPS + FAR_GAPS[:2], False),
                                               (None, LEADER_GAPS + FAR_GAPS[:2], True))):
                still.extend((t, dict(inside)[t]) for t, _ in joined[i] if any(t == c for c, _ in crowd))
        sketch.obstacles.append(Point(at.real, at.imag).buffer(big + 1.0))  # (the next detail finds room beside it)
    return still


def _free_spot(sketch: Sketch, near: complex, radius: float, title: tuple[float, float], limit, lines=()) -> complex | None:
    """The centre [mm] of a disk of *radius* with a *title* (width, height [mm]) under it that meet no obstacle, in
    the drawing's bounds nearest *near*, else beside (under, or right of) the drawing where it grows least, within
    *limit* (x0, y0, x1, y1 [mm]), clear of the drawing's *lines* too; None where there is no such room."""
    b = sketch.bounds
    step = 2.0
    x0, y0, x1, y1 = limit
    xs = np.arange(x0 + radius, x1 - radius + 1e-9, step)
    ys = np.arange(y0 + radius + title[1], y1 - radius + 1e-9, step)
    obstacles = np.array([o for o in list(sketch.obstacles) + list(lines) if not o.is_empty], dtype=object)
    if len(xs) and len(ys) and len(obstacles):
        spots = np.array([complex(x, y) for x in xs for y in ys])
        outside = (spots.imag - radius < b.ymin) | (spots.real + radius > b.xmax)
        # within the drawing first, nearest the crowd; else beside it where it adds least
        grows = np.maximum(b.ymin - (spots.imag - radius - title[1]), 0) + np.maximum(spots.real + radius - b.xmax, 0)
        spots = spots[np.lexsort((np.abs(spots - near), np.where(outside, grows, 0.0), outside))]
        tree = shapely.STRtree(obstacles)
        for start in range(0, len(spots), 1024):
            batch = spots[start:start + 1024]
            points = shapely.points(np.column_stack([batch.real, batch.imag]))
            pairs = tree.query(points, predicate="dwithin", distance=radius)
            busy = np.zeros(len(batch), dtype=bool)
            busy[pairs[0]] = True
            tops = batch.imag - radius
            boxes = shapely.box(batch.real - title[0] / 2, tops - title[1], batch.real + title[0] / 2, tops)
            busy[tree.query(boxes, predicate="intersects")[0]] = True
            free = np.flatnonzero(~busy)
            if len(free):
                return complex(batch[int(free[0])])
    return None


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


def place_number(sketch: Sketch, at: complex, text: str, *, gid: str, size: float, prefer: complex | None = None, rivals=None,
                 keep_out=(), gaps=None, cross_lines: bool = False, part_gids=None):
    """A position number beside its mark where it has room; else at the end of a short leader line; else none.

    Room means its box keeps :data:`NUMBER_CLEAR_MM` from every obstacle
    (marks, the scheme, its labels, the numbers already placed) and a leader
    crosses no other label; and, with *rivals* (the other marks [mm]), its
    centre is nearer its own mark than any rival; and it keeps off *keep_out*
    (shapes [mm] its leader may cross: a guide's hatching).  *gaps* [mm]: the
    distances tried, the first of :data:`NEAR_GAPS` beside the mark and the rest on
    a leader (default: :data:`NEAR_GAPS` then :data:`LEADER_GAPS`; all on a leader
    when none of them is near); *cross_lines*: its leader may cross any line (a link
    drawn in full), never a mark or a label.  The number is set as :func:`number_parts`
    says (the letter, and its index lowered at :data:`INDEX_PT`); numbers joined by
    ", " (marks all but on one another) take *part_gids*, one a number.  Returns the
    letter's Text, or None when there is no room.
    """
    w, h = number_size(text, size)
    base = cmath.phase(prefer) if prefer else math.radians(45)
    candidates = []  # (centre, unit direction, on a leader), in the order they are preferred
    tried = [(g, False) for g in NEAR_GAPS] + [(g, True) for g in LEADER_GAPS] if gaps is None else [(g, g not in NEAR_GAPS) for g in gaps]
    for gap, leader in tried:
        for k in range(DIRECTIONS):
            theta = base + 2 * math.pi * (k // 2 + 1) / DIRECTIONS * (1 if k % 2 else -1) if k else base
            u = cmath.exp(1j * theta)
            candidates.append((at + u * (gap + abs(u.real) * w / 2 + abs(u.imag) * h / 2), u, leader))
    # only what lies within reach of the farthest candidate can be in the way
    reach = max(g for g, _ in tried) + w + h + NUMBER_CLEAR_MM
    shapes = np.array(sketch.obstacles, dtype=object) if sketch.obstacles else np.array([], dtype=object)
    if len(shapes):
        x0, y0, x1, y1 = shapely.bounds(shapes).T
        shapes = shapes[(x0 <= at.real + reach) & (x1 >= at.real - reach) & (y0 <= at.imag + reach) & (y1 >= at.imag - reach)]
    boxes = np.array([box(c.real - w / 2, c.imag - h / 2, c.real + w / 2, c.imag + h / 2) for c, _, _ in candidates], dtype=object)
    crowded = _closer_than(boxes, shapes, NUMBER_CLEAR_MM)
    if len(keep_out):
        crowded |= _closer_than(boxes, np.array(list(keep_out), dtype=object), NUMBER_CLEAR_MM)
    if rivals is not None and len(rivals):
        others_at = np.asarray(rivals, dtype=complex)
        others_at = others_at[np.abs(others_at - at) > SAME_MARK_MM]  # (marks all but on one another: no label tells them apart)
        if len(others_at):
            centres_c = np.array([c for c, _, _ in candidates], dtype=complex)
            nearest = np.min(np.abs(centres_c[:, None] - others_at[None, :]), axis=1)
            crowded |= nearest <= np.abs(centres_c - at) + RIVAL_MARGIN_MM  # (nearer by a margin: as the glyphs read)
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
        own &= ~label_boxes(shapes)
    others, around = shapes[~own], shapes[own]
    # a leader may cross the strokes of a hatching (bare segments) and long thin lines (a guide), not a link,
    # a pin, a mark, an arrow or a label: a line's area is its length times its width (under THIN_MM)
    if len(others):
        area, half_round = shapely.area(others), shapely.length(others) / 2
        guide = (2 * area / np.maximum(2 * half_round, 1e-12) < THIN_MM) & (half_round >= LONG_MM)
        others = others[(area > 0) & ~guide]
    if cross_lines and len(others):  # (only the marks and the labels: small shapes and upright boxes)
        others = others[label_boxes(others) | (shapely.area(others) < 1.0)]

    for (centre, u, leader), label, no_room in zip(candidates, boxes, crowded):
        if no_room:
            continue
        if leader:
            start = at + u * (MARK_R + 0.3)
            # (to the number's box, where the line towards its centre meets it)
            end = centre - u * (min(w / 2 / max(abs(u.real), 1e-9), h / 2 / max(abs(u.imag), 1e-9)) + 0.3)
            line = LineString([(start.real, start.imag), (end.real, end.imag)])
            if len(others) and _closer_than(np.array([line], dtype=object), others, NUMBER_CLEAR_MM)[0]:  # the leader crosses nothing either
                continue
            if len(around) and float(shapely.intersection(line, shapely.union_all(around)).length) > LEADER_INSIDE * line.length:
                continue
            sketch.line([start, end], color=GHOST, lw=LEADER_PT, gid=f"{gid}-leader", zorder=4.4, obstacle=True)
        artist = _draw_number(sketch, centre, text, size, gid, part_gids)
        sketch.obstacles.append(label.buffer(LABEL_SPACE_MM, join_style=2))
        return artist
    return None


def number_parts(text: str, size: float) -> list[tuple[str, float, str]]:
    """How a position number is set: ``"A₁₀"`` → ``[("A", size, "letter"), ("10", INDEX_PT, "index")]``.

    The index (the position's number, ``0′`` for the other extreme) is set in ordinary
    digits at :data:`INDEX_PT`, lowered, rather than as Unicode subscripts (a subscript
    glyph is 56 % of the size: 4.5 pt at 8 pt, too small to read on a plate).  Numbers
    joined by ", " are set one after another (``("," , size, "comma")`` between).  A
    text without an index is one letter part.
    """
    out = []
    for k, one in enumerate(text.split(", ")):
        if k:
            out.append((",", size, "comma"))
        name = one.rstrip("₀₁₂₃₄₅₆₇₈₉′")
        index = one[len(name):]
        out.append((name, size, "letter"))
        if index and name:
            out.append((index.translate(_ASCII_DIGITS), INDEX_PT, "index"))
    return out


def number_size(text: str, size: float) -> tuple[float, float]:
    """Width and height [mm] of a position number set as :func:`number_parts` says."""
    parts = number_parts(text, size)
    w = sum(text_size(s, pt)[0] for s, pt, _ in parts) + INDEX_GAP_MM * sum(kind == "comma" for _, _, kind in parts)
    h = text_size("A", size)[1]
    if any(kind == "index" for _, _, kind in parts):
        h = h / 2 + INDEX_DROP * h + text_size("1", INDEX_PT)[1] / 2
    return w, h


def _draw_number(sketch: Sketch, centre: complex, text: str, size: float, gid: str, part_gids=None):
    """Set a position number with its box centred on *centre* [mm]: the letter (gid *gid*), its index (``…-index``)."""
    parts = number_parts(text, size)
    w, h = number_size(text, size)
    h_letter = text_size("A", size)[1]
    letter_y = centre.imag + h / 2 - h_letter / 2  # (the letter's line at the top of the box, its index lowered)
    x = centre.real - w / 2
    first, n = None, 0
    for s, pt, kind in parts:
        if kind == "letter":
            name = (part_gids[n] if part_gids and n < len(part_gids) else f"{gid}-{n}") if n else gid
            n += 1
        y = letter_y - (INDEX_DROP * h_letter if kind == "index" else 0.0)
        artist = sketch.text(complex(x, y), s, size=pt, ha="left", va="center", zorder=6.0, obstacle=False,
                             gid={"letter": name, "index": f"{name}-index", "comma": f"{name}-comma"}[kind])
        first = first or artist
        x += text_size(s, pt)[0] + (INDEX_GAP_MM if kind == "comma" else 0.0)
    return first


_ASCII_DIGITS = str.maketrans({c: str(n) for n, c in enumerate("₀₁₂₃₄₅₆₇₈₉")})


def _ascii(text: str) -> str:
    """A mark's number as a gid writes it: ``B₀′`` → ``B0p``."""
    return text.translate(_ASCII)


_ASCII = str.maketrans({**{c: str(n) for n, c in enumerate("₀₁₂₃₄₅₆₇₈₉")}, "′": "p"})


def _grouped(marks) -> list[list[tuple[str, complex]]]:
    """(text, at) marks in groups of those within :data:`SAME_MARK_MM` of a group's first [mm]: one number each."""
    groups: list[list[tuple[str, complex]]] = []
    for text, at in marks:
        group = next((g for g in groups if abs(g[0][1] - at) <= SAME_MARK_MM), None)
        if group is None:
            groups.append([(text, at)])
        else:
            group.append((text, at))
    return groups


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
    return sketch_on(ax, "pos", lambda sketch: draw_positions_into(sketch, positions_run, lang=lang, k_l=k_l, law=True))
