"""Automatic round scale factors and the drafting precision of a measurement.

A scale factor k maps a physical quantity to millimetres of drawing:
physical = k × drawn length.  Textbooks choose k among the round values
1, 2, 2.5 and 5 × 10ⁿ so that the figure fills the page; plans chooses the
smallest such value that draws the largest vector (or the larger side of the
mechanism's bounding box) at most :data:`DRAWN_MAX` = 120 mm long, which
then is more than :data:`DRAWN_MIN` = 60 mm long (consecutive round values
differ by a factor of 2 at most).

A scale factor given by the user (an argument, or the scene's ``[scales]``)
must draw the figure at least :data:`DRAWN_LEAST` = 1 mm and at most
:data:`DRAWN_LARGEST` = 1165 mm large (the long side of A0, the largest
sheet plans draws, less its margins); :func:`check_scale` refuses it
otherwise and says which range of the factor fits.  The size of a figure is
the larger side of its bounding box (:func:`extent`): the mechanism's
points, or a plan's pole, images and vector ends.

>>> round_scale(1.5)        # 1.5 m/s drawn 75 mm long with 0.02 (m/s)/mm
0.02
>>> round_scale(3101.7 * 2 ** 0.5)
50.0
"""

from __future__ import annotations

import math
import sys

from .. import rounding

__all__ = [
    "MANTISSAS",
    "PAGE_MANTISSAS",
    "round_up",
    "round_down",
    "DRAWN_MIN",
    "DRAWN_MAX",
    "DRAWN_LEAST",
    "DRAWN_LARGEST",
    "round_scale",
    "measure",
    "extent",
    "fitting_range",
    "check_scale",
]

#: The round mantissas of a scale factor.
MANTISSAS = (1, 2, 2.5, 5)
#: The finer mantissas with which a page's drawings fill their boxes (handouts, the centres page).
PAGE_MANTISSAS = (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8)
#: The range [mm] the largest drawn length falls into.
DRAWN_MIN = 60.0
DRAWN_MAX = 120.0
#: The smallest size [mm] a figure may be drawn at a given scale factor.
DRAWN_LEAST = 1.0
#: The largest size [mm] a figure may be drawn: A0's long side, 1189 mm, less two 12 mm margins.
DRAWN_LARGEST = 1165.0

_UNITS = {"k_l": "m/mm", "k_v": "(m/s)/mm", "k_a": "(m/s²)/mm"}


def round_up(need: float, mantissas=PAGE_MANTISSAS) -> float:
    """The smallest m·10ⁿ (m in *mantissas*, the pages' by default) not below *need* (:func:`plans.rounding.round_up`)."""
    return rounding.round_up(need, mantissas)


def round_down(below: float, mantissas=PAGE_MANTISSAS) -> float:
    """The largest m·10ⁿ (m in *mantissas*, the pages' by default) not above *below* (:func:`plans.rounding.round_down`)."""
    return rounding.round_down(below, mantissas)


def round_scale(largest: float, fallback: float = 1.0) -> float:
    """The smallest round scale factor that draws *largest* at most 120 mm long.

    Parameters
    ----------
    largest : float
        The largest physical quantity to draw [m, m/s or m/s²].
    fallback : float
        Returned when there is nothing to draw (*largest* is 0, or not a
        finite positive number).

    Returns
    -------
    float
        k = m × 10ⁿ with m in (1, 2, 2.5, 5), as the nearest float to that
        decimal; ``DRAWN_MIN < largest / k <= DRAWN_MAX``.
    """
    if not (math.isfinite(largest) and largest > 0.0):
        return fallback
    least = largest / DRAWN_MAX
    n = math.floor(math.log10(least))  # may be off by one near a power of ten
    for exponent in (n - 1, n, n + 1):
        for mantissa in MANTISSAS:
            k = float(f"{mantissa}e{exponent}")
            if k >= least:
                return k
    return float(f"1e{n + 2}")  # unreachable: 1e(n+1) >= least always


def measure(length: float, precision: float | None) -> float:
    """A length as read with a ruler [mm]: rounded to a multiple of *precision* [mm] if one is set."""
    if precision is None:
        return length
    return round(length / precision) * precision


def read_segment(length: float, precision: float | None) -> float:
    """A plan's segment [mm] as read: to *precision* [mm], a short one (under :data:`plans.rounding.SHORT_READ_MM`) to a tenth of it
    (the value its note under the plan gives: :func:`plans.rounding.reading_step`)."""
    return measure(length, None if precision is None else rounding.reading_step(length, precision))


def extent(points) -> float:
    """The larger side of the bounding box of complex *points* (0 for none) [their unit]."""
    points = list(points)
    if not points:
        return 0.0
    xs = [z.real for z in points]
    ys = [z.imag for z in points]
    return max(max(xs) - min(xs), max(ys) - min(ys))


def fitting_range(size: float) -> tuple[float, float]:
    """The scale factors [unit/mm] that draw a figure of physical *size* DRAWN_LEAST … DRAWN_LARGEST mm large."""
    return size / DRAWN_LARGEST, size / DRAWN_LEAST


def check_scale(key: str, k: float, size: float, *, what: str, where: str, source: str | None, field: str | None) -> None:
    """Refuse a scale factor that draws a figure of physical *size* larger than a sheet or smaller than 1 mm.

    Parameters
    ----------
    key : str
        ``"k_l"``, ``"k_v"`` or ``"k_a"``.
    k : float
        The scale factor [unit/mm].
    size : float
        The figure's physical size, :func:`extent` of it [m, m/s or m/s²];
        0 (a plan of a mechanism at rest) fits any factor.
    what, where : str
        The figure (``"the velocity plan"``) and the position (``"at φ = 30.0°"``), for the message.
    source, field : str or None
        Where the factor came from, for :class:`plans.errors.SceneError`
        (field None for a factor given as an argument).

    Raises
    ------
    plans.errors.SceneError
        Naming the size the factor would draw and the range that fits.
    """
    from ..errors import SceneError

    if not (math.isfinite(size) and size > 0):
        return
    drawn = size / k
    if DRAWN_LEAST <= drawn <= DRAWN_LARGEST:
        return
    low, high = fitting_range(size)
    unit = _UNITS[key]
    problem = "larger than the largest sheet (A0)" if drawn > DRAWN_LARGEST else "smaller than a millimetre"
    drawn_text = f"{drawn:.3g} mm large" if math.isfinite(drawn) else f"larger than {sys.float_info.max:.3g} mm (the largest number there is)"
    raise SceneError(
        f"{key} = {k:g} {unit} draws {what} {drawn_text} {where}, {problem}; a figure is drawn "
        f"{DRAWN_LEAST:g} to {DRAWN_LARGEST:g} mm large: for this scene at this position {key} from "
        f"{_round_up(low)} to {_round_down(high)} {unit} fits (leave it out for an automatic round value)",
        source,
        field,
    )


def _round_up(x: float) -> str:
    """*x* to 3 significant digits, rounded up."""
    e = math.floor(math.log10(x)) - 2
    if not 10.0**e > 0:
        return f"{x:.3g}"
    return f"{math.ceil(x / 10.0**e * (1 - 1e-12)) * 10.0**e:.3g}"


def _round_down(x: float) -> str:
    """*x* to 3 significant digits, rounded down."""
    e = math.floor(math.log10(x)) - 2
    if not 10.0**e > 0:
        return f"{x:.3g}"
    return f"{math.floor(x / 10.0**e * (1 + 1e-12)) * 10.0**e:.3g}"
