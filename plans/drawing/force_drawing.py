"""Drawings of the kinetostatics: each group's force plan, the driver's, and the free bodies of the groups.

Drawn from :class:`plans.forces.force_plans.ForcePlans` data and nothing
else: the plans' coordinates are already millimetres at μ_F, the free bodies
are the mechanism at k_l.  Nothing is solved here.

* :func:`draw_force_plan` — one force plan: the polygon of loads and
  reactions head to tail, the two closing lines of known direction, the
  reactions' components, every vector labelled, μ_F and the readings stated;
* :func:`draw_free_bodies` — the mechanism cut into its groups and the
  driver, each with its loads (weights, inertia forces and couples, given
  forces) and the reactions on it, at the length scale k_l (the arrows have
  one length, not to scale);
* :func:`force_figures` / :func:`write_force_drawings` — every drawing of a
  position, as figures or files (SVG true to scale, PDF, PNG), all or none.

Gids (labels in ASCII, Φ as ``Phi``): ``fplan-<kind>-<label>`` (shaft; ``-head``), ``fplan-line-<n>``,
``fplan-start``, ``fplan-label-<label>``, ``fplan-heading``, ``fplan-scale``,
``fplan-reading-<label>``, ``fplan-legend-<kind>``; ``fbody-link-<body>``,
``fbody-force-<label>``, ``fbody-couple-<label>``, ``fbody-heading-<group>``.
"""

from __future__ import annotations

import cmath
import math
import re
from pathlib import Path

from ._canvas import Sketch, fmt_number, sketch_on, text_size, unit
from .labels import place_label
from .numerals import localised, scale_caption
from .style import CAPTION_PT, CONSTRUCTION_STYLE, FIGURE_STYLE, FORCE_HOLLOW, FORCE_STYLE, HEADING_PT, INK, LABEL_PT, SMALL_PT
from ..forces.notation import centre_text, course_label, plain_centres
from ..i18n import term

__all__ = [
    "draw_force_plan",
    "draw_force_plan_into",
    "draw_free_bodies",
    "draw_free_bodies_into",
    "shoulders",
    "draw_force_legend_into",
    "legend_kinds",
    "force_figures",
    "write_force_drawings",
    "force_drawing_files",
    "force_math",
    "course_label",
    "lever_image_text",
    "draw_lever",
    "draw_lever_into",
    "FORCE_LEGEND",
    "FREE_ARROW_MM",
]

#: Length of every force arrow on the free bodies [mm] (not to scale).
FREE_ARROW_MM = 11.0
#: Radius of a couple's arc on the free bodies [mm].
COUPLE_R_MM = 6.0
#: Space between two free bodies [mm].
FREE_GAP_MM = 6.0
#: Room for a name beyond a free body's arrows [mm].
FREE_LABEL_MM = 3.0
#: How far a closing line runs past the intersection and behind its start [mm].
PAST_MM = 8.0
BEHIND_MM = 4.0
#: A vector shorter than this [mm] is drawn without a head; a note under the plan gives its length.
SHORT_MM = 3.0
#: Label gaps [mm] tried in turn.
GAPS = (0.8, 1.6, 2.6, 3.8, 5.5, 8.0, 11.0)

#: plan/force kind -> plans.i18n key of its legend words
FORCE_LEGEND = {
    "weight": "force_weight",
    "inertia": "force_inertia",
    "external": "force_external",
    "reaction": "force_reaction",
    "normal": "force_normal",
    "tangential": "force_tangential",
    "balancing": "balancing_force",
}


def _beside(drawn: list, tail: complex, u: complex) -> complex:
    """The sideways shift [mm] that keeps an arrow from *tail* along *u* off those already *drawn* there (same point, same way)."""
    same = sum(1 for t, w in drawn if abs(t - tail) < 0.5 and (w * u.conjugate()).real > 0.97)
    drawn.append((tail, u))
    return 1j * u * 2.6 * same


def _gid(label: str) -> str:
    """A label as a gid (ASCII): ``"F_Φ3"`` → ``"F_Phi3"``, ``"F′_Φ3"`` → ``"Fp_Phi3"``, ``"F″_Φ3"`` → ``"Fpp_Phi3"``."""
    return label.replace("Φ", "Phi").replace("″", "pp").replace("′", "p")


def _escape(text: str) -> str:
    text = text.replace("\\", "").replace("{", "").replace("}", "")
    for c in "$_%#&^~":
        text = text.replace(c, "\\" + c)
    return text


def force_math(label: str, lang: str = "en") -> str:
    """A force's label as mathtext: ``"R^t_23"`` → ``$R^{t}_{\\mathrm{23}}$``, ``"F_Φ3"``, a given load's name;
    ``"M_b"`` with the subscript of the course in *lang* (:func:`course_label`).

    The symbol, superscript and subscript are escaped (a load's name comes
    from the scene and is never read as a mathtext command).
    """
    head, _, sub = course_label(label, lang).partition("_")
    symbol, _, sup = head.partition("^")
    text = _escape(symbol) or " "
    if sup:
        text += "^{" + _escape(sup) + "}"
    if sub:
        text += r"_{\mathrm{" + _escape(sub) + "}}"
    return f"${text}$"


def _lower(words: str) -> str:
    """Words as they go inside a sentence or a legend: the first letter in lower case."""
    return words[:1].lower() + words[1:]


def _step(plan) -> float | None:
    """The smallest step of a force read off *plan* [N]: the precision times μ_F."""
    return plan.precision * plan.scale if plan.precision else None


def _reading(value: float, step: float | None, lang: str) -> str:
    """A value read to *step* (as many decimals as the step has), or to 4 significant figures without one."""
    if not step:
        return _number(value, lang)
    text = f"{step:.10f}".rstrip("0")
    decimals = len(text.partition(".")[2])
    return localised(f"{round(value / step) * step:.{decimals}f}", lang)


def _number(value: float, lang: str, digits: int = 4) -> str:
    """A reading to *digits* significant figures, in the language's numerals."""
    if value == 0:
        return "0"
    decimals = max(0, digits - 1 - math.floor(math.log10(abs(value))))
    return localised(f"{value:.{decimals}f}", lang)


# --- a force plan ----------------------------------------------------------------------


def draw_force_plan(plan, ax=None, *, lang: str = "en", legend: bool = True, balancing_moment: float | None = None, found_at: dict | None = None,
                    given: dict | None = None, names: dict | None = None) -> list:
    """Draw one force plan (:class:`plans.forces.force_plans.ForcePlan`), one data unit = 1 mm.

    *balancing_moment* [N·m], given for the driver's plan, is stated under it.
    *found_at* (:func:`found_scales`): reaction -> μ_F [N/mm] of the plan that
    found it, so that a reaction carried to this plan at another μ_F says so.
    *given* (:func:`given_loads`): load -> its magnitude [N] as the kinetostatics
    gives it (the plan's own value is the drawn length read back).
    *names*: group -> its words in the heading (``"group 3–4"``).
    Under the plan: the known loads (N and drawn mm), the components Rᵗ found
    first, the reactions read off it.
    Returns the artists; a new true-to-scale figure is ``artists[0].figure``.
    """
    return sketch_on(ax, "fplan", lambda sketch: draw_force_plan_into(sketch, plan, lang=lang, legend=legend, balancing_moment=balancing_moment, found_at=found_at, given=given,
                                                                        names=names))


def given_loads(forces) -> dict[str, float]:
    """Load label -> its magnitude [N] (weights, inertia forces, given forces) on every moving link of *forces*."""
    out: dict[str, float] = {}
    for f in forces.loads:
        out.setdefault(f.label, float(abs(f.force)))
    return out


def found_scales(plans) -> dict[str, float]:
    """Reaction label -> μ_F [N/mm] of the plan that found it (and of its opposite R_ji, the same force reversed)."""
    out: dict[str, float] = {}
    for plan in plans:
        for label in plan.found:
            out.setdefault(label, plan.scale)
            head, sep, sub = label.partition("_")
            if head == "R" and len(sub) == 2:
                out.setdefault(f"R_{sub[::-1]}", plan.scale)
    return out


def draw_force_plan_into(sketch: Sketch, plan, *, lang: str = "en", legend: bool = True, caption: bool = True, balancing_moment: float | None = None,
                         found_at: dict | None = None, given: dict | None = None, names: dict | None = None) -> None:
    """Draw *plan* into *sketch*: what :func:`draw_force_plan` does on a page's own Sketch (*caption*: the
    words under it; a page set by Typst, :mod:`plans.pages.forces`, sets them itself)."""
    vectors = [v for v in plan.vectors if v.length > 1e-9]
    for v in vectors:
        for z in (v.tail, v.tip):
            if not (math.isfinite(z.real) and math.isfinite(z.imag)):
                raise ValueError(f"force plan {plan.group}: {v.label} is not finite")
    # the closing lines, thin, under everything, from their point past the intersection
    target = _closing_point(plan)
    for n, line in enumerate(plan.lines):
        d = unit(complex(line.direction))
        t = ((target - line.through) * d.conjugate()).real if target is not None else 20.0
        lo, hi = min(0.0, t), max(0.0, t)
        a = line.through + d * (lo - (BEHIND_MM if t >= 0 else PAST_MM))
        b = line.through + d * (hi + (PAST_MM if t >= 0 else BEHIND_MM))
        color, lw, dashes = CONSTRUCTION_STYLE
        sketch.line([a, b], color=color, lw=lw, dashes=dashes, gid=f"line-{n}", zorder=1.0)
    # components and inner reactions first, under the polygon's own vectors
    order = {"normal": 0, "tangential": 1, "reaction": 2, "weight": 3, "inertia": 3, "external": 3, "balancing": 3}
    for v in sorted(vectors, key=lambda v: order[v.kind]):
        color, lw, dashes, head = FORCE_STYLE[v.kind]
        if v.length < SHORT_MM:  # too short for an arrow: its end is a point, its length a note
            sketch.line([complex(v.tail), complex(v.tip)], color=color, lw=lw, gid=f"{v.kind}-{_gid(v.label)}", zorder=3.0)
            continue
        sketch.arrow(complex(v.tail), complex(v.tip), color=color, lw=lw, dashes=dashes, head=min(head, v.length / 3.0), gid=f"{v.kind}-{_gid(v.label)}", zorder=3.0 if v.kind != "normal" else 2.6,
                     hollow=v.kind in FORCE_HOLLOW)
    sketch.circle(0j, 0.55, fc=INK, lw=0, gid="start", zorder=4.0)
    for name, z in plan.points.items():
        sketch.circle(complex(z), 0.35, fc=INK, lw=0, gid=f"vertex-{name}", zorder=4.0, obstacle=False)
    segments = [(complex(v.tail), complex(v.tip)) for v in vectors]
    for k, v in enumerate(vectors):
        tail, tip = segments[k]
        middle = (tail + tip) / 2
        # a vector another one all but retraces (R_23 and R_34 nearly along each other): its label a third of the way
        # along instead of at the middle, the other's at two thirds, so that each stands by its own
        twins = [j for j, seg in enumerate(segments) if j != k and _retraces(segments[k], seg)]
        if twins:
            middle = tail + (tip - tail) * (0.32 if k < twins[0] else 0.68)
        across = 1j * unit(tip - tail)  # a label stands beside its own vector, at its middle,
        others = [q for j, seg in enumerate(segments) if j != k for q in (seg[0], (seg[0] + seg[1]) / 2, seg[1])]
        if others and sum(abs(middle + across - q) for q in others) < sum(abs(middle - across - q) for q in others):
            across = -across  # on the side away from the other vectors
        rivals = tuple(seg for j, seg in enumerate(segments) if j != k and abs(seg[1] - seg[0]) > 1e-9)
        place_label(sketch, middle, [(force_math(v.label, lang), f"label-{_gid(v.label)}")], size=LABEL_PT if v.length >= 6 else SMALL_PT,
                    prefer=across, gaps=GAPS, mathtext=True, leader_from=4.0, color=FORCE_STYLE[v.kind][0] if v.kind != "reaction" else INK,
                    own=(tail, tip), rival_segments=rivals)
    if caption:
        _plan_caption(sketch, plan, vectors, lang, legend, balancing_moment, found_at or {}, given or {}, names)


def _retraces(a: tuple[complex, complex], b: tuple[complex, complex], near: float = 2.5) -> bool:
    """Whether segment *b* runs within *near* mm of *a*'s middle, nearly parallel to it (the two would share a label's place)."""
    da, db = a[1] - a[0], b[1] - b[0]
    if abs(da) < 1e-9 or abs(db) < 1e-9:
        return False
    parallel = abs((da * db.conjugate()).imag) <= 0.15 * abs(da) * abs(db)
    middle = (a[0] + a[1]) / 2
    t = min(1.0, max(0.0, ((middle - b[0]) * db.conjugate()).real / abs(db) ** 2))
    return parallel and abs(middle - (b[0] + t * db)) < near


def _closing_point(plan):
    """The intersection of the two closing lines [mm], if the plan has them."""
    if len(plan.lines) != 2:
        return None
    (p1, d1), (p2, d2) = ((complex(line.through), complex(line.direction)) for line in plan.lines)
    cross = (d1.conjugate() * d2).imag
    if abs(cross) < 1e-12:
        return None
    t = ((p2 - p1).conjugate() * d2).imag / cross
    return p1 + t * d1


def _plan_caption(sketch: Sketch, plan, vectors, lang: str, legend: bool, balancing_moment: float | None, found_at: dict,
                  given: dict | None = None, names: dict | None = None) -> None:
    """Heading, μ_F, the known loads, the reactions read off the plan, the legend: below the plan."""
    b = sketch.bounds
    x, y = b.xmin, b.ymin - 3.0
    crank = not any(v.label == "F_b" for v in plan.vectors)  # a linear driver's plan carries F_b; a crank's M_b is a couple
    what = driving_link_words(plan.links[0], crank, lang) if plan.group == "driver" else (names or {}).get(plan.group, plan.group)
    sketch.text(complex(x, y), f"{term('force_plan', lang)}: {what}", size=HEADING_PT, ha="left", va="top", weight="bold", gid="heading", obstacle=False)
    y -= 5.0
    sketch.text(complex(x, y), scale_caption(r"\mu_F", fmt_number(plan.scale), "N/mm", lang), size=CAPTION_PT, ha="left", va="top", gid="scale", obstacle=False, math=True)
    row = text_size("lp", CAPTION_PT)[1] + 0.9
    mu = localised(fmt_number(plan.scale), lang)
    width = max(b.width, 50.0)

    def flow(notes: list[tuple[str, str]], y: float, indent: float = 0.0) -> float:
        """Notes (text, gid) side by side as far as the plan is wide (at least 50 mm), rows downwards from *y*; the last row's y."""
        cursor = None
        for note, gid in notes:
            w = text_size(note, CAPTION_PT, math=True)[0]
            if cursor is None or cursor + w > x + width:
                y -= row
                cursor = x + indent
            sketch.text(complex(cursor, y), note, size=CAPTION_PT, ha="left", va="top", gid=gid, obstacle=False, math=True)
            cursor += w + 3.0
        return y

    # what is known before the plan is drawn: every load (and a reaction carried from a plan before), N and drawn mm
    y -= row
    sketch.text(complex(x, y), term("known_loads", lang) + ":", size=CAPTION_PT, ha="left", va="top", gid="known-heading", obstacle=False)
    known, carried_notes = [], []
    for v in vectors:
        if v.label in plan.found or v.kind in ("normal", "tangential"):
            continue
        value = _number(given[v.label], lang) if given and v.label in given else _reading(v.value, _step(plan), lang)
        line = f"{force_math(v.label, lang)} = {value} N → {_reading(v.length, plan.precision, lang)} mm"
        if v.kind == "reaction":  # not found here: a reaction carried from a plan before, the value read there
            carried = found_at.get(v.label, plan.scale)
            note = term("carried", lang)
            if abs(carried - plan.scale) > 1e-12 * plan.scale:
                note = term("carried_rescaled", lang).format(there=localised(fmt_number(carried), lang), here=mu).replace("μ_F", r"$\mu_F$")
            carried_notes.append((f"{line} ({note})", f"known-{_gid(v.label)}"))
        else:
            known.append((line + ";", f"known-{_gid(v.label)}"))
    if known:
        known[-1] = (known[-1][0].rstrip(";"), known[-1][1])
    y = flow(known, y, 2.0)
    y = flow(carried_notes, y, 2.0)
    # the tangential components, found first (from the moments about the middle joint)
    tangential = [v for v in vectors if v.kind == "tangential"]
    if tangential:
        y -= row
        sketch.text(complex(x, y), term("found_first", lang) + ":", size=CAPTION_PT, ha="left", va="top", gid="found-first", obstacle=False)
        y = flow([(f"{force_math(v.label, lang)} = {_reading(v.value, _step(plan), lang)} N → {_reading(v.length, plan.precision, lang)} mm",
                   f"reading-{_gid(v.label)}") for v in tangential], y, 2.0)
    for v in vectors:
        if v.label not in plan.found:
            continue
        y -= row
        line = f"{force_math(v.label, lang)} = {_reading(v.length, plan.precision, lang)} mm · {mu} N/mm = {_reading(v.value, _step(plan), lang)} N"
        sketch.text(complex(x, y), line, size=CAPTION_PT, ha="left", va="top", gid=f"reading-{_gid(v.label)}", obstacle=False, math=True)
    # notes on vectors too short for an arrow (their value in N too)
    y = flow([(f"|{force_math(v.label, lang)}| = {localised(f'{v.length:.2f}', lang)} mm "
               f"({_number(given[v.label], lang) if given and v.label in given else _reading(v.value, _step(plan), lang)} N)", f"short-{_gid(v.label)}")
              for v in vectors if v.length < SHORT_MM], y)
    if balancing_moment is not None:
        y -= row
        sketch.text(complex(x, y), f"{force_math('M_b', lang)} = {_number(abs(balancing_moment), lang)} N·m{sense_arrow(balancing_moment)} ({_lower(term('balancing_moment', lang))}, {term('from_force_plans', lang)})",
                    size=CAPTION_PT, ha="left", va="top", gid="reading-M_b", obstacle=False, math=True)
    if not legend:
        return
    kinds = [k for k in FORCE_LEGEND if any(v.kind == k and v.length >= SHORT_MM for v in vectors)]
    draw_force_legend_into(sketch, kinds, bool(plan.lines), lang, x, y - 2.0)


def legend_kinds(plans) -> tuple[list[str], bool]:
    """The kinds of force the *plans* draw as arrows (in legend order), and whether any has closing lines."""
    kinds = [k for k in FORCE_LEGEND if any(v.kind == k and v.length >= SHORT_MM for plan in plans for v in plan.vectors)]
    return kinds, any(plan.lines for plan in plans)


def draw_force_legend_into(sketch: Sketch, kinds, lines: bool, lang: str, x: float = 0.0, y: float = 0.0) -> None:
    """The legend of force plans: a sample arrow and the words of each kind, one row each downwards from (x, y) [mm]."""
    row = text_size("lp", CAPTION_PT)[1] + 0.9
    for kind in kinds:
        y -= row
        color, lw, dashes, _ = FORCE_STYLE[kind]
        sketch.arrow(complex(x, y), complex(x + 9.0, y), color=color, lw=lw, dashes=dashes, head=2.4, gid=f"legend-{kind}", hollow=kind in FORCE_HOLLOW)
        sketch.text(complex(x + 11.0, y), _lower(term(FORCE_LEGEND[kind], lang)), size=CAPTION_PT, ha="left", va="center", gid=f"legend-text-{kind}", obstacle=False)
    if lines:
        y -= row
        color, lw, dashes = CONSTRUCTION_STYLE
        sketch.line([complex(x, y), complex(x + 9.0, y)], color=color, lw=lw, dashes=dashes, gid="legend-construction", obstacle=False)
        sketch.text(complex(x + 11.0, y), term("construction_line", lang), size=CAPTION_PT, ha="left", va="center", gid="legend-text-construction", obstacle=False)


# --- the free bodies ---------------------------------------------------------------------


def draw_free_bodies(forces, ax=None, *, lang: str = "en", names: dict | None = None, equations=None) -> list:
    """The groups and the driver, cut apart, with their loads and the reactions on them.

    Each is drawn at one k_l (see :func:`draw_free_bodies_into`), side by side in the order of the
    force plans (the last group first, the driver last); every force is an
    arrow of :data:`FREE_ARROW_MM` at its point of application (a load from
    its point, a reaction into its joint), every couple an arc.
    """
    return sketch_on(ax, "fbody", lambda sketch: draw_free_bodies_into(sketch, forces, lang=lang, names=names, equations=equations))


def draw_free_bodies_into(sketch: Sketch, forces, *, lang: str = "en", caption: bool = True, k_l: float | None = None, per_row: int | None = None,
                          names: dict | None = None, columns: tuple[int, ...] | None = None, equations=None) -> None:
    """Draw the free bodies into *sketch* (see :func:`draw_free_bodies`), at *k_l* [m/mm], *per_row* of them in a
    row (by default all in one), each row under the one before, or in *columns* (how many each holds; a tall body
    beside a column of small ones); *names*: group -> the words written over its
    body (``"group 3–4"``; the group's own name without them).

    *equations* (:func:`plans.forces.plan_equations.plan_equations` of *forces*, as the page writes them): each arm
    h_k a moment equation uses drawn on its body (:func:`shoulders`), a thin line from the moment point perpendicular
    to the force's line of action (that line dotted as far as the foot), named ``h_k = … mm`` (its length on this
    drawing).

    By default k_l is the round value that draws the largest free body 60–120 mm across (a group is
    smaller than the mechanism: its links drawn at the mechanism's k_l would crowd their arrows).
    """
    g = forces.graphical
    if k_l is None:
        from ..graphical.scales import round_scale

        spans = []
        for plan in forces.plans:
            zs = [g.positions[n] for body in plan.links for n in g.scene.bodies[body].points]
            spans.append(max(max(z.real for z in zs) - min(z.real for z in zs), max(z.imag for z in zs) - min(z.imag for z in zs)))
        k_l = round_scale(max(spans), fallback=g.scales["k_l"])
    per_row = per_row or len(forces.plans)
    bodies = []
    for plan in forces.plans:
        links = plan.links
        pts = [g.positions[n] / k_l for body in links for n in g.scene.bodies[body].points]
        acting = []
        couples = []
        for body in links:
            f, c = forces.on(body)
            inner = {pair_label_of(r) for r in f if r.kind == "reaction" and _inside(r.label, links)}
            acting += [x for x in f if not (x.kind == "reaction" and x.label in inner)]
            couples += c
        # what the body takes with its arrows: a load's arrow from its point, a reaction's into its joint, a couple's
        # arc about its centre, and room for their names
        reach = [f.at / k_l + (1 if f.kind != "reaction" else -1) * f.force / abs(f.force) * (FREE_ARROW_MM + 2.0) for f in acting if abs(f.force)]
        reach += [f.at / k_l for f in acting]
        for c in couples:
            if c.moment:
                where = _pivot(g, c.body) if c.kind == "balancing" or forces.centres.get(c.body) is None else forces.centres[c.body].at
                reach += [where / k_l + (COUPLE_R_MM + 2.0) * d for d in (1, 1j, -1, -1j)]
        arms = shoulders(equations, plan.group, g) if equations else []
        reach += [z / k_l for arm in arms for z in (arm[1], arm[4])]
        zs = pts + reach
        what = driving_link_words(plan.links[0], _is_crank(g.scene), lang) if plan.group == "driver" else (names or {}).get(plan.group, plan.group)
        left = min(z.real for z in zs) - FREE_LABEL_MM
        right = max(z.real for z in zs) + FREE_LABEL_MM
        if text_size(what, CAPTION_PT)[0] > right - left and " (" in what:
            what = what.replace(" (", "\n(", 1)  # a name wider than its body in two lines: "driving link 2" / "(crank)"
        wide = max(text_size(line, CAPTION_PT)[0] for line in what.split("\n"))
        box = (left, max(right, left + wide),  # its name over it
               min(z.imag for z in zs) - FREE_LABEL_MM, max(z.imag for z in zs) + FREE_LABEL_MM + FREE_NAME_MM * (what.count("\n") + 1))
        bodies.append((plan, links, box, acting, couples, what, arms))
    placed = [(body[0], body[1], complex(x - body[2][0], y - body[2][3]), body[3], body[4], body[2], body[5], body[6]) for body, (x, y) in
              zip(bodies, _arrange([b[2] for b in bodies], per_row, columns))]
    # each body's name over it, first: the bodies' labels are then placed clear of it
    from shapely.geometry import box as shapely_box

    for plan, links, shift, _, _, box, what, _ in placed:
        for k, line in enumerate(what.split("\n")):
            corner = complex(box[0] + shift.real, box[3] + shift.imag - k * FREE_NAME_MM)
            sketch.text(corner, line, size=CAPTION_PT, ha="left", va="top", gid=f"heading-{plan.group}" + (f"-{k}" if k else ""))
            w, h = text_size(line, CAPTION_PT)
            sketch.obstacles.append(shapely_box(corner.real, corner.imag - h, corner.real + w, corner.imag).buffer(1.2))  # and a margin
    for plan, links, shift, acting, couples, _, _, arms in placed:
        _free_body(sketch, forces, plan, links, shift, acting, couples, lang, k_l, arms)
    if caption:
        b = sketch.bounds
        sketch.text(complex(b.xmin, b.ymax + 6.0), term("free_bodies", lang), size=HEADING_PT, ha="left", va="bottom", weight="bold", gid="heading", obstacle=False)
        sketch.text(complex(b.xmin, b.ymin - 3.0), f"{scale_caption('k_l', fmt_number(k_l), 'm/mm', lang)};  {term('not_to_scale', lang)}",
                    size=CAPTION_PT, ha="left", va="top", gid="scale", obstacle=False, math=True)


#: how far [mm] an arrow along a bar through its point is drawn beside the bar: its head (~0.7 mm a side) and the
#: bar (~0.4 mm) clear of each other with a gap that reads at print size
BESIDE_BAR_MM = 3.0

#: the height [mm] a line of a body's name takes over it
FREE_NAME_MM = 4.5


def _arrange(boxes, per_row: int, columns: tuple[int, ...] | None = None) -> list[tuple[float, float]]:
    """The top-left corner [mm] of each of *boxes* (xmin, xmax, ymin, ymax): *per_row* to a row, each row under the one
    before; or, with *columns* (how many bodies each column holds, in order), in columns side by side, each body under
    the one before (a tall body beside a column of small ones); each box holds its body's name over it."""
    corners = []
    if columns:
        x, k = 0.0, 0
        for count in columns:
            column = boxes[k:k + count]
            y = 0.0
            for box in column:
                corners.append((x, y))
                y -= box[3] - box[2] + FREE_GAP_MM
            x += max(box[1] - box[0] for box in column) + FREE_GAP_MM
            k += count
        return corners
    y = 0.0
    for start in range(0, len(boxes), per_row):
        row = boxes[start:start + per_row]
        x = 0.0
        for box in row:
            corners.append((x, y))
            x += box[1] - box[0] + FREE_GAP_MM
        y -= max(box[3] - box[2] for box in row) + FREE_GAP_MM
    return corners


def pair_label_of(force) -> str:
    return force.label


def _inside(label: str, links) -> bool:
    """Whether a reaction ``R_xy`` is between two links of the same free body (it cancels there)."""
    sub = label.partition("_")[2]
    names = sub.split(",") if "," in sub else list(sub)
    return len(names) == 2 and all(n in links for n in names)


def shoulders(equations, group: str, g) -> list[tuple[int, complex, complex, float, complex]]:
    """The arms h_k the moment equations of *group*'s plan use (*equations*: :class:`plans.forces.plan_equations.PlanEquations`
    of the plans), each ``(k, moment point [m], the force's line of action: a point [m] and its unit direction, the arm
    as the equation states it [m], the foot of the perpendicular [m])``; an arm of zero length (a force through the
    point) has no line to draw and is left out."""
    out = []
    for eq in equations:
        if eq.group != group:
            continue
        about = [(m.about, m.terms) for m in eq.moments] + ([(eq.pivot, eq.balancing)] if eq.pivot and eq.balancing else [])
        for name, terms in about:
            centre = complex(g.positions[name])
            for t in terms:
                if t.number is None or t.through is None or not t.arm:
                    continue
                u = complex(t.direction)
                foot = t.through + u * ((centre - t.through) * u.conjugate()).real
                if abs(centre - foot) > 1e-12:
                    out.append((t.number, centre, complex(t.through), float(t.arm), foot))
    return out


def _free_body(sketch: Sketch, forces, plan, links, shift: complex, acting, couples, lang: str, k_l: float, arms=()) -> None:
    """One free body: its links (a block as its body, a ram reaching to its centre of mass), then every arrow and couple,
    the arms of its moment equations (*arms*: :func:`shoulders`), and only then the labels, placed clear of all of them
    and of each other (as the plans place theirs)."""
    g = forces.graphical
    edge, _, fill = FIGURE_STYLE

    def at(z: complex) -> complex:
        return z / k_l + shift

    labels: list = []  # (anchor, pieces, keywords) placed after every mark is drawn
    segments: list[tuple[complex, complex]] = []  # the links drawn as bars [mm]
    blocks: dict[str, tuple[complex, float]] = {}  # a block's pin -> (centre, its half diagonal) [mm]
    labelled: set[str] = set()
    for body in links:
        names = list(g.scene.bodies[body].points)
        zs = [at(g.positions[n]) for n in names]
        block = g.scene.bodies[body].block
        if block or len(zs) == 1:
            centre = forces.centres.get(body)
            reach = _block(sketch, forces, body, zs[0], at, at(centre.at) if centre is not None else None)
            for n in names:
                blocks[n] = (zs[0], reach)
        else:
            far = max(((a, b) for a in zs for b in zs), key=lambda ab: abs(ab[0] - ab[1]))
            if len(zs) >= 3:
                sketch.polygon(_hull(zs), fc=fill, ec=INK, lw=1.4, gid=f"link-{body}", zorder=1.5)
                hull = _hull(zs)
                segments += [(hull[k], hull[(k + 1) % len(hull)]) for k in range(len(hull))]
            else:
                sketch.line(list(far), color=INK, lw=2.2, gid=f"link-{body}", zorder=1.5, capstyle="round")
                segments.append(far)
        for n, z in zip(names, zs):
            if n in labelled:
                continue
            labelled.add(n)
            if len(g.scene.bodies_with(n)) > 1:
                sketch.circle(z, 1.1, fc="white", ec=INK, lw=0.8, gid=f"pin-{n}", zorder=4.5)
            labels.append((z, [(n, f"point-{n}")], dict(size=LABEL_PT, gaps=(1.2, 2.2, 3.4, 5.0), leader_from=4.0)))
    for body in links:
        centre = forces.centres.get(body)
        if centre is not None:
            c = at(centre.at)
            sketch.circle(c, 1.0, fc="white", ec=INK, lw=0.7, gid=f"centre-{body}", zorder=4.6)
            sketch.polygon([c + 1.0, c + 1.0j, c - 1.0, c - 1.0j], fc=INK, ec=INK, lw=0.1, gid=f"centre-mark-{body}", zorder=4.7, obstacle=False)
            if not any(abs(centre.at - g.positions[n]) <= 1e-9 * (1 + abs(centre.at)) for n in g.scene.bodies[body].points):
                labels.append((c, [(centre_text(g.scene, body), f"centre-label-{body}")], dict(size=SMALL_PT, gaps=(1.4, 2.4, 3.6), leader_from=4.0)))
    drawn: list = []
    arrows = []  # [force, tail, tip, into, its point (beside a bar it lies along)] [mm]
    for f in acting:
        size = abs(f.force)
        if size == 0:
            continue
        u = f.force / size
        point = at(f.at)
        # a reaction points into its joint, unless a load's arrow from the same point lies there
        into = f.kind == "reaction" and not any(
            x.kind != "reaction" and abs(x.at - f.at) <= 1e-9 * (1 + abs(f.at)) and abs(x.force) > 0 and ((x.force / abs(x.force)) * u.conjugate()).real < -0.9
            for x in acting
        )
        # an arrow along a bar through its point would hide the bar: it is drawn beside it
        along = next((b - a for a, b in segments if _on_segment(point, a, b) and abs(((b - a) / abs(b - a) * u.conjugate()).imag) < 0.15), None)
        if along is not None:
            side = 1j * along / abs(along)
            point = point + side * BESIDE_BAR_MM
        if into:
            stop = 1.2
            near_block = next((b for n, b in blocks.items() if abs(at(g.positions[n]) - at(f.at)) < 1e-6), None)
            if near_block is not None:
                stop = near_block[1] + 0.4  # the head stays outside the block, its pin and letter in view
            tail, tip = point - u * (FREE_ARROW_MM + stop - 1.2), point - u * stop
        else:
            point = point + _beside(drawn, point, u)
            tail, tip = point, point + u * FREE_ARROW_MM
        arrows.append([f, tail, tip, into, point])
    # a reaction drawn into its joint across another arrow is drawn from the joint instead (the same force, its tail
    # at the point it acts at): no arrow crosses another's shaft, head or name
    for k, arrow in enumerate(arrows):
        f, tail, tip, into, point = arrow
        others = [(a[1], a[2]) for j, a in enumerate(arrows) if j != k]
        if into and _crossings((tail, tip), others):
            u = f.force / abs(f.force)
            start = point + _beside(drawn, point, u)
            out = (start + u * 1.2, start + u * (FREE_ARROW_MM + 1.2))
            if not _crossings(out, others):
                arrow[1:4] = [out[0], out[1], False]
    for f, tail, tip, into, point in arrows:
        u = f.force / abs(f.force)
        color, lw, dashes, head = FORCE_STYLE[f.kind]
        sketch.arrow(tail, tip, color=color, lw=lw, dashes=dashes, head=head, gid=f"force-{_gid(f.label)}", zorder=5.0, hollow=f.kind in FORCE_HOLLOW)
        sketch.obstacles.append(_segment_shape(tail, tip))
        end = tail if into else tip
        labels.append((end, [(force_math(f.label, lang), f"force-label-{_gid(f.label)}")],
                       dict(size=LABEL_PT, prefer=-u if into else u, gaps=(0.8, 1.8, 3.0, 4.5), mathtext=True, leader_from=4.0,
                            color=color if f.kind != "reaction" else INK)))
    shafts = [(a[1], a[2]) for a in arrows]
    for c in couples:
        if c.moment == 0:
            continue
        body_centre = forces.centres.get(c.body)
        if c.kind == "balancing" or body_centre is None:
            where = at(_pivot(g, c.body))
        else:
            where = at(body_centre.at)
        radii = (COUPLE_R_MM, COUPLE_R_MM * 0.75, COUPLE_R_MM * 1.4)
        near_block = next((b for b in blocks.values() if abs(b[0] - where) < b[1]), None)
        if near_block is not None:
            radii = (max(COUPLE_R_MM, abs(where - near_block[0]) + near_block[1] + 1.0),)  # round the block, not through it
        sweep = math.radians(250) * (1 if c.moment > 0 else -1)
        color = FORCE_STYLE["balancing" if c.kind == "balancing" else "inertia" if c.kind == "inertia" else "external"][0]
        # the arc crosses as few arrows as it can (an arrow from its own centre it may cross), at its usual radius
        # where that crosses no more; it starts (and its name stands) where it is farthest from the other points
        marks = [z for z, _, _ in labels if abs(z - where) > 1e-6]
        # an arrow at the arc's own centre it may cross (a textbook does), any other it keeps off; its head clear of both
        own = [s for s in shafts if min(abs(s[0] - where), abs(s[1] - where)) < 2.5]
        others = [s for s in shafts if s not in own]
        radius, start = max(((r, math.radians(145 + 15 * k)) for r in radii for k in range(24)),
                            key=lambda ra: (-_arc_crossings(where, ra[0], ra[1], sweep, others),
                                            _ends_clear(where, ra[0], ra[1], sweep, shafts + segments),
                                            -_arc_crossings(where, ra[0], ra[1], sweep, own), ra[0] == radii[0],
                                            round(min((abs(where + (ra[0] + 3.0) * cmath.exp(1j * ra[1]) - z) for z in marks), default=0.0), 1),
                                            -abs(ra[1] - math.radians(145))))
        sketch.arc_arrow(where, radius, start, sweep, color=color, lw=0.9, gid=f"couple-{_gid(c.label)}")
        labels.append((where + radius * cmath.exp(1j * start), [(force_math(c.label, lang), f"couple-label-{_gid(c.label)}")],
                       dict(size=LABEL_PT, prefer=cmath.exp(1j * start), gaps=(0.8, 1.8, 3.0), mathtext=True, leader_from=4.0, color=color)))
    inner = sum(at(g.positions[n]) for body in links for n in g.scene.bodies[body].points) / max(1, sum(len(g.scene.bodies[body].points) for body in links))
    for number, centre, through, arm, foot in arms:
        c, f, p = at(centre), at(foot), at(through)
        if abs(c - f) < SHOULDER_MIN_MM:  # too short to draw as a line (the equation still names it)
            continue
        color, lw, _ = CONSTRUCTION_STYLE
        # the line of action, dotted, from the force's point to the foot; the arm itself thin and solid, square to it
        if abs(f - p) > 0.3:
            sketch.line([p, f], color=color, lw=lw * 0.8, dashes=(1.0, 1.5), gid=f"action-h{number}", zorder=1.0, obstacle=False)
        sketch.line([c, f], color=INK, lw=SHOULDER_PT, gid=f"arm-h{number}", zorder=1.2)
        d = (c - f) / abs(c - f)
        e = unit(p - f) if abs(p - f) > 1e-9 else d * 1j
        mark = min(1.4, abs(c - f) / 3)
        sketch.line([f + d * mark, f + (d + e) * mark, f + e * mark], color=INK, lw=SHOULDER_PT * 0.8, gid=f"arm-square-h{number}", zorder=1.2, obstacle=False)
        mm = arm / k_l  # its length on this drawing, as the equation's arm [m] gives it at the drawing's k_l
        text = f"$h_{{{number}}}$ = {localised(f'{mm:.1f}', lang)} mm"
        across = d * 1j if ((inner - (c + f) / 2) * (d * 1j).conjugate()).real >= 0 else -d * 1j  # towards the body: kept in its box
        labels.append(((c + f) / 2, [(text, f"arm-label-h{number}")],
                       dict(size=SMALL_PT, prefer=across, gaps=(0.6, 1.4, 2.4, 3.6, 5.0), mathtext=True, leader_from=4.0, own=(c, f))))
    for anchor, pieces, options in labels:
        place_label(sketch, anchor, pieces, **options)


#: the line width [pt] of an arm h drawn on a free body (thin: a dimension, not a part)
SHOULDER_PT = 0.5
#: an arm shorter than this on the drawing [mm] is not drawn (a line that short does not read; its force all but
#: passes through the point)
SHOULDER_MIN_MM = 1.0


def lever_image_text(label: str, scene) -> str:
    """An image's label on the lever as the pages print it: a centre's image ``"s3"`` as the scene's centres are
    written (:func:`plans.forces.notation.plain_centres`: s3 beside the scene's S3, else s₃), any other image as
    the plans print it."""
    from .plan_drawing import image_text

    if plain_centres(scene) and re.fullmatch(r"s\d+", label.rstrip("′")):
        return label
    return image_text(label)


def _crossings(segment: tuple[complex, complex], others, clearance: float = 1.2) -> int:
    """How many of the arrows *others* (tail, tip) [mm] the arrow *segment* comes within *clearance* of (a head's
    half width and a little: a shaft through a head counts), an arrow from the same point excepted."""
    a, b = segment
    line = _segment_shape(a, b).buffer(clearance)
    return sum(1 for p, q in others if abs(p - a) > 0.5 and line.intersects(_segment_shape(p, q)))


def _arc_crossings(centre: complex, radius: float, start: float, sweep: float, arrows) -> int:
    """How many arrows (tail, tip) [mm] a couple's arc about *centre* from *start* turning *sweep* [rad] meets."""
    from shapely.geometry import LineString

    zs = [centre + radius * cmath.exp(1j * (start + sweep * k / 24)) for k in range(25)]
    arc = LineString([(z.real, z.imag) for z in zs]).buffer(0.8)
    return sum(1 for p, q in arrows if arc.intersects(_segment_shape(p, q)))


def _ends_clear(centre: complex, radius: float, start: float, sweep: float, lines, clearance: float = 2.4) -> bool:
    """Whether both ends of a couple's arc about *centre* (its tail, and its head from base to point and a head's length on) stand *clearance* [mm] off every one of
    *lines* (tail, tip) [mm]: the arrows and the bars (an arc crosses an arrow from its own centre; its head never
    lands on one)."""
    from shapely.geometry import LineString, Point

    head = min(abs(sweep) * 0.4, 2.6 / radius) * (1 if sweep > 0 else -1)  # the head's turn (Sketch.arc_arrow's 2.6 mm head)
    ends = [centre + radius * cmath.exp(1j * a) for a in (start, start + sweep + 1.5 * head, start + sweep + head, start + sweep, start + sweep - head, start + sweep - 1.5 * head)]
    return all(LineString([(p.real, p.imag), (q.real, q.imag)]).distance(Point(z.real, z.imag)) >= clearance for z in ends for p, q in lines)


def _on_segment(z: complex, a: complex, b: complex, tolerance: float = 0.3) -> bool:
    """Whether *z* lies on the segment a–b (within *tolerance* mm)."""
    d = b - a
    if abs(d) < 1e-9:
        return False
    t = ((z - a) * d.conjugate()).real / abs(d) ** 2
    return -0.01 <= t <= 1.01 and abs(z - (a + t * d)) <= tolerance


def _segment_shape(a: complex, b: complex):
    from shapely.geometry import LineString

    return LineString([(a.real, a.imag), (b.real, b.imag)]).buffer(0.3)


def _pivot(g, body: str) -> complex:
    """The crank's pivot, or the body's first point [m]."""
    driver = g.scene.driver
    if body == driver.link and hasattr(driver, "pivot"):
        return g.positions[driver.pivot]
    return g.positions[next(iter(g.scene.bodies[body].points))]


def _block(sketch: Sketch, forces, body: str, centre: complex, at, mass_centre: complex | None = None) -> float:
    """A slider block: a rectangle along the line it slides on, reaching to its centre of mass *mass_centre* [mm]
    when that lies off the block (a ram); returns the largest distance [mm] from *centre* to a corner."""
    g = forces.graphical
    scene = g.scene
    angle = g.poses[body][0]
    for p in scene.prismatics:
        if body in (p.slider, p.guide):
            line = scene.line(f"{p.guide}.{p.guide_line}")
            angle = g.poses[p.guide][0] + line.angle
            break
    u = cmath.exp(1j * angle)
    w, h = 4.5, 2.7
    x0, x1, y0, y1 = -w, w, -h, h
    if mass_centre is not None:
        local = (mass_centre - centre) / u
        x0, x1 = min(x0, local.real - 3.0), max(x1, local.real + 3.0)
        y0, y1 = min(y0, local.imag - 2.5), max(y1, local.imag + 2.5)
    corners = [centre + u * complex(x, y) for x, y in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))]
    ram = mass_centre is not None and (x0, x1, y0, y1) != (-w, w, -h, h)
    # a ram reaching to its centre of mass is drawn open, the bars it carries seen through it
    sketch.polygon(corners, fc="none" if ram else "white", ec=INK, lw=1.0 if ram else 1.2, gid=f"link-{body}", zorder=1.4 if ram else 1.6)
    return max(abs(z - centre) for z in corners) if mass_centre is None else math.hypot(w, h)


def _hull(zs):
    from shapely.geometry import MultiPoint

    hull = MultiPoint([(z.real, z.imag) for z in zs]).convex_hull
    if hull.geom_type != "Polygon":
        return zs
    return [complex(x, y) for x, y in list(hull.exterior.coords)[:-1]]


# --- all the drawings of a position ------------------------------------------------------


def force_figures(forces, *, lang: str = "en", lever=None, names: dict | None = None) -> list[tuple[str, object]]:
    """Every kinetostatic drawing of one position as ``(name, Figure)``.

    ``free-bodies``, ``force-plan-1`` … (one per group, in construction
    order: the last group first), ``force-plan-driver``, and ``lever`` when
    Joukowski's lever (:func:`plans.forces.lever.joukowski_lever`) is given.  *names*: group -> its words
    (``"group 3–4"``), written over its free body and in its plan's heading.
    """
    out = [("free-bodies", draw_free_bodies(forces, lang=lang, names=names)[0].figure)]
    found_at = found_scales(forces.plans)
    given = given_loads(forces)
    number = 0
    for plan in forces.plans:
        if plan.group == "driver":
            name = "force-plan-driver"
            artists = draw_force_plan(plan, lang=lang, balancing_moment=forces.balancing_moment, found_at=found_at, given=given, names=names)
        else:
            number += 1
            name = f"force-plan-{number}"
            artists = draw_force_plan(plan, lang=lang, found_at=found_at, given=given, names=names)
        out.append((name, artists[0].figure))
    if lever is not None:
        out.append(("lever", draw_lever(lever, lang=lang)[0].figure))
    return out


def force_drawing_files(forces, directory, *, lang: str = "en", formats=("svg",), lever=None, names: dict | None = None) -> dict[Path, bytes]:
    """The files of :func:`force_figures` in *directory* (``NAME.FORMAT`` for each of *formats*), rendered, not written."""
    from .formats import render

    directory = Path(directory)
    contents: dict[Path, bytes] = {}
    for name, fig in force_figures(forces, lang=lang, lever=lever, names=names):
        for fmt in formats:
            contents[directory / f"{name}.{fmt}"] = render(fig, fmt)
    return contents


def write_force_drawings(forces, directory, *, lang: str = "en", formats=("svg",), lever=None) -> list[Path]:
    """Write every drawing of :func:`force_figures` into *directory*, in each of *formats*, all or none.

    Returns the files written.
    """
    from .._files import replace_all

    return replace_all(force_drawing_files(forces, directory, lang=lang, formats=formats, lever=lever))


# --- Joukowski's lever ---------------------------------------------------------------------

#: Length of every force arrow on the lever [mm] (not to scale: the moments are what count).
LEVER_ARROW_MM = 12.0
#: An arm shorter than this [mm] is not drawn (its line would hide under the arrows).
ARM_MIN_MM = 0.5
#: The gap [mm] between two arrows along one line at one image (the second starts past the first one's head).
LEVER_GAP_MM = 2.0

#: the lever's load kinds (plans.forces.loads.LOAD_KINDS, "balancing") -> force style
_LEVER_KIND = {
    "weight": "weight",
    "inertia force": "inertia",
    "inertia couple": "inertia",
    "force": "external",
    "resistance": "external",
    "moment": "external",
    "balancing": "balancing",
}


def draw_lever(lever, ax=None, *, lang: str = "en") -> list:
    """Joukowski's lever (:class:`plans.forces.lever.JoukowskiLever`), one data unit = 1 mm of the velocity plan.

    The velocity plan turned by 90° (its images and link figures), every
    load as an arrow at the turned image of its point (parallel to the load;
    an inertia couple as its pair of forces), the balancing force F_b heavy,
    each force's arm from the pole p as a thin line to the foot of the
    perpendicular; under it the moments about the pole and M_b.
    """
    return sketch_on(ax, "lever", lambda sketch: draw_lever_into(sketch, lever, lang=lang))


def draw_lever_into(sketch: Sketch, lever, *, lang: str = "en", caption: bool = True) -> None:
    """Draw the lever into *sketch* (see :func:`draw_lever`)."""
    edge, lw_figure, fill = FIGURE_STYLE
    images = {k: complex(z) for k, z in lever.images.items()}
    for link, labels in lever.links.items():
        pts = []
        for label in labels:
            z = images.get(label)
            if z is not None and all(abs(z - q) > 1e-6 for q in pts):
                pts.append(z)
        if len(pts) >= 3:
            hull = _hull(pts)
            if len(hull) >= 3:
                sketch.polygon(hull, fc=fill, ec=edge, lw=lw_figure, gid=f"figure-{link}", zorder=0.8, obstacle=False)
                continue
        if len(pts) >= 2:
            a, b = max(((q, r) for q in pts for r in pts), key=lambda qr: abs(qr[0] - qr[1]))
            sketch.line([a, b], color=edge, lw=1.2, gid=f"figure-{link}", zorder=1.5)
    everything = list(lever.forces) + [lever.balancing_force]
    for f in everything:
        size = abs(f.force)
        if size == 0:
            continue
        if abs(f.arm) >= ARM_MIN_MM:
            color, lw, dashes = CONSTRUCTION_STYLE
            sketch.line([0j, complex(f.foot)], color=color, lw=lw, dashes=dashes, gid=f"arm-{_gid(f.name)}", zorder=1.0, obstacle=False)
            # the line of action through the point, as far as the foot
            sketch.line([complex(f.point), complex(f.foot)], color=color, lw=lw * 0.8, dashes=(1.0, 1.5), gid=f"action-{_gid(f.name)}", zorder=1.0, obstacle=False)
    sketch.circle(0j, 0.6, fc=INK, lw=0, gid="pole", zorder=4.0)
    for label, z in images.items():
        if abs(z) > 1e-6:
            sketch.circle(z, 0.45, fc=INK, lw=0, gid=f"dot-{label}", zorder=4.0, obstacle=False)
    names = lever_names(lever)
    tips: list[complex] = []
    for f in everything:
        size = abs(f.force)
        if size == 0:
            tips.append(complex(f.point))
            continue
        kind = _LEVER_KIND.get(f.kind, "external")
        color, lw, dashes, head = FORCE_STYLE[kind]
        u = f.force / size
        tail = complex(f.point)  # on a lever an arrow's place is its arm: every arrow starts at its point's image
        # an arrow along one drawn before at the same image (Φ₄ and F_пс at b) starts past that one's head, on its own
        # line of action through the image (its arm unchanged): each arrow, head and name reads by itself, none over another
        def same_line(g) -> bool:
            return bool(abs(g.force)) and abs(complex(g.point) - tail) < 0.5 and (g.force / abs(g.force) * u.conjugate()).real > 0.98

        along = sum(1 for g, t in zip(everything, tips) if same_line(g))
        # the arrows of one line share the length one arrow and a half would take (the drawing no larger for them)
        count = sum(1 for g in everything if same_line(g))
        length = (LEVER_ARROW_MM * (1 + 0.55 * (count - 1)) - LEVER_GAP_MM * (count - 1)) / count
        if along:
            color_line, lw_line, _ = CONSTRUCTION_STYLE  # the line of action from the image to the arrow, as the arms' lines
            start = tail + u * (length + LEVER_GAP_MM) * along
            sketch.line([tail, start], color=color_line, lw=lw_line * 0.8, dashes=(1.0, 1.5), gid=f"along-{_gid(names[id(f)])}",
                        zorder=1.0, obstacle=False)
            tail = start
        tip = tail + u * length
        tips.append(tip)
        sketch.arrow(tail, tip, color=color, lw=lw, dashes=dashes, head=head, gid=f"force-{_gid(names[id(f)])}", zorder=5.0, hollow=kind in FORCE_HOLLOW)
    groups: list[tuple[complex, list[tuple[str, str]]]] = [(0j, [("p", "pole-label")])]
    for label, z in images.items():
        for at, pieces in groups:
            if abs(at - z) <= 1e-3:
                pieces.append((lever_image_text(label, lever.scene), f"image-{label}"))
                break
        else:
            groups.append((z, [(lever_image_text(label, lever.scene), f"image-{label}")]))
    for at, pieces in groups:
        rivals = tuple(q for q, _ in groups if q != at)
        place_label(sketch, at, pieces, size=LABEL_PT, gaps=GAPS, leader_from=4.0, rivals=rivals)
    for f, tip in zip(everything, tips):
        if abs(f.force) == 0:
            continue
        u = f.force / abs(f.force)
        kind = _LEVER_KIND.get(f.kind, "external")
        place_label(sketch, tip, [(force_math(names[id(f)], lang), f"force-label-{_gid(names[id(f)])}")], size=LABEL_PT,
                    prefer=u, gaps=(0.8, 1.8, 3.0, 4.5), mathtext=True, leader_from=4.0, color=FORCE_STYLE[kind][0] if kind != "reaction" else INK)
    if caption:
        _lever_caption(sketch, lever, lang)


def driving_link_words(link: str, crank: bool, lang: str) -> str:
    """``"driving link 2 (crank)"`` in *lang* (``(slider)`` for a linear driver)."""
    return term("driving_link", lang).format(link=link, kind=term("crank_kind" if crank else "slider_kind", lang))


def _is_crank(scene) -> bool:
    from ..scene import Crank

    return isinstance(scene.driver, Crank)


def sense_arrow(value: float) -> str:
    """The sense of a moment as the arc arrow the plans draw for ω and ε: ``" ↺"`` counter-clockwise (> 0), ``" ↻"`` clockwise."""
    return "" if value == 0 else (" ↺" if value > 0 else " ↻")


def couple_pair_name(name: str, second: bool) -> str:
    """The name of one force of the pair that stands for a couple: ``"M_Φ3"`` → ``"F′_Φ3"``, ``"F″_Φ3"``."""
    mark = "″" if second else "′"
    head, sep, sub = name.partition("_")
    if head == "M":
        return f"F{mark}{sep}{sub}"
    return f"{head}{mark}{sep}{sub}"


def lever_names(lever) -> dict[int, str]:
    """id(force) -> the name written at it: a couple's pair as F′, F″ (its first and second point), the rest by their own name."""
    names: dict[int, str] = {}
    seen: dict[str, int] = {}
    for f in list(lever.forces) + [lever.balancing_force]:
        if f.kind in ("inertia couple", "moment"):
            names[id(f)] = couple_pair_name(f.name, seen.get(f.name, 0) > 0)
            seen[f.name] = seen.get(f.name, 0) + 1
        else:
            names[id(f)] = f.name
    return names


def _lever_caption(sketch: Sketch, lever, lang: str) -> None:
    """Heading, k_v, what the lever is, the moments about the pole (F, h, F·h), F_b and M_b."""
    b = sketch.bounds
    x, y = b.xmin, b.ymin - 3.0
    sketch.text(complex(x, y), term("joukowski_lever", lang), size=HEADING_PT, ha="left", va="top", weight="bold", gid="heading", obstacle=False)
    y -= 5.0
    row = text_size("lp", CAPTION_PT)[1] + 0.9
    sketch.text(complex(x, y), scale_caption("k_v", fmt_number(lever.k_v), "(m/s)/mm", lang) + ";", size=CAPTION_PT, ha="left", va="top", gid="scale",
                obstacle=False, math=True)
    y -= row
    sketch.text(complex(x, y), term("lever_turned_ccw", lang), size=CAPTION_PT, ha="left", va="top", gid="turn", obstacle=False)
    y -= row + 0.6
    sketch.text(complex(x, y), r"$\Sigma M_{\mathrm{p}} = \Sigma F \cdot h + " + force_math("F_b", lang)[1:-1] + r" \cdot " + force_math("h_b", lang)[1:-1] + " = 0$",
                size=CAPTION_PT, ha="left", va="top", gid="equation", obstacle=False, math=True)
    y -= row
    color, lw, dashes = CONSTRUCTION_STYLE  # the legend of the arm lines drawn from p
    middle = y - text_size("lp", CAPTION_PT)[1] / 2
    sketch.line([complex(x, middle), complex(x + 8.0, middle)], color=color, lw=lw, dashes=dashes, gid="legend-arm", obstacle=False)
    sketch.text(complex(x + 10.0, y), term("lever_arm_rule", lang), size=CAPTION_PT, ha="left", va="top", gid="arm-rule", obstacle=False)
    names = lever_names(lever)
    moments = {(load.name, load.body): float(load.moment) for load in lever.loads if load.is_couple}
    pairs: dict[tuple[str, str], list] = {}
    for f in lever.forces:
        if f.kind in ("inertia couple", "moment"):
            pairs.setdefault((f.name, f.body), []).append(f)
    for f in list(lever.forces) + [lever.balancing_force]:
        if abs(f.force) == 0:
            continue
        y -= row
        arm = f.arm if abs(f.arm) >= 0.05 else 0.0  # no "−0.0"
        h = localised(f"{arm:.1f}", lang) + " mm"
        if arm < 0:
            h = f"({h})"
        name = force_math(names[id(f)], lang)
        given = f"{name}: {_number(abs(f.force), lang)} N"
        pair = pairs.get((f.name, f.body), [])
        if len(pair) == 2 and (f.name, f.body) in moments:
            ends = [q.image.upper() for q in pair]
            couple = moments[(f.name, f.body)]
            length = abs(couple) / abs(f.force)  # the distance between the pair's points [m]
            given = (f"{name} = {force_math(f.name, lang)}/$l_{{\\mathrm{{{_escape(''.join(ends))}}}}}$ = {_number(abs(couple), lang)} N·m / "
                     f"{localised(f'{length:.4g}', lang)} m = {_number(abs(f.force), lang)} N ({f.image}"
                     + (f"; {term('lever_pair', lang).format(points=', '.join(q.image for q in pair))})" if f is pair[0] else ")"))
        line = f"{given} · {h} = {_number(f.moment, lang)} N·mm"
        sketch.text(complex(x, y), line, size=CAPTION_PT, ha="left", va="top", gid=f"moment-{_gid(names[id(f)])}", obstacle=False, math=True)
    for c in lever.couples:
        y -= row
        sketch.text(complex(x, y), f"{force_math(c.name, lang)} = {_number(c.couple, lang)} N·m → {_number(c.moment, lang)} N·mm ({term('lever_block_couple', lang)})",
                    size=CAPTION_PT, ha="left", va="top", gid=f"moment-{_gid(c.name)}", obstacle=False, math=True)
    y -= row
    if lever.balancing_kind == "moment":
        result = (f"{force_math('M_b', lang)} = {force_math('F_b', lang)}·$l_{{\\mathrm{{OA}}}}$ = {_number(abs(lever.balancing_force.force), lang)} N · "
                  f"{localised(f'{lever.crank_length:.4g}', lang)} m = {_number(abs(lever.balancing), lang)} N·m{sense_arrow(lever.balancing)} ({_lower(term('balancing_moment', lang))}, {term('from_lever', lang)})")
    else:
        result = f"{force_math('F_b', lang)} = {_number(lever.balancing, lang)} N ({_lower(term('balancing_force', lang))}, {term('from_lever', lang)})"
    sketch.text(complex(x, y), result, size=CAPTION_PT, ha="left", va="top", gid="result", obstacle=False, math=True)
