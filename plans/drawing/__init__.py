"""Drawings of a graphical solution: the mechanism, its plans, and a one-page sheet, as SVG.

Everything is drawn true to scale: the SVG declares its size in millimetres,
and one millimetre of plan (or k_l metres of mechanism) is one millimetre of
paper when printed at 100 %.  Output is byte-for-byte deterministic and
written atomically.

This package is the only one in plans that imports matplotlib; nothing in
``plans.scene``, ``plans.structure``, ``plans.analytic`` or
``plans.graphical`` imports it.

>>> from plans.drawing import write_drawings  # doctest: +SKIP
>>> write_drawings(solution, "out", formula="I(0,2) → RRP(3,4)")  # doctest: +SKIP
[PosixPath('out/mechanism.svg'), PosixPath('out/velocity.svg'), PosixPath('out/acceleration.svg'), PosixPath('out/sheet.svg')]
"""

from .mechanism import draw_mechanism
from .plan_drawing import draw_acceleration_plan, draw_plan, draw_velocity_plan
from .sheet import draw_sheet, write_drawings

__all__ = [
    "draw_mechanism",
    "draw_plan",
    "draw_velocity_plan",
    "draw_acceleration_plan",
    "draw_sheet",
    "write_drawings",
]
