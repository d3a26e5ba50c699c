"""Handouts: the course project of one mechanism as A4 pages, PDF (or SVG page by page).

Orchestration only: the positions are solved by :mod:`plans.positions`, the
equations written by :mod:`plans.loops`, the pages drawn by
:mod:`plans.drawing.sheets` and :mod:`plans.drawing.diagrams` (imported when
the pages are made, so importing this module loads no matplotlib).

What a handout holds:

* one position (``positions=None``): two pages — the *graphical* page (title,
  data, structural formula, the mechanism and both plans true to scale, the
  legend, the vector equations of every group) and the *analytic check*
  (graphical against analytic values with their errors, and the
  complex-number loop equations of every group with the numbers
  substituted); printed double-sided, one sheet of paper;
* several positions: a cover page (data, the plan of positions with the
  paths of the points, the list of positions), the two pages of every
  position, the kinematic diagrams over the cycle, and the output link's
  s–t, v–t, a–t diagrams by graphical differentiation (the method of chords
  drawn with its pole and rays) with the table of v and a at every position
  from the diagrams, the plans and analytic (:mod:`plans.differentiation`).

Every position page has the same arrangement (one :class:`plans.drawing.layout.Frame`
of boxes, chosen for the drawings it must hold).  The mechanism is drawn at
one k_l on every page; k_v and k_a are chosen for each position so that its
plans fill their boxes (each page states its own, and says so).  Factors
given by the user or the scene are kept.

>>> import plans
>>> from plans.handout import handout_pages
>>> scene = plans.load(plans.example_path("four-bar"))
>>> [name for name, _ in handout_pages(scene)]                       # doctest: +SKIP
['position-0', 'check-0']
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

from ._text import subscript
from .errors import PlansError
from .graphical.scales import PAGE_MANTISSAS, round_up
from .i18n import check_language, reason_text, term
from .scene import FRAME, Crank, Scene

__all__ = ["HandoutError", "write_handout", "handout_pages", "scene_data_lines", "cycle_lines", "handout_scales", "round_up", "HANDOUT_MANTISSAS"]

class HandoutError(PlansError, ValueError):
    """A handout that cannot be written as asked (such as several pages into one SVG)."""


# --- words ------------------------------------------------------------------------------


def _length_unit(scene: Scene) -> tuple[str, float]:
    sizes = [abs(z) for body in scene.bodies.values() for z in body.points.values()]
    largest = max(sizes, default=1.0)
    if largest < 1e-3:
        return "µm", 1e6
    if largest < 20.0:
        return "mm", 1e3
    return "m", 1.0


def _fmt(x: float) -> str:
    text = f"{x:.4g}"
    if "e" in text:
        text = f"{x:.3e}"
    return text.replace("-", "−")


def _guide_angle(scene: Scene, name: str) -> float:
    """The angle [rad] of the frame's line *name* (0 when the frame has no such line)."""
    line = scene.bodies[FRAME].lines.get(name)
    return line.angle if line is not None else 0.0


def scene_data_lines(scene: Scene, lang: str = "en") -> list[str]:
    """The scene's data as a few lines of text: driver, link lengths, fixed points."""
    unit, factor = _length_unit(scene)
    driver = scene.driver
    link = driver.link
    if isinstance(driver, Crank):
        first = (
            f"{term('driver', lang)} {link} ({driver.pivot}):  ω{subscript(link)} = {_fmt(driver.omega)} rad/s,  "
            f"ε{subscript(link)} = {_fmt(driver.epsilon)} rad/s²"
        )
    else:
        first = (
            f"{term('driver', lang)} {link} ({driver.point}, {driver.guide} ∥ {_fmt(math.degrees(_guide_angle(scene, driver.guide)))}°):  v = {_fmt(driver.velocity)} m/s,  "
            f"a = {_fmt(driver.acceleration)} m/s²"
        )
        if driver.stroke:
            first += f",  s ∈ [{_fmt(driver.stroke[0] * factor)}, {_fmt(driver.stroke[1] * factor)}] {unit}"
    lengths = []
    for name, body in scene.bodies.items():
        if name == FRAME or body.block:
            continue
        pts = list(body.points.items())
        pairs = []
        for a in range(len(pts)):
            for b in range(a + 1, len(pts)):
                (na, za), (nb, zb) = pts[a], pts[b]
                pairs.append(f"{na}{nb} = {_fmt(abs(za - zb) * factor)}")
        extra = [f"∠{line.name} = {_fmt(math.degrees(line.angle))}°" for line in body.lines.values() if line.angle]
        if pairs or extra:
            lengths.append(f"{name}: " + ", ".join(pairs + extra))
    second = f"{term('lengths', lang)} [{unit}]:  " + ";  ".join(lengths)
    frame = scene.bodies[FRAME]
    fixed = [f"{n} ({_fmt(z.real * factor)}, {_fmt(z.imag * factor)})" for n, z in frame.points.items()]
    fixed += [f"{line.name}: ∠{_fmt(math.degrees(line.angle))}°" for line in frame.lines.values()]
    third = f"{term('fixed_points', lang)} [{unit}]:  " + ",  ".join(fixed) if fixed else ""
    return [line for line in (first, second, third) if line]


def cycle_lines(run, lang: str = "en") -> list[str]:
    """What the cover states of a cycle (issue 19): the driver's law, the Grashof class of every four-bar loop,
    the output's stroke H (or swing ψ), θ, K and the working stroke (:mod:`plans.motion`)."""
    from .motion import four_bar_loops

    import textwrap

    lines = []
    if run.motion is not None:  # a long law in lines a cover's width (about 110 characters), the rest indented
        lines += textwrap.wrap(run.motion.law.describe(lang, run.scene.driver.link), 110, subsequent_indent="    ")
    for loop in four_bar_loops(run.scene, run.structure):
        turning = loop.turning_links()
        turns = f"{', '.join(turning)}: {term('turn_fully', lang)}" if turning else term("none_turns", lang)
        lines.append(f"{term('grashof_class', lang)} {loop.group}: {term(loop.grashof.kind, lang)} ({turns})")
    if run.strokes is not None:
        lines += run.strokes.summary(lang)
    return lines


def _table(run, lang: str) -> list[list[str]]:
    """The results table of a solved position, its slider rows named as the drawn vectors."""
    from .report import sheet_table
    from .drawing.sheet import translate_table

    return translate_table(sheet_table(run.comparisons, run.graphical, run.analytic), lang)


def _equations(graphical, structure) -> dict[str, list[str]]:
    """Page (``"velocity"``, ``"acceleration"``) -> the vector equations of its plan."""
    from .drawing.sheet import sheet_equations

    return {page: sheet_equations(graphical, driver_label=f"I({structure.frame},{structure.driver})", plans=(page,)) for page in ("velocity", "acceleration")}


# --- scales ------------------------------------------------------------------------------

#: The round mantissas of a handout's scale factors: finer than the textbook's
#: 1, 2, 2.5, 5 so that a drawing fills its box to within a factor of 4/3.
HANDOUT_MANTISSAS = PAGE_MANTISSAS
#: Room [mm] kept around a drawing's geometry in its box: the drawing's margin and labels, each side.
LABEL_ROOM = 6.0
#: Room [mm] under a drawing for its heading and scale factor.
CAPTION_ROOM = 13.0
#: What a page must give a drawing [mm]: the largest vector of a plan, a plan across, the mechanism across.
LARGEST_VECTOR_MM = 60.0
PLAN_ACROSS_MM = 40.0
MECHANISM_ACROSS_MM = 100.0


def _larger(k: float) -> float:
    """The next round scale factor above k."""
    return round_up(k * (1 + 1e-9) * 1.0000001)


def _bbox(points) -> tuple[float, float]:
    zs = list(points)
    if not zs:
        return 0.0, 0.0
    xs = [z.real for z in zs]
    ys = [z.imag for z in zs]
    return max(xs) - min(xs), max(ys) - min(ys)


def _extents(g) -> dict[str, tuple[float, float, float]]:
    """Physical (width, height, largest vector) of the mechanism [m] and of each plan [m/s, m/s²]."""
    out = {"k_l": (*_bbox(g.positions.values()), 0.0)}
    for key, plan in (("k_v", g.velocity_plan), ("k_a", g.acceleration_plan)):
        if plan is None:
            continue
        w, h = _bbox([z * plan.scale for z in plan.images.values()] + [0j])
        largest = max((abs(v.tip - v.tail) * plan.scale for v in plan.vectors), default=0.0)
        out[key] = (w, h, largest)
    return out


def _geometry_box(box, fixed=None) -> tuple[float, float]:
    """What *box* leaves a drawing's geometry [mm]: the box less *fixed* (what does not scale), by default the label and caption room."""
    _, _, w, h = box
    fw, fh = fixed if fixed is not None else (2 * LABEL_ROOM, 2 * LABEL_ROOM + CAPTION_ROOM)
    return max(w - fw, 5.0), max(h - fh, 5.0)


def _fixed_parts(g, lang: str, kinds=("mechanism", "velocity", "acceleration")) -> dict[str, tuple[float, float]]:
    """Kind -> what a drawing of *g* takes beyond its geometry [mm] (margin, labels, supports, blocks, driver arcs,
    caption), measured by drawing it once (never less than the default label and caption room).

    What does not scale with the drawing stays the same at any scale factor
    (a mechanism's blocks and supports, the labels, the caption): the size of
    a drawing at any k is its geometry / k plus this.
    """
    from .drawing.blocks import drawing_block
    from .drawing.svg import drawing_rc, new_figure

    e = _extents(g)
    out = {}
    objects = {"k_l": ("mechanism", g), "k_v": ("velocity", g.velocity_plan), "k_a": ("acceleration", g.acceleration_plan)}
    with drawing_rc():
        fig = new_figure()
        for key, (kind, obj) in objects.items():
            if obj is None or key not in e or kind not in kinds:
                continue
            block = drawing_block(fig, kind, obj, lang, legend=False)
            k = g.scales[key]
            out[kind] = (max(block.width - e[key][0] / k, 2 * LABEL_ROOM), max(block.height - e[key][1] / k, 2 * LABEL_ROOM + CAPTION_ROOM))
    return out


def _fit(extent, box, fallback: float, fixed=None) -> float:
    gw, gh = _geometry_box(box, fixed)
    need = max(extent[0] / gw, extent[1] / gh)
    return round_up(need) if need > 0 and math.isfinite(need) else fallback


def handout_scales(runs, frame, given: dict | None = None, fixed: dict | None = None) -> tuple[float, list[dict[str, float]]]:
    """The scale factors of a handout's position pages for the drawing boxes of *frame*.

    k_l is common to every position (the mechanism at the same scale on
    every page and on the plan of positions: every position's mechanism, drawn,
    fits the mechanism's box); k_v and k_a are chosen per
    position, each the smallest round factor (:data:`HANDOUT_MANTISSAS`)
    with which that position's plan fits its box, so that every plan fills
    its box.  Each page states its own.  Factors in *given* are kept.
    *fixed* (kind -> (width, height) [mm], see :func:`_fixed_parts`) is what
    a drawing takes beyond its geometry; by default a label and caption room;
    ``fixed["mechanisms"]``, when given, is each solved position's mechanism
    drawn: (a_w, b_w, a_h, b_h), its width a_w / k + b_w [mm] and its height
    a_h / k + b_h at any k_l (see :func:`_mechanism_sizes`).

    Returns
    -------
    (k_l, [ {"k_l", "k_v", "k_a"} per run ])
    """
    given = {k: v for k, v in (given or {}).items() if v is not None}
    fixed = fixed or {}
    solved = [r for r in runs if r.ok]
    extents = [_extents(r.graphical) for r in solved]
    if "k_l" in given:
        k_l = given["k_l"]
    else:
        parts = fixed.get("mechanism") or (2 * LABEL_ROOM, 2 * LABEL_ROOM + CAPTION_ROOM)
        each = fixed.get("mechanisms") or [(e["k_l"][0], parts[0], e["k_l"][1], parts[1]) for e in extents]
        need = 0.0
        for a_w, b_w, a_h, b_h in each:
            gw, gh = _geometry_box(frame.boxes["mechanism"], (b_w, b_h))
            need = max(need, a_w / gw, a_h / gh)
        k_l = round_up(need) if need > 0 and math.isfinite(need) else (solved[0].graphical.scales["k_l"] if solved else 1.0)
    per_run = []
    for r, e in zip(solved, extents):
        scales = {"k_l": k_l}
        for key, kind in (("k_v", "velocity"), ("k_a", "acceleration")):
            if key not in e:
                continue
            scales[key] = given[key] if key in given else _fit(e[key], frame.boxes[kind], r.graphical.scales[key], fixed.get(kind))
        per_run.append(scales)
    return k_l, per_run


def _frame_score(runs, frame, given, fixed=None) -> float:
    """How well *frame* serves the drawings, and the worst ratio of drawn size to what a page must give.

    Ratios (each capped at 1.5: beyond that a drawing is big enough) of the
    mechanism across to :data:`MECHANISM_ACROSS_MM`, each plan's largest
    vector to :data:`LARGEST_VECTOR_MM` and its size across to
    :data:`PLAN_ACROSS_MM`, over every position; the score is 0.2 × their
    mean + 0.8 × their minimum, so that a frame is chosen that makes the
    drawings large without leaving one of them small.  Returns (score, worst ratio).
    """
    k_l, per_run = handout_scales(runs, frame, given, fixed)
    ratios = []
    for r, scales in zip([r for r in runs if r.ok], per_run):
        e = _extents(r.graphical)
        ratios.append(max(e["k_l"][0], e["k_l"][1]) / k_l / MECHANISM_ACROSS_MM)
        for key in ("k_v", "k_a"):
            if key in e and e[key][2] > 0:
                w, h, largest = e[key]
                ratios.append(largest / scales[key] / LARGEST_VECTOR_MM)
                ratios.append(max(w, h) / scales[key] / PLAN_ACROSS_MM)
    capped = [min(x, 1.5) for x in ratios] or [0.0]
    return 0.2 * sum(capped) / len(capped) + 0.8 * min(capped), min(capped)


def _choose_frame(frames, runs, given, fixed):
    """The frame whose drawings are largest (:func:`_frame_score`), the mechanism and the velocity plan on one page
    when some such frame gives every drawing what a page must (a frame that parts them only when none does)."""
    scored = [(frame, *_frame_score(runs, frame, given, fixed)) for frame in frames]
    together = [item for item in scored if item[0].pages.get("velocity") == item[0].pages.get("mechanism")]
    if any(least >= 1.0 for _, _, least in together):
        scored = together
    return max(scored, key=lambda item: item[1])[0]


def _mechanism_sizes(solved, lang: str, first) -> list[tuple[float, float, float, float]]:
    """Each solved position's mechanism drawn, as (a_w, b_w, a_h, b_h): width a_w / k_l + b_w [mm], height a_h / k_l + b_h.

    Drawn once at its own k_l (*first*: what the first position's drawing
    takes beyond its geometry, measured already), the geometry (a = the
    extent of its points [m]) taken to scale and the rest not; a drawing
    whose guides or slots reach past its points has more that scales:
    :func:`_refine_mechanism_sizes` measures those again at the page's k_l.
    """
    out = []
    for n, r in enumerate(solved):
        w, h, _ = _extents(r.graphical)["k_l"]
        b_w, b_h = first if n == 0 else _fixed_parts(r.graphical, lang, ("mechanism",))["mechanism"]
        out.append((w, b_w, h, b_h, r.graphical.scales["k_l"]))
    return out


def _refine_mechanism_sizes(solved, sizes, k_l: float, box, lang: str, construct_at) -> bool:
    """Draw again at *k_l* the mechanisms that might not fit *box* at it, and make their (a, b) exact (two sizes, two k).

    A mechanism drawn at k₁ as D₁ mm is at most D₁·k₁/k_l at k_l (were all
    of it to scale): only those that could then run out of the box are drawn
    again.  Changes *sizes* in place; returns whether any changed.
    """
    from .drawing.blocks import drawing_block
    from .drawing.svg import drawing_rc, new_figure

    changed = False
    _, _, bw, bh = box
    for n, (r, size) in enumerate(zip(solved, sizes)):
        a_w, b_w, a_h, b_h, k1 = size
        if k1 == k_l or ((a_w / k1 + b_w) * k1 / k_l <= bw and (a_h / k1 + b_h) * k1 / k_l <= bh):
            continue
        with drawing_rc():
            block = drawing_block(new_figure(), "mechanism", construct_at(r, k_l), lang, legend=False)
        d1w, d1h = a_w / k1 + b_w, a_h / k1 + b_h
        inv = 1 / k_l - 1 / k1
        a_w2, a_h2 = max(a_w, (block.width - d1w) / inv), max(a_h, (block.height - d1h) / inv)
        sizes[n] = (a_w2, block.width - a_w2 / k_l, a_h2, block.height - a_h2 / k_l, k_l)
        changed = True
    return changed


def _make_room(g, frame, sizes, scales, given) -> dict[str, float]:
    """*scales* with each factor enlarged whose drawing, as drawn (*sizes* [mm]), runs out of its box.

    A drawing is its geometry (physical extent / k) plus what does not scale
    (margin, labels, caption): the new k gives the geometry what the box
    leaves beside the latter.
    """
    out = dict(scales)
    e = _extents(g)
    for key, kind in (("k_l", "mechanism"), ("k_v", "velocity"), ("k_a", "acceleration")):
        if kind not in sizes or given.get(key) is not None or key not in e:
            continue
        (w, h), (_, _, bw, bh) = sizes[kind], frame.boxes[kind]
        if w <= bw + 0.5 and h <= bh + 0.5:
            continue  # (the page lets a drawing run a little over before it asks)
        k = scales[key]
        need = k
        for drawn, box, extent in ((w, bw, e[key][0]), (h, bh, e[key][1])):
            fixed = drawn - extent / k
            room = box - fixed
            need = max(need, extent / room if room > 5.0 else k * 4)
        out[key] = round_up(need * (1 + 1e-9)) if need > k else _larger(k)
    return out


def _cover_scale(run, list_rows: int, common: float | None = None) -> float | None:
    """A round k_l that fits the plan of positions (every position and the paths) on the cover page: the
    position pages' *common* k_l when that fits (one k_l in the whole handout), else the smallest that does."""
    import numpy as np

    zs = []
    for r in run.runs:
        if r.ok:
            zs.extend(r.graphical.positions.values())
    for name in run.scene.report:
        if name in run.cycle.points:
            r = np.asarray(run.cycle.points[name].r)
            zs.extend(complex(z) for z in r[np.isfinite(r.real) & np.isfinite(r.imag)])
    if not zs:
        return None
    w, h = _bbox(zs)
    box_w = 210.0 - 2 * 11.0 - 24.0
    box_h = 297.0 - 2 * 11.0 - 45.0 - 30.0 - 5.0 * (list_rows + 2) - 24.0
    need = max(w / box_w, h / max(box_h, 40.0))
    if not (need > 0 and math.isfinite(need)):
        return None
    return common if common is not None and common >= need else round_up(need)


# --- pages --------------------------------------------------------------------------------


def handout_pages(
    scene: Scene,
    *,
    positions=None,
    lang: str = "en",
    k_l: float | None = None,
    k_v: float | None = None,
    k_a: float | None = None,
    precision: float | None = None,
    components: bool = False,
    progress=None,
    record: list | None = None,
    centres: bool = False,
    forces: bool = False,
    law: str | None = None,
    start: str = "output",
) -> list[tuple[str, object]]:
    """The handout's pages as (name, matplotlib Figure) pairs, in order.

    Names: ``cover``, ``position-K`` and ``check-K`` for each position K,
    ``unsolved-K`` for a position that cannot be solved, ``diagram-links``,
    ``diagram-points``, ``diagram-sliders``, ``kinematic-1`` (and ``kinematic-2``: the output link's
    kinematic diagrams by graphical differentiation, and their table), ``centres-K`` with *centres*,
    ``forces-K`` (``forces-K-2`` …) with *forces*.  Arguments as :func:`write_handout`;
    *record* (a list), when given, receives ``(page name, PositionRun drawn)``
    for every position page (the solution at the scale factors the page states).
    """
    from .compare import compare
    from .drawing.diagrams import draw_cycle_diagrams
    from .drawing.layout import stamp_page_number
    from .drawing.sheets import draw_check_pages, draw_cover_page, draw_position_page, draw_unsolved_page, position_page_frames
    from .graphical import construct
    from .loops import loop_equations
    from .positions import at_page_precision, position_text, run_positions

    check_language(lang)
    if forces and not scene.has_forces:
        from .errors import SceneError

        raise SceneError("--forces: the scene has no masses and no loads, so there is no kinetostatics to draw "
                         "(give mass, centre, inertia on the links, [gravity] and [[load]]; plans examples --loads lists scenes that do)", scene.source)
    scene = at_page_precision(scene, precision)  # lengths measured and printed to 0.1 mm unless told
    say = progress or (lambda text: None)
    given = {"k_l": k_l if k_l is not None else scene.scales.k_l,
             "k_v": k_v if k_v is not None else scene.scales.k_v,
             "k_a": k_a if k_a is not None else scene.scales.k_a}
    run = run_positions(scene, positions, k_l=given["k_l"], k_v=given["k_v"], k_a=given["k_a"], precision=None, law=law, start=start)
    # slots drawn over the cycle's travel; a frame guide (a ram's guideway) around the block's present place on
    # a position page: over its whole stroke it would take the velocity plan's room (the cover draws the stroke)
    run = replace(run, runs=tuple(
        replace(r, graphical=replace(r.graphical, travel={k: t for k, t in r.graphical.travel.items() if not k.startswith("frame.")}))
        if r.graphical is not None else r for r in run.runs
    ))
    multi = positions is not None
    data = scene_data_lines(scene, lang)
    footer = f"plans — {scene.title}"
    formula = f"{term('structural_formula', lang)}:  {run.structure.formula}"
    solved = [r for r in run.runs if r.ok]

    def where(r) -> str:
        return f"{term('position', lang)} {r.index}:  {r.label}" if multi else r.label

    def head(r, page="velocity"):
        # each scale factor is stated once, under the drawing it belongs to (its caption), not again in the header;
        # the scene's data are on the cover of a multi-position handout: its position pages give the room to the drawings
        if multi:
            return ["§" + where(r), "§" + formula, term("scales_per_position", lang)]
        return ["§" + where(r)] + (data if page == "velocity" else []) + ["§" + formula]

    def at_scales(r, scales):
        g = construct(r.scene, run.structure, k_l=scales["k_l"], k_v=scales["k_v"], k_a=scales.get("k_a"), precision=run.precision, check_scales=False)
        g = replace(g, travel=r.graphical.travel, cycle_poses=r.graphical.cycle_poses)  # slots over the cycle's travel (see below), the frame as on every page
        return replace(r, graphical=g, comparisons=compare(r.analytic, g))

    # one frame of drawing boxes for every position page, chosen for the drawings it must hold
    pages_runs = {}
    if solved:
        sample = solved[0]
        frames = position_page_frames(sample.graphical, lang=lang, header_lines=lambda page: head(sample, page), equations=_equations(sample.graphical, run.structure))
        # what the drawings take beyond their geometry: the plans' as the first position's, each mechanism's its own
        unscaled = _fixed_parts(sample.graphical, lang)
        sizes = None
        if given.get("k_l") is None:
            sizes = _mechanism_sizes(solved, lang, unscaled["mechanism"])
            unscaled["mechanisms"] = [size[:4] for size in sizes]
        frame = _choose_frame(frames, run.runs, given, unscaled)
        k_l_common, per_run = handout_scales(run.runs, frame, given, unscaled)
        # mechanisms whose guides or slots scale too: drawn again at that k_l, measured, and k_l fitted to them
        for _ in range(2):
            if sizes is None or not _refine_mechanism_sizes(solved, sizes, k_l_common, frame.boxes["mechanism"], lang,
                                                            lambda r, k: replace(construct(r.scene, run.structure, k_l=k, k_v=r.graphical.scales["k_v"], k_a=r.graphical.scales.get("k_a"), precision=run.precision, check_scales=False), cycle_poses=r.graphical.cycle_poses)):
                break
            unscaled["mechanisms"] = [size[:4] for size in sizes]
            k_l_common, per_run = handout_scales(run.runs, frame, given, unscaled)
        for r, scales in zip(solved, per_run):
            pages_runs[r.index] = (r, {**scales, "k_l": k_l_common})
        # the same k_l on every page: only k_v, k_a make room page by page
        fixed = {**given, "k_l": k_l_common} if len(solved) > 1 else given

    pages: list[tuple[str, object]] = []
    if multi and solved:
        listing = [f"{r.index}:  {r.label}" + ("" if r.ok else f"  ({term('not_solved', lang)}: {r.brief(lang)})") for r in run.runs]
        if run.strokes is not None and run.motion is not None and run.motion.start == "output" and run.strokes.law.crank:
            listing.append(f"0′:  {position_text(run.scene, run.strokes.other_position)}")  # the other extreme position
        cover_k = _cover_scale(run, math.ceil(len(listing) / 3), fixed.get("k_l"))
        cover_lines = data + cycle_lines(run, lang) + ["§" + formula]  # k_l stated under the plan of positions
        pages.append(("cover", draw_cover_page(run, lang=lang, header_lines=cover_lines, positions_lines=listing, footer=footer, k_l=cover_k)))
    for number, r in enumerate(run.runs, start=1):
        say(f"{term('position', lang)} {number}/{len(run.runs)}")
        if not r.ok:
            pages.append((f"unsolved-{r.index}", draw_unsolved_page(r, lang=lang, where=where(r), message=reason_text(str(r.error), lang, r.cause), footer=footer)))
            continue
        _, scales = pages_runs[r.index]

        def rescale(g, kind, size, r=r):
            key = {"mechanism": "k_l", "velocity": "k_v", "acceleration": "k_a"}[kind]
            wider = _make_room(g, frame, {kind: size}, g.scales, fixed)
            return None if wider[key] == g.scales[key] else at_scales(r, {**g.scales, key: wider[key]}).graphical

        equations = _equations(r.graphical, run.structure)
        here = at_scales(r, scales)
        drawn = []
        for page, name in (("velocity", "position"), ("acceleration", "acceleration")):
            if page == "acceleration" and here.graphical.acceleration_plan is None:
                continue
            fig, g = draw_position_page(here, frame=frame, page=page, lang=lang, header_lines=lambda g, r=r, page=page: head(r, page), equations=equations, footer=footer, rescale=rescale)
            if g is not here.graphical:
                here = replace(r, graphical=g)
            drawn.append((f"{name}-{r.index}", fig))
        here = replace(r, graphical=here.graphical, comparisons=compare(r.analytic, here.graphical))
        for name, fig in drawn:
            if record is not None:
                record.append((name, here))
            pages.append((name, fig))
        check_head = ["§" + where(r), formula]
        checks = draw_check_pages(here, lang=lang, header_lines=check_head, loops=loop_equations(here.analytic), table=_table(here, lang), footer=footer)
        for n, page in enumerate(checks):
            pages.append((f"check-{r.index}" + (f"-{n + 1}" if n else ""), page))
        if centres:  # the instant-centre page of the position (plans.drawing.centres_page)
            from .drawing.centres_page import draw_centres_page

            pages.append((f"centres-{r.index}", draw_centres_page(r, lang=lang, header_lines=check_head, footer=footer)))
        if forces:  # the kinetostatic pages of the position (plans.drawing.forces_page), from its graphical solution
            from .drawing.forces_page import draw_forces_pages
            from .forces.lever import LeverError, joukowski_lever

            try:
                lever = joukowski_lever(here.graphical)
            except LeverError:
                lever = None  # the driver at rest: no arm for the balancing force (the force plans still give M_b)
            for n, page in enumerate(draw_forces_pages(here.graphical, lang=lang, header_lines=check_head, footer=footer, lever=lever)):
                pages.append((f"forces-{r.index}" + (f"-{n + 1}" if n else ""), page))

    if multi and solved:
        marked = run.motion if run.motion is not None else run.positions
        for name, fig in draw_cycle_diagrams(run.cycle, marked=marked, lang=lang, components=components, cycle=run.dense, extremes=run.strokes):
            pages.append((f"diagram-{name}", fig))
        for number, fig in enumerate(_kinematic_pages(scene, positions, len(run.runs), precision, lang, footer, law, start), start=1):
            pages.append((f"kinematic-{number}", fig))
    # page numbers
    total = len(pages)
    for number, (_, fig) in enumerate(pages, start=1):
        stamp_page_number(fig, number, total, lang)
    return pages


def _kinematic_pages(scene: Scene, positions, count: int, precision: float | None, lang: str, footer: str,
                     law: str | None = None, start: str = "output") -> list:
    """The page of the output link's kinematic diagrams by graphical differentiation (and the page of its table
    when that does not fit under them), at the handout's count of positions (12 when it has fewer than 8).

    The diagrams take their own positions, from the output's extreme position under the driver's law
    (:func:`plans.differentiation.kinematic_diagrams`), as the course project numbers them.  A
    mechanism without an output slider or rocker, or not solved at one of those positions, gets a page that says so.
    """
    from .differentiation import DiagramsError, kinematic_diagrams
    from .drawing.kinematic_diagrams import draw_kinematic_pages, draw_unavailable_page

    if isinstance(positions, int):
        count = positions
    if count < 8:  # a course project differentiates over 8 or more
        count = 12
    try:
        diagrams = kinematic_diagrams(scene, count, law=law, start=start, precision=precision)
    except DiagramsError as exc:  # said on a page of its own, in the reader's language
        return [draw_unavailable_page(exc, title=scene.title, lang=lang, footer_text=footer)]
    return draw_kinematic_pages(diagrams, title=scene.title, lang=lang, footer_text=footer)


def write_handout(
    scene: Scene,
    path,
    *,
    positions=None,
    lang: str = "en",
    k_l: float | None = None,
    k_v: float | None = None,
    k_a: float | None = None,
    precision: float | None = None,
    components: bool = False,
    progress=None,
    centres: bool = False,
    forces: bool = False,
    law: str | None = None,
    start: str = "output",
) -> list[Path]:
    """Write the handout of a scene: a PDF of A4 pages, or SVG pages.

    Parameters
    ----------
    scene : Scene
    path : str or pathlib.Path
        ``FILE.pdf``: every page in one file.  ``FILE.svg``: one file per
        page, ``FILE-01.svg``, ``FILE-02.svg``, … (numbers zero-padded, so
        they sort in page order; a one-position handout has two pages).
    positions : None, int, str or sequence
        None: the scene's own position.  Otherwise anything
        :func:`plans.positions.parse_positions` takes (``12``,
        ``"0,30,55,90 deg"``): a cover page, two pages per position and the
        cycle diagrams.
    lang : str
        ``"en"`` (default), ``"sr"``, ``"ru"``, ``"bg"`` or ``"sl"``: headings
        and legends; point letters and symbols stay as they are.
    k_l, k_v, k_a : float, optional
        Scale factors; by default the round values that fit every position
        on the page.
    precision : float, optional
        Drafting precision [mm] of the graphical readings: every length is
        measured (and printed) to it.  Default: the scene's ``[scales]
        precision``, else :data:`plans.positions.PAGE_PRECISION` (0.1 mm);
        0 gives exact readings.
    components : bool
        Cycle diagrams of the x and y components of every point's v and a too.
    progress : callable, optional
        Called with a short text (``"position 3/12"``, ``"page 5/28"``) as the work goes on.
    centres : bool
        A page more after each position's: the instant centres (Kennedy's
        theorem, :mod:`plans.centres`) drawn on the mechanism with the circle
        diagram, and ω, v from them against the analytic values.
    forces : bool
        The kinetostatic pages after each position's (the scene must have
        masses or loads): the free bodies of the groups with their loads and
        reactions, each group's force plan and the driver's with the
        reactions read off them and M_b, and Joukowski's lever
        (:mod:`plans.drawing.forces_page`).
    law : str, optional
        The driver's law over the cycle (``"constant"``, ``"uniform"``,
        ``"harmonic"``; :func:`plans.motion.driver_law`); None: the scene's
        ``[driver] law`` or the default.  Stated on the cover and the diagrams.
    start : {"output", "scene"}
        Position 0 of a count: the extreme position of the output link that
        starts its working stroke (default), or the scene's own position.

    Returns
    -------
    list of pathlib.Path
        The files written (one for a PDF).

    Raises
    ------
    HandoutError
        For a file that is neither .pdf nor .svg, or an unknown language.
    StructureError, SceneError, AssemblyError, SingularPositionError
        For a scene that cannot be solved (a single position that cannot be
        assembled included; in a multi-position run such a position gets a
        page that says why).
    """
    from .drawing.formats import render_pdf
    from ._files import replace_all
    from .drawing.svg import render_svg

    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in (".pdf", ".svg", ".png"):
        raise HandoutError(f"{path}: a handout is written as .pdf (or .svg or .png, one file per page), not {path.suffix or 'a file without a suffix'}")
    try:
        check_language(lang)
    except ValueError as exc:
        raise HandoutError(str(exc)) from None
    if positions is None:
        _check_solvable(scene)
    pages = handout_pages(scene, positions=positions, lang=lang, k_l=k_l, k_v=k_v, k_a=k_a, precision=precision, components=components, progress=progress, centres=centres, forces=forces, law=law, start=start)
    say = progress or (lambda text: None)
    total = len(pages)
    if suffix == ".pdf":
        return replace_all({path: render_pdf([fig for _, fig in pages], progress=lambda n: say(f"{term('page', lang)} {n}/{total}"))})
    contents = {}
    digits = max(2, len(str(total)))
    for number, (_, fig) in enumerate(pages, start=1):
        say(f"{term('page', lang)} {number}/{total}")
        target = path.with_name(f"{path.stem}-{number:0{digits}d}{path.suffix}")
        if suffix == ".png":
            from .drawing.formats import render_png

            contents[target] = render_png(fig)
        else:
            contents[target] = render_svg(fig)
    return replace_all(contents)


def _check_solvable(scene: Scene) -> None:
    """A one-position handout of a position that cannot be solved is an error, with the solver's message."""
    from .analytic import solve

    solve(scene)
