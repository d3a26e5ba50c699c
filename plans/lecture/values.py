"""The values a lecture page shows beside each position: φ (or s), ω, ε, and the main v and a.

One table for all positions (the same rows in the same order), filled position
by position from the run's comparisons: the value read off the plans
(graphical) and the analytic one.  Numbers as the sheets print them
(:func:`plans.report.table_number`: four significant digits, a true minus),
with the decimal comma in sr, ru, bg and sl.  Nothing is computed here.
"""

from __future__ import annotations

import html
import math

from .._text import decimal_comma
from ..i18n import term
from ..report import table_number
from ..scene import Crank

__all__ = ["Row", "value_rows", "position_values", "column_heads", "NOT_SOLVED"]

#: A cell of a position that is not solved.
NOT_SOLVED = "—"

_UNITS = {"omega": "rad/s", "epsilon": "rad/s²", "v": "m/s", "a": "m/s²", "v_rel": "m/s", "a_rel": "m/s²", "coriolis": "m/s²"}


class Row:
    """One row of the table: where its value is found (``section``, ``name``, ``quantity``), its symbol as HTML, its unit."""

    def __init__(self, section: str, name: str, quantity: str, symbol: str, unit: str):
        self.section = section
        self.name = name
        self.quantity = quantity
        self.symbol = symbol
        self.unit = unit


def _sub(name: str) -> str:
    return f"<sub>{html.escape(name)}</sub>"


def value_rows(run) -> list[Row]:
    """The rows of the table of *run*: the driver's position (and the time t under the driver's law), then ω and ε of each link (blocks that only
    slide are left out), |v| and |a| of each reported point, and vʳ, aʳ, |aᵏ| of each prismatic pair."""
    scene = run.scene
    driver = scene.driver
    crank = isinstance(driver, Crank)
    rows = [Row("driver", driver.link, "phi" if crank else "s", ("φ" if crank else "s") + _sub(driver.link), "°" if crank else "mm")]
    if getattr(run, "motion", None) is not None:  # the time under the driver's law (plans.motion), from position 0
        rows.append(Row("time", "", "t", "t", "s"))
    accelerations = any(r.ok and r.graphical.acceleration_plan is not None for r in run.runs)
    for name in sorted((n for n in scene.links if not scene.bodies[n].block), key=lambda n: (0, int(n)) if n.isdigit() else (1, 0)):
        rows.append(Row("links", name, "omega", "ω" + _sub(name), _UNITS["omega"]))
        if accelerations:
            rows.append(Row("links", name, "epsilon", "ε" + _sub(name), _UNITS["epsilon"]))
    for name in scene.report:
        rows.append(Row("points", name, "v", f"|v{_sub(name)}|", _UNITS["v"]))
        if accelerations:
            rows.append(Row("points", name, "a", f"|a{_sub(name)}|", _UNITS["a"]))
    for pair in scene.prismatics:
        rows.append(Row("sliders", pair.name, "v_rel", f"v<sup>r</sup>{_sub(pair.name)}", _UNITS["v_rel"]))
        if accelerations:
            rows.append(Row("sliders", pair.name, "a_rel", f"a<sup>r</sup>{_sub(pair.name)}", _UNITS["a_rel"]))
            rows.append(Row("sliders", pair.name, "coriolis", f"|a<sup>k</sup>{_sub(pair.name)}|", _UNITS["coriolis"]))
    return rows


def _number(value, lang: str) -> str:
    if isinstance(value, complex):
        value = abs(value)
    return decimal_comma(table_number(float(value)), lang)


def _driver_value(position_run, lang: str) -> str:
    if isinstance(position_run.scene.driver, Crank):
        degrees = math.degrees(position_run.position) % 360.0
        text = f"{0.0 if round(degrees, 1) >= 360.0 else degrees:.1f}"
    else:
        text = f"{position_run.position * 1e3:.1f}"
    return decimal_comma(text.replace("-", "\u2212"), lang)


def position_values(run, rows: list[Row], lang: str = "en") -> list[list[list[str]]]:
    """For each position of *run*, for each row: ``[graphical, analytic]`` as text (the driver's position in
    both cells; :data:`NOT_SOLVED` where the position, or the quantity, is not solved)."""
    out = []
    for r in run.runs:
        found = {(c.section, c.name, c.quantity): c for c in (r.comparisons or ())}
        cells = []
        for row in rows:
            if row.section == "driver":
                text = _driver_value(r, lang)
                cells.append([text, text])
                continue
            if row.section == "time":
                text = decimal_comma(f"{float(run.motion.t[r.index]):.4f}", lang)
                cells.append([text, text])
                continue
            c = found.get((row.section, row.name, row.quantity)) if r.ok else None
            cells.append([NOT_SOLVED, NOT_SOLVED] if c is None else [_number(c.graphical, lang), _number(c.analytic, lang)])
        out.append(cells)
    return out


def column_heads(lang: str) -> list[str]:
    """The heads of the table's columns, in *lang*."""
    return [term("quantity", lang), term("graphical", lang), term("analytic", lang), term("lecture_unit", lang)]

