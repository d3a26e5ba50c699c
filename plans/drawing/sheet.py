"""The one-page sheet, the scale factors that make it full, and :func:`write_drawings`.

The sheet puts the mechanism and both plans (each at its own scale, 1:1 on
the page, so the stated scale factors hold on the printed sheet too), the
vector equations each group solved, the readings of both plans and the
results table in a drawing frame on A3 landscape, with a title block in the
lower right corner: title, structural formula, scale factors and assembly
branches.  The layout decides the regions first (the texts in columns at the
top right, over the title block); :func:`sheet_scales` then gives the factors
with which each drawing fills its region, for the caller to construct the
plans at (drawing never solves), and :func:`draw_sheet` places the drawn
blocks.  A larger ISO sheet only when factors given by the user draw the
figures too large for A3.
"""

from __future__ import annotations

import cmath
import itertools
import math
import re
from pathlib import Path

from .._files import replace_all
from .._text import decimal_comma, user_text
from ..graphical.scales import PAGE_MANTISSAS
from ..i18n import branch_text, term
from ._canvas import Sketch, fmt_number
from .blocks import READINGS_PT, TABLE_PT, drawing_block, pretty_equation, readings_block, rows_block, table_block, text_rows
from .layout import FRAME_LEFT, FRAME_OTHER, SHEET_FORMATS, TITLE_BLOCK_W
from .numerals import scale_caption
from .style import HEADING_PT
from .svg import drawing_rc, new_figure
from .typeset import draw_text, measure

__all__ = ["draw_sheet", "sheet_scales", "drawn_score", "fixed_parts", "SheetLayout", "ESTIMATED_FIXED", "SCALE_OF", "SHEET_FIRST", "branch_lines", "write_drawings", "sheet_equations", "guide_names", "translate_table", "label_driver"]

SHEET_PAD = 4.0  # mm between the frame and the content
GAP = 6.0  # mm between blocks
EQ_PT = 8.5
EQ_WIDTH = 105.0  # mm: the vector equations are broken to this width
SHEET_LINE_GAP = 1.5  # mm between the lines of the title and of the equations


#: a guide as the construction names it, ``frame.ram`` or ``4.slot``: the body's key before the scene's name
_GUIDE_KEY = re.compile(r"(?<![\w.])(?:frame|\d+)\.([^\W\d]\w*)")


def guide_names(line: str) -> str:
    """*line* with each guide named as the scene names it: ``∥ frame.ram`` → ``∥ ram``, ``∥ 4.slot`` → ``∥ slot``.

    >>> guide_names("v_E = v_E4 + v_EE4  (v_EE4 ∥ 4.slot);  a = 0.5 m")
    'v_E = v_E4 + v_EE4  (v_EE4 ∥ slot);  a = 0.5 m'
    """
    return _GUIDE_KEY.sub(r"\1", line)


def sheet_equations(solution, driver_label: str | None = None, plans=("velocity", "acceleration")) -> list[str]:
    """One line per construction step: ``"RRP(3,4):  v_B = v_A + v_BA;  v_B = …"``, velocity plan first.

    With *driver_label* (such as ``"I(1,2)"``) the driver's steps are headed
    with it instead of the English word ``driver`` (see :func:`label_driver`);
    *plans* says of which plans (both by default).
    """
    lines = []
    for plan in (solution.velocity_plan, solution.acceleration_plan):
        if plan is None or plan.kind not in plans:
            continue
        for step in plan.steps:
            if step.equations:
                lines.append(guide_names(f"{step.group}:  " + ";   ".join(step.equations)))
    return lines if driver_label is None else label_driver(lines, driver_label)


def label_driver(lines: list[str], label: str) -> list[str]:
    """Equation lines with a leading ``driver:`` replaced by ``label:`` (``"I(1,2):"``, the structural notation)."""
    return [f"{label}:" + line[len("driver:"):] if line.startswith("driver:") else line for line in lines]


_TABLE_HEADER = ["quantity", "graphical", "analytic", "rel. error"]


def translate_table(table: list[list[str]], lang: str) -> list[list[str]]:
    """The sheet table with its header row and the words link/slider in *lang*."""
    if lang == "en" or not table or list(table[0]) != _TABLE_HEADER:
        return table
    header = [term(k, lang) for k in ("quantity", "graphical", "analytic", "rel_error")]
    words = {" link ": f" {term('link', lang)} ", " slider ": f" {term('slider', lang)} "}
    rows = [header]
    for row in table[1:]:
        cell = row[0]
        for a, b in words.items():
            cell = cell.replace(a, b)
        rows.append([cell] + list(row[1:]))
    return rows


TITLE_BLOCK_PAD = 2.0
TITLE_BLOCK_PT = 8.0


def branch_lines(branches, lang: str = "en") -> list[str]:
    """The assembly branch of each group with two, one line each, from :class:`plans.structure.Branch` records.

    ``"RRR(3,4): C to the left of B→D (+1)"``; in the other languages in
    their words (:func:`plans.i18n.branch_text`), or the group and its sign
    alone for a form of words not known there.
    """
    out = []
    for b in branches or ():
        if not b.sign:
            continue
        sign = f"{b.sign:+d}".replace("-", "\u2212")
        words = branch_text(guide_names(b.words), lang)
        out.append(f"{b.group}: {words} ({sign})" if words else f"{b.group}: {sign}")
    return out


def _wrapped(text: str, size: float, weight: str, width: float) -> list[str]:
    """*text* broken at spaces into lines no wider than *width* [mm] (a word wider than that stays whole)."""
    if measure(text, size, weight)[0] <= width:
        return [text]
    lines, line = [], ""
    for word in text.split(" "):
        trial = f"{line} {word}" if line else word
        if line and measure(trial, size, weight)[0] > width:
            lines.append(line)
            line = word
        else:
            line = trial
    return lines + [line]


def _title_block_rows(title: str, formula: str, scales: dict, branches, lang: str) -> list[tuple[str, float, str]]:
    rows = [(title or "—", HEADING_PT + 1.0, "bold")]
    if formula:
        rows.append((f"{term('structural_formula', lang)}:  {formula}", TITLE_BLOCK_PT, "normal"))
    units = {"k_l": "m/mm", "k_v": "(m/s)/mm", "k_a": "(m/s²)/mm"}
    parts = [scale_caption(key, fmt_number(scales[key]), unit, lang) for key, unit in units.items() if scales.get(key)]
    if parts:
        rows.append((f"{term('scale_factors', lang)}:  " + ",  ".join(parts), TITLE_BLOCK_PT, "normal"))
    for line in branches or ():
        rows.append((line, TITLE_BLOCK_PT, "normal"))
    return rows


# --- the sheet's layout: regions first, then the scale factors that fill them ----------------------------

#: The sheet's format: A3 landscape for every sheet; a larger ISO sheet only when scale factors given by the
#: user (or a scene too large for A3's text columns) leave no arrangement that fits.
SHEET_FIRST = "A3"
#: A sheet whose best arrangement leaves a drawing short of its target tries its tables a point smaller
#: (:data:`SMALLER_PT`), and takes them when that scores :data:`SMALLER_GAIN` times higher.
SMALLER_PT = 1.0
SMALLER_GAIN = 1.03
#: What the layout aims at [mm] (issue 11 §1): the mechanism across (the larger side of its bounding box),
#: a plan's largest vector, a plan across.
MECHANISM_ACROSS_MM = 100.0
LARGEST_VECTOR_MM = 60.0
PLAN_ACROSS_MM = 40.0
#: Shares in which a region is split between drawings: coarse ones tried for every arrangement, then the fine
#: ones for the :data:`FINE_TRIES` best.
COARSE_SHARES = (0.35, 0.5, 0.65)
SHARES = tuple(round(0.2 + 0.05 * i, 2) for i in range(13))
FINE_TRIES = 3
#: Room [mm] a chosen scale factor leaves in its box: the drawing made at the final factors may differ a little
#: from the one its fixed parts were measured on (labels placed anew, numbers of other lengths).
FIT_SLACK = 2.0
#: What a drawing takes beyond its geometry [mm] (width, height: labels, supports, margins, caption, legend), as
#: a first estimate before a drawing has measured it (see :func:`fixed_parts`).
ESTIMATED_FIXED = {"mechanism": (40.0, 40.0), "velocity": (30.0, 50.0), "acceleration": (30.0, 60.0)}
#: the scale factor of each drawing of a sheet
SCALE_OF = {"mechanism": "k_l", "velocity": "k_v", "acceleration": "k_a"}
_TARGETS = {"mechanism": MECHANISM_ACROSS_MM}


class SheetLayout:
    """Where a sheet put its blocks [mm on the page, origin lower left]: what :func:`draw_sheet` records.

    ``format`` (``"A3"`` …), ``page`` (width, height), ``frame`` and
    ``title_block`` (x0, y0, x1, y1), ``boxes`` (kind -> the region a drawing
    was given), ``blocks`` (kind or text block kind -> the rectangle the block
    takes) and ``scales`` (the factors drawn).
    """

    def __init__(self, format, page, frame, title_block, boxes, blocks, scales, fixed=None):
        self.format = format
        #: kind -> what each drawing takes beyond its geometry [mm], as drawn here (see :func:`fixed_parts`)
        self.fixed = fixed or {}
        self.page = page
        self.frame = frame
        self.title_block = title_block
        self.boxes = boxes
        self.blocks = blocks
        self.scales = scales

    def __repr__(self) -> str:
        return f"SheetLayout({self.format!r}, boxes={self.boxes!r})"


class _Figure:
    """A drawing to place: its geometry's physical size, its largest vector, what it takes beyond its geometry [mm]."""

    def __init__(self, kind: str, size: tuple[float, float], largest: float, fixed: tuple[float, float], k: float, given: bool,
                 reach: tuple[float, float] | None = None):
        self.kind = kind
        self.size = size  # (width, height) of the geometry [m, m/s or m/s²]: what the targets measure
        #: (width, height) of what is drawn to scale [m …]: the geometry, and a mechanism's guides over their travel
        self.reach = reach or size
        self.at: dict[float, tuple[float, float]] = {}  # factor -> what the drawing took beyond its geometry, drawn at it
        self.largest = largest  # a plan's largest vector [m/s or m/s²]
        self.fixed = fixed  # (width, height) [mm] of labels, supports, margins, caption and legend
        self.k = k  # the factor it is drawn at now
        self.given = given  # the factor is the user's: kept as it is

    def fit(self, w: float, h: float, ladder) -> float | None:
        """The factor with which this drawing fills a box *w* × *h* [mm] (None: it cannot fit).

        Where the drawing was measured at the factor found (:attr:`at`), what it took there is used
        instead, and a larger factor taken when that does not fit (a plan's enlarged detail is drawn at
        some factors only).
        """
        k = self._fit(w, h, ladder, self.fixed)
        for _ in range(4):
            measured = next((f for at, f in self.at.items() if k is not None and math.isclose(at, k, rel_tol=1e-9)), None)
            if measured is None:
                break
            again = self._fit(w, h, ladder, measured)
            if again is None or again <= k * (1 + 1e-9):
                return k if again is not None else None
            k = again
        return k

    def _fit(self, w: float, h: float, ladder, fixed) -> float | None:
        gw, gh = w - fixed[0] - FIT_SLACK, h - fixed[1] - FIT_SLACK
        if gw <= 5.0 or gh <= 5.0:
            return None
        rw, rh = self.reach
        if self.given or not (rw > 0 or rh > 0):
            k = self.k
            return k if rw / k <= gw + 1e-9 and rh / k <= gh + 1e-9 else None
        return ladder(max(rw / gw, rh / gh))

    def ratios(self, k: float) -> list[float]:
        """The drawn size at *k* over what the sheet aims at (see :data:`MECHANISM_ACROSS_MM`)."""
        across = max(self.size) / k
        if self.kind == "mechanism":
            return [across / MECHANISM_ACROSS_MM] if across > 0 else []
        return [self.largest / k / LARGEST_VECTOR_MM, across / PLAN_ACROSS_MM] if across > 0 else []


def _bbox(points) -> tuple[float, float]:
    xs = [z.real for z in points]
    ys = [z.imag for z in points]
    return (max(xs) - min(xs), max(ys) - min(ys)) if xs else (0.0, 0.0)


def _objects(solution) -> dict:
    out = {"mechanism": solution, "velocity": solution.velocity_plan}
    if solution.acceleration_plan is not None:
        out["acceleration"] = solution.acceleration_plan
    return out


def _geometry(solution, kind: str) -> tuple[tuple[float, float], float]:
    """(width, height) of a drawing's geometry [m, m/s, m/s²] and its largest vector: what scales with its factor."""
    if kind == "mechanism":
        return _bbox(solution.positions.values()), 0.0
    plan = _objects(solution)[kind]
    ends = [0j, *plan.images.values(), *(v.tail for v in plan.vectors), *(v.tip for v in plan.vectors)]
    w, h = _bbox(ends)
    largest = max((abs(v.tip - v.tail) for v in plan.vectors), default=0.0)
    return (w * plan.scale, h * plan.scale), largest * plan.scale


def _reach(solution) -> tuple[float, float]:
    """(width, height) [m] of the mechanism's points and of its guides and slots over the travel the drawing
    gives them (``solution.travel``, metres along each line from its origin; see
    :meth:`plans.drawing.mechanism.MechanismDrawing._travel`): all of it scales with k_l, none of it is fixed."""
    points = [complex(z) for z in solution.positions.values()]
    travel = getattr(solution, "travel", None) or {}
    if not points or not travel:
        return _bbox(points)
    w, h = _bbox(points)
    size = math.hypot(w, h)
    ends = list(points)
    for key, span in travel.items():
        body, _, name = key.partition(".")
        line = getattr(solution.scene.bodies.get(body), "lines", {}).get(name)
        if line is None:
            continue
        phi, at = (0.0, 0j) if body not in solution.poses else solution.poses[body]
        origin = complex(at) + cmath.exp(1j * phi) * complex(line.origin)
        u = cmath.exp(1j * (phi + line.angle))
        along = [((z - origin) * u.conjugate()).real for z in points]
        lo, hi = min(along) - size, max(along) + size
        ends += [origin + u * min(max(float(t), lo), hi) for t in span if math.isfinite(t)]
    return _bbox(ends)


def drawn_score(solution, scales: dict | None = None, *, least: bool = False) -> float:
    """How large the drawings of *solution* are, at its factors (or at *scales*), against what a sheet aims at.

    The smallest ratio of drawn size to target (:data:`MECHANISM_ACROSS_MM`,
    :data:`LARGEST_VECTOR_MM`, :data:`PLAN_ACROSS_MM`) plus a fifth of their
    mean, the score :func:`sheet_scales` maximises; with *least*, the
    smallest ratio alone (1 or more: every drawing reaches its target).
    """
    scales = solution.scales if scales is None else scales
    ratios = []
    for kind in _objects(solution):
        size, largest = _geometry(solution, kind)
        ratios += _Figure(kind, size, largest, (0.0, 0.0), scales[SCALE_OF[kind]], True).ratios(scales[SCALE_OF[kind]])
    return min(ratios, default=0.0) if least else _score(ratios)


def fixed_parts(solution, blocks: dict) -> dict[str, tuple[float, float]]:
    """Kind -> what a drawn block takes beyond its geometry [mm] (labels, supports, arcs, margin, caption, legend).

    *blocks* are the drawing blocks (:func:`plans.drawing.blocks.drawing_block`)
    of *solution*, at its scale factors.
    """
    out = {}
    for kind, block in blocks.items():
        (w, h), _ = _geometry(solution, kind)
        if kind == "mechanism":
            w, h = _reach(solution)
        k = solution.scales[SCALE_OF[kind]]
        out[kind] = (max(block.width - w / k, 0.0), max(block.height - h / k, 0.0))
    return out


def _ladder(mantissas):
    """need -> the smallest round factor m·10ⁿ not below it (m in *mantissas*), memoised per decade."""
    decades: dict[int, list[float]] = {}

    def up(need: float) -> float:
        n = math.floor(math.log10(need))
        for e in (n - 1, n, n + 1):
            values = decades.get(e)
            if values is None:
                values = decades[e] = [float(f"{m}e{e}") for m in mantissas]
            for value in values:
                if value >= need * (1 - 1e-12):
                    return value
        return float(f"1e{n + 2}")

    return up


def _structures(kinds):
    """The ways to arrange *kinds* (in reading order) in one region, as trees: a kind, or (``"row"``/``"column"``, children)."""
    n = len(kinds)
    if n == 1:
        return [kinds[0]]
    if n == 2:
        return [("row", tuple(kinds)), ("column", tuple(kinds))]
    first, second, third = kinds
    return [
        ("row", tuple(kinds)),
        ("column", tuple(kinds)),
        ("column", (first, ("row", (second, third)))),  # the first above the other two side by side
        ("row", (first, ("column", (second, third)))),  # the first beside the other two stacked
        ("column", (("row", (first, second)), third)),  # the first two side by side above the third
        ("row", (("column", (first, second)), third)),  # the first two stacked beside the third
    ]


def _share_parts(node, box, shares=None):
    """Every split of *box* (x, y from the top, w, h) among the children of *node* by *shares*
    (:data:`SHARES` by default): a list of boxes."""
    shares = SHARES if shares is None else shares
    axis, children = node
    x, y, w, h = box
    length = (w if axis == "row" else h) - GAP * (len(children) - 1)
    if length <= 0:
        return
    if len(children) == 2:
        splits = [(s, 1.0 - s) for s in shares]
    else:
        thirds = [s for s in shares if 0.2 <= s <= 0.6 + 1e-9]
        splits = [(a, b, 1.0 - a - b) for a in thirds for b in thirds if 0.2 - 1e-9 <= 1.0 - a - b]
    for share in splits:
        parts, at = [], 0.0
        for p in share:
            size = length * p
            parts.append((x + at, y, size, h) if axis == "row" else (x, y + at, w, size))
            at += size + GAP
        yield parts


def _natural(node, sizes) -> tuple[float, float]:
    """(width, height) [mm] that *node* needs for blocks of *sizes* (kind -> (w, h)), GAP between them."""
    if isinstance(node, str):
        return sizes[node]
    axis, children = node
    parts = [_natural(c, sizes) for c in children]
    if axis == "row":
        return sum(p[0] for p in parts) + GAP * (len(parts) - 1), max(p[1] for p in parts)
    return max(p[0] for p in parts), sum(p[1] for p in parts) + GAP * (len(parts) - 1)


def _place_boxes(node, box, sizes):
    """kind -> box: *box* shared among the leaves of *node*, each its natural size plus an equal part of what is left."""
    if isinstance(node, str):
        return {node: box}
    axis, children = node
    x, y, w, h = box
    parts = [_natural(c, sizes) for c in children]
    out = {}
    if axis == "row":
        extra = (w - _natural(node, sizes)[0]) / len(children)
        for child, (cw, _) in zip(children, parts):
            out.update(_place_boxes(child, (x, y, cw + extra, h), sizes))
            x += cw + extra + GAP
    else:
        extra = (h - _natural(node, sizes)[1]) / len(children)
        for child, (_, ch) in zip(children, parts):
            out.update(_place_boxes(child, (x, y, w, ch + extra), sizes))
            y += ch + extra + GAP
    return out


def _text_options(texts):
    """The text blocks in columns: all in one, or split (in order) into two or three, either way round."""
    n = len(texts)
    if not n:
        yield []
        return
    seen = set()
    for cuts in [()] + [(i,) for i in range(1, n)] + ([(1, 2)] if n == 3 else []):
        bounds = (0, *cuts, n)
        columns = [texts[a:b] for a, b in zip(bounds, bounds[1:])]
        for order in (columns, columns[::-1]):
            key = tuple(tuple(id(b) for b in c) for c in order)
            if key not in seen:
                seen.add(key)
                yield order


def _arrangements(inner, tb, texts, kinds, strips=()):
    """Every arrangement tried on a sheet: (placed texts [(block, x, y)], [(region, tree of kinds)]), in content coordinates.

    *inner* is the content's (width, height) [mm], *tb* the title block's left
    edge and top in them (x from the left, y from the top); a region is
    (x, y, w, h).  The text columns stand at the top right, over the title
    block; one text block may instead stand at the foot of the sheet, left of
    the title block.  The drawings share what is left: the region on the left,
    the band under the texts and over the title block, the strip between them
    when the texts are narrower than the title block, and the room beside a
    text block at the foot.
    """
    width, height = inner
    tb_x, tb_y = tb
    for foot in [None] + list(texts):
        if foot is not None and (foot.width > tb_x - GAP + 1e-9 or foot.height > height - 60.0):
            continue
        rest = [b for b in texts if b is not foot]
        foot_h = foot.height + GAP if foot is not None else 0.0
        for columns in _text_options(rest):
            placed, tw, th, spans = [], 0.0, 0.0, []
            for column in columns:
                cw = max(b.width for b in column)
                y = 0.0
                for b in column:
                    placed.append((b, tw, y))
                    y += b.height + GAP
                th = max(th, y - GAP)
                spans.append((tw, cw, y - GAP))
                tw += cw + GAP
            tw = max(tw - GAP, 0.0)
            if th > tb_y - GAP + 1e-9 or tw > width - 60.0:
                continue
            x_text = width - tw
            placed_texts = [(b, x_text + dx, dy) for b, dx, dy in placed]
            if foot is not None:
                placed_texts.append((foot, 0.0, height - foot.height))
            right = min(x_text, tb_x)
            left = (0.0, 0.0, right - GAP, height - foot_h)
            if left[2] < 30.0 or left[3] < 30.0:
                continue
            top_band = th + GAP if columns else 0.0
            others = []
            band = (right, top_band, width - right, tb_y - GAP - top_band)
            if band[3] >= 30.0 and band[2] >= 30.0:
                others.append(band)
            if len(spans) > 1:  # under one column, the others being taller
                for dx, cw, ch in spans:
                    under = (width - tw + dx, ch + GAP, cw, tb_y - GAP - ch - GAP)
                    if under[3] >= 30.0 and under[2] >= 30.0 and ch + 1e-9 < th and under[0] >= tb_x - 1e-9:
                        others.append(under)
            if x_text - GAP - tb_x >= 30.0:  # texts narrower than the title block: a strip beside them
                others.append((tb_x, 0.0, x_text - GAP - tb_x, tb_y - GAP))
            if foot is not None and tb_x - GAP - foot.width - GAP >= 30.0:  # beside the text at the foot
                others.append((foot.width + GAP, height - foot.height, tb_x - GAP - foot.width - GAP, foot.height))
            for tree in _structures(kinds):
                yield placed_texts, [(left, tree)]
            for other in others:
                for alone in kinds:  # one drawing in the other region, the rest on the left
                    rest_kinds = [k for k in kinds if k != alone]
                    if rest_kinds:
                        for tree in _structures(rest_kinds):
                            yield placed_texts, [(left, tree), (other, alone)]
            if len(kinds) == 3:
                for i, one in enumerate(others):
                    for two in others[i + 1:]:
                        if _overlap(one, two):
                            continue
                        for order in itertools.permutations(kinds):
                            yield placed_texts, list(zip((left, one, two), order))
    if "mechanism" in kinds and len(kinds) > 1:  # a mechanism too wide for the left region: a strip across the top
        rest = [k for k in kinds if k != "mechanism"]
        for strip in strips:
            dy = strip + GAP
            if tb_y - dy < 60.0:
                continue
            for placed_texts, regions in _arrangements((width, height - dy), (tb_x, tb_y - dy), texts, rest):
                yield ([(b, x, y + dy) for b, x, y in placed_texts],
                       [((0.0, 0.0, width, strip), "mechanism")] + [((x, y + dy, w, h), tree) for (x, y, w, h), tree in regions])


def _overlap(a, b) -> bool:
    return a[0] < b[0] + b[2] - 1e-9 and b[0] < a[0] + a[2] - 1e-9 and a[1] < b[1] + b[3] - 1e-9 and b[1] < a[1] + a[3] - 1e-9


def _content(page, tb_h: float):
    """(width, height) of the content area and the title block's left edge and top in it [mm] on a *page*."""
    pw, ph = page
    width = pw - FRAME_LEFT - FRAME_OTHER - 2 * SHEET_PAD
    height = ph - 2 * FRAME_OTHER - 2 * SHEET_PAD
    tb_w = min(TITLE_BLOCK_W, pw - FRAME_LEFT - FRAME_OTHER)
    return (width, height), (width + SHEET_PAD - tb_w, height + SHEET_PAD - tb_h)


def _formats():
    names = [name for name, _ in SHEET_FORMATS]
    return SHEET_FORMATS[names.index(SHEET_FIRST):]


#: An arrangement that breaks the reading order (mechanism, velocity plan, acceleration plan: left to right or
#: top down) counts this much less for each pair out of order.
OUT_OF_ORDER = 0.85


def _order_factor(boxes) -> float:
    """:data:`OUT_OF_ORDER` to the power of the pairs of drawings out of reading order in *boxes* (kind -> x, y from the top, w, h)."""
    kinds = [k for k in ("mechanism", "velocity", "acceleration") if k in boxes]
    factor = 1.0
    for i, a in enumerate(kinds):
        for b in kinds[i + 1:]:
            ax, ay, aw, ah = boxes[a]
            bx, by, bw, bh = boxes[b]
            if bx + bw <= ax + 1e-6 or (by + bh <= ay + 1e-6 and not ax + aw <= bx + 1e-6):  # b left of a, or above it
                factor *= OUT_OF_ORDER
    return factor


def _leaves(tree) -> list[str]:
    return [tree] if isinstance(tree, str) else [k for child in tree[1] for k in _leaves(child)]


def _score(ratios) -> float:
    return min(ratios) + 0.2 * sum(ratios) / len(ratios) if ratios else 0.0


def _choose_scales(figures: dict, options, tb_h: float, mantissas, strips=()):
    """(format, page, scales) of the arrangement whose drawings, each filling its box, are largest.

    *options* are the lists of text blocks to try (the readings side by side,
    or stacked).  An arrangement is scored by its smallest ratio of drawn size
    to target plus a fifth of their mean (:func:`_Figure.ratios`), less for
    drawings out of reading order; each split of a region takes the share
    that scores best for the drawings on either side of it: first among
    :data:`COARSE_SHARES` for every arrangement, then among :data:`SHARES`
    for the few best.
    """
    ladder = _ladder(mantissas)
    kinds = list(figures)
    cache: dict = {}

    def best_in(tree, box, shares):
        """(score, ratios, kind -> k, kind -> box) of *tree* in *box*, its splits at their best shares; None: no fit."""
        key = (tree, box, shares)
        if key in cache:
            return cache[key]
        found = None
        if isinstance(tree, str):
            k = figures[tree].fit(box[2], box[3], ladder)
            if k is not None:
                ratios = figures[tree].ratios(k)
                found = (_score(ratios), ratios, {tree: k}, {tree: box})
        else:
            for parts in _share_parts(tree, box, shares):
                results = [best_in(child, part, shares) for child, part in zip(tree[1], parts)]
                if any(r is None for r in results):
                    continue
                ratios = [x for r in results for x in r[1]]
                score = _score(ratios)
                if found is None or score > found[0] + 1e-9:
                    found = (score, ratios, {k: v for r in results for k, v in r[2].items()}, {k: v for r in results for k, v in r[3].items()})
        cache[key] = found
        return found

    def evaluate(regions, shares):
        results = [best_in(tree, region, shares) for region, tree in regions]
        if any(r is None for r in results):
            return None
        boxes = {k: v for r in results for k, v in r[3].items()}
        ratios = [x for r in results for x in r[1]]
        return _score(ratios) * _order_factor(boxes), {k: v for r in results for k, v in r[2].items()}, min(ratios, default=0.0)

    for name, page in _formats():
        inner, tb = _content(page, tb_h)
        coarse = []
        kept: list[float] = []  # the FINE_TRIES best coarse scores so far, best first
        for texts in options:
            for _, regions in _arrangements(inner, tb, texts, kinds, strips):
                # each drawing given its whole region: an arrangement that cannot beat the ones kept is not split
                alone = [best_in(kind, region, COARSE_SHARES) for region, tree in regions for kind in _leaves(tree)]
                if any(r is None for r in alone):
                    continue
                if len(kept) >= FINE_TRIES and _score([x for r in alone for x in r[1]]) <= kept[-1]:
                    continue
                found = evaluate(regions, COARSE_SHARES)
                if found is not None:
                    coarse.append((found[0], len(coarse), regions))
                    kept = sorted(kept + [found[0]], reverse=True)[:FINE_TRIES]
        if not coarse:
            continue
        best = None
        for _, _, regions in sorted(coarse, key=lambda c: (-c[0], c[1]))[:FINE_TRIES]:
            found = evaluate(regions, SHARES)
            if found is not None and (best is None or found[0] > best[0] + 1e-9):
                best = found
        if best is not None:
            return name, page, best[1], best[0], best[2]
    return None


def _choose_places(drawings: dict, texts, tb_h: float):
    """(format, page, texts placed, kind -> box) for drawn blocks: an arrangement that holds them, the one they fill best."""
    kinds = list(drawings)
    sizes = {kind: (b.width, b.height) for kind, b in drawings.items()}
    for name, page in _formats():
        inner, tb = _content(page, tb_h)
        best = None
        wide = "mechanism" in sizes and sizes["mechanism"][0] > tb[0] - GAP  # wider than the left region can be
        for texts_placed, regions in _arrangements(inner, tb, texts, kinds, (sizes["mechanism"][1],) if wide else ()):
            fill = math.inf
            for (_, _, w, h), tree in regions:
                nw, nh = _natural(tree, sizes)
                if nw > w + 1e-6 or nh > h + 1e-6:
                    break
                fill = min(fill, max(nw / w, nh / h))
            else:
                boxes = {}
                for region, tree in regions:
                    boxes.update(_place_boxes(tree, region, sizes))
                fill *= _order_factor(boxes)
                if best is None or fill > best[0] + 1e-9:
                    best = (fill, texts_placed, boxes)
        if best is not None:
            return name, page, best[1], best[2], best[0]
    return None


def _sheet_texts(solution, *, formula, table, equations, lang, title, branches, small: bool = False):
    """The title block's rows and their heights, and the text blocks (equations, readings side by side or stacked, table)."""
    table = [[decimal_comma(cell, lang) for cell in row] for row in translate_table(table, lang)] if table else table
    title = user_text(title if title is not None else (solution.scene.title_in(lang) if hasattr(solution.scene, "title_in") else getattr(solution.scene, "title", "") or ""))
    # each row broken at spaces into lines that fit the title block (a position sheet's title is long)
    room = TITLE_BLOCK_W - 2 * TITLE_BLOCK_PAD - 2.0
    tb_rows = [(_wrapped(decimal_comma(t, lang) if k else t, size, weight, room), size, weight)
               for k, (t, size, weight) in enumerate(_title_block_rows(title, formula, solution.scales, branches, lang))]
    tb_heights = [sum(measure(line, size, weight)[1] + SHEET_LINE_GAP for line in lines) - SHEET_LINE_GAP + 2 * TITLE_BLOCK_PAD
                  for lines, size, weight in tb_rows]

    eq_lines = sheet_equations(solution) if equations is None else list(equations)
    if lang != "en":  # "driver:" is the one English word of the steps: the structural notation instead
        eq_lines = label_driver(eq_lines, f"I({getattr(solution.scene, 'frame_number', '1')},{getattr(getattr(solution.scene, 'driver', None), 'link', '')})")
    eq_block = None
    if eq_lines:
        heading = term("vector_equations", lang) if lang != "en" else "Vector equations"
        rows = text_rows(heading, [pretty_equation(decimal_comma(line, lang)) for line in eq_lines], EQ_WIDTH, EQ_PT)
        eq_block = rows_block(rows, "equation", line_gap=SHEET_LINE_GAP)
    less = SMALLER_PT if small else 0.0  # a crowded sheet: the tables a point smaller
    heading = "Results" if lang == "en" else term("results", lang)
    table_block_ = table_block(table, heading, size=TABLE_PT - less, heading_size=HEADING_PT - less) if table else None
    # what is measured on each plan and what it gives (issue 10 §2): the two plans' readings side by side, or stacked
    side, stacked = readings_block(solution, lang, size=READINGS_PT - less), readings_block(solution, lang, size=READINGS_PT - less, width=0.0)
    options = []
    for readings in ([side, stacked] if side is not None and stacked is not None and side.width != stacked.width else [side]):
        options.append([b for b in (eq_block, readings, table_block_) if b is not None])
    return tb_rows, tb_heights, options


def sheet_scales(
    solution,
    *,
    formula: str = "",
    table: list[list[str]] | None = None,
    equations: list[str] | None = None,
    lang: str = "en",
    title: str | None = None,
    branches: list[str] | None = None,
    given: dict | None = None,
    fixed: dict | None = None,
    mantissas=PAGE_MANTISSAS,
) -> dict[str, float]:
    """The scale factors with which the mechanism and the plans of *solution* fill their regions of its sheet.

    The sheet's regions come first: the text columns (vector equations,
    readings, results table) at the top right, over the title block, in one,
    two or three columns; the drawings share the rest, in the arrangement
    (which drawing where, in which shares) that makes the smallest of them,
    measured against :data:`MECHANISM_ACROSS_MM`, :data:`LARGEST_VECTOR_MM`
    and :data:`PLAN_ACROSS_MM`, largest.  Each factor is the smallest round
    value m·10ⁿ (m in *mantissas*: by default the page mantissas 1, 1.2, 1.5,
    2, 2.5, 3, 4, 5, 6, 8 of :data:`plans.graphical.scales.PAGE_MANTISSAS`)
    with which its drawing fits its region.  Drawing solves nothing: the
    caller constructs the plans again at these factors (the construction is a
    similarity: only the scale changes) and draws them with :func:`draw_sheet`.

    Parameters
    ----------
    solution : plans.graphical.GraphicalSolution
        Constructed at any factors (the automatic ones, say).
    formula, table, equations, lang, title, branches
        As for :func:`draw_sheet`: the texts take their room first.
    given : dict, optional
        ``{"k_l", "k_v", "k_a"}`` -> a factor the user gave (or None): kept exactly.
    fixed : dict, optional
        Kind -> what each drawing takes beyond its geometry [mm]
        (:func:`fixed_parts`); by default measured by drawing *solution* once.
        Its key ``"at"``, if any: kind -> {factor -> what the drawing took when drawn at that factor},
        used at those factors instead.
    mantissas : sequence of float
        The round mantissas allowed.

    Returns
    -------
    dict
        ``{"k_l", "k_v"}`` and ``"k_a"`` when there is an acceleration plan.
    """
    given = {k: v for k, v in (given or {}).items() if v is not None}
    with drawing_rc():
        if fixed is None:
            fig = new_figure()
            fixed = fixed_parts(solution, {kind: drawing_block(fig, kind, obj, lang) for kind, obj in _objects(solution).items()})
        tb_rows, tb_heights, options = _sheet_texts(solution, formula=formula, table=table, equations=equations, lang=lang, title=title, branches=branches)
    figures = {}
    for kind in _objects(solution):
        key = SCALE_OF[kind]
        size, largest = _geometry(solution, kind)
        figures[kind] = _Figure(kind, size, largest, fixed.get(kind, ESTIMATED_FIXED[kind]), given.get(key, solution.scales[key]), key in given,
                                _reach(solution) if kind == "mechanism" else None)
        figures[kind].at = dict(fixed.get("at", {}).get(kind, {}))
    best = _choose_scales(figures, options, sum(tb_heights), mantissas)
    if best is None or best[4] < 1.0:  # a drawing short of its target: the tables a point smaller, if that helps
        with drawing_rc():
            _, _, smaller = _sheet_texts(solution, formula=formula, table=table, equations=equations, lang=lang, title=title, branches=branches, small=True)
        found = _choose_scales(figures, smaller, sum(tb_heights), mantissas)
        if found is not None and (best is None or (_FORMAT_ORDER[found[0]], -found[3]) < (_FORMAT_ORDER[best[0]], -best[3] * SMALLER_GAIN)):
            best = found
    mechanism = figures.get("mechanism")
    if (best is None or best[4] < 1.0) and mechanism is not None and not mechanism.given and max(mechanism.size) > 0:
        # the mechanism across the top of the sheet, at the largest round factors that draw it 100 mm across or more
        need = max(mechanism.size) / MECHANISM_ACROSS_MM
        e = math.floor(math.log10(need))
        ks = sorted((k for k in (float(f"{m}e{d}") for d in (e - 1, e) for m in mantissas) if k <= need * (1 + 1e-12)), reverse=True)[:2]
        strips = tuple(mechanism.reach[1] / k + mechanism.fixed[1] + FIT_SLACK + 0.5 for k in ks)
        for texts in (options, smaller):
            found = _choose_scales(figures, texts, sum(tb_heights), mantissas, strips)
            if found is not None and (best is None or (_FORMAT_ORDER[found[0]], -found[4], -found[3]) < (_FORMAT_ORDER[best[0]], -best[4], -best[3])):
                best = found
    if best is None:  # nothing fits A0: the factors as they are
        return dict(solution.scales)
    return {SCALE_OF[kind]: k for kind, k in best[2].items()}


_FORMAT_ORDER = {name: i for i, (name, _) in enumerate(SHEET_FORMATS)}


def draw_sheet(
    solution,
    *,
    formula: str = "",
    table: list[list[str]] | None = None,
    equations: list[str] | None = None,
    lang: str = "en",
    title: str | None = None,
    branches: list[str] | None = None,
):
    """The one-page sheet as a matplotlib Figure (SVG canvas): A3 landscape, a frame and a title block.

    The drawings (mechanism, velocity and acceleration plans, each true to
    its scale factor), the vector equations, the readings of both plans and
    the results table are arranged inside the drawing frame: the texts in
    columns at the top right over the title block, the drawings in the
    regions left (see :func:`sheet_scales`, which chooses the factors that
    make them fill those regions).  The sheet is A3 landscape; a larger ISO
    sheet only when the factors (given by the user) draw the figures too
    large for A3.  The title block (lower right, ISO 7200 style) gives the
    title, the structural formula, the scale factors and, when given, the
    assembly branches.  Drawing solves nothing: everything printed is passed
    in.  The figure's ``plans_sheet`` attribute is the :class:`SheetLayout`.

    Parameters
    ----------
    solution : plans.graphical.GraphicalSolution
    formula : str
        The structural formula, for the title block.
    table : list of list of str, optional
        Results, first row the header.
    equations : list of str, optional
        Lines of vector equations; by default those of the plans' steps.
    lang : str
        Language of headings and legends (see :mod:`plans.i18n`); the table's
        header row is translated when it is the one of
        :func:`plans.report.sheet_table`.
    title : str, optional
        Instead of the scene's title.
    branches : list of str, optional
        The assembly branch of each group, one line each
        (``"RRR(3,4): C to the left of B→D"``), for the title block.
    """
    with drawing_rc():
        fig = new_figure()
        drawings = {kind: drawing_block(fig, kind, obj, lang) for kind, obj in _objects(solution).items()}
        texts_args = dict(formula=formula, table=table, equations=equations, lang=lang, title=title, branches=branches)
        tb_rows, tb_heights, options = _sheet_texts(solution, **texts_args)
        tb_h = sum(tb_heights)
        best = None
        for small in (False, True):  # the tables a point smaller only when A3 cannot hold them at their size
            variants = options if not small else _sheet_texts(solution, **texts_args, small=True)[2]
            for texts in variants:
                found = _choose_places(drawings, texts, tb_h)
                if found is not None and (best is None or (_FORMAT_ORDER[found[0]], -found[4]) < (_FORMAT_ORDER[best[0]], -best[4])):
                    best = found
            if best is not None and best[0] == SHEET_FIRST:
                break
        if best is None:  # larger than A0: the drawings in a row, the texts in a column beside them, a sheet of that size
            texts = options[0]
            row_w = sum(b.width for b in drawings.values()) + GAP * (len(drawings) - 1)
            row_h = max(b.height for b in drawings.values())
            text_w = max((b.width for b in texts), default=0.0)
            text_h = sum(b.height for b in texts) + GAP * max(len(texts) - 1, 0)
            pw = row_w + GAP + text_w + FRAME_LEFT + FRAME_OTHER + 2 * SHEET_PAD
            ph = max(row_h, text_h + GAP + tb_h) + 2 * FRAME_OTHER + 2 * SHEET_PAD
            boxes, x = {}, 0.0
            for kind, b in drawings.items():
                boxes[kind] = (x, 0.0, b.width, b.height)
                x += b.width + GAP
            placed, y = [], 0.0
            for b in texts:
                placed.append((b, x, y))
                y += b.height + GAP
            best = ("custom", (pw, ph), placed, boxes, 0.0)
        name, page, texts_placed, boxes, _ = best
        pw, ph = page
        fig.set_size_inches(pw / 25.4, ph / 25.4)
        paper = fig.add_axes([0, 0, 1, 1], zorder=-1)
        paper.set_xlim(0, pw)
        paper.set_ylim(0, ph)
        paper.set_axis_off()
        sheet = Sketch(paper, "sheet")

        # the drawing frame and the title block in its lower right corner
        left, right, bottom, top = FRAME_LEFT, pw - FRAME_OTHER, FRAME_OTHER, ph - FRAME_OTHER
        sheet.polygon([complex(left, bottom), complex(right, bottom), complex(right, top), complex(left, top)], lw=1.4, gid="sheet-frame", obstacle=False)
        tb_w = min(TITLE_BLOCK_W, right - left)
        tb_x = right - tb_w
        sheet.polygon([complex(tb_x, bottom), complex(right, bottom), complex(right, bottom + tb_h), complex(tb_x, bottom + tb_h)], lw=1.0, gid="title-block", obstacle=False)
        y = bottom + tb_h
        for k, ((lines, size, weight), h) in enumerate(zip(tb_rows, tb_heights)):
            if k:
                sheet.line([complex(tb_x, y), complex(right, y)], lw=0.5, gid="title-block-rule", obstacle=False)
            line_y = y - TITLE_BLOCK_PAD
            for line in lines:
                lh = measure(line, size, weight)[1]
                draw_text(sheet, complex(tb_x + TITLE_BLOCK_PAD + 1.0, line_y - lh / 2), line, size=size, weight=weight, gid="title-block-title" if k == 0 else f"title-block-row{k}")
                line_y -= lh + SHEET_LINE_GAP
            y -= h

        # content coordinates (x from the left, y down from the top of the content) to the page's
        x0, y0 = left + SHEET_PAD, top - SHEET_PAD
        placed_boxes, block_boxes = {}, {}
        for b, dx, dy in texts_placed:
            b.place(sheet, x0 + dx, y0 - dy - b.height, page)
            block_boxes.setdefault(b.kind, []).append((x0 + dx, y0 - dy - b.height, x0 + dx + b.width, y0 - dy))
        for kind, (bx, by, bw, bh) in boxes.items():  # each drawing centred in its box
            b = drawings[kind]
            x, yb = x0 + bx + (bw - b.width) / 2, y0 - by - bh + (bh - b.height) / 2
            b.place(sheet, x, yb, page)
            placed_boxes[kind] = (x0 + bx, y0 - by - bh, x0 + bx + bw, y0 - by)
            block_boxes[kind] = [(x, yb, x + b.width, yb + b.height)]
        fig.plans_sheet = SheetLayout(name, page, (left, bottom, right, top), (tb_x, bottom, right, bottom + tb_h), placed_boxes, block_boxes, dict(solution.scales), fixed_parts(solution, drawings))
    return fig


def write_drawings(
    solution,
    directory,
    *,
    formula: str = "",
    table: list[list[str]] | None = None,
    equations: list[str] | None = None,
    lang: str = "en",
    format: str = "svg",
    branches: list[str] | None = None,
    sheet=None,
) -> list[Path]:
    """Write ``mechanism.svg``, ``velocity.svg``, ``acceleration.svg`` and ``sheet.svg`` (or ``.pdf``, ``.png``: *format*).

    All four are rendered in memory first and then written atomically together
    (see :func:`plans._files.replace_all`): a failure leaves every
    existing file as it was and no temporary file behind.  ``acceleration.svg``
    is written only when the solution has an acceleration plan; an old one in
    *directory* is then removed if plans wrote it (and nobody changed it since),
    so the directory never mixes two runs.

    Parameters
    ----------
    solution : plans.graphical.GraphicalSolution
    directory : str or pathlib.Path
        Created if missing.
    formula : str
        The structural formula for the sheet.
    table : list of list of str, optional
        The results table for the sheet, first row the header.
    equations : list of str, optional
        Vector equations for the sheet; by default from the plans' steps.
    lang : str
        Language of headings and legends (:data:`plans.i18n.LANGUAGES`).
    branches : list of str, optional
        The assembly branches for the sheet's title block (:func:`branch_lines`).
    sheet : matplotlib.figure.Figure, optional
        The sheet, drawn already by :func:`draw_sheet` for this solution (else drawn here).

    Returns
    -------
    list of pathlib.Path
        The files written, in the order above.
    """
    from .mechanism import draw_mechanism
    from .plan_drawing import draw_plan

    from .formats import render

    directory = Path(directory)
    contents: dict[Path, bytes] = {}
    contents[directory / f"mechanism.{format}"] = render(draw_mechanism(solution, lang=lang)[0].figure, format)
    contents[directory / f"velocity.{format}"] = render(draw_plan(solution.velocity_plan, lang=lang)[0].figure, format)
    if solution.acceleration_plan is not None:
        contents[directory / f"acceleration.{format}"] = render(draw_plan(solution.acceleration_plan, lang=lang)[0].figure, format)
    if sheet is None:
        sheet = draw_sheet(solution, formula=formula, table=table, equations=equations, lang=lang, branches=branches)
    contents[directory / f"sheet.{format}"] = render(sheet, format)
    if format != "svg":  # the record of what plans wrote is an SVG comment: other formats remove nothing
        return replace_all(contents)
    # an acceleration.svg of an earlier run goes if plans wrote it (sheet.svg records it)
    return replace_all(contents, stale=(directory, r"acceleration\.svg", "sheet.svg"))
