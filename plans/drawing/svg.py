"""Deterministic SVG at a physical size.

* :func:`new_figure` makes a matplotlib ``Figure`` (no pyplot, no global
  state) with an SVG canvas, sized in millimetres.
* :func:`render_svg` renders it under :data:`plans.drawing.style.RC` (fixed
  hash salt, no date, fonts as text) and rewrites the root ``width`` and
  ``height`` in millimetres, so a viewer or printer at 100 % reproduces the
  scale factors.  The same figure always gives the same bytes.

The files are written with :func:`plans._files.replace_all`: either all of
them are replaced or none is.
"""

from __future__ import annotations

import io
import re
from contextlib import contextmanager
import matplotlib
from matplotlib.backends.backend_svg import FigureCanvasSVG
from matplotlib.figure import Figure

from .style import RC

__all__ = ["new_figure", "render_svg", "drawing_rc", "svg_size_mm"]

_ROOT_SIZE = re.compile(rb'(<svg\b[^>]*?)\swidth="([0-9.eE+-]+)pt"\s+height="([0-9.eE+-]+)pt"')
_MM_SIZE = re.compile(r'<svg\b[^>]*?\swidth="([0-9.]+)mm"\s+height="([0-9.]+)mm"')


@contextmanager
def drawing_rc():
    """The rcParams every drawing is made and rendered under (and math parses shared, see below)."""
    with matplotlib.rc_context(RC), _shared_math_parses():
        yield


# --- one parse of each math string ---------------------------------------------------------
#
# matplotlib caches a math string's parse per parser (and only the last 50): a drawing
# measures its math labels with one parser and every figure's renderer has its own, so
# each string was parsed again for every figure — a fifth of ``plans draw --positions``.
# While drawing, the parses are shared among parsers of the same output type: the parse
# depends only on the string, the dpi, the font properties, the glyph flags and the
# mathtext rcParams, which are all in the key.  Without the expected matplotlib hook the
# parsers are left as they are.

_MATH_PARSES: dict = {}
_MATH_PARSES_MAX = 4096
_math_depth = 0
_PARSE_ARGS = ["self", "s", "dpi", "prop", "antialiased", "load_glyph_flags"]


_CHECKED: dict = {}


def _math_parse_function():
    """matplotlib's uncached ``MathTextParser._parse_cached``, or None if it is not the one expected."""
    from matplotlib import mathtext

    cached = mathtext.MathTextParser.__dict__.get("_parse_cached")
    if id(cached) not in _CHECKED:
        _CHECKED.clear()
        _CHECKED[id(cached)] = (cached, _checked_parse_function(cached))
    return _CHECKED[id(cached)][1]


def _checked_parse_function(cached):
    import inspect

    plain = getattr(cached, "__wrapped__", None)
    if plain is None or not hasattr(cached, "cache_clear"):
        return None
    try:
        if list(inspect.signature(plain).parameters) != _PARSE_ARGS:
            return None
    except (TypeError, ValueError):
        return None
    return plain


def _shared_parse(plain):
    keys = sorted(k for k in matplotlib.rcParams if k.startswith("mathtext."))

    def parse(self, s, dpi, prop, antialiased, load_glyph_flags):
        rc = tuple(repr(matplotlib.rcParams[k]) for k in keys)
        key = (self._output_type, s, dpi, prop, antialiased, load_glyph_flags, rc)
        found = _MATH_PARSES.get(key)
        if found is None:
            if len(_MATH_PARSES) >= _MATH_PARSES_MAX:
                _MATH_PARSES.clear()
            found = _MATH_PARSES[key] = plain(self, s, dpi, prop, antialiased, load_glyph_flags)
        return found

    return parse


# Likewise the size of a plain string: matplotlib measures it once per renderer, and every
# page has its own renderer.  While drawing, the vector renderers' measurements of plain
# (not math) text are kept: they depend only on the string, the font properties and, for
# PDF/PS, whether the core fonts are used (in the key).

_TEXT_SIZES: dict = {}
_TEXT_SIZES_MAX = 65536


def _shared_size(method, tag: str):
    def size(self, s, prop, ismath):
        if ismath is not False or not isinstance(s, str):
            return method(self, s, prop, ismath)
        afm = getattr(self, "_use_afm_rc_name", None)
        key = (tag, type(self), s, prop.copy(), afm and matplotlib.rcParams[afm])
        found = _TEXT_SIZES.get(key)
        if found is None:
            if len(_TEXT_SIZES) >= _TEXT_SIZES_MAX:
                _TEXT_SIZES.clear()
            found = _TEXT_SIZES[key] = method(self, s, prop, ismath)
        return found

    size.__wrapped__ = method
    return size


def _size_methods():
    """(class, name) of the text measurements shared while drawing (those found)."""
    import sys

    from matplotlib.textpath import TextToPath

    # the PDF/PS renderers' base only if something has loaded it (an SVG drawing need not)
    pdf_ps = sys.modules.get("matplotlib.backends._backend_pdf_ps")
    found = []
    for cls in (TextToPath, getattr(pdf_ps, "RendererPDFPSBase", None)):
        method = getattr(cls, "__dict__", {}).get("get_text_width_height_descent")
        if callable(method):
            found.append((cls, method))
    return found


@contextmanager
def _shared_math_parses():
    """Within: every ``MathTextParser`` parses a math string once, and plain text is measured once (see above); nests."""
    global _math_depth
    from matplotlib import mathtext

    original = mathtext.MathTextParser.__dict__.get("_parse_cached") if _math_depth == 0 else None
    plain = _math_parse_function() if _math_depth == 0 else None
    sizes = _size_methods() if _math_depth == 0 else []
    if plain is not None:
        mathtext.MathTextParser._parse_cached = _shared_parse(plain)
    for cls, method in sizes:
        cls.get_text_width_height_descent = _shared_size(method, cls.__name__)
    _math_depth += 1
    try:
        yield
    finally:
        _math_depth -= 1
        if plain is not None:
            mathtext.MathTextParser._parse_cached = original
        for cls, method in sizes:
            cls.get_text_width_height_descent = method


# --- axes whose ticks are made when they are needed ------------------------------------------
#
# Every drawing is an Axes with its axis switched off, and making an Axes made
# four ticks (each two lines, two texts and a grid line) only to give them
# the clip path and grid setting: a tenth of a handout's time.  The axes of
# plans' figures make their ticks when something asks for them, with the same
# clip path and parameters they would have had.


class _LazyTicks:
    """An Axis (mixin) whose tick lists stay unmade by ``set_clip_path`` and ``set_tick_params``."""

    _pending_clip = None

    def _unmade(self) -> list[str]:
        return [name for name in ("majorTicks", "minorTicks") if name not in vars(self)]

    def _without_making_ticks(self, method, *args, **kwargs):
        unmade = self._unmade()
        placeholders = {name: [] for name in unmade}
        for name, empty in placeholders.items():
            setattr(self, name, empty)  # shadows matplotlib's lazy list while *method* runs
        try:
            return method(*args, **kwargs)
        finally:
            for name, empty in placeholders.items():
                if vars(self).get(name) is empty and not empty:
                    delattr(self, name)

    def set_clip_path(self, path, transform=None):
        self._pending_clip = (path, transform)
        self._without_making_ticks(super().set_clip_path, path, transform)

    def set_tick_params(self, which="major", reset=False, **kwargs):
        # a tick made later is made with these parameters (matplotlib keeps them for that)
        self._without_making_ticks(super().set_tick_params, which, reset, **kwargs)

    def _get_tick(self, major):
        # the first tick of a list (matplotlib's lazy list holds [] while it makes it): clipped as
        # set_clip_path would have clipped it; later ones copy the first
        first = vars(self).get("majorTicks" if major else "minorTicks") == []
        with matplotlib.rc_context():  # made under the rcParams of the axes' making, as it would have been
            dict.update(matplotlib.rcParams, self._made_under)
            tick = super()._get_tick(major)
        if first and self._pending_clip is not None:
            tick.set_clip_path(*self._pending_clip)
        return tick


def _axes_class():
    from matplotlib.axes import Axes
    from matplotlib.axis import XAxis, YAxis

    class LazyXAxis(_LazyTicks, XAxis):
        pass

    class LazyYAxis(_LazyTicks, YAxis):
        pass

    class PaperAxes(Axes):
        """matplotlib's Axes, its axes' ticks made only when needed."""

        def _init_axis(self):
            super()._init_axis()
            if type(self.xaxis) is XAxis and type(self.yaxis) is YAxis and not ({"majorTicks", "minorTicks"} & (vars(self.xaxis).keys() | vars(self.yaxis).keys())):
                made_under = dict.copy(matplotlib.rcParams)  # (the values, already checked)
                for axis, lazy in ((self.xaxis, LazyXAxis), (self.yaxis, LazyYAxis)):
                    axis.__class__ = lazy
                    axis._made_under = made_under

    return PaperAxes


_PAPER_AXES = None


class _Paper(Figure):
    """A Figure whose ``add_axes`` makes :func:`_axes_class` axes unless told another class or projection."""

    def add_axes(self, *args, **kwargs):
        global _PAPER_AXES
        if not {"axes_class", "projection", "polar"} & kwargs.keys() and args and not hasattr(args[0], "get_figure"):
            if _PAPER_AXES is None:
                _PAPER_AXES = _axes_class()
            kwargs["axes_class"] = _PAPER_AXES
        return super().add_axes(*args, **kwargs)


def new_figure(width_mm: float = 100.0, height_mm: float = 100.0) -> Figure:
    """A Figure with an SVG canvas, *width_mm* × *height_mm*."""
    fig = _Paper(figsize=(width_mm / 25.4, height_mm / 25.4), dpi=72)
    FigureCanvasSVG(fig)
    fig.patch.set_visible(False)
    return fig


def _mm(value: float) -> str:
    return f"{value:.4f}".rstrip("0").rstrip(".")


def render_svg(fig: Figure) -> bytes:
    """The figure as SVG bytes, sized in mm; deterministic for the same figure."""
    buffer = io.BytesIO()
    with drawing_rc():
        FigureCanvasSVG(fig).print_svg(buffer, metadata={"Date": None})
    data = buffer.getvalue()
    width_in, height_in = fig.get_size_inches()
    # xml:space="preserve": the spaces at the ends of a typeset run (" = " after v_A, " [m/s]") are drawn, not
    # collapsed (an SVG viewer strips them by default and the runs, placed one by one, close up: "v_A=  ω ₂")
    replacement = rb'\1 xml:space="preserve" width="%smm" height="%smm"' % (
        _mm(width_in * 25.4).encode(), _mm(height_in * 25.4).encode()
    )
    data, count = _ROOT_SIZE.subn(replacement, data, count=1)
    if count != 1:
        raise RuntimeError("matplotlib wrote an SVG root without width/height in pt")
    return data


def svg_size_mm(data: bytes | str) -> tuple[float, float]:
    """The (width, height) [mm] an SVG written by :func:`render_svg` declares."""
    text = data.decode("utf-8") if isinstance(data, bytes) else data
    match = _MM_SIZE.search(text)
    if not match:
        raise ValueError("no width/height in mm on the SVG root")
    return float(match.group(1)), float(match.group(2))
