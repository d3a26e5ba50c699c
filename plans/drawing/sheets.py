"""The sheets of a multi-position run: ``plans draw --positions``.

* :func:`write_position_sheets` — one sheet per position
  (:func:`plans.drawing.draw_sheet`, titled with the position) and the plan of
  positions, all at the run's common scale factors.
* :func:`plans.drawing.formats.render_pdf` — figures as the pages of one PDF: TrueType (Type 42)
  DejaVu Sans embedded, which has the Cyrillic glyphs; no creation date, so
  the same pages give the same bytes.
* :func:`plans.drawing.formats.save_figure` — one figure to ``.svg``, ``.pdf`` or ``.png``, atomically.

The handout's pages are set by Typst (:mod:`plans.pages.handout`).
"""

from __future__ import annotations

from pathlib import Path


from .._files import replace_all
from .._text import user_text
from ..i18n import term
from .sheet import branch_lines, draw_sheet

__all__ = ["write_position_sheets", "draw_position_sheet", "position_title"]


# --- plans draw --positions -----------------------------------------------------------


def position_title(run, total: int, lang: str = "en") -> str:
    """The title of a position's sheet: the scene's title, the position's number and its driver position."""
    return f"{user_text(run.scene.title_in(lang))} — {term('position', lang)} {run.index} ({run.index + 1}/{total}): {run.label}"


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
