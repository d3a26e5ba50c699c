"""Frames of an animation: the mechanism and its plans at every position of a run, on one canvas.

A lecture page or a slide shows the plans *move*: every frame is drawn at the
run's one set of scale factors (k_l, k_v, k_a shared by all positions, see
:func:`plans.positions.run_positions`), and every drawing keeps one place and
one size on a canvas that is the same for all frames, so the plans' growth
and shrinking is what the eye sees:

* the mechanism's frame pivots and each plan's pole stay where they are from
  frame to frame (each drawing's box is the union of its boxes over the cycle),
  and the two plans' poles are on one level;
* each drawing is headed by its name and scale factor, once for all frames;
* a position that cannot be solved gets a frame with the headings and the
  reason, in the reader's language.

:class:`CycleFrames` draws the frames (one matplotlib Figure each, the same
drawing code as the sheets: :class:`plans.drawing.mechanism.MechanismDrawing`
and :func:`plans.drawing.plan_drawing.draw_plan_into`, without the captions
that would move with each drawing's own box, and without the enlarged details
of crowded images, which would jump about).  ``svg(k)`` gives a frame as SVG
(deterministic: the same run gives the same bytes), ``rgb(k)`` as pixels
(matplotlib's Agg) for a GIF or an MP4.

:func:`draw_cursor_diagrams` draws the cycle diagrams once, each with a
cursor (an SVG group of its own id) and how far to move it, frame by frame;
:func:`draw_plan_legend` the legend of the plans' vector kinds, once.

Gids as on the sheets: ``mech-…`` of the scheme, ``vel-…`` and ``acc-…`` of
the plans; ``mech-heading``/``mech-scale`` (and ``vel-``, ``acc-``) of the
headings, ``mech-not-solved`` of the reason a position is not solved.
"""

from __future__ import annotations

import re

import numpy as np
from matplotlib.text import Text

from ..graphical.plan import KINDS
from ..i18n import term
from .._text import user_text
from ._canvas import Bounds, Sketch, fit_axes, fmt_number, text_size
from .diagrams import marks_shown, plot_cycle
from .mechanism import MechanismDrawing
from .numerals import scale_caption
from .plan_drawing import draw_plan_into, kinds_drawn, legend_row, legend_words
from .style import CAPTION_PT, HEADING_PT, INK, LABEL_PT, MARGIN_MM
from .svg import drawing_rc, new_figure, render_svg

__all__ = ["CycleFrames", "draw_cursor_diagrams", "draw_plan_legend", "frame_svg_text", "PANELS", "GAP_MM", "HEAD_MM", "CURSOR_COLOUR", "LECTURE_TEXT_SCALE", "NOTE_ROOM"]

#: The drawings of a frame, left to right: the scheme, the velocity plan, the acceleration plan.
PANELS = ("mechanism", "velocity", "acceleration")
_TAG = {"mechanism": "mech", "velocity": "vel", "acceleration": "acc"}
_HEADING = {"mechanism": "mechanism", "velocity": "velocity_plan", "acceleration": "acceleration_plan"}
_SCALE = {"mechanism": ("k_l", "m/mm"), "velocity": ("k_v", "(m/s)/mm"), "acceleration": ("k_a", "(m/s²)/mm")}
#: Space [mm] between the drawings of a frame.
GAP_MM = 10.0
#: Height [mm] of the heading band above each drawing (its name and its scale factor).
HEAD_MM = 13.0
#: How much larger the texts of a lecture page's frames are than on a sheet (:class:`CycleFrames`' ``text_scale``):
#: a frame of three drawings some 450 mm wide fills a screen 1280 px wide, about 2.5 px a millimetre, at which a
#: sheet's 10 pt label would be 9 px tall; 1.6 times it reads from the back of a lecture room.
LECTURE_TEXT_SCALE = 1.6
#: The cursor of the cycle diagrams.
CURSOR_COLOUR = "#c0392b"


def _plan(graphical, kind: str):
    return graphical.velocity_plan if kind == "velocity" else graphical.acceleration_plan


class CycleFrames:
    """The mechanism and its plans at every position of a run: one Figure per position, one canvas for all.

    Parameters
    ----------
    run : plans.positions.PositionsRun
        Solved at one set of scale factors (``run.scales``).
    lang : str
        Language of the headings and of the reasons (see :mod:`plans.i18n`).
    text_scale : float
        Every text of the drawings (labels, link numbers, ω of the driver, headings) is this many times the
        size it has on a sheet: a frame is shown on a screen or a projector the width of the whole frame,
        smaller than a sheet's millimetres (see :data:`LECTURE_TEXT_SCALE`); the drawings keep their scales.

    Attributes
    ----------
    panels : tuple of str
        The drawings of each frame (``"acceleration"`` only when the run has acceleration plans).
    size_mm : tuple of float
        (width, height) of every frame [mm]; one data unit of each drawing is one millimetre of it.
    extents : list of dict
        For each frame, each drawing's extent as drawn there, ``(xmin, ymin, xmax, ymax)`` [mm of the drawing,
        its pole or the frame's origin at 0], None where nothing is drawn.
    boxes : dict
        Each drawing's box (:class:`plans.drawing._canvas.Bounds`): the union of its extents over all frames,
        without the margins and the heading band.

    Raises
    ------
    ValueError
        For a run in which no position is solved (nothing to draw).
    """

    def __init__(self, run, *, lang: str = "en", text_scale: float = 1.0):
        self.run = run
        self.lang = lang
        self.text_scale = float(text_scale)
        solved = [r for r in run.runs if r.ok]
        if not solved:
            raise ValueError("no position of the run is solved: there is nothing to draw")
        self.panels = tuple(p for p in PANELS if p != "acceleration" or any(r.graphical.acceleration_plan is not None for r in solved))
        self.figures = []
        self._sketches = []
        with drawing_rc():
            for r in run.runs:
                fig = new_figure()
                sketches = {}
                for kind in self.panels:
                    ax = fig.add_axes([0.0, 0.0, 0.01, 0.01])
                    ax.set_axis_off()
                    sketch = Sketch(ax, _TAG[kind])
                    if r.ok:
                        if kind == "mechanism":
                            MechanismDrawing(sketch, r.graphical, lang=lang, caption=False).draw()
                        elif _plan(r.graphical, kind) is not None:
                            draw_plan_into(sketch, _plan(r.graphical, kind), lang=lang, caption=False, detail=False)
                    if self.text_scale != 1.0:
                        for artist in sketch.artists:
                            if isinstance(artist, Text):
                                artist.set_fontsize(artist.get_fontsize() * self.text_scale)
                    sketches[kind] = sketch
                self.figures.append(fig)
                self._sketches.append(sketches)
            self._lay_out()

    # -- one canvas for all frames -------------------------------------------------------

    def _lay_out(self) -> None:
        self.extents = [
            {kind: None if sketches[kind].bounds.empty else tuple(float(v) for v in (b.xmin, b.ymin, b.xmax, b.ymax)) for kind, b in
             ((kind, sketches[kind].bounds) for kind in self.panels)}
            for sketches in self._sketches
        ]
        scale = self.text_scale
        margin, head = MARGIN_MM * scale, HEAD_MM * scale  # room for the enlarged texts at the drawings' edges
        boxes = {}
        for kind in self.panels:
            union = Bounds()
            for sketches in self._sketches:
                b = sketches[kind].bounds
                if not b.empty:
                    union.add_box(b.xmin, b.ymin, b.xmax, b.ymax)
            if union.empty:
                union.add(0.0, 0.0)
            heading, caption = self._heading(kind)
            need = max(text_size(heading, HEADING_PT * scale, "bold")[0], text_size(caption, CAPTION_PT * scale, math=True)[0])
            if union.width + 2 * margin < need:
                union.add(union.xmin + need - 2 * margin, union.ymin)
            boxes[kind] = union
        widths = {k: b.width + 2 * margin for k, b in boxes.items()}
        # every panel is the frame's height, its heading at the top; the plans' poles (0, 0 of a plan) on one
        # level, so that the two plans read side by side; the scheme from the top
        pole_depth = max((b.ymax + margin + head for k, b in boxes.items() if k != "mechanism"), default=0.0)
        tops = {k: pole_depth if k != "mechanism" else b.ymax + margin + head for k, b in boxes.items()}
        height = max(tops[k] - (b.ymin - margin) for k, b in boxes.items())
        width = sum(widths.values()) + GAP_MM * (len(self.panels) - 1)
        self.size_mm = (width, height)
        self.boxes = boxes
        with drawing_rc():
            for r, fig, sketches in zip(self.run.runs, self.figures, self._sketches):
                fig.set_size_inches(width / 25.4, height / 25.4)
                x = 0.0
                for kind in self.panels:
                    b, sketch = boxes[kind], sketches[kind]
                    w = widths[kind]
                    ax = sketch.ax
                    ax.set_position([x / width, 0.0, w / width, 1.0])
                    ax.set_xlim(b.xmin - margin, b.xmax + margin)
                    ax.set_ylim(tops[kind] - height, tops[kind])
                    ax.set_aspect("auto")
                    heading, caption = self._heading(kind)
                    left, top = complex(b.xmin - margin + 1.0, 0), tops[kind] - 1.0
                    sketch.text(left + 1j * top, heading, size=HEADING_PT * scale, ha="left", va="top", weight="bold", gid="heading", obstacle=False)
                    sketch.text(left + 1j * (top - 6.0 * scale), caption, size=CAPTION_PT * scale, ha="left", va="top", gid="scale", obstacle=False,
                                math=True)
                    if not r.ok and kind == "mechanism":
                        # from the frame's left edge: the words may be wider than the scheme's panel, and the
                        # plans' panels beside it are empty at this position
                        at = complex(b.xmin - margin + 1.0, (b.ymin + b.ymax) / 2)
                        sketch.text(at, term("not_solved", self.lang), size=LABEL_PT * scale, ha="left", weight="bold", gid="not-solved", obstacle=False)
                        sketch.text(at - 6j * scale, user_text(r.brief(self.lang)), size=CAPTION_PT * scale, ha="left", gid="not-solved", obstacle=False)
                    x += w + GAP_MM

    def _heading(self, kind: str) -> tuple[str, str]:
        key, units = _SCALE[kind]
        return term(_HEADING[kind], self.lang), scale_caption(key, fmt_number(self.run.scales[key]), units, self.lang)

    # -- output -------------------------------------------------------------------------

    def __len__(self) -> int:
        return len(self.figures)

    def svg(self, k: int) -> bytes:
        """Frame *k* as SVG bytes (sized in mm; deterministic)."""
        return render_svg(self.figures[k])

    def rgb(self, k: int, width_px: int, title: str | None = None) -> np.ndarray:
        """Frame *k* as an (height, width, 3) array of uint8, *width_px* pixels wide (white background), with
        *title* written above the drawings (a slide has no page around it to say the position)."""
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        fig = self.figures[k]
        width_mm, height_mm = self.size_mm
        band = 9.0 if title else 0.0
        dpi = width_px / (width_mm / 25.4)
        with drawing_rc():
            saved = [ax.get_position().bounds for ax in fig.axes]
            fig.set_size_inches(width_mm / 25.4, (height_mm + band) / 25.4)
            for ax, (x0, y0, w, h) in zip(fig.axes, saved):  # each drawing keeps its size and moves down by the band
                ax.set_position([x0, y0 * height_mm / (height_mm + band), w, h * height_mm / (height_mm + band)])
            text = fig.text(4.0 / width_mm, 1 - 2.0 / (height_mm + band), title, fontsize=HEADING_PT + 1, ha="left", va="top", color=INK) if title else None
            fig.patch.set_visible(True)
            fig.patch.set_facecolor("white")
            try:
                canvas = FigureCanvasAgg(fig)
                fig.set_dpi(dpi)
                canvas.draw()
                pixels = np.asarray(canvas.buffer_rgba())[:, :, :3].copy()
            finally:
                if text is not None:
                    text.remove()
                fig.patch.set_visible(False)
                fig.set_dpi(72)
                fig.set_size_inches(width_mm / 25.4, height_mm / 25.4)
                for ax, bounds in zip(fig.axes, saved):
                    ax.set_position(bounds)
        return pixels


#: The ids matplotlib gives what has no gid of ours (``figure_1``, ``axes_2``, ``text_5`` …): the same in every SVG.
_AUTOMATIC_ID = re.compile(r' id="((?:figure|axes|patch|text|line2d|legend|xtick|ytick|matplotlib\.axis|PathCollection|PolyCollection|LineCollection|QuadMesh)_\d+)"')


#: The ids matplotlib derives from a hash of what it defines (markers ``m…``, clip paths ``p…``), and the references to
#: them: two SVGs of one page that draw the same marker would share the id.
_HASHED_ID = re.compile(r'(id="|href="#|url\(#)([mp][0-9a-f]{10})(?=[")])')


def frame_svg_text(data: bytes, name: str | None = None) -> str:
    """An SVG of :mod:`plans.drawing.svg` as text to put inside a page: no XML declaration, DOCTYPE or metadata;
    with *name*, matplotlib's own ids (``figure_1`` …) prefixed by it, so that SVGs side by side on one page do not
    share an id (the ids of plans' drawings, ``mech-…``, ``vel-…``, are kept; the markers' and clip paths' ids are
    prefixed too, with the references to them)."""
    text = data.decode("utf-8")
    start = text.index("<svg")
    text = text[start:]
    head, _, rest = text.partition("<metadata>")
    if rest:
        text = head + rest.partition("</metadata>")[2]
    if name:
        text = _AUTOMATIC_ID.sub(lambda m: f' id="{name}-{m.group(1)}"', text)
        text = _HASHED_ID.sub(lambda m: f"{m.group(1)}{name}-{m.group(2)}", text)
    return text.strip()


def draw_cursor_diagrams(run, quantities, *, lang: str = "en", columns: int = 2, cell_mm: tuple[float, float] = (118.0, 52.0)):
    """The cycle diagrams of *quantities* (names of :data:`plans.drawing.diagrams.QUANTITIES`), each with a cursor.

    Returns ``(figure, cursors)``: *cursors* maps the gid of each cursor (``cursor-omega`` …) to a list with,
    for each position of *run*, how far [SVG user units: pt] to move it from where it is drawn along the
    horizontal axis, or None where the diagram does not show that position (the mechanism does not assemble).
    """
    from matplotlib.backends.backend_svg import FigureCanvasSVG
    from matplotlib.figure import Figure

    quantities = list(quantities)
    rows = -(-len(quantities) // columns)
    cw, ch = cell_mm
    width, height = cw * min(columns, len(quantities)), ch * rows
    cursors = {}
    with drawing_rc():
        fig = Figure(figsize=(width / 25.4, height / 25.4), dpi=72)
        FigureCanvasSVG(fig)
        for n, quantity in enumerate(quantities):
            row, col = divmod(n, columns)
            left, bottom = col * cw + 17.0, height - (row + 1) * ch + 11.0
            ax = fig.add_axes([left / width, bottom / height, (cw - 17.0 - 32.0) / width, (ch - 17.0) / height])
            plot_cycle(run.cycle, quantity, ax, lang=lang, cycle=run.dense)
            _room_for_notes(ax)
            ticks = ax.get_xticks()
            if len(ticks) > 7:  # every 60° rather than 30°: a diagram of the page is narrower than a handout's
                ax.set_xticks(ticks[::2])
            marks = dict(marks_shown(run.cycle, run.motion if run.motion is not None else run.positions, cycle=run.dense))
            shown = [marks.get(r.index) if r.ok else None for r in run.runs]
            first = next((x for x in shown if x is not None), None)
            gid = f"cursor-{quantity}"
            if first is None:
                cursors[gid] = [None] * len(shown)
                continue
            ax.axvline(first, color=CURSOR_COLOUR, lw=1.6, zorder=4, clip_on=False, gid=gid)
            origin = float(ax.transData.transform((first, 0.0))[0])
            cursors[gid] = [None if x is None else round(float(ax.transData.transform((x, 0.0))[0]) - origin, 3) for x in shown]
    return fig, cursors


#: The share of a diagram's height kept free above its curves for the notes written in it.
NOTE_ROOM = 0.22


def _room_for_notes(ax) -> None:
    """Raise the top of *ax* so that the notes :func:`plans.drawing.diagrams.plot_cycle` writes across the top of
    the plotting area (ω₂ = 6 rad/s …, what is clipped) stand above the curves rather than hide them."""
    notes = [t for t in ax.texts if t.get_transform() == ax.transAxes and t.get_position()[1] >= 0.8 and 0.0 <= t.get_position()[0] <= 1.0]
    if notes:
        bottom, top = ax.get_ylim()
        ax.set_ylim(bottom, top + NOTE_ROOM / (1.0 - NOTE_ROOM) * (top - bottom))


def draw_plan_legend(run, *, lang: str = "en"):
    """The legend of the vector kinds drawn on the run's plans, one column per plan, as a Figure of its own size."""
    columns = []
    for kind in ("velocity", "acceleration"):
        drawn = set()
        for r in run.runs:
            if r.ok and _plan(r.graphical, kind) is not None:
                drawn |= kinds_drawn(_plan(r.graphical, kind))
        if drawn:
            rows = [(k, legend_words(kind, k, lang)) for k in KINDS if k in drawn] + [("construction", legend_words(kind, "construction", lang))]
            columns.append((kind, rows))
    with drawing_rc():
        fig = new_figure()
        ax = fig.add_axes([0, 0, 1, 1])
        sketch = Sketch(ax, "legend")
        x = 0.0
        row_h = text_size("lp", CAPTION_PT)[1] + 1.2
        for kind, rows in columns:
            sketch.text(complex(x, 0.0), term(_HEADING[kind], lang), size=CAPTION_PT, ha="left", va="center", weight="bold", gid=f"heading-{kind}", obstacle=False)
            widest = text_size(term(_HEADING[kind], lang), CAPTION_PT, "bold")[0]
            for n, (vector_kind, words) in enumerate(rows, 1):
                legend_row(sketch, vector_kind, words, x, -n * row_h, text_gid=f"text-{kind}-{vector_kind}")
                widest = max(widest, 11.0 + text_size(words, CAPTION_PT)[0])
            x += widest + 8.0
        fit_axes(ax, sketch.bounds, 1.5)
    return fig

