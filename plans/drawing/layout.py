"""Page layout: where blocks go on a page (blocks from :mod:`plans.drawing.blocks`).

* :func:`new_page` — an empty page of a given size [mm] with a paper axes in mm;
* :func:`header`, :func:`header_height`, :func:`footer`, :func:`stamp_page_number`;
* :func:`arrangements` — the ways of arranging the mechanism, the plans and the legend;
* :func:`place_rows`, :func:`excess` — rows of blocks placed from the top, and
  how far they would run over;
* :func:`choose_page` — the smallest ISO page that holds a content box.

User text (the title) is drawn as plain text (:func:`plans._text.user_text`).
"""

from __future__ import annotations

from .._text import user_text
from ..i18n import term
from ._canvas import Sketch
from .blocks import Block, column
from .svg import new_figure
from .typeset import draw_text, measure

__all__ = [
    "A4",
    "PAGES",
    "PAGE_MARGIN",
    "GAP",
    "DATA_PT",
    "FOOTER_PT",
    "PAGE_TITLE_PT",
    "new_page",
    "header",
    "header_height",
    "footer",
    "stamp_page_number",
    "arrangements",
    "place_rows",
    "excess",
    "choose_page",
]

A4 = (210.0, 297.0)  # mm, portrait
#: ISO 216 pages [mm], landscape; portrait is tried as well.
PAGES = {"A4": (297.0, 210.0), "A3": (420.0, 297.0), "A2": (594.0, 420.0), "A1": (841.0, 594.0), "A0": (1189.0, 841.0)}
PAGE_MARGIN = 11.0  # mm
GAP = 5.0  # mm between blocks
DATA_PT = 8.0
FOOTER_PT = 7.0
FOOTER_COLOUR = "#555555"
PAGE_NUMBER_Y = 6.0  # mm above the foot of the page, the centre of the page number
PAGE_TITLE_PT = 13.5


def new_page(size=A4):
    """A figure of *size* [mm] and a :class:`Sketch` on a paper axes whose data unit is 1 mm."""
    fig = new_figure(*size)
    paper = fig.add_axes([0, 0, 1, 1], zorder=-1)
    paper.set_xlim(0, size[0])
    paper.set_ylim(0, size[1])
    paper.set_axis_off()
    return fig, Sketch(paper, "page")


def _header_rows(title: str, lines: list[str]) -> list[tuple[str, float, str, float]]:
    """(text, size, weight, advance [mm]) of a header: the title (plain text), then the data lines (``§`` bold)."""
    rows = [(user_text(title), PAGE_TITLE_PT, "bold", measure("lp", PAGE_TITLE_PT, "bold")[1] + 1.2)]
    for line in lines:
        weight = "bold" if line.startswith("§") else "normal"
        line = line.lstrip("§")
        rows.append((line, DATA_PT, weight, measure(line, DATA_PT, weight)[1] + 0.7))
    return rows


def header(sketch: Sketch, size, title: str, lines: list[str]) -> float:
    """Title and data lines at the top of a page, a rule under them; returns the y [mm] below."""
    pw, ph = size
    y = ph - PAGE_MARGIN
    for k, (text, pt, weight, advance) in enumerate(_header_rows(title, lines)):
        h = measure(text, pt, weight)[1]
        draw_text(sketch, complex(PAGE_MARGIN, y - h / 2), text, size=pt, weight=weight, gid="page-title" if k == 0 else "page-data")
        y -= advance
    sketch.line([complex(PAGE_MARGIN, y - 1.0), complex(pw - PAGE_MARGIN, y - 1.0)], lw=0.6, gid="page-rule", obstacle=False)
    return y - 1.0 - GAP * 0.8


def header_height(lines) -> float:
    """What :func:`header` takes from the top of the page [mm]."""
    return PAGE_MARGIN + sum(row[3] for row in _header_rows("", list(lines))) + 1.0 + GAP * 0.8


def footer(sketch: Sketch, left: str) -> None:
    """A footer line at the foot of the page, left (plain text)."""
    draw_text(sketch, complex(PAGE_MARGIN, PAGE_MARGIN * 0.55), user_text(left), size=FOOTER_PT, gid="page-footer", color=FOOTER_COLOUR)


def stamp_page_number(fig, number: int, total: int, lang: str) -> None:
    """``"Page 3/12"`` at the foot of any page (a handout page or a cycle diagram), right-aligned in the margin."""
    width, height = fig.get_size_inches() * 25.4
    fig.text(1 - PAGE_MARGIN / width, PAGE_NUMBER_Y / height, f"{term('page', lang)} {number}/{total}", ha="right", va="center", fontsize=FOOTER_PT, color=FOOTER_COLOUR)


def place_rows(sketch: Sketch, size, top: float, rows: list[list[Block]]) -> None:
    """Rows of blocks from *top* down, each row spread over the page width (placed even if they do not fit)."""
    avail_w = size[0] - 2 * PAGE_MARGIN
    for row in rows:
        widths = sum(b.width for b in row)
        spare = max(0.0, avail_w - widths)
        gap = min(spare / (len(row) - 1), 18.0) if len(row) > 1 else 0.0
        x = PAGE_MARGIN
        h = max(b.height for b in row)
        for b in row:
            b.place(sketch, x, top - b.height, size)
            x += b.width + gap
        top -= h + GAP


def excess(size, top: float, rows) -> float:
    """How far [mm] rows of blocks placed from *top* run past the bottom margin or the width (0 or less: they fit)."""
    pw, _ = size
    need = sum(max(b.height for b in row) for row in rows) + GAP * (len(rows) - 1)
    over_h = need - (top - PAGE_MARGIN - 2.0)
    over_w = max(sum(b.width for b in row) + GAP * (len(row) - 1) for row in rows) - (pw - 2 * PAGE_MARGIN)
    return max(over_h, over_w)


def arrangements(mech: Block, vel: Block, acc: Block | None, legend: Block, size) -> list[list[list[Block]]]:
    """The arrangements of a page's drawings to try, in order of preference (rows of blocks)."""
    width = size[0] - 2 * PAGE_MARGIN
    plans_ = [b for b in (vel, acc) if b is not None]
    layouts: list[list[list[Block]]] = []
    # all three in a row (a long, low mechanism)
    if sum(b.width for b in [mech] + plans_) + GAP * len(plans_) <= width:
        layouts.append([[mech] + plans_, [legend]])
    # the mechanism (and the legend under it) beside the plans stacked: a tall mechanism
    left, right = column([mech, legend], GAP), column(plans_, GAP)
    if left.width + right.width + GAP <= width:
        layouts.append([[left, right]])
    stack = column(plans_ + [legend], GAP)
    if mech.width + stack.width + GAP <= width:
        layouts.append([[mech, stack]])
    # the mechanism and the velocity plan, then the acceleration plan and the legend
    if acc is not None:
        layouts.append([[mech, vel], [acc, legend]])
    else:
        layouts.append([[mech, vel], [legend]])
    return layouts


def choose_page(width: float, height: float, margin: float) -> tuple[str, tuple[float, float]]:
    """The smallest ISO page (landscape, then portrait) that holds *width* × *height* [mm] within *margin*."""
    need_w, need_h = width + 2 * margin, height + 2 * margin
    for name, (w, h) in PAGES.items():
        for size in ((w, h), (h, w)):
            if need_w <= size[0] + 1e-9 and need_h <= size[1] + 1e-9:
                return name, size
    return "custom", (need_w, need_h)
