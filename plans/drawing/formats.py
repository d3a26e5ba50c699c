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

__all__ = ["FORMATS", "PNG_DPI", "PDF_RC", "render", "render_png", "render_pdf", "format_of", "save_figure", "save_pages"]

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
        return replace_all({path: render_pdf([fig for _, fig in pages])})
    if len(pages) == 1:
        return replace_all({path: render(pages[0][1], fmt)})
    return replace_all({path.with_name(f"{path.stem}-{name}{path.suffix}"): render(fig, fmt) for name, fig in pages})


PDF_RC = {"pdf.fonttype": 42, "pdf.compression": 6}


def render_pdf(figures, progress=None) -> bytes:
    """The figures as the pages of one PDF (in order), deterministic; *progress* (optional) is called with each page's number."""
    buffer = io.BytesIO()
    import matplotlib
    from matplotlib.backends.backend_pdf import PdfPages

    from .svg import drawing_rc

    with drawing_rc(), matplotlib.rc_context(PDF_RC):
        with PdfPages(buffer, metadata={"CreationDate": None, "ModDate": None, "Creator": "plans", "Producer": "plans (matplotlib)"}) as pdf:
            for number, fig in enumerate(figures, start=1):
                pdf.savefig(fig)
                if progress is not None:
                    progress(number)
    return buffer.getvalue()


def save_figure(fig, path) -> Path:
    """Write one figure to *path*: SVG (true to scale), PDF or PNG by the suffix, atomically."""
    from .._files import replace_all

    path = Path(path)
    return replace_all({path: render(fig, format_of(path))})[0]  # creates the directory
