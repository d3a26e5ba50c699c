"""Automatic round scale factors and the drafting precision of a measurement.

A scale factor k maps a physical quantity to millimetres of drawing:
physical = k × drawn length.  Textbooks choose k among the round values
1, 2, 2.5 and 5 × 10ⁿ so that the figure fills the page; plans chooses the
smallest such value that draws the largest vector (or the larger side of the
mechanism's bounding box) at most :data:`DRAWN_MAX` = 120 mm long, which
then is more than :data:`DRAWN_MIN` = 60 mm long (consecutive round values
differ by a factor of 2 at most).

>>> round_scale(1.5)        # 1.5 m/s drawn 75 mm long with 0.02 (m/s)/mm
0.02
>>> round_scale(3101.7 * 2 ** 0.5)
50.0
"""

from __future__ import annotations

import math

__all__ = ["MANTISSAS", "DRAWN_MIN", "DRAWN_MAX", "round_scale", "measure"]

#: The round mantissas of a scale factor.
MANTISSAS = (1, 2, 2.5, 5)
#: The range [mm] the largest drawn length falls into.
DRAWN_MIN = 60.0
DRAWN_MAX = 120.0


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
