"""The one-page sheet and :func:`write_drawings`.

The sheet puts the mechanism and both plans (each at its own scale, 1:1 on
the page, so the stated scale factors hold on the printed sheet too), the
vector equations each group solved and the results table in a drawing frame
on A4 landscape, or A3 landscape when A4 cannot hold them (a larger ISO
sheet only when A3 cannot either), with a title block in the lower right
corner: title, structural formula, scale factors and assembly branches.
"""

from __future__ import annotations

import re
from pathlib import Path

from .._files import replace_all
from .._text import decimal_comma, user_text
from ..i18n import branch_text, term
from ._canvas import Sketch, fmt_number
from .blocks import drawing_block, pretty_equation, readings_block, rows_block, table_block, text_rows
from .layout import FRAME_LEFT, FRAME_OTHER, SHEET_FORMATS, TITLE_BLOCK_W
from .numerals import scale_caption
from .style import HEADING_PT
from .svg import drawing_rc, new_figure
from .typeset import draw_text, measure

__all__ = ["draw_sheet", "branch_lines", "write_drawings", "sheet_equations", "guide_names", "translate_table", "label_driver"]

SHEET_PAD = 4.0  # mm between the frame and the content
GAP = 6.0  # mm between blocks
EQ_PT = 8.5
EQ_WIDTH = 105.0  # mm: the vector equations are broken to this width
SHEET_LINE_GAP = 1.5  # mm between the lines of the title and of the equations


#: a guide as the construction names it, ``frame.ram`` or ``4.slot``: the body's key before the scene's name
_GUIDE_KEY = re.compile(r"(?<![\w.])(?:frame|\d+)\.([^\W\d]\w*)")


def guide_names(line: str) -> str:
    """*line* with each guide named as the scene names it: ``∥ frame.ram`` → ``∥ ram``, ``∥ 4.slot`` → ``∥ slot``.

    >>> guide_names("v_E = v_E4 + v_EE4  (v_EE4 ∥ 4.slot);  a = 0.5 m")
    'v_E = v_E4 + v_EE4  (v_EE4 ∥ slot);  a = 0.5 m'
    """
    return _GUIDE_KEY.sub(r"\1", line)


def sheet_equations(solution, driver_label: str | None = None, plans=("velocity", "acceleration")) -> list[str]:
    """One line per construction step: ``"RRP(3,4):  v_B = v_A + v_BA;  v_B = …"``, velocity plan first.

    With *driver_label* (such as ``"I(0,2)"``) the driver's steps are headed
    with it instead of the English word ``driver`` (see :func:`label_driver`);
    *plans* says of which plans (both by default).
    """
    lines = []
    for plan in (solution.velocity_plan, solution.acceleration_plan):
        if plan is None or plan.kind not in plans:
            continue
        for step in plan.steps:
            if step.equations:
                lines.append(guide_names(f"{step.group}:  " + ";   ".join(step.equations)))
    return lines if driver_label is None else label_driver(lines, driver_label)


def label_driver(lines: list[str], label: str) -> list[str]:
    """Equation lines with a leading ``driver:`` replaced by ``label:`` (``"I(0,2):"``, the structural notation)."""
    return [f"{label}:" + line[len("driver:"):] if line.startswith("driver:") else line for line in lines]


_TABLE_HEADER = ["quantity", "graphical", "analytic", "rel. error"]


def translate_table(table: list[list[str]], lang: str) -> list[list[str]]:
    """The sheet table with its header row and the words link/slider in *lang*."""
    if lang == "en" or not table or list(table[0]) != _TABLE_HEADER:
        return table
    header = [term(k, lang) for k in ("quantity", "graphical", "analytic", "rel_error")]
    words = {" link ": f" {term('link', lang)} ", " slider ": f" {term('slider', lang)} "}
    rows = [header]
    for row in table[1:]:
        cell = row[0]
        for a, b in words.items():
            cell = cell.replace(a, b)
        rows.append([cell] + list(row[1:]))
    return rows


TITLE_BLOCK_PAD = 2.0
TITLE_BLOCK_PT = 8.0


def branch_lines(branches, lang: str = "en") -> list[str]:
    """The assembly branch of each group with two, one line each, from :class:`plans.structure.Branch` records.

    ``"RRR(3,4): C to the left of B→D (+1)"``; in the other languages in
    their words (:func:`plans.i18n.branch_text`), or the group and its sign
    alone for a form of words not known there.
    """
    out = []
    for b in branches or ():
        if not b.sign:
            continue
        sign = f"{b.sign:+d}".replace("-", "\u2212")
        words = branch_text(guide_names(b.words), lang)
        out.append(f"{b.group}: {words} ({sign})" if words else f"{b.group}: {sign}")
    return out


def _title_block_rows(title: str, formula: str, scales: dict, branches, lang: str) -> list[tuple[str, float, str]]:
    rows = [(title or "—", HEADING_PT + 1.0, "bold")]
    if formula:
        rows.append((f"{term('structural_formula', lang)}:  {formula}", TITLE_BLOCK_PT, "normal"))
    units = {"k_l": "m/mm", "k_v": "(m/s)/mm", "k_a": "(m/s²)/mm"}
    parts = [scale_caption(key, fmt_number(scales[key]), unit, lang) for key, unit in units.items() if scales.get(key)]
    if parts:
        rows.append((f"{term('scale_factors', lang)}:  " + ",  ".join(parts), TITLE_BLOCK_PT, "normal"))
    for line in branches or ():
        rows.append((line, TITLE_BLOCK_PT, "normal"))
    return rows


def _layouts(drawings, texts):
    """The arrangements tried on a sheet, as lists of columns, each a list of rows of blocks (left to right, top down)."""
    mech, plans = drawings[0], drawings[1:]
    text_options = [[[t] for t in texts]] + ([[texts]] if len(texts) > 1 else []) if texts else [[]]
    out = []
    for rows in ([drawings], [[mech], plans]) if plans else ([drawings],):
        for under in text_options:
            out.append([rows + under])  # the texts under the drawings (stacked, or side by side)
            if texts:
                out.append([rows, [[t] for t in texts]])  # the texts in a column to the right
    if len(plans) == 2 and texts:
        # the mechanism over the velocity plan, the acceleration plan beside them, the texts in a third column
        out.append([[[mech], [plans[0]]], [[plans[1]]], [[t] for t in texts]])
    return out


def _arrange(columns):
    """(width, height, [(block, x, y from the top)]) of columns of rows of blocks, GAP apart, tops aligned."""
    placed = []
    x = 0.0
    height = 0.0
    for column in columns:
        y = 0.0
        width = 0.0
        for row in column:
            bx = x
            for b in row:
                placed.append((b, bx, y))
                bx += b.width + GAP
            width = max(width, bx - GAP - x)
            y += max(b.height for b in row) + GAP
        height = max(height, y - GAP)
        x += width + GAP
    return x - GAP, height, placed


def draw_sheet(
    solution,
    *,
    formula: str = "",
    table: list[list[str]] | None = None,
    equations: list[str] | None = None,
    lang: str = "en",
    title: str | None = None,
    branches: list[str] | None = None,
):
    """The one-page sheet as a matplotlib Figure (SVG canvas): A4 or A3 landscape, a frame and a title block.

    The drawings (mechanism, velocity and acceleration plans, each true to
    its scale factor), the vector equations and the results table are
    arranged inside the drawing frame, above the title block; the sheet is
    A4 landscape when they fit, else A3 landscape (a larger ISO sheet only
    when even A3 cannot hold them).  The title block (lower right, ISO 7200
    style) gives the title, the structural formula, the scale factors and,
    when given, the assembly branches.  Drawing solves nothing: everything
    printed is passed in.

    Parameters
    ----------
    solution : plans.graphical.GraphicalSolution
    formula : str
        The structural formula, for the title block.
    table : list of list of str, optional
        Results, first row the header.
    equations : list of str, optional
        Lines of vector equations; by default those of the plans' steps.
    lang : str
        Language of headings and legends (see :mod:`plans.i18n`); the table's
        header row is translated when it is the one of
        :func:`plans.report.sheet_table`.
    title : str, optional
        Instead of the scene's title.
    branches : list of str, optional
        The assembly branch of each group, one line each
        (``"RRR(3,4): C to the left of B→D"``), for the title block.
    """
    table = [[decimal_comma(cell, lang) for cell in row] for row in translate_table(table, lang)] if table else table
    with drawing_rc():
        fig = new_figure()
        drawings = [drawing_block(fig, "mechanism", solution, lang), drawing_block(fig, "velocity", solution.velocity_plan, lang)]
        if solution.acceleration_plan is not None:
            drawings.append(drawing_block(fig, "acceleration", solution.acceleration_plan, lang))

        title = user_text(title if title is not None else (getattr(solution.scene, "title", "") or ""))
        tb_rows = [(decimal_comma(t, lang) if k else t, size, weight) for k, (t, size, weight) in enumerate(_title_block_rows(title, formula, solution.scales, branches, lang))]
        tb_heights = [measure(t, size, weight)[1] + 2 * TITLE_BLOCK_PAD for t, size, weight in tb_rows]
        tb_h = sum(tb_heights)

        eq_lines = sheet_equations(solution) if equations is None else list(equations)
        if lang != "en":  # "driver:" is the one English word of the steps: the structural notation instead
            eq_lines = label_driver(eq_lines, f"I(0,{getattr(getattr(solution.scene, 'driver', None), 'link', '')})")
        eq_block = None
        if eq_lines:
            heading = term("vector_equations", lang) if lang != "en" else "Vector equations"
            rows = text_rows(heading, [pretty_equation(decimal_comma(line, lang)) for line in eq_lines], EQ_WIDTH, EQ_PT)
            eq_block = rows_block(rows, "equation", line_gap=SHEET_LINE_GAP)
        table_block_ = table_block(table, "Results" if lang == "en" else term("results", lang)) if table else None

        # arrangements: each a list of (block, x, y from the top) [mm] and its width and height
        # what is measured on each plan and what it gives (issue 10 §2): the two plans' readings side by side, or stacked
        options = []
        for readings in (readings_block(solution, lang), readings_block(solution, lang, width=0.0)):
            texts = [b for b in (eq_block, readings, table_block_) if b is not None]
            for order in (texts, texts[::-1]):  # reversed: the tallest (the table) left, clear of the title block
                options += [_arrange(layout) for layout in _layouts(drawings, order)]
        best = None
        for name, page in SHEET_FORMATS:
            inner_w = page[0] - FRAME_LEFT - FRAME_OTHER - 2 * SHEET_PAD
            full_h = page[1] - 2 * FRAME_OTHER - 2 * SHEET_PAD
            inner_h = full_h - tb_h - GAP
            tb_left = inner_w - min(TITLE_BLOCK_W, inner_w + 2 * SHEET_PAD) + SHEET_PAD - GAP  # the title block's left edge, from the content's
            fitting = [(o, True) for o in options if o[0] <= inner_w + 1e-9 and o[1] <= inner_h + 1e-9]
            # else beside the title block: top left, no block over the title block
            fitting += [(o, False) for o in options if o[0] <= inner_w + 1e-9 and o[1] <= full_h + 1e-9
                        and all(dy + b.height <= inner_h + 1e-9 or dx + b.width <= tb_left + 1e-9 for b, dx, dy in o[2])]
            if fitting:
                best = (name, page, min(fitting, key=lambda f: (not f[1], f[0][0] * f[0][1])))
                break
        if best is None:  # larger than A0: a sheet of its own size
            o = min(options, key=lambda o: o[0] * o[1])
            page = (o[0] + FRAME_LEFT + FRAME_OTHER + 2 * SHEET_PAD, o[1] + 2 * FRAME_OTHER + 2 * SHEET_PAD + tb_h + GAP)
            best = ("custom", page, (o, True))
        _, page, ((content_w, content_h, placed), centred) = best
        pw, ph = page
        fig.set_size_inches(pw / 25.4, ph / 25.4)
        paper = fig.add_axes([0, 0, 1, 1], zorder=-1)
        paper.set_xlim(0, pw)
        paper.set_ylim(0, ph)
        paper.set_axis_off()
        sheet = Sketch(paper, "sheet")

        # the drawing frame and the title block in its lower right corner
        left, right, bottom, top = FRAME_LEFT, pw - FRAME_OTHER, FRAME_OTHER, ph - FRAME_OTHER
        sheet.polygon([complex(left, bottom), complex(right, bottom), complex(right, top), complex(left, top)], lw=1.4, gid="sheet-frame", obstacle=False)
        tb_w = min(TITLE_BLOCK_W, right - left)
        tb_x = right - tb_w
        sheet.polygon([complex(tb_x, bottom), complex(right, bottom), complex(right, bottom + tb_h), complex(tb_x, bottom + tb_h)], lw=1.0, gid="title-block", obstacle=False)
        y = bottom + tb_h
        for k, ((text, size, weight), h) in enumerate(zip(tb_rows, tb_heights)):
            if k:
                sheet.line([complex(tb_x, y), complex(right, y)], lw=0.5, gid="title-block-rule", obstacle=False)
            draw_text(sheet, complex(tb_x + TITLE_BLOCK_PAD + 1.0, y - h / 2), text, size=size, weight=weight, gid="title-block-title" if k == 0 else f"title-block-row{k}")
            y -= h

        # the content centred in the frame above the title block
        area_w = right - left - 2 * SHEET_PAD
        area_h = top - (bottom + tb_h + GAP) - 2 * SHEET_PAD
        x0 = left + SHEET_PAD + (max(0.0, (area_w - content_w) / 2) if centred else 0.0)
        y = top - SHEET_PAD - (max(0.0, (area_h - content_h) / 2) if centred else 0.0)
        for block, dx, dy in placed:
            block.place(sheet, x0 + dx, y - dy - block.height, page)
    return fig


def write_drawings(
    solution,
    directory,
    *,
    formula: str = "",
    table: list[list[str]] | None = None,
    equations: list[str] | None = None,
    lang: str = "en",
    format: str = "svg",
    branches: list[str] | None = None,
) -> list[Path]:
    """Write ``mechanism.svg``, ``velocity.svg``, ``acceleration.svg`` and ``sheet.svg`` (or ``.pdf``, ``.png``: *format*).

    All four are rendered in memory first and then written atomically together
    (see :func:`plans._files.replace_all`): a failure leaves every
    existing file as it was and no temporary file behind.  ``acceleration.svg``
    is written only when the solution has an acceleration plan; an old one in
    *directory* is then removed if plans wrote it (and nobody changed it since),
    so the directory never mixes two runs.

    Parameters
    ----------
    solution : plans.graphical.GraphicalSolution
    directory : str or pathlib.Path
        Created if missing.
    formula : str
        The structural formula for the sheet.
    table : list of list of str, optional
        The results table for the sheet, first row the header.
    equations : list of str, optional
        Vector equations for the sheet; by default from the plans' steps.
    lang : str
        Language of headings and legends (:data:`plans.i18n.LANGUAGES`).
    branches : list of str, optional
        The assembly branches for the sheet's title block (:func:`branch_lines`).

    Returns
    -------
    list of pathlib.Path
        The files written, in the order above.
    """
    from .mechanism import draw_mechanism
    from .plan_drawing import draw_plan

    from .formats import render

    directory = Path(directory)
    contents: dict[Path, bytes] = {}
    contents[directory / f"mechanism.{format}"] = render(draw_mechanism(solution, lang=lang)[0].figure, format)
    contents[directory / f"velocity.{format}"] = render(draw_plan(solution.velocity_plan, lang=lang)[0].figure, format)
    if solution.acceleration_plan is not None:
        contents[directory / f"acceleration.{format}"] = render(draw_plan(solution.acceleration_plan, lang=lang)[0].figure, format)
    contents[directory / f"sheet.{format}"] = render(
        draw_sheet(solution, formula=formula, table=table, equations=equations, lang=lang, branches=branches), format
    )
    if format != "svg":  # the record of what plans wrote is an SVG comment: other formats remove nothing
        return replace_all(contents)
    # an acceleration.svg of an earlier run goes if plans wrote it (sheet.svg records it)
    return replace_all(contents, stale=(directory, r"acceleration\.svg", "sheet.svg"))
