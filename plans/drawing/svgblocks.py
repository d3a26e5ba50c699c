"""Drawings as SVG blocks of known physical size, for a typesetter to place at 100 %.

Each function draws one thing with matplotlib, one data unit one millimetre
of paper, and returns an :class:`SvgBlock`: the SVG bytes (root width and
height in mm, :func:`plans.drawing.svg.render_svg`) and that size.  A page
(:mod:`plans.pages`) places the block at its width, so the scale factor the
page states holds on the printed paper.

* :func:`mechanism_svg` — the kinematic scheme at k_l (no heading: the page states k_l);
* :func:`plan_svg` — a velocity or acceleration plan (no heading, no legend;
  notes on vectors too short to draw and the enlarged detail kept);
* :func:`legend_svg` — one legend for the plans of a page;
* :func:`positions_svg` — the plan of positions at k_l (paths of the points);
* :func:`centres_svg`, :func:`circle_diagram_svg` — the mechanism with its instant
  centres, and the circle diagram;
* :func:`figure_svg` — a whole matplotlib figure (a page of cycle diagrams).
"""

from __future__ import annotations

from dataclasses import dataclass

from ._canvas import Sketch, fit_axes
from .style import MARGIN_MM
from .svg import drawing_rc, new_figure, render_svg

__all__ = ["SvgBlock", "mechanism_svg", "plan_svg", "legend_svg", "positions_svg", "centres_svg", "circle_diagram_svg", "figure_svg", "sketched"]


@dataclass(frozen=True)
class SvgBlock:
    """A drawing as SVG bytes and its size [mm] on paper (width, height)."""

    svg: bytes
    width: float
    height: float


def _course_texts(fig, lang: str) -> None:
    """Every text of *fig* with its unit symbols as the course in *lang* writes them, before it is rendered.

    A text with math (a note ``$|v_K|$ = 2.35 mm``, a scale ``$k_l$ = 0.03 m/mm``) is
    rendered glyph by glyph, each its own SVG text node, where no whole symbol is left
    to rewrite: the texts are rewritten here, as matplotlib holds them (whole symbols
    outside the math only; a plan's image ``m`` stays).
    """
    if lang not in ("ru", "bg"):
        return
    from matplotlib.text import Text

    from .._text import course_units

    for artist in fig.findobj(Text):
        words = artist.get_text()
        if words:
            swapped = course_units(words, lang, drawn=True)
            if swapped != words:
                artist.set_text(swapped)


def _rendered(fig, lang: str) -> bytes:
    """*fig* as SVG, its texts' units first in the course's symbols (:func:`_course_texts`)."""
    _course_texts(fig, lang)
    return render_svg(fig)


def sketched(tag: str, draw, lang: str, margin: float = MARGIN_MM) -> SvgBlock:
    """Run ``draw(sketch)`` on a new figure sized to what it drew plus the *margin* [mm]."""
    with drawing_rc():
        fig = new_figure()
        ax = fig.add_axes([0, 0, 1, 1])
        sketch = Sketch(ax, tag)
        draw(sketch)
        width, height = fit_axes(ax, sketch.bounds, margin)
        return SvgBlock(_rendered(fig, lang), width, height)


def mechanism_svg(graphical, lang: str = "en") -> SvgBlock:
    """The kinematic scheme of a :class:`plans.graphical.GraphicalSolution` at its k_l, without heading and scale."""
    from .mechanism import MechanismDrawing

    return sketched("mech", lambda sketch: MechanismDrawing(sketch, graphical, lang=lang, caption=False).draw(), lang)


def plan_svg(plan, lang: str = "en", detail: bool = True, margin: float = MARGIN_MM, room: tuple[float, float] | None = None,
             detail_under: bool = False) -> SvgBlock:
    """A velocity or acceleration plan at its own scale, without heading, scale and legend (the page states them);
    *margin* [mm] of white around it (less for a plan across a page, whose edges are the text area's).

    With *room* (width, height [mm], the page's cell) a small plan whose short components are given only in notes is
    drawn again whole beside itself, enlarged n : 1 (the largest of
    :func:`plans.drawing.plan_drawing.whole_detail_ratios` that keeps the block in *room*), headed in the reader's
    language (gids ``…-detail-…``).  *detail_under*: an enlarged detail of crowded images that finds no room within
    the plan is drawn under it (:func:`plans.drawing.plan_drawing.draw_plan_into`)."""
    from .plan_drawing import draw_plan_into, enlarged, whole_detail_ratios

    tag = "vel" if plan.kind == "velocity" else "acc"

    def plain() -> SvgBlock:
        return sketched(tag, lambda sketch: draw_plan_into(sketch, plan, lang=lang, legend=False, detail=detail, heading=False,
                                                          detail_under=detail_under), lang, margin)

    if not detail or room is None:
        return plain()
    for ratio in whole_detail_ratios(plan):
        block = _beside_its_detail(plan, enlarged(plan, ratio), ratio, tag, lang, margin)
        if block.width <= room[0] + 0.5 and block.height <= room[1] + 0.5:
            return block
    return plain()


#: Gap [mm] between a plan's drawing and its whole detail beside it (besides the detail's margin).
DETAIL_GAP_MM = 4.0


def _beside_its_detail(plan, big, ratio: float, tag: str, lang: str, margin: float) -> SvgBlock:
    """The plan (its notes under it, one to a line where it is narrow) and, to its right, *big* (the plan enlarged
    *ratio* : 1) under its heading, tops level, in one block."""
    from ._canvas import text_size
    from .plan_drawing import detail_caption, draw_plan_into
    from .style import LABEL_PT

    with drawing_rc():
        fig = new_figure()
        ax = fig.add_axes([0, 0, 1, 1])
        small = Sketch(ax, tag)
        draw_plan_into(small, plan, lang=lang, legend=False, detail=True, heading=False, whole=ratio)
        ax2 = fig.add_axes([0, 0, 1, 1])
        large = Sketch(ax2, f"{tag}-detail")
        draw_plan_into(large, big, lang=lang, legend=False, caption=False, detail=False)
        b = large.bounds
        word, numeral = detail_caption(ratio, lang)
        if text_size(f"{word} {numeral}", LABEL_PT)[0] > b.width:  # (a long word, "выносной элемент", over the rest)
            large.text(complex(b.xmin, b.ymax + 3.0), numeral, size=LABEL_PT, ha="left", va="bottom", gid="name-ratio", obstacle=False)
            large.text(complex(b.xmin, large.bounds.ymax + 1.0), word, size=LABEL_PT, ha="left", va="bottom", gid="name", obstacle=False)
        else:
            large.text(complex(b.xmin, b.ymax + 3.0), f"{word} {numeral}", size=LABEL_PT, ha="left", va="bottom", gid="name", obstacle=False)
        w1, h1 = small.bounds.width + 2 * margin, small.bounds.height + 2 * margin
        w2, h2 = large.bounds.width + 2 * margin, large.bounds.height + 2 * margin
        x2 = w1 - margin + DETAIL_GAP_MM  # (the plan's margin the gap's first part)
        width, height = x2 + w2, max(h1, h2)
        fig.set_size_inches(width / 25.4, height / 25.4)
        fit_axes(ax, small.bounds, margin, (0.0, height - h1), (width, height))
        fit_axes(ax2, large.bounds, margin, (x2, height - h2), (width, height))
        return SvgBlock(_rendered(fig, lang), width, height)


#: the legend's rows [mm] apart; with a link's image among them (a row more), closer (8.5 pt text: 3 mm)
LEGEND_PITCH_MM, LEGEND_CLOSE_MM = 4.2, 3.6


def legend_svg(plans, lang: str = "en") -> SvgBlock:
    """One legend for *plans* (Plan objects): every kind of vector drawn on any of them, construction lines, and the
    images of links where a plan draws one."""
    from .plan_drawing import legend_entries, legend_row

    entries = legend_entries(plans, lang)
    # (a link's image, a row more, the rows closer: the legend about as tall as it was, the pages' flow kept)
    pitch = LEGEND_PITCH_MM if all(not kind.startswith("figure") for kind, _ in entries) else LEGEND_CLOSE_MM

    def draw(sketch):
        for k, (kind, text) in enumerate(entries):
            legend_row(sketch, kind, text, 0.0, -pitch * k, text_gid="legend-text")

    return sketched("legend", draw, lang)


def positions_svg(positions_run, k_l: float, lang: str = "en", extremes: dict | None = None) -> SvgBlock:
    """The plan of positions of a multi-position run at *k_l*: every position and the paths of the points (and the
    output's other extreme position, *extremes* ``{"0′": GraphicalSolution}``)."""
    from .positions_plan import draw_positions_into

    return sketched("positions", lambda sketch: draw_positions_into(sketch, positions_run, lang=lang, k_l=k_l, heading=False,
                                                                     extremes=extremes), lang)


def centres_svg(result, k_l: float, lang: str = "en", room_min: float | None = None, limit: tuple[float, float] | None = None,
                cycle=None) -> SvgBlock:
    """The mechanism at *k_l* with every instant centre (a :class:`plans.centres.CentresResult`), without the circle diagram
    (*limit*: the page's room [mm], see :func:`plans.drawing.centres.centres_frame`; *cycle*: the guides' travel and the
    cycle's poses, see :func:`plans.drawing.centres.draw_centres_into`)."""
    from .centres import ROOM_MIN, draw_centres_into

    with drawing_rc():
        fig = new_figure()
        ax = fig.add_axes([0, 0, 1, 1])
        width, height = draw_centres_into(ax, result, k_l, lang, legend=False, diagram=False, room_min=ROOM_MIN if room_min is None else room_min, limit=limit,
                                         cycle=cycle)
        return _fitted(fig, ax, width, height, lang)


def circle_diagram_svg(result, lang: str = "en", caption: bool = True, radius: float | None = None) -> SvgBlock:
    """The circle diagram of the instant centres (*caption* False: without its heading and legend; *radius* [mm] of its
    circle, by default :data:`plans.drawing.centres.DIAGRAM_R`)."""
    from .centres import draw_circle_diagram_into

    with drawing_rc():
        fig = new_figure()
        ax = fig.add_axes([0, 0, 1, 1])
        width, height = draw_circle_diagram_into(ax, result, lang, caption, **({"radius": radius} if radius else {}))
        return _fitted(fig, ax, width, height, lang)


def _fitted(fig, ax, width: float, height: float, lang: str) -> SvgBlock:
    fig.set_size_inches(width / 25.4, height / 25.4)
    ax.set_position([0.0, 0.0, 1.0, 1.0])
    return SvgBlock(_rendered(fig, lang), width, height)


def figure_svg(fig, lang: str = "en") -> SvgBlock:
    """A whole figure (drawn for a page in *lang*) as a block of its own size."""
    width, height = (x * 25.4 for x in fig.get_size_inches())
    with drawing_rc():
        return SvgBlock(_rendered(fig, lang), width, height)
