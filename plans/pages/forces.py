"""The kinetostatic pages of a position, set by Typst (``plans handout --forces``, ``plans forces -o``).

Matplotlib draws only the drawings (:mod:`plans.drawing.force_blocks`): the
free bodies of the groups and of the driver at the plate's k_l (in a row, rows
or columns, whichever fits; a coarser round k_l, stated in the title block,
only where none does), each force plan at the position's one μ_F, Joukowski's
lever at its velocity plan's k_v (or a coarser one of its own, stated).  They are placed at 100 %, so the scale
factors the pages state hold on paper.  Everything else is Typst's, in the
reader's language: the headings (a group named as the course names it, "group
3–4 (II₁)"), the input data of the force analysis (each link's m, centre of
mass S and J_S, g, the external loads and where they act, the offset e of an
offset slider-crank), the given loads (N, and mm at μ_F), what each plan's
construction reads off it (R = drawn mm × μ_F; a reaction carried to the next
plan as R_ji = −R_ij with the value found; the components Rᵗ found first;
vectors too short for an arrow), each plan's equations
(:mod:`plans.forces.plan_equations`: the vector equation with its known parts
underlined once or twice, the moment equations that give Rᵗ and M_b written
out with their measured arms), M_b with its sense, the legends' words, the
lever's moments about the pole and the table of the three methods (analytic to
4 significant figures, the graphical values to the digits their reading
justifies) with each method's difference from the analytic value.  The
balancing moment and force and the useful resistance carry the course's
subscripts on a Russian or Bulgarian page (M_ур, F_ур, F_пс:
:func:`plans.drawing.force_drawing.course_label`).

The sections of a position follow one another without a forced page break
after the first (a page with the free bodies starts the position): the free
bodies with the input data and the given loads; the force plans (μ_F stated in
the heading and in the title block of every page a plan lands on) each under
its equations, a plan with its equations never split (all on the plans' page
when keeping them there costs the plans at most :data:`EQUATION_COST` in μ_F);
Joukowski's lever with the table of the three methods.  A section's heading is
kept with what follows it; a title block states the free bodies' k_l on their
page and the plate's on the pages after it.  Where the plans leave the free
bodies' page less than half used, the bodies take their next (taller)
arrangement at the plate's k_l.  The lever, its moments about the pole with M_b
and the methods' table go where the plans end, as the laid-out document shows
(:func:`_lever_layout`): all under the plans, or the lever under them and its
legend and tables over the page, or all from a new page, whichever leaves no
page under half used; the lever at the plate's k_v or at a coarser round k_v
of its own (its largest vector at least 60 mm), said under its heading and in
its page's title block, its legend beside it where the page is wide enough.

μ_F is found from geometry: the plans are constructed once at their own round
scales, drawn once to learn what does not scale (labels, margins), and μ_F is
the smallest round value with which the largest plan fits its cell; they are
then constructed at that μ_F (by :func:`plans.forces.force_plans.construct_force_plans`,
here: drawing never constructs) and drawn, a round step coarser only while one
runs over its cell.
"""

from __future__ import annotations

import cmath
import math
import re
from dataclasses import dataclass, field

from ..graphical.scales import round_up
from ..i18n import term
from .document import GUTTER, SMALL_PT, TEXT_PT, Document
from .words import KINDS, group_words

__all__ = ["ForcePages", "force_pages", "force_scale", "force_document", "group_names", "drawn_group_names", "PLAN_ROOM", "FREE_BODIES_BOX"]

#: the height [mm] the force plans and the readings under them share down their page, by default (a page gives
#: its text height less its heading and legend, :func:`force_pages`)
PLAN_ROOM = 218.0
#: the box [mm] the free bodies are drawn in at most (the text width; the given loads and the legend under
#: them take what they need of the page's height first, :func:`force_pages`)
FREE_BODIES_BOX = (175.0, 170.0)

#: the tallest a plan's cell may be [mm] (two plans side by side need not fill the page)
PLAN_CELL_MAX = 120.0
#: the height of a line of readings under a plan [mm] (8 pt with its leading)
READING_LINE = 3.9
#: the height of a line of the plans' equations [mm] (8 pt math, room for a double underline)
EQUATION_LINE = 5.0
#: the equations share the plans' page when μ_F grows at most this much for them (60 → 100 N/mm: the plans three fifths as large)
EQUATION_COST = 1.7


@dataclass
class ForcePages:
    """What the pages of one position hold (for callers and tests).

    Attributes
    ----------
    mu_F : float
        The one force scale [N/mm] of every plan of the position.
    k_l : float
        The scale [m/mm] of the free bodies.
    plans : plans.forces.force_plans.ForcePlans
        The force plans constructed at ``mu_F`` (what the pages read).
    images : dict[str, str]
        What each drawing is: input key -> ``"free-bodies"``, ``"plan:<group>"``, ``"lever"``.
    comparisons : tuple
        :func:`plans.forces.compare.compare_forces` of the pages' plans and lever against the analytic values.
    lever : plans.forces.lever.JoukowskiLever or None
        The lever as drawn (at the plate's k_v or a coarser one of its own: its ``k_v``).
    """

    mu_F: float
    k_l: float
    plans: object
    images: dict[str, str] = field(default_factory=dict)
    comparisons: tuple = ()
    lever: object = None


# --- numbers as a page writes them -----------------------------------------------------------


def _number(value: float, digits: int = 4) -> str:
    """*value* to *digits* significant figures (a point; the page's words make it a comma where the language has one)."""
    if value == 0 or not math.isfinite(value):
        return "0" if value == 0 else "—"
    decimals = max(0, digits - 1 - math.floor(math.log10(abs(value))))
    return _minus(f"{value:.{decimals}f}")


#: significant figures of an inertia couple M_Φ = −J_S·ε on the pages: one more than a force's, so that the pair of
#: forces F = M_Φ/l the lever puts in its place is what the printed M_Φ gives (162.75 N·m / 0.3 m = 542.5 N, where
#: 162.8 would give 542.7): one number for M_Φ on every page (loads, moment equations, the lever)
COUPLE_DIGITS = 5


def _couple(value: float, label: str) -> str:
    """A couple [N·m] as every force page prints it: an inertia couple (``M_Φ…``) to :data:`COUPLE_DIGITS`
    significant figures, a given one to 4."""
    return _number(value, COUPLE_DIGITS if _inertia_couple(label) else 4)


def _inertia_couple(label: str) -> bool:
    """Whether *label* names an inertia couple (``"M_Φ3"``, :func:`plans.forces.loads.inertia_symbol`)."""
    return label.startswith("M_Φ")


def _reading(value: float, step: float | None) -> str:
    """A value read to *step* (as many decimals as the step has), or to 4 significant figures without one."""
    if not step:
        return _number(value)
    decimals = len(f"{step:.10f}".rstrip("0").partition(".")[2])
    return _minus(f"{round(value / step) * step:.{decimals}f}")


def _minus(text: str) -> str:
    return text.replace("-", "−")


def _scale(value: float) -> str:
    from ..drawing._canvas import fmt_number

    return fmt_number(value)


def _math(label: str, lang: str = "en") -> str:
    from ..drawing.force_drawing import force_math

    return force_math(label, lang)


def _lower(words: str) -> str:
    return words[:1].lower() + words[1:] if words[1:2].islower() or len(words) < 2 else words


def group_names(plans, lang: str) -> dict[str, str]:
    """Group -> its name in the course's words: ``"RRR(3,4)"`` -> ``"group 3–4 (II₁)"`` (``$…$`` math)."""
    out = {}
    for plan in plans:
        if plan.group == "driver":
            continue
        kind = plan.group.partition("(")[0]
        order = KINDS.get(kind)
        out[plan.group] = group_words(plan.group, lang) + (f" ($\\mathrm{{II}}_{{{order}}}$)" if order else "")
    return out


def drawn_group_names(plans, lang: str) -> dict[str, str]:
    """:func:`group_names` as a drawing writes them (plain text: ``"group 3–4 (II₁)"``, a Unicode subscript)."""
    return _drawn_names(group_names(plans, lang))


def _drawn_names(names: dict) -> dict[str, str]:

    from .._text import subscript

    return {k: re.sub(r"\$\\mathrm\{II\}_\{(\d)\}\$", lambda m: "II" + subscript(m.group(1)), v) for k, v in names.items()}


def _plan_title(plan, names: dict, lang: str) -> str:
    from ..drawing.force_drawing import driving_link_words

    if plan.group == "driver":
        crank = not any(v.label == "F_b" for v in plan.vectors)  # a linear driver's plan carries F_b; a crank's M_b is a couple
        return f"{term('force_plan', lang)}: {driving_link_words(plan.links[0], crank, lang)}"
    return f"{term('force_plan', lang)}: {names.get(plan.group, plan.group)}"


# --- μ_F from geometry ------------------------------------------------------------------------


def _extent(plan) -> tuple[float, float]:
    """The plan's polygon extent [N] (across, up): the drawn extent times its μ_F."""
    zs = [z for v in plan.vectors for z in (v.tail, v.tip)] + [0j]
    xs, ys = [z.real for z in zs], [z.imag for z in zs]
    return (max(xs) - min(xs)) * plan.scale, (max(ys) - min(ys)) * plan.scale


def _cells(plans, width: float, columns: int, equations: dict | None = None) -> tuple[int, float, list[float]]:
    """(columns, the cell's width [mm], the height of the words of each row [mm]: its equations above each plan,
    *equations*: group -> its lines, and the readings under it) of the force plans' page with *columns* plans across."""
    n = len(plans)
    columns = min(columns, n)
    cell = (width - (columns - 1) * GUTTER) / columns
    # a line of readings runs over into a second where it is longer than the cell is wide (8 pt: ~1.45 mm a character)
    per_line = max(20, int(cell / 1.45))
    across = columns > 1 and not _equations_fit(equations, cell)  # the equations then go across the page above the row
    texts = []
    for r in range(0, n, columns):
        row = plans[r:r + columns]
        readings = max(sum(-(-_visible(line) // per_line) for line in _plan_lines(p, {}, 1.0 if p.group == "driver" else None)) + 1 for p in row)
        written = [_equations_height((equations or {}).get(p.group, ())) for p in row]
        above = sum(h + READING_LINE for h in written if h) if across else max(written)
        texts.append(readings * READING_LINE + above + 4.0)
    return columns, cell, texts


def _equations_height(lines) -> float:
    """The height [mm] a plan's equations take above it (nothing without them)."""
    return EQUATION_LINE * len(lines) + 2.0 if lines else 0.0


def _equation_width(line: str) -> float:
    """About how wide [mm] a line of the plans' equations (Typst math markup) is set: 8 pt math, ~1.45 mm a
    character and ~1.2 mm more about each operator (its spaces)."""
    t = re.sub(r"#box\([^$]*\$underline\(", "", line).replace(")$})", "").replace("underline(", "")
    t = re.sub(r"\bquad\b", "  ", t)
    t = re.sub(r"\bdot\b", "·", t)
    t = re.sub(r"\babs\(", "|", t)
    t = re.sub(r'[$"(){}_^ ]', "", t)
    return 1.45 * len(t) + 1.2 * len(re.findall(r"[=+−·⇒:]", t))


def _equations_fit(equations: dict | None, cell: float) -> bool:
    """Whether every equation line fits a cell *cell* mm wide (a line of math is not broken)."""
    return all(_equation_width(line) <= cell for lines in (equations or {}).values() for line in lines)


def _visible(line: str) -> int:
    """How many characters a line of the program's text prints (its math markup left out)."""

    return len(re.sub(r"\\mathrm|[${}_^\\]", "", line))


def force_scale(graphical, lang: str = "en", width: float = FREE_BODIES_BOX[0], room: float = PLAN_ROOM, equations: dict | None = None,
                heights: bool = True):
    """(μ_F [N/mm], the plans constructed at it, their SVG blocks, columns): the smallest round μ_F with which every
    force plan fits its cell's width and the rows of plans with their readings (and *equations* above them: group ->
    its lines; two plans across only where every line of them fits a cell) fit *room* [mm] down the page (with
    *heights* false, a row of two plans or two rows of one with their words to a page: the plans then run over
    pages).

    Found from geometry: the plans are constructed once at their own scales and drawn once (what does not
    scale — labels, margins — is what a drawing takes beyond its polygon), the sizes at any μ_F follow; then
    constructed and drawn at the μ_F found, a round step coarser only while they run over.
    """
    from ..drawing.force_blocks import force_plan_svg
    from ..forces.force_plans import construct_force_plans

    first = construct_force_plans(graphical, mu_F=None)
    sizes = []  # (fixed width, fixed height [mm], extent across, up [N]) of each plan
    for plan in first.plans:
        block = force_plan_svg(plan, lang)
        ex, ey = _extent(plan)
        sizes.append((block.width - ex / plan.scale, block.height - ey / plan.scale, ex, ey))

    def fits(mu: float, drawn=None, columns: int = 2) -> bool:
        columns, cell, texts = _cells(first.plans, width, columns, equations)
        wide = [fw + ex / mu for fw, _, ex, _ in sizes] if drawn is None else [b.width for b in drawn]
        tall = [fh + ey / mu for _, fh, _, ey in sizes] if drawn is None else [b.height for b in drawn]
        rows = [max(tall[k:k + columns]) for k in range(0, len(tall), columns)]
        # with *heights*, all the rows with their words on one page; else a row of two plans to a page, or two rows
        # of one (a page not left half empty by a plan too tall to have the next under it)
        per_page = 1 if columns > 1 else 2
        pairs = [(rows[k:k + per_page], texts[k:k + per_page]) for k in range(0, len(rows), per_page)]
        down = sum(rows) + sum(texts) + 5.0 * (len(rows) - 1) if heights else max(sum(r) + sum(t) + 5.0 * (len(r) - 1) for r, t in pairs)
        return max(wide) <= cell + 0.5 and down <= room + 0.5 and max(tall) <= PLAN_CELL_MAX + 0.5

    best = None
    for columns in (1, 2):  # one plan under the other, or two across: whichever draws them larger
        cell = _cells(first.plans, width, columns)[1]
        mu = round_up(max(ex / max(cell - fw, 0.3 * cell) for fw, _, ex, _ in sizes) or max(p.scale for p in first.plans))
        for _ in range(60):  # the round values upwards (no drawing: the sizes above)
            if fits(mu, columns=columns):
                break
            mu = round_up(mu * 1.0001)
        if best is None or mu < best[0] * 0.999:
            best = (mu, columns)
    mu, columns = best
    for _ in range(8):
        plans = construct_force_plans(graphical, mu_F=mu)
        blocks = [force_plan_svg(plan, lang) for plan in plans.plans]
        if fits(mu, blocks, columns):
            break
        mu = round_up(mu * 1.0001)
    return mu, plans, blocks, min(columns, len(plans.plans))


def _free_bodies(plans, graphical, lang: str, names: dict, box=FREE_BODIES_BOX, k_plate: float | None = None, skip: int = 0, equations=None):
    """(k_l [m/mm], block): the free bodies in one row, two or a grid, at the plate's *k_plate* [m/mm] when they fit
    *box* at it in one of those arrangements (the plate's one k_l on every page), else at the round k_l that draws
    them largest within *box* (coarser than the plate's: the page states it); *skip*: how many of the arrangements that
    fit at the plate's k_l to pass over (a taller one, to fill a page the force plans do not follow onto); *equations*:
    the plans' equations, whose arms h_k are drawn on the bodies."""
    from functools import partial

    from ..drawing.force_blocks import free_bodies_svg

    free_bodies_svg = partial(free_bodies_svg, equations=equations)

    count = len(plans.plans)
    g = graphical
    spans = []
    for plan in plans.plans:
        zs = [g.positions[n] for body in plan.links for n in g.scene.bodies[body].points]
        zs += [f.at for body in plan.links for f in plans.on(body)[0]]
        spans.append((max(z.real for z in zs) - min(z.real for z in zs), max(z.imag for z in zs) - min(z.imag for z in zs)))
    drawn = _drawn_names(names)
    arrangements = list(dict.fromkeys([count, -(-count // 2), -(-count // 3), 1]))

    def fits(block) -> bool:
        return block.width <= box[0] + 0.5 and block.height <= box[1] + 0.5

    passing = skip > 0
    if k_plate:
        # the plate's k_l in the first arrangement it fits: rows of bodies, or columns side by side (a tall body
        # beside a column of small ones)
        tried = [(per_row, None) for per_row in arrangements]
        if 2 < count <= 6:
            tried[1:1] = [(None, split) for split in _splits(count) if 1 < len(split) < count]
        for per_row, columns in tried:
            block = free_bodies_svg(plans, k_plate, lang, per_row, drawn, columns)
            if fits(block):
                if skip <= 0:
                    return k_plate, block
                skip -= 1
        if passing:
            return None
    best = None
    for per_row in arrangements[:2]:
        rows = [spans[k:k + per_row] for k in range(0, count, per_row)]
        extent = (max(sum(w for w, _ in row) for row in rows), sum(max(h for _, h in row) for row in rows))
        k0 = k_plate or g.scales["k_l"]
        block = free_bodies_svg(plans, k0, lang, per_row, drawn)
        need = 0.0
        for size, size_drawn, room in zip(extent, (block.width, block.height), box):
            fixed = size_drawn - size / k0
            if size > 0:
                need = max(need, size / max(room - fixed, 0.3 * room))
        k = round_up(need) if need > 0 else k0
        for _ in range(6):
            block = free_bodies_svg(plans, k, lang, per_row, drawn)
            if fits(block):
                break
            k = round_up(k * 1.0001)
        if best is None or k < best[0]:
            best = (k, block)
    return best


def _splits(n: int) -> list[tuple[int, ...]]:
    """Every way of cutting *n* bodies, in their order, into consecutive runs (how many each run holds)."""
    if n == 0:
        return [()]
    return [(first,) + rest for first in range(1, n + 1) for rest in _splits(n - first)]


# --- what the pages say -----------------------------------------------------------------------


def _step(plan) -> float | None:
    return plan.precision * plan.scale if plan.precision else None


def _plan_lines(plan, given: dict, balancing_moment, lang: str = "en", equations=None) -> list[str]:
    """The lines under a force plan: reactions carried from a plan before, the components Rᵗ found first, the
    reactions read off it (drawn mm × μ_F), the vectors too short for an arrow, M_b on the driver's.

    An Rᵗ is written with the value its moment equation gives (*equations*: the plan's
    :class:`plans.forces.plan_equations.PlanEquations`, the value the page's equation states), to 4 significant
    figures, and its length at μ_F: one value, one rounding, on the plan's lines and in its equation."""
    from ..drawing.force_drawing import SHORT_MM, sense_arrow

    vectors = [v for v in plan.vectors if v.length > 1e-9]
    mu = _scale(plan.scale)
    lines = []
    for v in vectors:
        if v.kind == "reaction" and v.label not in plan.found:
            head, _, sub = v.label.partition("_")
            opposite = f" = −{_math(f'R_{sub[::-1]}', lang)}" if head == "R" and len(sub) == 2 else ""
            lines.append(f"{_math(v.label, lang)}{opposite} = {_reading(v.value, _step(plan))} N → {_reading(v.length, plan.precision)} mm "
                         f"({term('carried', lang)})")
    tangential = [v for v in vectors if v.kind == "tangential"]
    if tangential:
        stated = {m.label: m.value for m in equations.moments} if equations is not None else {}
        found = [(v, stated.get(v.label, v.value)) for v in tangential]
        lines.append(f"{term('found_first', lang)}: " + ";  ".join(
            f"{_math(v.label, lang)} = {_number(value)} N → {_reading(value / plan.scale, plan.precision)} mm" for v, value in found))
    for v in vectors:
        if v.label in plan.found:
            lines.append(f"{_math(v.label, lang)} = {_reading(v.length, plan.precision)} mm · {mu} N/mm = {_reading(v.value, _step(plan))} N")
    short = [v for v in vectors if v.length < SHORT_MM]
    if short:
        lines.append(";  ".join(f"|{_math(v.label, lang)}| = {v.length:.2f} mm ({_number(given[v.label]) if v.label in given else _reading(v.value, _step(plan))} N)"
                                for v in short))
    if balancing_moment is not None:
        lines.append(f"{_math('M_b', lang)} = {_number(abs(balancing_moment))} N·m{sense_arrow(balancing_moment)} ({_lower(term('balancing_moment', lang))}, {term('from_force_plans', lang)})")
    return lines


# --- the equations each plan is drawn from ------------------------------------------------------


def _typst_symbol(label: str, lang: str) -> str:
    """A force's label as Typst math (its course subscript in *lang*)."""
    from .typesetting import math as typst_math

    return typst_math(_math(label, lang)[1:-1])


def _marked(label: str, known: str, lang: str) -> str:
    """A vector of an equation underlined as the course marks it: twice (magnitude and direction known), once
    (direction), not at all (sought)."""
    from .equations import once, twice

    body = _typst_symbol(label, lang)
    return twice(body) if known == "full" else once(body) if known == "direction" else body


def _quoted(value: float, lang: str, digits: int = 4) -> str:
    """A number as a Typst math string, to *digits* significant figures, with the language's decimal sign."""
    from .._text import decimal_comma

    return '"' + decimal_comma(_number(value, digits), lang) + '"'


def _signed(terms) -> str:
    """Terms (sign, math) joined as an equation's side: ``a + b − c`` (a leading minus kept)."""
    out = ""
    for k, (sign, body) in enumerate(terms):
        out += (("−" if sign < 0 else "") if k == 0 else (" − " if sign < 0 else " + ")) + body
    return out



def _moment_terms(letters: list, numbers: list, terms, lang: str) -> tuple[list, list]:
    """A moment equation's terms after its first ones, in letters (``F dot h_1``) and in numbers (``1500 dot 0,042``):
    a couple by its magnitude (``|M_Φ3|``: the pages' tables list it signed), a force with its arm h_k (numbered in
    order over the plan's equations, as the free bodies name the arms drawn); each term's sign is its sense,
    counter-clockwise positive."""
    for t in terms:
        symbol = _typst_symbol(t.label, lang)
        if t.arm is None:  # a couple by its magnitude, its sense in the term's sign (the table lists it signed)
            letters.append((t.moment, f"abs({symbol})"))
            numbers.append((t.moment, _quoted(t.size, lang, COUPLE_DIGITS if _inertia_couple(t.label) else 4)))
        else:
            letters.append((t.moment, f"{symbol} dot h_{t.number}"))
            numbers.append((t.moment, f"{_quoted(t.size, lang)} dot {_quoted(t.arm, lang)}"))
    return letters, numbers

def _equation_lines(eq, lang: str) -> list[str]:
    """A plan's equations as Typst markup lines: the polygon's vector equation (known parts underlined); each
    moment equation that gives an Rᵗ first, in letters and in numbers (arms measured on the drawing, m) with the
    Rᵗ it gives; the inner reaction's equation over one link; the driver's moment equation that gives M_b."""
    newton = _NEWTON.get(lang, "N")
    metre = "м" if lang in ("ru", "bg") else "m"
    lines = []
    if eq.polygon:
        lines.append("$" + " + ".join(_marked(label, known, lang) for label, known in eq.polygon) + " = 0$")
    for m in eq.moments:
        r = _typst_symbol(m.label, lang)
        letters, numbers = _moment_terms([(m.sign, f'{r} dot l_("{m.joint}{m.about}")')], [(m.sign, f"{r} dot {_quoted(m.length, lang)}")], m.terms, lang)
        lines.append(f'$Σ M_("{m.about}") ("{m.link}") = 0: quad {_signed(letters)} = 0$')
        lines.append(f'${_signed(numbers)} = 0 quad ⇒ quad {r} = {_quoted(m.value, lang)} "{newton}"$')
    if eq.inner:
        lines.append("$" + " + ".join(_marked(label, known, lang) for label, known in eq.inner) + " = 0$")
    if eq.balancing:
        b = _typst_symbol("M_b", lang)
        letters, numbers = _moment_terms([(1, b)], [(1, b)], eq.balancing, lang)
        value = -sum(t.moment for t in eq.balancing)
        lines.append(f'$Σ M_("{eq.pivot}") ("{eq.crank}") = 0: quad {_signed(letters)} = 0$')
        lines.append(f'${_signed(numbers)} = 0 quad ⇒ quad {b} = {_quoted(value, lang)} "{newton}·{metre}"$')
    return lines


_LOAD_KIND = {"weight": "weight", "inertia": "inertia_force", "external": "external_force"}


def _loads_table(plans, lang: str) -> list[list[str]]:
    """The given loads: symbol, link, kind, value (N or N·m), drawn length [mm] at μ_F on the plan that carries it."""
    drawn = {}
    for plan in plans.plans:
        for v in plan.vectors:
            if v.kind in _LOAD_KIND:
                drawn.setdefault(v.label, (v.length, plan.precision))
    # a resistance named as the course names it (the useful resistance), not as "a force"
    resisting = {load.name for load in plans.graphical.scene.loads if load.kind == "resistance"}
    rows = [["", term("link", lang), term("kind", lang), "N, N·m", "mm ($μ_F$)"]]
    for f in plans.loads:
        length = drawn.get(f.label)
        kind = "useful_resistance" if f.kind == "external" and f.label in resisting else _LOAD_KIND.get(f.kind, "external_force")
        rows.append([_math(f.label, lang), f.body, term(kind, lang), f"{_number(abs(f.force))} N",
                     _reading(*length) if length else "—"])
    for c in plans.couples:
        if c.kind == "balancing" or c.moment == 0:
            continue
        rows.append([_math(c.label, lang), c.body, term("inertia_couple" if c.kind == "inertia" else "couple", lang), f"{_couple(c.moment, c.label)} N·m", "—"])
    return rows


def _mm(value: float) -> str:
    """A length [m] in mm as the data give it (to 0.1 mm, no trailing zeros)."""
    return _minus(f"{value * 1000:.1f}".rstrip("0").rstrip("."))


def _given(value: float) -> str:
    """A datum as given (up to 6 significant figures, no trailing zeros: 2 kg is "2", 0.004 kg·m² "0.004")."""
    return _minus(f"{value:.6g}") if "e" not in f"{value:.6g}" else _number(value)


def _centre_words(scene, mass, lang: str) -> str:
    """Where the centre of mass S of a body lies, as a course's data state it: at a joint (``S₄ ≡ B``), or its distance
    from the body's first point along the line to the next (``l_OS₂ = 40 mm``), with the angle from that line when
    off it."""
    from ..forces.notation import centre_text

    body = scene.bodies[mass.body]
    s = centre_text(scene, mass.body)
    if mass.point is not None and len(scene.bodies_with(mass.point)) > 1:  # at a joint (a block's pin)
        return f"{s} ≡ {mass.point}"
    at = {n: z for n, z in body.points.items() if n != mass.point}
    same = next((n for n, z in at.items() if abs(z - mass.centre) <= 1e-9), None)
    if same is not None:
        return f"{s} ≡ {same}"
    if not at:
        return s
    names = list(at)
    first = names[0]
    origin = at[first]
    distance = abs(mass.centre - origin)
    words = f"$l_{{\\mathrm{{{first}{s}}}}}$ = {_mm(distance)} mm"
    second = next((n for n in names[1:] if abs(at[n] - origin) > 1e-12), None)
    if second is not None:
        turn = math.degrees(cmath.phase((mass.centre - origin) / (at[second] - origin)))
        if abs(turn) > 0.05:  # off the line first–second: the angle from it, counter-clockwise
            words += f", ∠({first}{second}, {first}{s}) = {_minus(f'{turn:.1f}')}°"
    return words


def _offset(scene) -> float | None:
    """The offset e [m] of a slider-crank's guide from the crank's pivot (None: not an offset slider-crank)."""
    from ..scene import Crank

    frame = next(iter(scene.bodies))
    moving = [b for b in scene.bodies if b != frame]
    if not isinstance(scene.driver, Crank) or len(scene.prismatics) != 1 or len(moving) != 3:
        return None
    p = scene.prismatics[0]
    if p.guide != frame:
        return None
    line = scene.line(f"{p.guide}.{p.guide_line}")
    pivot = scene.bodies[frame].points[scene.driver.pivot]
    e = abs(((pivot - line.origin) * cmath.exp(-1j * line.angle)).imag)
    return e if e > 1e-9 else None


def _data_rows(scene, lang: str, loads=()) -> tuple[str, list[list[str]], list[str]]:
    """The input data of the force analysis: (heading with the offset e of an offset slider-crank, the table of the
    links' masses — link, m [kg], centre of mass S, J_S [kg·m²] — and the lines of gravity and the external loads:
    each its magnitude, point and link, and its direction: a resistance against a point's velocity with the angle
    that gives at the position, from *loads*, the plans' applied forces)."""
    kg = "kg"
    heading = term("force_data", lang)
    e = _offset(scene)
    if e is not None:
        heading += f";  {term('offset_e', lang)}\u00a0e = {_mm(e)} mm"  # the word and its value on one line
    rows = [[term("link", lang), f"$m$ [{kg}]", term("mass_centre", lang), f"$J_{{S}}$ [{kg}·m²]"]]
    for name, mass in scene.masses.items():
        rows.append([name, _given(mass.mass), _centre_words(scene, mass, lang), _given(mass.inertia)])
    lines = []
    if scene.gravity is not None and scene.gravity.g:
        g = scene.gravity
        way = term("downwards", lang) if abs(g.angle + math.pi / 2) < 1e-9 else f"∠ {_minus(f'{math.degrees(g.angle) % 360:.1f}')}°"
        lines.append(f"{term('gravity_g', lang)}: g = {_given(g.g)} m/s², {way}")
    for load in scene.loads:
        name = _math(load.name, lang)
        where = load.point if load.point is not None else f"({_mm(load.at.real)}; {_mm(load.at.imag)}) mm"
        if load.kind == "moment":
            lines.append(f"{name} = {_number(load.moment)} N·m{' ↺' if load.moment > 0 else ' ↻'}, {term('on_link', lang).format(link=load.body)}")
            continue
        at = term("load_at", lang).format(point=where, link=load.body)
        if load.kind == "resistance":
            line = f"{term('useful_resistance', lang)} {name} = {_number(load.magnitude)} N, {at}, {term('against_velocity', lang).format(point=where)}"
            acting = next((f for f in loads if f.label == load.name and abs(f.force) > 0), None)
            if acting is not None:
                line += f" (∠ {math.degrees(math.atan2(acting.force.imag, acting.force.real)) % 360:.1f}°)"
        else:
            f = complex(load.force)
            line = f"{name} = {_number(abs(f))} N ∠ {math.degrees(math.atan2(f.imag, f.real)) % 360:.1f}°, {at}"
        if load.working is not None:
            line += f" ({term('working_only', lang)})"
        lines.append(line)
    return heading, rows, lines


def _methods_table(comparisons, analytic, lang: str, plans=None, lever=None) -> list[list[str]]:
    """The three methods side by side: M_b (or F_b) by analytic, force plans and the lever; each reaction by
    analytic and force plans; each method's difference from the analytic value [%].

    As every comparison table prints (:func:`plans.report.row_texts`): the graphical values to the digits their
    readings justify (:func:`_method_steps`; a row of two methods to the coarser of the two), the analytic value
    to the same decimals, and δ the difference of the printed numbers, |g − a| / |a| (of the vectors for a
    reaction), so that a reader recomputes it from the row.  Without drafting precision: 4 significant figures."""
    from ..forces.report import method_name

    rows = [[term("quantity", lang), method_name("analytic", lang), method_name("force_plans", lang), "δ [%]", method_name("lever", lang), "δ [%]"]]
    by = {(c.quantity, c.method): c for c in comparisons}
    symbol = "M_b" if analytic.balancing_kind == "moment" else "F_b"
    unit = "N·m" if symbol == "M_b" else "N"
    exact = float(analytic.balancing[0])
    steps = _method_steps(plans, lever, symbol)
    present = [m for m in ("force_plans", "lever") if by.get((symbol, m)) is not None]
    decimals = [_decimals(steps[m]) for m in present if steps[m]]
    places = min(decimals) if decimals and len(decimals) == len(present) else None
    a_text = _fixed(exact, places)
    row = [f"{_math(symbol, lang)} [{unit}]", a_text]
    for method in ("force_plans", "lever"):
        c = by.get((symbol, method))
        if c is None:
            row += ["—", "—"]
            continue
        g_text = _fixed(c.value.real, places)
        row += [g_text, _printed_percent(_plain(g_text), _plain(a_text))]
    rows.append(row)
    places = _decimals(steps["reaction"]) if steps["reaction"] else None
    for label, reaction in analytic.reactions.items():
        force = complex(reaction.force[0])
        c = by.get((label, "force_plans"))
        cell = _polar(force, places)
        if c is None:
            rows.append([f"{_math(label, lang)} [N]", cell, "—", "—", "", ""])
            continue
        g_cell = _polar(complex(c.value), places)
        rows.append([f"{_math(label, lang)} [N]", cell, g_cell, _printed_percent(_plain(g_cell), _plain(cell)), "", ""])
    return rows


def _decimals(step: float) -> int:
    """The decimals a reading of resolution *step* justifies (as :func:`plans.report.reading_number`)."""
    return max(0, -math.floor(math.log10(step)))


def _fixed(value: float, places: int | None) -> str:
    """*value* to *places* decimals (trailing zeros kept), or to 4 significant figures when None."""
    if places is None or value == 0:
        return _number(value)
    return _minus(f"{value:.{places}f}")


def _plain(cell: str) -> complex:
    """A printed cell back to its number: ``9640 ∠ 199.9°`` → the vector, ``−619`` → −619."""
    if "∠" in cell:
        magnitude, angle = cell.split("∠")
        return float(magnitude.replace("−", "-")) * cmath.exp(1j * math.radians(float(angle.strip().rstrip("°").replace("−", "-"))))
    return complex(float(cell.replace("−", "-")))


def _printed_percent(g: complex, a: complex) -> str:
    """δ [%] of the two printed values, |g − a| / |a|; "—" for an analytic 0."""
    return _percent(abs(g - a) / abs(a)) if a != 0 else "—"


def _method_steps(plans, lever, symbol: str) -> dict[str, float | None]:
    """The resolution of each graphical value of the three methods' table: a reaction read off a plan, one drafting
    step (its precision [mm]) × μ_F [N]; M_b by the force plans, that step × the longest arm on the crank [N·m]
    (F_b of a linear driver: the step itself); M_b by the lever, |M_b| × the step ÷ the balancing force's arm h_b
    [mm] (F_b likewise).  None where readings are exact (no precision)."""
    steps: dict[str, float | None] = {"force_plans": None, "lever": None, "reaction": None}
    if plans is not None:
        driver = next((p for p in plans.plans if p.group == "driver"), None)
        precision = next((p.precision for p in plans.plans if p.precision), None)
        if precision and driver is not None:
            steps["reaction"] = precision * driver.scale
            if symbol == "M_b":
                g = plans.graphical
                link = g.scene.driver.link
                pivot = g.positions[g.scene.driver.pivot]
                steps["force_plans"] = steps["reaction"] * max(abs(g.positions[n] - pivot) for n in g.scene.bodies[link].points)
            else:
                steps["force_plans"] = steps["reaction"]
    if lever is not None and plans is not None and steps["reaction"] is not None:
        arm = abs(lever.balancing_force.arm)
        precision = steps["reaction"] / next(p.scale for p in plans.plans if p.group == "driver")
        if arm > 0:
            steps["lever"] = abs(lever.balancing) * precision / arm
    return steps


def _polar(z: complex, places: int | None = None) -> str:
    """|z| ∠ its angle: |z| to *places* decimals (4 significant figures when None); 0…360° to 0.1°."""
    if abs(z) == 0:
        return "0"
    return f"{_fixed(abs(z), places)} ∠ {math.degrees(math.atan2(z.imag, z.real)) % 360.0:.1f}°"


def _percent(rel: float) -> str:
    return f"{100 * rel:.2f}".replace("-", "−")


# --- the pages --------------------------------------------------------------------------------


def _table(doc: Document, rows, aligns: str, heading: str | None = None) -> str:
    """A table across the text width (the first row its header), as Typst markup."""
    ncol = len(rows[0])
    body = []
    for i, row in enumerate(rows):
        weight = "bold" if i == 0 else "regular"
        body.append(", ".join(f"text(weight: \"{weight}\")[{_words(doc, str(c))}]" for c in list(row) + [""] * (ncol - len(row))))
    title = f"#text(weight: \"bold\", size: {SMALL_PT + 0.5}pt)[{_words(doc, heading)}] \\\n" if heading else ""
    return (f"#block(breakable: false)[{title}#text(size: {SMALL_PT}pt)[#table(columns: {ncol}, stroke: none, inset: (x: 1.4mm, y: 0.9mm), align: {aligns}, "
            f"table.hline(stroke: 0.7pt), " + ", table.hline(stroke: 0.4pt), ".join([body[0], ", ".join(body[1:])]) + ", table.hline(stroke: 0.7pt))]]\n")


def _legend(doc: Document, key: str, kinds, lang: str, column: bool = False) -> str:
    """The legend: each kind's sample (drawn) and its words (set), two columns of rows (*column*: one, to stand
    beside a drawing)."""
    from ..drawing.force_blocks import force_key_svg
    from ..drawing.force_drawing import FORCE_LEGEND

    cells = []
    for kind in kinds:
        words = term("construction_line", lang) if kind == "construction" else term("lever_arm_rule", lang) if kind == "arm" else _lower(term(FORCE_LEGEND[kind], lang))
        cells.append(f"[#{doc.add_image(f'{key}-key-{kind}', force_key_svg(kind))}], [#text(size: {SMALL_PT}pt)[{_words(doc, words)}]]")
    columns = 4 if len(kinds) > 2 and not column else 2
    sizes = ", ".join(["auto", "1fr"] * (columns // 2))
    return f"#grid(columns: ({sizes}), column-gutter: 2mm, row-gutter: 1.6mm, align: left + horizon, {', '.join(cells)})\n"


#: the newton, as the course in a language writes it (the other units: :func:`plans.pages.words.units`)
_NEWTON = {"ru": "Н", "bg": "Н"}


def _newtons(line: str, lang: str) -> str:
    """*line* with the units N and kg (outside its ``$…$`` math) as the course in *lang* writes them."""
    if lang not in _NEWTON:
        return line
    pieces = re.split(r"(?<!\\)(\$[^$]*\$)", line)
    return "".join(p if p.startswith("$") else re.sub(r"(?<![\w\\{])N(?=[·/ \])\];,]|$)", _NEWTON[lang], p).replace("kg·m²", "кг·м²").replace("kg", "кг")
                   for p in pieces)


def _words(doc: Document, line: str) -> str:
    """A line of the page's text as markup in its language (:meth:`Document.words`), N as the course writes it."""
    return doc.words(_newtons(line, doc.lang))


def _scale_note(doc: Document, words: str) -> None:
    """The page's own scale for the title block (as :meth:`plans.pages.document.Document.full_page` leaves it)."""
    doc.body.append(f"#metadata([{_words(doc, words)}]) <plans-page-scale>\n")


def force_pages(doc: Document, graphical, *, lever=None, analytic=None, where: str | None = None, key: str = "forces") -> ForcePages:
    """Set the kinetostatic pages of one position into *doc*: the free bodies and the given loads; the force plans at
    one μ_F with their readings; Joukowski's lever (when given) and the three methods side by side (with *analytic*,
    :class:`plans.forces.analytic.AnalyticForces` of the position).

    *where*: the position in words (a line under each heading); *key*: the prefix of the drawings' input keys.
    """
    from ..drawing.force_blocks import lever_svg
    from ..drawing.force_drawing import given_loads, legend_kinds
    from ..forces.compare import compare_forces
    from ..forces.plan_equations import plan_equations

    lang = doc.lang
    # each plan's equations above it (the order a student works in), all on the plans' page when that costs the
    # plans at most EQUATION_COST in μ_F; else the plans keep the scale they fit a page at alone, and each plan with
    # its equations goes on as a whole (over the page where the rest of it does not hold it)
    from ..forces.force_plans import construct_force_plans

    room = doc.page.text_height - 33.0
    equation_lines = {e.group: _equation_lines(e, lang) for e in plan_equations(construct_force_plans(graphical, mu_F=None))}
    alone = force_scale(graphical, lang, doc.page.text_width, room, equation_lines, heights=False)
    together = force_scale(graphical, lang, doc.page.text_width, room, equation_lines)
    mu, plans, blocks, columns = together if together[0] <= EQUATION_COST * alone[0] else alone
    names = group_names(plans.plans, lang)
    loads = _loads_table(plans, lang)
    data_heading, data, data_lines = _data_rows(graphical.scene, lang, plans.loads)
    # what the free bodies' page sets beside them: heading (and the position), k_l, legend, the input data and the
    # loads' table side by side
    tables = max(4.2 * len(loads) + 6.0, 4.2 * len(data) + 6.0 + 4.6 * len(data_lines))
    text = 16.0 + (5.0 if where else 0.0) + 5.0 + 4.6 * -(-len(_body_kinds(plans)) // 2) + 8.0 + tables + 6.0
    box = (doc.page.text_width, min(FREE_BODIES_BOX[1], doc.page.text_height - text))
    plate_kl = doc.plate.get("k_l")
    arms = plan_equations(plans)  # the equations the pages write: the bodies draw the arms h_k they use
    k_l, free = _free_bodies(plans, graphical, lang, names, box, plate_kl, equations=arms)
    pages = ForcePages(mu, k_l, plans)
    mu_words = f"$μ_{{F}}$ = {_scale(mu)} N/mm"
    head = term("kinetostatics", lang)

    def heading(what: str, new_page: bool = True, under=()) -> None:
        """A section's heading, the position under it and the lines *under* that ((words, size) each): on a page of its
        own, or (*new_page* false) where the section before ends, kept with what follows (never left at a page's foot)."""
        lines = ([(where, TEXT_PT)] if where else []) + list(under)
        if new_page:
            doc.heading(_newtons(f"{head} — {what}", lang), level=2, new_page=True)
            for line, size in lines:
                doc.line(_newtons(line, lang), size=size)
            return
        doc.body.append(f"#v(4mm)\n#block(sticky: true, breakable: false)[#heading(level: 2)[{doc.words(_newtons(f'{head} — {what}', lang))}]\n"
                        + "".join(doc.line_markup(_newtons(line, lang), size) + "\n" for line, size in lines) + "]\n")

    # 1. the free bodies, the given loads and the legend
    heading(_lower(term("free_bodies", lang)))
    kl_at = len(doc.body)
    if plate_kl is not None:
        doc.body.append(f"#plate-kl.update([{doc.scale_words('k_l', k_l)}])")  # the title block states the free bodies' k_l
    _scale_note(doc, mu_words)
    bodies_at = len(doc.body)
    doc.figure(f"{key}-free-bodies", free)
    doc.body.append(f"#metadata(none) <{key}-free-bodies>\n")
    pages.images[f"{key}-free-bodies"] = "free-bodies"
    coarser = ""
    if plate_kl is not None and abs(k_l - plate_kl) > 1e-12 * plate_kl:  # none of the arrangements fits at the plate's k_l
        coarser = ";  " + term("free_bodies_coarser", lang).format(scale=f"$k_{{l}}$ = {_scale(plate_kl)} m/mm")
    caption_at = len(doc.body)
    doc.line(_newtons(f"$k_{{l}}$ = {_scale(k_l)} m/mm;  {term('not_to_scale', lang)}{coarser}", lang), size=SMALL_PT)
    doc.body.append(_legend(doc, f"{key}-bodies-legend", _body_kinds(plans), lang))
    given_data = _table(doc, data, "(left, right, left, right)", data_heading)
    given_loads_table = _table(doc, loads, "(left, left, left, right, right)", f"{term('loads', lang)}: {mu_words}")
    # the two tables side by side, then g and the external loads across the page (a long line would narrow them)
    doc.body.append(f"#grid(columns: (auto, auto), column-gutter: {GUTTER}mm, align: top + left,\n  [{given_data}],\n  [{given_loads_table}])\n")
    doc.body.append("".join(f"#text(size: {SMALL_PT}pt)[{_words(doc, line)}] \\\n" for line in data_lines))

    doc.mark(f"{key}-bodies-end", solid=True)
    if coarser:  # the estimate of the page's text left the bodies too little room: at the plate's k_l where the laid-out page holds them
        found = _bodies_at_plate(doc, key, free, plate_kl, lambda: _free_bodies(plans, graphical, lang, names, (box[0], math.inf), plate_kl, equations=arms))
        if found is not None:
            k_l, free = found
            pages.k_l = k_l
            coarser = ""
            doc.body[kl_at] = f"#plate-kl.update([{doc.scale_words('k_l', k_l)}])"
            doc.body[bodies_at] = ""
            doc.figure(f"{key}-free-bodies", free)
            doc.body[bodies_at] = doc.body.pop()
            doc.body[caption_at] = ""
            doc.line(_newtons(f"$k_{{l}}$ = {_scale(k_l)} m/mm;  {term('not_to_scale', lang)}", lang), size=SMALL_PT)
            doc.body[caption_at] = doc.body.pop()
    # 2. the force plans at one μ_F
    doc.mark(f"{key}-plans-start")
    # where the free bodies end, kept with the first plan
    heading(f"{_lower(term('force_plans', lang))}; {mu_words}", new_page=False)
    _scale_note(doc, mu_words)
    # a title block states the free bodies' k_l on their page, the plate's on a page of plans after it
    reset = ""
    if plate_kl is not None and coarser:
        reset = (f"#context {{ if here().page() != locate(<{key}-free-bodies>).page() "
                 f"{{ plate-kl.update([{doc.scale_words('k_l', plate_kl)}]) }} }}")
    given = given_loads(plans)
    written = {e.group: e for e in arms}
    # each plan under its equations: in its cell, or (where a line of them is wider than a cell) the equations of a
    # row's plans across the page above the row
    cell = (doc.page.text_width - (columns - 1) * GUTTER) / columns
    lines_of = {plan.group: _equation_lines(written[plan.group], lang) for plan in plans.plans}
    across = columns > 1 and not _equations_fit(lines_of, cell)

    def equations_markup(plan) -> str:
        rows = ", ".join(f"[{line}]" for line in lines_of[plan.group])
        return f"#text(size: {SMALL_PT}pt)[#table(columns: 1, stroke: none, inset: (x: 0mm, y: 0.9mm), row-gutter: 1.2mm, {rows})]"

    def item(k: int, with_equations: bool) -> str:
        plan, block = plans.plans[k], blocks[k]
        image_key = f"{key}-plan-{k + 1}" if plan.group != "driver" else f"{key}-plan-driver"
        pages.images[image_key] = f"plan:{plan.group}"
        moment = plans.balancing_moment if plan.group == "driver" else None
        lines = _plan_lines(plan, given, moment, lang, written[plan.group])
        # the title block of the page the plan lands on states μ_F
        parts = [f"{reset}#metadata([{_words(doc, mu_words)}]) <plans-page-scale>#text(size: {SMALL_PT + 1}pt, weight: \"bold\")[{_words(doc, _plan_title(plan, names, lang))}]"]
        if lines_of[plan.group] and with_equations:  # the vector and moment equations the plan is drawn from, before it
            parts.append(equations_markup(plan))
        parts.append(f"#align(center)[#{doc.add_image(image_key, block)}]")
        parts += [f"#text(size: {SMALL_PT}pt)[{_words(doc, line)}]" for line in lines]
        return "block(breakable: false, width: 100%)[" + " \\\n".join(parts) + "]"

    count = len(plans.plans)
    if across:
        for r in range(0, count, columns):
            row = list(range(r, min(r + columns, count)))
            if r:
                _scale_note(doc, mu_words)  # a row that runs over to a page of its own: its title block states μ_F
            if len(row) == 1:  # a plan alone in its row: the page's width, its equations in its cell
                doc.body.append(f"#{item(row[0], True)}\n")
                continue
            above = " \\\n".join(f"#text(size: {SMALL_PT + 1}pt, weight: \"bold\")[{_words(doc, _plan_title(plans.plans[k], names, lang))}] \\\n"
                                  f"{equations_markup(plans.plans[k])}" for k in row if lines_of[plans.plans[k].group])
            doc.body.append(f"#block(breakable: false, below: 5mm)[{above}\n#grid(columns: {columns}, column-gutter: {GUTTER}mm, align: top + left,\n  "
                            + ",\n  ".join(item(k, False) for k in row) + ")]\n")
    else:
        doc.body.append(f"#grid(columns: {columns}, column-gutter: {GUTTER}mm, row-gutter: 5mm, align: top + left,\n  "
                        + ",\n  ".join(item(k, True) for k in range(count)) + ")\n")
    kinds, closing = legend_kinds(plans.plans)
    doc.body.append("#v(2mm)\n" + _legend(doc, f"{key}-legend", list(kinds) + (["construction"] if closing else []), lang))

    if plate_kl is not None and not coarser:
        _fill_bodies_page(doc, key, bodies_at, free, lambda: _free_bodies(plans, graphical, lang, names, box, plate_kl, skip=1, equations=arms))
    # 3. Joukowski's lever and the three methods
    comparisons = compare_forces(analytic, lever, plans) if analytic is not None else ()
    pages.comparisons = comparisons
    if lever is not None:
        lever, comparisons = _lever_section(doc, graphical, lever, analytic, plans, key, heading, reset, mu_words)
        pages.images[f"{key}-lever"] = "lever"
        pages.lever = lever
        pages.comparisons = comparisons
    elif comparisons:
        doc.body.append("#v(4mm)")
        doc.body.append(_table(doc, _methods_table(comparisons, analytic, lang, plans, lever), "(left, right, right, right, right, right)", term("force_methods", lang)))
    return pages


def _bodies_at_plate(doc: Document, key: str, block, plate: float, at_plate):
    """(k_l, block) of the free bodies at the plate's k_l *plate* (*at_plate()*: the first arrangement as wide as the
    page, at *plate* or a coarser k_l where none is) where the laid-out page, with them at the coarser k_l (*block*),
    holds what they add under :data:`LEVER_SPARE` (read from the laid-out document); else None."""
    from .typesetting import query_document

    found = at_plate()
    if found is None or abs(found[0] - plate) > 1e-12 * plate:  # no arrangement as wide as the page at the plate's k_l
        return None
    marks = {m["name"]: m for m in query_document(doc.source(), doc.images, "<plans-mark>") if m["name"].startswith(key)}
    end = marks.get(f"{key}-bodies-end")
    if end is None:
        return None
    top, page = doc.page.margins[2], doc.page.text_height
    if found[1].height - block.height > top + page - end["y"] - LEVER_ABOVE - LEVER_SPARE:
        return None
    return found


def _fill_bodies_page(doc: Document, key: str, at: int, block, taller) -> None:
    """Where the force plans do not follow the free bodies onto their page and leave it less than :data:`PAGE_USE`
    (and a margin) used, the free bodies in their next arrangement at the plate's k_l (*taller()*: (k_l, block) or None), when the
    rest of that page holds what it adds (read from the laid-out document)."""
    from .typesetting import query_document

    marks = {m["name"]: m for m in query_document(doc.source(), doc.images, "<plans-mark>") if m["name"].startswith(key)}
    end, plans = marks.get(f"{key}-bodies-end"), marks.get(f"{key}-plans-start")
    if end is None or plans is None or plans["page"] == end["page"]:
        return
    top, page = doc.page.margins[2], doc.page.text_height
    if (end["y"] - top) / page >= PAGE_USE + 0.1:  # (the mark stands a line's spacing under the last ink)
        return
    found = taller()
    if found is None or found[1].height <= block.height:
        return
    if found[1].height - block.height > top + page - end["y"] - LEVER_ABOVE:
        return
    doc.body[at] = ""
    doc.figure(f"{key}-free-bodies", found[1])
    doc.body[at] = doc.body.pop()


#: the least size [mm] of the lever's largest vector (from the pole to the image of the fastest point) when it is
#: drawn at a scale of its own to fit its page
LEVER_LEAST = 60.0
#: the share of its text height a page of the force pages fills at least (not the handout's last section's only page)
PAGE_USE = 0.5
#: room [mm] kept free under what a page is reckoned to hold (the typesetter's spacing between blocks)
LEVER_SPARE = 1.5
#: the width [mm] of the lever's legend set in a column beside it
LEGEND_COLUMN = 58.0
#: the spacing [mm] above the lever's heading where it follows the force plans on their page
LEVER_ABOVE = 4.0


def _captured(doc: Document, write) -> str:
    """The markup *write()* appends to *doc*'s body, taken back out (to measure it or place it later)."""
    start = len(doc.body)
    write()
    markup = "".join(doc.body[start:])
    del doc.body[start:]
    return markup


def _lever_pieces(doc: Document, lever, analytic, plans, key: str, heading, mu_words: str, k_plate: float):
    """The lever section's markup in its four pieces (heading with the scale lines; the lever's legend; the moments
    about the pole with M_b; the three methods' table) and the comparisons, for *lever* drawn at its k_v."""
    from ..forces.compare import compare_forces

    lang = doc.lang
    own = ""
    if abs(lever.k_v - k_plate) > 1e-12 * k_plate:  # the lever at a scale of its own: said on the page
        own = ";  " + term("lever_own_scale", lang).format(scale=f"$k_{{v}}$ = {_scale(k_plate)} (m/s)/mm")
    head = _captured(doc, lambda: heading(term("joukowski_lever", lang), new_page=False, under=[
        (f"$k_{{v}}$ = {_scale(lever.k_v)} (m/s)/mm;  {term('lever_turned_ccw', lang)}{own}", SMALL_PT)]))
    legend = _legend(doc, f"{key}-lever-legend", _lever_kinds(lever) + ["arm"], lang)
    # the lever's equation over the table of its terms
    equation = r"$ΣM_{\mathrm{p}} = ΣF \cdot h + " + _math("F_b", lang)[1:-1] + r" \cdot " + _math("h_b", lang)[1:-1] + " = 0$"
    moments = ("#block(breakable: false)[" + doc.line_markup(_newtons(equation, lang), TEXT_PT) + "\n" + _table(doc, _lever_rows(lever, lang), "(left, left, right, right, right, left)", term("lever_moments", lang))
               + "".join(doc.line_markup(_newtons(line, lang), TEXT_PT) + "\n" for line in _lever_result(lever, lang)) + "]\n")
    comparisons = compare_forces(analytic, lever, plans) if analytic is not None else ()
    methods = (_table(doc, _methods_table(comparisons, analytic, lang, plans, lever), "(left, right, right, right, right, right)", term("force_methods", lang))
               if comparisons else "")
    return head, legend, moments, methods, comparisons


def _lever_layout(room: float, page: float, first: float, between: float, second: float, drawn, scales, least,
                  legend: float = 0.0, with_legend=None) -> tuple[str, float, float]:
    """(layout, k_v, the height [mm] the lever may take there: with its legend, or alone on ``"split"``): where the lever section goes and at which scale, from the heights [mm] the typesetter measured.

    *room*: what is left of the page the force plans end on; *page*: a page's text height; *first*: the heading and
    the legend (the lever's drawing, *drawn(k)* high at k_v = k, between them); *second*: the moments about the pole
    with M_b and the methods' table; *between*: the space between the two; *scales*: the round k_v to try, the
    plate's first; *least(k)*: whether the lever's largest vector keeps :data:`LEVER_LEAST` at k.  Layouts:
    ``"rest"`` (all of it under the plans), ``"split"`` (the lever under the plans, its legend (*legend* high, in
    *first*) and tables on the next page),
    ``"page"`` (all of it from a new page); *with_legend(k)*, where given, the height of the lever with its legend
    (beside it where that is lower) in place of *drawn(k)* + *legend*.  The first of them that leaves no page under :data:`PAGE_USE` used, with
    the lever drawn largest; else the one whose emptier page is fullest."""
    used = page - room  # of the plans' page
    room -= LEVER_ABOVE
    options = []  # (every page used at least PAGE_USE, pages added, -k, layout, k, the emptier page's use)

    def lever(k: float) -> float:  # the lever and its legend
        return with_legend(k) if with_legend is not None else drawn(k) + legend

    def finest(limit: float, rest: float, bound: bool, height=lever):
        for k in scales:
            if bound and not least(k) and k != scales[0]:
                return None
            if height(k) + rest + LEVER_SPARE <= limit:
                return k
        return None

    head = first - legend
    k = finest(room, head + between + second, True)
    if k is not None:
        options.append((True, 0, -k, "rest", k, 1.0, room - head - between - second - LEVER_SPARE))
    k = finest(room, head, True, drawn)
    if k is not None:
        options.append(((second + legend) / page >= PAGE_USE, 1, -k, "split", k, min((second + legend) / page, 1.0), room - head - LEVER_SPARE))
    k = finest(page, head + between + second, False) or scales[-1]
    whole = (head + lever(k) + between + second) / page
    options.append((used / page >= PAGE_USE and whole >= PAGE_USE, 1, -k, "page", k, min(used / page, whole), page - head - between - second - LEVER_SPARE))
    good = [o for o in options if o[0]]
    best = min(good, key=lambda o: (o[1], -o[2])) if good else max(options, key=lambda o: o[5])  # the lever largest
    return best[3], best[4], best[6]


def _lever_section(doc: Document, graphical, lever, analytic, plans, key: str, heading, reset: str, mu_words: str):
    """Set Joukowski's lever, the moments about the pole with M_b and the three methods' table where the force plans
    end (:func:`_lever_layout`), the lever at the plate's k_v or, where that leaves a page nearly empty, at a coarser
    round k_v of its own (its largest vector at least :data:`LEVER_LEAST`), stated under its heading and in the title
    block of its page.  Returns (the lever drawn, the comparisons of the three methods)."""
    from ..drawing.force_blocks import lever_svg
    from ..forces.lever import joukowski_lever
    from .typesetting import query_document

    k_plate = lever.k_v
    block = lever_svg(lever, doc.lang)
    ys = [z.imag for z in lever.images.values()] + [0.0]
    span = max(ys) - min(ys)  # [mm] at the plate's k_v: what scales
    fixed = block.height - span
    longest = max(abs(z) for z in lever.images.values())

    def drawn(k: float) -> float:
        return fixed + span * k_plate / k

    def least(k: float) -> bool:
        return longest * k_plate / k >= LEVER_LEAST - 1e-9

    scales = [k_plate]
    while len(scales) < 40:
        scales.append(round_up(scales[-1] * 1.0001))
    head, legend, moments, methods, comparisons = _lever_pieces(doc, lever, analytic, plans, key, heading, mu_words, k_plate)
    # the room left under the plans and the pieces' heights, from one layout of the document so far
    width = doc.page.text_width
    image = doc.add_image(f"{key}-lever", block)
    figure = f"#align(center)[#{image}]\n"
    column = _legend(doc, f"{key}-lever-legend", _lever_kinds(lever) + ["arm"], doc.lang, column=True)
    pieces = (("head", head), ("column", f"#box[{column}]"), ("first", head + figure + legend), ("second", moments + methods), ("all", head + figure + legend + moments + methods))
    sizes = ", ".join(f"{name}: measure(block(width: {width if name != 'column' else LEGEND_COLUMN}mm)[{markup}]).height.mm()"
                      for name, markup in pieces)
    start = len(doc.body)
    doc.mark(f"{key}-lever-room", solid=True)
    doc.body.append(f"#context [#metadata((name: \"{key}-lever-sizes\", {sizes})) <plans-mark>]\n")
    try:
        marks = {m["name"]: m for m in query_document(doc.source(), doc.images, "<plans-mark>")}
    finally:
        del doc.body[start:]
    top, page = doc.page.margins[2], doc.page.text_height
    room = top + page - marks[f"{key}-lever-room"]["y"]
    h = marks[f"{key}-lever-sizes"]
    drawn_plate = drawn(k_plate)
    first, second = h["first"] - drawn_plate, h["second"]
    legend_height = first - h["head"]  # with its spacing
    between = h["all"] - h["first"] - h["second"]  # the spacing between the two
    spans_x = [z.real for z in lever.images.values()] + [0.0]
    across = max(spans_x) - min(spans_x)
    fixed_w = block.width - across

    def beside(k: float) -> bool:  # the legend in a column beside the lever, where the page is wide enough
        return fixed_w + across * k_plate / k + GUTTER + LEGEND_COLUMN <= width

    def with_legend(k: float) -> float:
        return min(drawn(k) + legend_height, max(drawn(k), h["column"]) + 1.0 if beside(k) else math.inf)

    layout, k, allowed = _lever_layout(room, page, first, between, second, drawn, scales, least, legend_height, with_legend)
    def taken(block) -> float:  # the height [mm] the lever drawn (with its legend, but on a "split") takes
        if layout == "split":
            return block.height
        stacked = block.height + legend_height
        return min(stacked, max(block.height, h["column"]) + 1.0) if beside(k) else stacked

    for _ in range(4):  # drawn at k: a round step coarser while the drawing runs over the room it has (its labels
        if k != lever.k_v:  # need more of it than reckoned), as long as its largest vector keeps its least size
            lever = joukowski_lever(graphical, k_v=k)
            block = lever_svg(lever, doc.lang)
        step = scales.index(k) + 1
        if taken(block) <= allowed + 0.5 or step >= len(scales) or not least(scales[step]):
            break
        k = scales[step]
    head, legend, moments, methods, comparisons = _lever_pieces(doc, lever, analytic, plans, key, heading, mu_words, k_plate)
    # the title block of every page the section lands on states the scales it uses: μ_F (the three methods' table
    # reads the force plans at it) and the lever's own k_v where it has one (its arms are mm at that k_v); inside each
    # piece that may begin a page of its own
    notes = f"#metadata([{_words(doc, mu_words)}]) <plans-page-scale>"
    if k != k_plate:
        notes += f"#metadata([{_words(doc, term('joukowski_lever', doc.lang) + f': $k_{{v}}$ = {_scale(k)} (m/s)/mm')}]) <plans-page-scale>"
    # (inside a block: a note between blocks would set a line of its own and take room the layout did not reckon with)
    moments, methods = (piece.replace("#block(breakable: false)[", "#block(breakable: false)[" + notes, 1) for piece in (moments, methods))
    head = head.replace("#block(sticky: true, breakable: false)[", "#block(sticky: true, breakable: false)[" + notes, 1)
    if layout == "page":
        doc.body.append("#pagebreak(weak: true)\n")
    doc.body.append(head)
    if layout != "split" and beside(k) and max(block.height, h["column"]) + 1.0 < block.height + legend_height:
        column = _legend(doc, f"{key}-lever-legend", _lever_kinds(lever) + ["arm"], doc.lang, column=True)
        doc.body.append(f"#grid(columns: (auto, {LEGEND_COLUMN}mm), column-gutter: {GUTTER}mm, align: horizon + left, "
                        f"{doc.add_image(f'{key}-lever', block)}, [{column}])\n")
        doc.body.append(reset + "\n")
    else:
        doc.figure(f"{key}-lever", block)
        doc.body.append(reset + "\n")
        if layout == "split":  # the legend with the tables, over the page
            doc.body.append("#pagebreak(weak: true)\n")
        doc.body.append(legend)
    doc.body.append(moments)
    if methods:
        doc.body.append(methods)
    return lever, comparisons


def _body_kinds(plans) -> list[str]:
    """The kinds of force the free bodies draw (in the legend's order)."""
    from ..drawing.force_drawing import FORCE_LEGEND

    drawn = {f.kind for body in {b for p in plans.plans for b in p.links} for f in plans.on(body)[0] if abs(f.force)}
    return [k for k in FORCE_LEGEND if k in drawn]


_LEVER_KIND = {"weight": "weight", "inertia force": "inertia", "inertia couple": "inertia", "force": "external", "resistance": "external",
               "moment": "external", "balancing": "balancing"}


def _lever_kinds(lever) -> list[str]:
    drawn = {_LEVER_KIND.get(f.kind, "external") for f in list(lever.forces) + [lever.balancing_force] if abs(f.force)}
    return [k for k in ("weight", "inertia", "external", "balancing") if k in drawn]


def _lever_rows(lever, lang: str) -> list[list[str]]:
    """The moments about the pole: force, its image, |F| [N], arm h [mm], F·h [N·mm], and for a couple's pair how it was found."""
    from ..drawing.force_drawing import lever_names
    from ..drawing.force_drawing import lever_image_text

    names = lever_names(lever)
    moments = {(load.name, load.body): float(load.moment) for load in lever.loads if load.is_couple}
    pairs: dict = {}
    for f in lever.forces:
        if f.kind in ("inertia couple", "moment"):
            pairs.setdefault((f.name, f.body), []).append(f)
    rows = [["", term("image", lang), "|F| [N]", "h [mm]", "F·h [N·mm]", ""]]
    for f in list(lever.forces) + [lever.balancing_force]:
        if abs(f.force) == 0:
            continue
        arm = f.arm if abs(f.arm) >= 0.05 else 0.0
        note = ""
        pair = pairs.get((f.name, f.body), [])
        if len(pair) == 2 and (f.name, f.body) in moments:
            ends = "".join(q.image.upper() for q in pair)
            couple = moments[(f.name, f.body)]
            length = abs(couple) / abs(f.force)
            note = f"= {_math(f.name, lang)}/$l_{{\\mathrm{{{ends}}}}}$ = {_couple(abs(couple), f.name)} N·m / {length:.4g} m"
            if f is pair[0]:
                note += f"; {term('lever_pair', lang).format(points=', '.join(lever_image_text(q.image, lever.scene) for q in pair))}"
        rows.append([_math(names[id(f)], lang), lever_image_text(f.image, lever.scene), _number(abs(f.force)), _minus(f"{arm:.1f}"), _number(f.moment), note])
    return rows


def _lever_result(lever, lang: str) -> list[str]:
    from ..drawing.force_drawing import sense_arrow

    lines = [f"{_math(c.name, lang)} = {_couple(c.couple, c.name)} N·m → {_number(c.moment)} N·mm ({term('lever_block_couple', lang)})" for c in lever.couples]
    if lever.balancing_kind == "moment":
        lines.append(f"{_math('M_b', lang)} = {_math('F_b', lang)}·$l_{{\\mathrm{{OA}}}}$ = {_number(abs(lever.balancing_force.force))} N · "
                     f"{lever.crank_length:.4g} m = {_number(abs(lever.balancing))} N·m{sense_arrow(lever.balancing)} ({_lower(term('balancing_moment', lang))}, {term('from_lever', lang)})")
    else:
        lines.append(f"{_math('F_b', lang)} = {_number(lever.balancing)} N ({_lower(term('balancing_force', lang))}, {term('from_lever', lang)})")
    return lines


def force_document(run, lang: str = "en") -> tuple[Document, ForcePages]:
    """The kinetostatic pages of one position of ``plans forces`` (a :class:`plans.forces.compare.KinetostaticRun`
    with its graphical solution) as a Document of their own: its title block states the run's scales."""
    doc = Document(run.scene, lang)
    doc.plate = dict(run.graphical.scales)
    doc.plate_name = "kinetostatics"
    pages = force_pages(doc, run.graphical, lever=run.lever, analytic=run.analytic)
    return doc, pages
