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


def _math_parse_function():
    """matplotlib's uncached ``MathTextParser._parse_cached``, or None if it is not the one expected."""
    import inspect

    from matplotlib import mathtext

    cached = mathtext.MathTextParser.__dict__.get("_parse_cached")
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


@contextmanager
def _shared_math_parses():
    """Within: every ``MathTextParser`` parses a math string once (see above); nests."""
    global _math_depth
    from matplotlib import mathtext

    original = mathtext.MathTextParser.__dict__.get("_parse_cached") if _math_depth == 0 else None
    plain = _math_parse_function() if _math_depth == 0 else None
    if plain is not None:
        mathtext.MathTextParser._parse_cached = _shared_parse(plain)
    _math_depth += 1
    try:
        yield
    finally:
        _math_depth -= 1
        if plain is not None:
            mathtext.MathTextParser._parse_cached = original


def new_figure(width_mm: float = 100.0, height_mm: float = 100.0) -> Figure:
    """A Figure with an SVG canvas, *width_mm* × *height_mm*."""
    fig = Figure(figsize=(width_mm / 25.4, height_mm / 25.4), dpi=72)
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
    replacement = rb'\1 width="%smm" height="%smm"' % (
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
