"""The one-page sheet and :func:`write_drawings`.

The sheet puts the title, the structural formula, the mechanism and both
plans (each at its own scale, 1:1 on the page, so the stated scale factors
hold on the printed sheet too), the vector equations each group solved and
the results table on one ISO page: the smallest of A4 … A0 (landscape or
portrait) that holds them, or a larger custom page when even A0 does not.
"""

from __future__ import annotations

import re
from pathlib import Path

from .._files import replace_all
from .._text import decimal_comma, user_text
from ..i18n import term
from ._canvas import Sketch
from .blocks import drawing_block, pretty_equation, rows_block, table_block
from .layout import choose_page
from .style import HEADING_PT, TITLE_PT
from .svg import drawing_rc, new_figure, render_svg

__all__ = ["draw_sheet", "write_drawings", "sheet_equations", "guide_names", "translate_table", "label_driver"]

PAGE_MARGIN = 12.0  # mm
GAP = 8.0  # mm between blocks
EQ_PT = 8.5
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


def draw_sheet(
    solution,
    *,
    formula: str = "",
    table: list[list[str]] | None = None,
    equations: list[str] | None = None,
    lang: str = "en",
    title: str | None = None,
):
    """The one-page sheet as a matplotlib Figure (SVG canvas), sized in mm to an ISO page.

    Parameters
    ----------
    solution : plans.graphical.GraphicalSolution
    formula : str
        The structural formula, printed under the title.
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
    """
    table = [[decimal_comma(cell, lang) for cell in row] for row in translate_table(table, lang)] if table else table
    with drawing_rc():
        fig = new_figure()
        drawings = [drawing_block(fig, "mechanism", solution, lang), drawing_block(fig, "velocity", solution.velocity_plan, lang)]
        if solution.acceleration_plan is not None:
            drawings.append(drawing_block(fig, "acceleration", solution.acceleration_plan, lang))

        title = user_text(title if title is not None else (getattr(solution.scene, "title", "") or ""))
        head_rows = [(title, TITLE_PT, "bold")] if title else []
        if formula:
            head_rows.append((f"{term('structural_formula', lang)}:  {formula}", HEADING_PT, "normal"))
        head = rows_block(head_rows, "title", line_gap=SHEET_LINE_GAP) if head_rows else None

        eq_lines = sheet_equations(solution) if equations is None else list(equations)
        if lang != "en":  # "driver:" is the one English word of the steps: the structural notation instead
            eq_lines = label_driver(eq_lines, f"I(0,{getattr(getattr(solution.scene, 'driver', None), 'link', '')})")
        eq_block = None
        if eq_lines:
            rows = [(term("vector_equations", lang) if lang != "en" else "Vector equations", HEADING_PT, "bold")]
            rows += [(pretty_equation(line), EQ_PT, "normal") for line in eq_lines]
            eq_block = rows_block(rows, "equation", line_gap=SHEET_LINE_GAP)
        table_block_ = table_block(table, "Results" if lang == "en" else term("results", lang)) if table else None

        # arrangements of the drawings: one row, or the mechanism above the plans
        arrangements = [[drawings]]
        if len(drawings) > 1:
            arrangements.append([[drawings[0]], drawings[1:]])
        texts = [b for b in (eq_block, table_block_) if b is not None]
        best = None
        for rows in arrangements:
            row_w = max(sum(b.width for b in row) + GAP * (len(row) - 1) for row in rows)
            row_h = sum(max(b.height for b in row) for row in rows) + GAP * (len(rows) - 1)
            for side_by_side in (True, False) if len(texts) > 1 else (True,):
                if not texts:
                    bottom_w = bottom_h = 0.0
                elif side_by_side:
                    bottom_w = sum(b.width for b in texts) + GAP * (len(texts) - 1)
                    bottom_h = max(b.height for b in texts)
                else:
                    bottom_w = max(b.width for b in texts)
                    bottom_h = sum(b.height for b in texts) + GAP * (len(texts) - 1)
                width = max(row_w, bottom_w, head.width if head else 0.0)
                height = (head.height + GAP if head else 0.0) + row_h + (GAP + bottom_h if texts else 0.0)
                _, page = choose_page(width, height, PAGE_MARGIN)
                area = page[0] * page[1]
                if best is None or area < best[0] - 1e-6:
                    best = (area, rows, page, side_by_side, width, height)
        _, rows, page, side_by_side, content_w, content_h = best

        pw, ph = page
        fig.set_size_inches(pw / 25.4, ph / 25.4)
        paper = fig.add_axes([0, 0, 1, 1], zorder=-1)
        paper.set_xlim(0, pw)
        paper.set_ylim(0, ph)
        paper.set_axis_off()
        sheet = Sketch(paper, "sheet")

        # the content block centred on the page
        x0 = max(PAGE_MARGIN, (pw - content_w) / 2)
        y = ph - max(PAGE_MARGIN, (ph - content_h) / 2)
        if head:
            y -= head.height
            head.place(sheet, x0, y, page)
            y -= GAP
        for row in rows:
            h = max(b.height for b in row)
            x = x0
            for b in row:
                b.place(sheet, x, y - b.height, page)  # tops aligned
                x += b.width + GAP
            y -= h + GAP
        if texts:
            if side_by_side:
                x = x0
                for b in texts:
                    b.place(sheet, x, y - b.height, page)
                    x += b.width + GAP
            else:
                for b in texts:
                    b.place(sheet, x0, y - b.height, page)
                    y -= b.height + GAP
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
        draw_sheet(solution, formula=formula, table=table, equations=equations, lang=lang), format
    )
    if format != "svg":  # the record of what plans wrote is an SVG comment: other formats remove nothing
        return replace_all(contents)
    # an acceleration.svg of an earlier run goes if plans wrote it (sheet.svg records it)
    return replace_all(contents, stale=(directory, r"acceleration\.svg", "sheet.svg"))
