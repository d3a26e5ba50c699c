"""The one-page A3 sheets of ``plans draw``: their scale factors fitted to the sheet, and the sheets of a
multi-position run, position by position.

Orchestration (it constructs the plans again at the factors it chooses, so it is not drawing's; the CLI
only parses and calls): :func:`fitted_sheet` chooses a sheet's factors for its regions
(:func:`plans.drawing.sheet.sheet_scales`), constructs the plans at them and draws the sheet, measuring
what each drawing takes beyond its geometry and drawing again when that lets the drawings grow;
:func:`position_sheets` gives :func:`plans.drawing.write_position_sheets` a function that does so for each
position, carrying the measurements from one sheet to the next.  Imports of matplotlib happen in the
functions, on first use.
"""

from __future__ import annotations

__all__ = ["fitted_sheet", "position_sheets", "REFIT_GAIN", "PART_AT_SOME_FACTORS"]


#: A sheet that fits A3 is drawn again at the factors its own measurements give only when they make its
#: drawings this much larger (:func:`plans.drawing.sheet.drawn_score`).
REFIT_GAIN = 1.05
#: A drawing that takes this much more [mm] beyond its geometry than on the sheet before draws a part at some
#: factors only (a plan's enlarged detail): the re-fit charges it at the factor it was measured at.
PART_AT_SOME_FACTORS = 20.0


def fitted_sheet(graphical, construct_at, draw, choose, *, given: dict, fixed=None):
    """(graphical, sheet figure): the sheet's factors chosen for its regions (:func:`plans.drawing.sheet.sheet_scales`,
    *choose*), the plans constructed again at them (*construct_at*: drawing never solves) and the sheet drawn (*draw*).

    The factors are chosen from what each drawing takes beyond its geometry (labels, supports, caption,
    legend): *fixed* as measured on another sheet, else an estimate.  The sheet drawn then measures it for
    itself; when that gives other factors, the sheet is drawn once more at those (kept if it fits A3, or if
    the first did not, or if its drawings are larger).
    """
    from .drawing.sheet import ESTIMATED_FIXED, SCALE_OF, SHEET_FIRST, drawn_score

    scales = choose(graphical, fixed or ESTIMATED_FIXED)
    if scales != graphical.scales:
        graphical = construct_at(scales)
    figure = draw(graphical)
    if all(given.get(key) is not None for key in graphical.scales):
        return graphical, figure
    if figure.plans_sheet.format == SHEET_FIRST and drawn_score(graphical, least=True) >= 1.0 and fixed is not None:
        return graphical, figure  # fits A3 and every drawing reaches its size, from another sheet's measurements
    first = figure.plans_sheet
    measured = {kind: {graphical.scales[SCALE_OF[kind]]: f} for kind, f in first.fixed.items()}
    own = dict(first.fixed)
    for kind, f in first.fixed.items():
        before = (fixed or {}).get(kind)
        if before is not None and max(f[0] - before[0], f[1] - before[1]) > PART_AT_SOME_FACTORS:
            # much more than on the sheet before: a part drawn at some factors only (a plan's enlarged detail),
            # charged at this factor, not at the others
            own[kind] = tuple(map(min, f, before))
    again = choose(graphical, {**own, "at": measured})
    fits = first.format == SHEET_FIRST
    if again == graphical.scales or fits and drawn_score(graphical, again) < REFIT_GAIN * drawn_score(graphical):
        return graphical, figure  # drawn again only to fit A3, or for drawings noticeably larger
    second = construct_at(again)
    second_figure = draw(second)
    second_fits = second_figure.plans_sheet.format == SHEET_FIRST
    if second_fits and (not fits or drawn_score(second) > drawn_score(graphical)):
        return second, second_figure
    if not second_fits and (not fits or drawn_score(graphical, least=True) < 1.0):
        # the second took more than chosen for (a part drawn at its factors only): chosen once more with what
        # both drawings measured at their factors, kept if it fits A3 (and beats a first that fits)
        for kind, f in second_figure.plans_sheet.fixed.items():
            measured.setdefault(kind, {})[second.scales[SCALE_OF[kind]]] = f
        third = choose(graphical, {**first.fixed, "at": measured})
        if third not in (graphical.scales, second.scales) and (not fits or drawn_score(graphical, third) > drawn_score(graphical)):
            third_solution = construct_at(third)
            third_figure = draw(third_solution)
            if third_figure.plans_sheet.format == SHEET_FIRST:
                return third_solution, third_figure
    if not fits:
        return second, second_figure
    return graphical, figure


def position_sheets(run, lang: str, given: dict):
    """A function: a solved position -> its sheet, at the factors that make its drawings fill their regions
    (given ones kept), for :func:`plans.drawing.write_position_sheets` to call position by position.

    What the drawings take beyond their geometry is measured on each sheet drawn, for the next
    (see :func:`fitted_sheet`).
    """
    from dataclasses import replace

    from .compare import compare
    from .drawing.sheet import branch_lines, sheet_scales
    from .drawing.sheets import draw_position_sheet, position_title
    from .graphical import construct
    from .report import sheet_table

    measured = {}

    def sheet_of(r):
        def table_of(g):
            return sheet_table(compare(r.analytic, g), g, r.analytic)

        def construct_at(scales):
            g = construct(r.scene, run.structure, k_l=scales["k_l"], k_v=scales["k_v"], k_a=scales.get("k_a"), precision=run.precision, check_scales=False)
            return replace(g, travel=r.graphical.travel, cycle_poses=r.graphical.cycle_poses)  # slots, guides, frame as the run drew them

        def draw(g):
            return draw_position_sheet(replace(r, graphical=g, comparisons=compare(r.analytic, g)), lang=lang, total=len(run.runs))

        def choose(g, fixed):
            return sheet_scales(g, formula=r.analytic.structure.formula, table=table_of(g), lang=lang, title=position_title(r, len(run.runs), lang),
                                branches=branch_lines(r.analytic.branches, lang), given=given, fixed=fixed)

        _, figure = fitted_sheet(r.graphical, construct_at, draw, choose, given=given, fixed=measured.get("fixed"))
        measured["fixed"] = figure.plans_sheet.fixed
        return figure

    return sheet_of
