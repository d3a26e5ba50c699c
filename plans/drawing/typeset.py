"""Typesetting of the pages' text: plain text, and the small TeX subset plans writes its equations in.

matplotlib's mathtext parser takes tens of milliseconds per long line and
refuses what it does not know (``Double superscript``, an unknown macro),
which made a handout slow and let a title crash it.  Page text is therefore
set here: a line is split into runs (plain text, ``$…$`` math), the math is
read by a small parser that never fails (an unknown command is printed as its
name), laid out with the font's own advance widths, and drawn as plain text
artists — a superscript is a smaller run raised from the baseline.  The
layout of a string is computed once and cached.

What the math subset knows: ``x_{…}``, ``x^{…}`` (both, nested), ``{…}``
groups, Greek letters by name, ``\\mathrm{…}``, ``\\dot``/``\\ddot``,
``\\cdot``, ``\\times``, ``\\Rightarrow``, ``\\circ`` (``^\\circ`` is the
degree sign, attached), spaces ``\\,``, ``\\ ``, ``\\quad``, ``\\qquad``.
Latin letters are set italic, everything else upright; ``-`` is a true minus.

Script size: 0.75 of the text it belongs to, never below 6 pt (or the text's
own size when that is smaller), so exponents stay legible in print.
"""

from __future__ import annotations

import functools
import itertools
import math
import re
import unicodedata
import weakref
from contextlib import contextmanager

from matplotlib.font_manager import FontProperties, findfont, get_font
from matplotlib.ft2font import LoadFlags
from matplotlib import colors as mcolors
from matplotlib.artist import Artist, allow_rasterization
from matplotlib.transforms import Bbox

from ._canvas import Sketch, text_size
from .style import FONT_FAMILY, INK, MM_PER_PT

__all__ = ["fast_pdf_text", "measure", "draw_text", "TypesetText", "text_width", "runs", "plain_runs", "SCRIPT_SCALE", "MIN_SCRIPT_PT", "MATH_LINE"]

SCRIPT_SCALE = 0.75
MIN_SCRIPT_PT = 6.0
#: a line with math is this much taller than a line of plain text
MATH_LINE = 1.22
SUP_RISE = 0.40  # × the size of the text carrying the script
SUB_DROP = 0.20
#: Space [× the base's size] between a base and its subscript for letters whose foot reaches out to the right
#: (DejaVu's μ: a subscript set at its advance touches the foot, and μₜ reads as "ɥ").
SUB_KERN = {"μ": 0.10, "µ": 0.10}

_SYMBOLS = {
    "cdot": "·", "times": "×", "Rightarrow": "⇒", "rightarrow": "→", "to": "→", "pm": "±", "mp": "∓",
    "perp": "⊥", "parallel": "∥", "angle": "∠", "infty": "∞", "approx": "≈", "leq": "≤", "geq": "≥",
    "le": "≤", "ge": "≥", "neq": "≠", "circ": "°", "degree": "°", "prime": "′", "minus": "−",
    "varphi": "φ", "varepsilon": "ε", "vartheta": "ϑ", "phi": "ϕ", "epsilon": "ϵ", "ldots": "…", "dots": "…",
    "sqrt": "√", "sum": "Σ", "partial": "∂", "nabla": "∇", "in": "∈", "cdots": "⋯", "lbrace": "{", "rbrace": "}",
}
#: spaces as characters of the font (so that a run of text is not cut at a space)
_SPACES = {",": "\u2009", ":": "\u2005", ";": "\u2005", " ": " ", "!": "", "quad": "\u2003", "qquad": "\u2003\u2003", "enspace": "\u2002"}
#: letters set upright in math: the constants e and i (ISO 80000-2); other Latin letters are variables, italic
_UPRIGHT_LETTERS = {"e", "i"}
_ACCENTS = {"dot": "\u0307", "ddot": "\u0308", "vec": "\u20d7", "bar": "\u0304", "hat": "\u0302", "tilde": "\u0303"}
_UPRIGHT = {"mathrm", "text", "textrm", "mathsf", "operatorname", "mathbf", "mathit"}
_IGNORED = {"left", "right", "displaystyle", "limits", "big", "Big"}
_BINARY = {"+": " + ", "-": " − ", "−": " − ", "=": " = ", "·": "·", "×": " × ", "⇒": " ⇒ ", "→": " → ", "≈": " ≈ ", "±": " ± "}


_FONT_SCALE = 100.0  # pt: widths are measured at this size and scaled


@functools.lru_cache(maxsize=8)
def _font_file(weight: str) -> str:
    return findfont(FontProperties(family=FONT_FAMILY, weight=weight))


@functools.lru_cache(maxsize=65536)
def _advance(text: str, weight: str) -> float:
    """Advance width [pt] of *text* at :data:`_FONT_SCALE` pt (the oblique face has the same advances)."""
    font = get_font(_font_file(weight))
    font.set_size(_FONT_SCALE, 72)
    font.set_text(text, 0.0, flags=LoadFlags.NO_HINTING)
    return font.get_width_height()[0] / 64.0


def text_width(text: str, size: float, weight: str = "normal") -> float:
    """Width [mm] of plain *text* at *size* [pt] (what :func:`plans.drawing._canvas.text_size` measures, faster)."""
    return _advance(text, weight) * size / _FONT_SCALE * MM_PER_PT


def _greek(name: str) -> str | None:
    try:
        return unicodedata.lookup(("GREEK CAPITAL LETTER " if name[0].isupper() else "GREEK SMALL LETTER ") + name.upper())
    except KeyError:
        return None


# --- parsing -----------------------------------------------------------------------------

# nodes: ("char", text, italic) | ("space", characters) | ("group", [nodes], upright) | ("script", base, sup, sub)


def _parse(s: str) -> list:
    pos = 0

    def atom(upright: bool):
        nonlocal pos
        if pos >= len(s):
            return None
        ch = s[pos]
        if ch == "{":
            pos += 1
            nodes = seq(upright, "}")
            return ("group", nodes, upright)
        if ch == "\\":
            pos += 1
            if pos >= len(s):
                return ("char", "\\", False)
            m = re.match(r"[A-Za-z]+", s[pos:])
            if not m:
                c = s[pos]
                pos += 1
                if c in _SPACES:
                    return ("space", _SPACES[c])
                return ("char", c, False)
            name = m.group(0)
            pos += len(name)
            if name in _SPACES:
                return ("space", _SPACES[name])
            if name in _IGNORED:
                return ("space", "")
            if name in _UPRIGHT:
                inner = atom(True)
                return ("group", [inner] if inner else [], True)
            if name in _ACCENTS:
                inner = atom(upright)
                return ("group", _accent(inner, _ACCENTS[name]), upright)
            if name in _SYMBOLS:
                return ("char", _SYMBOLS[name], False)
            greek = _greek(name)
            if greek:
                return ("char", greek, False)
            return ("char", name, False)  # unknown: its name, never an error
        pos += 1
        if ch == " ":
            return ("space", "")
        return ("char", ch, ch.isascii() and ch.isalpha() and ch not in _UPRIGHT_LETTERS and not upright)

    def seq(upright: bool, close: str | None) -> list:
        nonlocal pos
        nodes: list = []
        while pos < len(s):
            ch = s[pos]
            if close and ch == close:
                pos += 1
                return nodes
            if ch in "^_":
                pos += 1
                script = atom(upright)
                script = [script] if script else []
                base = nodes.pop() if nodes and nodes[-1][0] != "space" else ("group", [], upright)
                if base[0] == "script":
                    _, b, sup, sub = base
                else:
                    b, sup, sub = [base], None, None
                if ch == "^":
                    sup = (sup or []) + script  # a second superscript is set beside the first, never an error
                else:
                    sub = (sub or []) + script
                nodes.append(("script", b, sup, sub))
                continue
            node = atom(upright)
            if node is not None:
                nodes.append(node)
        return nodes

    return seq(False, None)


def _accent(node, mark: str) -> list:
    if node is None:
        return [("char", mark, False)]
    if node[0] == "char":
        return [("char", node[1] + mark, node[2])]
    if node[0] == "group" and node[1] and node[1][-1][0] == "char":
        last = node[1][-1]
        return node[1][:-1] + [("char", last[1] + mark, last[2])]
    return [node]


# --- layout ------------------------------------------------------------------------------


def _script_size(size: float) -> float:
    return max(size * SCRIPT_SCALE, min(MIN_SCRIPT_PT, size))


class _Layout:
    def __init__(self, weight: str):
        self.weight = weight
        self.out: list[list] = []  # [text, x_mm, rise_mm, size_pt, italic]
        self.x = 0.0
        self.last: str | None = None  # "op", "open", "atom" or None: whether a minus is binary

    def emit(self, text: str, rise: float, size: float, italic: bool) -> None:
        if not text:
            return
        width = text_width(text, size, self.weight)
        prev = self.out[-1] if self.out else None
        if prev and prev[2] == rise and prev[3] == size and prev[4] == italic and abs(prev[1] + prev[5] - self.x) < 1e-9:
            prev[0] += text
            prev[5] += width
        else:
            self.out.append([text, self.x, rise, size, italic, width])
        self.x = self.out[-1][1] + self.out[-1][5]

    def nodes(self, nodes, rise: float, size: float, top: bool) -> None:
        for k, node in enumerate(nodes):
            kind = node[0]
            if kind == "space":
                self.emit(node[1], rise, size, False)
            elif kind == "char":
                ch = node[1]
                if ch in _BINARY and top:
                    unary = ch in "-−" and self.last in (None, "op", "open")
                    self.emit("−" if unary else _BINARY[ch], rise, size, False)
                    self.last = "op"
                else:
                    self.emit("−" if ch == "-" else ch, rise, size, node[2])
                    self.last = "open" if ch in "([{" else "atom"
            elif kind == "group":
                self.nodes(node[1], rise, size, top)
            else:
                _, base, sup, sub = node
                self.nodes(base, rise, size, top)
                if sup and len(sup) == 1 and sup[0][0] == "char" and sup[0][1] == "°":
                    self.emit("°", rise, size, False)  # the degree sign, attached at full size
                    sup = None
                small = _script_size(size)
                start = self.x
                ends = []
                if sup:
                    self.x = start
                    self.nodes(sup, rise + SUP_RISE * size * MM_PER_PT, small, False)
                    ends.append(self.x)
                if sub:
                    self.x = start + SUB_KERN.get(_last_char(base), 0.0) * size * MM_PER_PT
                    self.nodes(sub, rise - SUB_DROP * size * MM_PER_PT, small, False)
                    ends.append(self.x)
                self.x = max(ends, default=start)
                self.last = "atom"


def _last_char(nodes) -> str | None:
    """The last character of a base (through groups), or None."""
    while nodes:
        node = nodes[-1]
        if node[0] == "char":
            return node[1]
        if node[0] != "group":
            return None
        nodes = node[1]
    return None


_DOLLAR = re.compile(r"(?<!\\)\$")


def _pieces(text: str) -> list[tuple[str, bool]]:
    """*text* cut at unescaped ``$``: (piece, is_math); an unpaired ``$`` is a literal dollar."""
    parts = _DOLLAR.split(text)
    if len(parts) % 2 == 0:  # odd number of $: the last one is a literal
        parts = parts[:-2] + [parts[-2] + "$" + parts[-1]]
    return [(p, k % 2 == 1) for k, p in enumerate(parts) if p]


@functools.lru_cache(maxsize=8192)
def runs(text: str, size: float, weight: str = "normal") -> tuple[tuple[tuple[str, float, float, float, bool], ...], float, bool]:
    """The runs ``(text, x [mm], rise [mm], size [pt], italic)`` of *text*, its width [mm] and whether it had math."""
    layout = _Layout(weight)
    has_math = False
    for piece, is_math in _pieces(text):
        if is_math:
            has_math = True
            layout.last = None
            layout.nodes(_parse(piece), 0.0, size, True)
        else:
            layout.emit(piece.replace(r"\$", "$"), 0.0, size, False)
            layout.last = None
    return tuple((t, x, r, s, i) for t, x, r, s, i, _ in layout.out), layout.x, has_math


def plain_runs(text: str) -> str:
    """The characters *text* shows, in order (math laid out): for tests and searching."""
    return "".join(r[0] for r in runs(text, 10.0)[0])


def measure(text: str, size: float, weight: str = "normal") -> tuple[float, float]:
    """Width and height [mm] of *text* set at *size* (``$…$`` parts typeset)."""
    _, width, has_math = runs(text, size, weight)
    height = text_size("lp", size)[1] * (MATH_LINE if has_math else 1.0)
    return width, height


class TypesetText(Artist):
    """One line of typeset text: its runs drawn by the renderer, one ``draw_text`` call each.

    A matplotlib ``Text`` per run cost most of a handout's time (each one
    builds font properties and lays itself out again at every draw); the runs
    here are laid out once, by :func:`runs`, and drawn at their places.
    ``get_text()`` gives the characters shown, ``get_window_extent()`` the
    box matplotlib's text layout gives the runs.
    """

    def __init__(self, x: float, baseline: float, items, size: float, weight: str, color, transform):
        super().__init__()
        self._x = x
        self._baseline = baseline
        self._items = items
        self._size = size
        self._weight = weight
        self._color = mcolors.to_rgba(color)
        self.set_transform(transform)
        self.set_zorder(6.0)
        self.set_clip_on(False)

    def get_text(self) -> str:
        return "".join(t for t, *_ in self._items)

    def get_position(self) -> tuple[float, float]:
        """Where the line starts: x and its baseline [data units], as :meth:`matplotlib.text.Text.get_position`."""
        return self._x, self._baseline

    def get_fontsize(self) -> float:
        return self._size

    def get_color(self):
        return self._color

    def runs(self):
        """``(text, x, baseline [data units], size [pt], font properties)`` of each run."""
        return [(t, self._x + x, self._baseline + rise, s, _font_properties(s, self._weight, italic)) for t, x, rise, s, italic in self._items]

    def _points(self, renderer):
        placed = self.runs()
        xy = self.get_transform().transform([(x, y) for _, x, y, _, _ in placed]) if placed else []
        return placed, xy

    def get_window_extent(self, renderer=None):
        """The union of the runs' boxes [display units], measured by matplotlib's text layout."""
        if renderer is None:
            renderer = self.figure._get_renderer()
        placed, xy = self._points(renderer)
        boxes = []
        for (t, _, _, _, prop), (x, y) in zip(placed, xy):
            w, h, d = renderer.get_text_width_height_descent(t, prop, ismath=False)
            boxes.append(Bbox.from_extents(x, y - d, x + w, y - d + h))
        return Bbox.union(boxes) if boxes else Bbox.from_bounds(0, 0, 0, 0)

    @allow_rasterization
    def draw(self, renderer):
        if not self.get_visible() or not self._items:
            return
        renderer.open_group("text", self.get_gid())
        placed, xy = self._points(renderer)
        canvas_h = renderer.get_canvas_width_height()[1]
        flip = renderer.flipy()
        gc = renderer.new_gc()
        gc.set_foreground(self._color, isRGBA=True)
        gc.set_alpha(self.get_alpha())
        gc.set_antialiased(True)
        self._set_gc_clip(gc)
        points = [(t, prop, x, canvas_h - y if flip else y) for (t, _, _, _, prop), (x, y) in zip(placed, xy)]
        pdf = _pdf_renderer(renderer)
        if pdf is not None:
            _draw_pdf_line(pdf, gc, points)
        else:
            for t, prop, x, y in points:
                renderer.draw_text(gc, x, y, t, prop, 0.0, ismath=False, mtext=None)
        gc.restore()
        renderer.close_group("text")
        self.stale = False


@functools.lru_cache(maxsize=256)
def _font_properties(size: float, weight: str, italic: bool) -> FontProperties:
    return FontProperties(family=FONT_FAMILY, size=size, weight=weight, style="italic" if italic else "normal")


def draw_text(sketch: Sketch, at: complex, text: str, *, size: float, weight: str = "normal", ha: str = "left", gid: str | None = None, color=None) -> None:
    """*text* with its box's left (or right, or centre) edge and vertical centre at *at* [mm].

    The line is one :class:`TypesetText` artist on the figure, placed in the
    axes' millimetres (an axes would give it a clip path); nothing reaches
    matplotlib's math parser (dollar signs are drawn as dollar signs).
    """
    items, width, _ = runs(text, size, weight)
    x0 = {"left": at.real, "right": at.real - width, "center": at.real - width / 2}[ha]
    line_h = text_size("lp", size)[1]
    baseline = at.imag - 0.28 * line_h
    artist = TypesetText(x0, baseline, items, size, weight, color or INK, sketch.ax.transData)
    if gid is not None:
        artist.set_gid(sketch.gid(gid))
    sketch.ax.figure.add_artist(artist)
    sketch.artists.append(artist)


# --- PDF: a line in one text object ----------------------------------------------------------
#
# matplotlib's PDF ``draw_text`` lays every string out again (libraqm) and
# wraps it in its own graphics state and text object; a check page has some
# 500 runs.  For TrueType (Type 42) output the runs of a line are written
# here into one text object, with each run's glyph layout computed once per
# (string, font, size): the same operators draw_text writes for each run
# (select font, move, show glyphs with kerning), so the page looks the same.
# This leans on the PDF backend's glyph tracker (for font subsetting); when
# that is not there (another matplotlib), every run goes through draw_text.


def _pdf_renderer(renderer):
    """The PDF renderer behind *renderer* when runs can be written directly, else None."""
    import matplotlib

    vector = getattr(renderer, "_vector_renderer", renderer)
    if getattr(renderer, "_renderer", vector) is not vector:  # rasterizing
        return None
    if type(vector).__name__ != "RendererPdf" or matplotlib.rcParams["pdf.fonttype"] != 42 or matplotlib.rcParams["pdf.use14corefonts"]:
        return None
    from matplotlib.backends import backend_pdf

    if not all(hasattr(backend_pdf, name) for name in ("_fill", "pdfRepr", "Op")):
        return None
    file = getattr(vector, "file", None)
    if not hasattr(file, "_character_tracker") or not hasattr(vector, "_encode_glyphs") or not hasattr(vector, "_get_font_ttf"):
        return None
    return vector


_PDF_LAYOUTS: dict = {}


def _pdf_layout(renderer, text: str, prop) -> tuple:
    """(font, char, glyph, x, y, kern) of each glyph of *text*, as the PDF backend lays it out."""
    key = (text, prop)
    items = _PDF_LAYOUTS.get(key)
    if items is None:
        font = renderer._get_font_ttf(prop)
        if hasattr(font, "_layout"):
            # what matplotlib's _text_helpers.layout gives, without loading each glyph's outline
            # (the PDF needs only the glyph indices and places)
            placed = font._layout(text, LoadFlags.NO_HINTING)
        else:
            from matplotlib import _text_helpers

            placed = _text_helpers.layout(text, font)
        items = tuple((i.ft_object, i.char, i.glyph_index, i.x, i.y, i.prev_kern) for i in placed)
        _PDF_LAYOUTS[key] = items
    return items


#: per PDF file (weakly held): (text, font properties) -> the bytes that draw that run after its
#: text matrix; its glyphs are tracked for subsetting the first time the run is made for that file
_PDF_RUNS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def _pdf_run(renderer, text: str, prop) -> bytes:
    """The operators that draw *text* in *prop* from the current text matrix, as bytes (made once per file)."""
    file = renderer.file
    cache = _PDF_RUNS.get(file)
    if cache is None:
        cache = _PDF_RUNS[file] = {}
    key = (text, prop)
    data = cache.get(key)
    if data is not None:
        return data

    from matplotlib.backends.backend_pdf import Op, _fill, pdfRepr
    from matplotlib.font_manager import FontPath

    tracker = file._character_tracker
    size = prop.get_size_in_points()
    out: list[bytes] = []

    def output(*items) -> None:  # what PdfFile.output writes
        out.append(_fill([pdfRepr(x) for x in items]) + b"\n")

    def flush(chunk: list) -> None:
        if chunk:
            output(
                [(-1000 * next(group) / size) if kind is float else renderer._encode_glyphs(group, 42) for kind, group in itertools.groupby(chunk, type)],
                Op.showkern,
            )
            chunk.clear()

    chunk: list = []
    previous = None
    start = 0.0
    for font, char, glyph, gx, gy, kern in _pdf_layout(renderer, text, prop):
        subset, code = tracker.track_glyph(font, char, glyph)
        if (font, subset) != previous:
            flush(chunk)
            output(file.fontName(FontPath(font.fname, font.face_index), subset), size, Op.selectfont)
            output(gx - start, 0, Op.textpos)
            previous, start = (font, subset), gx
        if gy:
            flush(chunk)
            output(gy, Op.textrise)
        if kern:
            chunk.append(kern)
        chunk.append(code)
        if gy:
            flush(chunk)
            output(0, Op.textrise)
    flush(chunk)
    data = cache[key] = b"".join(out)
    return data


def _draw_pdf_line(renderer, gc, points) -> None:
    """The runs of a line in one text object: ``BT``, per run its text matrix and its operators, ``ET``.

    Byte for byte what writing each operator with ``PdfFile.output`` gives; a
    run's operators are made once per file (:func:`_pdf_run`).
    """
    from matplotlib.backends.backend_pdf import pdfRepr

    renderer.check_gc(gc, gc._rgb)
    parts = [b"BT\n"]
    for text, prop, x, y in points:
        parts.append(b"1 0 0 1 %s %s Tm\n" % (pdfRepr(x), pdfRepr(y)))
        parts.append(_pdf_run(renderer, text, prop))
    parts.append(b"ET\n")
    renderer.file.write(b"".join(parts))


# --- PDF: matplotlib's own text the same way -------------------------------------------------
#
# Drawing labels, captions and the diagrams' tick labels are matplotlib ``Text``; the PDF
# backend lays each string out again at every draw.  While :func:`fast_pdf_text` is on, a
# plain horizontal string is written from the same cached run as a typeset line, wrapped
# in exactly what ``RendererPdf.draw_text`` writes around it (save state, move, text
# object, restore); anything else (math, rotated text, links, font features) goes to
# matplotlib.


def _draw_text_from_runs(original):
    def draw_text(self, gc, x, y, s, prop, angle, ismath=False, mtext=None):
        plain = not ismath and not angle and isinstance(s, str) and gc.get_url() is None
        if plain and mtext is not None:
            plain = not (getattr(mtext, "get_fontfeatures", lambda: None)() or getattr(mtext, "get_language", lambda: None)())
        if not plain or _pdf_renderer(self) is not self:
            return original(self, gc, x, y, s, prop, angle, ismath=ismath, mtext=mtext)
        from matplotlib.backends.backend_pdf import _fill, pdfRepr

        self.check_gc(gc, gc._rgb)
        a = math.radians(angle)
        place = _fill([pdfRepr(v) for v in (math.cos(a), math.sin(a), -math.sin(a), math.cos(a), x, y)] + [b"cm"])
        self.file.write(b"q\n" + place + b"\nBT\n" + _pdf_run(self, s, prop) + b"ET\nQ\n")

    draw_text.__wrapped__ = original
    return draw_text


@contextmanager
def fast_pdf_text():
    """Within: the PDF backend draws plain horizontal ``Text`` from cached runs (same bytes); nests."""
    try:
        from matplotlib.backends.backend_pdf import RendererPdf
    except ImportError:  # pragma: no cover
        yield
        return
    original = RendererPdf.__dict__.get("draw_text")
    if original is None or hasattr(original, "__wrapped__"):
        yield
        return
    RendererPdf.draw_text = _draw_text_from_runs(original)
    try:
        yield
    finally:
        RendererPdf.draw_text = original
