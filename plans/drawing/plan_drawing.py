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

import math

from .._text import SUBSCRIPT
from ._canvas import Sketch, fmt_number, sketch_on, text_size, unit
from .labels import place_label
from .style import (
    CAPTION_PT,
    CONSTRUCTION_STYLE,
    HEADING_PT,
    INK,
    LABEL_PT,
    VECTOR_STYLE,
)
from ..graphical.plan import KINDS
from ..i18n import term

__all__ = ["draw_plan", "draw_plan_into", "draw_velocity_plan", "draw_acceleration_plan", "vectors_drawn", "legend_words", "ZERO_MM"]

#: A vector shorter than this [mm] is not drawn (it has no direction to show).
ZERO_MM = 1e-6
#: Images closer than this [mm] share one label ("p, o, d").
SAME_MM = 1e-3
#: How far a construction line runs past the intersection and behind its start [mm].
PAST_MM = 7.0
BEHIND_MM = 3.0

_UNITS = {"velocity": ("k_v", "(m/s)/mm"), "acceleration": ("k_a", "(m/s²)/mm")}


def vectors_drawn(plan) -> list:
    """The plan's vectors that a drawing shows.

    Zero-length vectors are left out, and so is a component that coincides
    with an absolute vector (the normal acceleration of a crank pin turning at
    constant speed *is* its acceleration): drawn under it, it could not be
    seen, yet it would add a legend entry.
    """
    vectors = [v for v in plan.vectors if abs(v.tip - v.tail) > ZERO_MM]
    absolute = [v for v in vectors if v.kind == "absolute"]
    return [
        v
        for v in vectors
        if v.kind == "absolute"
        or not any(abs(v.tail - w.tail) <= SAME_MM and abs(v.tip - w.tip) <= SAME_MM for w in absolute)
    ]


def draw_plan(plan, ax=None, *, lang: str = "en", legend: bool = True) -> list:
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

    Returns
    -------
    list of matplotlib.artist.Artist
        Shafts are Line2D, heads Polygons whose first vertex is the tip.
    """
    if plan.kind not in _UNITS:
        raise ValueError(f"a plan is 'velocity' or 'acceleration', got {plan.kind!r}")
    tag = "vel" if plan.kind == "velocity" else "acc"
    return sketch_on(ax, tag, lambda sketch: draw_plan_into(sketch, plan, lang=lang, legend=legend))


def draw_velocity_plan(plan, ax=None, *, lang: str = "en") -> list:
    """:func:`draw_plan` for a velocity plan."""
    return draw_plan(plan, ax, lang=lang)


def draw_acceleration_plan(plan, ax=None, *, lang: str = "en") -> list:
    """:func:`draw_plan` for an acceleration plan."""
    return draw_plan(plan, ax, lang=lang)


def image_text(name: str) -> str:
    """An image's label as the textbook prints it: the link number of a coincident point as a subscript.

    ``"e5"`` → ``"e₅"``, ``"a4′"`` → ``"a₄′"``; names without digits are unchanged.
    """
    letters = name.rstrip("0123456789′")
    return letters + name[len(letters):].translate(SUBSCRIPT)


def legend_row(sketch, kind: str, words: str, x: float, y: float, *, text_gid: str) -> None:
    """One legend entry at (x, y) [mm]: a 9 mm sample of the *kind*'s line or arrow, then its words."""
    a, c = complex(x, y), complex(x + 9.0, y)
    if kind == "construction":
        color, lw, dashes = CONSTRUCTION_STYLE
        sketch.line([a, c], color=color, lw=lw, dashes=dashes, gid=f"legend-{kind}", obstacle=False)
    else:
        color, lw, dashes, _ = VECTOR_STYLE[kind]
        sketch.arrow(a, c, color=color, lw=lw, dashes=dashes, head=2.4, gid=f"legend-{kind}")
    sketch.text(complex(x + 11.0, y), words, size=CAPTION_PT, ha="left", va="center", gid=text_gid, obstacle=False)


def _check(z: complex, what: str) -> complex:
    z = complex(z)
    if not (math.isfinite(z.real) and math.isfinite(z.imag)):
        raise ValueError(f"{what} is not finite: {z!r}")
    return z


def draw_plan_into(sketch: Sketch, plan, lang: str = "en", legend: bool = True, caption: bool = True) -> None:
    """Draw *plan* into *sketch* (one data unit = 1 mm): what :func:`draw_plan` does on a page's own Sketch.

    *caption* False leaves out the heading, scale and legend; *legend* False only the legend.
    """
    images = {name: _check(z, f"image {name}") for name, z in plan.images.items()}
    vectors = vectors_drawn(plan)
    for v in vectors:
        _check(v.tail, v.label)
        _check(v.tip, v.label)

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

    # components under the absolute vectors, in a fixed order of kinds
    for kind in ("normal", "tangential", "coriolis", "relative", "absolute"):
        for v in vectors:
            if v.kind != kind:
                continue
            color, lw, dashes, head = VECTOR_STYLE[kind]
            z = 3.0 if kind == "absolute" else 2.5
            sketch.arrow(complex(v.tail), complex(v.tip), color=color, lw=lw, dashes=dashes, head=head, gid=f"{kind}-{v.label}", zorder=z)

    # the pole and the image points
    sketch.circle(0j, 0.55, fc=INK, lw=0, gid="pole", zorder=4.0)
    for name, z in images.items():
        if abs(z) > SAME_MM:
            sketch.circle(z, 0.4, fc=INK, lw=0, gid=f"dot-{name}", zorder=4.0, obstacle=False)

    # labels: the pole first, then each group of coincident images
    groups: list[tuple[complex, list[str]]] = [(0j, [plan.pole])]
    for name, z in images.items():
        for at, names in groups:
            if abs(at - z) <= SAME_MM:
                names.append(name)
                break
        else:
            groups.append((z, [name]))
    for at, names in groups:
        away = 0j
        for v in vectors:
            for end, other in ((v.tail, v.tip), (v.tip, v.tail)):
                if abs(end - at) <= SAME_MM:
                    away -= unit(other - end)
        pieces = [
            (image_text(n), "pole-label" if (k == 0 and at == 0j and n == plan.pole) else f"image-{n}")
            for k, n in enumerate(names)
        ]
        place_label(sketch, at, pieces, size=LABEL_PT, prefer=away if abs(away) > 1e-9 else None)

    if caption:
        _caption(sketch, plan, vectors, drawn_lines, lang, legend)


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
    return term(LEGEND_TERMS[plan_kind][kind], lang)


def _caption(sketch: Sketch, plan, vectors, drawn_lines: int, lang: str = "en", legend: bool = True) -> None:
    """Heading, scale factor and legend, below the plan where they cover nothing."""
    symbol, units = _UNITS[plan.kind]
    heading = term("velocity_plan" if plan.kind == "velocity" else "acceleration_plan", lang)
    b = sketch.bounds
    x, y = b.xmin, b.ymin - 3.0
    sketch.text(complex(x, y), heading, size=HEADING_PT, ha="left", va="top", weight="bold", gid="heading", obstacle=False)
    y -= 5.0
    sketch.text(complex(x, y), f"{symbol} = {fmt_number(plan.scale)} {units}", size=CAPTION_PT, ha="left", va="top", gid="scale", obstacle=False)
    if not legend:
        return
    kinds = [k for k in KINDS if any(v.kind == k for v in vectors)]
    rows = [(k, legend_words(plan.kind, k, lang)) for k in kinds]
    if drawn_lines:
        rows.append(("construction", legend_words(plan.kind, "construction", lang)))
    row_h = text_size("lp", CAPTION_PT)[1] + 0.9
    y -= 4.6
    for kind, words in rows:
        y -= row_h
        legend_row(sketch, kind, words, x, y, text_gid=f"legend-text-{kind}")
