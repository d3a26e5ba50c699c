"""Text helpers shared by the drawings and the handout (no matplotlib here).

* :data:`SUBSCRIPT` — the ``str.translate`` table of the digits to subscript digits;
* :func:`subscript` — a link's name as the subscript of a symbol: ``"3"`` → ``"₃"``, ``"rod"`` → ``"_rod"``;
* :func:`user_text` — text a user typed (a title) made safe to draw as plain text;
* :func:`math_name` — a name from the scene (a point, a link) made safe to set inside math.
"""

from __future__ import annotations

import re
import unicodedata

__all__ = ["SUBSCRIPT", "SUPERSCRIPT", "subscript", "user_text", "math_name", "decimal_comma", "DECIMAL_COMMA"]

#: languages whose numbers are written with a decimal comma (0,025)
DECIMAL_COMMA = ("sr", "ru", "bg", "sl")
_DECIMAL_POINT = re.compile(r"(?<=\d)\.(?=\d)")

#: Digits to subscript digits, for :meth:`str.translate`.
SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
#: position numbers on the plan of positions (``E¹``), apart from a link's subscript (``E₁``)
SUPERSCRIPT = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def subscript(name: str) -> str:
    """*name* as the subscript of a symbol: subscript digits for a number (``"3"`` → ``"₃"``), else ``"_name"``."""
    return name.translate(SUBSCRIPT) if name.isdigit() else f"_{name}"


def user_text(text) -> str:
    """*text* (a title, a name) as plain text for a drawing: never read as math, nothing invisible.

    Unicode NFC; format characters (a byte-order mark U+FEFF, zero-width
    joiners, direction marks) removed; control characters (tabs, newlines)
    become spaces, runs of spaces one; every ``$`` escaped as ``\\$``, which
    matplotlib draws as a literal dollar sign and never passes to its math
    parser.

    >>> user_text("\\ufeffPump   $\\\\alpha$\\n")
    'Pump \\\\$\\\\alpha\\\\$'
    """
    text = unicodedata.normalize("NFC", str(text))
    out = []
    for ch in text:
        category = unicodedata.category(ch)
        if category == "Cf":
            continue
        out.append(" " if category in ("Cc", "Zl", "Zp") else ch)
    return " ".join("".join(out).split()).replace("$", r"\$")


#: what math reads as markup: groups, scripts, commands, the end of math, a space it drops
_MATH_MARKUP = frozenset("\\{}$_^ ")


def math_name(name) -> str:
    """*name* (a point, a link, a line of the scene) as math that sets it as written.

    A name with nothing math reads as markup comes back as it is (``CA``,
    ``B,x``), so the math around it sets it as before.  Otherwise it is put in
    ``\\text{…}`` with each of ``\\ { } $ _ ^`` and the space escaped by a
    backslash, which matplotlib's math parser and plans' own typesetter
    (:mod:`plans.drawing.typeset`) both read as "this character as it is":
    ``A_1_2`` is set as ``A_1_2``, never as a double subscript.  Whitespace
    and invisible characters are cleaned as :func:`user_text` cleans them.

    >>> print(math_name("A_1_2"), math_name("CA"))
    \\text{A\\_1\\_2} CA
    """
    text = user_text(name).replace(r"\$", "$")
    if not _MATH_MARKUP.intersection(text):
        return text
    return r"\text{" + "".join("\\" + ch if ch in _MATH_MARKUP else ch for ch in text) + "}"


def decimal_comma(text: str, lang: str) -> str:
    """*text* with the decimal point of its numbers as *lang* writes it: ``0.025`` → ``0,025`` in sr, ru, bg, sl.

    Only a point between two digits changes (``5.rod``, ``I(1,2)`` stay).

    >>> decimal_comma("k_v = 0.025 (m/s)/mm, φ = 55.0°", "ru")
    'k_v = 0,025 (m/s)/mm, φ = 55,0°'
    """
    return _DECIMAL_POINT.sub(",", text) if lang in DECIMAL_COMMA else text


#: Units as the Russian and Bulgarian courses write them (Cyrillic symbols); Serbian and Slovenian
#: courses write the international symbols, as English does.
_CYRILLIC_UNITS = {"rad/s²": "рад/с²", "rad/s": "рад/с", "m/s²": "м/с²", "m/s": "м/с", "m/mm": "м/мм", "s/mm": "с/мм", "mm": "мм", "rad": "рад",
                   "m": "м", "[s]": "[с]", " s": " с", "[m]": "[м]"}
_UNIT = re.compile(r"(?<![\w\\{])(rad/s²|rad/s|m/s²|m/s|m/mm|s/mm|mm|rad|m)(?![\w}′″'₀-₉])|(\[s\])|(?<=[0-9])( s)(?![\w])")
#: the same without a bare "m" (a drawing's labels: the image m of a point M stays), but metres in an axis' brackets
_DRAWN_UNIT = re.compile(r"(?<![\w\\{])(rad/s²|rad/s|m/s²|m/s|m/mm|s/mm|mm|rad)(?![\w}])|(\[s\])|(?<=[0-9])( s)(?![\w])|(\[m\])")


def course_units(line: str, lang: str, drawn: bool = False) -> str:
    """*line* with its unit symbols as the course in *lang* writes them (ru, bg: ``м/с``, ``мм``); math parts kept.

    Only the text outside ``$…$`` changes, and only whole unit symbols there
    (a point or a link named ``m`` inside math stays, and so does an image ``m′``, ``m₁``
    in a readings table); *drawn* (a drawing's
    text, where ``m`` is the image of a point M) leaves a bare ``m`` alone.
    """
    if lang not in ("ru", "bg"):
        return line
    pattern = _DRAWN_UNIT if drawn else _UNIT

    def swap(u) -> str:
        return _CYRILLIC_UNITS[next(g for g in u.groups() if g)]

    pieces = re.split(r"(?<!\\)(\$)", line)
    out, inside = [], False
    for piece in pieces:
        if piece == "$":
            inside = not inside
            out.append(piece)
            continue
        if inside:
            piece = re.sub(r"\\mathrm\{([^}]*)\}", lambda m: "\\mathrm{" + pattern.sub(swap, m.group(1)) + "}", piece)
        else:
            piece = pattern.sub(swap, piece)
        out.append(piece)
    return "".join(out)
