"""Drawings of a graphical solution: the mechanism, its plans, and a one-page sheet, as SVG;
the plan of positions and the sheets of a multi-position run, cycle diagrams,
the kinetostatics (force plans, free bodies, Joukowski's lever), and the A4
pages of a handout (SVG or PDF with the fonts embedded).

Everything is drawn true to scale: the SVG declares its size in millimetres,
and one millimetre of plan (or k_l metres of mechanism) is one millimetre of
paper when printed at 100 %.  Output is byte-for-byte deterministic and
written atomically.

This package and :mod:`plans.bench.plot` (the benchmark's figure) are the
only modules of plans that import matplotlib; nothing in ``plans.scene``,
``plans.structure``, ``plans.analytic`` or ``plans.graphical`` imports it.

>>> from plans.drawing import draw_mechanism, draw_plan  # doctest: +SKIP

The one-page sheets of ``plans draw`` (``write_drawings``, ``write_position_sheets``) are pages set by Typst:
:mod:`plans.pages.sheet` (``plans.write_drawings``, ``plans.write_position_sheets``).
"""

from .mechanism import draw_mechanism
from .plan_drawing import draw_acceleration_plan, draw_plan, draw_velocity_plan


def __getattr__(name: str):
    # multi-position output and handout pages, loaded on first use
    if name in ("render_pdf", "save_figure"):
        from . import formats

        return getattr(formats, name)
    if name in ("draw_positions_plan",):
        from .positions_plan import draw_positions_plan

        return draw_positions_plan
    if name in ("draw_force_plan", "draw_free_bodies", "draw_lever", "write_force_drawings"):
        from . import force_drawing

        return getattr(force_drawing, name)
    if name in ("draw_cycle_diagrams", "write_cycle_diagrams"):
        from . import diagrams

        return getattr(diagrams, name)
    raise AttributeError(f"module 'plans.drawing' has no attribute {name!r}")


__all__ = [
    "draw_mechanism",
    "draw_plan",
    "draw_velocity_plan",
    "draw_acceleration_plan",
    "draw_positions_plan",
    "draw_cycle_diagrams",
    "write_cycle_diagrams",
    "render_pdf",
    "save_figure",
    "draw_force_plan",
    "draw_free_bodies",
    "draw_lever",
    "write_force_drawings",
]
