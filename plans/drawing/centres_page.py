"""The handout's instant-centre page of a position (``plans handout … --centres``).

After a position's pages, one A4 page: the mechanism at that position with
every instant centre marked and labelled (P₁₂ …), the Kennedy lines thin,
the circle diagram beside it (:func:`plans.drawing.centres.draw_centres_into`),
and a table of ω of every link and v of every reported point found from the
centres (:mod:`plans.centres`, the third method: its own positions and
nothing of the analytic or graphical kinematics) beside the analytic values
of the handout's own analytic solution, with the relative error
(:func:`plans.compare.compare_centres`).

The page is built from the public names of the page layer
(:mod:`plans.drawing.layout`, :mod:`plans.drawing.blocks`,
:mod:`plans.drawing.typeset`); words from :mod:`plans.i18n`, decimal comma in
sr, ru, bg, sl.
"""

from __future__ import annotations

import cmath
import math

from .._text import decimal_comma, math_name
from ..i18n import term
from ..graphical.scales import PAGE_MANTISSAS, round_down, round_up
from ..report import table_error, table_number
from .blocks import Block, rows_block, table_block, text_rows
from .centres import CentresSizer, centre_text, draw_centres_into, draw_circle_diagram_into
from .layout import A4, GAP, PAGE_MARGIN, footer as page_footer, header, new_page
from .svg import drawing_rc

__all__ = ["draw_centres_page", "centres_page_table", "centres_page_k_l", "CENTRES_PAGE_MANTISSAS"]

#: the round mantissas of the page's k_l
CENTRES_PAGE_MANTISSAS = PAGE_MANTISSAS
TEXT_PT = 8.0
LEGEND_PT = 7.5
#: the least room [mm] around the mechanism on the page (its near centres widen it; far ones are arrows outside)
ROOM_MIN = 12.0
LINE_GAP = 0.7


def _number(value: float) -> str:
    """*value* as every table prints numbers: 4 significant digits (:func:`plans.report.table_number`)."""
    return table_number(value)


def _vector(z: complex) -> str:
    """``0.4993 ∠ 27.0°``: the direction 0…360° counter-clockwise from x, as on every other page."""
    if z == 0:
        return "0"
    return f"{_number(abs(z))} ∠ {math.degrees(cmath.phase(z)) % 360.0:.1f}°".replace("-", "−")


def _about(result, body: str) -> str:
    """The label of P_1j of *body* (``P₁₃``), ``P₁₄ ∞`` when it is at infinity (the body translates)."""
    if body == "frame":
        return "—"
    centre = result.centre("frame", body)
    return centre_text(centre.label) + ("" if centre.point is not None else " ∞")


def centres_page_table(result, comparisons, lang: str = "en", k_l: float | None = None) -> list[list[str]]:
    """The page's table: header, then ω of every link and v of every reported point, from the centres and analytic.

    Columns: quantity, the centre P_1j its body turns about, the value from
    the centres, the analytic value, the relative error (of the vector for v).
    *comparisons* from :func:`plans.compare.compare_centres`.  With *k_l* [m/mm] (the drawing's),
    a column more after P_1j: the reading P_1jM [mm] on the drawing, from which v_M = |ω_j| · P_1jM × k_l
    (a dash for ω, and where P_1j is at infinity: the link translates).
    """
    header = [term("quantity", lang), "$P_{1j}$", term("by_centres", lang), term("analytic", lang), term("rel_error", lang)]
    if k_l is not None:
        header.insert(2, "$P_{1j}M$ [mm]")
    rows = [header]
    by = {(c.section, c.name): c for c in comparisons}

    def reading(name: str) -> list[str]:
        if k_l is None:
            return []
        centre = result.centre("frame", result.scene.home_of(name))
        if centre.point is None:
            return ["—"]
        return [f"{abs(result.positions[name] - centre.point) / k_l:.1f}"]

    for name in result.scene.links:
        row = by.get(("links", name))
        if row is not None:
            rows.append([f"$\\omega_{{{math_name(name)}}}$ [rad/s]", _about(result, name)] + (["—"] if k_l is not None else [])
                        + [_number(row.graphical), _number(row.analytic), table_error(row.rel_error)])
    for name in result.scene.report:
        row = by.get(("points", name))
        if row is not None:
            rows.append([f"$v_{{{math_name(name)}}}$ [m/s]", _about(result, result.scene.home_of(name))] + reading(name)
                        + [_vector(complex(row.graphical)), _vector(complex(row.analytic)), table_error(row.rel_error)])
    return [[decimal_comma(cell, lang) for cell in row] for row in rows]


def _rules(lang: str) -> list[str]:
    return [
        f"{term('centres_omega_rule', lang)}:  $\\omega_j / \\omega_k = P_{{1k}}P_{{jk}} / P_{{1j}}P_{{jk}}$",
        f"{term('centres_v_rule', lang)}:  $v_M = \\omega_j \\cdot P_{{1j}}M \\times k_l$",
    ]


def _drawing(fig, result, k_l: float | None, lang: str) -> Block:
    """The mechanism with its centres at *k_l* (None: the circle diagram alone) as a block in axes of its own."""
    ax = fig.add_axes([0, 0, 0.01, 0.01])
    if k_l is None:
        width, height = draw_circle_diagram_into(ax, result, lang)
    else:
        width, height = draw_centres_into(ax, result, k_l, lang, legend=False, diagram=False, room_min=ROOM_MIN)

    def place(sketch, x: float, y: float, page) -> None:
        pw, ph = page
        ax.set_position([x / pw, y / ph, width / pw, height / ph])

    block = Block(width, height, place, kind="mechanism")
    block.axes = ax
    return block


class _Sizes:
    """The drawing's size [mm] at each k_l: from geometry (:class:`plans.drawing.centres.CentresSizer`: two
    drawings of the mechanism alone), or as drawn, once a k_l has been drawn."""

    def __init__(self, result, lang: str):
        self.sizer = CentresSizer(result, lang, room_min=ROOM_MIN)
        self.known: dict[float, tuple[float, float]] = {}

    def size(self, k: float) -> tuple[float, float]:
        return self.known.get(k) or self.sizer.size(k)

    def fits(self, k: float, box: tuple[float, float]) -> bool:
        w, h = self.size(k)
        return w <= box[0] + 0.5 and h <= box[1] + 0.5


def _need(sizes: _Sizes, box: tuple[float, float], k0: float) -> float:
    """The k_l the drawing's size, fixed + scaled / k_l (from its sizes at k0 and k0/2), says fits *box*."""
    (w0, h0), (w1, h1) = sizes.size(k0), sizes.size(k0 / 2)
    needs = []
    for a, b, room in ((w0, w1, box[0]), (h0, h1, box[1])):
        scaled = max((b - a) * k0, 0.0)  # a = fixed + scaled/k0, b = fixed + 2·scaled/k0
        fixed = a - scaled / k0
        if scaled > 0:
            needs.append(scaled / (room - fixed) if room - fixed > 5.0 else 4 * k0)
    return max(needs, default=k0)


def centres_page_k_l(sizes: _Sizes, box: tuple[float, float], guess: float, least: float | None = None) -> float:
    """The smallest round k_l (the largest drawing) with which the centres drawing fits *box* (width, height [mm]).

    From the round value at *guess* (or *least*, the plate's k_l, when given: never finer than it):
    larger ones while the drawing runs over, else smaller ones while it still fits.  Sizes come
    from :class:`_Sizes`: geometry, not drawings.
    """
    k = round_up(least if least is not None else guess)
    if sizes.fits(k, box):
        for _ in range(12):
            if least is not None:
                break
            smaller = round_down(k * 0.999)
            if not sizes.fits(smaller, box):
                break
            k = smaller
        return k
    for _ in range(24):
        k = round_up(k * 1.001)
        if sizes.fits(k, box):
            break
    return k


def draw_centres_page(run, *, lang: str = "en", header_lines=(), title: str | None = None, footer: str = "", k_l: float | None = None):
    """The instant-centre page of a solved position *run* (a :class:`plans.positions.PositionRun`), A4 portrait.

    *k_l* [m/mm]: the plate's scale, which the page keeps where the drawing fits (else the next
    coarser round value that fits); None: the largest that fits.

    The centres are found by :func:`plans.centres.instant_centres` from the
    position's scene alone; the analytic values compared with are those of
    ``run.analytic``.  Where the method cannot find the velocities at this
    position (a centre it needs is undetermined), the page says so.
    """
    from ..centres import instant_centres
    from ..compare import compare_centres
    from ..errors import PlansError

    size = A4
    width = size[0] - 2 * PAGE_MARGIN
    kennedy = term("kennedy_theorem", lang)
    lines = [decimal_comma(line, lang) for line in header_lines] + [
        "§" + term("centres_page", lang),
        f"{kennedy[0].upper() + kennedy[1:]}: {term('kennedy_statement', lang)}",
    ]
    with drawing_rc():
        fig, sketch = new_page(size)
        top = header(sketch, size, title or run.scene.title, lines)
        bottom = PAGE_MARGIN + 4.0
        try:
            result = instant_centres(run.scene, run.analytic.structure)
            comparisons = compare_centres(run.analytic, result)
        except PlansError as exc:
            rows = text_rows(term("instant_centres", lang), [decimal_comma(str(exc), lang)], width, TEXT_PT)
            block = rows_block(rows, "centres-refused", line_gap=LINE_GAP)
            block.place(sketch, PAGE_MARGIN, top - block.height, size)
            page_footer(sketch, footer)
            return fig
        k0 = run.scene.scales.k_l or None
        from ..graphical.scales import round_scale

        k0 = k0 or round_scale(result.size)
        # (centres_page_table(..., k_l) has a column of readings P_1jM [mm]: too wide for this page's layout of
        # table and circle diagram side by side, it is left to the plate's page)
        table = table_block(centres_page_table(result, comparisons, lang), term("centres_results", lang))
        rules = rows_block([(line, TEXT_PT, "normal") for line in _rules(lang)], "centres-rule", line_gap=LINE_GAP)
        legend_lines = [f"{term('centres_legend', lang)};", term("centres_edge_legend", lang)]
        legend = rows_block(text_rows("", legend_lines, width, LEGEND_PT)[1:], "centres-legend", line_gap=0.5)
        circle = _drawing(fig, result, None, lang)
        # the circle diagram beside the mechanism, beside the table or under the mechanism: whichever draws it largest
        sizes = _Sizes(result, lang)
        below = rules.height + GAP * 0.6 + table.height + GAP + legend.height + GAP * 0.6
        beside_mechanism = (width - circle.width - GAP, top - bottom - below)
        # beside the table, the legend goes above the table, left of the circle diagram
        narrow = rows_block(text_rows("", legend_lines, width - circle.width - GAP, LEGEND_PT)[1:], "centres-legend", line_gap=0.5)
        left_column = table.height + GAP + narrow.height
        beside_table = (width, top - bottom - rules.height - GAP * 0.6 - max(left_column, circle.height) - GAP)
        stacked = (width, beside_mechanism[1] - circle.height - GAP)
        # the layout that draws the mechanism largest (the first of equals: the diagram beside the mechanism)
        layouts = [("beside", beside_mechanism), ("stacked", stacked)]
        if table.width + GAP + circle.width <= width:
            layouts.insert(1, ("table", beside_table))
        tried = []
        for n, (name, box) in enumerate(layouts):
            if box[1] > 20.0 and box[0] > 20.0:
                guess = min(max(_need(sizes, box, k0), k0 / 8), k0 * 8)
                tried.append((centres_page_k_l(sizes, box, guess, k_l), n, name, box))
        k_l, _, layout, box = min(tried)
        # drawn once; where the mechanism's names fall otherwise than foreseen and it runs over, at the next round k_l
        for _ in range(6):
            drawing = _drawing(fig, result, k_l, lang)
            if drawing.width <= box[0] + 0.5 and drawing.height <= box[1] + 0.5:
                break
            sizes.known[k_l] = (drawing.width, drawing.height)
            drawing.axes.remove()
            k_l = centres_page_k_l(sizes, box, k_l, round_up(k_l * 1.001))
        rules.place(sketch, PAGE_MARGIN, bottom, size)
        y = bottom + rules.height + GAP * 0.6
        table.place(sketch, PAGE_MARGIN, y, size)
        x = PAGE_MARGIN + (width - drawing.width) / 2
        if layout == "table":
            circle.place(sketch, PAGE_MARGIN + width - circle.width, y, size)
            narrow.place(sketch, PAGE_MARGIN, y + table.height + GAP, size)
        elif layout == "beside":
            x = PAGE_MARGIN + (width - drawing.width - GAP - circle.width) / 2
            circle.place(sketch, x + drawing.width + GAP, top - (drawing.height + circle.height) / 2, size)
            legend.place(sketch, PAGE_MARGIN, top - max(drawing.height, circle.height) - GAP * 0.6 - legend.height, size)
        else:
            circle.place(sketch, PAGE_MARGIN + (width - circle.width) / 2, top - drawing.height - GAP - circle.height, size)
            legend.place(sketch, PAGE_MARGIN, top - drawing.height - GAP - circle.height - GAP * 0.6 - legend.height, size)
        drawing.place(sketch, x, top - drawing.height, size)
        page_footer(sketch, footer)
    fig.centres_k_l = k_l  # (the tests read the scale the page states)
    return fig
