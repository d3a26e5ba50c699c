"""Round values as drawings state them: the smallest (or largest) m·10ⁿ with m from a set of mantissas.

Every scale a page states is such a value: the plans' k_l, k_v, k_a (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 × 10ⁿ,
:mod:`plans.graphical.scales`), the kinematic diagrams' μ_t, μ_s (1, 2, 2.5, 5 × 10ⁿ,
:mod:`plans.differentiation`) and the force diagrams' μ_φ, μ_M, μ_F.

>>> round_up(0.0123, (1, 2, 2.5, 5))
0.02
>>> round_down(0.0123, (1, 2, 2.5, 5))
0.01
"""

from __future__ import annotations

import math

__all__ = ["round_up", "round_down", "TEXTBOOK_MANTISSAS", "SHORT_READ_MM", "reading_step"]

#: The textbook's round values: 1, 2, 2.5, 5 × 10ⁿ.
TEXTBOOK_MANTISSAS = (1, 2, 2.5, 5)


def round_up(need: float, mantissas=TEXTBOOK_MANTISSAS) -> float:
    """The smallest m·10ⁿ (m in *mantissas*) not below *need* > 0 (as the nearest float to that decimal)."""
    n = math.floor(math.log10(need)) - 1
    while True:
        for m in mantissas:
            value = float(f"{m}e{n}")
            if value >= need * (1 - 1e-12):
                return value
        n += 1


def round_down(below: float, mantissas=TEXTBOOK_MANTISSAS) -> float:
    """The largest m·10ⁿ (m in *mantissas*) not above *below* > 0 (as the nearest float to that decimal)."""
    n = math.floor(math.log10(below)) + 1
    while True:
        for m in reversed(mantissas):
            value = float(f"{m}e{n}")
            if value <= below * (1 + 1e-12):
                return value
        n -= 1


#: a length on a drawing shorter than this [mm] is read to a tenth of the drafting precision, as if on a 10:1 detail
#: (the page prints it to 0.01 mm: ``n₁ b′ = 2,65 mm``): the drafting rule the plans and the centres both read by
SHORT_READ_MM = 3.0


def reading_step(mm: float, precision: float) -> float:
    """The step [mm] a length of *mm* on a drawing is read to: *precision*, a tenth of it under :data:`SHORT_READ_MM`."""
    return precision / 10 if mm < SHORT_READ_MM else precision
