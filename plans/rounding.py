"""Round values as drawings state them: the smallest (or largest) m·10ⁿ with m from a set of mantissas.

Every scale a page states is such a value, from one series, the standard's (:data:`STANDARD_MANTISSAS`,
1, 1.5, 2, 2.5, 4, 5, 7.5 × 10ⁿ): the plans' k_l, k_v, k_a (:mod:`plans.graphical.scales`), the kinematic
diagrams' μ_s, μ_v, μ_a (:mod:`plans.differentiation`; μ_t = T/L is the course's quotient, not a chosen
factor), the force plans' and the force diagrams' μ_F, μ_φ, μ_M.  k_l [m/mm] is the drawing scale
1 : (1000·k_l): 1:1, 1:1.5, 1:2, 1:2.5, 1:4, 1:5, 1:7.5 (for a reduction the standard has 1:75, not 1:7.5),
1:10, 1:15, 1:20, 1:25, 1:40, 1:50, 1:75, 1:100 … — the reduction scales of GOST 2.302 (ISO 5455's 1:2, 1:5,
1:10 … among them).  The textbook's coarser 1, 2, 2.5, 5 × 10ⁿ (:data:`TEXTBOOK_MANTISSAS`) is a subset.

>>> round_up(0.0123, (1, 2, 2.5, 5))
0.02
>>> round_down(0.0123, (1, 2, 2.5, 5))
0.01
"""

from __future__ import annotations

import math

__all__ = ["round_up", "round_down", "STANDARD_MANTISSAS", "TEXTBOOK_MANTISSAS", "is_standard"]

#: The one series of every scale a page states: m·10ⁿ with m among these, the reduction scales of GOST 2.302
#: (1:1, 1:2, 1:2.5, 1:4, 1:5, 1:10, 1:15, 1:20, 1:25, 1:40, 1:50, 1:75, 1:100 …) read as mantissas.
STANDARD_MANTISSAS = (1, 1.5, 2, 2.5, 4, 5, 7.5)
#: The textbook's round values, 1, 2, 2.5, 5 × 10ⁿ (domain.md §3): a subset of :data:`STANDARD_MANTISSAS`, used
#: where a value must draw its figure 60–120 mm long (consecutive values differ by 2 at most), the automatic
#: factor of one construction (:func:`plans.graphical.scales.round_scale`) and of the diagrams' first draft.
TEXTBOOK_MANTISSAS = (1, 2, 2.5, 5)


def round_up(need: float, mantissas=STANDARD_MANTISSAS) -> float:
    """The smallest m·10ⁿ (m in *mantissas*) not below *need* > 0 (as the nearest float to that decimal)."""
    n = math.floor(math.log10(need)) - 1
    while True:
        for m in mantissas:
            value = float(f"{m}e{n}")
            if value >= need * (1 - 1e-12):
                return value
        n += 1


def round_down(below: float, mantissas=STANDARD_MANTISSAS) -> float:
    """The largest m·10ⁿ (m in *mantissas*) not above *below* > 0 (as the nearest float to that decimal)."""
    n = math.floor(math.log10(below)) + 1
    while True:
        for m in reversed(mantissas):
            value = float(f"{m}e{n}")
            if value <= below * (1 + 1e-12):
                return value
        n -= 1


def is_standard(value: float, mantissas=STANDARD_MANTISSAS) -> bool:
    """Whether *value* > 0 is m·10ⁿ with m in *mantissas* (to 10⁻⁹ relative: a value as printed and read back)."""
    if not (value > 0 and math.isfinite(value)):
        return False
    n = math.floor(math.log10(value))
    return any(abs(value - m * 10.0**e) <= 1e-9 * value for m in mantissas for e in (n - 1, n, n + 1))
