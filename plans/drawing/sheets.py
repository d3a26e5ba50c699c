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
from ._canvas import Sketch, fit_axes, fmt_number
from .blocks import Block, drawing_block, legend_block, pretty_equation, readings_block, rows_block, table_block, text_rows
from .layout import A4, GAP, PAGE_MARGIN, header, header_height, new_page, place_in_box
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
    "draw_check_pages",
    "draw_cover_page",
    "draw_unsolved_page",
    "scale_line",
]

TEXT_PT = 8.0  # equations on a handout page (their exponents ≥ 6 pt, see plans.drawing.typeset)
LINE_GAP = 0.7  # mm between the lines of a text block on a page
#: a drawing may run this far [mm] past its box (into the gap between boxes) before it is drawn again smaller
BOX_TOLERANCE = 2.5
#: text size [pt] of the readings tables on a check page
READINGS_PAGE_PT = 7.0
#: text sizes [pt] tried on a check page, largest first, so that the table and the loop equations share one page
CHECK_PT = (8.0, 7.6, 7.2, 6.8)

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


def write_position_sheets(positions_run, directory, *, lang: str = "en", format: str = "svg", sheets=None) -> list[Path]:
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
    for run in positions_run.runs:
        if not run.ok:
            continue
        fig = sheets(run) if sheets is not None else draw_position_sheet(run, lang=lang, total=total)
        contents[directory / f"sheet-{run.index:0{width}d}.{format}"] = render(fig, format)
    contents[directory / f"positions.{format}"] = render(draw_positions_plan(positions_run, lang=lang)[0].figure, format)
    if format != "svg":  # the record of what plans wrote is an SVG comment: other formats remove nothing
        return replace_all(contents)
    # sheets of an earlier run with more positions go if plans wrote them (positions.svg records them)
    return replace_all(contents, stale=(directory, r"sheet-\d+\.svg", "positions.svg"))


# --- handout pages ------------------------------------------------------------------------


#: the pages of a position's drawings: page -> the drawings on it
POSITION_PAGES = {"velocity": ("mechanism", "velocity"), "acceleration": ("acceleration",)}


def position_page_bands(graphical, *, lang: str = "en", header_lines=(), equations=None) -> dict[str, tuple[float, float]]:
    """Page (``"velocity"``, ``"acceleration"``) -> (top, bottom) [mm] of the room it leaves for its drawings.

    Under the header (*header_lines*: a list, or a callable given the page),
    above the page's legend and vector equations (*equations*: page -> lines).
    """
    width = A4[0] - 2 * PAGE_MARGIN
    out = {}
    for page in POSITION_PAGES:
        if page == "acceleration" and graphical.acceleration_plan is None:
            continue
        lines = header_lines(page) if callable(header_lines) else header_lines
        with drawing_rc():
            legend = legend_block(graphical, lang, columns=2, plans=(page,))
            eq_block = _equations_block(graphical, None if equations is None else equations[page], lang, width, page)
        top = A4[1] - header_height(list(lines))
        bottom = PAGE_MARGIN + 4.0 + eq_block.height + GAP + legend.height + GAP
        out[page] = (top, bottom)
    return out


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
    """A graphical page of a position, A4 portrait: returns (Figure, the GraphicalSolution drawn).

    *page* ``"velocity"``: the mechanism and the velocity plan;
    ``"acceleration"``: the acceleration plan, alone on its page.  The title
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
    equations : list of str, optional
        Vector equations of the page's plan, by default from its steps.
    rescale : callable, optional
        ``rescale(solution, kind, (width, height))`` is called when a drawing
        (kind ``"mechanism"``, ``"velocity"``, ``"acceleration"``) runs out
        of its box; it returns the solution at another scale factor to draw
        again (at most twice), or None to keep the drawing.
    """
    g = run.graphical
    size = A4
    width = size[0] - 2 * PAGE_MARGIN
    objects = {"mechanism": lambda s: s, "velocity": lambda s: s.velocity_plan, "acceleration": lambda s: s.acceleration_plan}
    with drawing_rc():
        fig, sketch = new_page(size)
        for kind, box in frame.on(page).items():
            if objects[kind](g) is None:
                continue
            for attempt in range(3):
                block = drawing_block(fig, kind, objects[kind](g), lang, legend=False)
                inside = block.width <= box[2] + BOX_TOLERANCE and block.height <= box[3] + BOX_TOLERANCE
                other = None if inside or rescale is None or attempt == 2 else rescale(g, kind, (block.width, block.height))
                if other is None:
                    break
                block.axes.remove()
                g = other
            place_in_box(block, sketch, box, size)
        lines = header_lines(g) if callable(header_lines) else header_lines
        header(sketch, size, title or run.scene.title, [decimal_comma(line, lang) for line in lines])
        eq_block = _equations_block(g, equations, lang, width, page)
        legend = legend_block(g, lang, columns=2, plans=(page,))
        y = PAGE_MARGIN + 4.0
        eq_block.place(sketch, PAGE_MARGIN, y, size)
        y += eq_block.height + GAP
        legend.place(sketch, PAGE_MARGIN, y, size)
        page_footer(sketch, footer)
    return fig, g


def _equations_block(g, equations, lang: str, width: float, page: str) -> Block:
    lines = [pretty_equation(line) for line in (sheet_equations(g, plans=(page,)) if equations is None else equations)]
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

        # the smallest text that puts everything on one page, down to CHECK_MIN_PT; else continued pages at TEXT_PT
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


def scale_line(scales: dict, lang: str) -> str:
    """``"Scale factors:  $k_l$ = 0.01 m/mm,  $k_v$ = 0.02 (m/s)/mm,  $k_a$ = 0.25 (m/s²)/mm"`` (symbols typeset)."""
    units = {"k_l": "m/mm", "k_v": "(m/s)/mm", "k_a": "(m/s²)/mm"}
    parts = [f"${key}$ = {fmt_number(value)} {units[key]}" for key, value in scales.items() if key in units]
    return f"{term('scale_factors', lang)}:  " + ",  ".join(parts)
