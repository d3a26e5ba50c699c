"""Blocks: the rectangles a page is made of, each knowing its size [mm] before it is placed.

Data flows one way: solved results → blocks (this module) → page layout
(:mod:`plans.drawing.layout`) → SVG/PDF (:mod:`plans.drawing.svg`).  The sheets and the
handout are set by Typst (:mod:`plans.pages`); they take :func:`plan_readings` from here.

* :class:`Block` — width, height and a function that draws it at a lower-left corner;
* :func:`legend_block` — one legend for both plans;
* :func:`plan_readings` — what a student measures on each plan and
  computes from it: segment, length as printed, × scale factor (÷ link length) = value;
* :func:`pretty_equation`, :func:`break_math`, :func:`text_rows` — the lines of
  vector and loop equations, typeset and broken to a width.
"""

from __future__ import annotations

import math
import re

from ..i18n import term
from .._text import decimal_comma, math_name, user_text
from ._canvas import Sketch, text_size
from .plan_drawing import aliases, end_letters, legend_entries, legend_row, segment, vectors_drawn
from .style import CAPTION_PT, HEADING_PT
from .typeset import measure

__all__ = [
    "Block",
    "legend_block",
    "plan_readings",
    "link_length",
    "printed_length",
    "pretty_equation",
    "break_math",
    "text_rows",
    "MIN_SHRINK",
]

#: a line of an equation is set at most this much smaller before it is wrapped inside a term
MIN_SHRINK = 0.8
CONTINUED = "…"


class Block:
    """A rectangle [mm] with a function that draws it with its lower-left corner at (x, y).

    ``place(sketch, x, y, page)``: *sketch* draws on the page's paper axes
    (text and rules); *page* is the page size [mm], for blocks that have axes
    of their own (drawings) and put them there.
    """

    def __init__(self, width: float, height: float, place, kind: str = "text"):
        self.width = width
        self.height = height
        self._place = place
        #: ``"mechanism"``, ``"velocity"``, ``"acceleration"``, ``"legend"``, ``"table"``, ``"text"``, ``"column"``
        self.kind = kind

    def place(self, sketch: Sketch, x: float, y: float, page: tuple[float, float]) -> None:
        self._place(sketch, x, y, page)


def legend_block(graphical, lang: str, columns: int = 1, plans=("velocity", "acceleration")) -> Block:
    """One legend for the *plans* (both by default): each kind of vector drawn, and construction lines (in *columns*, filled down)."""
    drawn = [plan for plan in (graphical.velocity_plan, graphical.acceleration_plan) if plan is not None and plan.kind in plans]
    entries = legend_entries(drawn, lang)
    row_h = text_size("lp", CAPTION_PT)[1] + 0.8
    column_w = 11.0 + max(text_size(w, CAPTION_PT)[0] for _, w in entries) + 6.0
    per = -(-len(entries) // max(1, columns))
    used = -(-len(entries) // per)
    width = column_w * used - 6.0
    height = row_h * per

    def place(sketch: Sketch, x: float, y: float, page) -> None:
        for k, (kind, text) in enumerate(entries):
            c, r = divmod(k, per)
            legend_row(sketch, kind, text, x + c * column_w, y + height - row_h * (r + 0.5), text_gid="legend-text")

    return Block(width, height, place, kind="legend")


# --- readings: what is measured on a plan and what it gives ------------------------------------

_UNIT = {"velocity": "m/s", "acceleration": "m/s²"}
_RATE = {"velocity": ("omega", r"\omega", "rad/s"), "acceleration": ("epsilon", r"\varepsilon", "rad/s²")}


def printed_length(length: float, precision: float | None) -> str:
    """A measured length [mm] as a sheet prints it: to the drafting precision's decimals (0.1 mm: ``"59.2"``),
    to 0.001 mm when readings are exact (no precision); a segment under 3 mm to a tenth of the precision, as
    the note under the plan gives it (:func:`plans.graphical.scales.read_segment`)."""
    from ..graphical.scales import SHORT_READ_MM

    if precision is not None and abs(length) < SHORT_READ_MM:
        precision = precision / 10  # a short segment is read as its note under the plan gives it (0.01 mm)
    decimals = 3 if precision is None else max(0, math.ceil(-math.log10(precision) - 1e-9))
    return f"{abs(length):.{decimals}f}"


def _vector_symbol(label: str) -> str:
    head, _, sub = label.partition("_")
    base, _, sup = head.partition("^")
    return f"${base}" + (f"^{{{sup}}}" if sup else "") + (f"_{{{math_name(sub)}}}" if sub else "") + "$"


def link_length(graphical, between: str) -> str:
    """The length a link's ω (ε) is divided by, as mathtext the textbook writes: ``l_{AC}``.

    *between* is the subscript of the plan vector it is read from (``"A4C"``: the point A of link 4 and C); the two
    points are named as the scene names them (A, C), without the link number that tells the plan's coincident points
    apart.  A subscript not made of two points of the plans is written as it is.
    """
    written: dict[str, str] = {}
    for plan in (graphical.velocity_plan, graphical.acceleration_plan):
        for name, body in (getattr(plan, "points", None) or {}).values():
            written.setdefault(name + body, name)
    for cut in range(1, len(between)):
        first, second = between[:cut], between[cut:]
        if first in written and second in written:
            return f"l_{{{math_name(written[first] + written[second])}}}"
    return f"l_{{{math_name(between)}}}"


def plan_readings(graphical, kind: str, lang: str = "en") -> list[list[str]]:
    """The readings table of one plan (*kind* ``"velocity"`` or ``"acceleration"``): header, then one row per value.

    Columns: the quantity, the segment measured (``pa``, ``n₁ c′``), its
    length [mm] as printed (to the drafting precision), × the scale factor,
    ÷ the link length [m] (ω, ε only), and = the value, which is exactly
    what the results table calls graphical: point velocities
    (accelerations), the drawn relative vectors of sliders, then ω (ε) of the
    links with the sense.  Values to the digits one drafting step of the segment justifies
    (:func:`plans.report.reading_number`; 4 significant digits when readings are exact).
    """
    from ..report import reading_number, table_number

    plan = graphical.velocity_plan if kind == "velocity" else graphical.acceleration_plan
    if plan is None:
        return []
    k = plan.scale
    key = "k_v" if kind == "velocity" else "k_a"
    drawn = vectors_drawn(plan)
    letters = end_letters(drawn, plan)
    by_label = {v.label: v for v in plan.vectors}
    precision = graphical.precision
    unit = _UNIT[kind]
    rows = [["", term("segment", lang), "mm", f"× ${key[0]}_{{{key[2]}}}$  (÷ l [m])", "="]]

    def row(symbol: str, v, divide: float | None = None, sense: float | None = None, between: str = "") -> list[str]:
        length = v.value / k if v is not None else 0.0
        measured = segment(plan, v, letters) if v is not None else "—"
        value = (v.value if v is not None else 0.0) / (divide or 1.0)
        # to the digits one drafting step of the segment justifies, as the results table prints the same reading
        # (plans.report.reading_step): one number for one quantity on a page
        step = precision * k / (divide or 1.0) if precision else None
        if sense is not None:  # ω, ε: the magnitude measured, the sense seen on the plan
            value = math.copysign(value, sense)
            rate_unit = _RATE[kind][2]
            # the sense as the arc arrow a plan or a scheme draws it (↺ counter-clockwise, ↻ clockwise): the
            # same narrow sign in every language, so the readings stand beside the results table
            arrow = "" if value == 0 else (" ↺" if value > 0 else " ↻")
            text = f"{reading_number(abs(value), step)} {rate_unit}{arrow}"
        else:
            text = f"{reading_number(value, step)} {unit}"
        factor = f"×\u00a0{fmt(k)}" if divide is not None else f"× {fmt(k)}"
        if divide is not None:
            # the link length by the textbook's name, the segment between the two points as the scene names them;
            # no-break spaces: the cell never wraps inside it
            factor += f"\u00a0÷\u00a0{table_number(divide)}\u00a0(${link_length(graphical, between)}$)"
        return [symbol, measured, printed_length(length, precision), factor, text]

    from ._canvas import fmt_number as fmt

    symbol = "v" if kind == "velocity" else "a"
    # a vector drawn once under several names is one row naming it each way: "v_A4 = v_A4C"
    also = aliases(plan)
    listed: set[str] = set()  # every name a row gives

    def symbols(label: str) -> str:
        listed.update([label] + also.get(label, []))
        return " = ".join(_vector_symbol(x)[1:-1] for x in [label] + also.get(label, [])).join("$$")

    for name in graphical.scene.report:
        label = f"{symbol}_{name}"
        v = by_label.get(label)
        if v is not None:
            rows.append(row(symbols(label), v))
    # the points of links at sliders (A4, E5): their absolute vectors too
    reported = {f"{symbol}_{name}" for name in graphical.scene.report} | {f"{symbol}_{name}" for name in graphical.scene.point_names}
    for v in plan.vectors:
        if v.kind == "absolute" and v.label not in reported:
            rows.append(row(symbols(v.label), v))
    for name, entry in getattr(graphical, "relative", {}).items():
        for q in (("v_rel",) if kind == "velocity" else ("coriolis", "a_rel")):
            label = entry.get(q)
            v = by_label.get(label) if label else None
            if v is not None and label not in listed:
                rows.append(row(_vector_symbol(label), v))
    rate, tex, _ = _RATE[kind]
    shared: dict[tuple, list[str]] = {}
    for link, entry in getattr(graphical, "rotations", {}).items():
        if rate in entry:
            shared.setdefault(entry[rate], []).append(link)
    for (label, between, length), links in shared.items():
        v = by_label.get(label)
        symbol_text = "$" + " = ".join(f"{tex}_{{{math_name(link)}}}" for link in links) + "$"
        rows.append(row(symbol_text, v, divide=length, sense=graphical.links[links[0]][rate], between=between))
    if len(rows) == 1:
        return []
    return [[decimal_comma(cell, lang) for cell in r] for r in rows]


_TOKEN = re.compile(r"(?<![A-Za-z0-9.])([A-Za-zα-ωΑ-Ω])(?:\^([A-Za-z]+))?(?:_([A-Za-z0-9′_]*[A-Za-z0-9′]))?(?![A-Za-z0-9])")


def pretty_equation(line: str) -> str:
    """``v_BA``, ``a^n_CB``, ``ω2`` → typeset sub- and superscripts (``$v_{BA}$``); other text as it is.

    A line that already holds ``$`` is left alone.
    """
    if "$" in line:
        return line

    def repl(m: re.Match) -> str:
        base, sup, sub = m.group(1), m.group(2), m.group(3)
        if not sup and not sub or (not sup and base.isascii() and base.isupper()):
            return m.group(0)  # a point's name (C_1_2), or segment (C_1_2A_1_2): as written
        sup_part = f"^{{{sup}}}" if sup else ""
        sub_part = f"_{{{math_name(sub)}}}" if sub else ""  # names as written: A_1_2 is no double subscript
        return f"${base}{sup_part}{sub_part}$"

    text = _TOKEN.sub(repl, line)
    return re.sub(r"(?<![A-Za-z0-9$])([α-ω])(\d+)(?![A-Za-z0-9])", r"$\1_{\2}$", text)


def _cuts(body: str) -> list[int]:
    """Where a mathtext body may break: before a top-level ``=``, ``⇒``, ``+`` or ``−`` between terms."""
    cuts = []
    depth = 0
    for k, ch in enumerate(body):
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif depth == 0 and k > 0 and (body.startswith((" = ", " + ", " - "), k) or body.startswith(r"\ \Rightarrow", k)):
            cuts.append(k)
    return cuts


def break_math(line: str, width: float, size: float) -> list[tuple[str, float]]:
    """*line* as lines ``(text, size)`` that each fit *width* [mm]; always ends, for any width.

    1. a line that fits is kept;
    2. a ``$…$`` line is broken before its top-level ``=``, ``⇒``, ``+``,
       ``−`` (continuations indented), as many terms to a line as fit;
    3. a piece that alone is still too wide is set smaller, down to
       :data:`MIN_SHRINK` of *size*;
    4. what still does not fit is wrapped inside the term as plain text,
       each broken line ending in ``…`` (so the reader sees it continues).
    """
    if measure(line, size)[0] <= width:
        return [(line, size)]
    if not (line.startswith("$") and line.endswith("$") and line.count("$") == 2):
        return [(piece, size) for piece in _wrap_plain(line, width, size)]
    body = line[1:-1]
    cuts = _cuts(body)
    terms = [body[a:b].strip() for a, b in zip([0] + cuts, cuts + [len(body)])]
    indent = r"\qquad "
    out: list[tuple[str, float]] = []
    current = ""
    for t in terms:
        trial = f"{current} {t}" if current else (t if not out else indent + t)
        if current and measure(f"${trial}$", size)[0] > width:
            out.append((f"${current}$", size))
            current = indent + t
        else:
            current = trial
    out.append((f"${current}$", size))
    final: list[tuple[str, float]] = []
    for text, s in out:
        w = measure(text, s)[0]
        shrunk = s * max(MIN_SHRINK, width / w * 0.999)
        if w <= width:
            final.append((text, s))
        elif measure(text, shrunk)[0] <= width:
            final.append((text, shrunk))
        else:
            small = s * MIN_SHRINK
            final.extend((piece, small) for piece in _wrap_plain(_plain(text), width, small))
    return final


def _plain(text: str) -> str:
    """A math line as plain text that keeps its meaning (``ω_3^2``, true minus signs), for wrapping inside a term."""
    from ..loops import plain

    flat = plain(text.replace(r"\qquad", r"\quad"))
    return " ".join(flat.split()).replace(" - ", " − ").replace("(-", "(−").replace("=-", "=−")


def _wrap_plain(text: str, width: float, size: float) -> list[str]:
    """Plain *text* wrapped to *width* [mm]: at spaces where it can, inside a word where it must (ending ``…``)."""
    lines: list[str] = []
    current = ""
    for word in text.split(" "):
        trial = f"{current} {word}" if current else word
        if measure(trial, size)[0] <= width or not current and measure(word, size)[0] <= width:
            current = trial
            continue
        if current:
            lines.append(current)
        current = word
        while measure(current, size)[0] > width and len(current) > 1:
            # the longest head that fits with its continuation mark
            lo, hi = 1, len(current) - 1
            while lo < hi:
                mid = (lo + hi + 1) // 2
                if measure(current[:mid] + CONTINUED, size)[0] <= width:
                    lo = mid
                else:
                    hi = mid - 1
            lines.append(current[:lo] + CONTINUED)
            current = current[lo:]
    if current:
        lines.append(current)
    return lines


def text_rows(heading: str, lines: list[str], width: float, size: float) -> list[tuple[str, float, str]]:
    """Rows ``(text, size, weight)`` of a text block: a bold heading, then *lines* broken to *width* [mm].

    A line starting with ``§`` is a bold subheading; other lines go through :func:`break_math`.
    """
    rows = [(heading, HEADING_PT, "bold")]
    for line in lines:
        if line.startswith("§"):
            rows.extend((piece, size, "bold") for piece in _wrap_plain(user_text(line[1:]) if "$" not in line else line[1:], width, size))
            continue
        rows.extend((piece, s, "normal") for piece, s in break_math(line, width, size))
    return rows
