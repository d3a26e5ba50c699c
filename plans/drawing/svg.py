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
    """The rcParams every drawing is made and rendered under."""
    with matplotlib.rc_context(RC):
        yield


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
