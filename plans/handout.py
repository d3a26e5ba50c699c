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
  position, and the kinematic diagrams over the cycle.

Every position uses the same scale factors, chosen (unless given) as the
round values that fit the largest mechanism drawing and plan of all the
positions into their place on an A4 page.

>>> import plans
>>> from plans.handout import handout_pages
>>> scene = plans.load(plans.example_path("four-bar"))
>>> [name for name, _ in handout_pages(scene)]                       # doctest: +SKIP
['position-0', 'check-0']
"""

from __future__ import annotations

import math
from pathlib import Path

from ._text import subscript
from .errors import PlansError
from .i18n import check_language, term
from .scene import FRAME, Crank, Scene

__all__ = ["HandoutError", "write_handout", "handout_pages", "scene_data_lines", "handout_scales", "BOXES_MM"]

#: Where the drawings go on a page [mm], per layout of the page: the largest
#: mechanism (width, height) and plans.  Candidate scale factors are made from
#: these boxes, enlarged and shrunk; the first (largest drawings) whose pages
#: fit is kept.
BOXES_MM = {"k_l": (90.0, 80.0), "k_v": (80.0, 80.0), "k_a": (110.0, 80.0)}
LAYOUT_BOXES_MM = (
    BOXES_MM,
    {"k_l": (95.0, 190.0), "k_v": (85.0, 85.0), "k_a": (85.0, 85.0)},
    {"k_l": (70.0, 70.0), "k_v": (55.0, 70.0), "k_a": (55.0, 70.0)},
)
FACTORS = (1.5, 1.3, 1.15, 1.0, 0.85, 0.7, 0.55, 0.4, 0.3)


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
            f"{term('driver', lang)} {link} ({driver.point}, frame.{driver.guide}):  v = {_fmt(driver.velocity)} m/s,  "
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


def _table(comparisons, lang: str) -> list[list[str]]:
    from .report import sheet_table
    from .drawing.sheet import translate_table

    return translate_table(sheet_table(comparisons), lang)


def _equations(graphical, structure) -> list[str]:
    from .drawing.sheet import sheet_equations

    return sheet_equations(graphical, driver_label=f"I(0,{structure.driver})")


# --- scales ------------------------------------------------------------------------------


def _bbox(points) -> tuple[float, float]:
    zs = list(points)
    if not zs:
        return 0.0, 0.0
    xs = [z.real for z in zs]
    ys = [z.imag for z in zs]
    return max(xs) - min(xs), max(ys) - min(ys)


def handout_scales(positions_run, boxes: dict[str, tuple[float, float]] = BOXES_MM, given: dict | None = None) -> dict[str, float]:
    """Round scale factors that fit every position's mechanism and plans into their boxes on the page.

    For each kind, the smallest round factor (1, 2, 2.5, 5 × 10ⁿ) with which
    the largest width and the largest height over all the positions are drawn
    within the box (the geometry only; labels and captions take the page's
    remaining room).
    """
    from .graphical.scales import MANTISSAS

    given = {k: v for k, v in (given or {}).items() if v is not None}
    extents = {"k_l": [0.0, 0.0], "k_v": [0.0, 0.0], "k_a": [0.0, 0.0]}
    for run in positions_run.runs:
        if not run.ok:
            continue
        g = run.graphical
        w, h = _bbox(g.positions.values())
        extents["k_l"] = [max(extents["k_l"][0], w), max(extents["k_l"][1], h)]
        for key, plan in (("k_v", g.velocity_plan), ("k_a", g.acceleration_plan)):
            if plan is None:
                continue
            w, h = _bbox([z * plan.scale for z in plan.images.values()] + [0j])
            extents[key] = [max(extents[key][0], w), max(extents[key][1], h)]
    out = {}
    for key, current in positions_run.scales.items():
        if key in given:
            out[key] = given[key]
            continue
        bw, bh = boxes[key]
        need = max(extents[key][0] / bw, extents[key][1] / bh)
        if not (need > 0 and math.isfinite(need)):
            out[key] = current
            continue
        n = math.floor(math.log10(need)) - 1
        k = None
        while k is None:
            for m in MANTISSAS:
                value = float(f"{m}e{n}")
                if value >= need * (1 - 1e-12):
                    k = value
                    break
            n += 1
        out[key] = k
    return out


def _fit_scales(scene, positions, first, given: dict, precision, overrun, cache: dict):
    """The run at the largest round scale factors whose graphical pages fit on A4.

    Starts from the largest drawings the page boxes allow (enlarged by
    :data:`FACTORS` [0]) and, while the pages of the positions with the
    largest drawings do not fit, makes one scale factor one round step
    larger: that of the largest drawing among the steps that make the pages
    fit, else among those that win room.
    """
    from .positions import run_positions

    def solve_at(scales):
        return run_positions(
            scene, positions, k_l=scales["k_l"], k_v=scales["k_v"], k_a=scales.get("k_a"), precision=precision, check_scales=False
        )

    def excess(run) -> float:
        return max((overrun(r, run) for r in _worst(run)), default=0.0)

    candidates = [handout_scales(first, {k: (w * FACTORS[0], h * FACTORS[0]) for k, (w, h) in boxes.items()}, given) for boxes in LAYOUT_BOXES_MM]
    scales = {key: min(c[key] for c in candidates) for key in candidates[0]}
    free = [key for key in scales if given.get(key) is None]
    run = solve_at(scales)
    over = excess(run)
    for _ in range(24):
        if over <= 0.0 or not free:
            return run
        options = []
        for key in free:
            bumped = {**scales, key: _larger(scales[key])}
            trial = solve_at(bumped)
            after = excess(trial)
            # the largest drawing gives way first: among the bumps that make the page
            # fit, else among those that win room at all
            kind = {"k_l": "mechanism", "k_v": "velocity", "k_a": "acceleration"}[key]
            area = max((w * h for (_, k, s, _), (w, h) in cache.items() if k == kind and s == float(scales[key])), default=0.0)
            rank = (0 if after <= 0.0 else 1 if after < over - 1e-9 else 2, -area)
            options.append((rank, key, bumped, trial, after))
        options.sort(key=lambda o: o[0])
        _, _, scales, run, over = options[0]
    return run


def _candidates(run, given: dict) -> list[dict]:
    """Scale factor sets to try, the largest drawings first."""
    seen = {}
    for boxes in LAYOUT_BOXES_MM:
        for f in FACTORS:
            scaled = {key: (w * f, h * f) for key, (w, h) in boxes.items()}
            scales = handout_scales(run, scaled, given)
            key = tuple(sorted(scales.items()))
            seen.setdefault(key, scales)
    ordered = sorted(seen.values(), key=lambda s: sum(math.log10(v) for v in s.values()))
    return ordered + [{k: _larger(_larger(_larger(v))) if given.get(k) is None else v for k, v in ordered[-1].items()}]


def _worst(run) -> list:
    """The positions with the largest mechanism and plans: the ones whose pages must fit."""
    picks = []
    measures = {"mech": lambda g: _bbox(g.positions.values()),
                "vel": lambda g: _bbox([z for z in g.velocity_plan.images.values()] + [0j]),
                "acc": lambda g: _bbox([z for z in g.acceleration_plan.images.values()] + [0j]) if g.acceleration_plan else (0.0, 0.0)}
    solved = [r for r in run.runs if r.ok]
    for measure in measures.values():
        for axis in (0, 1):
            best = max(solved, key=lambda r: measure(r.graphical)[axis], default=None)
            if best is not None and best not in picks:
                picks.append(best)
    if solved:
        total = max(solved, key=lambda r: sum(sum(m(r.graphical)) for m in measures.values()))
        if total in picks:
            picks.remove(total)
        picks.insert(0, total)
    return picks


def _cover_scale(run, list_rows: int) -> float | None:
    """A round k_l that fits the plan of positions (every position and the paths) on the cover page."""
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
    from .graphical.scales import MANTISSAS

    n = math.floor(math.log10(need)) - 1
    while True:
        for m in MANTISSAS:
            value = float(f"{m}e{n}")
            if value >= need:
                return value
        n += 1


def _larger(k: float) -> float:
    """The next round scale factor above k."""
    from .graphical.scales import MANTISSAS

    n = math.floor(math.log10(k)) - 1
    while True:
        for m in MANTISSAS:
            value = float(f"{m}e{n}")
            if value > k * (1 + 1e-9):
                return value
        n += 1


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
) -> list[tuple[str, object]]:
    """The handout's pages as (name, matplotlib Figure) pairs, in order.

    Names: ``cover``, ``position-K`` and ``check-K`` for each position K,
    ``unsolved-K`` for a position that cannot be solved, ``diagram-links``,
    ``diagram-points``, ``diagram-sliders``.  Arguments as :func:`write_handout`.
    """
    from .drawing.diagrams import draw_cycle_diagrams
    from .drawing.sheets import draw_check_pages, draw_cover_page, draw_position_page, position_page_excess, scale_line, stamp_page_number
    from .loops import loop_equations
    from .positions import run_positions

    check_language(lang)
    given = {"k_l": k_l if k_l is not None else scene.scales.k_l,
             "k_v": k_v if k_v is not None else scene.scales.k_v,
             "k_a": k_a if k_a is not None else scene.scales.k_a}
    first = run_positions(scene, positions, k_l=given["k_l"], k_v=given["k_v"], k_a=given["k_a"], precision=precision)
    multi = positions is not None
    data = scene_data_lines(scene, lang)
    footer = f"plans — {scene.title}"
    formula = f"{term('structural_formula', lang)}:  {first.structure.formula}"

    def where(r) -> str:
        return f"{term('position', lang)} {r.index}:  {r.label}" if multi else r.label

    def head(r, run):
        return ["§" + where(r)] + data + ["§" + formula, scale_line(run.scales, lang)]

    def front(r, run, strict):
        return draw_position_page(r, lang=lang, header_lines=head(r, run), equations=_equations(r.graphical, run.structure), footer=footer, strict=strict)

    cache: dict = {}

    def overrun(r, run) -> float:
        return position_page_excess(r, lang=lang, header_lines=head(r, run), equations=_equations(r.graphical, run.structure), cache=cache)

    run = _fit_scales(scene, positions, first, given, precision, overrun, cache)

    solved = [r for r in run.runs if r.ok]
    pages: list[tuple[str, object]] = []
    if multi:
        listing = [f"{r.index}:  {r.label}" + ("" if r.ok else f"  ({term('not_solved', lang)}: {r.brief(lang)})") for r in run.runs]
        if solved:
            pages.append(("cover", draw_cover_page(run, lang=lang, header_lines=data + ["§" + formula, scale_line(run.scales, lang)], positions_lines=listing, footer=footer, k_l=_cover_scale(run, math.ceil(len(listing) / 3)))))
    for r in run.runs:
        if not r.ok:
            pages.append((f"unsolved-{r.index}", _unsolved_page(r, lang, where(r), str(r.error), footer)))
            continue
        pages.append((f"position-{r.index}", front(r, run, False)))
        check_head = ["§" + where(r), formula]
        checks = draw_check_pages(r, lang=lang, header_lines=check_head, loops=loop_equations(r.analytic), table=_table(r.comparisons, lang), footer=footer)
        for n, fig in enumerate(checks):
            pages.append((f"check-{r.index}" + (f"-{n + 1}" if n else ""), fig))

    if multi and solved:
        for name, fig in draw_cycle_diagrams(run.cycle, marked=run.positions, lang=lang, components=components):
            pages.append((f"diagram-{name}", fig))
    # page numbers
    total = len(pages)
    for number, (_, fig) in enumerate(pages, start=1):
        stamp_page_number(fig, number, total, lang)
    return pages


def _unsolved_page(run, lang: str, where: str, message: str, footer: str):
    from .drawing.sheets import A4, PAGE_MARGIN, _footer, _header, _page
    from .drawing.svg import drawing_rc

    with drawing_rc():
        fig, sketch = _page(A4)
        top = _header(sketch, A4, run.scene.title, ["§" + where])
        import textwrap

        for k, line in enumerate(textwrap.wrap(f"{term('not_solved', lang)}: {message}", 110)):
            sketch.text(complex(PAGE_MARGIN, top - 5 - 4.5 * k), line, size=8.5, ha="left", gid="unsolved", obstacle=False)
        _footer(sketch, footer)
    return fig


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
) -> list[Path]:
    """Write the handout of a scene: a PDF of A4 pages, or SVG pages.

    Parameters
    ----------
    scene : Scene
    path : str or pathlib.Path
        ``FILE.pdf``: every page in one file.  ``FILE.svg``: the first page
        to FILE.svg and each further page to ``FILE-2.svg``, ``FILE-3.svg``, …
        (a one-position handout has two pages).
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
        Drafting precision [mm] of the graphical readings.
    components : bool
        Cycle diagrams of the x and y components of every point's v and a too.

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
    from .drawing.sheets import render_pdf
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
    pages = handout_pages(scene, positions=positions, lang=lang, k_l=k_l, k_v=k_v, k_a=k_a, precision=precision, components=components)
    if suffix == ".pdf":
        return replace_all({path: render_pdf([fig for _, fig in pages])})
    contents = {}
    for number, (_, fig) in enumerate(pages, start=1):
        target = path if number == 1 else path.with_name(f"{path.stem}-{number}{path.suffix}")
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
