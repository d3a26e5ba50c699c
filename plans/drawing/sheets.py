"""Pages of a multi-position run and of a handout: A4 sheets, PDF and SVG output.

* :func:`write_position_sheets` — ``plans draw --positions``: one sheet per
  position (:func:`plans.drawing.draw_sheet`, titled with the position) and
  the plan of positions, all at the run's common scale factors.
* :func:`draw_position_page` — one A4 portrait handout page of a position:
  title, data, structural formula, the mechanism and both plans true to
  scale, one legend, the results table, the vector equations of the plans and
  the complex-number loop equations with their numbers.
* :func:`draw_cover_page` — the first page of a multi-position handout: the
  data and the plan of positions.
* :func:`render_pdf` — figures as the pages of one PDF: TrueType (Type 42)
  DejaVu Sans embedded, which has the Cyrillic glyphs; no creation date, so
  the same pages give the same bytes.
* :func:`save_figure` — one figure to ``.svg`` or ``.pdf``, atomically.
"""

from __future__ import annotations

import io
from pathlib import Path

import matplotlib
from matplotlib.backends.backend_pdf import PdfPages

from .._files import replace_all
from ..graphical.plan import KINDS
from ..i18n import term
from ._canvas import Sketch, fit_axes, fmt_number, text_size
from .plan_drawing import legend_row, legend_words, vectors_drawn
from .sheet import _Block, _drawing_block, _rows_block, _table_block, draw_sheet
from .style import CAPTION_PT, HEADING_PT, MARGIN_MM, SMALL_PT
from .svg import drawing_rc, new_figure, render_svg

__all__ = [
    "A4",
    "PAGE_MARGIN",
    "render_pdf",
    "save_figure",
    "write_position_sheets",
    "draw_position_sheet",
    "draw_position_page",
    "position_page_excess",
    "draw_check_pages",
    "draw_cover_page",
    "scale_line",
    "page_text_rows",
    "stamp_page_number",
    "PageOverflow",
]

A4 = (210.0, 297.0)  # mm, portrait
PAGE_MARGIN = 11.0  # mm
GAP = 5.0  # mm between blocks
TEXT_PT = 7.6  # equations on a handout page
DATA_PT = 8.0
FOOTER_PT = 7.0
FOOTER_COLOUR = "#555555"
PAGE_NUMBER_Y = 6.0  # mm above the foot of the page, the centre of the page number
PAGE_TITLE_PT = 13.5
LINE_GAP = 1.1  # mm between the lines of a text block on a page
MATH_LINE = 1.25  # a mathtext line is this much taller than a line of text

#: rcParams of PDF output: TrueType fonts embedded (DejaVu Sans covers Cyrillic and Greek).
PDF_RC = {"pdf.fonttype": 42, "pdf.compression": 6}


class PageOverflow(Exception):
    """The blocks of a page do not fit on it at the scale factors given: :func:`draw_position_page` with ``strict=True``.

    (The handout does not rely on it: it measures with :func:`position_page_excess`
    and enlarges the scale factors until the page fits.)
    """

    def __init__(self, excess: float):
        super().__init__(f"the page is {excess:.1f} mm too tall")
        self.excess = excess


# --- output -----------------------------------------------------------------------


def render_pdf(figures) -> bytes:
    """The figures as the pages of one PDF (in order), deterministic."""
    buffer = io.BytesIO()
    with drawing_rc(), matplotlib.rc_context(PDF_RC):
        with PdfPages(buffer, metadata={"CreationDate": None, "ModDate": None, "Creator": "plans", "Producer": "plans (matplotlib)"}) as pdf:
            for fig in figures:
                pdf.savefig(fig)
    return buffer.getvalue()


def save_figure(fig, path) -> Path:
    """Write one figure to *path*: SVG (true to scale), PDF or PNG by the suffix, atomically."""
    from .formats import format_of, render

    path = Path(path)
    return replace_all({path: render(fig, format_of(path))})[0]  # creates the directory


# --- plans draw --positions -----------------------------------------------------------


def _position_title(run, total: int, lang: str) -> str:
    return f"{run.scene.title} — {term('position', lang)} {run.index} ({run.index + 1}/{total}): {run.label}"


def draw_position_sheet(run, *, lang: str = "en", total: int | None = None):
    """The one-page sheet of a position (see :func:`plans.drawing.draw_sheet`), titled with the position."""
    from ..report import sheet_table

    return draw_sheet(
        run.graphical,
        formula=run.analytic.structure.formula,
        table=sheet_table(run.comparisons),
        lang=lang,
        title=_position_title(run, total or run.index + 1, lang),
    )


def write_position_sheets(positions_run, directory, *, lang: str = "en", format: str = "svg") -> list[Path]:
    """Write ``sheet-00.svg``, ``sheet-01.svg``, … and ``positions.svg`` (the plan of positions).

    Every sheet uses the run's common scale factors.  A position that cannot
    be solved gets no sheet (it is left out, and the plan of positions does
    not draw it).  All files are written together, atomically; sheets of an
    earlier run with more positions that plans wrote (and nobody changed
    since) are removed; other files in *directory* are never touched.

    Parameters
    ----------
    positions_run : plans.positions.PositionsRun
    directory : str or pathlib.Path
    lang : str

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
        fig = draw_position_sheet(run, lang=lang, total=total)
        contents[directory / f"sheet-{run.index:0{width}d}.{format}"] = render(fig, format)
    contents[directory / f"positions.{format}"] = render(draw_positions_plan(positions_run, lang=lang)[0].figure, format)
    if format != "svg":  # the record of what plans wrote is an SVG comment: other formats remove nothing
        return replace_all(contents)
    # sheets of an earlier run with more positions go if plans wrote them (positions.svg records them)
    return replace_all(contents, stale=(directory, r"sheet-\d+\.svg", "positions.svg"))


# --- handout pages ------------------------------------------------------------------------


def _page(size=A4):
    fig = new_figure(*size)
    paper = fig.add_axes([0, 0, 1, 1], zorder=-1)
    paper.set_xlim(0, size[0])
    paper.set_ylim(0, size[1])
    paper.set_axis_off()
    return fig, Sketch(paper, "page")


def _math_width(text: str, size: float) -> float:
    return text_size(text, size, "normal", "$" in text)[0]


def _split_math(line: str, width: float, size: float) -> list[str]:
    """A mathtext line split at its top-level ``=`` or ``⇒`` until every piece fits *width* [mm]."""
    if _math_width(line, size) <= width or not line.startswith("$") or not line.endswith("$"):
        return [line]
    body = line[1:-1]
    cuts = []
    depth = 0
    for k, ch in enumerate(body):
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif depth == 0 and (body.startswith(" = ", k) or body.startswith(r"\ \Rightarrow", k)):
            cuts.append(k)
    if not cuts:
        return [line]
    best = None
    for k in cuts:
        head = "$" + body[:k] + "$"
        if _math_width(head, size) <= width or best is None:
            best = k
    head, tail = body[:best], body[best:].lstrip()
    indent = r"\qquad "
    return [f"${head}$"] + _split_math(f"${indent}{tail}$", width, size)


def page_text_rows(heading: str, lines: list[str], width: float, size: float = TEXT_PT) -> list[tuple[str, float, str, bool]]:
    """Rows (text, size, weight, mathtext) of a text block: a heading, then lines split to *width*."""
    rows = [(heading, HEADING_PT, "bold", False)]
    for line in lines:
        if line.startswith("§"):  # a subheading
            rows.append((line[1:], size, "bold", False))
            continue
        for piece in _split_math(line, width, size):
            rows.append((piece, size, "normal", "$" in piece))
    return rows


def _legend_block(graphical, lang: str) -> _Block:
    """One legend for both plans: each kind of vector drawn, and construction lines."""
    words: dict[str, list[str]] = {}
    for plan in (graphical.velocity_plan, graphical.acceleration_plan):
        if plan is None:
            continue
        kinds = {v.kind for v in vectors_drawn(plan)}
        for kind in KINDS:
            if kind in kinds:
                text = legend_words(plan.kind, kind, lang)
                if text not in words.setdefault(kind, []):
                    words[kind].append(text)
    # one row per style: "absolute velocity / absolute acceleration"
    entries = [(kind, " / ".join(words[kind])) for kind in KINDS if kind in words]
    entries.append(("construction", legend_words("velocity", "construction", lang)))
    row_h = text_size("lp", CAPTION_PT)[1] + 0.8
    width = 11.0 + max(text_size(w, CAPTION_PT)[0] for _, w in entries)
    height = row_h * len(entries)

    def place(sketch: Sketch, x: float, y: float) -> None:
        top = y + height
        for kind, words in entries:
            legend_row(sketch, kind, words, x, top - row_h / 2, text_gid="legend-text")
            top -= row_h

    return _Block(width, height, place)


def _header_rows(title: str, lines: list[str]) -> list[tuple[str, float, str, bool, float, float]]:
    """The rows of a page's header: (text, size, weight, mathtext, height of its box [mm], advance [mm]).

    The title, then the data lines (a leading ``§`` makes one bold).  Both
    :func:`_header` and :func:`_header_height` read these.
    """
    h = text_size("lp", PAGE_TITLE_PT, "bold")[1]
    rows = [(title, PAGE_TITLE_PT, "bold", False, h, h + 1.2)]
    for line in lines:
        weight = "bold" if line.startswith("§") else "normal"
        line = line.lstrip("§")
        is_math = "$" in line
        h = text_size("lp", DATA_PT)[1] * (1.2 if is_math else 1.0) + 0.7
        rows.append((line, DATA_PT, weight, is_math, h, h))
    return rows


def _header(sketch: Sketch, size, title: str, lines: list[str]) -> float:
    """Title and data lines at the top of a page; returns the y [mm] below them."""
    pw, ph = size
    y = ph - PAGE_MARGIN
    for k, (text, pt, weight, is_math, h, advance) in enumerate(_header_rows(title, lines)):
        gid = "page-title" if k == 0 else "page-data"
        sketch.text(complex(PAGE_MARGIN, y - h / 2), text, size=pt, weight=weight, ha="left", gid=gid, obstacle=False, math=is_math)
        y -= advance
    sketch.line([complex(PAGE_MARGIN, y - 1.0), complex(pw - PAGE_MARGIN, y - 1.0)], lw=0.6, gid="page-rule", obstacle=False)
    return y - 1.0 - GAP * 0.8


def _header_height(lines) -> float:
    """What :func:`_header` takes from the top of the page [mm]."""
    return PAGE_MARGIN + sum(row[5] for row in _header_rows("", list(lines))) + 1.0 + GAP * 0.8


def _footer(sketch: Sketch, left: str) -> None:
    y = PAGE_MARGIN * 0.55
    sketch.text(complex(PAGE_MARGIN, y), left, size=FOOTER_PT, ha="left", va="center", gid="page-footer", obstacle=False, color=FOOTER_COLOUR)


def stamp_page_number(fig, number: int, total: int, lang: str) -> None:
    """``"Page 3/12"`` at the foot of any page (a handout page or a cycle diagram), right-aligned in the margin."""
    width, height = fig.get_size_inches() * 25.4
    fig.text(1 - PAGE_MARGIN / width, PAGE_NUMBER_Y / height, f"{term('page', lang)} {number}/{total}", ha="right", va="center", fontsize=FOOTER_PT, color=FOOTER_COLOUR)


def _place_rows(sketch: Sketch, size, top: float, rows: list[list[_Block]]) -> None:
    """Rows of blocks from *top* down, each row spread over the page width (placed even if they do not fit)."""
    avail_w = size[0] - 2 * PAGE_MARGIN
    for row in rows:
        widths = sum(b.width for b in row)
        spare = max(0.0, avail_w - widths)
        gap = spare / (len(row) - 1) if len(row) > 1 else 0.0
        gap = min(gap, 18.0) if len(row) > 1 else 0.0
        x = PAGE_MARGIN
        h = max(b.height for b in row)
        for b in row:
            if b.drawing:
                b.place(x, top - b.height, size)
            else:
                b.place(sketch, x, top - b.height)
            x += b.width + gap
        top -= h + GAP


def draw_position_page(
    run,
    *,
    lang: str = "en",
    header_lines: list[str] = (),
    title: str | None = None,
    equations: list[str] | None = None,
    footer: str = "",
    strict: bool = True,
):
    """The graphical page of a position, A4 portrait (a matplotlib Figure).

    The title and data, the mechanism and both plans true to scale (the
    scale factors stated under each), one legend for the plans, and the
    vector equations each group's construction solved.

    Parameters
    ----------
    run : plans.positions.PositionRun
        A solved position (``run.ok``).
    header_lines : list of str
        Data lines under the title (mathtext allowed; a leading ``§`` makes
        one bold).
    equations : list of str, optional
        Vector equations, by default from the plans' steps.
    strict : bool
        Raise :class:`PageOverflow` when the blocks do not fit in any layout;
        False places them in the last layout anyway (the handout does so,
        having fitted the scale factors with :func:`position_page_excess`).
    """

    g = run.graphical
    size = A4
    with drawing_rc():
        fig, sketch = _page(size)
        top = _header(sketch, size, title or run.scene.title, list(header_lines))
        width = size[0] - 2 * PAGE_MARGIN

        mech = _drawing_block(fig, "mechanism", g, lang, legend=False)
        vel = _drawing_block(fig, "velocity", g.velocity_plan, lang, legend=False)
        acc = _drawing_block(fig, "acceleration", g.acceleration_plan, lang, legend=False) if g.acceleration_plan is not None else None
        legend = _legend_block(g, lang)
        layouts = _layouts(mech, vel, acc, legend, size)

        eq_block = _equations_block(g, equations, lang, width)
        chosen = None
        for layout in layouts:
            rows = layout + [[eq_block]]
            if _fits(size, top, rows):
                chosen = rows
                break
        if chosen is None:
            if strict:
                raise PageOverflow(_excess(size, top, layouts[-1] + [[eq_block]]))
            chosen = layouts[-1] + [[eq_block]]
        _place_rows(sketch, size, top, chosen)
        _footer(sketch, footer)
    return fig


def _layouts(mech, vel, acc, legend, size) -> list[list[list[_Block]]]:
    """The arrangements of a graphical page's drawings to try, in order of preference."""
    width = size[0] - 2 * PAGE_MARGIN
    plans_ = [b for b in (vel, acc) if b is not None]
    layouts: list[list[list[_Block]]] = []
    # all three in a row (a long, low mechanism)
    if sum(b.width for b in [mech] + plans_) + GAP * len(plans_) <= width:
        layouts.append([[mech] + plans_, [legend]])
    # the mechanism (and the legend under it) beside the plans stacked: a tall mechanism
    left, right = _column([mech, legend], size), _column(plans_, size)
    if left.width + right.width + GAP <= width:
        layouts.append([[left, right]])
    column = _column(plans_ + [legend], size)
    if mech.width + column.width + GAP <= width:
        layouts.append([[mech, column]])
    # the mechanism and the velocity plan, then the acceleration plan and the legend
    if acc is not None:
        layouts.append([[mech, vel], [acc, legend]])
    else:
        layouts.append([[mech, vel], [legend]])
    return layouts


def _equations_block(g, equations, lang: str, width: float) -> _Block:
    from .sheet import _pretty, sheet_equations

    lines = [_pretty(line)[0] for line in (sheet_equations(g) if equations is None else equations)]
    return _rows_block(page_text_rows(term("vector_equations", lang), lines, width), "equation", line_gap=LINE_GAP, math_scale=MATH_LINE)


def position_page_excess(run, *, lang: str = "en", header_lines=(), equations=None, cache: dict | None = None) -> float:
    """How far [mm] the graphical page of a position would run over A4 in its best layout (0 or less: it fits).

    Measures the drawings without making the page; *cache* keeps the size of
    each drawing by (position, kind, scale factor), so trying other scale
    factors redraws only what changed.
    """
    g = run.graphical
    cache = {} if cache is None else cache
    width = A4[0] - 2 * PAGE_MARGIN
    top = A4[1] - _header_height(list(header_lines))

    def size_of(kind, obj, scale):
        key = (run.index, kind, float(scale), lang)
        if key not in cache:
            with drawing_rc():
                fig = new_figure()
                block = _drawing_block(fig, kind, obj, lang, legend=False)
            cache[key] = (block.width, block.height)
        return _Block(*cache[key], None)

    with drawing_rc():
        mech = size_of("mechanism", g, g.scales["k_l"])
        vel = size_of("velocity", g.velocity_plan, g.velocity_plan.scale)
        acc = size_of("acceleration", g.acceleration_plan, g.acceleration_plan.scale) if g.acceleration_plan is not None else None
        legend = _legend_block(g, lang)
        eq_block = _equations_block(g, equations, lang, width)
    return min(_excess(A4, top, layout + [[eq_block]]) for layout in _layouts(mech, vel, acc, legend, A4))


def _fits(size, top: float, rows) -> bool:
    return _excess(size, top, rows) <= 0.0


def _excess(size, top: float, rows) -> float:
    """How far [mm] rows of blocks placed from *top* run past the bottom margin or the width (0 or less: they fit)."""
    pw, _ = size
    need = sum(max(b.height for b in row) for row in rows) + GAP * (len(rows) - 1)
    over_h = need - (top - PAGE_MARGIN - 2.0)
    over_w = max(sum(b.width for b in row) + GAP * (len(row) - 1) for row in rows) - (pw - 2 * PAGE_MARGIN)
    return max(over_h, over_w)


def _column(blocks: list[_Block], size, gap: float = GAP) -> _Block:
    """Blocks one above the other, left-aligned (drawings and sheet blocks alike), on a page of *size* [mm]."""
    width = max(b.width for b in blocks)
    height = sum(b.height for b in blocks) + gap * (len(blocks) - 1)

    def place(sketch: Sketch, x: float, y: float) -> None:
        top = y + height
        for b in blocks:
            if b.drawing:
                b.place(x, top - b.height, size)
            else:
                b.place(sketch, x, top - b.height)
            top -= b.height + gap

    return _Block(width, height, place)


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
    """The analytic pages of a position, A4 portrait: the results table, then the loop equations.

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
        loop_lines.extend(block.lines)
    with drawing_rc():
        rows = page_text_rows(heading, loop_lines, width) if loop_lines else []
        figures = []
        first = True
        while first or rows:
            fig, sketch = _page(size)
            top = _header(sketch, size, title or run.scene.title, list(header_lines))
            bottom = PAGE_MARGIN + 4.0
            if first and table:
                block = _table_block(table, term("results", lang), size=SMALL_PT + 0.3)
                block.place(sketch, PAGE_MARGIN, top - block.height)
                top -= block.height + GAP
            if rows:
                take = len(rows)
                while take > 1 and _rows_block(rows[:take], "loop", line_gap=LINE_GAP, math_scale=MATH_LINE).height > top - bottom:
                    take -= 1
                while take > 1 and rows[take - 1][2] == "bold":  # no heading alone at the foot
                    take -= 1
                block = _rows_block(rows[:take], "loop", line_gap=LINE_GAP, math_scale=MATH_LINE)
                block.place(sketch, PAGE_MARGIN, top - block.height)
                rest = rows[take:]
                rows = [(f"{heading} {term('continued', lang)}", HEADING_PT, "bold", False)] + rest if rest else []
            _footer(sketch, footer)
            figures.append(fig)
            first = False
    return figures


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
        fig, sketch = _page(size)
        top = _header(sketch, size, positions_run.scene.title, list(header_lines))
        ax = fig.add_axes([0, 0, 0.01, 0.01])
        plan_sketch = Sketch(ax, "positions")
        draw_positions_into(plan_sketch, positions_run, lang=lang, k_l=k_l)
        bounds = plan_sketch.bounds
        w, h = bounds.width + 2 * MARGIN_MM, bounds.height + 2 * MARGIN_MM
        x = max(PAGE_MARGIN, (size[0] - w) / 2)
        fit_axes(ax, bounds, MARGIN_MM, rect_mm=(x, top - h), page_mm=size)
        y = top - h - GAP
        if positions_lines:
            h = text_size("lp", HEADING_PT, "bold")[1]
            sketch.text(complex(PAGE_MARGIN, y - h / 2), term("positions_list", lang), size=HEADING_PT, ha="left", weight="bold", gid="positions-heading", obstacle=False)
            y -= h + 1.5
            # the entries in columns, column by column, aligned
            column_w = max(text_size(e, DATA_PT)[0] for e in positions_lines) + 8.0
            columns = max(1, min(4, int((size[0] - 2 * PAGE_MARGIN) // column_w)))
            per = -(-len(positions_lines) // columns)
            row_h = text_size("lp", DATA_PT)[1] + 1.0
            for k, entry in enumerate(positions_lines):
                c, r = divmod(k, per)
                sketch.text(complex(PAGE_MARGIN + c * column_w, y - (r + 0.5) * row_h), entry, size=DATA_PT, ha="left", gid="positions-entry", obstacle=False)
        _footer(sketch, footer)
    return fig


def scale_line(scales: dict, lang: str) -> str:
    """``"Scale factors: k_l = 0.01 m/mm, k_v = 0.02 (m/s)/mm, k_a = 0.25 (m/s²)/mm"``."""
    units = {"k_l": "m/mm", "k_v": "(m/s)/mm", "k_a": "(m/s²)/mm"}
    parts = [f"{key} = {fmt_number(value)} {units[key]}" for key, value in scales.items() if key in units]
    return f"{term('scale_factors', lang)}:  " + ",  ".join(parts)
