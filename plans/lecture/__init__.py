"""Plans that move: a lecture page, a GIF or an MP4 of the mechanism and its plans over the cycle.

A lecturer explains a velocity plan by turning the crank and letting the class
watch the plan change shape.  :func:`animate` solves the mechanism at N
positions of its cycle (default 36) with :func:`plans.positions.run_positions`
— the positions its driver law gives (:func:`plans.positions.parse_positions`),
one k_l, k_v, k_a for all of them — and returns an :class:`Animation`:

* ``animation.html`` — one self-contained HTML page (:mod:`plans.lecture.page`):
  the mechanism, its velocity and acceleration plans, the cycle diagrams with
  a cursor, the position's values; a slider, play/pause, step keys; opens
  from a file, no server or network; ``page.html#position=K`` opens position K;
* ``animation.gif()``, ``animation.mp4()`` — for slides (:mod:`plans.lecture.video`);
* ``animation.save(path)`` — by the suffix: ``.html``, ``.gif`` or ``.mp4``, atomically;
* in a notebook the Animation shows itself: its ``_repr_html_`` is the same page
  (in an inline frame, so that its keys and ids stay its own).

The positions and the driver's rates follow the driver's law over the cycle (:mod:`plans.motion`: constant
speed by default, a harmonic swing for a crank that cannot turn fully), from the output link's extreme
position; the page states the law.

The command line: ``plans animate SCENE -o page.html [--positions N] [--lang sr] [--law L] [--start S]``.

>>> import plans
>>> from plans.lecture import animate
>>> page = animate(plans.load(plans.example_path("four-bar")), 4).html   # doctest: +SKIP
"""

from __future__ import annotations

import html as html_module
from functools import cached_property
from pathlib import Path

from .._files import write_atomic
from ..errors import OutputError, PlansError
from ..i18n import check_language, term

__all__ = ["animate", "Animation", "SUFFIXES", "DEFAULT_POSITIONS", "SLIDE_WIDTH_PX", "SCALE_UNITS", "diagram_quantities"]

#: Positions over the cycle when none are asked for.
DEFAULT_POSITIONS = 36
#: What :meth:`Animation.save` writes, by the suffix of the path.
SUFFIXES = (".html", ".htm", ".gif", ".mp4")
#: The unit of each scale factor (one millimetre of the drawing stands for k of it).
SCALE_UNITS = {"k_l": "m/mm", "k_v": "(m/s)/mm", "k_a": "(m/s²)/mm"}
#: Width [px] of the frames of a GIF or an MP4 (a slide's width).
SLIDE_WIDTH_PX = 1600


def _varies(values, valid) -> bool:
    """Whether *values* (real or complex, over a sweep) change where the mechanism assembles."""
    import numpy as np

    v = np.asarray(values)
    v = np.abs(v) if np.iscomplexobj(v) else v.astype(float)
    v = v[np.asarray(valid, dtype=bool) & np.isfinite(v)]
    if v.size < 2:
        return False
    return float(np.ptp(v)) > 1e-9 * max(float(np.max(np.abs(v))), 1e-300)


def diagram_quantities(run) -> list[str]:
    """The cycle diagrams a lecture page shows for *run*: ω and ε of the links, |v| and |a| of the reported
    points, vʳ and |aᵏ| of the prismatic pairs, each only where some of its curves change over the cycle (a
    diagram of constants, ω of a wedge's links, would be empty)."""
    cycle = run.cycle
    scene = run.scene
    valid = cycle.valid
    links = [cycle.links[n] for n in scene.links if not scene.bodies[n].block and n in cycle.links]
    points = [cycle.points[p] for p in scene.report if p in cycle.points]
    pairs = [cycle.sliders[p.name] for p in scene.prismatics if p.name in cycle.sliders]
    candidates = [
        ("omega", [x.omega for x in links]),
        ("epsilon", [x.epsilon for x in links]),
        ("v", [x.v for x in points]),
        ("a", [x.a for x in points]),
        ("v_rel", [x.v_rel for x in pairs]),
        ("coriolis", [x.coriolis for x in pairs]),
    ]
    return [name for name, series in candidates if any(_varies(values, valid) for values in series)]


class Animation:
    """The mechanism and its plans over the cycle, ready to be a page, a GIF or an MP4.

    Parameters
    ----------
    run : plans.positions.PositionsRun
        The positions, solved at one set of scale factors.
    lang : str
        The reader's language.

    Attributes
    ----------
    run : PositionsRun
    lang : str
    """

    def __init__(self, run, *, lang: str = "en"):
        self.run = run
        self.lang = check_language(lang)
        if not any(r.ok for r in run.runs):
            reasons = "; ".join(run.skipped_messages()[:3])
            raise PlansError(f"{run.scene.source}: the mechanism is not solved at any of the {len(run.runs)} positions: {reasons}")

    def __len__(self) -> int:
        return len(self.run.runs)

    @cached_property
    def frames(self):
        """The frames (:class:`plans.drawing.frames.CycleFrames`), drawn on first use."""
        from ..drawing.frames import LECTURE_TEXT_SCALE, CycleFrames

        return CycleFrames(self.run, lang=self.lang, text_scale=LECTURE_TEXT_SCALE)

    def labels(self) -> list[str]:
        """The words of each position: ``"Position 5: φ₂ = 105.0°"`` in the reader's language."""
        from .._text import decimal_comma

        return [decimal_comma(f"{term('position', self.lang)} {r.index}: {r.label}", self.lang) for r in self.run.runs]

    @cached_property
    def html(self) -> str:
        """The lecture page (one self-contained HTML document) as text."""
        from ..drawing.frames import draw_cursor_diagrams, draw_plan_legend, frame_svg_text
        from ..drawing.svg import render_svg
        from .page import lecture_html
        from .values import column_heads, position_values, value_notes, value_rows

        frames = self.frames
        svgs = [frame_svg_text(frames.svg(k), "frame") for k in range(len(frames))]
        quantities = diagram_quantities(self.run)
        # one SVG a diagram: the page sets them two or three a row, as wide as the screen allows
        diagrams, cursors = [], {}
        for quantity in quantities:
            figure, moves = draw_cursor_diagrams(self.run, [quantity], lang=self.lang, columns=1)
            diagrams.append(frame_svg_text(render_svg(figure), f"diagram-{quantity}"))
            cursors.update(moves)
        rows = value_rows(self.run)
        from .._text import decimal_comma

        scales = [("k", key.partition("_")[2], decimal_comma(f"{value:g}", self.lang), SCALE_UNITS[key]) for key, value in self.run.scales.items()]
        subtitle = [self.run.structure.formula, f"{len(self.run.runs)} {term('positions', self.lang)}"]
        if self.run.motion is not None:  # the driver's law over the cycle, in its own words and numbers
            subtitle.append(self.run.motion.law.describe(self.lang, self.run.scene.driver.link))
        return lecture_html(
            title=self.run.scene.title_in(self.lang),
            subtitle=subtitle,
            lang=self.lang,
            frames=svgs,
            labels=self.labels(),
            rows=rows,
            values=position_values(self.run, rows, self.lang),
            heads=column_heads(self.lang),
            diagrams=diagrams,
            cursors=cursors,
            legend=frame_svg_text(render_svg(draw_plan_legend(self.run, lang=self.lang)), "legend"),
            scales=scales,
            notes=value_notes(self.run, rows, self.lang),
        )

    def _pixels(self, width_px: int) -> list:
        labels = self.labels()
        return [self.frames.rgb(k, width_px, title=labels[k]) for k in range(len(self.frames))]

    def gif(self, width_px: int = SLIDE_WIDTH_PX) -> bytes:
        """A looping GIF, one cycle in :data:`plans.lecture.page.SECONDS_PER_CYCLE` seconds."""
        from .page import SECONDS_PER_CYCLE
        from .video import gif_bytes

        return gif_bytes(self._pixels(width_px), SECONDS_PER_CYCLE / len(self))

    def mp4(self, width_px: int = SLIDE_WIDTH_PX, *, path_for_errors: str = "animation.mp4") -> bytes:
        """An H.264 MP4, one cycle in :data:`plans.lecture.page.SECONDS_PER_CYCLE` seconds."""
        from .page import SECONDS_PER_CYCLE
        from .video import mp4_bytes

        try:
            import imageio_ffmpeg  # noqa: F401  (refused before drawing a frame)
        except ImportError:
            from .video import MP4_INSTALL

            raise OutputError(f"{path_for_errors}: {MP4_INSTALL}") from None
        return mp4_bytes(self._pixels(width_px), len(self) / SECONDS_PER_CYCLE, path_for_errors=path_for_errors)

    def save(self, path) -> Path:
        """Write the page (``.html``, ``.htm``), a GIF (``.gif``) or an MP4 (``.mp4``) to *path*, atomically; returns the path."""
        path = Path(path)
        suffix = check_suffix(path)
        if suffix in (".html", ".htm"):
            data = self.html.encode("utf-8")
        elif suffix == ".gif":
            data = self.gif()
        else:
            data = self.mp4(path_for_errors=str(path))
        return write_atomic(path, data)

    def _repr_html_(self) -> str:
        # the same page, in an inline frame: its keys, ids and address are its own, not the notebook's
        return (
            '<iframe title="plans animate" style="width:100%;height:52rem;border:1px solid #ccc" '
            f'srcdoc="{html_module.escape(self.html, quote=True)}"></iframe>'
        )


def check_suffix(path) -> str:
    """The suffix of *path* if :meth:`Animation.save` writes it, else an OutputError naming the path and the choices."""
    suffix = Path(path).suffix.lower()
    if suffix not in SUFFIXES:
        raise OutputError(f"{path}: plans animate writes a page (.html), a GIF (.gif) or an MP4 (.mp4), not {suffix or 'a file without a suffix'}")
    return suffix


__all__ += ["check_suffix"]


def animate(scene, positions=DEFAULT_POSITIONS, *, lang: str = "en", k_l: float | None = None, k_v: float | None = None,
            k_a: float | None = None, precision: float | None = None, law: str | None = None, start: str = "output") -> Animation:
    """The mechanism of *scene* and its plans at *positions* of its cycle, as an :class:`Animation`.

    Parameters
    ----------
    scene : Scene
    positions : int, str or sequence
        A count N (positions equally spaced over the driver's cycle, position 0
        the scene's own) or anything :func:`plans.positions.parse_positions` takes.
    lang : str
        The reader's language (en, sr, ru, bg, sl).
    k_l, k_v, k_a : float, optional
        Scale factors; those not given are the round factors that fit every
        position, as for the sheets of ``plans draw --positions`` (one set for all frames).
    precision : float, optional
        Drafting precision [mm] of the plans' readings (default 0.1 mm, as on the sheets; 0: exact).
    law : str, optional
        The driver's law over the cycle (:func:`plans.motion.driver_law`: ``"constant"``, ``"uniform"``,
        ``"harmonic"``); None: the scene's ``[driver] law``, else the default.
    start : {"output", "scene"}
        Position 0: the output link's extreme position that starts its working stroke, or the scene's own.

    Raises
    ------
    PlansError
        When the mechanism is not solved at any of the positions.
    """
    from ..positions import at_page_precision, run_positions

    check_language(lang)
    scene = at_page_precision(scene, precision)
    run = run_positions(scene, positions, k_l=k_l, k_v=k_v, k_a=k_a, precision=scene.scales.precision, law=law, start=start)
    return Animation(run, lang=lang)
