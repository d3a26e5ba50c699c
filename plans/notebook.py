"""Notebook display of graphical results, kept out of the results themselves.

The results of :func:`plans.construct` (:class:`plans.graphical.GraphicalSolution`
and its :class:`plans.graphical.plan.Plan` objects) are plain data: the
graphical layer never imports the drawing layer.  This module sits above both
and joins them, one way:

* :func:`plot` — draw a solution's mechanism or a plan into a matplotlib Axes
  (or a new true-to-scale figure), returning the Axes;
* :func:`sheet` — a solution's one-page sheet (:class:`plans.pages.sheet.Sheet`, set by Typst);
* :func:`save` — a plan or a solution's sheet to ``.svg``, ``.pdf`` or ``.png``, atomically;
* :func:`svg` — the SVG text a notebook shows;
* :func:`animate` — the mechanism and its plans over the cycle, as a lecture page
  (:func:`plans.lecture.animate`; ``solution.animate()`` calls it);
* :func:`register` — tell a running IPython to show solutions and plans as
  SVG (``import plans`` calls it; it does nothing outside IPython).

The results' own ``.plot``, ``.save`` and ``.sheet`` methods call these functions
through :data:`plans.display.DISPLAY`, which importing this module fills: the
graphical layer never imports drawing code.  matplotlib is imported only when
something is drawn.

>>> import plans, plans.notebook as nb
>>> solution = plans.construct(plans.load(plans.example_path("slider-crank")))
>>> nb.svg(solution.velocity_plan).startswith("<?xml")               # doctest: +SKIP
True
"""

from __future__ import annotations

import sys

from .display import DISPLAY

__all__ = ["plot", "sheet", "save", "svg", "animate", "animate_run", "register", "kinematic_pages", "save_pages", "svg_of_figure"]


def _is_plan(obj) -> bool:
    return hasattr(obj, "images") and hasattr(obj, "pole")


def _artists(obj, ax=None, lang: str = "en") -> list:
    from .drawing import draw_mechanism, draw_plan

    return draw_plan(obj, ax, lang=lang) if _is_plan(obj) else draw_mechanism(obj, ax, lang=lang)


def plot(obj, ax=None, *, lang: str = "en"):
    """Draw a plan, or a solution's mechanism at k_l, into *ax* (one data unit = 1 mm) or a new figure; returns the Axes."""
    artists = _artists(obj, ax, lang)
    return ax if ax is not None else artists[0].axes


def sheet(solution, *, lang: str = "en"):
    """The one-page sheet of a GraphicalSolution (mechanism, both plans, vector equations, readings, and the table
    against the analytic values) at its own factors, as a :class:`plans.pages.sheet.Sheet` (set by Typst)."""
    from .analytic import solve
    from .pages.sheet import sheet_at

    return sheet_at(solution, solve(solution.scene), lang=lang)


def save(obj, path, *, lang: str = "en"):
    """Write a plan, or a solution's sheet, to *path* (``.svg`` true to scale, ``.pdf`` or ``.png``), atomically; returns the path."""
    if not _is_plan(obj):
        return sheet(obj, lang=lang).save(path)
    from .drawing.formats import save_figure

    return save_figure(plot(obj, lang=lang).figure, path)


def svg(obj, *, lang: str = "en") -> str:
    """The SVG of a plan or of a solution's sheet, as text."""
    if not _is_plan(obj):
        return sheet(obj, lang=lang).pages("svg")[0].decode("utf-8")
    from .drawing.svg import render_svg

    return render_svg(plot(obj, lang=lang).figure).decode("utf-8")


def animate(scene, positions=36, *, lang: str = "en"):
    """A :class:`plans.lecture.Animation` of *scene* over *positions* of its cycle; a notebook shows it as the lecture page."""
    from .lecture import animate as lecture_animate

    return lecture_animate(scene, positions, lang=lang)


def animate_run(run, *, lang: str = "en"):
    """A :class:`plans.lecture.Animation` of a :class:`plans.positions.PositionsRun` (``run.animate()``), at its scale factors."""
    from .lecture import Animation

    return Animation(run, lang=lang)


def register(shell=None) -> bool:
    """Show GraphicalSolution and Plan objects as SVG in IPython (*shell*, or the running one).

    Returns whether a shell was found.  The types are named, not imported,
    so registering loads nothing.
    """
    if shell is None:
        ipython = sys.modules.get("IPython")
        shell = ipython.get_ipython() if ipython is not None and hasattr(ipython, "get_ipython") else None
    if shell is None:
        return False
    formatter = shell.display_formatter.formatters["image/svg+xml"]
    formatter.for_type_by_name("plans.graphical.plan", "Plan", svg)
    formatter.for_type_by_name("plans.graphical.plan", "GraphicalSolution", svg)
    return True


def kinematic_pages(diagrams, *, lang: str = "en", title: str = "") -> list:
    """The drawing of :class:`plans.differentiation.KinematicDiagrams` as a one-figure list, at the scales an A4
    page prints them readably (:func:`plans.drawing.kinematic_diagrams.draw_kinematic_figure`)."""
    from .drawing.kinematic_diagrams import draw_kinematic_figure, page_diagrams
    from .pages.document import A4_PORTRAIT

    return [draw_kinematic_figure(page_diagrams(diagrams, A4_PORTRAIT.text_width), title=title, lang=lang)]


def force_cycle_page(cycle_forces, *, lang: str = "en", title: str = ""):
    """The page of :class:`plans.forces.cycle.CycleForces` (:func:`plans.drawing.force_diagrams.draw_force_diagrams`)."""
    from .drawing.force_diagrams import draw_force_diagrams

    return draw_force_diagrams(cycle_forces, lang=lang, title=title)


def save_pages(pages, path) -> list:
    """Named figures written to *path* by its suffix (:func:`plans.drawing.formats.save_pages`)."""
    from pathlib import Path

    from .drawing.formats import save_pages as write

    return write(pages, Path(path))


def svg_of_figure(fig) -> str:
    """A figure as SVG text."""
    from .drawing.svg import render_svg

    return render_svg(fig).decode("utf-8")


DISPLAY.update(plot=plot, save=save, sheet=sheet, kinematic_pages=kinematic_pages, force_cycle_page=force_cycle_page, save_pages=save_pages, svg_of_figure=svg_of_figure, animate=animate, animate_run=animate_run)
