"""The values a lecture page shows beside each position: φ (or s), ω, ε, and the main v and a.

One table for all positions (the same rows in the same order), filled position
by position from the run's comparisons: the value read off the plans
(graphical) and the analytic one.  A row that is zero at every position (|aᵏ|
of a slider on a guide that does not turn, ε of a crank at constant speed) is
left out.  Each row keeps one number of decimals over the cycle (the digits do
not jump as the crank turns): the graphical column no finer than a plan is
read (the drafting precision, 0.1 mm, times k_v or k_a; ω and ε to three
significant digits of the row's largest value), the analytic column one
decimal more.  A true minus, the decimal comma in sr, ru, bg and sl.
"""

from __future__ import annotations

import html
import math

from .._text import decimal_comma
from ..i18n import term
from ..scene import Crank

__all__ = ["Row", "value_rows", "position_values", "column_heads", "value_notes", "row_decimals", "NOT_SOLVED", "READING_MM"]

#: A cell of a position that is not solved.
NOT_SOLVED = "—"

#: The precision [mm] to which a plan is read when the scene states none (as on the sheets).
READING_MM = 0.1
#: The scale factor a quantity is read off the plans with.
_SCALE_OF = {"v": "k_v", "v_rel": "k_v", "a": "k_a", "a_rel": "k_a", "coriolis": "k_a"}
#: A value this small [SI] is zero (a row zero at every position is left out).
_ZERO = 1e-9

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
    return [row for row in rows if row.section in ("driver", "time") or not _zero_everywhere(run, row)]


def _comparisons(run, row):
    for r in run.runs:
        if r.ok:
            for c in r.comparisons or ():
                if (c.section, c.name, c.quantity) == (row.section, row.name, row.quantity):
                    yield c


def _zero_everywhere(run, row) -> bool:
    """Whether *row*'s analytic value is zero at every solved position (a row with no value at all is kept: it says —)."""
    found = list(_comparisons(run, row))
    return bool(found) and all(abs(c.analytic) <= _ZERO for c in found)


def row_decimals(run, row) -> int:
    """Decimals of *row*'s graphical values over the cycle: v and a to the plans' reading step (the scene's
    drafting precision, else :data:`READING_MM`, times k_v or k_a: 0.1 mm × 0.05 (m/s)/mm = 0.005 m/s → 3),
    ω and ε (a plan's segment over a link's length) to three significant digits of the row's largest value."""
    if row.quantity in _SCALE_OF:
        precision = getattr(run.scene.scales, "precision", None) or READING_MM
        step = precision * float(run.scales[_SCALE_OF[row.quantity]])
        return max(0, math.ceil(-math.log10(step) - 1e-9))
    largest = max((abs(c.analytic) for c in _comparisons(run, row)), default=0.0)
    if largest <= _ZERO:
        return 0
    return max(0, 2 - math.floor(math.log10(largest)))


def _number(value, lang: str, decimals: int) -> str:
    if isinstance(value, complex):
        value = abs(value)
    text = f"{float(value):.{decimals}f}"
    if float(text) == 0.0:
        text = text.lstrip("-")  # no −0.00
    return decimal_comma(text.replace("-", "\u2212"), lang)


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
    decimals = [row_decimals(run, row) if row.section not in ("driver", "time") else 0 for row in rows]
    out = []
    for r in run.runs:
        found = {(c.section, c.name, c.quantity): c for c in (r.comparisons or ())}
        cells = []
        for row, places in zip(rows, decimals):
            if row.section == "driver":
                text = _driver_value(r, lang)
                cells.append([text, text])
                continue
            if row.section == "time":
                text = decimal_comma(f"{float(run.motion.t[r.index]):.4f}", lang)
                cells.append([text, text])
                continue
            c = found.get((row.section, row.name, row.quantity)) if r.ok else None
            cells.append([NOT_SOLVED, NOT_SOLVED] if c is None else [_number(c.graphical, lang, places), _number(c.analytic, lang, places + 1)])
        out.append(cells)
    return out


def value_notes(run, rows: list[Row], lang: str = "en") -> list[str]:
    """The table's footnotes in *lang*: the reading precision of the graphical values, and for each prismatic
    pair in the table the positive direction of its vʳ and aʳ (along its guide line, in that line's direction)."""
    precision = getattr(run.scene.scales, "precision", None) or READING_MM
    notes = [term("lecture_digits", lang).format(precision=decimal_comma(f"{precision:g}", lang))]
    pairs = {p.name: p for p in run.scene.prismatics}
    for name in dict.fromkeys(row.name for row in rows if row.quantity in ("v_rel", "a_rel")):
        pair = pairs[name]
        line = run.scene.bodies[pair.guide].lines[pair.guide_line]
        angle = decimal_comma(f"{math.degrees(line.angle) % 360.0:.1f}", lang)
        key = "lecture_relative_sign_frame" if run.scene.bodies[pair.guide].is_frame else "lecture_relative_sign"
        notes.append(term(key, lang).format(pair=name, line=pair.guide_line, guide=pair.guide, angle=angle))
    return notes


def column_heads(lang: str) -> list[str]:
    """The heads of the table's columns, in *lang*."""
    return [term("quantity", lang), term("graphical", lang), term("analytic", lang), term("lecture_unit", lang)]

