"""Pages of a multi-position run and of a handout: A4 sheets, PDF and SVG output.

* :func:`write_position_sheets` — ``plans draw --positions``: one sheet per
  position (:func:`plans.drawing.draw_sheet`, titled with the position) and
  the plan of positions, all at the run's common scale factors.
* :func:`draw_position_page` — the two A4 portrait graphical pages of a
  position: the mechanism and the velocity plan on one, the acceleration plan
  on the other, each true to scale with its legend and vector equations;
* :func:`draw_check_pages` — the results table and the complex-number loop
  equations with their numbers.
* :func:`draw_cover_page` — the first page of a multi-position handout: the
  data and the plan of positions.
* :func:`plans.drawing.formats.render_pdf` — figures as the pages of one PDF: TrueType (Type 42)
  DejaVu Sans embedded, which has the Cyrillic glyphs; no creation date, so
  the same pages give the same bytes.
* :func:`plans.drawing.formats.save_figure` — one figure to ``.svg``, ``.pdf`` or ``.png``, atomically.
"""

from __future__ import annotations

from pathlib import Path


from .._files import replace_all
from .._text import decimal_comma, user_text
from ..i18n import term
from ._canvas import Sketch, fit_axes
from .blocks import Block, drawing_block, legend_block, pretty_equation, readings_block, rows_block, table_block, text_rows
from .layout import A4, GAP, PAGE_MARGIN, Frame, header, header_height, new_page, place_in_box, position_frames
from .sheet import branch_lines, draw_sheet, sheet_equations
from .style import HEADING_PT, MARGIN_MM, SMALL_PT
from .svg import drawing_rc
from .layout import DATA_PT
from .layout import footer as page_footer
from .typeset import draw_text, measure

__all__ = [
    "write_position_sheets",
    "draw_position_sheet",
    "position_title",
    "draw_position_page",
    "POSITION_PAGES",
    "position_page_bands",
    "position_page_frames",
    "draw_check_pages",
    "draw_cover_page",
    "draw_unsolved_page",
]

TEXT_PT = 8.0  # equations on a handout page (their exponents ≥ 6 pt, see plans.drawing.typeset)
LINE_GAP = 0.7  # mm between the lines of a text block on a page
#: a drawing may run this far [mm] past its box (into the gap between boxes) before it is drawn again smaller
BOX_TOLERANCE = 2.5
#: text size [pt] of the readings tables on a check page
READINGS_PAGE_PT = 7.0
#: text sizes [pt] tried on a check page, largest first: the largest with which the table and the loop equations
#: share one page (a short chain of groups gets larger type rather than an empty half page)
CHECK_PT = (9.5, 9.0, 8.5, 8.0, 7.6, 7.2, 6.8)

#: rcParams of PDF output: TrueType fonts embedded (DejaVu Sans covers Cyrillic and Greek).
# --- plans draw --positions -----------------------------------------------------------


def position_title(run, total: int, lang: str = "en") -> str:
    """The title of a position's sheet: the scene's title, the position's number and its driver position."""
    return f"{user_text(run.scene.title)} — {term('position', lang)} {run.index} ({run.index + 1}/{total}): {run.label}"


def draw_position_sheet(run, *, lang: str = "en", total: int | None = None):
    """The one-page sheet of a position (see :func:`plans.drawing.draw_sheet`), titled with the position."""
    from ..report import sheet_table

    return draw_sheet(
        run.graphical,
        formula=run.analytic.structure.formula,
        table=sheet_table(run.comparisons, run.graphical, run.analytic),
        lang=lang,
        title=position_title(run, total or run.index + 1, lang),
        branches=branch_lines(run.analytic.branches, lang),
    )


def write_position_sheets(positions_run, directory, *, lang: str = "en", format: str = "svg", sheets=None, progress=None) -> list[Path]:
    """Write ``sheet-00.svg``, ``sheet-01.svg``, … and ``positions.svg`` (the plan of positions).

    Each sheet is the one *sheets* gives (``plans draw --positions`` draws
    every sheet at the factors that fill it), else drawn here at the run's
    common scale factors.  A position that cannot
    be solved gets no sheet (it is left out, and the plan of positions does
    not draw it).  All files are written together, atomically; sheets of an
    earlier run with more positions that plans wrote (and nobody changed
    since) are removed; other files in *directory* are never touched.

    Parameters
    ----------
    positions_run : plans.positions.PositionsRun
    directory : str or pathlib.Path
    lang : str
    sheets : callable, optional
        ``sheets(run)`` -> the sheet of that position, called for each solved
        position in turn (``plans draw --positions`` draws each at the factors
        that fill it); by default each is drawn here at the run's common factors.
    progress : callable, optional
        Called with ``"sheet 3/13"`` as each file is made (the plan of positions last).

    Returns
    -------
    list of pathlib.Path
        The sheets in position order, then ``positions.svg``.
    """
    from .positions_plan import draw_positions_plan

    from .formats import render

    directory = Path(directory)
    total = len(positions_run.runs)
    width = max(2, len(str(total - 1)))
    contents: dict[Path, bytes] = {}
    say = progress or (lambda text: None)
    files = sum(1 for run in positions_run.runs if run.ok) + 1
    for run in positions_run.runs:
        if not run.ok:
            continue
        say(f"sheet {len(contents) + 1}/{files}")
        fig = sheets(run) if sheets is not None else draw_position_sheet(run, lang=lang, total=total)
        contents[directory / f"sheet-{run.index:0{width}d}.{format}"] = render(fig, format)
    say(f"sheet {files}/{files}")
    contents[directory / f"positions.{format}"] = render(draw_positions_plan(positions_run, lang=lang)[0].figure, format)
    if format != "svg":  # the record of what plans wrote is an SVG comment: other formats remove nothing
        return replace_all(contents)
    # sheets of an earlier run with more positions go if plans wrote them (positions.svg records them)
    return replace_all(contents, stale=(directory, r"sheet-\d+\.svg", "positions.svg"))


# --- handout pages ------------------------------------------------------------------------


#: the pages of a position's drawings: page -> the drawings on it
POSITION_PAGES = {"velocity": ("mechanism", "velocity"), "acceleration": ("acceleration",)}


def position_page_bands(graphical, *, lang: str = "en", header_lines=(), equations=None, size=A4) -> dict[str, tuple[float, float]]:
    """Page (``"velocity"``, ``"acceleration"``) -> (top, bottom) [mm] of the room it leaves for its drawings.

    Under the header (*header_lines*: a list, or a callable given the page),
    above the page's legend and vector equations (*equations*: page -> lines)
    in a band at its foot; on a page of *size* [mm].
    """
    width = size[0] - 2 * PAGE_MARGIN
    out = {}
    for page in POSITION_PAGES:
        if page == "acceleration" and graphical.acceleration_plan is None:
            continue
        lines = header_lines(page) if callable(header_lines) else header_lines
        with drawing_rc():
            legend, eq_block = _page_text(graphical, None if equations is None else equations[page], lang, width, page)
        top = size[1] - header_height(list(lines))
        bottom = FOOT + eq_block.height + GAP + legend.height + GAP
        out[page] = (top, bottom)
    return out


#: where the blocks of a page end [mm from the foot]: above the footer and page number
FOOT = PAGE_MARGIN + 4.0
#: the widths [fraction of the page's width] tried for a column of legend and equations beside the velocity plan
TEXT_COLUMNS = (0.3, 0.36, 0.42, 0.5)
#: the shares [fraction of the room's height] tried for the mechanism above the velocity plan
MECHANISM_SHARES = (0.45, 0.5, 0.55, 0.6, 0.65, 0.7)
#: the shares [fraction of the page's width] tried for the mechanism beside the velocity plan
MECHANISM_COLUMNS = (0.45, 0.5, 0.55, 0.6, 0.65)


def position_page_frames(graphical, *, lang: str = "en", header_lines=(), equations=None) -> list[Frame]:
    """The arrangements of a position's pages to choose from (:class:`plans.drawing.layout.Frame`).

    Those of :func:`plans.drawing.layout.position_frames` (the legend and the
    equations in a band at the foot of the page), and on the velocity page:

    * ``top-S-text-C``: the mechanism across the page (S % of the room's
      height), under it the velocity plan and, beside it on the right, a
      column (C % of the width) of the legend and the equations;
    * ``left-S-text``: the mechanism in a column on the left (S % of the
      width); on the right the velocity plan over the legend and equations.

    Every drawing and text box lies between the header and the foot of the
    page; the text columns are measured, so they hold their text.
    """
    bands = position_page_bands(graphical, lang=lang, header_lines=header_lines, equations=equations)
    frames = position_frames(bands)
    x0 = PAGE_MARGIN
    width = A4[0] - 2 * PAGE_MARGIN
    top = bands["velocity"][0]
    room = top - FOOT
    lines = None if equations is None else equations["velocity"]
    extra = {"acceleration": frames[0].boxes["acceleration"]} if "acceleration" in frames[0].boxes else {}
    pages = frames[0].pages
    with drawing_rc():
        heights = {}
        for cw in [round(width * c, 3) for c in TEXT_COLUMNS] + [round(width * (1.0 - s) - GAP, 3) for s in MECHANISM_COLUMNS]:
            legend, eq_block = _page_text(graphical, lines, lang, cw, "velocity")
            heights[cw] = (max(legend.width, eq_block.width), legend.height + GAP + eq_block.height)
    for share in MECHANISM_SHARES:
        hm = room * share
        below = room - hm - GAP
        for c in TEXT_COLUMNS:
            cw = round(width * c, 3)
            tw, th = heights[cw]
            if th > below or tw > cw + 0.5:
                continue
            boxes = {"mechanism": (x0, top - hm, width, hm), "velocity": (x0, FOOT, width - cw - GAP, below), **extra}
            text = {"velocity": (x0 + width - cw, FOOT, cw, below)}
            frames.append(Frame(f"top-{round(share * 100)}-text-{round(c * 100)}", boxes, pages, text))
    for share in MECHANISM_COLUMNS:
        wm = width * share
        cw = round(width * (1.0 - share) - GAP, 3)
        tw, th = heights[cw]
        if tw > cw + 0.5 or room - th - GAP < 40.0:
            continue
        boxes = {"mechanism": (x0, FOOT, wm, room), "velocity": (x0 + wm + GAP, FOOT + th + GAP, cw, room - th - GAP), **extra}
        text = {"velocity": (x0 + wm + GAP, FOOT, cw, th)}
        frames.append(Frame(f"left-{round(share * 100)}-text", boxes, pages, text))
    frames.extend(_landscape_frames(graphical, lang, header_lines, equations, extra))
    if graphical.acceleration_plan is not None:
        frames.extend(_apart_frames(graphical, lang, header_lines, equations))
    return frames


#: the shares [fraction of the room's height] tried for the velocity plan above the acceleration plan on one page
PLANS_SHARES = (0.4, 0.45, 0.5, 0.55, 0.6)


def _apart_frames(graphical, lang, header_lines, equations) -> list[Frame]:
    """``apart-P-S``, ``apart-L-S``: the mechanism on the first page (A4 portrait P or landscape L) over the
    vector equations of both plans; both plans on the second, the velocity plan over the acceleration plan
    (S % of the room), their legend at the foot: for a mechanism too wide to share a page with a plan."""
    x0 = PAGE_MARGIN
    width = A4[0] - 2 * PAGE_MARGIN
    both = ("velocity", "acceleration")
    lines = None if equations is None else [line for kind in both for line in equations[kind]]
    with drawing_rc():
        legend = _page_text(graphical, None, lang, width, both)[0]
    head = list(header_lines("acceleration") if callable(header_lines) else header_lines)
    top = A4[1] - header_height(head)
    bottom = FOOT + legend.height + GAP
    room = top - bottom
    pages = {"mechanism": "velocity", "velocity": "acceleration", "acceleration": "acceleration"}
    frames = []
    for name, size in (("P", A4), ("L", LANDSCAPE)):
        with drawing_rc():
            eq_block = _equations_block(graphical, lines, lang, size[0] - 2 * PAGE_MARGIN, both)
        first = list(header_lines("velocity") if callable(header_lines) else header_lines)
        m_top = size[1] - header_height(first)
        m_bottom = FOOT + eq_block.height + GAP
        mechanism = (x0, m_bottom, size[0] - 2 * PAGE_MARGIN, m_top - m_bottom)
        for share in PLANS_SHARES:
            hv = room * share
            boxes = {"mechanism": mechanism, "velocity": (x0, top - hv, width, hv), "acceleration": (x0, bottom, width, room - hv - GAP)}
            frames.append(Frame(f"apart-{name}-{round(share * 100)}", boxes, pages, None, {"velocity": size}, {"velocity": both, "acceleration": ()}))
    return frames


#: the velocity page of a position turned (A4 landscape): for mechanisms too wide for a portrait page beside their plan
LANDSCAPE = (A4[1], A4[0])
#: the shares [fraction of the width] tried for the mechanism on a landscape velocity page
LANDSCAPE_COLUMNS = (0.35, 0.4, 0.45, 0.5, 0.55, 0.6, 0.65, 0.7)


def _landscape_frames(graphical, lang, header_lines, equations, extra) -> list[Frame]:
    """``land-S-text`` and ``land-S``: the velocity page A4 landscape, the mechanism in a column on the left
    (S % of the width); on the right the velocity plan over its legend and equations (``-text``), or the
    legend and equations in a band at the foot of the page."""
    size = LANDSCAPE
    bands = position_page_bands(graphical, lang=lang, header_lines=header_lines, equations=equations, size=size)
    top, bottom = bands["velocity"]
    x0 = PAGE_MARGIN
    width = size[0] - 2 * PAGE_MARGIN
    room = top - FOOT
    lines = None if equations is None else equations["velocity"]
    pages = {"mechanism": "velocity", "velocity": "velocity", "acceleration": "acceleration"}
    sizes = {"velocity": size}
    frames = []
    for share in LANDSCAPE_COLUMNS:
        wm = width * share
        cw = width - wm - GAP
        with drawing_rc():
            legend, eq_block = _page_text(graphical, lines, lang, cw, "velocity")
        tw, th = max(legend.width, eq_block.width), legend.height + GAP + eq_block.height
        if tw <= cw + 0.5 and room - th - GAP >= 40.0:
            boxes = {"mechanism": (x0, FOOT, wm, room), "velocity": (x0 + wm + GAP, FOOT + th + GAP, cw, room - th - GAP), **extra}
            frames.append(Frame(f"land-{round(share * 100)}-text", boxes, pages, {"velocity": (x0 + wm + GAP, FOOT, cw, th)}, sizes))
        boxes = {"mechanism": (x0, bottom, wm, top - bottom), "velocity": (x0 + wm + GAP, bottom, cw, top - bottom), **extra}
        frames.append(Frame(f"land-{round(share * 100)}", boxes, pages, None, sizes))
    return frames


def _page_text(g, equations, lang: str, width: float, plans) -> tuple[Block, Block]:
    """The legend of *plans* (a kind or a tuple of kinds; two columns when they fit *width* [mm], else one) and
    the vector equations (*equations*, by default those of *plans*) broken to *width*."""
    plans = (plans,) if isinstance(plans, str) else tuple(plans)
    legend = legend_block(g, lang, columns=2, plans=plans)
    if legend.width > width:
        legend = legend_block(g, lang, columns=1, plans=plans)
    return legend, _equations_block(g, equations, lang, width, plans)


def draw_position_page(
    run,
    *,
    frame,
    page: str = "velocity",
    lang: str = "en",
    header_lines=(),
    title: str | None = None,
    equations: list[str] | None = None,
    footer: str = "",
    rescale=None,
):
    """A graphical page of a position, A4: returns (Figure, the GraphicalSolution drawn).

    *page* ``"velocity"`` (the first page) and ``"acceleration"`` (the second)
    hold the drawings *frame* puts on them: as a rule the mechanism and the
    velocity plan, then the acceleration plan alone; the page is the
    frame's size for it (portrait, or landscape).  The title
    and data at the top; the drawings true to scale, each at the top of its
    box of *frame* (a :class:`plans.drawing.layout.Frame`, the same on every
    position of a handout); the legend of the page's plan and the vector
    equations its construction solved, at the foot.

    Parameters
    ----------
    run : plans.positions.PositionRun
        A solved position (``run.ok``).
    header_lines : list of str, or callable
        Data lines under the title (``$…$`` typeset; a leading ``§`` makes
        one bold); a callable is given the solution drawn (its scale factors
        are those the page states).
    equations : list of str, or dict, optional
        Vector equations of the page's plans (a dict: plan kind -> its
        equations), by default from their steps.
    rescale : callable, optional
        ``rescale(solution, kind, (width, height))`` is called when a drawing
        (kind ``"mechanism"``, ``"velocity"``, ``"acceleration"``) runs out
        of its box; it returns the solution at another scale factor to draw
        again (at most twice), or None to keep the drawing.
    """
    g = run.graphical
    size = frame.size(page)
    width = size[0] - 2 * PAGE_MARGIN
    objects = {"mechanism": lambda s: s, "velocity": lambda s: s.velocity_plan, "acceleration": lambda s: s.acceleration_plan}
    with drawing_rc():
        fig, sketch = new_page(size)
        for kind, box in frame.on(page).items():
            if objects[kind](g) is None:
                continue
            detail = kind != "mechanism"  # crowded images of a plan enlarged in a detail, when the box has room for it
            for attempt in range(3):
                block = drawing_block(fig, kind, objects[kind](g), lang, legend=False, detail=detail)
                inside = block.width <= box[2] + BOX_TOLERANCE and block.height <= box[3] + BOX_TOLERANCE
                if not inside and detail and _has_detail(block):  # no room for the detail: the plan without it
                    block.axes.remove()
                    detail = False
                    block = drawing_block(fig, kind, objects[kind](g), lang, legend=False, detail=False)
                    inside = block.width <= box[2] + BOX_TOLERANCE and block.height <= box[3] + BOX_TOLERANCE
                other = None if inside or rescale is None or attempt == 2 else rescale(g, kind, (block.width, block.height))
                if other is None:
                    break
                block.axes.remove()
                g = other
            place_in_box(block, sketch, box, size)
        lines = header_lines(g) if callable(header_lines) else header_lines
        header(sketch, size, title or run.scene.title, [decimal_comma(line, lang) for line in lines])
        shown = tuple(kind for kind in ("velocity", "acceleration") if kind in frame.on(page) and objects[kind](g) is not None)
        solved = tuple(kind for kind in frame.equations_on(page) if objects[kind](g) is not None)
        if isinstance(equations, dict):
            equations = [line for kind in solved for line in equations.get(kind, ())]
        tx, ty, tw, _ = frame.text.get(page, (PAGE_MARGIN, FOOT, width, 0.0))
        # in a column or a band, down to the foot of the page: the equations at the foot, the legend of the plans drawn above them
        y = ty
        if solved:
            eq_block = _equations_block(g, equations, lang, tw, solved)
            eq_block.place(sketch, tx, y, size)
            y += eq_block.height + GAP
        if shown:
            _page_text(g, None, lang, tw, shown)[0].place(sketch, tx, y, size)
        page_footer(sketch, footer)
    return fig, g


def _has_detail(block: Block) -> bool:
    """Whether a plan's drawing has an enlarged detail of crowded images (its circle, gid ``detail``)."""
    return any((artist.get_gid() or "").endswith("-detail") for artist in block.axes.get_children())


def _equations_block(g, equations, lang: str, width: float, plans: tuple) -> Block:
    lines = [pretty_equation(line) for line in (sheet_equations(g, plans=plans) if equations is None else equations)]
    return rows_block(text_rows(term("vector_equations", lang), lines, width, TEXT_PT), "equation", line_gap=LINE_GAP)


def draw_check_pages(
    run,
    *,
    lang: str = "en",
    header_lines: list[str] = (),
    title: str | None = None,
    loops: list | None = None,
    table: list[list[str]] | None = None,
    footer: str = "",
) -> list:
    """The analytic pages of a position, A4 portrait: the results table with the readings of both plans
    beside it (or above it when the page is too narrow), then the loop equations.

    The readings (:func:`plans.drawing.blocks.readings_block`) say what is
    measured on each plan of the position page before and what it gives: the
    graphical column of the results table, recomputable from them.

    Usually one page; the equations of a long chain of groups continue on
    further pages (never a group's heading alone at the foot of a page).

    Parameters
    ----------
    run : plans.positions.PositionRun
    loops : list of plans.loops.LoopBlock
        The complex-number equations with their numbers.
    table : list of list of str
        Graphical against analytic values, first row the header.

    Returns
    -------
    list of matplotlib.figure.Figure
    """
    size = A4
    width = size[0] - 2 * PAGE_MARGIN
    heading = term("loop_equations", lang)
    loop_lines = []
    for block in loops or ():
        if not block.lines:
            continue
        loop_lines.append("§" + block.title)
        loop_lines.extend(decimal_comma(line, lang) for line in block.lines)
    cells = [[decimal_comma(cell, lang) for cell in row] for row in table] if table else None
    with drawing_rc():
        readings = readings_block(run.graphical, lang, size=READINGS_PAGE_PT, width=width) if run.graphical is not None else None
        # the two readings tables one above the other, to stand beside the results table when the page is wide enough
        stacked = readings_block(run.graphical, lang, size=READINGS_PAGE_PT, width=0.0) if run.graphical is not None else None

        def top_blocks(pt: float):
            """The results table at *pt*, whether the stacked readings stand beside it, and the height both take."""
            table_ = table_block(cells, term("results", lang), size=pt) if cells else None
            beside = table_ is not None and stacked is not None and table_.width + GAP + stacked.width <= width
            if beside:
                return table_, True, max(table_.height, stacked.height) + GAP
            return table_, False, (table_.height + GAP if table_ else 0.0) + (readings.height + GAP if readings is not None else 0.0)

        # the largest text that puts everything on one page, down to CHECK_PT[-1]; else continued pages at TEXT_PT
        rows = text_rows(heading, loop_lines, width, TEXT_PT) if loop_lines else []
        room = size[1] - header_height([decimal_comma(line, lang) for line in header_lines]) - (PAGE_MARGIN + 4.0)
        for pt in CHECK_PT:
            trial = text_rows(heading, loop_lines, width, pt) if loop_lines else []
            if _rows_that_fit(trial, room - top_blocks(pt - 0.4)[2]) == len(trial):
                rows, table_pt = trial, pt - 0.4
                break
        else:
            table_pt = SMALL_PT + 0.3
        figures = []
        first = True
        while first or rows:
            fig, sketch = new_page(size)
            top = header(sketch, size, title or run.scene.title, [decimal_comma(line, lang) for line in header_lines])
            bottom = PAGE_MARGIN + 4.0
            if first:
                block, beside, used = top_blocks(table_pt)
                if beside:  # the results table, and beside it the readings that recompute its graphical column
                    block.place(sketch, PAGE_MARGIN, top - block.height, size)
                    stacked.place(sketch, PAGE_MARGIN + block.width + GAP, top - stacked.height, size)
                else:
                    if readings is not None:
                        readings.place(sketch, PAGE_MARGIN, top - readings.height, size)
                        top -= readings.height + GAP
                    if block is not None:
                        block.place(sketch, PAGE_MARGIN, top - block.height, size)
                        top -= block.height + GAP
                    used = 0.0
                top -= used
            if rows:
                take = _rows_that_fit(rows, top - bottom)
                if first and take < len(rows) and all(row[2] == "bold" for row in rows[:take]):
                    take = 0  # headings alone at the foot of the first page: they begin the next page
                if take:
                    block = rows_block(rows[:take], "loop", line_gap=LINE_GAP)
                    block.place(sketch, PAGE_MARGIN, top - block.height, size)
                    rest = rows[take:]
                    rows = [(f"{heading} {term('continued', lang)}", HEADING_PT, "bold")] + rest if rest else []
            page_footer(sketch, footer)
            figures.append(fig)
            first = False
    return figures


def _rows_that_fit(rows, room: float) -> int:
    """How many of *rows* go on a page with *room* [mm]: all that fit, but a group's lines kept together.

    A page ends before a bold row (a group's heading) when the group that
    follows would not fit whole; a group longer than a page is cut where the
    page ends.  Never fewer than one row.
    """
    heights = [measure(t, s, w)[1] + LINE_GAP for t, s, w in rows]
    take, used = 0, 0.0
    while take < len(rows) and used + heights[take] <= room:
        used += heights[take]
        take += 1
    if take == len(rows):
        return take
    # the last heading among the rows taken, after the first row: end the page before it
    starts = [k for k in range(1, take) if rows[k][2] == "bold"]
    if starts:
        return starts[-1]
    return max(take, 1)


def draw_cover_page(
    positions_run,
    *,
    lang: str = "en",
    header_lines: list[str] = (),
    positions_lines: list[str] = (),
    footer: str = "",
    k_l: float | None = None,
):
    """The first page of a multi-position handout: data, the plan of positions and the list of positions."""
    from .positions_plan import draw_positions_into

    size = A4
    with drawing_rc():
        fig, sketch = new_page(size)
        top = header(sketch, size, positions_run.scene.title, [decimal_comma(line, lang) for line in header_lines])
        positions_lines = [decimal_comma(line, lang) for line in positions_lines]
        ax = fig.add_axes([0, 0, 0.01, 0.01])
        plan_sketch = Sketch(ax, "positions")
        draw_positions_into(plan_sketch, positions_run, lang=lang, k_l=k_l)
        bounds = plan_sketch.bounds
        w, h = bounds.width + 2 * MARGIN_MM, bounds.height + 2 * MARGIN_MM
        x = max(PAGE_MARGIN, (size[0] - w) / 2)
        fit_axes(ax, bounds, MARGIN_MM, rect_mm=(x, top - h), page_mm=size)
        y = top - h - GAP
        if positions_lines:
            h = measure("lp", HEADING_PT, "bold")[1]
            draw_text(sketch, complex(PAGE_MARGIN, y - h / 2), term("positions_list", lang), size=HEADING_PT, weight="bold", gid="positions-heading")
            y -= h + 1.5
            # the entries in columns, column by column, aligned
            column_w = max(measure(e, DATA_PT)[0] for e in positions_lines) + 8.0
            columns = max(1, min(4, int((size[0] - 2 * PAGE_MARGIN) // column_w)))
            per = -(-len(positions_lines) // columns)
            row_h = measure("lp", DATA_PT)[1] + 1.0
            for k, entry in enumerate(positions_lines):
                c, r = divmod(k, per)
                draw_text(sketch, complex(PAGE_MARGIN + c * column_w, y - (r + 0.5) * row_h), entry, size=DATA_PT, gid="positions-entry")
        page_footer(sketch, footer)
    return fig


def draw_unsolved_page(run, *, lang: str, where: str, message: str, footer: str = ""):
    """The page of a position that cannot be solved: the position and why, in words."""
    with drawing_rc():
        fig, sketch = new_page(A4)
        top = header(sketch, A4, run.scene.title, ["§" + decimal_comma(where, lang)])
        rows = text_rows(term("not_solved", lang), [decimal_comma(message, lang)], A4[0] - 2 * PAGE_MARGIN, DATA_PT + 0.5)
        block = rows_block(rows, "unsolved", line_gap=LINE_GAP)
        block.place(sketch, PAGE_MARGIN, top - block.height, A4)
        page_footer(sketch, footer)
    return fig


