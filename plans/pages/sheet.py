"""The single sheets of ``plans draw``, set by Typst on the plate's page (:mod:`plans.pages.document`).

A sheet is an A3 landscape page with the plate's frame (20 mm binding margin)
and its title block in the lower right corner (plate name, the scene's title
in the reader's language, the scale factors, sheet n of m, drawn by / checked
by / date).  On its left the drawings — the mechanism at k_l, the velocity
plan at k_v and the acceleration plan at k_a, matplotlib SVG blocks
(:mod:`plans.drawing.svgblocks`) placed at 100 %, so that the stated factors
hold on paper — each under its name and scale; on its right, over the title
block, a column of text set by Typst in the reader's language: the structural
formula and the assembly of the groups in words, the vector equations with
their known parts underlined, the legend of the plans, the readings of both
plans and the table of graphical against analytic values.

Scale factors: one k_l, k_v, k_a per sheet (for ``--positions``: one of each
over every position's sheet, the plate's rule), each the round factor with
which the largest of its drawings fills the region the sheet gives it; the
regions are arranged (mechanism over the plans, the three one above the
other, or the mechanism beside the plans) as draws the drawings largest.  A
factor the user or the scene gives is kept.  This module orchestrates: the
plans are constructed at the chosen factors here (drawing never solves).

Room: a sheet whose text does not fit its column on A3 (found by the page
count Typst gives) — or whose drawings at factors the user gave do not fit
the region A3 leaves them — goes to the next ISO size (A2, A1, A0), with
its factors chosen again for that sheet's regions.
"""

from __future__ import annotations

import re

import math
from dataclasses import dataclass, field, replace
from pathlib import Path

from ..i18n import term
from .document import GUTTER, SMALL_PT, TEXT_PT, Document, PageGeometry, bbox, fitted, plan_extent
from .equations import placement_rows
from ..graphical.scales import round_down, round_up
from .typesetting import compile_document, image, query_value
from .words import assembly_lines, formula_words, namer, scene_data_lines

__all__ = ["Sheet", "PAPERS", "sheet_page", "build_sheet", "fitted_sheet", "sheet_at", "position_sheets", "position_heading", "positions_page",
           "write_drawings", "write_position_sheets", "similarity_markup", "TEXT_COLUMN", "TITLE_BLOCK_ROOM", "CAPTION", "in_reading_order"]

#: the ISO sheets a sheet may take, smallest first, landscape [mm]
PAPERS = (("A3", (420.0, 297.0)), ("A2", (594.0, 420.0)), ("A1", (841.0, 594.0)), ("A0", (1189.0, 841.0)))
#: room [mm] the title block takes above the frame's foot (the text column stops above it)
TITLE_BLOCK_ROOM = 27.0
#: the width [mm] of the text column at the right (over the title block, which is 185 mm wide)
TEXT_COLUMN = 180.0
#: room [mm] over a drawing for its name and its scale (two lines)
CAPTION = 10.5
#: the drawings' corner of the page: its distance [mm] from the frame's foot (the drawings may go down beside the title block)
FOOT = 4.0
#: the part of a drawing that does not scale [mm] (labels, margins, supports), reckoned before it is drawn
ESTIMATED_FIXED = {"mechanism": (24.0, 24.0), "velocity": (14.0, 20.0), "acceleration": (14.0, 20.0)}
#: the scale factor of each drawing
SCALE_OF = {"mechanism": "k_l", "velocity": "k_v", "acceleration": "k_a"}
#: the factors a drawing depends on (a plan is constructed from the readings of the drawings before it)
FACTORS_OF = {"mechanism": ("k_l",), "velocity": ("k_l", "k_v"), "acceleration": ("k_l", "k_v", "k_a")}


def sheet_page(paper: str = "A3") -> PageGeometry:
    """The page of a sheet on *paper* (``"A3"`` … ``"A0"``, landscape): the text area's foot clears the title block."""
    size = dict(PAPERS)[paper]
    return PageGeometry(size, (20.0, 5.0), (25.0, 10.0, 10.0, 5.0 + TITLE_BLOCK_ROOM), title_block_width=185.0)


def _drawing_room(page: PageGeometry) -> tuple[float, float]:
    """(width, height) [mm] of the drawings' region: the text area's left part, down to near the frame's foot."""
    width = page.text_width - TEXT_COLUMN - GUTTER
    height = page.size[1] - page.margins[2] - page.frame[1] - FOOT
    return width, height


@dataclass
class Sheet:
    """A sheet ready to compile: Typst source, the SVG inputs, its factors and where its drawings are.

    Attributes
    ----------
    source : str
        The Typst document (one page).
    images : dict[str, bytes]
        Input key -> SVG of a drawing (placed at its physical size).
    scales : dict[str, float]
        The sheet's k_l, k_v, k_a.
    paper : str
        ``"A3"`` (or a larger ISO sheet when the sheet needs it).
    placed : dict[str, tuple[float, float, float, float]]
        Drawing -> (x, y, width, height) [mm] from the page's top left corner.
    graphical : GraphicalSolution
        The solution at the sheet's factors (what its drawings show).
    """

    source: str
    images: dict[str, bytes]
    scales: dict[str, float]
    paper: str
    placed: dict[str, tuple[float, float, float, float]] = field(default_factory=dict)
    graphical: object = field(default=None, repr=False)

    def pdf(self) -> bytes:
        """The sheet as a PDF (deterministic)."""
        return compile_document(self.source, self.images, "pdf")

    def pages(self, fmt: str = "svg", ppi: float = 110.0) -> list[bytes]:
        """The sheet's pages (one) as SVG (root size in mm) or PNG."""
        return compile_document(self.source, self.images, fmt, ppi=ppi)

    def render(self, fmt: str) -> bytes:
        """The sheet as the bytes of a ``.svg``, ``.pdf`` or ``.png`` file."""
        if fmt == "pdf":
            return self.pdf()
        if fmt == "svg":  # an XML file as every SVG plans writes (and the record of what it wrote goes at its end)
            return b'<?xml version="1.0" encoding="utf-8" standalone="no"?>\n' + self.pages("svg")[0]
        if fmt == "png":
            return self.pages(fmt)[0]
        raise ValueError(f"no output format {fmt!r}; choose one of svg, pdf, png")

    def save(self, path) -> Path:
        """Write the sheet to *path* in the format its suffix names (``.svg``, ``.pdf``, ``.png``), atomically."""
        from .._files import replace_all
        from ..drawing.formats import format_of

        path = Path(path)
        return replace_all({path: self.render(format_of(path))})[0]

    def _repr_svg_(self) -> str:
        return self.pages("svg")[0].decode("utf-8")


# --- the regions of the drawings ------------------------------------------------------------------


#: the least height [mm] of the room under the text column worth a drawing
UNDER_LEAST = 45.0


def _arrangements(room, kinds, under=None):
    """Candidate regions {kind: (x, y, w, h)} [mm from the text area's top left corner] in the drawings' room
    (*room*: its width and height at the left of the text column; *under*: (x, y, w, h), the room left under the
    text column, or None; *kinds*: the drawings, mechanism first)."""
    width, height = room
    g = GUTTER
    plans = [k for k in kinds if k != "mechanism"]
    out = []
    if under is not None and under[3] >= UNDER_LEAST:
        ux, uy, uw, uh = under
        # the mechanism alone at the left, the plans under the text (side by side, or one of them)
        w = (uw - g * (len(plans) - 1)) / max(len(plans), 1)
        out.append({"mechanism": (0.0, 0.0, width, height), **{k: (ux + n * (w + g), uy, w, uh) for n, k in enumerate(plans)}})
        for f in (0.3, 0.4, 0.5, 0.6, 0.7):
            top = height * f
            for k in plans:  # one plan under the text, the other (if any) under the mechanism
                other = [p for p in plans if p != k]
                boxes = {"mechanism": (0.0, 0.0, width, top - g / 2), k: (ux, uy, uw, uh)}
                if other:
                    boxes[other[0]] = (0.0, top + g / 2, width, height - top - g / 2)
                else:
                    boxes["mechanism"] = (0.0, 0.0, width, height)
                out.append(boxes)
    for f in (0.2, 0.3, 0.4, 0.5, 0.6, 0.7):
        top = height * f
        # the mechanism over the plans, the plans side by side
        boxes = {"mechanism": (0.0, 0.0, width, top - g / 2)}
        w = (width - g * (len(plans) - 1)) / max(len(plans), 1)
        for n, k in enumerate(plans):
            boxes[k] = (n * (w + g), top + g / 2, w, height - top - g / 2)
        out.append(boxes)
        if len(plans) == 2:
            # the three one above the other
            rest = (height - top - g) / 2
            out.append({"mechanism": (0.0, 0.0, width, top - g / 2), plans[0]: (0.0, top + g / 2, width, rest),
                        plans[1]: (0.0, top + g * 1.5 + rest, width, rest - g / 2)})
        # the mechanism beside the plans (the plans one above the other)
        left = width * f
        boxes = {"mechanism": (0.0, 0.0, left - g / 2, height)}
        h = (height - g * (len(plans) - 1)) / max(len(plans), 1)
        for n, k in enumerate(plans):
            boxes[k] = (left + g / 2, n * (h + g), width - left - g / 2, h)
        out.append(boxes)
    return out


def _drawn(extent, box, fixed) -> float:
    """How large [mm per physical unit] a drawing of *extent* with *fixed* parts is drawn in *box* (caption kept)."""
    room = (box[2] - fixed[0], box[3] - CAPTION - fixed[1])
    ratios = [r / e for r, e in zip(room, extent) if e > 0]
    if any(r <= 0 for r in room):
        return 0.0
    return min(ratios) if ratios else 1.0


def _choose_regions(room, extents: dict, fixed: dict, given_sizes: dict, under=None, needs=None):
    """The arrangement that draws the drawings largest, or None when a drawing at a given factor (*given_sizes*:
    kind -> (w, h) [mm]) fits none (*room*, *under*: :func:`_arrangements`).

    Largest: first every drawing at least its least size (*needs*: kind -> [(physical length, least mm)…], the
    sizes a sheet gives its drawings, :data:`LEAST`) by the most (up to :data:`ENOUGH`), then the geometric
    mean of their sizes.
    """
    ranked = _ranked_regions(room, extents, fixed, given_sizes, under, needs)
    return ranked[0] if ranked else None


def _ranked_regions(room, extents: dict, fixed: dict, given_sizes: dict, under=None, needs=None) -> list:
    """The arrangements in which the drawings fit, best first (:func:`_choose_regions`)."""
    scored = []
    for boxes in _arrangements(room, list(extents), under):
        least, score, ratios = ENOUGH, 0.0, []
        for kind, extent in extents.items():
            box = boxes[kind]
            if kind in given_sizes:
                w, h = given_sizes[kind]
                if w > box[2] + 0.5 or h > box[3] - CAPTION + 0.5:
                    score = -math.inf
                    break
                continue
            size = _drawn(extent, box, fixed[kind])
            if size <= 0:
                score = -math.inf
                break
            size = 1.0 / round_up(1.0 / size)  # at the round factor it will be drawn at
            score += math.log(size)
            reached = [size * length / mm for length, mm in (needs or {}).get(kind, ()) if length > 0]
            if reached:
                least = min(least, min(reached))
                ratios.append(min(reached))
        if score > -math.inf:
            starved = len(ratios) > 1 and max(ratios) > STARVED * max(min(ratios), 1.0)
            scored.append(((least, score, starved), len(scored), boxes))
    # every drawing at its least size first; of those, the ones that keep the textbook's order (scheme, velocity
    # plan, acceleration plan: left to right, top to bottom) before any that does not; then the one whose smallest
    # drawing is largest (up to ENOUGH); then one where no drawing starves another (a velocity plan 200 mm across
    # beside an acceleration plan at its least: STARVED); then the largest
    order = [k for k in ("mechanism", "velocity", "acceleration") if k in extents]
    return [boxes for _, _, boxes in sorted(scored, key=lambda t: (-min(t[0][0], 1.0), not in_reading_order(t[2], order), -t[0][0],
                                                                  t[0][2], -t[0][1], t[1]))]


def in_reading_order(boxes: dict, kinds: list) -> bool:
    """Whether the regions *boxes* {kind: (x, y, w, h)} [mm] are read in the order *kinds*: of two regions side by
    side (their heights overlap) the left one first, else the upper one first."""
    def before(a, b) -> bool:
        (ax, ay, _, ah), (bx, by, _, bh) = a, b
        if ay < by + bh and by < ay + ah:  # side by side
            return ax <= bx
        return ay <= by

    return all(before(boxes[a], boxes[b]) for n, a in enumerate(kinds) for b in kinds[n + 1:])


#: the least sizes [mm] a sheet gives its drawings (issue 11 §1): the mechanism 100 mm across, a plan's
#: largest vector 60 mm and the plan 40 mm across
LEAST = {"mechanism": 100.0, "vector": 60.0, "plan": 40.0}
#: how far over its least size a drawing counts in choosing the arrangement (the round factors and what does not
#: scale take some of it back)
ENOUGH = 1.3
#: an arrangement starves a drawing where another is drawn more than this many times as far over its least size
#: (and more than this many times its least size: the Russian four-bar's velocity plan 200 mm, 3.3 × its least,
#: beside an acceleration plan at 1.05 ×)
STARVED = 2.0


def _needs(kind: str, objs) -> list[tuple[float, float]]:
    """[(physical length, least mm)…] of the drawings of *kind* (*objs*: a solution's, or a plan per position)."""
    if kind == "mechanism":  # one k_l over the positions: the smallest across reaches its size
        return [(min(max(_extent(kind, g)) for g in objs), LEAST["mechanism"])]
    return [(max((v.value for p in objs for v in p.vectors), default=0.0), LEAST["vector"]),
            (max(max(_extent(kind, p)) for p in objs), LEAST["plan"])]


# --- the sheet -------------------------------------------------------------------------------------


def _readings(doc: Document, graphical, lang: str) -> list:
    from ..drawing.readings import plan_readings

    out = []
    for kind in ("velocity", "acceleration"):
        rows = plan_readings(graphical, kind, lang)
        if rows:
            out.append((f"{term(kind + '_plan', lang)}: {term('readings', lang)}", rows))
    return out


def _placements(graphical, kind: str) -> dict:
    """The rows placing the images no step places (:func:`placement_rows`), but for the proportions: the sheet says
    those once, with their numbers, under "Images by similarity"."""
    rows = {at: [row for row in rows if row.kind != "proportion"] for at, rows in placement_rows(graphical, kind).items()}
    return {at: rows for at, rows in rows.items() if rows}


def _texts(doc: Document, graphical, *, table, formula, assembly, legend, heading, split: bool = False,
           notes: bool = True) -> list[str]:
    """The text column's markup (collected from the document's own sections); *split*: the comparison table in two
    halves side by side (a long one: :data:`SPLIT_ROWS`), the legend under them; *notes*: whether a plan has notes
    under it (short segments, near-coincident directions), which the legend then explains."""
    lang = doc.lang
    name = namer(doc.scene, lang, "parallel")  # (the equations' guide names follow ∥)
    body, doc.body = doc.body, []
    try:
        if heading:
            doc.heading(heading, level=2)
        # the given data (the driver's ω, ε or v, a; the link lengths; the fixed points), as the handout states them
        for n, line in enumerate(scene_data_lines(doc.scene, lang)):
            if n == 0 and not heading:  # the driver's position at the sheet's instant (a crank's φ, a sliding driver's s), where no heading states it
                line += ",  " + _driver_position(doc.scene)
            doc.line(_capitalised(line), size=SMALL_PT + 0.5)
        if formula:
            doc.line(f"{term('structural_formula', lang)}:  {formula_words(formula)}", size=TEXT_PT)
        if assembly:
            doc.line(f"{term('assembly', lang)}: " + ";  ".join(assembly), size=SMALL_PT + 0.5)
        for plan in (graphical.velocity_plan, graphical.acceleration_plan):
            if plan is not None and any(step.equations for step in plan.steps):
                doc.equations(f"{term('vector_equations', lang)}: {term(plan.kind + '_plan', lang).lower()}", plan.steps, name,
                              similar=_placements(graphical, plan.kind))
        readings = [doc.table_markup(heading, rows, "(left, left, right, left, right)") for heading, rows in _readings(doc, graphical, lang)]
        if len(readings) == 2:  # the readings of the two plans side by side, each as wide as it needs (its cells do not
            # break: a factor '× 0.025 ÷ 0.6765 (l_EB)' in a half column ran over its value), else one under the other
            doc.body.append(f"#text(size: {SMALL_PT}pt)[#layout(room => {{ let a = {readings[0]}; let b = {readings[1]}; "
                            f"let wa = measure(a).width; let wb = measure(b).width; "
                            f"if wa + wb + {GUTTER}mm <= room.width {{ grid(columns: (wa / (wa + wb) * 1fr, wb / (wa + wb) * 1fr), "
                            f"column-gutter: {GUTTER}mm, align: top + left, a, b) }} else {{ stack(spacing: 3mm, a, b) }} }})]\n")
        elif readings:
            doc.body.append(f"#text(size: {SMALL_PT}pt)[#grid(columns: (1fr, 1fr), column-gutter: {GUTTER}mm, align: top + left, "
                            + ", ".join(readings) + ")]\n")
        results = doc.table_markup(term("comparison", lang), table) if table and len(table) > 1 else "[]"
        # under the plans' legend, what the notes under a plan are (short segments, near-coincident directions)
        # (the legend as drawn, or narrower where the column is narrow: it never runs over the table beside it)
        legend_image = "align(right)[#layout(room => " + doc.add_image('legend', legend).replace(
            f"width: {legend.width:.3f}mm", f"width: calc.min(room.width, {legend.width:.3f}mm)") + ")]" if legend is not None else ""
        notes = (f"block(width: 100%)[#text(size: {SMALL_PT - 0.5}pt)[{doc.words(term('plan_notes_legend', lang))}]]"
                 if legend is not None and notes else "")  # (not where no plan has a note: it referred to nothing)
        # the proportions of the images placed by similarity, beside the table under the legend
        similar = similarity_markup(doc, [("", graphical)])
        if split and table and len(table) > SPLIT_ROWS:
            # a long table in two halves side by side (the second under the same header, its heading line left blank),
            # the legend under them, its notes and the proportions beside it
            cut = (len(table) + 1) // 2
            halves = (doc.table_markup(term("comparison", lang), table[:cut]), doc.table_markup("", [table[0]] + table[cut:]))
            doc.body.append(f"#text(size: {SMALL_PT}pt)[#grid(columns: (auto, auto), column-gutter: {2 * GUTTER}mm, align: top + left, "
                            f"{halves[0]}, {halves[1]})]\n")
            right = " + ".join(x for x in (notes, f"block(above: 3mm)[{similar}]" if similar else "") if x) or "[]"
            doc.body.append(f"#text(size: {SMALL_PT}pt)[#block(above: 4mm)[#grid(columns: (auto, 1fr), column-gutter: {2 * GUTTER}mm, "
                            f"align: top + left, {legend_image or '[]'}, {right})]]\n")
        else:
            legend_cell = " + ".join(x for x in (legend_image, notes, f"block(above: 3mm)[{similar}]" if similar else "") if x) or "[]"
            doc.body.append(f"#text(size: {SMALL_PT}pt)[#grid(columns: (auto, 1fr), column-gutter: {GUTTER}mm, align: top + left, {results}, {legend_cell})]\n")
        return doc.body
    finally:
        doc.body = body


#: a comparison table longer than this (rows, with its header) is set in two halves side by side
SPLIT_ROWS = 16


def similarity_markup(doc: Document, solutions) -> str:
    """The proportions by which the plans of *solutions* (``(words, GraphicalSolution)``: the words before its lines,
    a handout's position, or "") place images by similarity (:func:`plans.drawing.readings.similarity_lines`) under
    their heading, as Typst markup ("" when there are none)."""
    from ..drawing.readings import similarity_lines

    lines = [where + line for where, g in solutions for kind in ("velocity", "acceleration") for line in similarity_lines(g, kind, doc.lang)]
    if not lines:
        return ""
    return (f"#block(breakable: false)[#text(size: {SMALL_PT}pt)[#text(weight: \"bold\", size: {SMALL_PT + 0.5}pt)"
            f"[{doc.words(term('similar_images', doc.lang))}] \\\n" + " \\\n".join(doc.words(line) for line in lines) + "]]\n")


def build_sheet(scene, graphical, blocks: dict, regions: dict, *, lang: str = "en", table=None, formula: str = "",
                assembly=(), legend=None, heading: str = "", paper: str = "A3", number: tuple[int, int] | None = None,
                text_scale: float = 1.0, split: bool = False) -> Sheet:
    """The sheet of *graphical* (drawn already: *blocks* kind -> SvgBlock at its factor) with its drawings at the top left
    in *regions* (kind -> (x, y, w, h) [mm] in the drawings' room), the text column beside them.

    *table*: the results table (rows of text, the header first, in *lang*); *formula*: the structural formula;
    *assembly*: the groups' assembly in words; *legend*: the plans' legend (an SvgBlock); *heading*: a line over
    the text (a position's sheet: the position); *number*: (n, m) of a set of sheets (else 1 of 1); *text_scale*: the
    text column's enlargement (:func:`_text_layout`); *split*: the comparison table in two halves (:func:`_texts`).
    """
    page = sheet_page(paper)
    doc = Document(scene, lang, page)
    doc.plate = dict(graphical.scales)
    doc.sheet_number = number
    width, _ = _drawing_room(page)
    noted = any(re.search(rb'id="(?:vel|acc)-(?:short|along)-', block.svg) for block in blocks.values())
    texts = _texts(doc, graphical, table=table, formula=formula, assembly=assembly, legend=legend, heading=heading, split=split,
                   notes=noted)
    placed = {}
    names = {"mechanism": term("mechanism", lang), "velocity": term("velocity_plan", lang), "acceleration": term("acceleration_plan", lang)}
    for kind, block in blocks.items():
        x, y, w, h = regions[kind]
        # every drawing in the top-left corner of its region (the plate's one arrangement: the scheme at the sheet's
        # top left whatever its shape, the plans beside and under it), its name and scale centred over it
        bx, by = x, y + CAPTION
        cw = min(max(block.width, 70.0), w)  # (a narrow drawing's caption wider than it, from the region's left)
        key = SCALE_OF[kind]
        caption = (f"#text(size: {TEXT_PT + 0.5}pt, weight: \"bold\")[{doc.words(names[kind])}] \\\n"
                   f"{doc.scale_markup(key, graphical.scales[key])}")
        doc.body.append(f"#place(top + left, dx: {x:.3f}mm, dy: {by - CAPTION:.3f}mm, block(width: {cw:.3f}mm, height: {CAPTION}mm)[#align(center)[{caption}]])")
        doc.add_image(kind, block)
        doc.body.append(f"#place(top + left, dx: {bx:.3f}mm, dy: {by:.3f}mm, {image(kind, block.width)})")
        placed[kind] = (page.margins[0] + bx, page.margins[2] + by, block.width, block.height)
    column = enlarged("\n".join(texts), text_scale)
    doc.body.append(f"#pad(left: {width + GUTTER:.3f}mm)[\n" + column + "]\n")
    return Sheet(doc.source(), doc.images, dict(graphical.scales), paper, placed, graphical)


def _objects(graphical) -> dict:
    out = {"mechanism": graphical, "velocity": graphical.velocity_plan}
    if graphical.acceleration_plan is not None:
        out["acceleration"] = graphical.acceleration_plan
    return out


def _extent(kind: str, obj) -> tuple[float, float]:
    """A drawing's geometry in physical units (the mechanism's joints [m], a plan's images and pole)."""
    return bbox(obj.positions.values()) if kind == "mechanism" else plan_extent(obj)


def _block(kind: str, graphical, lang: str, box=None, detail: bool = True):
    """The drawing of *kind* of *graphical*: a plan with its enlarged details beside it, else under it when that runs
    over *box*, without them only when both do (their lengths then stand in the plan's notes), or without *detail*."""
    from ..drawing.svgblocks import mechanism_svg, plan_svg

    if kind == "mechanism":
        return mechanism_svg(graphical, lang)  # (at its k_l alone: the cache of _fit_factors counts on it)
    plan = graphical.velocity_plan if kind == "velocity" else graphical.acceleration_plan
    def over(block) -> bool:
        return block.width > box[2] + 0.5 or block.height > box[3] - CAPTION + 0.5

    block = plan_svg(plan, lang, detail=detail)
    if detail and box is not None and over(block):
        block = plan_svg(plan, lang, detail=True, detail_under=True)
        if over(block):
            block = plan_svg(plan, lang, detail=False)
    return block


def _fit_factors(samples, construct_at, lang: str, given: dict, room, under=None):
    """(scales, regions, {sample index: (graphical, blocks)}) for one or more positions' solutions (*samples*)
    drawn at one k per kind, each the round factor with which the largest drawing of its kind fills its region.

    *construct_at(i, scales)*: sample *i* constructed at *scales*; *room*, *under*: :func:`_arrangements`.
    Returns None when drawings at given factors fit no arrangement.
    """
    kinds = list(_objects(samples[0]))
    if any(g.acceleration_plan is None for g in samples):
        kinds = [k for k in kinds if k != "acceleration"]
    extents = {}
    largest = {}
    for kind in kinds:
        per = [(_extent(kind, _objects(g)[kind]), i) for i, g in enumerate(samples)]
        extents[kind] = (max(e[0] for e, _ in per), max(e[1] for e, _ in per))
        largest[kind] = max(per, key=lambda p: p[0][0] + p[0][1])[1]
    scales = dict(samples[0].scales)
    drawn = {}  # a drawing is drawn once at its factors: the mechanism's at k_l, a velocity plan's at k_l, k_v
    regions = {}

    def block_at(i, kind, at, detail=True):
        """Sample *i*'s drawing of *kind* at *at* (*detail* "anywhere": a plan's details wherever they fall)."""
        key = (i, kind, detail) + tuple(at[k] for k in FACTORS_OF[kind]) + ((regions.get(kind),) if kind != "mechanism" else ())
        if key not in drawn:
            box = None if detail == "anywhere" else regions.get(kind)
            drawn[key] = _block(kind, construct_at(i, at), lang, box, bool(detail))
        return drawn[key]

    fixed = dict(ESTIMATED_FIXED)
    for kind in kinds:
        key = SCALE_OF[kind]
        if given.get(key) is not None:
            continue
        # a drawing's size at two factors tells what scales (the geometry; for the mechanism its guides and slots
        # drawn over the cycle's travel too) from what does not (labels, supports, notes): size = fixed + geometry / k
        i = largest[kind]
        k0 = samples[i].scales[key]
        # (a plan without its enlarged detail, which is drawn at some factors only)
        one, two = (block_at(i, kind, {**scales, key: k}, detail=kind == "mechanism") for k in (k0, 2 * k0))
        geometry = (2 * k0 * (one.width - two.width), 2 * k0 * (one.height - two.height))
        # what does not scale, from this sample's own geometry (the extents are the largest over the samples: a
        # sample's fixed parts reckoned against another's geometry would be too small)
        fixed[kind] = tuple(max(b - g / k0, 0.0) for b, g in zip((one.width, one.height), geometry))
        own = _extent(kind, _objects(samples[i])[kind])
        # the drawn geometry over the joints' (guides drawn over the travel, arcs): the same margin on every sample
        extents[kind] = tuple(max(g, e + max(g - o, 0.0)) for g, e, o in zip(geometry, extents[kind], own))
    given_sizes = {}
    for kind in kinds:
        if given.get(SCALE_OF[kind]) is not None:
            k = given[SCALE_OF[kind]]
            fx, fy = ESTIMATED_FIXED[kind]
            given_sizes[kind] = (extents[kind][0] / k + fx, extents[kind][1] / k + fy)
    needs = {kind: _needs(kind, [_objects(g)[kind] for g in samples]) for kind in kinds}
    best = None
    for chosen in _ranked_regions(room, extents, fixed, given_sizes, under, needs)[:TRIED]:
        regions.clear()
        regions.update(chosen)
        found = _factors_in(kinds, chosen, extents, largest, samples, scales, given, block_at, needs)
        if found is None:
            continue
        reached = min((length / found[SCALE_OF[kind]] / mm for kind in kinds if given.get(SCALE_OF[kind]) is None
                       for length, mm in needs[kind] if length > 0), default=1.0)
        if best is None or reached > best[0]:
            best = (reached, dict(chosen), found)
        if reached >= 1.0:
            break  # every drawing at its least size at least
    if best is None:
        return None
    _, chosen, factors = best
    regions.clear()
    regions.update(chosen)
    drawn_all = _every_sample(samples, kinds, chosen, factors, given, block_at, construct_at)
    if drawn_all is None:
        return None
    return drawn_all[0], chosen, drawn_all[1]


#: how many of the best arrangements are drawn before the one that gives every drawing its least size is taken
TRIED = 3


def _factors_in(kinds, regions, extents, largest, samples, first, given, block_at, needs=None):
    """The factors with which the largest drawing of each kind fills its region of *regions* (drawn and measured:
    :func:`plans.pages.document.fitted`, then finer while it still fits), given ones kept; a plan's factor a step
    coarser where that gives its enlarged details room and the plan keeps its least sizes (*needs*: :func:`_needs`)."""
    scales = dict(first)
    boxes = {kind: (regions[kind][2], regions[kind][3] - CAPTION) for kind in kinds}
    # one kind after the other, each constructed with the factors chosen before it (a plan reads the mechanism)
    for kind in kinds:
        key = SCALE_OF[kind]
        i = largest[kind]

        def draw(k, kind=kind, key=key, i=i):
            return block_at(i, kind, {**scales, key: k})

        scales[key], block = fitted(draw, extents[kind], boxes[kind], samples[i].scales[key], given.get(key))
        # finer while it still fits (what does not scale was over-reckoned): a step or three for one position's
        # drawing, one for several (each position's drawing of the kind must fit at it)
        for _ in range((3 if len(samples) == 1 else 1) if given.get(key) is None else 0):
            finer = round_down(scales[key] * 0.9999)
            trials = (block_at(j, kind, {**scales, key: finer}) for j in [i] + [j for j in range(len(samples)) if j != i])
            if any(t.width > boxes[kind][0] + 0.5 or t.height > boxes[kind][1] + 0.5 for t in trials):  # (the first over ends it)
                break
            scales[key] = finer
        if kind != "mechanism" and given.get(key) is None:
            coarsest = min((length / mm for length, mm in (needs or {}).get(kind, ()) if length > 0), default=math.inf)
            scales[key] = _room_for_details(lambda k, i=i, kind=kind, key=key: (lambda at: (
                block_at(i, kind, at), block_at(i, kind, at, detail=False), block_at(i, kind, at, detail="anywhere")))(
                {**scales, key: k}), scales[key], coarsest)
    return scales


#: How many round factors coarser a plan may be drawn to give its enlarged details room in its region.
DETAIL_STEPS = 2


def _room_for_details(drawings, k: float, coarsest: float = math.inf) -> float:
    """*k*, or the first of the next :data:`DETAIL_STEPS` coarser round factors at which a plan keeps the enlarged
    details it has (*drawings(k)*: the plan as fitted to its region, without details, with details anywhere): a
    detail is how a student measures ab, bc of a crowded cluster (six-bar velocity plan), worth a plan a step
    smaller, never coarser than *coarsest* (the plan's least sizes); when none gives them room *k* stands (the plan
    without them, their lengths in its notes)."""
    trial = k
    for _ in range(DETAIL_STEPS + 1):
        if trial > coarsest * (1 + 1e-9):
            return k
        boxed, bare, anywhere = drawings(trial)
        if boxed.svg != bare.svg or anywhere.svg == bare.svg:
            return trial  # the details kept, or none to keep
        trial = round_up(trial * 1.0001)
    return k


def _every_sample(samples, kinds, regions, first, given, block_at, construct_at):
    """(scales, {sample: (graphical, blocks)}): every sample drawn at the factors, a factor made coarser while a
    drawing of its kind still runs over its region; None when drawings at given factors do."""
    scales = dict(first)
    boxes = {kind: (regions[kind][2], regions[kind][3] - CAPTION) for kind in kinds}
    out = {}
    for _ in range(4):
        out, over = {}, {}
        for i in range(len(samples)):
            blocks = {kind: block_at(i, kind, scales) for kind in kinds}
            out[i] = (construct_at(i, scales), blocks)
            for kind, block in blocks.items():
                f = max(block.width / (boxes[kind][0] + 0.5), block.height / (boxes[kind][1] + 0.5))
                if f > 1.0 and given.get(SCALE_OF[kind]) is None:
                    over[kind] = max(over.get(kind, 1.0), f)
        if not over:
            break
        for kind, f in over.items():
            scales[SCALE_OF[kind]] = round_up(scales[SCALE_OF[kind]] * f * 1.0001)
    if any(block.width > boxes[kind][0] + 0.5 or block.height > boxes[kind][1] + 0.5
           for _, blocks in out.values() for kind, block in blocks.items()):
        return None  # drawings at given factors larger than this sheet's regions
    return scales, out


def _fits_one_page(sheet: Sheet) -> bool:
    """Whether the sheet's text stays on its one page (Typst flows what does not fit onto a second)."""
    return len(compile_document(sheet.source, sheet.images, "svg")) == 1


def _text_parts(scene, g, analytic, lang: str) -> dict:
    """What the text column of the sheet of *g* says besides its equations and readings: the results table (with
    *analytic*, the same position's analytic solution), the structural formula, the assembly, the plans' legend."""
    from ..compare import compare
    from ..drawing.sheet import translate_table
    from ..drawing.svgblocks import legend_svg
    from ..report import sheet_table
    from ..structure import find_structure

    plans = [p for p in (g.velocity_plan, g.acceleration_plan) if p is not None]
    if analytic is None:
        return {"table": None, "formula": find_structure(scene).formula, "assembly": (), "legend": legend_svg(plans, lang)}
    return {"table": translate_table(sheet_table(compare(analytic, g), g, analytic), lang), "formula": analytic.structure.formula,
            "assembly": assembly_lines(analytic.branches, scene, lang, g.positions), "legend": legend_svg(plans, lang)}


def _text_height(scene, g, parts: dict, lang: str, heading: str, paper: str) -> float:
    """The height [mm] of the sheet's text column (measured by Typst before the page is laid out): at its set size;
    where that does not fit the page's text area, its comparison table in two halves, and then reduced
    (:data:`TEXT_REDUCED`) as far as it takes to fit; over that at the least size (the sheet goes to a larger paper)."""
    room = sheet_page(paper).text_height
    heights = _text_heights(scene, g, parts, lang, heading, paper, (1.0,))
    if heights[0] <= room:  # (the common case measured alone: a Typst pass lays out every size it is asked)
        return heights[0]
    heights += _text_heights(scene, g, parts, lang, heading, paper, TEXT_REDUCED)
    if _splits(parts):
        halves = _text_heights(scene, g, parts, lang, heading, paper, (1.0,) + TEXT_REDUCED, split=True)
        heights = [min(a, b) for a, b in zip(heights, halves)]
    return next((h for h in heights if h <= room), heights[-1])


def _splits(parts: dict) -> bool:
    """Whether the comparison table of the text column's *parts* is long enough to be set in two halves."""
    return bool(parts.get("table")) and len(parts["table"]) > SPLIT_ROWS


def _text_heights(scene, g, parts: dict, lang: str, heading: str, paper: str, scales, split: bool = False) -> list[float]:
    """The heights [mm] of the sheet's text column with its text enlarged by each of *scales* (:func:`enlarged`),
    measured by Typst in one pass (*split*: :func:`_texts`)."""
    doc = Document(scene, lang, sheet_page(paper))
    doc.plate = dict(g.scales)
    texts = _texts(doc, g, heading=heading, split=split, **parts)
    column = "\n".join(texts)
    for n, f in enumerate(scales):
        doc.body.append(f"#let plans-texts-{n} = [\n" + enlarged(column, f) + "]")
    heights = ", ".join(f"measure(block(width: {TEXT_COLUMN}mm, plans-texts-{n})).height.mm()" for n in range(len(scales)))
    doc.body.append(f"#context [#metadata(({heights},)) <plans-text-height>]")
    return [float(h) for h in query_value(doc.source(), doc.images, "plans-text-height")]


def _text_layout(scene, g, parts: dict, lang: str, heading: str, paper: str, regions: dict) -> tuple[float, bool]:
    """(enlargement, split) of the text column: the largest enlargement of :data:`TEXT_SCALES`, 1 and
    :data:`TEXT_REDUCED` whose height fits the room the drawings leave it (:func:`_text_limit`; 0 where none does), the
    comparison table whole where that is as large as in two halves.

    A column grows with its text, so the largest that fits is found by bisection over the enlargements, each measured
    alone (a Typst pass lays out every size it is asked: 4 sizes measured, not 9, the largest first and alone)."""
    page = sheet_page(paper)
    scales = TEXT_SCALES + (1.0,) + TEXT_REDUCED
    limit = _text_limit(page, regions)

    def largest(split: bool) -> float:
        def fits(f: float) -> bool:
            return _text_heights(scene, g, parts, lang, heading, paper, (f,), split=split)[0] <= limit

        if fits(scales[0]):
            return scales[0]
        lo, hi = 1, len(scales)  # (the first that fits lies in [lo, hi); hi: none does)
        while lo < hi:
            mid = (lo + hi) // 2
            if fits(scales[mid]):
                hi = mid
            else:
                lo = mid + 1
        return scales[lo] if lo < len(scales) else 0.0

    whole = largest(False)
    if not _splits(parts) or whole == TEXT_SCALES[0]:
        return max(whole, TEXT_REDUCED[-1]), False
    halves = largest(True)
    # (a column that fits only with its table halved is set so; one that fits at no size, at the least)
    least = TEXT_REDUCED[-1]
    return (max(halves, least), True) if halves > whole else (max(whole, least), False)


def enlarged(markup: str, factor: float) -> str:
    """Typst *markup* with every text size it sets (``size: 8.0pt``) × *factor* (the legend, a drawing, as drawn)."""
    import re

    if factor == 1.0:
        return markup
    return re.sub(r"size: ([0-9.]+)pt", lambda m: f"size: {float(m.group(1)) * factor:.2f}pt", markup)


#: how much a sheet's text column may be enlarged (its tables, equations and readings set at 8–9.5 pt, at 1.25 at
#: 10–12 pt), the largest first: the largest that still fits over the drawings placed under it and the title block
TEXT_SCALES = (1.25, 1.2, 1.15, 1.1, 1.05)
#: how far a text column too long for A3 at its set size is reduced before the sheet goes to a larger paper (the
#: equations' 9.5 pt to 8.1 pt, the tables' 8 pt to 6.8 pt at 0.85: the linear-arm's sheet, whose equations place
#: every image)
TEXT_REDUCED = (0.95, 0.9, 0.85)


def _text_limit(page: PageGeometry, regions: dict) -> float:
    """The height [mm] the text column may take: down to the first drawing placed under it (*regions*: kind ->
    (x, y, w, h) [mm] in the text area), else to the title block; the drawings keep their regions and factors."""
    width, _ = _drawing_room(page)
    tops = [y for x, y, w, h in regions.values() if x >= width]
    return min(tops, default=page.text_height + GUTTER + 3.0) - GUTTER - 3.0


def _under(page: PageGeometry, text_height: float):
    """The room (x, y, w, h) [mm] under a text column of *text_height*, over the title block."""
    width, _ = _drawing_room(page)
    y = text_height + GUTTER + 3.0
    return (width + GUTTER, y, page.text_width - width - GUTTER, page.text_height - y)


def fitted_sheet(scene, graphical, analytic, construct_at, *, lang: str = "en", given: dict | None = None,
                 heading: str = "", number: tuple[int, int] | None = None) -> Sheet:
    """The sheet of one position, its factors chosen for its regions (see the module).

    *graphical*: the solution at first factors (the scene's or automatic); *construct_at(scales)*: the
    solution constructed at other factors (the caller's: drawing never solves); *analytic*: the analytic
    solution of the same position (the results table and the assembly); *given*: factors kept as given
    (``{"k_l": …}``, None for those to choose).
    """
    given = {key: value for key, value in (given or {}).items() if value is not None}
    parts = _text_parts(scene, graphical, analytic, lang)
    cache = {}

    def constructed(i, scales):
        key = tuple(scales.get(k) for k in ("k_l", "k_v", "k_a"))
        if key not in cache:
            cache[key] = construct_at(scales)
        return cache[key]

    for paper, _ in PAPERS:
        page = sheet_page(paper)
        last = paper == PAPERS[-1][0]
        height = _text_height(scene, graphical, parts, lang, heading, paper)
        if height > page.text_height and not last:
            continue  # the text does not fit its column: a larger sheet
        found = _fit_factors([graphical], constructed, lang, given, _drawing_room(page), _under(page, height))
        if found is None:
            continue
        scales, regions, out = found
        g, blocks = out[0]
        text = _text_parts(scene, g, analytic, lang)
        text_scale, split = _text_layout(scene, g, text, lang, heading, paper, regions)
        sheet = build_sheet(scene, g, blocks, regions, lang=lang, heading=heading, paper=paper, number=number,
                            text_scale=text_scale, split=split, **text)
        if last or _fits_one_page(sheet):
            return sheet
    from ..errors import PlansError

    raise PlansError("the drawings at the factors given are larger than A0: give larger scale factors (--k-l, --k-v, --k-a)")


def sheet_at(graphical, analytic=None, *, lang: str = "en", heading: str = "", number: tuple[int, int] | None = None) -> Sheet:
    """The sheet of *graphical* at its own factors (nothing constructed: a notebook's or a position's sheet), the
    regions arranged for its drawings; with *analytic* (the same position's), the results table and the assembly."""
    scene = graphical.scene
    kinds = _objects(graphical)
    parts = _text_parts(scene, graphical, analytic, lang)
    blocks = {kind: _block(kind, graphical, lang) for kind in kinds}
    sizes = {kind: (b.width, b.height) for kind, b in blocks.items()}
    extents = {kind: _extent(kind, obj) for kind, obj in kinds.items()}
    for paper, _ in PAPERS:
        page = sheet_page(paper)
        last = paper == PAPERS[-1][0]
        height = _text_height(scene, graphical, parts, lang, heading, paper)
        needs = {kind: _needs(kind, [obj]) for kind, obj in kinds.items()}
        regions = _choose_regions(_drawing_room(page), extents, ESTIMATED_FIXED, sizes, _under(page, height), needs)
        if regions is None and not last:
            continue
        regions = regions or _arrangements(_drawing_room(page), list(kinds))[0]
        sheet = build_sheet(scene, graphical, blocks, regions, lang=lang, heading=heading, paper=paper, number=number, **parts)
        if last or _fits_one_page(sheet):
            return sheet


def position_heading(r, lang: str) -> str:
    """The position of a sheet in words: ``Position 3:  φ₂ = 90.0°``."""
    return f"{term('position', lang)} {r.index}:  {r.label}"


def position_sheets(run, *, lang: str = "en", given: dict | None = None, progress=None) -> tuple[list, dict]:
    """The sheets of a multi-position run's solved positions, all at one k_l, one k_v, one k_a (each the factor
    with which the largest drawing of its kind fills its region; given ones kept), each titled with its position
    and numbered n of m (m: the solved positions and the plan of positions).  Returns ``([(run, Sheet)…], scales)``.
    """
    from ..compare import compare
    from ..errors import PlansError
    from ..graphical import construct

    say = progress or (lambda words: None)
    given = {key: value for key, value in (given or {}).items() if value is not None}
    solved = [r for r in run.runs if r.ok]
    if not solved:
        return [], {}
    cache = {}

    def construct_at(i, scales):
        key = (i, tuple(sorted((k, v) for k, v in scales.items() if v is not None)))
        if key not in cache:
            r = solved[i]
            g = construct(r.scene, run.structure, k_l=scales["k_l"], k_v=scales["k_v"], k_a=scales.get("k_a"), precision=run.precision,
                          check_scales=False)
            cache[key] = replace(g, travel=r.graphical.travel, cycle_poses=r.graphical.cycle_poses)
        return cache[key]

    samples = [r.graphical for r in solved]
    total = len(solved) + 1
    names = [name for name, _ in PAPERS]
    parts = [_text_parts(r.scene, r.graphical, r.analytic, lang) for r in solved]
    for paper in names:
        page = sheet_page(paper)
        # the tallest text column of all the sheets: the drawings under it clear every sheet's
        height = max(_text_height(r.scene, r.graphical, p, lang, position_heading(r, lang), paper) for r, p in zip(solved, parts))
        if height > page.text_height and paper != names[-1]:
            continue
        found = _fit_factors(samples, construct_at, lang, given, _drawing_room(page), _under(page, height))
        if found is not None:
            break
    else:
        raise PlansError("the drawings at the factors given are larger than A0: give larger scale factors (--k-l, --k-v, --k-a)")
    scales, regions, out = found
    texts = [_text_parts(r.scene, out[i][0], r.analytic, lang) for i, r in enumerate(solved)]
    # one size of text over the set: the enlargement every sheet's column takes (each sheet's table whole or halved)
    layouts = [_text_layout(r.scene, out[i][0], t, lang, position_heading(r, lang), paper, regions) for i, (r, t) in enumerate(zip(solved, texts))]
    text_scale = min(f for f, _ in layouts)
    sheets = []
    for i, r in enumerate(solved):
        say(f"sheet {i + 2}/{total}")
        g, blocks = out[i]
        h = replace(r, graphical=g, comparisons=compare(r.analytic, g))
        sheet = build_sheet(r.scene, g, blocks, regions, lang=lang, heading=position_heading(r, lang), paper=paper,
                            number=(i + 2, total), text_scale=text_scale, split=layouts[i][1], **texts[i])
        sheets.append((h, sheet))
    return sheets, scales


def _driver_position(scene) -> str:
    """The driver's position the sheet is drawn at: ``φ₂ = 30.0°`` (a crank, from the x axis, counter-clockwise) or
    ``s = 20.0 mm`` (a sliding driver: along its guide from the guide's origin, the symbol of its stroke ``s ∈ […]``)."""
    from .._text import subscript
    from ..scene import Crank

    driver = scene.driver
    if isinstance(driver, Crank):
        degrees = round(math.degrees(driver.phi) % 360.0, 1) % 360.0
        return f"φ{subscript(driver.link)} = {degrees:.1f}°"
    return f"s = {driver.s * 1e3:.1f} mm".replace("-", "\u2212")


def _capitalised(line: str) -> str:
    """A line of data as a sentence: its first word capitalised (a symbol such as θ or ω₂ is left as written)."""
    import re

    return line[:1].upper() + line[1:] if re.match(r"[^\W\d_]{2}", line) else line


#: the size [pt] of the plan of positions' data (the driver's law, the stroke, θ, K, the working stroke)
DATA_PT = TEXT_PT + 1.0
#: the height [mm] of a line of the plan of positions' data (at DATA_PT)
DATA_LINE = 5.2
#: the room [mm] between the plan of positions and its data under it; the least it closes to so that the plan keeps
#: a set's k_l (one k_l across the plate) when it runs over its room by no more than the difference
DATA_GAP = 6.0
DATA_GAP_MIN = 2.0


def positions_page(run, k_l: float | None = None, *, lang: str = "en", number: tuple[int, int] | None = None) -> Sheet:
    """The plan of positions of *run* on a sheet of its own (sheet 1 of a set, the textbook's order), drawn at *k_l*
    (a set of sheets': the positions' sheets' k_l, one k_l across the plate; the data's gap under it closes first,
    to :data:`DATA_GAP_MIN`, and a coarser round one only when it still runs over the page), or without one at the round factor with which it fills the page; its k_l is stated under its
    name and in the title block.  The cycle's data (the driver's law, the Grashof class, the stroke, θ and K, the
    working stroke) under the drawing, left-aligned with it, at :data:`DATA_PT`."""
    import numpy as np

    from ..drawing.svgblocks import positions_svg
    from .words import cycle_lines

    page = sheet_page("A3")
    doc = Document(run.scene, lang, page)
    lines = [_capitalised(line) for line in cycle_lines(run, lang)]
    # the data lines under the drawing, over the title block
    under = len(lines) * DATA_LINE + DATA_GAP if lines else 0.0
    room = (page.text_width, page.text_height - CAPTION - 2.0 - under)
    extremes = run.other_extreme()
    zs = [complex(z) for r in run.runs if r.ok for z in r.graphical.positions.values()]
    zs += [complex(z) for g in extremes.values() for z in g.positions.values()]
    for p in run.scene.report:
        if p in run.cycle.points:
            path = np.asarray(run.cycle.points[p].r)
            zs.extend(complex(z) for z in path[np.isfinite(path.real) & np.isfinite(path.imag)])
    k0 = run.scales["k_l"] if k_l is None else k_l
    given = k_l is not None
    k_l, block = fitted(lambda k: positions_svg(run, k, lang, extremes), bbox(zs), room, k0, None if k_l is None else k_l)
    gap = DATA_GAP
    if given and lines and block.width <= room[0] + 0.5 and room[1] + 0.5 < block.height <= room[1] + DATA_GAP - DATA_GAP_MIN:
        # the set's k_l kept: the data's gap under the drawing closes (to DATA_GAP_MIN at least) before the scale changes
        gap, room = DATA_GAP - (block.height - room[1]), (room[0], block.height)
    for _ in range(6):  # a given factor coarser while it runs over the page
        if block.width <= room[0] + 0.5 and block.height <= room[1] + 0.5:
            break
        k_l = round_up(k_l * max(block.width / room[0], block.height / room[1]) * 1.0001)
        block = positions_svg(run, k_l, lang, extremes)
    doc.plate = {"k_l": k_l}
    doc.sheet_number = number
    doc.body.append(f"#align(center)[#text(size: {TEXT_PT + 1.5}pt, weight: \"bold\")[{doc.words(term('positions_plan', lang))}] \\\n"
                    f"{doc.scale_markup('k_l', k_l)}]\n")
    y = CAPTION + 2.0 + max(room[1] - block.height, 0.0) / 2  # the drawing in the middle of its room
    x = (page.text_width - block.width) / 2
    if lines:  # under the drawing, from its left edge (the page's left for a drawing as wide as the page)
        text = " \\\n".join(doc.words(formula_words(line)) for line in lines)
        left = min(max(x, 0.0), page.text_width / 2)
        doc.body.append(f"#place(top + left, dx: {left:.3f}mm, dy: {y + block.height + gap:.3f}mm, block(width: {page.text_width - left:.1f}mm)"
                        f"[#text(size: {DATA_PT}pt)[{text}]])\n")
    doc.body.append(f"#place(top + left, dx: {x:.3f}mm, dy: {y:.3f}mm, {image('positions', block.width)})")
    doc.add_image("positions", block)
    return Sheet(doc.source(), doc.images, {"k_l": k_l}, "A3", {"positions": (page.margins[0] + x, page.margins[2] + y, block.width, block.height)})


# --- files -----------------------------------------------------------------------------------------


def write_drawings(sheet, directory, *, lang: str = "en", format: str = "svg") -> list[Path]:
    """Write ``mechanism.svg``, ``velocity.svg``, ``acceleration.svg`` (the drawings of the sheet's solution, as
    drawings) and ``sheet.svg`` (*sheet*, the page), or ``.pdf``, ``.png`` (*format*).

    *sheet*: a :class:`Sheet` (:func:`fitted_sheet`), or a GraphicalSolution, whose sheet is then set at its own
    factors (:func:`sheet_at`: its drawings, equations and readings; no table against analytic values, which a
    solution alone does not carry).

    All are rendered in memory first and written atomically together (:func:`plans._files.replace_all`): a
    failure leaves every existing file as it was.  ``acceleration.svg`` is written only when the solution has an
    acceleration plan; an old one in *directory* is then removed if plans wrote it (and nobody changed it since).
    """
    from .._files import replace_all
    from ..drawing.formats import render
    from ..drawing.mechanism import draw_mechanism
    from ..drawing.plan_drawing import draw_plan

    if not isinstance(sheet, Sheet):
        sheet = sheet_at(sheet, lang=lang)
    solution = sheet.graphical
    directory = Path(directory)
    contents: dict[Path, bytes] = {}
    contents[directory / f"mechanism.{format}"] = render(draw_mechanism(solution, lang=lang)[0].figure, format)
    contents[directory / f"velocity.{format}"] = render(draw_plan(solution.velocity_plan, lang=lang)[0].figure, format)
    if solution.acceleration_plan is not None:
        contents[directory / f"acceleration.{format}"] = render(draw_plan(solution.acceleration_plan, lang=lang)[0].figure, format)
    contents[directory / f"sheet.{format}"] = sheet.render(format)
    if format != "svg":  # the record of what plans wrote is an SVG comment: other formats remove nothing
        return replace_all(contents)
    return replace_all(contents, stale=(directory, r"acceleration\.svg", "sheet.svg"))


def write_position_sheets(run, directory, *, lang: str = "en", format: str = "svg", given: dict | None = None, progress=None) -> list[Path]:
    """Write ``sheet-00.svg``, ``sheet-01.svg``, … (a sheet per solved position, :func:`position_sheets`) and
    ``positions.svg`` (the plan of positions at the sheets' k_l), or ``.pdf``, ``.png`` (*format*).

    A position that cannot be solved gets no sheet.  All files are written together, atomically; sheets of an
    earlier run with more positions that plans wrote (and nobody changed since) are removed; other files in
    *directory* are never touched.  Returns the sheets in position order, then the plan of positions.
    """
    from .._files import replace_all

    directory = Path(directory)
    say = progress or (lambda words: None)
    total = len(run.runs)
    width = max(2, len(str(total - 1)))
    sheets, scales = position_sheets(run, lang=lang, given=given, progress=say)
    contents: dict[Path, bytes] = {}
    for r, sheet in sheets:
        contents[directory / f"sheet-{r.index:0{width}d}.{format}"] = sheet.render(format)
    files = len(sheets) + 1
    say(f"sheet 1/{files}")
    # the plan of positions at the sheets' k_l: one k_l across the plate (the schemes can be laid over it)
    contents[directory / f"positions.{format}"] = positions_page(run, scales.get("k_l"), lang=lang, number=(1, files)).render(format)
    if format != "svg":
        return replace_all(contents)
    return replace_all(contents, stale=(directory, r"sheet-\d+\.svg", "positions.svg"))
