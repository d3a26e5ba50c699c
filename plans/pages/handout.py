"""The handout as the course project's plate, set by Typst (:mod:`plans.pages.typesetting`).

What the handout holds, in the order a student draws the plate (domain.md §10):

1. the data, the structural formula, the assembly of the groups and the
   plan of positions (every position at one k_l, the paths of the points);
2. the vector equations of the velocity plans, the known parts underlined;
3. the velocity plans of every position at one k_v, each from its own pole,
   two across a page; when only a few positions' plans are far larger than
   the rest (a quick return), those take a row of their own and k_v is the
   one with which the largest fills that row, so that the rest are drawn
   large enough to measure;
4. the vector equations of the acceleration plans and the acceleration
   plans of the chosen positions (by default two: one of the working and one
   of the idle stroke) at one k_a;
5. the tables comparing the graphical values with the analytic ones (the
   graphical accelerations only of the positions whose acceleration plans
   are drawn: the others' tables hold their velocities), and
   the complex-number loop equations of the chosen positions;
6. the kinematic diagrams over the cycle; with ``centres``, the method's
   page (Kennedy's theorem, the circle diagram once, the rules, the order of
   finding the centres) and a page of instant centres for every position,
   all at one k_l (the plate's, or the coarsest any of them needs), which
   their title block states.

One k_l, one k_v, one k_a over the whole handout (each the round factor
with which the largest of its drawings fills the room a page gives it; a
factor the user or the scene gives is kept); ``scales="per-position"``
gives each position its own k_v and k_a, and says so.  Every page has a
frame with a binding margin and a title block: plate name, scales, sheet
n of m, drawn by / checked by / date.

The drawings are matplotlib SVG blocks of known size
(:mod:`plans.drawing.svgblocks`) placed at 100 %; everything else — text,
tables, equations, headings, pagination — is Typst's.  A page in another
language than English holds no English word: the scene's title and names are
taken in the page's language where the scene gives them
(:mod:`plans.pages.words`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace

from ..graphical.scales import round_up
from ..i18n import term
from .document import A4_PORTRAIT, Document, GUTTER, HEADING_ABOVE, SMALL_PT, TEXT_PT
from .document import bbox as _bbox, fitted as _fitted, plan_extent as _plan_extent
from .equations import placement_rows
from .typesetting import compile_document
from .words import assembly_lines, formula_words, namer

__all__ = ["Handout", "build_handout", "position_entry", "angles_key", "ORDER", "ACCELERATIONS_DEFAULT", "DIAGRAM_PAGE", "TEXT_WIDTH", "TEXT_HEIGHT"]

#: The sections of a multi-position handout, in the plate's order (names as :attr:`Handout.order` lists them).
ORDER = ("data", "positions", "velocity-equations", "velocity-plans", "acceleration-equations", "acceleration-plans",
         "tables", "loops", "diagrams", "forces", "centres")
#: How many acceleration plans a handout draws unless asked: one of the working stroke, one of the idle.
ACCELERATIONS_DEFAULT = 2
#: A stroke's acceleration plan is chosen among its positions this far into it (not at a dead centre, where
#: components vanish)...
STROKE_INNER = (0.15, 0.85)
#: ...among those whose plan reads at least this share as well as the stroke's best (:func:`plan_readability`), the
#: one nearest the stroke's middle.
READABLE_SHARE = 0.5

# the text area of the handout's A4 page [mm]
TEXT_WIDTH, TEXT_HEIGHT = A4_PORTRAIT.text_width, A4_PORTRAIT.text_height
#: the boxes [mm] the drawings are fitted to: the plan of positions (under the data), a velocity plan
#: (two across, three down a page; one position's larger); the acceleration plans' cells: :func:`_acceleration_cells`
POSITIONS_BOX = (TEXT_WIDTH, 150.0)
VELOCITY_CELL = ((TEXT_WIDTH - GUTTER) / 2, 70.0)
#: a velocity plan too large for a half cell at the plate's k_v takes a row of its own (three rows to a page)
VELOCITY_WIDE = (TEXT_WIDTH, 80.0)
#: the white margin [mm] of a velocity plan in a row of its own: the text area's edges are its frame (a half cell's
#: plan keeps the drawings' margin, which parts it from its neighbour)
WIDE_MARGIN = 1.0
#: at most this share of the positions may take a row of their own (else every plan goes two across, the
#: largest filling a half cell): the wide rows are for the few positions whose plans are large
WIDE_SHARE = 1 / 3
#: room [mm] a centres page keeps for its heading (one line), the legend (two lines), the rules (two) and the gaps;
#: its table takes CENTRES_ROW a row, and the drawing the rest, at most CENTRES_DRAWING_MAX
CENTRES_PAGE_TEXT = 30.0
CENTRES_ROW = 4.2
CENTRES_DRAWING_MAX = 185.0
#: the page of cycle diagrams [mm]: the text area (a little short of it), so that it prints at 100 %, its 8 pt type 8 pt
DIAGRAM_PAGE = (TEXT_WIDTH, TEXT_HEIGHT - 4.0)


@dataclass
class Handout:
    """A handout ready to compile: Typst source, the SVG inputs, and what it holds (for callers and tests).

    Attributes
    ----------
    source : str
        The Typst document.
    images : dict[str, bytes]
        Input key -> SVG of a drawing (placed at its physical size).
    scales : dict[str, float]
        The plate's k_l, k_v, k_a (per position: ``per_position``).
    per_position : dict[int, dict[str, float]]
        Position index -> its scale factors (the same for all unless ``scales="per-position"``).
    order : list[str]
        The sections in the order they are set (names of :data:`ORDER`).
    accelerations : list[int]
        The positions whose acceleration plans are drawn.
    drawn : dict[str, tuple[float, float]]
        Input key -> size [mm] of the drawing.
    """

    source: str
    images: dict[str, bytes]
    scales: dict[str, float]
    per_position: dict[int, dict[str, float]] = field(default_factory=dict)
    order: list[str] = field(default_factory=list)
    accelerations: list[int] = field(default_factory=list)
    drawn: dict[str, tuple[float, float]] = field(default_factory=dict)
    runs: list = field(default_factory=list, repr=False)

    def pdf(self) -> bytes:
        """The handout as one PDF (deterministic)."""
        return compile_document(self.source, self.images, "pdf")

    def pages(self, fmt: str = "svg", ppi: float = 110.0) -> list[bytes]:
        """The handout as SVG or PNG pages."""
        return compile_document(self.source, self.images, fmt, ppi=ppi)


# --- scales -------------------------------------------------------------------------------------


# --- the handout --------------------------------------------------------------------------------


def _output_sense(run) -> float:
    """The sense of the output's motion at a position: the velocity of the last group's slider along its frame
    guide, else ω of the last group's link; 0 when it is at rest."""
    from ..scene import FRAME as GROUND

    a = run.analytic
    groups = a.structure.groups
    if not groups:
        return 0.0
    last = groups[-1]
    for p in run.scene.prismatics:
        if GROUND in (p.slider, p.guide) and (p.slider in last.links or p.guide in last.links) and p.name in a.sliders:
            return float(a.sliders[p.name].v_rel[0])
    for link in last.links:
        motion = a.links.get(link)
        if motion is not None and not run.scene.bodies[link].block:
            return float(motion.omega[0])
    return 0.0


def stroke_phases(run) -> dict[int, tuple[str, float]]:
    """Position index -> (``"working"`` or ``"idle"``, how far into that stroke, 0…1), for a crank turning fully
    under a turning law (:class:`plans.motion.Strokes`: the working stroke starts at the output's extreme
    position 0 and runs the working arc in the sense of motion); empty where the strokes are not known so
    (a rocker input, a linear driver): then the sense of the output's motion tells them apart."""
    import math as m

    st = getattr(run, "strokes", None)
    if st is None or not st.law.crank or st.law.kind == "harmonic" or not (st.working_arc > 0 and st.return_arc > 0):
        return {}
    out = {}
    turn = 2 * m.pi
    for r in run.runs:
        if not r.ok:
            continue
        phase = ((float(r.position) - st.law.x0) * st.law.sense) % turn
        into = (phase - st.start_phase) % turn
        if into < st.working_arc:
            out[r.index] = ("working", into / st.working_arc)
        else:
            out[r.index] = ("idle", (into - st.working_arc) / st.return_arc)
    return out


def plan_readability(plan) -> float:
    """How well a plan's construction reads [1]: its shortest component (relative, normal, tangential, Coriolis) over
    its longest vector; 1 for a plan of absolute vectors alone.  Near 0 the plan collapses onto a line and its
    components cannot be measured (the quick-return's lever upright at mid-stroke: π a₄′ along π d′, the Coriolis
    component 0.003 of the plan)."""
    longest = max((v.value for v in plan.vectors), default=0.0)
    components = [v.value for v in plan.vectors if v.kind != "absolute"]
    if not components or longest <= 0.0:
        return 1.0
    return min(components) / longest


def choose_accelerations(run, asked) -> list[int]:
    """The indices of the positions whose acceleration plans are drawn.

    *asked*: ``"all"``, a list of indices, or None — then two: one of the
    working stroke and one of the idle stroke (:func:`stroke_phases`), each the
    position nearest the stroke's middle among those whose plan reads
    (:data:`STROKE_INNER`, :data:`READABLE_SHARE`, :func:`plan_readability`:
    not where the plan collapses onto a line); without them, the strokes told
    apart by the sense of the output's motion, the working one the longer
    run of positions); one of each third when the output never turns back,
    and for a sliding driver (its cycle is its stroke, one way: no idle stroke).
    """
    runs = run.runs
    solved = [r for r in runs if r.ok and r.graphical is not None and r.graphical.acceleration_plan is not None]
    if asked == "all":
        return [r.index for r in solved]
    if asked is not None:
        known = {r.index for r in solved}
        unknown = [k for k in asked if k not in known]
        if unknown:
            from ..errors import PlansError

            raise PlansError(f"accelerations: position {unknown[0]} is not one of the handout's solved positions "
                             f"({', '.join(str(k) for k in sorted(known)) or 'none'}); give 'all' or some of those")
        return list(dict.fromkeys(asked))
    if len(solved) <= ACCELERATIONS_DEFAULT:
        return [r.index for r in solved]
    if not _turning_driver(run):  # a sliding driver's cycle is its stroke, one way: two positions along it
        return [solved[len(solved) // 3].index, solved[(2 * len(solved)) // 3].index]
    phases = stroke_phases(run)
    if phases:
        chosen = []
        for stroke in ("working", "idle"):
            here = [r for r in solved if phases.get(r.index, ("", 0))[0] == stroke]
            inner = [r for r in here if STROKE_INNER[0] <= phases[r.index][1] <= STROKE_INNER[1]] or here
            if inner:
                reads = {r.index: plan_readability(r.graphical.acceleration_plan) for r in inner}
                readable = [r for r in inner if reads[r.index] >= READABLE_SHARE * max(reads.values())]
                chosen.append(min(readable, key=lambda r: abs(phases[r.index][1] - 0.5)).index)
        if len(chosen) == 2:
            return sorted(chosen)
    plus = [r for r in solved if _output_sense(r) > 0]
    minus = [r for r in solved if _output_sense(r) < 0]
    strokes = sorted([s for s in (plus, minus) if s], key=len, reverse=True)
    if len(strokes) < 2:
        return [solved[len(solved) // 3].index, solved[(2 * len(solved)) // 3].index]
    return sorted(s[len(s) // 2].index for s in strokes)


def _with_given_note(lines: list[str], run, lang: str) -> list[str]:
    """The cycle's *lines* with the scene's own ε (a) said to be its instant's only, under the law's lines, where
    the law does not keep it (:meth:`plans.motion.DriverLaw.given_note`): the data above give it, the law a = 0."""
    note = run.motion.law.given_note(lang, run.scene.driver.link) if run.motion is not None else ""
    if not note:
        return lines
    head = term("driver_law", lang)
    at = next((i for i, line in enumerate(lines) if line.startswith(head)), None)
    if at is None:
        return lines
    end = at + 1
    while end < len(lines) and lines[end].startswith("    "):  # the law's wrapped lines
        end += 1
    return lines[:end] + [f"    ({note})"] + lines[end:]


def _proportions(doc, line: str) -> str:
    """A line of :func:`plans.drawing.readings.similarity_lines` as markup: each proportion with its numbers one box
    (a line breaks between a triangle's two, never inside one: ``f₄′ k′ / f₄′ π =`` at a line's end)."""
    # (the semicolon escaped: right after "#box[…]" Typst reads a bare ";" as the end of the expression, not as text)
    return "\\;  ".join(f"#box[{doc.words(part)}]" for part in line.split(";  "))


def _equations_height(plan) -> float:
    """The height [mm] of a plan's vector equations under their heading (:meth:`Document.equations`), reckoned
    line by line."""
    return 16.0 + 6.4 * sum(len(step.equations) for step in plan.steps)


def _first_page_room(scene, lang: str, r) -> float:
    """The height [mm] the first page of a one-position handout leaves its mechanism: the text height less the
    data, the heading with k_l and the velocity equations under it, line by line (:data:`SINGLE_MECHANISM`)."""
    lines = len(data_lines(scene, lang)) + 2  # the data, the structural formula and the assembly
    return TEXT_HEIGHT - (12.0 + 5.0 * lines) - 14.0 - _equations_height(r.graphical.velocity_plan) - 8.0


def _reason(r, lang: str) -> str:
    """Why a position is not solved, in the reader's words and numbers, the group named as the course names it."""
    from ..i18n import reason_text
    from .words import group_words

    words = reason_text(str(r.error), lang, r.cause)
    return re.sub(r"\b[RP]{3}\([^,()]+,[^,()]+\)", lambda m: group_words(m.group(0), lang), words)


def angles_key(doc, plans) -> str:
    """What the angles in the plans' notes are measured from (``∠(pa) = 181,3°``: from the x axis, counter-clockwise),
    said once beside the plans' scale, as markup; empty when none of *plans* has such a note
    (:func:`plans.drawing.plan_drawing.alongside`)."""
    from ..drawing.plan_drawing import alongside

    if not any(alongside(plan) for plan in plans):
        return ""
    return doc.line_markup(";   " + term("angle_from_x", doc.lang), SMALL_PT)


def position_entry(r, lang: str, accelerated: bool = False, stroke: str = "") -> str:
    """One line of the positions' list: ``4:  φ₂ = 91,3°  (план убрзања — радни ход)``: a position whose acceleration
    plan is drawn says so (with its stroke, when known), an unsolved one says that."""
    entry = f"{r.index}:  {r.label}"
    if not r.ok:
        return entry + f"  ({term('not_solved', lang)})"
    if accelerated:
        plan = term("acceleration_plan", lang).lower()
        entry += f"  ({plan} — {stroke})" if stroke else f"  ({plan})"
    return entry


def _turning_driver(run) -> bool:
    """Whether the driver turns (a crank or a rocker): a sliding driver has a stroke, one way, and no working or idle stroke."""
    from ..scene import LinearDriver

    return not isinstance(run.scene.driver, LinearDriver)


def _stroke(r, working_sign: float, lang: str, phases=None) -> str:
    """The stroke a position is in, in words (empty when not known, or for a sliding driver: its cycle is one stroke)."""
    from ..scene import LinearDriver

    if isinstance(r.scene.driver, LinearDriver):
        return ""
    if phases and r.index in phases:
        return term("working_stroke" if phases[r.index][0] == "working" else "idle_stroke", lang)
    sense = _output_sense(r)
    if not sense or not working_sign:
        return ""
    return term("working_stroke" if sense * working_sign > 0 else "idle_stroke", lang)


def build_handout(
    scene,
    *,
    positions=None,
    lang: str = "en",
    k_l: float | None = None,
    k_v: float | None = None,
    k_a: float | None = None,
    precision: float | None = None,
    components: bool = False,
    progress=None,
    centres: bool = False,
    accelerations=None,
    scales: str = "plate",
    forces: bool = False,
    law: str | None = None,
    start: str = "output",
) -> Handout:
    """The handout of *scene* (see the module); arguments as :func:`plans.handout.write_handout`."""
    from ..compare import compare
    from ..graphical import construct
    from ..positions import at_page_precision, run_positions
    from ..drawing.readings import similarity_lines
    from ..drawing.svgblocks import legend_svg, mechanism_svg, plan_svg, positions_svg

    say = progress or (lambda words: None)
    scene = at_page_precision(scene, precision)
    given = {"k_l": k_l if k_l is not None else scene.scales.k_l,
             "k_v": k_v if k_v is not None else scene.scales.k_v,
             "k_a": k_a if k_a is not None else scene.scales.k_a}
    run = run_positions(scene, positions, k_l=given["k_l"], k_v=given["k_v"], k_a=given["k_a"], precision=None, law=law, start=start)
    # a frame guide (a ram's guideway) around the block's present place: the plan of positions draws the stroke
    run = replace(run, runs=tuple(
        replace(r, graphical=replace(r.graphical, travel={k: t for k, t in r.graphical.travel.items() if not k.startswith("frame.")}))
        if r.graphical is not None else r for r in run.runs))
    multi = positions is not None
    eq_under_v = True  # (one position: whether the acceleration equations go under the velocity plan)
    solved = [r for r in run.runs if r.ok]
    name = namer(scene, lang, "parallel")  # (the equations' guide names follow ∥)
    doc = Document(scene, lang)

    def at(r, ks):
        g = construct(r.scene, run.structure, k_l=ks["k_l"], k_v=ks["k_v"], k_a=ks.get("k_a"), precision=run.precision, check_scales=False)
        g = replace(g, travel=r.graphical.travel, cycle_poses=r.graphical.cycle_poses)
        return replace(r, graphical=g, comparisons=compare(r.analytic, g))

    def scaled(r, key, k):
        ks = dict(r.graphical.scales)
        ks[key] = k
        return at(r, ks)

    # --- one k_l: the plan of positions (one position: its mechanism) fills its box
    say(term("positions_plan" if multi else "mechanism", lang))
    if not solved:
        from ..errors import PlansError

        raise PlansError("no position of the handout could be solved: " + "; ".join(r.brief("en") for r in run.runs))
    k_l0 = solved[0].graphical.scales["k_l"]
    if multi:
        zs = [z for r in solved for z in r.graphical.positions.values()]
        import numpy as np

        for p in scene.report:
            if p in run.cycle.points:
                path = np.asarray(run.cycle.points[p].r)
                zs.extend(complex(z) for z in path[np.isfinite(path.real) & np.isfinite(path.imag)])
        extremes = run.other_extreme()
        zs += [z for g in extremes.values() for z in g.positions.values()]
        extent = _bbox(zs)
        k_l_plate, first = _fitted(lambda k: positions_svg(run, k, lang, extremes), extent, POSITIONS_BOX, k_l0, given["k_l"])
    else:
        # one position: each drawing a region of its own, drawn large: the mechanism under the data with the
        # velocity equations under it (page 1), the velocity plan (page 2), the acceleration plan with its equations
        # (page 3); each region's height reckoned from the text it shares its page with
        room = _first_page_room(scene, lang, solved[0])
        extent = _bbox(solved[0].graphical.positions.values())
        k_l_plate, first = _fitted(lambda k: mechanism_svg(scaled(solved[0], "k_l", k).graphical, lang), extent,
                                   (TEXT_WIDTH, min(max(room, SINGLE_MECHANISM[0]), SINGLE_MECHANISM[1])), k_l0, given["k_l"])
        # the velocity plan under the equations when page 1 leaves it room enough (a flat mechanism), else page 2
        room_v = room - first.height - VELOCITY_PAGE_TEXT
        if room_v < SINGLE_VELOCITY_MIN:
            room_v = TEXT_HEIGHT - VELOCITY_PAGE_TEXT
        velocity_alone = (TEXT_WIDTH, min(room_v, SINGLE_VELOCITY[1]))

    # --- one k_v over every position: the largest plan fills a cell
    cell_v = VELOCITY_CELL if multi else velocity_alone
    chosen = choose_accelerations(run, accelerations) if scene.accelerations else []
    phases = stroke_phases(run)
    accel_columns, cell_a = _acceleration_cells([r for r in solved if r.index in chosen])
    per_position = {}
    if scales == "per-position":
        for r in solved:
            ks = {"k_l": k_l_plate}
            ks["k_v"], _ = _fitted(lambda k, r=r: plan_svg(scaled(r, "k_v", k).graphical.velocity_plan, lang), _plan_extent(r.graphical.velocity_plan), cell_v, r.graphical.scales["k_v"], given["k_v"])
            if r.index in chosen:
                ks["k_a"], _ = _fitted(lambda k, r=r: plan_svg(scaled(r, "k_a", k).graphical.acceleration_plan, lang), _plan_extent(r.graphical.acceleration_plan), cell_a, r.graphical.scales["k_a"], given["k_a"])
            else:
                ks["k_a"] = r.graphical.scales.get("k_a")
            per_position[r.index] = ks
        plate = {"k_l": k_l_plate}
    else:
        largest_v = max(solved, key=lambda r: max(e / b for e, b in zip(_plan_extent(r.graphical.velocity_plan), cell_v)))
        k_v_plate, block_v = _fitted(lambda k: plan_svg(scaled(largest_v, "k_v", k).graphical.velocity_plan, lang), _plan_extent(largest_v.graphical.velocity_plan), cell_v, largest_v.graphical.scales["k_v"], given["k_v"])
        if not multi and chosen:
            # one position: the acceleration equations under the velocity plan when they fit there (its page then
            # holds both, the acceleration plan a page of its own), else on the acceleration plan's page
            eq_a = _equations_height(solved[0].graphical.acceleration_plan)
            eq_under_v = block_v.height + eq_a <= room_v - 10.0
            if not eq_under_v:
                cell_a = (TEXT_WIDTH, TEXT_HEIGHT - ACCELERATION_PAGE_TEXT - eq_a)
        if multi and given["k_v"] is None and len(solved) > 1:
            # the largest plan given a row of its own: kept when only a few plans need one (they are then far
            # larger than the rest, which a half cell would leave small)
            largest_wide = max(solved, key=lambda r: max(e / b for e, b in zip(_plan_extent(r.graphical.velocity_plan), VELOCITY_WIDE)))
            k_wide, _ = _fitted(lambda k: plan_svg(scaled(largest_wide, "k_v", k).graphical.velocity_plan, lang, margin=WIDE_MARGIN),
                                _plan_extent(largest_wide.graphical.velocity_plan), VELOCITY_WIDE, largest_wide.graphical.scales["k_v"], None)
            # the finest round factor (from the largest's row up) with which only a few need a row
            k = min(k_wide, round_up(k_v_plate / 2))
            while k < k_v_plate:
                if (k >= k_wide or not any(_wide(r.graphical.velocity_plan, k, VELOCITY_WIDE) for r in solved)) and \
                        sum(_wide(r.graphical.velocity_plan, k) for r in solved) <= WIDE_SHARE * len(solved):
                    k_v_plate = k
                    break
                k = round_up(k * 1.0001)
        plate = {"k_l": k_l_plate, "k_v": k_v_plate}
        accel = [r for r in solved if r.index in chosen]
        if accel:
            largest_a = max(accel, key=lambda r: max(e / b for e, b in zip(_plan_extent(r.graphical.acceleration_plan), cell_a)))
            plate["k_a"], _ = _fitted(lambda k: plan_svg(scaled(largest_a, "k_a", k).graphical.acceleration_plan, lang), _plan_extent(largest_a.graphical.acceleration_plan), cell_a, largest_a.graphical.scales["k_a"], given["k_a"])
        else:
            plate["k_a"] = solved[0].graphical.scales.get("k_a")
        per_position = {r.index: dict(plate) for r in solved}

    # --- every position at the plate's factors, its plans drawn
    # (a plan never runs out of its cell: one whose enlarged detail would is drawn without it, its notes kept;
    # one still too wide makes the factor of its kind coarser for every position, so that it stays one)
    here = {}
    velocity_blocks, acceleration_blocks = {}, {}

    def fitting(plan, cell, **margin):
        block = plan_svg(plan, lang, room=cell, **margin)  # (a small plan drawn again whole, enlarged, when its cell has room)
        # (a velocity plan too tall for its half cell takes a row of its own; an acceleration plan's cell is its room)
        def over(b) -> bool:
            return b.width > cell[0] + 0.5 or (plan.kind == "acceleration" and b.height > cell[1] + 0.5)

        if plan.kind == "acceleration":  # its crowd's detail under it where the plan has no room for it within
            under = plan_svg(plan, lang, room=cell, detail_under=True, **margin)
            if over(block) or (not over(under) and under.svg.count(b'-detail-ring') > block.svg.count(b'-detail-ring')):
                block = under
        if over(block):  # else none (its notes kept)
            block = plan_svg(plan, lang, detail=False, **margin)
        return block

    wide = set()  # the positions whose velocity plans take a row of their own
    for attempt in range(4):
        wider = {}
        wide = set()
        for n, r in enumerate(solved, start=1):
            say(f"{term('position', lang)} {n}/{len(solved)}")
            h = at(r, per_position[r.index])
            here[r.index] = h
            velocity_blocks[r.index] = fitting(h.graphical.velocity_plan, cell_v)
            block = velocity_blocks[r.index]
            if multi and scales != "per-position" and (block.width > cell_v[0] + 0.5 or block.height > cell_v[1] + 0.5):
                wide.add(r.index)
                velocity_blocks[r.index] = block = fitting(h.graphical.velocity_plan, VELOCITY_WIDE, margin=WIDE_MARGIN)
                if block.width > VELOCITY_WIDE[0] + 0.5:
                    wider["k_v"] = max(wider.get("k_v", 1.0), block.width / VELOCITY_WIDE[0])
            elif block.width > cell_v[0] + 0.5:
                wider["k_v"] = max(wider.get("k_v", 1.0), block.width / cell_v[0])
            if r.index in chosen and h.graphical.acceleration_plan is not None:
                acceleration_blocks[r.index] = fitting(h.graphical.acceleration_plan, cell_a)
                if acceleration_blocks[r.index].width > cell_a[0] + 0.5:
                    wider["k_a"] = max(wider.get("k_a", 1.0), acceleration_blocks[r.index].width / cell_a[0])
        wider = {key: f for key, f in wider.items() if given[key] is None}
        if not wider:
            break
        for ks in per_position.values():
            for key, f in wider.items():
                ks[key] = round_up(ks[key] * f * 1.0001)
        for key, f in wider.items():
            if key in plate:
                plate[key] = round_up(plate[key] * f * 1.0001)
    legend_v = legend_svg([h.graphical.velocity_plan for h in here.values()], lang)
    legend_a = legend_svg([here[k].graphical.acceleration_plan for k in acceleration_blocks], lang) if acceleration_blocks else None

    # --- the document
    doc.plate = plate
    doc.per_position = per_position if scales == "per-position" else None
    sample = here[solved[0].index]
    senses = [_output_sense(r) for r in solved]
    plus, minus = sum(1 for s in senses if s > 0), sum(1 for s in senses if s < 0)
    working = (1.0 if plus >= minus else -1.0) if plus and minus else 0.0

    doc.section("data")
    doc.title(term("plate_title", lang), scene.title_in(lang))  # the plate's name, the scene's title under it
    from .words import cycle_lines

    cycle_law = run.motion.law if multi and run.motion is not None else None  # the cycle's law, stated below the data
    said_once = cycle_law is not None and cycle_law.kind == "constant"  # the rate in the driver's line, ε = 0 in the law's
    doc.lines([formula_words(line) for line in data_lines(scene, lang, cycle_law)
               + (_with_given_note(cycle_lines(run, lang, rate=not said_once), run, lang) if multi else [])],
              size=TEXT_PT)
    doc.line(f"{term('structural_formula', lang)}:  {formula_words(run.structure.formula)}", size=TEXT_PT)
    branch_words = assembly_lines(sample.analytic.branches, scene, lang, sample.graphical.positions)
    if branch_words:
        doc.line(f"{term('assembly', lang)}: " + ";  ".join(branch_words), size=TEXT_PT)
    doc.section("positions")
    doc.headed_line(term("positions_plan", lang) if multi else term("mechanism", lang), doc.scale_markup("k_l", k_l_plate))
    doc.figure("positions" if multi else "mechanism", first)
    if multi:
        entries = []
        for r in run.runs:
            accelerated = r.ok and r.index in chosen
            entries.append(position_entry(r, lang, accelerated, _stroke(r, working, lang, phases) if accelerated else ""))
        if run.strokes is not None and run.motion is not None and run.motion.start == "output" and run.strokes.law.crank:
            from ..positions import position_text

            entries.append(f"0′:  {position_text(run.scene, run.strokes.other_position)}")  # the other extreme position
        doc.listing(term("positions_list", lang), entries)

    doc.section("velocity-equations")
    doc.equations(f"{term('vector_equations', lang)}: {term('velocity_plan', lang).lower()}", sample.graphical.velocity_plan.steps, name,
                  similar=max((placement_rows(h.graphical, "velocity") for h in here.values()), key=lambda s: sum(map(len, s.values()))), flow=True)
    doc.section("velocity-plans")
    doc.headed_legend(term("velocity_plans", lang) + (f" ({term('each_from_its_pole', lang)})" if multi else ""),
                      (doc.scale_markup("k_v", plate["k_v"]) if scales != "per-position" else doc.line_markup(term("scales_each_position", lang), SMALL_PT))
                      + angles_key(doc, [h.graphical.velocity_plan for h in here.values()]),
                      "legend-v", legend_v)
    cells = []
    for r in run.runs:
        caption = f"{term('position', lang)} {r.index}:  {r.label}" if multi else r.label
        if not r.ok:
            cells.append((caption, None, f"{term('not_solved', lang)}: {_reason(r, lang)}"))
            continue
        extra = f"$k_v$ = {per_position[r.index]['k_v']:g}" if scales == "per-position" else ""
        cells.append((caption, (f"v-{r.index}", velocity_blocks[r.index]), extra, r.index in wide))
    doc.grid(cells, columns=2 if len(run.runs) > 1 else 1)
    if multi and acceleration_blocks and scales != "per-position" and given["k_a"] is None:
        # the acceleration plans sized to the room the velocity plans leave (read from the laid-out pages): the
        # rest of a page they leave less than half used, else a page of their own (under their equations when
        # those do not fit under the velocity plans)
        room = _acceleration_room(doc, _equations_height(here[chosen[0]].graphical.acceleration_plan))
        k_a = None
        if room is not None:
            columns_rest, cell_rest = _acceleration_cells([here[k] for k in chosen], room)
            largest_a = max((here[k] for k in chosen), key=lambda r: max(e / b for e, b in zip(_plan_extent(r.graphical.acceleration_plan), cell_rest)))
            k_a, _ = _fitted(lambda k: plan_svg(scaled(largest_a, "k_a", k).graphical.acceleration_plan, lang),
                             _plan_extent(largest_a.graphical.acceleration_plan), cell_rest, largest_a.graphical.scales["k_a"], None)
            longest = max(max((abs(v.tip - v.tail) for v in here[k].graphical.acceleration_plan.vectors), default=0.0)
                          * here[k].graphical.scales["k_a"] for k in chosen)  # [m/s²]
            small = k_a * ACCELERATION_REST_SHARE > plate["k_a"] or longest / k_a < ACCELERATION_LEAST - 1e-9
            if small and room < TEXT_HEIGHT - ACCELERATION_PAGE_TEXT - 1.0:
                k_a = None  # (too small there: a page of their own, but the first there when it fits the rest as it is)
                if acceleration_blocks[chosen[0]].height + 8.0 <= room:
                    accel_columns = 1
            else:
                accel_columns, cell_a = columns_rest, cell_rest
        if k_a is not None:
            for _ in range(4):  # coarser while a plan still runs over its cell
                for ks in per_position.values():
                    ks["k_a"] = k_a
                plate["k_a"] = k_a
                for k in chosen:
                    here[k] = at(here[k], per_position[k])
                    acceleration_blocks[k] = fitting(here[k].graphical.acceleration_plan, cell_a)
                over = max(max(acceleration_blocks[k].width / cell_a[0], acceleration_blocks[k].height / cell_a[1]) for k in chosen)
                if over <= 1.0 + 0.5 / min(cell_a):
                    break
                k_a = round_up(k_a * over * 1.0001)
            if accel_columns == 1:
                # the plans one under another: a small plan's enlarged detail may take the height the others leave
                # (the quick-return's working-stroke plan, 18 mm at the k_a of the idle stroke's, 2 mm short of its own cell)
                spare = sum(cell_a[1] - acceleration_blocks[k].height for k in chosen)
                for k in chosen:
                    old = acceleration_blocks[k]
                    block = plan_svg(here[k].graphical.acceleration_plan, lang, room=(cell_a[0], old.height + spare))
                    if block.height > old.height + 1e-6 and block.width <= cell_a[0] + 0.5:
                        acceleration_blocks[k] = block
                        spare -= block.height - old.height
            for index, h in here.items():  # one k_a on every position's record (its tables)
                if index not in chosen:
                    here[index] = at(h, per_position[index])
            legend_a = legend_svg([here[k].graphical.acceleration_plan for k in acceleration_blocks], lang)

    if acceleration_blocks:
        doc.section("acceleration-equations")
        # the equations fill what the velocity plans leave (one position's: they head its plan's page); the plans
        # follow, their heading kept with them
        doc.equations(f"{term('vector_equations', lang)}: {term('acceleration_plan', lang).lower()}", here[chosen[0]].graphical.acceleration_plan.steps,
                      name, new_page=not multi and not eq_under_v, similar=max((placement_rows(here[k].graphical, "acceleration") for k in chosen), key=lambda s: sum(map(len, s.values()))), flow=True)
        doc.section("acceleration-plans")
        doc.headed_legend(term("acceleration_plans", lang),
                          (doc.scale_markup("k_a", plate["k_a"]) if scales != "per-position" else doc.line_markup(term("scales_each_position", lang), SMALL_PT))
                          + angles_key(doc, [here[k].graphical.acceleration_plan for k in chosen]),
                          "legend-a", legend_a)
        cells = []
        for k in chosen:
            r = here[k]
            stroke = _stroke(r, working, lang, phases)
            caption = (f"{term('position', lang)} {k}:  {r.label}" if multi else r.label) + (f"  ({stroke})" if stroke and multi else "")
            extra = f"$k_a$ = {per_position[k]['k_a']:g}" if scales == "per-position" else ""
            cells.append((caption, (f"a-{k}", acceleration_blocks[k]), extra))
        doc.grid(cells, columns=accel_columns)

    doc.section("tables")
    doc.heading(term("comparison", lang), level=2)
    doc.tables([(f"{term('position', lang)} {h.index}:  {h.label}" if multi else h.label, _table(h, lang, h.index in acceleration_blocks)) for h in here.values()])
    # what a student measures on the plans of the chosen positions and what it gives (segment, mm, × k, = value)
    from ..drawing.readings import plan_readings

    readings = []  # (heading, rows, the proportions of the images that plan places by similarity, with numbers)
    attached = set()
    for k in chosen or [sample.index]:
        h = here[k]
        for kind in ("velocity", "acceleration"):
            rows = plan_readings(h.graphical, kind, lang)
            if rows:  # ("Положај 2 — план брзина: очитавања", not two colons in a row)
                named = term(kind + '_plan', lang)
                heading = f"{term('position', lang)} {h.index} — {named[0].lower()}{named[1:]}" if multi else named
                readings.append((f"{heading}: {term('readings', lang)}", rows, similarity_lines(h.graphical, kind, lang)))
                attached.add((h.index, kind))
    if readings:  # (as Document.tables: two across, each whole; the proportions under their plan's readings)
        parts = []
        for heading, rows, lines in readings:
            part = doc.table_markup(heading, rows, "(left, left, right, left, right)", full_width=True)
            if lines:
                said = term("by_similarity", lang)
                part = (part[:-1] + f" \\\n#text(size: {SMALL_PT}pt)[{doc.words(said[0].upper() + said[1:] + ':')} "
                        + " \\\n".join(_proportions(doc, line) for line in lines) + "]]")
            parts.append(part)
        doc.body.append(f"#text(size: {SMALL_PT}pt)[#grid(columns: (1fr, 1fr), column-gutter: {GUTTER}mm, row-gutter: 3mm, align: left + top,\n  "
                        + ",\n  ".join(parts) + ")]\n")
    # the proportions of the other positions' plans (those without readings), with their numbers: text that flows
    # over a page's end, its heading kept with its first line
    similar = [(f"{term('position', lang)} {h.index}, " if multi else "", kind, line) for h in here.values()
               for kind in ("velocity", "acceleration") if (kind == "velocity" or h.index in acceleration_blocks) and (h.index, kind) not in attached
               for line in similarity_lines(h.graphical, kind, lang)]
    if similar:
        doc.body.append(f"#block(sticky: true, above: 3mm)[#text(weight: \"bold\", size: {SMALL_PT + 1}pt)[{doc.words(term('similar_images', lang))}]]\n")
        doc.body.append(f"#text(size: {SMALL_PT}pt)[" + " \\\n".join(
            doc.words(f"{where}{term(kind + '_plan', lang).lower()}:") + " " + _proportions(doc, line) for where, kind, line in similar) + "]\n")

    loops_of = [here[k] for k in chosen] or [sample]
    doc.section("loops")
    from ..loops import loop_equations

    heading_at = len(doc.body)  # the heading kept with the first position's heading and the driver's equations under it
    doc.heading(term("loop_equations", lang), level=2)
    doc.mark("loops-start")
    for h in loops_of:
        if multi:
            doc.heading(f"{term('position', lang)} {h.index}:  {h.label}", level=3)
        for block in loop_equations(h.analytic):
            doc.loop_block(block)
            if heading_at is not None:
                _kept(doc, heading_at)
                heading_at = None
    doc.mark("loops-end", solid=True)

    loops_fitted = False
    if multi:
        say(term("cycle_diagrams" if _turning_driver(run) else "stroke_diagrams", lang))
        from ..drawing.diagrams import draw_cycle_diagrams
        from ..drawing.svgblocks import figure_svg

        doc.section("diagrams")
        doc.mark("diagrams-start")  # (the pages from here on stand alone: diagrams, kinematic, force, centres pages)
        marked = run.motion if run.motion is not None else run.positions
        kinematic = _plate_plans(_kinematic(scene, positions, len(run.runs), precision, law, start), run, here, set(acceleration_blocks), plate)
        # each page's title and words set by Typst above its figure, which takes the rest of the text area at 100 %
        from .typesetting import text as literal

        words_room = 36.0  # mm: the heading and four lines of words

        def cycle_pages(size):
            return draw_cycle_diagrams(run.cycle, marked=marked, lang=lang, components=components, cycle=run.dense,
                                       extremes=run.strokes, size=size, signed_elsewhere=_output_points(scene, kinematic), heading=False)

        # the output's kinematic diagrams and their table first; the cycle pages after them, the one with the fewest
        # panels under the table when the rest of its page holds it readably (each panel CYCLE_PANEL_MIN tall)
        _kinematic_pages(doc, kinematic, lang)
        _fit_loops(doc)  # (the loops' size settled first: what follows is measured where it then falls)
        loops_fitted = True
        pages = cycle_pages((DIAGRAM_PAGE[0], DIAGRAM_PAGE[1] - words_room))
        rest = _rest_of_page(doc, "kinematic-end") if pages and not isinstance(kinematic, Exception) else None
        under = None
        if rest is not None:
            height = rest - words_room - CYCLE_FLOW_MARGIN
            fewest = min(range(len(pages)), key=lambda k: (len(pages[k][1].axes), k))
            if (height - CYCLE_FIXED) / len(pages[fewest][1].axes) >= CYCLE_PANEL_MIN:
                name = pages[fewest][0]
                under = next((k, (n, fig)) for k, (n, fig) in enumerate(cycle_pages((DIAGRAM_PAGE[0], height))) if n == name)
        order = ([under[1]] if under is not None else []) + [page for k, page in enumerate(pages) if under is None or k != under[0]]
        for n, (page_name, fig) in enumerate(order):
            title, lines = fig.plans_heading
            doc.heading(title, level=2, new_page=not (n == 0 and under is not None))
            doc.body.append(f"#text(size: {SMALL_PT + 1}pt)[{literal(lines[0])}]\n")  # the scene's title, as written
            doc.lines(lines[1:], size=SMALL_PT + 1)
            doc.figure(f"diagram-{page_name}", figure_svg(fig, lang))
    if forces:
        doc.section("forces")
        _forces_pages(doc, [here[k] for k in chosen or [sample.index]], lang, multi)
    if centres:
        doc.section("centres")
        _centres_pages(doc, list(here.values()), k_l_plate, lang, multi, say)
    if not loops_fitted:
        _fit_loops(doc)
    return Handout(doc.source(), doc.images, plate, per_position, doc.order, chosen, doc.sizes, list(here.values()))


#: the least height [mm] the acceleration plans are given on the page the velocity plans end on, and what their
#: heading band with its scale, legend and captions takes there
ACCELERATION_ROOM_MIN = 80.0
ACCELERATION_BAND = 34.0
#: on the rest of the velocity plans' page the acceleration plans are drawn at least this share of the size a page
#: of their own gives them (else they take that page)
ACCELERATION_REST_SHARE = 0.5
#: ...and their largest vector at least this long [mm] (the plate's least acceleration plan, issue 20 §1)
ACCELERATION_LEAST = 50.0


def _acceleration_room(doc, equations: float) -> float | None:
    """The height [mm] the acceleration plans' cells share (under their heading band) given where the velocity
    plans end on the laid-out pages (:meth:`Document.mark`): the rest of that page when it is less than half
    used and leaves :data:`ACCELERATION_ROOM_MIN` under the *equations* [mm]; a page under the equations when
    those do not fit under the velocity plans; else None (a page of their own, the equations above)."""
    from .typesetting import query_document

    doc.mark("velocity-end", solid=True)
    end = next(m for m in query_document(doc.source(), doc.images, "<plans-mark>") if m["name"] == "velocity-end")
    top, height = doc.page.margins[2], doc.page.text_height
    left = height - (end["y"] - top) - 6.0
    if (end["y"] - top) / height < PAGE_USE_MIN and left - equations - ACCELERATION_BAND >= ACCELERATION_ROOM_MIN:
        return left - equations - ACCELERATION_BAND
    if equations <= left:
        return None
    return height - ACCELERATION_PAGE_TEXT - equations


#: the share of the text height a page of the flow (not the handout's last, not a page of its own) fills at least
PAGE_USE_MIN = 0.5
#: the loop equations' text may be set this much smaller or larger than the small text to fill their last page
LOOPS_SCALE = (0.9, 1.2)


def _fit_loops(doc) -> None:
    """The loop equations end the flow of text before the pages of their own (diagrams, forces, centres).  Where
    the kinematic diagrams follow them, their heading, words and first diagram (one block) flow up onto the loops'
    last page when it holds them, and the loops' text is set a little smaller (within :data:`LOOPS_SCALE`) when
    that lets them; otherwise, when the loops run a few lines onto a page and leave it nearly empty, their text is
    set a little smaller so that those lines go back onto the page before, or else a little larger so that their
    last page is at least :data:`PAGE_USE_MIN` filled.  Where they end is read from the laid-out document
    (:meth:`Document.mark`); the handout's last page may stay short."""
    from .typesetting import query_document

    top, height = doc.page.margins[2], doc.page.text_height

    def measure():  # (one layout: the page count and the marks)
        doc.body.insert(0, "#context [#metadata((name: \"pages\", page: counter(page).final().first(), y: 0)) <plans-mark>]\n")
        try:
            marks = {m["name"]: m for m in query_document(doc.source(), doc.images, "<plans-mark>")}
        finally:
            doc.body.pop(0)
        return marks["pages"]["page"], marks["loops-start"], marks["loops-end"], marks.get("kinematic-first")

    pages, start, end, first = measure()
    if first is not None and first["page"] != end["page"] and (end["y"] - top) / height < LOOPS_FLOW_USE:
        for scale in LOOPS_FLOW_SCALES:  # (the diagrams' first block onto the loops' last page, their text smaller)
            doc.loops_scale = scale
            _, _, end_now, first_now = measure()
            if first_now["page"] == end_now["page"]:
                return
        doc.loops_scale = 1.0
    used = (end["y"] - top) / height
    if first is not None and first["page"] != end["page"] and used < LOOPS_FILL:
        # what follows does not flow up: the loops' text a little larger, to fill their last page
        # (the growth per unit of scale first reckoned from the loops' run, then from what a try measured: a run
        # starting at a page's foot does not grow in proportion, and a first try may fall a little short; short of
        # the fill, the fullest try that keeps the loops' pages is kept)
        length = (end["page"] - start["page"]) * height + (end["y"] - start["y"])
        known = (1.0, end["y"])  # a scale and where the loops then end on their last page [mm]
        best = (end["y"], 1.0)
        for target in (LOOPS_FILL + 0.04, LOOPS_FILL + 0.04, LOOPS_FILL + 0.02):
            scale = known[0] + (target * height + top - known[1]) / length
            if not 1.0 < scale <= LOOPS_SCALE[1]:
                continue
            doc.loops_scale = round(scale, 3)
            _, start_now, end_now, _ = measure()
            if end_now["page"] != end["page"] or start_now["page"] != start["page"]:
                continue
            if (end_now["y"] - top) / height >= LOOPS_FILL:
                return
            best = max(best, (end_now["y"], doc.loops_scale))
            if end_now["y"] > known[1]:  # short of the fill: the next try from this one, at the growth it measured
                length = (end_now["y"] - known[1]) / (doc.loops_scale - known[0])
                known = (doc.loops_scale, end_now["y"])
        doc.loops_scale = best[1]
        if best[1] != 1.0:
            return
    if end["page"] == pages or used >= PAGE_USE_MIN or end["page"] == start["page"] or (first is not None and first["page"] == end["page"]):
        return
    length = (end["page"] - start["page"]) * height + (end["y"] - start["y"])  # the loops' run [mm]
    tries = [1.0 - (end["y"] - top + 4.0) / length, 1.0 + (PAGE_USE_MIN * height - (end["y"] - top) + 12.0) / length]
    for scale in tries:
        if not LOOPS_SCALE[0] <= scale <= LOOPS_SCALE[1]:
            continue
        doc.loops_scale = round(scale, 3)
        pages_now, _, end_now, _ = measure()
        if end_now["page"] == pages_now or (end_now["y"] - top) / height >= PAGE_USE_MIN:
            return
    doc.loops_scale = 1.0


#: the loops' last page is filled by the kinematic diagrams' first block when the loops leave more than this share
#: of it; the loops' text scales tried (smaller, not under :data:`LOOPS_SCALE`'s least) to let that block flow up
LOOPS_FLOW_USE = 0.75
LOOPS_FLOW_SCALES = (0.95, 0.9)
#: the loops' last page, when what follows them starts a page, is filled at least this share by their text set larger
LOOPS_FILL = 0.88


#: a one-position handout's regions [mm]: the mechanism's height (at least, at most: what page 1 leaves under the
#: data and above the velocity equations) and the velocity plan's cell (page 2, under its heading and legend)
SINGLE_MECHANISM = (100.0, 150.0)
SINGLE_VELOCITY = (TEXT_WIDTH, 150.0)
#: the least height [mm] page 1 must leave under the mechanism for the velocity plan to be drawn there
SINGLE_VELOCITY_MIN = 70.0
#: what the velocity plan's page gives its heading, scale, legend and caption [mm]
VELOCITY_PAGE_TEXT = 32.0
#: room [mm] the acceleration plans' page gives its heading, scale and legend (the rest holds the plans; their
#: vector equations go under the velocity plans)
ACCELERATION_PAGE_TEXT = 45.0
#: what a plan's drawing takes beyond its geometry, reckoned before it is drawn [mm] (labels, margin, caption)
PLAN_FIXED = (14.0, 20.0)


def _wide(plan, k_v: float, cell=VELOCITY_CELL) -> bool:
    """Whether the velocity *plan* drawn at *k_v* [(m/s)/mm] runs over *cell* [mm] (a half cell by default;
    reckoned from its extent and :data:`PLAN_FIXED`, before it is drawn)."""
    return any(e / k_v + f > c for e, f, c in zip(_plan_extent(plan), PLAN_FIXED, cell))


def _acceleration_cells(runs, room: float | None = None) -> tuple[int, tuple[float, float]]:
    """(columns, cell [mm]) for the acceleration plans of *runs*: one above the other or side by side,
    whichever draws the largest of them largest (two fill the page under the equations, or *room* [mm]; more
    go two across, as many down a page as fit)."""
    if not runs:
        return 1, (TEXT_WIDTH, 100.0)
    room = TEXT_HEIGHT - ACCELERATION_PAGE_TEXT if room is None else room
    n = len(runs)
    options = []
    for columns in (1, 2):
        rows = max(1, min(-(-n // columns), 2))
        cell = ((TEXT_WIDTH - (columns - 1) * GUTTER) / columns, room / rows - 6.0)
        need = max(max(e / max(c - f, 10.0) for e, c, f in zip(_plan_extent(r.graphical.acceleration_plan), cell, PLAN_FIXED)) for r in runs)
        options.append((need, columns, cell))
    need, columns, cell = min(options)
    return columns, cell


def _kinematic(scene, positions, count: int, precision, law=None, start: str = "output"):
    """The output link's kinematic diagrams by graphical differentiation at the handout's count of positions (12
    when it has fewer than 8), or the :class:`plans.differentiation.DiagramsError` that says why there are none."""
    from ..differentiation import DiagramsError, kinematic_diagrams

    if isinstance(positions, int):
        count = positions
    if count < 8:  # a course project differentiates over 8 or more
        count = 12
    try:
        return kinematic_diagrams(scene, count, law=law, start=start, precision=precision, plans=False)
    except DiagramsError as exc:
        return exc


def _plate_plans(kinematic, run, here: dict, drawn_accelerations, plate: dict) -> object:
    """*kinematic* (from :func:`_kinematic`) with its "plans" column read off the plans the handout draws: each row's
    position matched to the handout's position at the same time and driver position, its output's v_rel, a_rel
    (ω, ε) the values the plate's plans give at the plate's scales and drafting precision (the comparison tables'
    values, rounded as they are: :func:`plans.report.reading_step`); a only where that position's acceleration plan
    is drawn (*drawn_accelerations*), NaN elsewhere and where a row has no position on the plate."""
    import math

    import numpy as np

    from ..differentiation import with_plans
    from ..report import reading_step

    if isinstance(kinematic, Exception):
        return kinematic
    motion = run.motion
    n = len(kinematic.motion.t)
    v, a, v_step, a_step = (np.full(n, np.nan) for _ in range(4))
    section, quantities = (("sliders", ("v_rel", "a_rel")) if kinematic.motion.kind == "slider" else ("links", ("omega", "epsilon")))
    if motion is not None:
        crank = kinematic.law is not None and kinematic.law.crank
        duration = kinematic.motion.duration or 1.0
        times = np.asarray(motion.t, dtype=float)
        places = np.asarray(motion.positions, dtype=float)
        for k in range(n):
            t_k, x_k = float(kinematic.motion.t[k]), float(kinematic.positions[k])
            for index, h in here.items():
                dx = places[index] - x_k
                if crank:
                    dx = math.remainder(dx, 2 * math.pi)
                if abs(times[index] - t_k) > 1e-9 * duration or abs(dx) > 1e-9 * max(1.0, abs(x_k)):
                    continue
                rows = {c.quantity: c for c in h.comparisons if c.section == section and c.name == kinematic.motion.name}
                for q, values, steps in ((quantities[0], v, v_step), (quantities[1], a, a_step)):
                    if q not in rows or (q == quantities[1] and index not in drawn_accelerations):
                        continue
                    values[k] = float(rows[q].graphical)
                    step = reading_step(h.graphical, rows[q])
                    steps[k] = step if step is not None else np.nan
                break
    return with_plans(kinematic, v, a, v_step=v_step, a_step=a_step, plan_scales=dict(plate),
                      precision=run.precision)


def _output_points(scene, kinematic) -> tuple:
    """The reported points of the output slider (a body translating on a frame guide: each point's v and a are its
    own), whose signed v and a the kinematic diagrams give: the cycle page does not repeat them as |v|, |a|."""
    motion = getattr(kinematic, "motion", None)
    if motion is None or motion.kind != "slider":
        return ()
    links = [pair.slider for pair in scene.prismatics if pair.name == motion.name]
    if not links:
        return ()
    return tuple(p for p in scene.report if p in scene.bodies[links[0]].points)


#: a page of cycle diagrams set under the kinematic table keeps each panel at least this tall [mm]; what its figure
#: takes beyond the panels (the positions' numbers above, the axis and the legend below) [mm]; and the room [mm] it
#: leaves free at the page's foot (its words' height is reckoned, not measured)
CYCLE_PANEL_MIN = 32.0
CYCLE_FIXED = 40.0
CYCLE_FLOW_MARGIN = 6.0


def _rest_of_page(doc, name: str) -> float | None:
    """The height [mm] left on the page under a mark *name* set now at the end of the flow (read from the laid-out
    document, :meth:`Document.mark`)."""
    from .typesetting import query_document

    doc.mark(name, solid=True)
    marks = [m for m in query_document(doc.source(), doc.images, "<plans-mark>") if m["name"] == name]
    if not marks:
        return None
    top, height = doc.page.margins[2], doc.page.text_height
    return top + height - marks[-1]["y"]


def _kinematic_pages(doc, kinematic, lang: str) -> None:
    """The pages of the output link's kinematic diagrams (*kinematic*, from :func:`_kinematic`): the data lines,
    each diagram under its title and scales at 100 % (a rate constant over the cycle said in a line), the legend,
    the comparison table and its notes, set by Typst and flowing over pages (the table on the diagrams' page when it
    fits there, and what follows it on its page when that fits); a mechanism without an output slider
    or rocker, or not solved at one of the positions, gets a page that says so."""
    from ..drawing import kinematic_diagrams as kd

    # the heading flows on from the loop equations where their last page leaves room for it, its words and its first
    # diagram, all one block (never a heading at a page's foot with its diagram on the next page)
    start = len(doc.body)
    doc.heading(kd.page_heading(lang), level=2)
    if isinstance(kinematic, Exception):  # said on the page, in the reader's language
        doc.body.append(f"#text(weight: \"bold\")[{doc.words(term('kd_not_drawn', lang) + ':')}]\n")
        doc.line(kd.unavailable_reason(kinematic, lang))
        _kept(doc, start)
        return
    d = kd.page_diagrams(kinematic, doc.page.text_width)
    doc.lines(kd.header_lines(d, lang), size=SMALL_PT + 0.5)
    doc.legend(kd.legend_items(d, lang))
    blocks = kd.diagram_svgs(d, lang)
    for key in kd.KEYS:
        if key in blocks:
            doc.captioned(kd.diagram_title(d, key, lang), f"kinematic-{key}", blocks[key])
        else:
            doc.line(kd.flat_line(d, key, lang), size=SMALL_PT + 0.5)
        if start is not None and key in blocks:
            _kept(doc, start)
            doc.mark("kinematic-first", solid=True)  # (where the first diagram ends: on the loops' last page when it flowed there)
            start = None
    if start is not None:
        _kept(doc, start)
    table = kd.diagrams_table(d, lang)
    doc.grouped_table(kd.table_heading(lang), *kd.table_header(d, lang), table[1:])
    doc.lines(kd.notes(d, lang), size=SMALL_PT)


def _kept(doc, start: int, above: str = "") -> None:
    """What the document's body gained from *start* on, one block that does not break (moves whole to the next page
    when the rest of this one does not hold it); *above*: its own space above it (a block headed by a heading keeps
    the heading's, which a heading inside a block does not bring with it)."""
    inside = "\n".join(doc.body[start:])
    del doc.body[start:]
    doc.body.append(f"#block(breakable: false, width: 100%{f', above: {above}' if above else ''})[\n{inside}\n]\n")


#: the quantities read off a velocity plan (a position without its acceleration plan on the plate tabulates only these)
VELOCITY_QUANTITIES = ("v", "omega", "v_rel")


def _table(h, lang: str, accelerations: bool = True) -> list[list[str]]:
    """The comparison table of the position *h*; without *accelerations* (its acceleration plan is not on the
    plate) only what its velocity plan gives: no graphical acceleration with no plan behind it."""
    from ..drawing.sheet import translate_table
    from ..report import sheet_table

    comparisons = h.comparisons if accelerations else [c for c in h.comparisons if c.quantity in VELOCITY_QUANTITIES]
    return translate_table(sheet_table(comparisons, h.graphical, h.analytic, points_of_links=True), lang)


def _forces_pages(doc, positions, lang: str, multi: bool) -> None:
    """The kinetostatic pages of each of *positions* (:func:`plans.pages.forces.force_pages`): its free bodies, its
    force plans at one μ_F, Joukowski's lever (not when the driver is at rest) and the three methods side by side."""
    from ..forces.analytic import forces_from
    from ..forces.lever import LeverError, joukowski_lever
    from .forces import force_pages

    doc.plate_name = "kinetostatics"  # the title block of the force pages
    for h in positions:
        try:
            lever = joukowski_lever(h.graphical)
        except LeverError:
            lever = None  # the driver at rest: no arm for the balancing force (the force plans still give M_b)
        where = f"{term('position', lang)} {h.index}:  {h.label}" if multi else None
        force_pages(doc, h.graphical, lever=lever, analytic=forces_from(h.analytic), where=where, key=f"forces-{h.index}")
    doc.plate_name = "plate_title"


def _centres_pages(doc, positions, k_l: float, lang: str, multi: bool, say=lambda words: None) -> float | None:
    """The instant centres' pages: first the method (its title, Kennedy's theorem and the circle diagram, the same
    for every position, drawn once), then a page for every position of *positions*: the mechanism with its centres
    at one k_l for all the pages (the plate's, or the coarsest any of them needs to hold its drawing above its
    table), stated on each page and in their title block; the table (ω and v as read off the drawing at that k_l,
    to the scene's drafting precision: :func:`plans.centres.instant_centres`) and the rules.  Returns that k_l
    (None: no page has a drawing)."""
    from ..centres import instant_centres
    from ..compare import compare_centres
    from ..drawing.centres import CentresSizer
    from ..drawing.centres_page import ROOM_MIN, centres_page_table
    from ..drawing.svgblocks import centres_svg, circle_diagram_svg
    from ..errors import PlansError

    pages = []  # (h, result, comparisons, table, box) or (h, error)
    sizers = {}
    k = k_l
    diagram = None
    for n, h in enumerate(positions, start=1):
        say(f"{term('instant_centres', lang)} {n}/{len(positions)}")
        try:
            result = instant_centres(h.scene, h.analytic.structure)
            comparisons = compare_centres(h.analytic, result, translations=True)
        except PlansError as exc:
            pages.append((h, exc))
            continue
        if diagram is None:
            diagram = (f"circle-{h.index}", circle_diagram_svg(result, lang, caption=False, radius=CENTRES_DIAGRAM_R))
        # the drawing gets what the page leaves under its heading and the legend, over the table and the rules
        table = centres_page_table(result, comparisons, lang)
        box = (TEXT_WIDTH, min(CENTRES_DRAWING_MAX, TEXT_HEIGHT - CENTRES_PAGE_TEXT - CENTRES_ROW * len(table)))
        # sizes from geometry (two drawings of the mechanism alone, plans.drawing.centres.CentresSizer)
        sizer = sizers[h.index] = CentresSizer(result, lang, room_min=ROOM_MIN, cycle=_centres_cycle(h))
        for _ in range(24):
            width, height = sizer.size(k, box)
            if width <= box[0] + 0.5 and height <= box[1] + 0.5:
                break
            k = round_up(k * max(width / box[0], height / box[1], 1.0001))
        pages.append((h, result, comparisons, table, box))
    drawn = [p for p in pages if len(p) > 2]
    blocks = {}
    for _ in range(4):  # the sizer is exact at its own two scales, close elsewhere: coarser while a drawing runs over
        over = 1.0
        for h, result, _, _, box in drawn:
            if h.index not in blocks or blocks[h.index][0] != k:
                blocks[h.index] = (k, centres_svg(result, k, lang, room_min=ROOM_MIN, limit=box, cycle=_centres_cycle(h)))
            block = blocks[h.index][1]
            over = max(over, block.width / (box[0] + 0.5), block.height / (box[1] + 0.5))
        if over <= 1.0:
            break
        k = round_up(k * over * 1.0001)
    # the table's values as a student reads them off the drawing at its k_l, to the handout's drafting precision
    for n, page in enumerate(pages):
        if len(page) > 2:
            h, result = page[0], page[1]
            try:
                frame = sizers[h.index].frame(k, page[4])  # the centres drawn where they are: the lengths read
                read = instant_centres(h.scene, h.analytic.structure, k_l=k, precision=h.scene.scales.precision,
                                       room=(frame.lo * k, frame.hi * k))
            except PlansError:  # every path of centres has two on one spot of the drawing: exact values, said on the page
                pages[n] = page[:4] + (page[4], term("centres_read_exact", lang))
                continue
            comparisons = compare_centres(h.analytic, read, translations=True)
            pages[n] = (h, result, comparisons, centres_page_table(read, comparisons, lang, k_l=k), page[4])
    # the step through a link that translates (the quick-return's ram 6, a slider-crank's slider) stated with the rules
    translating = any(p[1].translates(j) for p in drawn for j in p[1].scene.links if j != p[1].scene.driver.link)
    _centres_method(doc, diagram, k, lang, drawn[0][1] if drawn else None, translating)
    for page in pages:
        _centres_page(doc, page, k, blocks, lang, multi)
    return k if drawn else None


def _centres_cycle(h):
    """(travel, cycle poses) of position *h*'s drawings: the centres drawing's guides and supports as the plate's."""
    g = h.graphical
    return getattr(g, "travel", None), getattr(g, "cycle_poses", None)


#: the centres' tables at the text's size, the labels' subscripts (P₁₂: the content of the order table and the P₁ⱼ column)
#: set as digits at 0.8 of it (7.6 pt; the font's subscript glyphs are about 5 pt), in a scope of their own
CENTRES_TABLE_PT = TEXT_PT
CENTRES_SUBSCRIPT_EM = 0.8
_CENTRES_TABLE_OPEN = (
    "#[\n"
    f"#show table: set text(size: {CENTRES_TABLE_PT}pt)\n"
    f"#show regex(\"[₀-₉ⱼₖ]+\"): it => sub(typographic: false, size: {CENTRES_SUBSCRIPT_EM}em, it.text.clusters().map("
    "c => if c == \"ⱼ\" {\"j\"} else if c == \"ₖ\" {\"k\"} else {str(str.to-unicode(c) - 0x2080)}).join())\n")


#: the circle diagram's radius on the centres' method page [mm]
CENTRES_DIAGRAM_R = 32.0


def _centres_method(doc, diagram, k: float, lang: str, result, translating: bool = False) -> None:
    """The centres' first page: the method's title, Kennedy's theorem, the circle diagram (once: it is the same for
    every position), the rules (*translating*: with the step through a link that translates) and the order of
    finding the centres (*result*: a position's centres)."""
    from ..drawing.centres_page import centres_order_table, centres_rules

    # one block that flows on under what comes before it where the rest of that page holds it (a page of cycle
    # diagrams with few panels), else heads a page
    start = len(doc.body)
    doc.heading(term("centres_page", lang), level=2)
    doc.body.append(f"#plate-kl.update([{doc.scale_words('k_l', k)}])")  # the title block of the centres' pages
    kennedy = term("kennedy_theorem", lang)
    doc.line(f"{kennedy[0].upper() + kennedy[1:]}: {term('kennedy_statement', lang)}", size=TEXT_PT)
    if diagram is not None and result is not None:
        # the circle diagram large (the method's tool), its legend and the rules beside it at the text's size, the order
        # of finding the centres under them across the page: the page read as a whole, not 40 % empty (third review)
        circle = f"{term('circle_diagram', lang)}: {term('circle_diagram_legend', lang).replace(chr(10), ' ')}"
        lines = [circle, term("centres_legend", lang), term("centres_edge_legend", lang)]
        rules = centres_rules(lang, result.scene.frame_number, result.scene.driver, result.numbers, translating)
        words = "".join(f"#block(above: 0pt, below: 2mm)[{doc.words(line)}]" for line in lines) + "#v(2mm)"
        for rule in rules:  # the rule's words, its formula on a line of its own under them
            said, _, formula = rule.partition(":  ")
            words += f"#block(above: 0pt, below: 1mm)[{doc.words(said)}:]#block(above: 0pt, below: 2.5mm, inset: (left: 6mm))[{doc.words(formula)}]"
        key, block = diagram
        doc.body.append(f"#v(2mm)\n#grid(columns: (auto, 1fr), column-gutter: {GUTTER}mm, align: top + left, {doc.add_image(key, block)}, "
                        f"text(size: {TEXT_PT}pt)[{words}])\n#v(3mm)\n")
        doc.body.append(_CENTRES_TABLE_OPEN)
        doc.body.append("#" + doc.table_markup(term("centres_order", lang), centres_order_table(result, lang), "(left, left)") + "\n")
        doc.body.append("]\n")
    # (the heading's space above it: after the loop equations' last line, under a mark of no height, the block was
    # set over that line)
    _kept(doc, start, above=HEADING_ABOVE)


def _centres_page(doc, page, k: float, blocks, lang: str, multi: bool) -> None:
    """The page of instant centres of one position (:func:`_centres_pages`), headed by the position in one line."""
    h = page[0]
    where = f"{term('position', lang)} {h.index}:  {h.label}"
    doc.heading(f"{term('instant_centres', lang)} — {where}" if multi else f"{term('instant_centres', lang)}:  {h.label}",
                level=2, new_page=True)
    if len(page) == 2:
        doc.line(str(page[1]), size=TEXT_PT)
        return
    result, table = page[1], page[3]
    doc.figure(f"centres-{h.index}", blocks[h.index][1])
    if len(page) > 5:  # the values not read off the drawing, and why (the legend and rules: on the method's page)
        doc.line(page[5], size=SMALL_PT)
    doc.body.append(_CENTRES_TABLE_OPEN)
    doc.beside(None, table, [])
    doc.body.append("]\n")


def data_lines(scene, lang: str, law=None) -> list[str]:
    """The scene's data as a few lines of text in *lang*: driver, link lengths, fixed points (names in *lang*);
    *law*: the cycle's law stated below them (:func:`plans.pages.words.scene_data_lines`)."""
    from .words import scene_data_lines

    return scene_data_lines(scene, lang, law)


