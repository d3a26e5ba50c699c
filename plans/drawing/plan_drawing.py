"""Velocity and acceleration plans, drawn from :class:`plans.graphical.plan.Plan` data.

Plan coordinates are already millimetres of paper (the construction applied
k_v or k_a), so one data unit is one millimetre and a vector drawn from the
pole to an image measures |v| / k_v.  Nothing is computed here beyond where a
label goes.

Gids (for tests and for styling the SVG afterwards): ``vel-``/``acc-``
prefix, then ``absolute-v_B`` (shaft) and ``absolute-v_B-head`` (head, whose
first vertex is the tip), ``relative-…``, ``normal-…``, ``tangential-…``,
``coriolis-…``, ``construction-…``, ``pole``, ``image-b``, ``legend-<kind>``,
``scale``.
"""

from __future__ import annotations

import cmath
import math
import re

import numpy as np
import shapely
from shapely.geometry import MultiPoint, Point
from shapely.geometry import Polygon as ShapelyPolygon

from .._text import SUBSCRIPT, math_name
from ._canvas import Sketch, fmt_number, sketch_on, text_size, unit
from .labels import LABEL_SPACE_MM, place_label, place_ring_name
from .numerals import detail_title, detail_word, localised, scale_caption

from .style import (
    CAPTION_PT,
    CONSTRUCTION_STYLE,
    FIGURE_STYLE,
    MM_PER_PT,
    HEADING_PT,
    INK,
    LABEL_PT,
    VECTOR_STYLE,
)
from ..graphical.plan import KINDS
from ..i18n import term

__all__ = [
    "draw_plan",
    "draw_plan_into",
    "draw_velocity_plan",
    "draw_acceleration_plan",
    "vectors_drawn",
    "aliases",
    "alongside",
    "pole_text",
    "at_rest_texts",
    "along_note",
    "kinds_drawn",
    "link_figures",
    "vector_math",
    "end_letters",
    "coriolis_letter",
    "segment",
    "notes_text",
    "legend_words",
    "legend_entries",
    "figure_entries",
    "ZERO_MM",
    "SHORT_MM",
    "enlarged",
    "whole_detail_ratios",
    "detail_caption",
]

#: A vector shorter than this [mm] is not drawn (it has no direction to show).
ZERO_MM = 1e-6
#: A vector shorter than this [mm] is too short for an arrow (its head, at most
#: a third of it, would be under 1 mm: linear-arm aⁿ of 2.3 and 2.6 mm): its end
#: is marked as a labelled point and a note under the plan gives its length.
SHORT_MM = 3.0
#: The end of a short vector this close [mm] to an image shares its label ("a′, n₁").
JOIN_MM = 1.0
#: A component lying along an absolute vector is drawn this far beside it [mm],
#: with thin ticks to its true ends, so that it can be seen.
BESIDE_MM = 1.2
#: A vector from the pole along a longer absolute vector from the pole (six-bar
#: π→m′ on π→a′, quick-return v_A4C = p→a₄ on p→d) is drawn on it, as the
#: textbook draws it: its head stands on that shaft with a white rim this wide [pt].
HALO_PT = 1.2
#: Two plan labels' boxes sharing more than this [mm²] overlap (one is then placed before the other).
LABEL_CLASH_MM2 = 0.01
#: A label set further than this from its point [mm] gets a leader line.
LEADER_FROM_MM = 2.0
#: Label gaps [mm] tried in turn on a plan (the far ones with a leader line).
PLAN_GAPS = (0.6, 1.4, 2.4, 3.6, 5.5, 8.0, 11.0, 15.0)
#: Images closer than this [mm] share one label ("p, o, d").
SAME_MM = 1e-3
#: How far a construction line runs past the intersection and behind its start [mm].
PAST_MM = 7.0
BEHIND_MM = 3.0

#: A link whose images all lie within this span [mm] crowds: its arrowheads
#: overlap and its figure cannot be read (six-bar a b c), so it is drawn again,
#: enlarged, in a detail beside the plan.
CROWD_MM = 8.0
#: A link whose images span up to twice :data:`CROWD_MM` crowds too when two of them are closer than this [mm]
#: (six-bar a b c at the handout's k_v: 10 mm across, b 2.5 mm from c: their heads pile on each other; not the
#: quick-return's c a₄ d on one line through the pole, 3.4 mm apart at the least).
CLOSE_MM = 3.0
#: The detail enlarges the crowd to about this span [mm]...
DETAIL_SPAN_MM = 28.0
#: ...and its two closest images to at least this distance [mm] (two full heads apart)...
DETAIL_APART_MM = 7.0
#: ...by the first of these drafting ratios (n : 1) that does both.
DETAIL_RATIOS = (2, 2.5, 4, 5, 10)
#: The detail's name on the plan and over the detail (a drafting detail numeral).
DETAIL_NAME = "I"

#: A plan no larger than this [mm] across whose short components are given only in notes (quick-return position 4's
#: acceleration plan, 22 mm at the plate's k_a) is drawn again whole, enlarged n : 1, beside itself (a detail)...
SMALL_PLAN_MM = 30.0
#: ...at most this large [mm]; the plan's notes then wrapped this wide [mm].
ENLARGED_MAX_MM = 120.0
NARROW_NOTES_MM = 30.0

_UNITS = {"velocity": ("k_v", "(m/s)/mm"), "acceleration": ("k_a", "(m/s²)/mm")}


def enlarged(plan, ratio: float):
    """*plan* drawn *ratio* times larger: every image, vector end and construction line's point [mm] multiplied by
    *ratio*, the scale factor divided by it (the same plan at k / n; nothing solved again)."""
    from dataclasses import replace

    def vector(v):
        return replace(v, tail=complex(v.tail) * ratio, tip=complex(v.tip) * ratio)

    steps = tuple(replace(s, known=tuple(vector(v) for v in s.known), found=tuple(vector(v) for v in s.found),
                          lines=tuple(replace(cl, through=complex(cl.through) * ratio) for cl in s.lines)) for s in plan.steps)
    return replace(plan, scale=plan.scale / ratio, images={k: complex(z) * ratio for k, z in plan.images.items()},
                   vectors=tuple(vector(v) for v in plan.vectors), steps=steps)


def whole_detail_ratios(plan) -> tuple[float, ...]:
    """The ratios n, largest first, at which a small *plan* is drawn again whole beside itself (a detail; none for a plan
    larger than :data:`SMALL_PLAN_MM`, one without components too short for an arrow, or one with a crowd detailed
    within it): each makes it at most :data:`ENLARGED_MAX_MM` across and draws one more of its short vectors as an arrow."""
    vectors = vectors_drawn(plan)
    shorts = [v for v in vectors if v.length < SHORT_MM]
    if not shorts or _crowds(plan, plan.images, vectors):
        return ()
    zs = [0j] + [complex(z) for z in plan.images.values()] + [complex(v.tip) for v in vectors]
    extent = max(max(z.real for z in zs) - min(z.real for z in zs), max(z.imag for z in zs) - min(z.imag for z in zs))
    if extent >= SMALL_PLAN_MM:
        return ()
    return tuple(n for n in reversed(DETAIL_RATIOS) if extent * n <= ENLARGED_MAX_MM and any(v.length * n >= SHORT_MM for v in shorts))


def detail_caption(ratio: float, lang: str = "en") -> tuple[str, str]:
    """The heading of a plan's whole detail in the reader's language, as (word, numeral and ratio): ``("Detail", "I (5 : 1)")``,
    written ``Detail I (5 : 1)`` as every detail's title (:func:`~plans.drawing.numerals.detail_title`; the word over the
    rest where the detail is narrower than the whole)."""
    return detail_word(lang), f"{DETAIL_NAME} ({localised(fmt_number(ratio), lang)} : 1)"


def _same(v, w) -> bool:
    return abs(v.tail - w.tail) <= SAME_MM and abs(v.tip - w.tip) <= SAME_MM


def vectors_drawn(plan) -> list:
    """The plan's vectors that a drawing shows, each once.

    Zero-length vectors are left out, and so is a component that coincides
    with an absolute vector (the normal acceleration of a crank pin turning at
    constant speed *is* its acceleration): drawn under it, it could not be
    seen, yet it would add a legend entry.  Identical vectors (the points of
    one sliding link: p→w, p→t, p→u) are drawn once, the first in plan order;
    the label at their tip names every image.  Vectors shorter than
    :data:`SHORT_MM` are in the list but drawn as a point (see :func:`draw_plan`).
    """
    vectors = [v for v in plan.vectors if abs(v.tip - v.tail) > ZERO_MM]
    absolute = [v for v in vectors if v.kind == "absolute"]
    out: list = []
    for v in vectors:
        if v.kind != "absolute" and any(_same(v, w) for w in absolute):
            continue
        if any(_same(v, w) for w in out):
            continue
        out.append(v)
    return out


def kinds_drawn(plan) -> set[str]:
    """The kinds of vector a drawing of *plan* shows (what its legend lists).

    Every kind the plan holds: a vector shorter than :data:`SHORT_MM`, drawn as
    a lettered point with a note under the plan (``a′k = 0,29 mm``), is a vector
    of the plan all the same, named in its equations and readings, and the legend
    says what its kind is (a Coriolis component too short for an arrow is still a
    Coriolis component).
    """
    return {v.kind for v in vectors_drawn(plan)}


def vector_math(label: str) -> str:
    """A plan vector's name as mathtext: ``"a^n_CA"`` → ``"$a^{n}_{\\mathrm{CA}}$"``."""
    head, _, sub = label.partition("_")
    symbol, _, sup = head.partition("^")
    text = symbol + (f"^{{{sup}}}" if sup else "") + (rf"_{{\mathrm{{{math_name(sub)}}}}}" if sub else "")
    return f"${text}$"


#: The letter of a Coriolis component's end as textbooks letter it...
CORIOLIS_LETTER = "k"
#: ...and, when an image of the scene is lettered k (linear-arm's point K: its image k′ beside a Coriolis end k or κ
#: reads as one letter), the Coriolis component's own symbol as the legend, the equations and the readings write it
#: (aᵏ; aᵏ₁, aᵏ₂ in the order of the equations when there are several), the component named at its end.
CORIOLIS_LETTER_ELSE = "aᵏ"


def coriolis_letter(plan=None) -> str:
    """The letter of the Coriolis components' ends on *plan*: ``k``, or ``aᵏ`` when an image of a scene point is lettered k."""
    images = getattr(plan, "images", {}) or {}
    points = getattr(plan, "points", None)
    for name in images:
        text = image_text(name, points)
        if text.rstrip("′").rstrip("₀₁₂₃₄₅₆₇₈₉0123456789").lower() == CORIOLIS_LETTER:
            return CORIOLIS_LETTER_ELSE
    return CORIOLIS_LETTER


def end_letters(vectors, plan=None) -> dict[str, str]:
    """Vector label -> the letter of its end point, as textbooks letter the plan: normal
    components end at n₁, n₂, …, Coriolis components at k (k₁, k₂, … when there are several;
    aᵏ, aᵏ₁, … when the scene has a point K, see :func:`coriolis_letter`)."""
    out = {}
    for kind, letter in (("normal", "n"), ("coriolis", coriolis_letter(plan))):
        these = [v for v in vectors if v.kind == kind]
        for index, v in enumerate(these, 1):
            out[v.label] = letter + (str(index).translate(SUBSCRIPT) if (kind == "normal" or len(these) > 1) else "")
    return out


def segment(plan, v, letters: dict[str, str] | None = None) -> str:
    """The segment of the plan that *v* is drawn as, named by the letters of its ends: ``pa``, ``π a′``, ``a a₄``, ``n₁ c′``, ``a′ k``.

    The tail of an absolute vector is the pole; a relative vector v_XY runs from the
    image of Y to that of X (its subscript's second and first points); a component
    that starts or ends off the images at a lettered end (n₁, k) is named by it.
    *letters* is :func:`end_letters` of the drawn vectors (found when omitted).
    """
    if letters is None:
        letters = end_letters(vectors_drawn(plan), plan)
    ends = {}
    for w in plan.vectors:
        if w.label in letters:
            ends.setdefault(letters[w.label], complex(w.tip))
    sub = v.label.partition("_")[2]
    points = getattr(plan, "points", None) or {}
    rest = at_rest_texts(plan)

    def written(name: str) -> str:
        return "".join(points[name]) if name in points else name.rstrip("′").upper()

    def fits(name: str, tail: bool) -> int:
        """2: the image is the point the subscript names (A4 of v_A4A3), 1: of the same name on another link (F of F3), 0: not."""
        w = written(name)
        if sub.endswith(w) if tail else sub.startswith(w):
            return 2 + len(w)
        bare = re.escape(points[name][0] if name in points else w)
        return 1 if re.search(rf"{bare}\d*$" if tail else rf"^{bare}\d*", sub) else 0

    def letter(z: complex, tail: bool) -> str:
        here = [name for name, w in plan.images.items() if abs(w - z) <= SAME_MM]
        named = [name for name in here if fits(name, tail)]
        if named:
            best = max(named, key=lambda n: fits(n, tail))
            return rest.get(best) or image_text(best, points)
        for text, at in ends.items():
            if abs(at - z) <= SAME_MM:
                return text
        if abs(z) <= SAME_MM:
            return pole_text(plan)
        return (rest.get(here[0]) or image_text(here[0], points)) if here else "?"

    a = pole_text(plan) if v.kind == "absolute" else letter(complex(v.tail), True)
    b = letter(complex(v.tip), False)
    return a + b if (a + b).isascii() and len(a) == 1 and len(b) == 1 else f"{a} {b}"


def draw_plan(plan, ax=None, *, lang: str = "en", legend: bool = True, detail: bool | None = None) -> list:
    """Draw a velocity or acceleration plan (``plan.kind`` says which).

    Parameters
    ----------
    plan : plans.graphical.plan.Plan
    ax : matplotlib.axes.Axes, optional
        Drawn into, one data unit = one millimetre.  When omitted, a new figure
        exactly the size of the plan is made (true to scale); reach it as
        ``artists[0].figure``.
    lang : str
        Language of the heading and the legend (see :mod:`plans.i18n`).
    legend : bool
        False leaves the legend out (a page that shows one legend for all).
    detail : bool, optional
        Draw crowded images again, enlarged, in a detail beside the plan (see
        :data:`CROWD_MM`).  By default as *legend*: a handout's position page
        (one legend for all) chooses each plan's scale to fill its box, and a
        detail, which does not scale with the plan, would make it choose a coarser one.

    Returns
    -------
    list of matplotlib.artist.Artist
        Shafts are Line2D, heads Polygons whose first vertex is the tip.
    """
    if plan.kind not in _UNITS:
        raise ValueError(f"a plan is 'velocity' or 'acceleration', got {plan.kind!r}")
    tag = "vel" if plan.kind == "velocity" else "acc"
    detail = legend if detail is None else detail
    return sketch_on(ax, tag, lambda sketch: draw_plan_into(sketch, plan, lang=lang, legend=legend, detail=detail))


def draw_velocity_plan(plan, ax=None, *, lang: str = "en") -> list:
    """:func:`draw_plan` for a velocity plan."""
    return draw_plan(plan, ax, lang=lang)


def draw_acceleration_plan(plan, ax=None, *, lang: str = "en") -> list:
    """:func:`draw_plan` for an acceleration plan."""
    return draw_plan(plan, ax, lang=lang)


def image_text(name: str, points: dict | None = None) -> str:
    """An image's label as the textbook prints it: the point's name in lower case, the link number of a coincident point as a subscript.

    *points* is the plan's :attr:`~plans.graphical.plan.Plan.points` (image label ->
    (point as the scene writes it, link number or ``""``)): ``"e5"`` of (E, 5) → ``"e₅"``,
    ``"a4′"`` → ``"a₄′"``, and the image of a point the scene names O2 → ``"o2"``, its digits
    as written (not ``"o₂"``, which would read as the point O of link 2).  Without *points*
    (or for a label it does not know) trailing digits are taken for a link number.
    """
    base = name.rstrip("′")
    primes = name[len(base):]
    if points and name in points:
        point, body = points[name]
        return point.lower() + body.translate(SUBSCRIPT) + primes
    letters = name.rstrip("0123456789′")
    return letters + name[len(letters):].translate(SUBSCRIPT)


def pole_text(plan) -> str:
    """The pole's label: ``p`` (``π``), or ``pᵥ`` (``πₐ``) when an image would otherwise share it (a point named P)."""
    texts = {image_text(name, plan.points) for name, z in plan.images.items() if abs(z) > SAME_MM}
    pole = image_text(plan.pole)
    if pole in texts:
        return pole + ("ᵥ" if plan.kind == "velocity" else "ₐ")
    return pole


def at_rest_texts(plan) -> dict[str, str]:
    """Image label -> its label when the plan's vectors name the point at rest differently: a point of the frame only
    (of no moving link's figure) whose image is at the pole, named by a vector from the pole with a link's number (six-bar: the sleeve 6 pivoted at the
    frame point E, ``v_E5E6``, whose equations read v_E6 = 0: the image e at the pole is lettered ``e₆``, ``e₆′``)."""
    points = getattr(plan, "points", None) or {}
    on_links = {n for names in getattr(plan, "links", {}).values() for n in names}
    out = {}
    for name, z in plan.images.items():
        if abs(z) > SAME_MM or name not in points or points[name][1] or name in on_links:
            continue  # (a point of a moving link at rest for the instant keeps its letter: linear-arm's f′)
        point = points[name][0]
        written = {"".join(points[n]) for n in plan.images if n in points}
        for v in plan.vectors:
            m = re.search(rf"(?<![A-Za-z]){re.escape(point)}([0-9]+)$", v.label.partition("_")[2])
            if abs(v.tail) <= SAME_MM and v.kind != "absolute" and m and point + m.group(1) not in written:
                out[name] = point.lower() + m.group(1).translate(SUBSCRIPT) + name[len(name.rstrip("′")):]
                break
    return out


def aliases(plan) -> dict[str, list[str]]:
    """Absolute vector label -> the other names of the same vector, which the drawing draws once with it.

    A relative vector from a point at rest (v_A4C with c at the pole, v_HQ, v_EE0) or a crank pin's
    normal acceleration (a^n_AO) *is* the absolute vector: the plan draws it once, as absolute, and
    the readings name it both ways (``v_A4 = v_A4C``).
    """
    vectors = [v for v in plan.vectors if abs(v.tip - v.tail) > ZERO_MM]
    out: dict[str, list[str]] = {}
    for w in vectors:
        if w.kind != "absolute":
            continue
        for v in vectors:
            if v.kind != "absolute" and _same(v, w) and v.label not in out.setdefault(w.label, []):
                out[w.label].append(v.label)
    return {k: names for k, names in out.items() if names}


#: Two vectors from the pole closer than this in direction [degrees], the shorter's tip within
#: :data:`ALONG_OFF_MM` of the longer's shaft, lie one on the other: a note under the plan gives both directions.
ALONG_DEG = 3.0
#: ...and the shorter's tip closer than this [mm] to the longer's shaft: its head (1.2 mm wide) stands on that shaft or
#: all but touches it (four-bar p m, 0.44° off p a and 158 mm long on the A3 sheet: 1.22 mm off).
ALONG_OFF_MM = 2.0
#: ...but more than this apart [degrees]: images on one line through the pole (quick-return a₄ on p d, the
#: similarity of link 4's images) lie exactly along, as the construction makes them, and need no note.
ALONG_MIN_DEG = 0.05


def alongside(plan) -> list[tuple]:
    """Pairs (shorter, longer) of drawn absolute vectors that lie one along the other (six-bar π m′ on π a′, 0.6° apart).

    The shorter's head stands on the longer's shaft (within a white rim); as the two shafts read
    as one, the plan's notes give both directions (:func:`draw_plan`).
    """
    absolute = [v for v in vectors_drawn(plan) if v.kind == "absolute" and v.length >= SHORT_MM and abs(v.tail) <= SAME_MM]
    out = []
    for v in absolute:
        for w in absolute:
            if w is v or w.length <= v.length + SAME_MM:
                continue
            turn = abs(math.degrees(cmath.phase(complex(v.tip) / complex(w.tip))))
            off = (complex(v.tip) * unit(complex(w.tip)).conjugate()).imag
            if ALONG_MIN_DEG < turn < ALONG_DEG and abs(off) < ALONG_OFF_MM:
                out.append((v, w))
                break
    return out


def legend_row(sketch, kind: str, words: str, x: float, y: float, *, text_gid: str) -> None:
    """One legend entry at (x, y) [mm]: a 9 mm sample of the *kind*'s line or arrow (a link's image: a lightly filled
    triangle), then its words."""
    a, c = complex(x, y), complex(x + 9.0, y)
    if kind == "construction":
        color, lw, dashes = CONSTRUCTION_STYLE
        sketch.line([a, c], color=color, lw=lw, dashes=dashes, gid=f"legend-{kind}", obstacle=False)
    elif kind == "figure":  # (a link's image: a lightly filled triangle, as the plans draw it)
        edge, lw, fill = FIGURE_STYLE
        sketch.polygon([a - 1.2j, c - 1.2j, a + 6.0 + 1.2j], fc=fill, ec=edge, lw=lw, gid=f"legend-{kind}", obstacle=False)
    elif kind == "figure_segment":  # (a link's image whose points lie on a line: the thin segment the plans draw)
        edge, lw, _ = FIGURE_STYLE
        sketch.line([a, c], color=edge, lw=lw, gid=f"legend-{kind}", obstacle=False)
    else:
        color, lw, dashes, _ = VECTOR_STYLE[kind]
        sketch.arrow(a, c, color=color, lw=lw, dashes=dashes, head=2.4, gid=f"legend-{kind}")
    sketch.text(complex(x + 11.0, y), words, size=CAPTION_PT, ha="left", va="center", gid=text_gid, obstacle=False)


def _check(z: complex, what: str) -> complex:
    z = complex(z)
    if not (math.isfinite(z.real) and math.isfinite(z.imag)):
        raise ValueError(f"{what} is not finite: {z!r}")
    return z


def draw_plan_into(sketch: Sketch, plan, lang: str = "en", legend: bool = True, caption: bool = True, detail: bool = True,
                   heading: bool = True, whole: float | None = None, detail_under: bool = False) -> None:
    """Draw *plan* into *sketch* (one data unit = 1 mm): what :func:`draw_plan` does on a page's own Sketch.

    *caption* False leaves out the heading, scale and legend; *legend* False only the legend;
    *detail* False the enlarged detail of crowded images; *heading* False the heading and the
    scale factor only (a page that states them itself keeps the notes on short vectors); *whole* the ratio of a detail
    of the whole plan drawn beside it (:func:`whole_detail_ratios`: its notes say which short vectors it draws);
    *detail_under* an enlarged detail that finds no room within the plan drawn under it rather than to its right
    (a sheet's region taller than wide).
    """
    images = {name: _check(z, f"image {name}") for name, z in plan.images.items()}
    vectors = vectors_drawn(plan)
    for v in vectors:
        _check(v.tail, v.label)
        _check(v.tip, v.label)
    letters = end_letters(vectors, plan)

    # construction lines, thin, under everything
    drawn_lines = 0
    for step in plan.steps:
        target = images.get(step.image)
        for cl in step.lines:
            through = _check(cl.through, f"construction line {cl.label}")
            d = unit(complex(cl.direction))
            t = ((target - through) * d.conjugate()).real if target is not None else 20.0
            lo, hi = min(0.0, t), max(0.0, t)
            a = through + d * (lo - (BEHIND_MM if t >= 0 else PAST_MM))
            b = through + d * (hi + (PAST_MM if t >= 0 else BEHIND_MM))
            color, lw, dashes = CONSTRUCTION_STYLE
            sketch.line([a, b], color=color, lw=lw, dashes=dashes, gid=f"construction-{step.image}", zorder=1.0, obstacle=True)
            drawn_lines += 1

    _figures(sketch, plan, images, vectors)

    # components under the absolute vectors, in a fixed order of kinds
    absolute = [v for v in vectors if v.kind == "absolute" and v.length >= SHORT_MM]
    placed: dict[str, list[tuple[complex, complex]]] = {}  # kind -> (tail, tip) of the components drawn so far
    for kind in ("normal", "tangential", "coriolis", "relative", "absolute"):
        for v in vectors:
            if v.kind != kind or v.length < SHORT_MM:
                continue
            color, lw, dashes, head = VECTOR_STYLE[kind]
            z = 3.0 if kind == "absolute" else 2.5
            tail, tip = complex(v.tail), complex(v.tip)
            along = _along(v, absolute)
            if along is not None:
                # its shaft lies under the longer vector's; its head, full size, stands
                # out on that shaft within a white rim
                size = _head(max(head, VECTOR_STYLE["absolute"][3]), lw, v.length)
                _, head_artist = sketch.arrow(tail, tip, color=color, lw=lw, dashes=dashes, head=size, gid=f"{kind}-{v.label}", zorder=2.4)
                _rim(sketch, head_artist, f"{kind}-{v.label}-rim")
                continue
            if kind != "absolute":
                # off an absolute vector it would lie on unseen, or off a component of its kind drawn along the same
                # line (linear-arm: the two Coriolis components of sliders on one rod, 1.5 mm apart, read as one line)
                shift = _beside(tail, tip, absolute) or _apart(tail, tip, placed.get(kind, []))
                if shift:
                    for end in (tail, tip):
                        sketch.line([end, end + shift * 1.25], color=color, lw=0.4, gid=f"{kind}-{v.label}-tick", zorder=z, obstacle=False)
                    tail, tip = tail + shift, tip + shift
            sketch.arrow(tail, tip, color=color, lw=lw, dashes=dashes, head=_head(head, lw, v.length), gid=f"{kind}-{v.label}", zorder=z)
            placed.setdefault(kind, []).append((tail, tip))

    # the pole, the image points and the lettered ends of components
    sketch.circle(0j, 0.55, fc=INK, lw=0, gid="pole", zorder=4.0)
    for name, z in images.items():
        if abs(z) > SAME_MM:
            sketch.circle(z, 0.4, fc=INK, lw=0, gid=f"dot-{name}", zorder=4.0, obstacle=False)
    ends = []
    for v in vectors:
        if v.label in letters:
            tip = complex(v.tip)
            if not any(abs(tip - z) <= SAME_MM for z in images.values()):
                sketch.circle(tip, 0.3, fc=INK, lw=0, gid=f"end-dot-{v.label}", zorder=4.0, obstacle=False)
            ends.append((tip, letters[v.label], v.label))
    shorts = [v for v in vectors if v.length < SHORT_MM]
    for v in shorts:
        if v.label not in letters and not any(abs(complex(v.tip) - z) <= SAME_MM for z in images.values()):
            sketch.circle(complex(v.tip), 0.3, fc=INK, lw=0, gid=f"end-dot-{v.label}", zorder=4.0, obstacle=False)

    # labels: the pole first, then each group of coincident images (and component ends)
    # a detail of short components that crowd is drawn first, where the plan has room for it (else their
    # notes stand alone); a link's crowd is ringed first, so that the plan's labels keep off the ring, and its
    # detail, beside the plan when there is no room within, is drawn after them
    in_detail: dict[str, tuple[str, float]] = {}  # (a short vector's label: the detail drawing it, its ratio)
    rings = []
    names_given: list[str] = []  # I, II, … in the order the details are drawn

    def next_name() -> str:
        names_given.append(DETAIL_NAME + "I" * len(names_given))
        return names_given[-1]

    for pts, names in _crowds(plan, images, vectors) if detail else []:
        chain = [v.length for v in shorts if not names and any(abs(complex(v.tail) - q) <= SAME_MM for q in pts) and any(abs(complex(v.tip) - q) <= SAME_MM for q in pts)]
        ring = _ring(pts, min(chain) if chain else None)
        if names:
            _draw_ring(sketch, ring)
            rings.append((ring, names))
        elif (at := _spot(sketch, ring, within=True)) is not None:
            _draw_ring(sketch, ring)
            name = next_name()
            for label in _detail(sketch, plan, vectors, images, ends, ring, names, name, at, lang=lang):
                in_detail.setdefault(label, (name, ring[2]))
        elif detail_under:  # (no room within: under the plan, after its labels, as a link's crowd)
            _draw_ring(sketch, ring)
            rings.append((ring, names))
    if detail:
        # a vector from the pole along a longer one (six-bar π m′ on π a′, 0.6° apart): its tip, under a millimetre off
        # the other's shaft, is ringed and drawn enlarged within the plan, where the two read apart
        for v, w in alongside(plan):
            tip = complex(v.tip)
            u = unit(complex(w.tip) - complex(w.tail))
            foot = complex(w.tail) + u * ((tip - complex(w.tail)) * u.conjugate()).real
            ring = _ring([tip, foot])
            if any(abs(tip - c) <= r for (c, r, _), _ in rings):
                continue  # within a crowd's detail
            if (at := _spot(sketch, ring, within=True)) is not None:
                _draw_ring(sketch, ring)  # (only where the plan has room for it: the page's plan keeps its scale)
                name = next_name()
                for label in _detail(sketch, plan, vectors, images, ends, ring, [], name, at, lang=lang):
                    in_detail.setdefault(label, (name, ring[2]))
    groups = _label_groups(plan, images, ends, shorts, JOIN_MM)
    # every dot of the plan: a label stands nearer its own point than any other (it reads as that point's)
    where = {"pole-label": 0j} | {f"image-{name}": z for name, z in images.items()} | {f"end-{label}": z for z, _, label in ends}

    def place_labels(order: list[int], led: frozenset = frozenset(), clear: bool = False) -> tuple[list[tuple[int, int]], bool]:
        """Place the groups' labels in *order* (those in *led* may stand off with a leader; *clear*: where the leader
        crosses no mark); the pairs (later, earlier) whose boxes overlap, and whether a leader runs across a label."""
        boxes: list[tuple[int, object]] = []
        leaders: list[tuple[int, object]] = []
        clashes = []
        for i in order:
            at, pieces = groups[i]
            mine = [where[gid] for _, gid in pieces if gid in where]
            rivals = tuple(q for q in where.values() if all(abs(q - m) > SAME_MM for m in mine))
            before = len(sketch.obstacles)
            place_label(sketch, at, pieces, size=LABEL_PT, prefer=_away(at, vectors), gaps=PLAN_GAPS, leader_from=LEADER_FROM_MM, rivals=rivals,
                        by_box=True, leader_ok=i in led, beyond=True, clear_leaders=clear)
            drawn = sketch.obstacles[-1].buffer(-LABEL_SPACE_MM, join_style=2)  # the label's own box
            clashes += [(i, j) for j, other in boxes if drawn.intersection(other).area > LABEL_CLASH_MM2]
            boxes.append((i, drawn))
            if len(sketch.obstacles) > before + 1:  # (its leader line, drawn before its box)
                leaders.append((i, sketch.obstacles[-2]))
        across = any(leader.intersects(box_) for i, leader in leaders for j, box_ in boxes if i != j)
        return clashes, across

    def arrange(clear: bool) -> bool:
        """Labels where they fit, the pole's and the coincident images' first; a label that lands on one placed before
        it (linear-arm position 2: n₁ 2.3 mm off the pole under "π, d′, q′, a′, f′") is placed before that one
        instead, the other taking the room it leaves, with a leader when it must stand off.  Whether a leader runs
        across a label."""
        order, led = list(range(len(groups))), frozenset()
        clashes, across = place_labels(order, clear=clear)
        for _ in range(3):
            if not clashes:
                break
            earlier = list(order)
            led_more = led | {i for pair in clashes for i in pair}
            for later, first in clashes:
                if earlier.index(later) > earlier.index(first):
                    earlier.remove(later)
                    earlier.insert(earlier.index(first), later)
            sketch.restore(state)
            tried, across = place_labels(earlier, led_more, clear)
            if len(tried) < len(clashes):
                order, led, clashes = earlier, led_more, tried
            else:  # no better: as it was
                sketch.restore(state)
                _, across = place_labels(order, led, clear)
                break
        return across

    state = sketch.checkpoint()
    if arrange(clear=False):
        # a leader across another label (quick-return position 2, 18 mm at the plate's k_a: n₂'s through "d′"): again,
        # each leader where it crosses no mark
        sketch.restore(state)
        arrange(clear=True)

    for ring, names in rings:
        name = next_name()
        for label in _detail(sketch, plan, vectors, images, ends, ring, names, name, under=detail_under, lang=lang):
            in_detail.setdefault(label, (name, ring[2]))

    if whole:
        for v in shorts:
            if v.length * whole >= SHORT_MM:
                in_detail.setdefault(v.label, (DETAIL_NAME, whole))
    if caption:
        _caption(sketch, plan, vectors, drawn_lines, lang, legend, notes=[(v, in_detail.get(v.label)) for v in shorts],
                 along=alongside(plan), heading=heading, letters=letters, narrow=bool(whole))


def _crowds(plan, images: dict, vectors=()) -> list[tuple[list[complex], list[str]]]:
    """What crowds on the plan, each as (its points, the images of its link figure):

    * the images of a link, 3 or more distinct within :data:`CROWD_MM`, or within twice that with two of them
      closer than :data:`CLOSE_MM` (six-bar a b c);
    * a chain of vectors too short for an arrow (under :data:`SHORT_MM`) but long enough to
      read at the largest ratio, joining 3 or more distinct points within :data:`CROWD_MM`
      (quick-return pos 2: a′ →k Coriolis 1.38 mm, k →a₄′ aʳ 1.26 mm), whose heads the plan cannot show.
    """
    out: list[tuple[list[complex], list[str]]] = []
    for link, labels in getattr(plan, "links", {}).items():
        names: list[str] = []
        for label in labels:
            z = images.get(label)
            if z is not None and all(abs(z - images[n]) > SAME_MM for n in names):
                names.append(label)
        pts = [images[n] for n in names]
        if len(pts) >= 3:
            span = max(abs(q - r) for q in pts for r in pts)
            closest = min(abs(q - r) for i, q in enumerate(pts) for r in pts[:i])
            crowded = span < CROWD_MM or (closest < CLOSE_MM and span < 2 * CROWD_MM)
            if 0.5 < span and crowded and not any(set(names) <= set(c) for _, c in out):
                out.append((pts, names))
    # chains of short vectors: their ends joined into clusters, in plan order
    readable = DETAIL_APART_MM / DETAIL_RATIOS[-1]
    clusters: list[list[complex]] = []
    for v in vectors:
        if not readable <= v.length < SHORT_MM:
            continue
        ends = [complex(v.tail), complex(v.tip)]
        hit = [c for c in clusters if any(abs(e - q) <= SAME_MM for e in ends for q in c)]
        merged: list[complex] = []
        for c in hit:
            clusters.remove(c)
            merged.extend(q for q in c if all(abs(q - m) > SAME_MM for m in merged))
        merged.extend(e for e in ends if all(abs(e - m) > SAME_MM for m in merged))
        clusters.append(merged)
    for pts in clusters:
        if len(pts) < 3 or max(abs(q - r) for q in pts for r in pts) >= CROWD_MM:
            continue
        if any(all(any(abs(q - w) <= SAME_MM for w in c) for q in pts) for c, _ in out):
            continue  # already in a link's detail
        out.append((pts, []))
    return out


def _clip(a: complex, b: complex, centre: complex, r: float):
    """The part of segment a–b inside the circle (centre, r), as (a′, b′), or None."""
    d = b - a
    f = a - centre
    qa = (d * d.conjugate()).real
    if qa <= 0:
        return None
    qb = 2 * (f * d.conjugate()).real
    qc = (f * f.conjugate()).real - r * r
    disc = qb * qb - 4 * qa * qc
    if disc <= 0:
        return None
    root = math.sqrt(disc)
    t0, t1 = max(0.0, (-qb - root) / (2 * qa)), min(1.0, (-qb + root) / (2 * qa))
    if t1 - t0 <= 1e-9:
        return None
    return a + d * t0, a + d * t1


def _label_groups(plan, images: dict, ends, shorts, join: float) -> list[tuple[complex, list[tuple[str, str]]]]:
    """The plan's labels: (point, [(text, gid), …]) for the pole, each group of coincident images, and component ends.

    Images closer than :data:`SAME_MM` share one label ("p, o, c"); a component's
    lettered end within *join* of an image shares that image's label ("a′, n₁").
    """
    groups: list[tuple[complex, list[tuple[str, str]]]] = [(0j, [(pole_text(plan), "pole-label")])]

    def add(z: complex, piece: tuple[str, str], within: float) -> None:
        for at, pieces in groups:
            if abs(at - z) <= within:
                pieces.append(piece)
                return
        groups.append((z, [piece]))

    rest = at_rest_texts(plan)
    for name, z in images.items():
        add(z, (rest.get(name) or image_text(name, getattr(plan, "points", None)), f"image-{name}"), SAME_MM)
    for z, letter, label in ends:
        # a lettered end within *join* of an image shares its label whether its own vector or the next one is the
        # short one (quick-return position 4: n₁ 0.16 mm from a₄′, the tangential component between them)
        add(z, (letter, f"end-{label}"), join)
    return groups


def _away(at: complex, vectors) -> complex | None:
    """The direction away from the vectors that start or end at *at* (where its label is preferred), or None."""
    away = 0j
    for v in vectors:
        for end, other in ((v.tail, v.tip), (v.tip, v.tail)):
            if abs(end - at) <= SAME_MM and abs(other - end) > SAME_MM:
                away -= unit(other - end)
    return away if abs(away) > 1e-9 else None


def _ring(pts: list[complex], shortest: float | None = None) -> tuple[complex, float, float]:
    """The ring around crowding points on the plan: (centre, radius, ratio n of its detail).

    A link's crowd is enlarged to about :data:`DETAIL_SPAN_MM` with its images
    :data:`DETAIL_APART_MM` apart; a chain of short components (the *shortest* of
    them given) just enough for each to be an arrow twice :data:`SHORT_MM` long,
    so that its detail finds room within the plan.
    """
    centre = sum(pts) / len(pts)
    r = max(abs(q - centre) for q in pts) + 1.6
    closest = min(abs(q - w) for i, q in enumerate(pts) for w in pts[:i])
    if shortest is not None:
        fits = (k for k in DETAIL_RATIOS if 2 * r * k >= 0.75 * DETAIL_SPAN_MM and shortest * k >= 2 * SHORT_MM and closest * k >= 0.5 * DETAIL_APART_MM)
    else:
        fits = (k for k in DETAIL_RATIOS if 2 * r * k >= DETAIL_SPAN_MM and closest * k >= DETAIL_APART_MM)
    return centre, r, next(fits, DETAIL_RATIOS[-1])


def _draw_ring(sketch: Sketch, ring: tuple[complex, float, float]) -> None:
    """The ring on the plan (gid ``detail-ring``), an obstacle to labels."""
    centre, r, _ = ring
    edge, _, _ = FIGURE_STYLE
    sketch.circle(centre, r, fc="none", ec=edge, lw=0.5, gid="detail-ring", zorder=1.2, obstacle=False)
    sketch.obstacles.append(Point(centre.real, centre.imag).buffer(r).exterior.buffer(0.2))


#: Gap [mm] between a plan and an enlarged detail drawn under it (the detail's name, over its circle, stands in it).
DETAIL_UNDER_GAP_MM = 8.0


#: the room [mm] between a detail's circle and the ring on the plan it enlarges
RING_CLEAR_MM = 6.0


def _spot(sketch: Sketch, ring: tuple[complex, float, float], within: bool = False, under: bool = False) -> complex | None:
    """Where the ring's detail goes: in a free part of the plan (the page's room for it is not widened),
    nearest the crowd; else (unless *within*) beside it, to the right, level with the crowd (*under*: below it,
    under the crowd, its name clear of the plan)."""
    centre, r, ratio = ring
    big = r * ratio
    b = sketch.bounds
    free = big + 1.5
    step = 2.0
    spots = [
        complex(b.xmin + free + i * step, b.ymin + free + j * step)
        for i in range(int(max(0.0, b.width - 2 * free) / step) + 1)
        for j in range(int(max(0.0, b.height - 2 * free) / step) + 1)
    ]
    # (clear of the ring it enlarges by room for the ring's name and its points' labels: round 25's six-bar detail
    # touched the ring at m′, its "m′" and "I" on the detail's edge)
    spots = [c for c in spots if abs(c - centre) >= big + r + RING_CLEAR_MM]
    spots.sort(key=lambda c: (abs(c - centre), c.real, c.imag))
    # A spot is free when its disk (a polygon inside the circle of radius *free*) meets no obstacle.  One
    # spatial query finds, for every spot at once, the obstacles within *free* of it (a superset of those
    # the disk meets); the disks themselves are made and tested only for those pairs.
    # the spots in batches, nearest the crowd first: a free spot near it ends the search early
    obstacles = np.array([o for o in sketch.obstacles if not o.is_empty], dtype=object)
    tree = shapely.STRtree(obstacles)
    for start in range(0, len(spots), 1024):
        batch = spots[start:start + 1024]
        points = shapely.points([(c.real, c.imag) for c in batch])
        pairs = tree.query(points, predicate="dwithin", distance=free * (1 + 1e-9) + 1e-9)
        near = np.zeros(len(batch), dtype=bool)
        if pairs.shape[1]:
            meets = shapely.intersects(shapely.buffer(points[pairs[0]], free, quad_segs=16), obstacles[pairs[1]])  # as Point.buffer
            near[pairs[0][meets]] = True
        free_spots = np.flatnonzero(~near)
        if len(free_spots):
            return batch[int(free_spots[0])]
    if within:
        return None
    if under:
        x = min(max(centre.real, b.xmin + big), b.xmax - big) if b.width >= 2 * big else centre.real
        return complex(x, b.ymin - DETAIL_UNDER_GAP_MM - big)
    # level with the crowd, but within the plan's height when the plan is taller than the detail
    level = min(max(centre.imag, b.ymin + big), b.ymax - big) if b.height >= 2 * big else centre.imag
    outside = [complex(b.xmax + 6.0 + big, level), complex(b.xmax + 6.0 + big, b.ymax - big), complex(b.xmax + 6.0 + big, b.ymin + big)]
    return next((c for c in outside if not any(Point(c.real, c.imag).buffer(big + 2.0).intersects(o) for o in sketch.obstacles)), outside[0])


def _detail(sketch: Sketch, plan, vectors, images: dict, ends, ring: tuple[complex, float, float], names: list[str], name: str, at: complex | None = None,
            under: bool = False, lang: str = "en") -> set[str]:
    """Crowded images drawn again, enlarged n : 1, in a circle beside the plan (a drafting detail).

    The crowd is ringed on the plan and named.  The detail shows everything the
    ring holds, enlarged: every vector that passes through it (the part inside,
    with its head when its tip is inside), also one too short for an arrow on
    the plan that is long enough at n : 1 (the plan's note on it says where it
    is drawn), the link's figure, and every image point and lettered component
    end inside the ring with the label it has on the plan (the pole "p, o, c").
    Gids: ``detail-ring``, ``detail``, ``detail-<vector>`` (shaft, ``-head``),
    ``detail-figure``, ``detail-pole``, ``detail-dot-<n>``, ``detail-end-dot-<vector>``, ``detail-pole-label``,
    ``detail-image-<name>``, ``detail-end-<vector>``, ``detail-name``.

    *ring* is the crowd's ring on the plan (:func:`_ring`), *names* the images of the link whose figure is drawn (or none),
    *at* the detail's centre (by default where :func:`_spot` finds room, *under* the plan if asked).
    Returns the labels of the vectors shorter than :data:`SHORT_MM` that the detail draws.
    """
    centre, r, ratio = ring
    big = r * ratio
    edge, lw, fill = FIGURE_STYLE
    if at is None:
        at = _spot(sketch, ring, under=under)

    def f(z: complex) -> complex:
        return at + (z - centre) * ratio

    def inside(z: complex) -> bool:
        return abs(complex(z) - centre) <= r

    sketch.circle(at, big, fc="none", ec=edge, lw=0.6, gid="detail", zorder=1.2, obstacle=False)
    sketch.bounds.add_box(at.real - big, at.imag - big, at.real + big, at.imag + big)
    sketch.obstacles.append(Point(at.real, at.imag).buffer(big).exterior.buffer(0.3))
    figure = [f(images[n]) for n in names]
    hull = MultiPoint([(q.real, q.imag) for q in figure]).convex_hull
    if len(figure) >= 3 and hull.geom_type == "Polygon":
        sketch.polygon([complex(x, y) for x, y in list(hull.exterior.coords)[:-1]], fc=fill, ec=edge, lw=lw, gid="detail-figure", zorder=0.8)
    shown: set[str] = set()
    long_absolute = [v for v in vectors if v.kind == "absolute" and v.length * ratio >= SHORT_MM]
    for v in vectors:
        part = _clip(complex(v.tail), complex(v.tip), centre, r)
        if part is None or v.length * ratio < SHORT_MM:
            continue  # outside the ring, or too short for an arrow even at n : 1
        color, vlw, dashes, head = VECTOR_STYLE[v.kind]
        a, c = f(part[0]), f(part[1])
        z = 3.0 if v.kind == "absolute" else 2.5
        if abs(part[1] - complex(v.tip)) <= SAME_MM and abs(c - a) > 1.0:
            if _along(v, long_absolute) is None and not _on_shaft(v, long_absolute, 0.5 / ratio):
                sketch.arrow(a, c, color=color, lw=vlw, dashes=dashes, head=_head(head, vlw, abs(c - a)), gid=f"detail-{v.label}", zorder=z)
            else:
                # on a longer absolute vector's shaft (v_A4C on p→d): its head stands out within a white rim, as on the plan
                _, head_artist = sketch.arrow(a, c, color=color, lw=vlw, dashes=dashes, head=_head(max(head, VECTOR_STYLE["absolute"][3]), vlw, abs(c - a)), gid=f"detail-{v.label}", zorder=2.4)
                _rim(sketch, head_artist, f"detail-{v.label}-rim")
        else:
            sketch.line([a, c], color=color, lw=vlw, dashes=dashes, gid=f"detail-{v.label}", zorder=z)
        if v.length < SHORT_MM:
            shown.add(v.label)
    # every image and lettered end inside the ring, labelled as on the plan; an end
    # that shares an image's label on the plan (a short component) has its own here
    groups = [(q, pieces) for q, pieces in _label_groups(plan, images, ends, [], SAME_MM) if inside(q)]
    for q, pieces in groups:
        first = pieces[0][1]  # the point's gid as on the plan: pole, dot-<image>, end-dot-<vector>
        dot = "pole" if first == "pole-label" else "dot-" + first[len("image-"):] if first.startswith("image-") else "end-dot-" + first[len("end-"):]
        sketch.circle(f(q), 0.55 if abs(q) <= SAME_MM else 0.45, fc=INK, lw=0, gid=f"detail-{dot}", zorder=4.0)
    near = [v for v in vectors if v.length * ratio >= SHORT_MM]
    for q, pieces in groups:
        away = _away(q, near)
        if away is None:
            away = f(q) - at if abs(f(q) - at) > 1e-9 else None
        place_label(sketch, f(q), [(text, f"detail-{gid}") for text, gid in pieces], size=LABEL_PT, prefer=away, gaps=PLAN_GAPS, leader_from=LEADER_FROM_MM)
    sketch.text(at + 1j * (big + 3.2), detail_title(name, fmt_number(ratio), lang), size=LABEL_PT, gid="detail-name")
    # the detail's whole disk from here on: no label of the plan inside it (round 25: the six-bar's "m′" and the ring's
    # name "I" stood in the circle of the detail that enlarges them); then the ring's name, clear of it
    sketch.obstacles.append(Point(at.real, at.imag).buffer(big))
    place_ring_name(sketch, centre, r, [(name, "detail-mark")], size=LABEL_PT)
    return shown


def _on_shaft(v, absolute, within: float) -> bool:
    """Whether *v*'s tip lies within *within* [mm] of the inside of another absolute vector's shaft (its head would be lost on it)."""
    tip = complex(v.tip)
    for w in absolute:
        if w is v or _same(v, w):
            continue
        u = unit(w.tip - w.tail)
        off = (tip - w.tail) * u.conjugate()
        if within < off.real < w.length - within and abs(off.imag) < within:
            return True
    return False


def _rim(sketch: Sketch, head_artist, gid: str) -> None:
    """Raise an arrowhead over the shaft it stands on, within a white rim :data:`HALO_PT` wide."""
    head_artist.set_zorder(3.6)
    rim = ShapelyPolygon(head_artist.get_xy()[:3]).buffer(HALO_PT * MM_PER_PT, join_style=2)
    sketch.polygon([complex(x, y) for x, y in list(rim.exterior.coords)[:-1]], fc="white", ec="none", lw=0, gid=gid, zorder=3.5, obstacle=False)


def _head(head: float, lw: float, length: float) -> float:
    """Arrowhead length [mm]: the style's, but never more than a third of the vector."""
    return min(head, length / 3.0)


def _beside(tail: complex, tip: complex, absolute) -> complex:
    """The shift [mm] that takes a component off an absolute vector it would lie on unseen, or 0.

    A component whose ends are both within :data:`BESIDE_MM` of the absolute
    vector's line, along a stretch it shares with it, is moved across (to the
    side it already leans to) until both ends are :data:`BESIDE_MM` off.
    """
    d = tip - tail
    for w in absolute:
        u = unit(w.tip - w.tail)
        off = [((z - w.tail) * u.conjugate()) for z in (tail, tip)]
        if all(abs(o.imag) < BESIDE_MM for o in off):
            lo, hi = sorted(o.real for o in off)
            overlap = min(hi, w.length) - max(lo, 0.0)
            if overlap > 0.3 * abs(d):
                side = 1.0 if sum(o.imag for o in off) >= 0 else -1.0
                worst = min(o.imag * side for o in off)
                return u * 1j * side * (BESIDE_MM - worst)
    return 0j


#: Two components of one kind on nearly one line, closer than this [mm] along a stretch they share, read as one line:
#: the later is drawn this far off the other (with ticks to its true ends).
APART_MM = 2.5


def _apart(tail: complex, tip: complex, drawn) -> complex:
    """The shift [mm] that takes a component off a parallel one of its kind it would run along (*drawn*: their
    (tail, tip) as drawn), or 0."""
    d = tip - tail
    if abs(d) == 0:
        return 0j
    for a, b in drawn:
        if abs(b - a) == 0:
            continue
        u = unit(b - a)
        if abs((unit(d) * u.conjugate()).imag) > math.sin(math.radians(ALONG_DEG)):
            continue  # not parallel
        off = [((z - a) * u.conjugate()) for z in (tail, tip)]
        if all(abs(o.imag) < APART_MM for o in off):
            lo, hi = sorted(o.real for o in off)
            if min(hi, abs(b - a)) - max(lo, 0.0) > 1.0:
                side = 1.0 if sum(o.imag for o in off) >= 0 else -1.0
                worst = min(o.imag * side for o in off)
                return u * 1j * side * (APART_MM - worst)
    return 0j


def _along(v, absolute):
    """The longer absolute vector from the pole that *v* (also from the pole) lies on, or None."""
    if abs(v.tail) > SAME_MM:
        return None
    for w in absolute:
        if w is v or abs(w.tail) > SAME_MM or w.length <= v.length + SAME_MM:
            continue
        u = unit(w.tip - w.tail)
        off = (v.tip - w.tail) * u.conjugate()
        if off.real > 0 and abs(off.imag) < BESIDE_MM:
            return w
    return None


def _at(z: complex, w: complex) -> bool:
    return abs(z - w) <= SAME_MM


def link_figures(plan, images: dict | None = None, vectors=None) -> list[tuple[str, list[complex], bool]]:
    """The image of each link as a plan draws it (similarity): ``(link, points [mm], filled)`` — its triangle (a b c),
    lightly filled, or the segment its images lie on (b e₅ m), from end to end.

    Images already joined end to end by a drawn vector need no segment (two images, or more on one line).  *images*
    and *vectors* default to the plan's (:func:`vectors_drawn`).
    """
    images = {name: complex(z) for name, z in plan.images.items()} if images is None else images
    vectors = vectors_drawn(plan) if vectors is None else vectors
    out = []
    for link, labels in getattr(plan, "links", {}).items():
        pts: list[complex] = []
        for label in labels:
            z = images.get(label)
            if z is not None and all(abs(z - q) > SAME_MM for q in pts):
                pts.append(z)
        if len(pts) < 2:
            continue
        hull = MultiPoint([(q.real, q.imag) for q in pts]).convex_hull
        span = max(abs(q - r) for q in pts for r in pts)
        if len(pts) > 2 and hull.geom_type == "Polygon" and hull.area > 0.01 * span * span:
            out.append((link, [complex(x, y) for x, y in list(hull.exterior.coords)[:-1]], True))
            continue
        a, b = max(((q, r) for q in pts for r in pts), key=lambda qr: abs(qr[0] - qr[1]))
        # (a segment a drawn vector already covers end to end is not drawn again: the slider-crank's a s₃ b under v_BA,
        # round 28, whose legend named a thin line nobody could see)
        if any({_at(v.tail, a), _at(v.tip, b)} == {True} or (_at(v.tail, b) and _at(v.tip, a)) for v in vectors):
            continue
        out.append((link, [a, b], False))
    return out


def _figures(sketch: Sketch, plan, images: dict, vectors) -> None:
    """The image of each link (:func:`link_figures`) drawn: a triangle lightly filled, else a thin segment."""
    edge, lw, fill = FIGURE_STYLE
    for link, pts, filled in link_figures(plan, images, vectors):
        if filled:
            sketch.polygon(pts, fc=fill, ec=edge, lw=lw, gid=f"figure-{link}", zorder=0.8, obstacle=False)
            sketch.obstacles.append(ShapelyPolygon([(q.real, q.imag) for q in pts]).exterior.buffer(lw * MM_PER_PT / 2))
        else:
            sketch.line(pts, color=edge, lw=lw, gid=f"figure-{link}", zorder=1.5)


#: plan kind -> vector kind -> key of plans.i18n.TERMS
LEGEND_TERMS = {
    "velocity": {"absolute": "absolute_velocity", "relative": "relative_velocity"},
    "acceleration": {
        "absolute": "absolute_acceleration",
        "relative": "relative_acceleration",
        "normal": "normal_component",
        "tangential": "tangential_component",
        "coriolis": "coriolis_component",
    },
}


def legend_words(plan_kind: str, kind: str, lang: str = "en") -> str:
    """The legend's words for a vector kind on a plan (``"construction"`` for construction lines)."""
    if kind == "construction":
        return term("construction_line", lang)
    if kind in ("figure", "figure_segment"):
        return term("link_image", lang)
    return term(LEGEND_TERMS[plan_kind][kind], lang)


def legend_entries(plans, lang: str = "en") -> list[tuple[str, str]]:
    """One legend for *plans* (Plan objects): ``(kind, words)`` for every kind drawn on any of them
    (:func:`kinds_drawn`: also a kind drawn only as lettered points with notes), one row per style ("absolute velocity / absolute acceleration"),
    then the construction lines, then the images of links where a plan draws one (:func:`link_figures`)."""
    words: dict[str, list[str]] = {}
    for plan in plans:
        drawn = kinds_drawn(plan)
        for kind in KINDS:
            if kind in drawn:
                text = legend_words(plan.kind, kind, lang)
                if text not in words.setdefault(kind, []):
                    words[kind].append(text)
    entries = [(kind, " / ".join(words[kind])) for kind in KINDS if kind in words]
    entries.append(("construction", legend_words("velocity", "construction", lang)))
    entries += figure_entries([f for plan in plans for f in link_figures(plan)], lang)
    return entries


def figure_entries(figures, lang: str = "en") -> list[tuple[str, str]]:
    """The legend's row for the images of links *figures* (:func:`link_figures`) where a plan draws any (round 20:
    the thin f h₃ g of the linear-arm rod's image was in no legend): its sample as they are drawn, a lightly filled
    triangle where one is, else a thin segment (rounds 23, 24: a triangle beside plans of segments only)."""
    if not figures:
        return []
    kind = "figure" if any(filled for _, _, filled in figures) else "figure_segment"
    return [(kind, legend_words("velocity", kind, lang))]


def _tip_text(plan, v) -> str:
    """The letter of the image at *v*'s tip (the one *v*'s name is of, when several meet there)."""
    sub = v.label.partition("_")[2]
    here = [name for name, z in plan.images.items() if abs(z - complex(v.tip)) <= SAME_MM]
    named = [name for name in here if "".join(plan.points.get(name, (name.rstrip("′").upper(), ""))) == sub]
    name = (named or here or ["?"])[0]
    return image_text(name, plan.points)


def along_note(plan, pairs, lang: str = "en") -> list[str]:
    """The notes on vectors from the pole that lie one along another (:func:`alongside` *pairs*): each direction once,
    in plan order, ``∠(πm′) = 235,6°``, ``∠(πa′) = 235,0°`` (0…360°, counter-clockwise from the x axis; the segment
    as the plan letters it)."""
    seen: list = []
    for pair in pairs:
        for u in pair:
            if all(u is not w for w in seen):
                seen.append(u)

    def angle(u) -> str:
        return localised(f"{math.degrees(cmath.phase(complex(u.tip) - complex(u.tail))) % 360.0:.1f}", lang)

    return [f"∠({pole_text(plan)}{_tip_text(plan, u)}) = {angle(u)}°" for u in seen]


def notes_text(plan, notes, lang: str = "en", letters: dict[str, str] | None = None) -> list[str]:
    """The notes under a plan on vectors too short for an arrow: each the segment it is on the plan and its length
    [mm on the paper], ``a a₄ = 0,45 mm``, ``π e′ = 2,44 mm``, and, when the plan's detail draws it enlarged,
    where and how long it is there (``π e′ = 2,44 mm (detail I: 12,20 mm)``: round 20 measured the plan's length in
    the detail).  *notes* are ``(vector, (detail name, its ratio) or None)``."""
    out = []
    for v, detail in notes:
        where = ""
        if detail:
            name, ratio = detail
            where = f" ({term('detail', lang)} {name}: {localised(f'{v.length * ratio:.2f}', lang)} mm)"
        # a length under the hundredth the note prints is no "0,00 mm": its ends all but coincide
        length = f"= {localised(f'{v.length:.2f}', lang)}" if v.length >= 0.005 else f"< {localised('0.01', lang)}"
        out.append(f"{segment(plan, v, letters)} {length} mm{where}")
    return out


def _caption(sketch: Sketch, plan, vectors, drawn_lines: int, lang: str = "en", legend: bool = True, notes=(), along=(), heading: bool = True,
             letters: dict[str, str] | None = None, narrow: bool = False) -> None:
    """Heading, scale factor, notes on vectors too short to draw and on vectors that lie one along the other, and the legend, below the plan
    (*heading* False: no heading and scale; *narrow*: the notes side by side only as far as the plan itself is wide, a detail beside it)."""
    symbol, units = _UNITS[plan.kind]
    b = sketch.bounds
    x, y = b.xmin, b.ymin - 3.0
    if heading:
        words = term("velocity_plan" if plan.kind == "velocity" else "acceleration_plan", lang)
        sketch.text(complex(x, y), words, size=HEADING_PT, ha="left", va="top", weight="bold", gid="heading", obstacle=False)
        y -= 5.0
        sketch.text(complex(x, y), scale_caption(symbol, fmt_number(plan.scale), units, lang), size=CAPTION_PT, ha="left", va="top", gid="scale", obstacle=False, math=True)
    else:
        y += 4.6
    # notes side by side as far as the plan is wide (a plan with many of them grows by a line, not by a line each):
    # first the segments too short for an arrow, then the directions of vectors that lie one along another
    width = max(b.width, NARROW_NOTES_MM) if narrow else max(b.width, 60.0)
    items = [(text, f"short-{v.label}") for (v, _), text in zip(notes, notes_text(plan, notes, lang, letters))]
    if narrow:
        # beside a detail, a note wider than the plan says where it is drawn on a line of its own ("(выносной элемент I)")
        split = []
        for text, gid in items:
            head, _, where = text.rpartition(" (")
            if head and text_size(text, CAPTION_PT)[0] > width:
                split += [(head, gid), ("(" + where, "where-" + gid[len("short-"):])]
                name, colon, length = where.partition(": ")
                if colon and text_size("(" + where, CAPTION_PT)[0] > width:  # (and its length there on a line of its own)
                    split[-1:] = [("(" + name + ":", "where-" + gid[len("short-"):]), (length, "where-length-" + gid[len("short-"):])]
            else:
                split.append((text, gid))
        items = split
    if along:
        items += [(text, f"along-{along[0][0].label}" + (f"-{k}" if k else "")) for k, text in enumerate(along_note(plan, along, lang))]
    cursor, cursor_along = None, False
    for note, gid in items:
        w = text_size(note, CAPTION_PT)[0]
        if cursor is None or cursor + w > x + width or gid.startswith("where-") or (gid.startswith("along") and not cursor_along):
            y -= 4.6
            cursor = x
        cursor_along = gid.startswith("along")
        sketch.text(complex(cursor, y), note, size=CAPTION_PT, ha="left", va="top", gid=gid, obstacle=False)
        cursor += w + 4.0
    if not legend:
        return
    drawn = kinds_drawn(plan)
    kinds = [k for k in KINDS if k in drawn]
    rows = [(k, legend_words(plan.kind, k, lang)) for k in kinds]
    if drawn_lines:
        rows.append(("construction", legend_words(plan.kind, "construction", lang)))
    rows += figure_entries(link_figures(plan, vectors=vectors), lang)
    row_h = text_size("lp", CAPTION_PT)[1] + 0.9
    y -= 4.6
    for kind, words in rows:
        y -= row_h
        legend_row(sketch, kind, words, x, y, text_gid=f"legend-text-{kind}")
