"""The words of a page that come from the scene: its title, its names, the assembly of its groups.

A scene may give its title and names per language (``title = { en = "…",
sr = "…" }``, ``[names] slot = { en = "slot", sr = "кулиса" }``); a page
prints them in its language, and where the scene gives only one form,
exactly as written.  The assembly of each group is said in the textbook's
words ("the slider to the right of B", "C to the left of the line BD"),
never as a program token (``RRR(3,4): … (−1)``).
"""

from __future__ import annotations

import math
import re

from ..i18n import term
from ..scene import FRAME

__all__ = ["namer", "assembly_lines", "group_words", "assembly_text", "units"]


def namer(scene, lang: str):
    """A function: a name as the scene writes it → the name on a page in *lang*."""
    return lambda name: scene.name_in(name, lang)


_GROUP = re.compile(r"^[A-Z]{3}\(([^,()]+),([^,()]+)\)$")


def group_words(group: str, lang: str) -> str:
    """``RRR(3,4)`` → ``group 3–4`` (the links it is made of, as the course names a group)."""
    m = _GROUP.match(group)
    if not m:
        return group
    return f"{term('group', lang)} {m.group(1)}–{m.group(2)}"


_NAME = r"[^\W]+"


def _guide_angle(scene, key: str) -> float | None:
    """The frame guide's angle [rad] for a key ``frame.ram``; None for a guide on a moving link."""
    body, _, line = key.partition(".")
    if body != FRAME or line not in scene.bodies[FRAME].lines:
        return None
    return scene.bodies[FRAME].lines[line].angle


def _side(angle: float, sign: int, lang: str) -> str | None:
    """Along a frame guide at *angle*: right/left/above/below when the guide is within 10° of an axis."""
    deg = math.degrees(angle) % 360.0
    for axis, (ahead, back) in ((0.0, ("right_of", "left_of")), (90.0, ("above", "below")), (180.0, ("left_of", "right_of")), (270.0, ("below", "above"))):
        if min(abs(deg - axis), 360 - abs(deg - axis)) <= 10.0:
            return term(ahead if sign > 0 else back, lang)
    return None


def assembly_text(branch, scene, lang: str) -> str | None:
    """One group's assembly in words, or None for a group with one assembly (or a form not known here)."""
    name = namer(scene, lang)
    words = branch.words.strip()
    m = re.fullmatch(rf"({_NAME}) to the (left|right) of ({_NAME})→({_NAME})", words)
    if m:
        c, side, b, d = m.groups()
        return term("assembly_side", lang).format(c=c, side=term(side, lang), b=b, d=d)
    m = re.fullmatch(rf"({_NAME}) at the intersection (further along|nearer the start of) ({_NAME}(?:\.{_NAME})?) \(of the two the circle about ({_NAME}) meets\)", words)
    if m:
        c, how, key, b = m.groups()
        sign = 1 if how == "further along" else -1
        angle = _guide_angle(scene, key) if "." in key else _frame_line(scene, key)
        side = _side(angle, sign, lang) if angle is not None else None
        if side is not None:
            return term("assembly_slider_side", lang).format(c=c, where=side, b=b)
        return term("assembly_along", lang).format(c=c, where=term("ahead_of" if sign > 0 else "behind", lang), b=b, key=name(key.rpartition(".")[2]))
    m = re.fullmatch(rf"line ({_NAME}(?:\.{_NAME})?) pointing from ({_NAME}) towards ({_NAME})", words)
    if m:
        key, a, b = m.groups()
        return term("assembly_directed", lang).format(key=name(key.rpartition(".")[2]), a=a, b=b)
    return None


def _frame_line(scene, key: str) -> float | None:
    line = scene.bodies[FRAME].lines.get(key)
    return line.angle if line is not None else None


def assembly_lines(branches, scene, lang: str) -> list[str]:
    """The assembly of every group that has two, one line each: ``group 3–4: C to the left of the line BD, …``."""
    out = []
    for b in branches or ():
        if not b.sign:
            continue
        words = assembly_text(b, scene, lang)
        if words:
            out.append(f"{group_words(b.group, lang)}: {words}")
    return out


#: Units as the Russian and Bulgarian courses write them (Cyrillic symbols); Serbian and Slovenian
#: courses write the international symbols, as English does.
_CYRILLIC_UNITS = {"rad/s²": "рад/с²", "rad/s": "рад/с", "m/s²": "м/с²", "m/s": "м/с", "m/mm": "м/мм", "mm": "мм", "rad": "рад", "m": "м"}
_UNIT = re.compile(r"(?<![\w\\{])(rad/s²|rad/s|m/s²|m/s|m/mm|mm|rad|m)(?![\w}])")


def units(line: str, lang: str) -> str:
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
