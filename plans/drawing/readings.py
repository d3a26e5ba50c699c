"""What a student measures on each plan and computes from it: segment, its length as printed, × the scale factor
(÷ a link's length) = the value (:func:`plan_readings`); the sheets and the handout set these tables (Typst,
:mod:`plans.pages`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..i18n import term
from ..scene import FRAME, Crank
from .._text import SUBSCRIPT, decimal_comma, math_name
from .plan_drawing import aliases, end_letters, image_text, pole_text, segment, vectors_drawn

__all__ = ["plan_readings", "link_length", "printed_length", "Placement", "image_placements", "at_rest", "label_point", "similarity_lines", "proportion_text"]


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


@dataclass(frozen=True)
class Placement:
    """How images of a plan are placed that no construction step places (a step places its own image).

    Attributes
    ----------
    how : str
        ``"rest"``: points of the frame, their images at the pole (v = 0, a = 0);
        ``"translates"``: the images of a link that does not turn (ω = 0, ε = 0) at one place with a known one;
        ``"similar"``: the figure of the link's images similar to the link (two of its images known);
        ``"turns"``: one image of the link known and the link turning with *partner* (a rod sliding in a sleeve,
        a block on its guide: ω and ε of *partner*), the next image from it (v_G = v_F + v_GF, v_GF = ω·FG).
    images : tuple[str, ...]
        The image labels it places.
    start : tuple[str, ...]
        The known image labels it starts from: ``()`` (rest), ``(y,)`` (translates), ``(y, z)`` (similar, *y* the
        image at the pole when there is one), ``(y, a, b)`` (turns: *y* the link's known image, *a*, *b* two known
        images of *partner*, whose figure gives ω and ε).
    link : str
        The link whose images they are (``""`` for rest).
    partner : str
        The link it turns with (``"turns"``), else ``""``.
    after : int
        The index of the plan's step after which it is drawn (-1: before the first).
    """

    how: str
    images: tuple[str, ...]
    start: tuple[str, ...] = ()
    link: str = ""
    partner: str = ""
    after: int = -1


def image_placements(graphical, kind: str) -> list[Placement]:
    """How each image of the plan of *kind* (``"velocity"``, ``"acceleration"``) is placed that no step of its
    construction places, in the order they are drawn (:class:`Placement`).

    Read from the construction: the images at rest (the frame's points, at the pole) and each step's image are
    constructed; then a link that translates (slides on the frame, or is a sliding driver) has every image at one
    place (no proportion); a link with two images known has the rest of its images by similarity; a link with one
    image known that the construction turned with another
    (:attr:`~plans.graphical.plan.GraphicalSolution.turns_with`: a rod in a sleeve, ω₃ = ω₄) has its next image from
    that one with the other's ω, ε, the rest then by similarity.  A step's image is its step's, in its turn.
    """
    plan = graphical.velocity_plan if kind == "velocity" else graphical.acceleration_plan
    if plan is None:
        return []
    points = getattr(plan, "points", None) or {}
    rest = at_rest(graphical, plan)
    out = [Placement("rest", rest)] if rest else []
    known = set(rest)
    made = {step.image for step in plan.steps}  # (each placed by its own step, in its turn)
    turns = getattr(graphical, "turns_with", None) or {}
    driver = graphical.scene.driver
    sliding_driver = None if isinstance(driver, Crank) else driver.link

    def translates(link: str) -> bool:
        """The link does not turn, by construction: it slides on the frame or is (turns with) a sliding driver
        (not a link whose ω is zero for the instant: its images are placed as any turning link's)."""
        seen = set()
        while link not in seen:
            if link == FRAME or link == sliding_driver:
                return True
            seen.add(link)
            link = turns.get(link, link)
        return False

    def real(label: str) -> complex:
        return graphical.positions[label_point(plan, label)[0]]

    def partner_pair(link: str):
        """(the link whose figure gives ω, ε of *link*, two of its known images), following a chain of links that
        turn together (a block on a rod in a sleeve) to one with two images known; None when not yet known."""
        seen = {link}
        other = turns.get(link)
        while other is not None and other not in seen:
            have = [label for label in plan.links.get(other, ()) if label in known]
            if len(have) >= 2:
                pairs = [(a, b) for i, a in enumerate(have) for b in have[i + 1:] if abs(real(a) - real(b)) > 0]
                if pairs:  # the image at the pole first, the two farthest apart on the link
                    a, b = max(pairs, key=lambda ab: (plan.images[ab[0]] == 0 or plan.images[ab[1]] == 0, abs(real(ab[0]) - real(ab[1]))))
                    return other, tuple(sorted((a, b), key=lambda label: plan.images[label] != 0))
            seen.add(other)
            other = turns.get(other)
        return None

    def spread(after: int) -> None:
        changed = True
        while changed:
            changed = False
            for link, labels in plan.links.items():
                have = [label for label in labels if label in known]
                todo = [label for label in labels if label not in known and label not in made and label in plan.images]
                if not have or not todo:
                    continue
                if translates(link):
                    out.append(Placement("translates", tuple(todo), (have[0],), link, after=after))
                    known.update(todo)
                elif len(have) >= 2:
                    y, z = sorted(have[:2], key=lambda label: plan.images[label] != 0)
                    for x in todo:
                        out.append(Placement("similar", (x,), (y, z), link, after=after))
                        known.add(x)
                else:
                    found = partner_pair(link)
                    if found is None:
                        continue
                    y = have[0]
                    # the next image: a point the link is named by (not a coincident point's), the farthest from y
                    x = max(todo, key=lambda label: (not (label in points and points[label][1]), abs(real(label) - real(y))))
                    out.append(Placement("turns", (x,), (y, *found[1]), link, found[0], after))
                    known.add(x)
                changed = True

    spread(-1)
    for index, step in enumerate(plan.steps):
        known.add(step.image)
        spread(index)
    return out


def at_rest(graphical, plan) -> tuple[str, ...]:
    """The images of *plan* at the pole because their points are the frame's (not a step's image, not a moving
    point at rest for the instant: linear-arm's f′ when a_A = 0)."""
    made = {step.image for step in plan.steps}
    frame = set(graphical.scene.frame.points)
    points = getattr(plan, "points", None) or {}
    return tuple(label for label, z in plan.images.items()
                 if z == 0 and label not in made and (label not in points or points[label][0] in frame))


def label_point(plan, label: str) -> tuple[str, str]:
    """(the mechanism point's name as the scene writes it, the number of the link it is a point of or ``""``) of an
    image *label* of *plan*: ``"h3′"`` -> ``("H", "3")``."""
    points = getattr(plan, "points", None) or {}
    if label in points:
        return points[label]
    base = label.rstrip("′")
    letters = base.rstrip("0123456789")
    return letters.upper(), base[len(letters):]


def similarity_lines(graphical, kind: str, lang: str = "en") -> list[str]:
    """The proportions by which the images of the plan of *kind* (``"velocity"``, ``"acceleration"``) were placed by
    similarity or with the ω, ε of the link they turn with (:func:`image_placements`), with their numbers: the plan's
    segments [mm on the plan] in proportion to the link's lengths [mm] (:func:`proportion_text`)."""
    out = []
    for placement in image_placements(graphical, kind):
        line = proportion_text(graphical, kind, placement, lang=lang)
        if line:
            out.append(line)
    return out


def proportion_text(graphical, kind: str, placement: Placement, numbers: bool = True, lang: str = "en") -> str:
    """The proportion that places the image of *placement* on the plan of *kind*, with its numbers (*numbers*: the
    plan's segments [mm on the plan] and the link's lengths [mm] from the mechanism), ``""`` for images at rest or
    of a link that translates (no proportion):

    - three points on a line: ``pd / pa₄ = CD / CA:  pd = 45.0 · 550.0 / 327.0 = 75.7 mm``;
    - a triangle (yzx similar to YZX): its two sides, ``am / ab = AM / AB:  am = …;  bm / ba = BM / BA:  bm = …``;
    - an image of a link that turns with another (yx from that link's ab, the figures similar):
      ``fg / p f₄ = FG / DF:  fg = 14.8 · 550.0 / 255.8 = 31.8 mm  (ω₃ = ω₄)``.

    Without *numbers* each proportion alone (``am / ab = AM / AB;  bm / ba = BM / BA``).  A result that the plan's
    segment, measured to 0.1 mm as the readings tables give it, does not repeat (its inputs rounded to 0.1 mm) says
    what the plan measures, in the words of *lang*: ``fg = 10.7 · 550.0 / 329.0 = 17.9 mm (on the plan 17.8 mm)``,
    the number the next proportion and the readings table use.
    """
    plan = graphical.velocity_plan if kind == "velocity" else graphical.acceleration_plan
    if plan is None or placement.how not in ("similar", "turns"):
        return ""
    points = getattr(plan, "points", None) or {}
    rest = at_rest(graphical, plan)

    def letter(label: str) -> str:  # (an image at the pole as its point is the frame's: the pole's letter)
        return pole_text(plan) if label in rest else image_text(label, points)

    def seg(a: str, b: str) -> str:
        first, second = letter(a), letter(b)
        return first + second if (first + second).isascii() and len(first) == len(second) == 1 else f"{first} {second}"

    def name(label: str) -> str:
        return label_point(plan, label)[0]

    def on_plan(a: str, b: str) -> float:
        return abs(plan.images[a] - plan.images[b])

    def real(a: str, b: str) -> float:  # [mm]
        return abs(graphical.positions[name(a)] - graphical.positions[name(b)]) * 1e3

    def proportion(a: str, x: str, b: str, c: str, base: str) -> str:
        """ax / bc = AX / BC, ax = bc · AX / BC; *base* the plan's segment bc's letters."""
        text = f"{seg(a, x)} / {base} = {name(a)}{name(x)} / {name(b)}{name(c)}"
        bc_real = round(real(b, c), 1)
        if numbers and bc_real:  # (the result from the numbers as printed: a student's arithmetic gives the same last digit)
            read, ax, bc = (round(v, 1) for v in (on_plan(b, c), real(a, x), bc_real))
            result, measured = f"{read * ax / bc:.1f}", f"{round(on_plan(a, x), 1):.1f}"
            text += f":  {seg(a, x)} = {read:.1f} · {ax:.1f} / {bc:.1f} = {result} mm"
            if result != measured:  # (rounded inputs: the plan, drawn exactly, measures the next number)
                text += f" ({term('on_the_plan', lang)} {measured} mm)"
        return text

    labels = (*placement.start, *placement.images)
    if any(name(label) not in graphical.positions for label in labels):
        return ""
    x = placement.images[0]
    if placement.how == "turns":
        y, a, b = placement.start
        if real(a, b) == 0:
            return ""
        link, partner = placement.link.translate(SUBSCRIPT), placement.partner.translate(SUBSCRIPT)
        same = f"ω{link} = ω{partner}" + (f", ε{link} = ε{partner}" if kind == "acceleration" else "")
        return proportion(y, x, a, b, seg(a, b)) + f"  ({same})"
    y, z = placement.start
    if real(y, z) == 0:
        return ""
    Y, Z, X = (graphical.positions[name(label)] for label in (y, z, x))
    zy, zx = Y - Z, X - Z
    if abs((zy.conjugate() * zx).imag) <= 1e-9 * max(abs(zy) * abs(zx), 1e-30):  # on a line: yx / yz = YX / YZ
        return proportion(y, x, y, z, seg(y, z))
    # the triangle yzx similar to YZX: its two other sides from yz, each in the same proportion
    return ";  ".join(proportion(a, x, a, b, seg(a, b)) for a, b in ((y, z), (z, y)))
