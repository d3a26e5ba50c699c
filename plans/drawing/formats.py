"""One figure to bytes in the format a file name asks for: SVG, PDF or PNG.

``.save(path)`` everywhere in plans means: write one file, *path*, in the
format its suffix names (:data:`FORMATS`).  SVG is true to scale (sized in
mm); PDF embeds its fonts; PNG is rendered at :data:`PNG_DPI` dots per inch,
so that one millimetre of drawing is PNG_DPI / 25.4 pixels.  All three are
deterministic: the same figure gives the same bytes.
"""

from __future__ import annotations

import io
from pathlib import Path

__all__ = ["FORMATS", "PNG_DPI", "render", "render_png", "format_of", "save_pages"]

#: The output formats, as file suffixes without the dot.
FORMATS = ("svg", "pdf", "png")
#: Resolution of PNG output [dots per inch]: 150 dpi, about 5.9 pixels per mm of drawing.
PNG_DPI = 150


def format_of(path) -> str:
    """``"svg"``, ``"pdf"`` or ``"png"`` from *path*'s suffix; a ValueError for any other."""
    path = Path(path)
    suffix = path.suffix.lower().lstrip(".")
    if suffix not in FORMATS:
        raise ValueError(
            f"{path}: write a drawing as .svg, .pdf or .png, not {path.suffix or 'without a suffix'} "
            "(.save(path) writes one file, in the format its suffix names)"
        )
    return suffix


def render_png(fig, dpi: int = PNG_DPI) -> bytes:
    """The figure as PNG bytes at *dpi*, deterministic (no date, a fixed Software tag)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from .svg import drawing_rc

    buffer = io.BytesIO()
    with drawing_rc():
        canvas = FigureCanvasAgg(fig)
        canvas.figure.savefig(buffer, format="png", dpi=dpi, metadata={"Software": "plans"})
    return buffer.getvalue()


def render(fig, fmt: str) -> bytes:
    """The figure as bytes of *fmt* (one of :data:`FORMATS`)."""
    if fmt == "svg":
        from .svg import render_svg

        return render_svg(fig)
    if fmt == "pdf":
        from .sheets import render_pdf

        return render_pdf([fig])
    if fmt == "png":
        return render_png(fig)
    raise ValueError(f"no output format {fmt!r}; choose one of {', '.join(FORMATS)}")


def save_pages(pages, path) -> list[Path]:
    """Write named figures ``[(name, fig), …]`` to the one *path* its suffix names, atomically.

    ``.pdf``: one file, a page each.  ``.svg`` or ``.png`` with one figure: that
    file; with several: ``STEM-NAME.svg`` (``diagrams-links.png``, …) beside it,
    all or none.  Returns the files written.
    """
    from .._files import replace_all

    path = Path(path)
    fmt = format_of(path)
    pages = list(pages)
    if fmt == "pdf":
        from .sheets import render_pdf

        return replace_all({path: render_pdf([fig for _, fig in pages])})
    if len(pages) == 1:
        return replace_all({path: render(pages[0][1], fmt)})
    return replace_all({path.with_name(f"{path.stem}-{name}{path.suffix}"): render(fig, fmt) for name, fig in pages})
