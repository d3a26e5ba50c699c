"""Numbers as a page in a given language writes them (no matplotlib here).

* :data:`DECIMAL_COMMA` — the languages written with a decimal comma (sr, ru, bg, sl);
* :func:`localised` — a number already formatted as text, with the language's
  decimal mark and a true minus sign (U+2212);
* :func:`scale_caption` — a drawing's scale statement, the symbol typeset
  (``$k_{v}$ = 0,025 (m/s)/mm``);
* :func:`detail_title` — an enlarged detail's title, ``Детайл I (4 : 1)``.

>>> localised("-0.25", "sr"), localised("-0.25", "en")
('−0,25', '−0.25')
"""

from __future__ import annotations

__all__ = ["DECIMAL_COMMA", "MINUS", "localised", "scale_caption", "detail_title", "detail_word", "course_units"]

from .._text import course_units  # noqa: E402 (re-exported: the drawings' unit symbols)
from ..i18n import term

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


def detail_title(name: str, ratio: str, lang: str) -> str:
    """An enlarged detail's title, the same on the plan of positions and on every plan: *name* (``I``), *ratio*
    formatted (``4``) — ``Детайл I (4 : 1)`` (round 20 read "I (4 : 1)" on a plan against "Детайл I (10 : 1)" on the
    plan of positions).

    >>> detail_title("II", "2.5", "bg")
    'Детайл II (2,5 : 1)'
    """
    return f"{detail_word(lang)} {name} ({localised(ratio, lang)} : 1)"


def detail_word(lang: str) -> str:
    """The word a detail's title starts with, capitalised: ``Детайл``, ``Выносной элемент``, ``Detail``."""
    word = term("detail", lang)
    return word[:1].upper() + word[1:]
