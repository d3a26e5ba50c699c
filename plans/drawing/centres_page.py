"""The content of the handout's instant-centre page of a position (``plans handout … --centres``).

The page itself is set by :mod:`plans.pages.handout`: the mechanism at that
position with every instant centre marked and labelled (P₁₂ …), the Kennedy
lines thin (:func:`plans.drawing.svgblocks.centres_svg`), the circle diagram,
the two rules and the table made here: ω of every link and v of every
reported point found from the centres (:mod:`plans.centres`, the third
method: its own positions and nothing of the analytic or graphical
kinematics) beside the analytic values of the handout's own analytic
solution, with the relative error (:func:`plans.compare.compare_centres`).
Words from :mod:`plans.i18n`, decimal comma in sr, ru, bg, sl.
"""

from __future__ import annotations

import cmath
import math

from .._text import decimal_comma
from ..i18n import term
from ..report import table_error, table_number
from .centres import centre_text

__all__ = ["centres_page_table", "centres_rules", "ROOM_MIN"]

#: the least room [mm] around the mechanism on the page (its near centres widen it; far ones are arrows outside)
ROOM_MIN = 12.0


def _number(value: float) -> str:
    """*value* to 6 significant digits as tables print numbers (:func:`plans.report.table_number`)."""
    return table_number(value, 6)


def _vector(z: complex) -> str:
    if z == 0:
        return "0"
    return f"{_number(abs(z))} ∠ {math.degrees(cmath.phase(z)):.1f}°".replace("-", "−")


def _about(result, body: str) -> str:
    """The label of P_1j of *body* (``P₁₃``), ``P₁₄ ∞`` when it is at infinity (the body translates)."""
    if body == "frame":
        return "—"
    centre = result.centre("frame", body)
    return centre_text(centre.label) + ("" if centre.point is not None else " ∞")


def centres_page_table(result, comparisons, lang: str = "en") -> list[list[str]]:
    """The page's table: header, then ω of every link and v of every reported point, from the centres and analytic.

    Columns: quantity, the centre P_1j its body turns about, the value from
    the centres, the analytic value, the relative error (of the vector for v).
    *comparisons* from :func:`plans.compare.compare_centres`.
    """
    rows = [[term("quantity", lang), "$P_{1j}$", term("by_centres", lang), term("analytic", lang), term("rel_error", lang)]]
    by = {(c.section, c.name): c for c in comparisons}
    for name in result.scene.links:
        row = by.get(("links", name))
        if row is not None:
            rows.append([f"$\\omega_{{{name}}}$ [rad/s]", _about(result, name), _number(row.graphical), _number(row.analytic), table_error(row.rel_error)])
    for name in result.scene.report:
        row = by.get(("points", name))
        if row is not None:
            rows.append([f"$v_{{{name}}}$ [m/s]", _about(result, result.scene.home_of(name)), _vector(complex(row.graphical)),
                         _vector(complex(row.analytic)), table_error(row.rel_error)])
    return [[decimal_comma(cell, lang) for cell in row] for row in rows]


def centres_rules(lang: str) -> list[str]:
    """The two rules of the method, each with its formula (``$…$``): ω from the centres, v of a point from its link's centre."""
    return [
        f"{term('centres_omega_rule', lang)}:  $\\omega_j / \\omega_k = P_{{1k}}P_{{jk}} / P_{{1j}}P_{{jk}}$",
        f"{term('centres_v_rule', lang)}:  $v_M = \\omega_j \\cdot P_{{1j}}M$",
    ]
