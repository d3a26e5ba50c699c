"""The Typst document every page of plans is set in: handout pages, centres pages and the A3 sheets.

A :class:`Document` is Typst source built section by section — headings,
lines of the program's text in the page's language (:mod:`plans.pages.words`),
vector equations, tables, drawings placed at their physical size
(:mod:`plans.drawing.svgblocks`) — on pages of a :class:`PageGeometry`: a
frame 20 mm from the bound edge and 5 mm from the others, with the plate's
title block (plate name, scene title, sheet n of m, scale factors, drawn by /
checked by / date) in the lower right corner.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import math

from ..graphical.scales import round_up
from ..i18n import term
from .._text import decimal_comma
from .equations import PlacementRow, placement_math, step_lines
from .typesetting import FONT as _FONT, MATH_FONT as _MATH, image, mixed, string, text
from .words import block_words, units

__all__ = ["bbox", "plan_extent", "fit_factor", "fitted", "fitted_line", "formula_parts", "Document", "PageGeometry", "A4_PORTRAIT", "A3_LANDSCAPE", "GUTTER", "HEADING_ABOVE", "TEXT_PT", "SMALL_PT", "TITLE_BLOCK_LEAST_PT"]

#: The space above a heading (a block that starts with a heading is given it: a heading inside a block does not bring it).
HEADING_ABOVE = "1.1em"
GUTTER = 5.0  # mm between drawings and between columns
TEXT_PT = 9.5
SMALL_PT = 8.0
#: the least size [pt] of the title block's words (the plate's name and the scene's title): a long title wraps to
#: two lines rather than shrink below it
TITLE_BLOCK_LEAST_PT = 8.0


@dataclass(frozen=True)
class PageGeometry:
    """A page [mm]: its *size*, the frame's distance from the bound (left) edge and from the others, the text
    area's *margins* (left, right, top, bottom: the bottom one keeps the title block clear) and the title
    block's width (the whole frame's width, or *title_block_width* in the lower right corner)."""

    size: tuple[float, float]
    frame: tuple[float, float]
    margins: tuple[float, float, float, float]
    title_block_width: float | None = None

    @property
    def text_width(self) -> float:
        return self.size[0] - self.margins[0] - self.margins[1]

    @property
    def text_height(self) -> float:
        return self.size[1] - self.margins[2] - self.margins[3]

    @property
    def title_block_side(self) -> str:
        return "left" if self.title_block_width is None else "right"

    @property
    def title_block_dx(self) -> float:
        return self.frame[0] if self.title_block_width is None else -self.frame[1]


#: the handout's page: A4 portrait, the title block across the frame's foot
A4_PORTRAIT = PageGeometry((210.0, 297.0), (20.0, 5.0), (25.0, 10.0, 10.0, 36.0))
#: the sheet's page: A3 landscape, the title block (185 mm, as ISO 7200's) in the lower right corner
A3_LANDSCAPE = PageGeometry((420.0, 297.0), (20.0, 5.0), (25.0, 10.0, 10.0, 10.0), title_block_width=185.0)


# --- drawings fitted to the room a page gives them (the handout and the sheets) -----------------


def bbox(points) -> tuple[float, float]:
    """(width, height) of the points' bounding box (complex numbers; in their units)."""
    zs = list(points)
    if not zs:
        return 0.0, 0.0
    xs = [z.real for z in zs]
    ys = [z.imag for z in zs]
    return max(xs) - min(xs), max(ys) - min(ys)


def plan_extent(plan) -> tuple[float, float]:
    """The plan's extent in physical units [m/s or m/s²] (its images and the pole)."""
    return bbox([z * plan.scale for z in plan.images.values()] + [0j])


def fit_factor(extent, box, fixed) -> float:
    """The round factor with which a drawing of *extent* (physical) plus *fixed* [mm] fits *box* [mm]."""
    need = 0.0
    for e, b, f in zip(extent, box, fixed):
        if e > 0:
            need = max(need, e / max(b - f, 0.25 * b))
    return round_up(need) if need > 0 and math.isfinite(need) else 0.0


def fitted(draw, extent, box, k0: float, given: float | None):
    """(k, block): the round factor with which ``draw(k)`` fits *box*, measured (at most a few drawings), and the drawing at it.

    The part that does not scale (labels, margins, supports) is what the
    first drawing takes beyond ``extent / k``; the factor is then the
    smallest round one that gives the rest to the geometry, larger ones
    while the drawing still runs over the box.
    """
    if given is not None:
        return given, draw(given)
    block = draw(k0)
    fixed = (block.width - extent[0] / k0, block.height - extent[1] / k0)
    k = fit_factor(extent, box, fixed) or k0
    for _ in range(6):
        if k != k0:
            block = draw(k)
        if block.width <= box[0] + 0.5 and block.height <= box[1] + 0.5:
            break
        k0, k = k, round_up(k * 1.0001)
    return k, block


#: a symbol with a subscript written in plain text (``t_w``), or a ``$…$`` part left as it is
#: a formula that must not break across lines: ``ω₂ = 6 rad/s``, ``$k_l$ = 0,006 m/mm``, ``|a_A| = 0`` (a name, ``=``, a
#: number and its unit, if any; ``$…$`` math whole)
_FORMULA = re.compile(r"(?:\$[^$]*\$|[^\s=$]+) = [−-]?\d+(?:[.,]\d+)*"
                      r"(?: \(?(?:rad|m|mm|µm|s|N|kg|м|мм|с|мкм|Н|кг)(?![^\W\d_])[^\s,;]*|(?=[\s;)]|,\s|,?$))|\$[^$]*\$")


#: a ``$…$`` formula standing alone up to this many characters is kept on one line too (``ω_k = ±v_A / P₁ₖP₂ₖ`` in a
#: rule's words); a longer one may break where Typst breaks math
SHORT_MATH = 60


def formula_parts(line: str) -> list[tuple[str, bool]]:
    """*line* cut into ``(piece, formula)``: a formula (``ω₂ = 6 rad/s``, or ``$…$`` math standing alone up to
    :data:`SHORT_MATH` characters) is set in one box on a page, never broken across lines; the rest as it is."""
    out: list[tuple[str, bool]] = []
    last = 0
    for m in _FORMULA.finditer(line):
        alone = m.group(0).startswith("$") and m.group(0).endswith("$") and m.group(0).count("$") == 2
        if " = " not in m.group(0) or (alone and len(m.group(0)) > SHORT_MATH):
            continue
        if m.start() > last:
            out.append((line[last:m.start()], False))
        out.append((m.group(0), True))
        last = m.end()
    if last < len(line):
        out.append((line[last:], False))
    return out


def fitted_line(content: str, size_pt: float, least_pt: float = 8.0) -> str:
    """Typst code setting *content* (a content expression) at *size_pt*, or smaller so that it fits the width it is
    given on one line (measured by Typst), never under *least_pt* (there it wraps)."""
    return (f"#layout(room => {{ let body(s) = {{ set text(size: s); {content} }}; "
            f"let w = measure(body({size_pt}pt)).width; "
            f"if w <= room.width {{ body({size_pt}pt) }} else {{ body(calc.max({least_pt}pt, {size_pt}pt * (room.width / w) * 0.99)) }} }})")


_SUBSCRIPTED = re.compile(r"\$[^$]*\$|(?<![\w\\])([A-Za-zα-ωΑ-Ω])_([A-Za-z0-9]+)(?!\w)")


#: the equations' rows' padding above and below [mm], on handout pages and sheets alike, whatever size a sheet sets its
#: column at (a double underline's second rule, a fixed 1.7 pt under its row, clears the arrows of the row under it)
ROW_INSET_MM = 1.5


class Document:
    """Typst source built section by section: text, equations, tables and drawings (SVG inputs)."""

    def __init__(self, scene, lang: str, page: "PageGeometry | None" = None):
        self.scene, self.lang = scene, lang
        self.page = page or A4_PORTRAIT
        self.body: list[str] = []
        self.images: dict[str, bytes] = {}
        self.sizes: dict[str, tuple[float, float]] = {}
        self.order: list[str] = []
        self.plate: dict = {}
        self.per_position = None
        #: the size of the loop equations' text against its own (:meth:`loop_block`; a flow fitted to its pages)
        self.loops_scale = 1.0
        #: the plate's name in the title block (an i18n key): a section that is not kinematics (the force pages)
        #: sets it before its first heading and sets it back after its last page
        self.plate_name = "plate_title"
        self._named = "plate_title"
        #: (n, m) of a set of one-page documents (a sheet of ``plans draw --positions``); None: the pages counted
        self.sheet_number: tuple[int, int] | None = None

    # words
    def words(self, line: str) -> str:
        """A line of the program's text (with ``$…$`` math) as markup in the page's language, names and units."""
        for name in self.scene.names:
            # after ∥ the name in the form that reads there ("∥ направляющей ползуна")
            line = re.sub(rf"∥ {re.escape(name)}(?!\w)", lambda m: "∥ " + self.scene.name_in(name, self.lang, "parallel"), line)
            called = self.scene.name_in(name, self.lang)
            # a name already in the page's words (a data line's "ram guide" for the guide ram) is left as it is
            line = re.sub(rf"(?<![\w.]){re.escape(name)}(?!\w)",
                          lambda m: m.group(0) if m.string.startswith(called, m.start()) else called, line)
        line = _SUBSCRIPTED.sub(lambda m: m.group(0) if m.group(0).startswith("$") else f"${m.group(1)}_{{{m.group(2)}}}$", line)
        line = units(decimal_comma(line, self.lang), self.lang)
        return "".join(f"#box[{mixed(piece)}]" if formula else mixed(piece) for piece, formula in formula_parts(line))

    def section(self, name: str) -> None:
        self.order.append(name)

    def heading(self, words: str, level: int = 2, new_page: bool = False) -> None:
        if new_page and self.body:
            self.body.append("#pagebreak(weak: true)")
        self.body.append("=" * level + " " + self.words(words))
        if new_page and self.plate_name != self._named:
            # the title block is set at the page's end: the name changes on the page a section starts
            self.body.append(f"#plate-name.update({string(term(self.plate_name, self.lang))})")
            self._named = self.plate_name

    def title(self, plate: str, title: str) -> None:
        """The first page's heading as a plate prints it: the plate's name (a level-1 heading), the scene's *title*
        on its own line under it, one line: set smaller where it is long (:func:`fitted_line`, down to 8 pt; below
        that it wraps)."""
        self.body.append("= " + self.words(plate))
        self.body.append(fitted_line(f"text(weight: \"bold\")[{self.words(title)}]", 12.0) + "\n")

    def line_markup(self, words: str, size: float = TEXT_PT) -> str:
        return f"#text(size: {size}pt)[{self.words(words)}]"

    def line(self, words: str, size: float = TEXT_PT) -> None:
        self.body.append(self.line_markup(words, size) + "\n")

    def headed_legend(self, heading: str, under: str, key: str, legend) -> None:
        """A heading and a line under it on the left, a drawing's legend on the right (one band across the page),
        kept with the first row of what follows it (never left at a page's foot)."""
        self.body.append(f"#block(sticky: true, breakable: false)[#grid(columns: (1fr, auto), column-gutter: {GUTTER}mm, align: (left + top, right + top),\n"
                         f"  [#heading(level: 2, {string(heading)})\n{under}], [#{self.add_image(key, legend)}])]\n")

    def headed_line(self, heading: str, under: str, level: int = 2) -> None:
        """A heading with a line under it (its scale), kept with what follows them."""
        self.body.append(f"#block(sticky: true, breakable: false)[#heading(level: {level}, {string(heading)})\n{under}]\n")

    def lines(self, lines, size: float = TEXT_PT) -> None:
        for line in lines:
            self.line(line, size)

    def scale_markup(self, key: str, value: float) -> str:
        from ..drawing._canvas import fmt_number
        from ..drawing.numerals import scale_caption

        unit = {"k_l": "m/mm", "k_v": "(m/s)/mm", "k_a": "(m/s²)/mm"}[key]
        return self.line_markup(scale_caption(key, fmt_number(value), unit, self.lang), size=TEXT_PT)

    def scale_words(self, key: str, value: float) -> str:
        """``k_l = 0,006 m/mm`` as markup (the title block's words for a scale factor)."""
        from ..drawing._canvas import fmt_number

        unit = {"k_l": "m/mm", "k_v": "(m/s)/mm", "k_a": "(m/s²)/mm"}[key]
        return self.words(f"${key[0]}_{{{key[2]}}}$ = {fmt_number(value)} {unit}")

    def scale_line(self, key: str, value: float) -> None:
        self.body.append(self.scale_markup(key, value) + "\n")

    def listing(self, heading: str, entries) -> None:
        cells = ", ".join(f"[{self.words(e)}]" for e in entries)
        self.body.append(f"#block(breakable: false)[#text(weight: \"bold\")[{text(heading)}] \\\n"
                         f"#text(size: {SMALL_PT}pt)[#grid(columns: 3, column-gutter: 6mm, row-gutter: 1.6mm, {cells})]]\n")

    def add_image(self, key: str, block) -> str:
        self.images[key] = block.svg
        self.sizes[key] = (block.width, block.height)
        return image(key, block.width)

    def figure(self, key: str, block) -> None:
        if block is None:
            return
        self.body.append(f"#align(center)[#{self.add_image(key, block)}]\n")

    def full_page(self, key: str, block, scale_note: str | None = None) -> None:
        """A drawing that is a page of its own (a page of diagrams), fitted to the text area.

        *scale_note*: a scale the page's drawing adds to the title block's (a force plans' μ_F).
        """
        scale = min(self.page.text_width / block.width, self.page.text_height / block.height, 1.0)
        self.images[key] = block.svg
        self.sizes[key] = (block.width * scale, block.height * scale)
        note = f"#metadata([{self.words(scale_note)}]) <plans-page-scale>\n" if scale_note else ""
        note += "#context [#metadata(here().page()) <plans-full-page>]\n"  # (the pages that stand alone, for a reader of the flow)
        self.body.append(f"#pagebreak(weak: true)\n{note}#align(center)[#image(bytes(sys.inputs.at({string(key)})), format: \"svg\", width: {block.width * scale:.3f}mm)]\n")

    def captioned(self, caption: str, key: str, block, size: float = SMALL_PT + 0.5) -> None:
        """A line of words over a drawing placed at its physical size, left-aligned, kept together on a page."""
        self.body.append(f"#block(breakable: false, below: 2.5mm)[#text(size: {size}pt)[{self.words(caption)}] \\\n"
                         f"#{self.add_image(key, block)}]\n")

    def legend(self, items, size: float = SMALL_PT) -> None:
        """A legend in one line: (colour ``"#rrggbb"``, width [pt], dashed, words) per kind of line drawn."""
        parts = []
        for colour, width, dashed, words in items:
            stroke = f"(paint: rgb({string(colour)}), thickness: {width}pt{', dash: (3pt, 2pt)' if dashed else ''})"
            parts.append(f"#box(baseline: -0.6mm, line(length: 6mm, stroke: {stroke})) {self.words(words)}")
        self.body.append(f"#text(size: {size}pt)[" + " #h(4mm) ".join(parts) + "]\n")

    def grouped_table(self, heading: str, first, groups, second, body, size: float = SMALL_PT) -> None:
        """A table across the page with a two-row header: *first* (the first cells; from each group's start column
        its words span *groups*' columns: ``(start, words)``, five columns each), *second* under it, *body* rows.
        The first column left, the others right; breakable over pages with its header repeated."""
        ncol = len(second)
        starts = dict(groups)
        top, c = [], 0
        while c < ncol:
            if c in starts:
                span = next((s for s in sorted(starts) if s > c), ncol) - c
                top.append(f"table.cell(colspan: {span}, align: center)[#text(weight: \"bold\")[{self.words(starts[c])}]]")
                c += span
            else:
                top.append(f"text(weight: \"bold\")[{self.words(first[c])}]")
                c += 1
        rules = ", ".join(f"table.hline(y: 1, start: {s}, end: {next((t for t in sorted(starts) if t > s), ncol)}, stroke: 0.4pt)" for s in sorted(starts))
        under = ", ".join(f"text(weight: \"bold\")[{self.words(cell)}]" for cell in second)
        rows = ", ".join(", ".join(f"[{self.words(cell)}]" for cell in row) for row in body)
        whole = "true" if len(body) > 40 else "false"  # a table that fits a page is never parted from its heading
        self.body.append(f"#block(breakable: {whole})[#block(below: 2mm)[#text(weight: \"bold\", size: {SMALL_PT + 1}pt)[{self.words(heading)}]]\n"
                         f"#text(size: {size}pt)[#table(columns: {ncol}, stroke: none, inset: (x: 1.1mm, y: 0.8mm), align: (x, y) => if x == 0 {{ left }} else {{ right }},\n"
                         f"  table.header(table.hline(stroke: 0.8pt), {', '.join(top)}, {rules}, {under}, table.hline(stroke: 0.5pt)),\n"
                         f"  {rows}, table.hline(stroke: 0.8pt))]]\n")

    def grid(self, cells, columns: int) -> None:
        """Drawings with captions, *columns* across, flowing over pages (a cell never split)."""
        items = []
        column = 0  # where the next cell falls in its row (a cell across the page starts a row of its own)
        for caption, drawing, extra, *across in cells:
            parts = [f"#text(size: {SMALL_PT + 0.5}pt, weight: \"bold\")[{self.words(caption)}]"]
            if extra:
                parts.append(f"#text(size: {SMALL_PT}pt)[{self.words(extra)}]")
            if drawing is not None:
                key, block = drawing
                parts.append(f"#align(center)[#{self.add_image(key, block)}]")
            cell = "block(breakable: false, width: 100%)[" + " \\\n".join(parts[:-1] + [parts[-1]]) + "]"
            if across and across[0]:
                if column:
                    items.append(f"grid.cell(colspan: {columns - column})[]")
                items.append(f"grid.cell(colspan: {columns})[#{cell}]")
                column = 0
            else:
                items.append(cell)
                column = (column + 1) % columns
        self.body.append(f"#grid(columns: {columns}, column-gutter: {GUTTER}mm, row-gutter: 4mm, align: top + left,\n  " + ",\n  ".join(items) + ")\n")

    def equations(self, heading: str, steps, name, new_page: bool = False, similar=None, flow: bool = False) -> None:
        """The vector equations of the plans' steps under *heading*, with the note on the underlines: one block,
        never parted from its heading (*flow*: the rows flow on over a page's end, a group's whole, the heading kept
        with the first); *similar*: step index -> the rows placing the images no step places
        (:func:`plans.pages.equations.placement_rows`; a text: a proportion by similarity) once that step is drawn,
        after the step's rows (-1: before the first step)."""
        from .words import group_words

        if new_page and self.body:
            self.body.append("#pagebreak(weak: true)")
        rows = []
        similar = similar or {}

        def group(who: str, cells) -> None:  # a group's rows (its name a cell spanning them; not an unbreakable cell:
            # Typst then drops the second rule of a double underline in those rows, found on the six-bar handout)
            for k, cell in enumerate(cells):
                rows.append((f"table.cell(rowspan: {len(cells)})[{text(who)}], " if k == 0 else "") + cell)

        def by_similarity(index: int) -> None:  # the rows of one column word (a link's number, "by similarity") as one group
            cells: list[tuple[str, list[str]]] = []
            for row in similar.get(index, ()):
                row = PlacementRow("by_similarity", "proportion", row) if isinstance(row, str) else row
                who = term(row.who, self.lang) if row.who in ("fixed_points", "by_similarity") else f"{term('link', self.lang)} {row.who}"
                if row.kind == "proportion":  # (clear of a double underline's second rule in the row above)
                    cell = f"[#pad(top: 3.5pt)[#text(style: \"italic\")[{self.words(row.text)}]]], []"
                else:
                    eq, cond = placement_math(row, name)
                    cell = f"[${eq}$], " + (f"[${cond}$]" if cond else "[]")
                if cells and cells[-1][0] == who:
                    cells[-1][1].append(cell)
                else:
                    cells.append((who, [cell]))
            for who, rows_of in cells:
                group(who, rows_of)

        by_similarity(-1)
        for index, step in enumerate(steps):
            who = f"{term('driver', self.lang)}" if step.group == "driver" else group_words(step.group, self.lang)
            if step.equations:
                group(who, [f"[${eq}$], " + (f"[${cond}$]" if cond else "[]") for eq, cond in step_lines(step, name)])
            by_similarity(index)
        # the heading and the note kept with the table's first rows; the rows flow on over a page's end (a long set
        # of equations fills the page it starts on)
        self.body.append(f"#block({'sticky: true' if flow else 'breakable: false'})[#heading(level: 2)[{self.words(heading)}]\n"
                         + f"#text(size: {SMALL_PT}pt, style: \"italic\")[{text(term('underlines', self.lang))}]"
                         + ("]\n" if flow else "\n\n")
                         + f"#text(size: {TEXT_PT}pt)[#table(columns: (auto, auto, 1fr), stroke: none, inset: (x: 1.5mm, y: {ROW_INSET_MM}mm), align: left + horizon,\n  "
                         + ",\n  ".join(rows) + ")]" + ("\n" if flow else "]\n"))

    def table_code(self, rows, aligns: str = "(left, right, right, right, right)") -> str:
        """Rows of values as a Typst ``table(…)`` expression: the first row the header, in bold, between rules."""
        ncol = len(rows[0])
        body = []
        for i, row in enumerate(rows):
            cells = list(row) + [""] * (ncol - len(row))
            weight = "bold" if i == 0 else "regular"
            body.append(", ".join(f"text(weight: \"{weight}\")[{self.words(c)}]" for c in cells))
        return (f"table(columns: {ncol}, stroke: none, inset: (x: 1.2mm, y: 0.9mm), align: {aligns}, table.hline(stroke: 0.7pt), "
                + ", table.hline(stroke: 0.4pt), ".join([body[0], ", ".join(body[1:])]) + ", table.hline(stroke: 0.7pt))")

    def table_markup(self, heading: str, rows, aligns: str = "(left, right, right, right, right)", full_width: bool = False) -> str:
        """A table of values under its *heading*, as Typst code (a block never parted, *full_width*: as wide as its
        place; first row the header)."""
        width = ", width: 100%" if full_width else ""
        return (f"block(breakable: false{width})[#text(weight: \"bold\", size: {SMALL_PT + 0.5}pt)[{self.words(heading)}] \\\n"
                f"#{self.table_code(rows, aligns)}]")

    def tables(self, tables, aligns: str = "(left, right, right, right, right)") -> None:
        """Tables of values, two across the page, each whole under its caption (*aligns*: Typst's alignment of
        the columns).

        Set as the cells of a grid, two to a row, a row moving whole to the next page when it does not fit:
        not in Typst's ``columns``, which sets a table that may not break, in a column starting lower on a page
        than the table is tall, with every row on one line, one over the other."""
        parts = [self.table_markup(heading, rows, aligns, full_width=True) for heading, rows in tables if rows]
        if parts:
            self.body.append(f"#text(size: {SMALL_PT}pt)[#grid(columns: (1fr, 1fr), column-gutter: {GUTTER}mm, row-gutter: 3mm, align: left + top,\n  "
                             + ",\n  ".join(parts) + ")]\n")

    def loop_block(self, block) -> None:
        """A loop's equations under its title (their size :attr:`loops_scale` of the small text's)."""
        self.body.append(f"#block(sticky: true)[#text(size: loops-size + 0.5pt, weight: \"bold\")[{self.words(block_words(block.title, self.lang))}]]\n")
        # an equation and the lines of its solution under it (``$\quad …``) one block, never parted by a page's end;
        # what the guide points Q_B are, in words, under the line that places them
        origins = block.origins
        kept: list[list[str]] = []
        for k, line in enumerate(block.lines):
            if kept and line.startswith("$\\quad"):
                kept[-1].append(line)
            else:
                kept.append([line])
            if k == len(origins) - 1:
                kept.extend([term("guide_origin", self.lang).format(q=f"$Q_{{{pin}}}$", s=f"$s_{{{pin}}}$")] for pin in origins)
        for lines in kept:
            words = " \\\n".join(self.loop_line(line) for line in lines)
            self.body.append(f"#block(breakable: false, spacing: 0.6em)[#text(size: loops-size)[{words}]]\n" if len(lines) > 1
                             else f"#text(size: loops-size)[{words}]\n")

    def loop_line(self, line: str) -> str:
        """A line of loop equations as markup: a solution's results (``⇒ ω₄ = 1,946, ṡ_A = −0,01116``) each in a box,
        so that a long line breaks between them, never inside one (``ω₄ =`` at a line's end, its value under it)."""
        arrow = r"\ \Rightarrow\ "
        if not (line.startswith("$") and line.endswith("$") and line.count("$") == 2 and arrow in line):
            return self.words(line)
        left, right = line[1:-1].split(arrow, 1)
        results = ", ".join(f"#box[{self.words('$' + part + '$')}]" for part in right.split(r",\ "))
        return self.words("$" + left + arrow.rstrip("\\ ") + "$") + " " + results

    def mark(self, name: str, solid: bool = False) -> None:
        """A mark in the flow that the laid-out document reports: its *name*, page and height on the page [mm
        from the top] (:func:`plans.pages.typesetting.query_document` with ``"<plans-mark>"``).

        A mark alone travels with what follows it (to the next page, when that does not fit); a *solid* one is a
        block of no height that stays where the content before it ends."""
        mark = f"#context [#metadata((name: {string(name)}, page: here().page(), y: here().position().y.mm())) <plans-mark>]"
        self.body.append(f"#block(height: 0pt, above: 0pt, below: 0pt)[{mark}]\n" if solid else mark + "\n")

    def beside(self, drawing, table, lines) -> None:
        """*table* (none: empty) and *lines* beside a *drawing* ``(key, block)``; with *drawing* None, alone (the page's width)."""
        words = " \\\n".join(self.words(line) for line in lines)
        # the first two columns (the quantity, the centre) to the left, every other one (numbers) to the right
        aligns = "(" + ", ".join(["left", "left"] + ["right"] * (len(table[0]) - 2)) + ")" if table else ""
        content = f"#{self.table_code(table, aligns)} \\\n{words}" if table else words
        if drawing is None:
            self.body.append(f"#text(size: {SMALL_PT}pt)[{content}]\n")
            return
        key, block = drawing
        self.body.append(f"#grid(columns: (auto, 1fr), column-gutter: {GUTTER}mm, align: top + left, {self.add_image(key, block)}, "
                         f"text(size: {SMALL_PT}pt)[{content}])\n")

    # the whole
    def source(self) -> str:
        lang = self.lang
        scales = [self.scale_words(key, self.plate[key]) for key in ("k_v", "k_a") if self.plate.get(key) is not None]
        # k_l from a state: the instant centres' pages may draw at a coarser one (and say so on the page)
        plate_kl = self.scale_words("k_l", self.plate["k_l"]) if self.plate.get("k_l") is not None else ""
        if plate_kl:
            scale_text = "#context plate-kl.get()" + (self.words(";   ") + self.words(";   ").join(scales) if scales else "")
        else:
            scale_text = self.words(";   ").join(scales) if scales else self.words("—")
        # a page that states a scale of its own (a force plans' μ_F) adds it here
        scale_text += ("#context { let page = here().page(); let notes = query(<plans-page-scale>).filter(m => m.location().page() == page);"
                       " if notes.len() > 0 [;   #notes.map(m => m.value).dedup().join([;   ])] }")
        if self.per_position is not None:
            scale_text += " " + text("(" + term("scales_each_position", lang) + ")")
        if self.sheet_number is not None:
            sheet = f"{text(term('sheet', lang))} {self.sheet_number[0]} {text(term('of_sheets', lang))} {self.sheet_number[1]}"
        else:
            sheet = f"{text(term('sheet', lang))} #context counter(page).get().first() {text(term('of_sheets', lang))} #context counter(page).final().first()"
        def field(key: str) -> str:  # a title block's field to fill in by hand: its name
            return f"#text(size: 8pt)[{text(term(key, lang))}:]"

        named = fitted_line('[#text(weight: "bold")[#context plate-name.get()] — ' + text(self.scene.title_in(lang)) + "]", 10.0, TITLE_BLOCK_LEAST_PT)
        title_block = (
            f"table(columns: (1fr, 1fr, 1fr, 42mm), stroke: 0.6pt, inset: (x: 2mm, y: 1.4mm), align: left + horizon,"
            f" table.cell(colspan: 3)[{named}],"
            f" [#text(size: 9pt)[{sheet}]],"
            f" table.cell(colspan: 4)[#text(size: 8.5pt)[{text(term('scale_factors', lang))}: {scale_text}]],"
            # the student's fields, as a course plate has them: the institution and group, who drew it (and index number)
            f" table.cell(colspan: 3)[{field('institution')}], [{field('student_group')}],"
            f" [{field('drawn_by')}], [{field('index_number')}], [{field('checked_by')}], [{field('date')}])"
        )
        g = self.page
        inner_w = g.size[0] - g.frame[0] - g.frame[1]
        inner_h = g.size[1] - 2 * g.frame[1]
        head = f"""#set document(date: none)
#let plate-kl = state("plate-kl", [{plate_kl}])
#let plate-name = state("plate-name", [{text(term('plate_title', lang))}])
#set page(width: {g.size[0]}mm, height: {g.size[1]}mm, margin: (left: {g.margins[0]}mm, right: {g.margins[1]}mm, top: {g.margins[2]}mm, bottom: {g.margins[3]}mm),
  background: place(top + left, dx: {g.frame[0]}mm, dy: {g.frame[1]}mm, rect(width: {inner_w}mm, height: {inner_h}mm, stroke: 0.8pt)),
  foreground: place(bottom + {g.title_block_side}, dx: {g.title_block_dx}mm, dy: -{g.frame[1]}mm, block(width: {g.title_block_width or (g.size[0] - g.frame[0] - g.frame[1])}mm, {title_block})))
#set text(font: {string(_FONT)}, size: {TEXT_PT}pt, lang: {string(lang)})
#show math.equation: set text(font: {string(_MATH)})
#let loops-size = {SMALL_PT * self.loops_scale:.2f}pt
#set par(leading: 0.5em, spacing: 0.7em)
#show heading: set block(above: {HEADING_ABOVE}, below: 0.6em)
#show heading.where(level: 1): set text(size: 13pt)
#show heading.where(level: 2): set text(size: 11pt)
#show heading.where(level: 3): set text(size: 9.5pt)
"""
        return head + "\n".join(self.body)
