"""Page layout of the matplotlib pages (the A3 sheets and the force pages).

* :func:`new_page` — an empty page of a given size [mm] with a paper axes in mm;
* :func:`header`, :func:`header_height`, :func:`footer`;
* :func:`choose_page` — the smallest ISO page that holds a content box.

The handout's pages are set by Typst (:mod:`plans.pages`).

User text (the title) is drawn as plain text (:func:`plans._text.user_text`).
"""

from __future__ import annotations

from .._text import user_text
from ._canvas import Sketch
from .svg import new_figure
from .typeset import draw_text, measure

__all__ = [
    "A4",
    "PAGES",
    "PAGE_MARGIN",
    "SHEET_FORMATS",
    "FRAME_LEFT",
    "FRAME_OTHER",
    "TITLE_BLOCK_W",
    "GAP",
    "DATA_PT",
    "FOOTER_PT",
    "PAGE_TITLE_PT",
    "new_page",
    "header",
    "header_height",
    "footer",
    "choose_page",
]

A4 = (210.0, 297.0)  # mm, portrait
#: ISO 216 pages [mm], landscape; portrait is tried as well.
PAGES = {"A4": (297.0, 210.0), "A3": (420.0, 297.0), "A2": (594.0, 420.0), "A1": (841.0, 594.0), "A0": (1189.0, 841.0)}
#: Sheet formats, landscape, smallest first: A4 or A3 as a rule; the larger ones only for what A3 cannot hold.
SHEET_FORMATS = (("A4", (297.0, 210.0)), ("A3", (420.0, 297.0)), ("A2", (594.0, 420.0)), ("A1", (841.0, 594.0)), ("A0", (1189.0, 841.0)))
#: The drawing frame [mm] (ISO 5457): 20 mm on the left (binding), 10 mm elsewhere.
FRAME_LEFT = 20.0
FRAME_OTHER = 10.0
#: The title block [mm] (ISO 7200): in the lower right corner of the frame, 180 mm wide.
TITLE_BLOCK_W = 180.0
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


def choose_page(width: float, height: float, margin: float) -> tuple[str, tuple[float, float]]:
    """The smallest ISO page (landscape, then portrait) that holds *width* × *height* [mm] within *margin*."""
    need_w, need_h = width + 2 * margin, height + 2 * margin
    for name, (w, h) in PAGES.items():
        for size in ((w, h), (h, w)):
            if need_w <= size[0] + 1e-9 and need_h <= size[1] + 1e-9:
                return name, size
    return "custom", (need_w, need_h)


# --- the position page of a handout: one frame of boxes, the same on every position page -------------
