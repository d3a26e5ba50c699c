"""Numbers as a page in a given language writes them (no matplotlib here).

* :data:`DECIMAL_COMMA` — the languages written with a decimal comma (sr, ru, bg, sl);
* :func:`localised` — a number already formatted as text, with the language's
  decimal mark and a true minus sign (U+2212);
* :func:`scale_caption` — a drawing's scale statement, the symbol typeset
  (``$k_{v}$ = 0,025 (m/s)/mm``).

>>> localised("-0.25", "sr"), localised("-0.25", "en")
('−0,25', '−0.25')
"""

from __future__ import annotations

__all__ = ["DECIMAL_COMMA", "MINUS", "localised", "scale_caption", "course_units"]

import re

#: Languages written with a decimal comma.
DECIMAL_COMMA = ("sr", "ru", "bg", "sl")
#: The minus sign (not the hyphen-minus).
MINUS = "\u2212"


def localised(text: str, lang: str) -> str:
    """*text* (a formatted number, or a line of them) with a true minus sign and, in sr, ru, bg, sl, a decimal comma."""
    text = text.replace("-", MINUS)
    return text.replace(".", ",") if lang in DECIMAL_COMMA else text


def scale_caption(key: str, value: str, units: str, lang: str) -> str:
    """A drawing's scale statement: *key* ``"k_v"`` typeset as k with subscript v, *value* (formatted) localised.

    >>> scale_caption("k_v", "0.025", "(m/s)/mm", "sr")
    '$k_{v}$ = 0,025 (m/s)/mm'
    """
    symbol, _, sub = key.partition("_")
    return f"${symbol}_{{{sub}}}$ = {localised(value, lang)} {units}"


#: Units as the Russian and Bulgarian courses write them (Cyrillic symbols); Serbian and Slovenian
#: courses write the international symbols, as English does.
_CYRILLIC_UNITS = {"rad/s²": "рад/с²", "rad/s": "рад/с", "m/s²": "м/с²", "m/s": "м/с", "m/mm": "м/мм", "mm": "мм", "rad": "рад", "m": "м"}
_UNIT = re.compile(r"(?<![\w\\{])(rad/s²|rad/s|m/s²|m/s|m/mm|mm|rad|m)(?![\w}])")


def course_units(line: str, lang: str) -> str:
    """*line* with its unit symbols as the course in *lang* writes them (ru, bg: ``м/с``, ``мм``); math parts kept.

    Only the text outside ``$…$`` changes, and only whole unit symbols there
    (a point or a link named ``m`` inside math stays).
    """
    if lang not in ("ru", "bg"):
        return line
    pieces = re.split(r"(?<!\\)(\$)", line)
    out, inside = [], False
    for piece in pieces:
        if piece == "$":
            inside = not inside
            out.append(piece)
            continue
        if inside:
            piece = re.sub(r"\\mathrm\{([^}]*)\}", lambda m: "\\mathrm{" + _UNIT.sub(lambda u: _CYRILLIC_UNITS[u.group(1)], m.group(1)) + "}", piece)
        else:
            piece = _UNIT.sub(lambda u: _CYRILLIC_UNITS[u.group(1)], piece)
        out.append(piece)
    return "".join(out)
