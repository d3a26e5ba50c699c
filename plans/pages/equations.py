"""The vector equations of the plans as a textbook writes them, known parts marked.

A construction step (:class:`plans.graphical.plan.Step`) holds its equations
as text (``"v_A4 = v_C + v_A4C  (v_A4C ⊥ CA)"``), the components it knew in
full before the intersection (``step.known``) and those it found there,
whose direction alone was known (``step.found``).  On the page every vector
carries an arrow and the known parts are underlined as the course marks
them: **twice** where magnitude and direction are known (every term on the
right that the step did not find: a known point's velocity, a normal or
Coriolis component), **once** where only the direction is (what the
intersection gives).  The sought vector on the left is not underlined.

Whether a term is the step's unknown is read from the equation itself, not
only from ``step.found`` (which leaves out a vector of zero length, at a
dead centre): a term whose direction alone the conditions give (``v_ED ⊥
DE``, ``a^r_EE0 ∥ ram``) is underlined once unless it is a normal or a
Coriolis component (``a^n``, ``a^k``: magnitude and direction known).  A
driver's equation (no vector on its right: ``v_A = ω2 × OA``, ``a_A = a``)
gives its right side in full: the right side is underlined twice, the
sought left side, as everywhere, not at all.  A modulus ``|ω2|`` is set as
Typst's ``abs(ω_2)`` (bars that fit the symbol, no space inside).

The second line of a double underline is a thin rule (:data:`DOUBLE_STROKE_PT`)
drawn :data:`DOUBLE_GAP_PT` below the bounds of the first (the math font's
own underline), so the two stay apart on a screen at 70 dpi and in print
(Typst's nested ``underline(underline(…))`` sets them about one rule apart:
one thick bar).

>>> print(equation_math("v_C = v_B + v_CB", found={"v_CB"}))
arrow(v)_(C) = #box(stroke: (bottom: 0.4pt), outset: (bottom: 1.8pt), {set text(bottom-edge: "bounds"); $underline(arrow(v)_(B))$}) + underline(arrow(v)_(C B))
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .typesetting import string

__all__ = ["equation_math", "condition_math", "step_lines", "PlacementRow", "placement_rows", "placement_math", "VECTOR", "once", "twice", "DOUBLE_GAP_PT", "DOUBLE_STROKE_PT"]

#: the stroke [pt] of a double underline's second rule (thin, as the math font's own rule, about 0.04 em)
DOUBLE_STROKE_PT = 0.4
#: how far [pt] the second rule's middle lies below the bounds of the first underline (its clear gap ≥ this − half the
#: stroke, 1.6 pt: two lines at 100 dpi, not one thick bar; at 1.1 pt round 18's reviewer read "v̲_GF" as underlined
#: once).  An outset takes no room: the rows stay where they are
DOUBLE_GAP_PT = 1.8


def once(body: str) -> str:
    """Typst math of *body* underlined once (direction known)."""
    return f"underline({body})"


def twice(body: str) -> str:
    """Typst math of *body* underlined twice (magnitude and direction known), the two rules clearly apart (see the module)."""
    return (f"#box(stroke: (bottom: {DOUBLE_STROKE_PT}pt), outset: (bottom: {DOUBLE_GAP_PT}pt), "
            f'{{set text(bottom-edge: "bounds"); ${once(body)}$}})')

#: a vector as the graphical method names it: ``v_B``, ``a^n_CB``, ``v_A4A3``
VECTOR = re.compile(r"(?<![\w^])([a-z])(?:\^([a-z]+))?_([A-Za-z0-9′]+)")
_RATE = re.compile(r"([α-ωΑ-Ω])(\d+²?|²)")
_ABS = re.compile(r"\|([^|]+)\|")
_WORD = re.compile(r"[^\W\d_]+[0-9]*")


def _letters(sub: str) -> str:
    """A subscript of point names, one token each for Typst: ``A4C`` → ``A 4 C``."""
    return " ".join(re.findall(r"[0-9]+|′|[^\W\d_]", sub))


def vector_math(symbol: str, sup: str | None, sub: str) -> str:
    """``a``, ``n``, ``CB`` → ``arrow(a)^n_(C B)``."""
    return f"arrow({symbol})" + (f"^{sup}" if sup else "") + f"_({_letters(sub)})"


def _greek(ch: str) -> str:
    from .typesetting import math

    return math(ch)


def _plain_math(part: str, name) -> str:
    """Text between vectors as Typst math: ω2 → ω₂, point pairs (``CA``) italic, other words as names in text."""
    out = []
    k = 0
    while k < len(part):
        m = _ABS.match(part, k)
        if m:  # a modulus |ω2| → abs(ω_2)
            out.append(f"abs({_plain_math(m.group(1), name)})")
            k = m.end()
            continue
        m = _RATE.match(part, k)
        if m:
            number, squared = m.group(2).rstrip("²"), m.group(2).endswith("²")
            out.append(m.group(1) + (f"_{number}" if number else "") + ("^2" if squared else ""))
            k = m.end()
            continue
        m = _WORD.match(part, k)
        if m:
            word = m.group(0)
            if re.fullmatch(r"(?:[A-Z][0-9]*′?)+", word) or len(word) == 1:
                out.append(_letters(word))
            else:
                out.append(string(name(word)))
            k = m.end()
            continue
        ch = part[k]
        if ch.isspace():
            out.append(" ")
        elif ch in ",;":  # between conditions: the mark, then a word's space (``∥ CA,  a^t_CA ⊥ AC``)
            out.append((ch if ch == "," else string(ch)) + " thick ")
        elif ch.isdigit() or ch in ".+-=()|×·∥⊥":
            out.append({"·": " dot.op ", "×": " times ", "∥": " parallel ", "⊥": " perp ", "|": " |"}.get(ch, ch))
        else:
            out.append(string(ch))
        k += 1
    return " ".join("".join(out).split())


def condition_math(text: str, name=lambda word: word) -> str:
    """The conditions of an equation (``v_A4C ⊥ CA, |ω2|·OA``) as Typst math; *name* gives a word in the reader's language."""
    out = []
    last = 0
    for m in VECTOR.finditer(text):
        out.append(_plain_math(text[last:m.start()], name))
        out.append(vector_math(*m.groups()))
        last = m.end()
    out.append(_plain_math(text[last:], name))
    return " ".join(piece for piece in out if piece)


def direction_only(condition: str) -> set[str]:
    """The vectors whose direction alone *condition* gives (``v_ED ⊥ DE`` → ``{"v_ED"}``); normal and Coriolis components excepted."""
    out = set()
    for m in VECTOR.finditer(condition):
        if m.group(2) in ("n", "k"):
            continue
        if re.match(r"\s*[⊥∥]", condition[m.end():]):
            out.add(m.group(0))
    return out


def term_math(piece: str, name=lambda word: word) -> str:
    """One term (a vector or a formula) as Typst math, not underlined."""
    m = VECTOR.fullmatch(piece.strip())
    return vector_math(*m.groups()) if m else condition_math(piece.strip(), name)


def equation_math(equation: str, known=(), found=(), name=lambda word: word, condition: str = "") -> str:
    """One vector equation ``lhs = t1 + t2 …`` as Typst math with the known parts underlined (see the module).

    *condition* is the text in brackets after the equation; a vector whose
    direction alone it gives is underlined once, as a vector in *found*.
    """
    lhs, eq, rhs = equation.partition(" = ")
    if not eq:
        return condition_math(equation, name)
    known = set(known)  # a vector the step knows in full stays twice, whatever direction its condition repeats
    found = set(found) | (direction_only(condition) - known)  # (the driver's a^t_AO ⊥ OA with ε₂ given: twice)
    if rhs.strip() == "0":  # a zero (a constant-speed driver's a_A = 0): nothing to underline
        return f"{term_math(lhs, name)} = 0"
    if not any(VECTOR.fullmatch(t.strip()) for t in rhs.split(" + ")):  # a driver's equation: the right side given in full
        return f"{term_math(lhs, name)} = {twice(condition_math(rhs.strip(), name))}"

    def term(piece: str) -> str:
        m = VECTOR.fullmatch(piece.strip())
        if not m:
            return condition_math(piece.strip(), name)
        body = vector_math(*m.groups())
        label = m.group(0)
        if label in found:
            return once(body)
        return twice(body)

    terms = [term(t) for t in rhs.split(" + ")]
    return f"{term_math(lhs, name)} = " + " + ".join(terms)  # the sought vector: never underlined


def step_lines(step, name=lambda word: word) -> list[tuple[str, str]]:
    """The equations of a construction step as ``(equation, conditions)`` pairs of Typst math.

    Conditions are what the text gives in brackets after the equation (the
    direction of each unknown, a zero); empty when there are none.
    """
    from ..drawing.sheet import guide_names

    known = {v.label for v in step.known}
    found = {v.label for v in step.found}
    out = []
    for text in step.equations:
        text = guide_names(text)
        main, _, rest = text.partition("  (")
        if not rest and text.endswith(")") and " (" in text:  # one space before the conditions (a linear driver's)
            cut = text.rfind(" (")
            main, rest = text[:cut], text[cut + 2:]
        condition = rest[:-1] if rest.endswith(")") else rest
        out.append((equation_math(main.strip(), known, found, name, condition), condition_math(condition, name) if condition else ""))
    return out


@dataclass(frozen=True)
class PlacementRow:
    """A row of the vector equations saying how images that no construction step places are placed
    (:func:`plans.drawing.readings.image_placements`).

    Attributes
    ----------
    who : str
        Its first column: ``"fixed_points"`` or ``"by_similarity"`` (words of :mod:`plans.i18n`), or a link's number
        (``"3"``: the row of link 3).
    kind : str
        ``"equation"``: a vector equation with its conditions, the known parts underlined as a step's
        (``v_G = v_F + v_GF``, ``v_GF ⊥ FG; ω3 = ω4``); ``"fact"``: an equality set as it is
        (``v_D = v_Q = 0``); ``"proportion"``: a proportion in words (``ab / ac = AB / AC``).
    text : str
        The equation, the fact or the proportion, in the plans' notation (:data:`VECTOR`).
    condition : str
        The conditions after an equation (``""``: none).
    known : tuple[str, ...]
        The vectors of an equation known in magnitude and direction (underlined twice).
    images : tuple[str, ...]
        The image labels the row places (``("g",)``).
    """

    who: str
    kind: str
    text: str
    condition: str = ""
    known: tuple[str, ...] = ()
    images: tuple[str, ...] = ()


def placement_rows(graphical, kind: str) -> dict[int, list[PlacementRow]]:
    """Step index -> the rows (:class:`PlacementRow`) placing the images of the plan of *kind* (``"velocity"``,
    ``"acceleration"``) that no step places, each once the images it starts from are drawn (-1: before the first
    step): the points at rest (at the pole), the images of a link that translates, by similarity, and those of a
    link that turns with another (ω₃ = ω₄)."""
    from ..drawing.plan_drawing import at_rest_texts
    from ..drawing.readings import image_placements, label_point, proportion_text

    plan = graphical.velocity_plan if kind == "velocity" else graphical.acceleration_plan
    if plan is None:
        return {}
    symbol = "v" if kind == "velocity" else "a"
    unprimed = str.maketrans({"′": None})
    written = {label: text.translate(unprimed) for label, text in at_rest_texts(plan).items()}

    def name(label: str) -> str:
        """The point's name in a vector's subscript (``F``, ``H3``; a point at rest as the plan letters it, ``E6``)."""
        if label in written:
            text = written[label]
            return text[0].upper() + text[1:].translate(_DIGITS)
        point, body = label_point(plan, label)
        return point + body

    out: dict[int, list[PlacementRow]] = {}
    for p in image_placements(graphical, kind):
        rows = out.setdefault(p.after, [])
        if p.how == "rest":
            rows.append(PlacementRow("fixed_points", "fact", " = ".join(f"{symbol}_{name(x)}" for x in p.images) + " = 0", images=p.images))
        elif p.how == "translates":
            y = name(p.start[0])
            still = f"ω{p.link} = 0" + (f", ε{p.link} = 0" if kind == "acceleration" else "")
            for k, x in enumerate(p.images):  # (why, on the first row)
                rows.append(PlacementRow(p.link, "equation", f"{symbol}_{name(x)} = {symbol}_{y}", "" if k else still, (f"{symbol}_{y}",), (x,)))
        elif p.how == "similar":
            rows.append(PlacementRow("by_similarity", "proportion", proportion_text(graphical, kind, p, numbers=False), images=p.images))
        else:  # turns: x from y with the ω, ε of the link it turns with
            x, y = name(p.images[0]), name(p.start[0])
            xy = f"{x}{y}"
            link, other = p.link, p.partner
            if kind == "velocity":
                terms, condition = [f"v_{y}", f"v_{xy}"], f"v_{xy} ⊥ {y}{x}; ω{link} = ω{other}"
            else:  # (the magnitudes ω²·FG, ε·FG known with ω, ε: underlined twice)
                terms = [f"a_{y}", f"a^n_{xy}", f"a^t_{xy}"]
                condition = f"a^n_{xy} ∥ {x}{y}, a^t_{xy} ⊥ {y}{x}; ω{link} = ω{other}, ε{link} = ε{other}"
            rows.append(PlacementRow(link, "equation", f"{symbol}_{x} = " + " + ".join(terms), condition, tuple(terms), p.images))
    return {index: rows for index, rows in out.items() if rows}


_DIGITS = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")


def placement_math(row: PlacementRow, name=lambda word: word) -> tuple[str, str]:
    """A row of :func:`placement_rows` (not a proportion) as (equation, conditions) Typst math, as :func:`step_lines`."""
    if row.kind == "fact":
        return condition_math(row.text, name), ""
    return (equation_math(row.text, row.known, (), name, row.condition),
            condition_math(row.condition, name) if row.condition else "")
