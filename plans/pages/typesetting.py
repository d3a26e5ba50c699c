"""Typst as the typesetter: text, math and drawings into Typst source, and the source into PDF, SVG or PNG.

Every user text goes into the source as a Typst *string literal*
(:func:`string`, :func:`text`), so it is printed as written and never read as
markup or math.  The program's own formulas (written in the small mathtext
dialect of :mod:`plans.loops` and :mod:`plans.report`: ``$v_{A4C}$``,
``\\omega_{2}``, ``\\mathrm{m/s}``) are translated to Typst math by
:func:`math`; :func:`mixed` does both for a line that holds text and ``$…$``
parts.  Drawings are SVG blocks of known size (:class:`plans.drawing.svgblocks.SvgBlock`)
handed to the compiler as inputs and placed at their physical width
(:func:`image`), so the scale factors a page states hold on paper.

:func:`compile_document` runs the compiler (the ``typst`` wheel: nothing
else to install) with the fonts that ship with it and with matplotlib
(DejaVu Sans, which the drawings name), never the system's, and with no
date, so the same source gives the same bytes on any machine.
"""

from __future__ import annotations

import re
import unicodedata

from ..errors import PlansError

__all__ = ["string", "text", "math", "mixed", "image", "compile_document", "query_document", "query_value", "TypesetError", "FONT", "MATH_FONT"]

#: the text font of every page (ships with Typst; Latin, Cyrillic, Greek)
FONT = "Libertinus Serif"
#: the font of equations
MATH_FONT = "New Computer Modern Math"


class TypesetError(PlansError, RuntimeError):
    """The typesetter refused a page (a bug in the page's source: the message names the line)."""


def _clean(value) -> str:
    """User text as plain text: NFC, format characters dropped, control characters (newlines) as spaces."""
    out = []
    for ch in unicodedata.normalize("NFC", str(value)):
        category = unicodedata.category(ch)
        if category == "Cf":
            continue
        out.append(" " if category.startswith("C") else ch)
    return re.sub(r" {2,}", " ", "".join(out))


def string(value) -> str:
    """*value* as a Typst string literal (``"…"``, quotes and backslashes escaped)."""
    return '"' + _clean(value).replace("\\", "\\\\").replace('"', '\\"') + '"'


def text(value) -> str:
    """*value* as Typst markup that prints it exactly as written (an embedded string literal)."""
    return "#" + string(value) if str(value) else ""


# --- the program's mathtext → Typst math ----------------------------------------------------------

_COMMANDS = {
    "omega": "omega", "varepsilon": "epsilon", "epsilon": "epsilon.alt", "varphi": "phi", "phi": "phi.alt",
    "alpha": "alpha", "beta": "beta", "gamma": "gamma", "delta": "delta", "theta": "theta", "psi": "psi",
    "mu": "mu", "pi": "pi", "tau": "tau", "lambda": "lambda", "rho": "rho", "sigma": "sigma",
    "Delta": "Delta", "Omega": "Omega", "Phi": "Phi",
    "cdot": "dot.op", "times": "times", "Rightarrow": "arrow.r.double", "rightarrow": "arrow.r", "to": "arrow.r",
    "quad": "quad", "qquad": "wide", "circ": "circle.stroked.tiny", "parallel": "parallel", "perp": "perp",
    "angle": "angle", "pm": "plus.minus", "approx": "approx", "infty": "infinity", "sqrt": "sqrt",
    "left": "", "right": "",
}
_SPACES = {",": "thin", " ": "space", ";": "med", ":": "med", "!": ""}


def _math_string(value: str) -> str:
    return string(value)


def math(body: str) -> str:
    """A mathtext body (without the ``$``) as Typst math content (without the ``$``).

    Letters are set one by one (``A4C`` → ``A 4 C``: Typst reads a run of
    letters as a name); ``{…}`` after ``_`` or ``^`` become ``(…)``, other
    braces vanish; ``\\mathrm{…}`` is upright text; ``^\\circ`` a degree sign;
    ``/`` and other characters Typst math would read as syntax are set as
    symbols.
    """
    out: list[str] = []
    stack: list[bool] = []
    k = 0
    n = len(body)
    after_script = False
    while k < n:
        ch = body[k]
        if ch == "\\":
            m = re.match(r"\\([A-Za-z]+)", body[k:])
            if m:
                name = m.group(1)
                k += len(m.group(0))
                if name in ("mathrm", "text", "mathit", "mathbf"):
                    depth, j = 0, k
                    while j < n:
                        if body[j] == "{":
                            depth += 1
                        elif body[j] == "}":
                            depth -= 1
                            if depth == 0:
                                break
                        j += 1
                    inner = body[k + 1:j] if k < n and body[k] == "{" else ""
                    k = j + 1
                    inner = inner.replace("\\,", " ").replace("\\ ", " ").replace("^{2}", "²").replace("^2", "²").replace("^{3}", "³").replace("^3", "³")
                    out.append(_math_string(inner) + " ")
                    after_script = False
                    continue
                if name in ("dot", "ddot", "vec", "bar", "overline", "underline", "hat"):
                    fn = {"dot": "dot", "ddot": "dot.double", "vec": "arrow", "bar": "overline", "overline": "overline",
                          "underline": "underline", "hat": "hat"}[name]
                    out.append(fn + "(")
                    if k < n and body[k] == "{":
                        stack.append(True)
                        k += 1
                    else:  # one token
                        out.append(_math_token(body[k]) + ")")
                        k += 1
                    after_script = False
                    continue
                if name == "circ" and out and out[-1] == "^":
                    out[-1] = "°"
                    after_script = False
                    continue
                symbol = _COMMANDS.get(name)
                out.append((symbol if symbol is not None else _math_string(name)) + " ")
                after_script = False
                continue
            nxt = body[k + 1] if k + 1 < n else ""
            k += 2
            if nxt in _SPACES:
                out.append(_SPACES[nxt] + " " if _SPACES[nxt] else "")
            elif nxt in "{}$_%&#^":
                out.append(_math_string(nxt))
            else:
                out.append(_math_token(nxt))
            continue
        if ch == "{":
            stack.append(after_script)
            out.append("(" if after_script else "")
            after_script = False
            k += 1
            continue
        if ch == "}":
            opened = stack.pop() if stack else False
            out.append(")" if opened else "")
            k += 1
            continue
        if ch in "_^":
            if out:
                out[-1] = out[-1].rstrip()
            out.append(ch)
            after_script = True
            k += 1
            continue
        if ch.isdigit():
            m = re.match(r"[0-9]+(?:[.,][0-9]+)?", body[k:])
            token = m.group(0)
            if "," in token:  # a decimal comma: one number, not a list (Typst math spaces a comma)
                # a string keeps the spaces written around it (a number does not): set it tight, so that a unary
                # minus sits against it as against 25.64 (−25,64, not − 25,64), and 7,5i, i0,97 read as 7.5i, i0.97
                token = _math_string(token)
                while out and out[-1].endswith(" ") and not out[-1].rstrip().endswith('"'):  # two strings stay apart
                    out[-1] = out[-1].rstrip()
                    if not out[-1]:
                        out.pop()
                if after_script and len(token) > 1:
                    token = f"({token})"
                out.append(token)
                k += len(m.group(0))
                while k < n and body[k] == " ":
                    k += 1
                after_script = False
                continue
            if after_script and len(token) > 1:
                token = f"({token})"
            out.append(token + " ")
            k += len(m.group(0))
            after_script = False
            continue
        out.append(_math_token(ch) + " ")
        after_script = False
        k += 1
    while stack:
        out.append(")" if stack.pop() else "")
    return "".join(out).strip()


_SAFE = set("+-=()[]|,.<>!'′″·×−±∥⊥∠°→⇒≈")


def _math_token(ch: str) -> str:
    """One character as a Typst math token: a letter or a safe symbol as it is, anything else as a string."""
    if ch.isspace():
        return " "
    if ch.isalpha() or ch in _SAFE:
        return ch
    return _math_string(ch)


def mixed(line: str) -> str:
    """A line of text with ``$…$`` parts as Typst markup: the text as string literals, the parts as math.

    ``\\$`` is a literal dollar sign.
    """
    pieces = re.split(r"(?<!\\)\$", line)
    out = []
    for k, piece in enumerate(pieces):
        if k % 2:
            out.append("$" + math(piece) + "$")
        elif piece:
            out.append(text(piece.replace("\\$", "$")))
    return "".join(out)


def image(key: str, width_mm: float) -> str:
    """The code that places the SVG input *key* at *width_mm* (its physical width: 1:1 on paper)."""
    return f'image(bytes(sys.inputs.at({string(key)})), format: "svg", width: {width_mm:.3f}mm)'


_FONT_PATHS: list[str] | None = None


def _font_paths() -> list[str]:
    """matplotlib's own fonts (DejaVu Sans, which every drawing names), beside those that ship with Typst."""
    global _FONT_PATHS
    if _FONT_PATHS is None:
        import os

        import matplotlib

        _FONT_PATHS = [os.path.join(matplotlib.get_data_path(), "fonts", "ttf")]
    return _FONT_PATHS


def compile_document(source: str, images: dict | None = None, fmt: str = "pdf", ppi: float = 110.0):
    """Compile Typst *source* with *images* (key -> SVG bytes or str) to ``"pdf"`` (bytes) or to
    ``"svg"`` / ``"png"`` (a list of bytes, a page each).

    No system fonts, no date: the same source and images give the same bytes.
    """
    import typst

    inputs = {key: (data.decode("utf-8") if isinstance(data, bytes) else data) for key, data in (images or {}).items()}
    try:
        out = typst.compile(source.encode("utf-8"), format=fmt, ppi=ppi if fmt == "png" else None, sys_inputs=inputs,
                            font_paths=_font_paths(), ignore_system_fonts=True, pdf_tags=False)
    except typst.TypstError as exc:
        raise TypesetError(f"the typesetter refused a page: {exc}") from None
    if fmt == "pdf":
        return out
    pages = list(out) if isinstance(out, list) else [out]
    return [_svg_in_mm(page) for page in pages] if fmt == "svg" else pages


def query_document(source: str, images: dict | None, selector: str) -> list:
    """The values of the ``metadata`` elements *selector* (a label, ``"<name>"``) finds in the laid-out document:
    where the page's flow put something (a page number, a height), read back to fit the flow."""
    import json

    import typst

    inputs = {key: (data.decode("utf-8") if isinstance(data, bytes) else data) for key, data in (images or {}).items()}
    try:
        out = typst.query(source.encode("utf-8"), selector, field="value", sys_inputs=inputs, font_paths=_font_paths(),
                          ignore_system_fonts=True)
    except typst.TypstError as exc:
        raise TypesetError(f"the typesetter refused a page: {exc}") from None
    return json.loads(out)


def query_value(source: str, images: dict | None, label: str):
    """The value of the one ``metadata`` labelled *label* in the laid-out document *source* (a size Typst measured:
    the page asks before it is laid out)."""
    values = query_document(source, images, f"<{label}>")
    if len(values) != 1:
        raise TypesetError(f"the typesetter found {len(values)} marks <{label}> where one was expected")
    return values[0]


_ROOT_PT = re.compile(rb'(<svg\b[^>]*?)\bwidth="([0-9.]+)pt" height="([0-9.]+)pt"')


def _svg_in_mm(data: bytes) -> bytes:
    """An SVG page with its root size in millimetres (a viewer or printer at 100 % reproduces the scale factors)."""
    def mm(pt: bytes) -> bytes:
        return f"{float(pt) * 25.4 / 72:.3f}".rstrip("0").rstrip(".").encode() + b"mm"

    return _ROOT_PT.sub(lambda m: m.group(1) + b'width="' + mm(m.group(2)) + b'" height="' + mm(m.group(3)) + b'"', data, count=1)
