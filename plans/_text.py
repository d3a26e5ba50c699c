"""Text helpers shared by the drawings and the handout (no matplotlib here).

* :data:`SUBSCRIPT` — the ``str.translate`` table of the digits to subscript digits;
* :func:`subscript` — a link's name as the subscript of a symbol: ``"3"`` → ``"₃"``, ``"rod"`` → ``"_rod"``.
"""

from __future__ import annotations

__all__ = ["SUBSCRIPT", "subscript"]

#: Digits to subscript digits, for :meth:`str.translate`.
SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def subscript(name: str) -> str:
    """*name* as the subscript of a symbol: subscript digits for a number (``"3"`` → ``"₃"``), else ``"_name"``."""
    return name.translate(SUBSCRIPT) if name.isdigit() else f"_{name}"
