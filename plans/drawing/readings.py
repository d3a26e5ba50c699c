"""What a student measures on each plan and computes from it: segment, its length as printed, × the scale factor
(÷ a link's length) = the value (:func:`plan_readings`); the sheets and the handout set these tables (Typst,
:mod:`plans.pages`).
"""

from __future__ import annotations

import math

from ..i18n import term
from .._text import decimal_comma, math_name
from .plan_drawing import aliases, end_letters, image_text, pole_text, segment, vectors_drawn

__all__ = ["plan_readings", "link_length", "printed_length", "similar_images", "similarity_lines"]


_UNIT = {"velocity": "m/s", "acceleration": "m/s²"}
_RATE = {"velocity": ("omega", r"\omega", "rad/s"), "acceleration": ("epsilon", r"\varepsilon", "rad/s²")}


def printed_length(length: float, precision: float | None) -> str:
    """A measured length [mm] as a sheet prints it: to the drafting precision's decimals (0.1 mm: ``"59.2"``),
    to 0.001 mm when readings are exact (no precision); a segment under 3 mm to a tenth of the precision, as
    the note under the plan gives it (:func:`plans.graphical.scales.read_segment`)."""
    from ..rounding import reading_step

    if precision is not None:  # a short segment is read as its note under the plan gives it (0.01 mm)
        precision = reading_step(abs(length), precision)
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
    rows = [["", term("segment", lang), "mm", f"× ${key[0]}_{{{key[2]}}}$  (÷ l [m])", f"= {term('reading_value', lang)}"]]

    def row(symbol: str, v, divide: float | None = None, sense: float | None = None, between: str = "") -> list[str]:
        length = v.value / k if v is not None else 0.0
        measured = segment(plan, v, letters) if v is not None else "—"
        value = (v.value if v is not None else 0.0) / (divide or 1.0)
        if v is not None and v.label in given:  # a given vector (the driver's point): its given value, not its drawn length read
            value = v.length * k
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
            # no-break spaces: the cell never wraps inside it (the sheet gives the readings tables the width they need)
            factor += f"\u00a0÷\u00a0{table_number(divide)}\u00a0(${link_length(graphical, between)}$)"
        return [symbol, measured, printed_length(length, precision), factor, text]

    from ._canvas import fmt_number as fmt

    symbol = "v" if kind == "velocity" else "a"
    driver = graphical.scene.driver.link
    given = {f"{symbol}_{name}" for name in graphical.scene.bodies[driver].points} if driver in graphical.scene.bodies else set()
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


# --- images placed by similarity ----------------------------------------------------------------------------------


def similar_images(plan) -> list[tuple[str, str, str]]:
    """The images of *plan* placed by the similarity theorem: ``(y, z, x)`` image labels, *x* placed from the known
    images *y*, *z* of the same link (the figure yzx similar to the link's YZX, lettered in the same sense).

    Read from the plan's construction: the images at rest (the pole) and each step's image are constructed; a link
    with two images known has the rest of its images by similarity (*y* the one at the pole when there is one); a
    link that translates has every image at one place (no proportion).  In the order they are placed.
    """
    known = {label for label, z in plan.images.items() if z == 0}
    out = []

    def spread() -> None:
        changed = True
        while changed:
            changed = False
            for labels in plan.links.values():
                have = [label for label in labels if label in known]
                rest = [label for label in labels if label not in known and label in plan.images]
                if not have or not rest:
                    continue
                zs = [plan.images[label] for label in labels if label in plan.images]
                if max(abs(z - zs[0]) for z in zs) <= 1e-9 * max(1.0, max(abs(z) for z in zs)):
                    known.update(rest)  # a link that translates: its images at one place
                    changed = True
                elif len(have) >= 2:
                    y, z = sorted(have[:2], key=lambda label: plan.images[label] != 0)
                    for x in rest:
                        out.append((y, z, x))
                        known.add(x)
                    changed = True

    for step in plan.steps:
        known.add(step.image)
        spread()
    return out


def similarity_lines(graphical, kind: str) -> list[str]:
    """The proportions by which the images of the plan of *kind* (``"velocity"``, ``"acceleration"``) were placed
    by similarity (:func:`similar_images`), with their numbers: the plan's segments [mm on the plan] in proportion
    to the link's lengths [mm]:

    - three points on a line: ``pd / pa₄ = CD / CA:  pd = 45.0 · 550.0 / 327.0 = 75.7 mm``;
    - a triangle (yzx similar to YZX): its two sides, ``am / ab = AM / AB:  am = …;  bm / ba = BM / BA:  bm = …``.
    """
    plan = graphical.velocity_plan if kind == "velocity" else graphical.acceleration_plan
    if plan is None:
        return []
    points = getattr(plan, "points", None) or {}

    def letter(label: str) -> str:
        return pole_text(plan) if plan.images[label] == 0 and label not in {s.image for s in plan.steps} else image_text(label, points)

    def seg(a: str, b: str) -> str:
        first, second = letter(a), letter(b)
        return first + second if (first + second).isascii() and len(first) == len(second) == 1 else f"{first} {second}"

    def name(label: str) -> str:
        return points[label][0] if label in points else label.rstrip("′").upper()

    def on_plan(a: str, b: str) -> float:
        return abs(plan.images[a] - plan.images[b])

    def real(a: str, b: str) -> float:  # [mm]
        return abs(graphical.positions[name(a)] - graphical.positions[name(b)]) * 1e3

    lines = []
    for y, z, x in similar_images(plan):
        Y, Z, X = name(y), name(z), name(x)
        if any(n not in graphical.positions for n in (Y, Z, X)) or real(y, z) == 0:
            continue
        zy, zx = graphical.positions[Y] - graphical.positions[Z], graphical.positions[X] - graphical.positions[Z]
        line_up = abs((zy.conjugate() * zx).imag) <= 1e-9 * max(abs(zy) * abs(zx), 1e-30)
        if line_up:  # yx / yz = YX / YZ
            lines.append(f"{seg(y, x)} / {seg(y, z)} = {Y}{X} / {Y}{Z}:  {seg(y, x)} = {on_plan(y, z):.1f} · {real(y, x):.1f} / "
                         f"{real(y, z):.1f} = {on_plan(y, z) * real(y, x) / real(y, z):.1f} mm")
        else:  # the triangle yzx similar to YZX: its two other sides from yz, each in the same proportion
            lines.append(";  ".join(
                f"{seg(a, x)} / {seg(a, b)} = {A}{X} / {A}{B}:  {seg(a, x)} = {on_plan(a, b):.1f} · {real(a, x):.1f} / {real(a, b):.1f} = "
                f"{on_plan(a, b) * real(a, x) / real(a, b):.1f} mm" for a, b, A, B in ((y, z, Y, Z), (z, y, Z, Y))))
    return lines
