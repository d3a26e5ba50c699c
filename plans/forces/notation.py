"""The letters a course writes for the program's force symbols, by language (text only: no drawing, no solving).

The program names its forces in one notation (domain.md §11): the inertia force
``F_Φ3`` and couple ``M_Φ3`` of link 3 (the lever's pair standing for a couple
``F′_Φ3``, ``F″_Φ3``), the balancing moment ``M_b``, force ``F_b`` and the
lever's arm ``h_b``, and the useful resistance ``F_r`` (a scene's load may carry
that name).  A Russian or Bulgarian course writes the inertia force Ф₃ and the
inertia couple M_Ф3 (the Cyrillic Ф), the balancing moment and force M_ур, F_ур
(уравновешивающий / уравновесяващ) and the useful resistance F_пс (сила полезного
сопротивления / сила на полезното съпротивление).  Serbian, Slovenian and
English keep the program's letters (domain.md §11 writes F_Φ, M_Φ, M_b); the
Serbian and Slovenian balancing subscripts were not confirmed from a course.

>>> course_label("F_Φ3", "ru"), course_label("M_Φ3", "ru"), course_label("F′_Φ3", "bg")
('Ф_3', 'M_Ф3', 'Ф′_3')
>>> course_label("M_b", "ru"), course_label("F_r", "bg"), course_label("F_Φ3", "sr")
('M_ур', 'F_пс', 'F_Φ3')
"""

from __future__ import annotations

import re

__all__ = ["COURSE_SUBSCRIPTS", "course_label", "plain_centres", "centre_text"]

#: the subscripts a course writes for the program's symbols, by language (b: balancing, r: useful resistance)
COURSE_SUBSCRIPTS = {"ru": {"b": "ур", "r": "пс"}, "bg": {"b": "ур", "r": "пс"}}
#: the program's symbols whose subscript is the course's (symbol -> the subscript key of COURSE_SUBSCRIPTS)
_COURSE_SYMBOLS = {"M_b": "b", "F_b": "b", "h_b": "b", "F_r": "r"}
#: the languages whose course writes the inertia force Ф_k and couple M_Фk (Cyrillic Ф)
_CYRILLIC_INERTIA = ("ru", "bg")
_INERTIA = re.compile(r"^([FM])([′″]?)_Φ(.*)$")


def course_label(label: str, lang: str = "en") -> str:
    """A force's label (``symbol_subscript``) with the letters the course in *lang* writes: ``"M_b"`` → ``"M_ур"``
    (``"F_b"``, ``"h_b"`` likewise; ``"F_r"`` → ``"F_пс"``), ``"F_Φ3"`` → ``"Ф_3"``, ``"M_Φ3"`` → ``"M_Ф3"`` in
    Russian and Bulgarian; any other label, and every label in another language, as it is."""
    if lang in _CYRILLIC_INERTIA:
        m = _INERTIA.match(label)
        if m:
            kind, prime, sub = m.groups()
            return f"Ф{prime}_{sub}" if kind == "F" else f"M{prime}_Ф{sub}"
    key = _COURSE_SYMBOLS.get(label)
    if key is None or lang not in COURSE_SUBSCRIPTS:
        return label
    return f"{label.partition('_')[0]}_{COURSE_SUBSCRIPTS[lang][key]}"



def plain_centres(scene) -> bool:
    """Whether the scene names a centre of mass itself in the plain form S and its link's number (``S3`` on link 3,
    the number on the line): its pages print that name as written (the kinematic pages do), and so every centre
    the program names on them (S2, its image s2), one spelling on every page; else the course's S₂, s₂."""
    for mass in scene.masses.values():
        point = mass.point
        if point and point[:1] in "Ss" and point[1:] == mass.body and len(scene.bodies_with(point)) == 1:
            return True
    return False


def centre_text(scene, body: str) -> str:
    """The name of link *body*'s centre of mass on a page: ``"S₃"``, or ``"S3"`` where the scene writes its centres so
    (:func:`plain_centres`)."""
    from .._text import subscript

    return f"S{body}" if plain_centres(scene) else f"S{subscript(body)}"

