"""Page layout: where blocks go on a page (blocks from :mod:`plans.drawing.blocks`).

* :func:`new_page` — an empty page of a given size [mm] with a paper axes in mm;
* :func:`header`, :func:`header_height`, :func:`footer`, :func:`stamp_page_number`;
* :func:`position_frames`, :func:`place_in_box` — the arrangements of a
  position's drawings (boxes on its velocity and acceleration pages), and a
  block placed in its box;
* :func:`choose_page` — the smallest ISO page that holds a content box.

User text (the title) is drawn as plain text (:func:`plans._text.user_text`).
"""

from __future__ import annotations

from .._text import user_text
from ..i18n import term
from ._canvas import Sketch
from .blocks import Block
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
    "stamp_page_number",
    "choose_page",
    "Frame",
    "position_frames",
    "place_in_box",
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


def stamp_page_number(fig, number: int, total: int, lang: str) -> None:
    """``"Page 3/12"`` at the foot of any page (a handout page or a cycle diagram), right-aligned in the margin."""
    width, height = fig.get_size_inches() * 25.4
    fig.text(1 - PAGE_MARGIN / width, PAGE_NUMBER_Y / height, f"{term('page', lang)} {number}/{total}", ha="right", va="center", fontsize=FOOTER_PT, color=FOOTER_COLOUR)


def choose_page(width: float, height: float, margin: float) -> tuple[str, tuple[float, float]]:
    """The smallest ISO page (landscape, then portrait) that holds *width* × *height* [mm] within *margin*."""
    need_w, need_h = width + 2 * margin, height + 2 * margin
    for name, (w, h) in PAGES.items():
        for size in ((w, h), (h, w)):
            if need_w <= size[0] + 1e-9 and need_h <= size[1] + 1e-9:
                return name, size
    return "custom", (need_w, need_h)


# --- the position page of a handout: one frame of boxes, the same on every position page -------------


class Frame:
    """Boxes [mm] (x, y of the lower-left corner, width, height) for the drawings of a position's pages.

    ``boxes`` has ``"mechanism"``, ``"velocity"`` and (when there is one)
    ``"acceleration"``; ``pages`` says on which page each is drawn
    (``"velocity"``: the mechanism and the velocity plan;
    ``"acceleration"``: the acceleration plan alone); *name* says which
    arrangement it is; ``text`` (page -> box), where a page's legend and
    vector equations go when not in a band at its foot; ``sizes`` (page -> (width, height) [mm]),
    a page that is not A4 portrait (A4 landscape); ``equations`` (page -> plan kinds), the plans whose
    vector equations a page prints when not those drawn on it.
    """

    def __init__(self, name: str, boxes: dict[str, tuple[float, float, float, float]], pages: dict[str, str] | None = None,
                 text: dict[str, tuple[float, float, float, float]] | None = None, sizes: dict[str, tuple[float, float]] | None = None,
                 equations: dict[str, tuple[str, ...]] | None = None):
        self.name = name
        self.boxes = boxes
        self.pages = pages or {kind: "velocity" for kind in boxes}
        self.text = text or {}
        self.sizes = sizes or {}
        self.equations = equations or {}

    def equations_on(self, page: str) -> tuple[str, ...]:
        """The plans whose vector equations *page* prints: those of its plans unless the frame says otherwise."""
        return self.equations.get(page, tuple(kind for kind in ("velocity", "acceleration") if self.pages.get(kind) == page))

    def size(self, page: str) -> tuple[float, float]:
        """The size [mm] of *page*: A4 portrait unless the frame says otherwise (``sizes``)."""
        return self.sizes.get(page, A4)

    def on(self, page: str) -> dict[str, tuple[float, float, float, float]]:
        """The boxes drawn on *page* (``"velocity"`` or ``"acceleration"``)."""
        return {kind: box for kind, box in self.boxes.items() if self.pages[kind] == page}

    def __repr__(self) -> str:
        return f"Frame({self.name!r}, {self.boxes!r})"


def position_frames(bands: dict[str, tuple[float, float]], size=A4) -> list[Frame]:
    """The arrangements of a position's drawings to choose from, on two A4 portrait pages.

    *bands* gives (top, bottom) [mm] of the room each page leaves its
    drawings: ``"velocity"`` (the mechanism and the velocity plan) and, when
    there is an acceleration plan, ``"acceleration"`` (that plan alone, the
    whole room).  On the velocity page:

    * ``top-N``: the mechanism across the page (N % of the height), the
      velocity plan under it;
    * ``left-N``: the mechanism in a column on the left (N % of the width),
      the velocity plan on the right.
    """
    x0 = PAGE_MARGIN
    width = size[0] - 2 * PAGE_MARGIN
    top, bottom = bands["velocity"]
    height = top - bottom
    extra: dict[str, tuple[float, float, float, float]] = {}
    if "acceleration" in bands:
        a_top, a_bottom = bands["acceleration"]
        extra["acceleration"] = (x0, a_bottom, width, a_top - a_bottom)
    pages = {"mechanism": "velocity", "velocity": "velocity", "acceleration": "acceleration"}
    frames = []
    for share in (0.4, 0.5, 0.6):
        hm = height * share
        boxes = {"mechanism": (x0, top - hm, width, hm), "velocity": (x0, bottom, width, height - hm - GAP), **extra}
        frames.append(Frame(f"top-{round(share * 100)}", boxes, pages))
    for share in (0.5, 0.6):
        wm = width * share
        boxes = {"mechanism": (x0, bottom, wm, height), "velocity": (x0 + wm + GAP, bottom, width - wm - GAP, height), **extra}
        frames.append(Frame(f"left-{round(share * 100)}", boxes, pages))
    return frames


def place_in_box(block: Block, sketch: Sketch, box, size) -> float:
    """*block* at the top of *box*, centred across it; returns how far [mm] it runs out of the box (0: inside)."""
    x, y, w, h = box
    bx = x + (w - block.width) / 2
    block.place(sketch, bx, y + h - block.height, size)
    return max(0.0, block.width - w, block.height - h)
