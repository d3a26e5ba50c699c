"""The kinetostatic drawings as SVG blocks of known physical size, for the force pages set by Typst.

Each function draws one thing with matplotlib, one data unit one millimetre
of paper, without a word of caption (the page sets the headings, scales,
readings and legends' words): a typesetter places the block at its width, so
the μ_F, k_l and k_v the page states hold on the printed paper.

* :func:`free_bodies_svg` — the groups and the driver cut apart, with their
  loads and reactions, at k_l (the arrows of one length, not to scale);
* :func:`force_plan_svg` — one force plan at its μ_F (the plans are
  constructed at it by the caller: drawing never constructs);
* :func:`lever_svg` — Joukowski's lever at its velocity plan's k_v;
* :func:`force_key_svg` — the sample arrow (or line) of a legend's row.
"""

from __future__ import annotations

from .force_drawing import draw_force_plan_into, draw_free_bodies_into, draw_lever_into
from .style import CONSTRUCTION_STYLE, FORCE_HOLLOW, FORCE_STYLE
from .svgblocks import SvgBlock, sketched

__all__ = ["free_bodies_svg", "force_plan_svg", "lever_svg", "force_key_svg", "KEY_KINDS"]

#: the legend's rows a page may ask for: a kind of force (``FORCE_STYLE``), ``"construction"`` (a closing
#: line of a force plan) and ``"arm"`` (an arm on the lever, from the pole)
KEY_KINDS = tuple(FORCE_STYLE) + ("construction", "arm")


def free_bodies_svg(forces, k_l: float, lang: str = "en", per_row: int | None = None, names: dict | None = None,
                    columns: tuple[int, ...] | None = None, equations=None) -> SvgBlock:
    """The free bodies of *forces* (:class:`plans.forces.force_plans.ForcePlans`) at *k_l* [m/mm], *per_row* to a row
    (or in *columns*, how many each holds); *names*: group -> the words written over its body; *equations*: the
    plans' equations as the page writes them, whose arms h_k are drawn on the bodies."""
    return sketched("fbody", lambda s: draw_free_bodies_into(s, forces, lang=lang, caption=False, k_l=k_l, per_row=per_row, names=names,
                                                           columns=columns, equations=equations), lang)


def force_plan_svg(plan, lang: str = "en") -> SvgBlock:
    """One force plan (:class:`plans.forces.force_plans.ForcePlan`), drawn at the μ_F it was constructed at."""
    return sketched("fplan", lambda s: draw_force_plan_into(s, plan, lang=lang, legend=False, caption=False), lang)


def lever_svg(lever, lang: str = "en") -> SvgBlock:
    """Joukowski's lever (:class:`plans.forces.lever.JoukowskiLever`), at the k_v it was constructed at (its velocity
    plan's, or one of its own: :func:`plans.forces.lever.joukowski_lever`)."""
    return sketched("lever", lambda s: draw_lever_into(s, lever, lang=lang, caption=False), lang)


def force_key_svg(kind: str) -> SvgBlock:
    """A legend row's sample, 9 mm long: the arrow of a force of *kind*, a construction line or a lever's arm."""
    def draw(sketch):
        if kind in FORCE_STYLE:
            color, lw, dashes, _ = FORCE_STYLE[kind]
            sketch.arrow(0j, 9.0 + 0j, color=color, lw=lw, dashes=dashes, head=2.4, gid=f"key-{kind}", hollow=kind in FORCE_HOLLOW)
        elif kind in ("construction", "arm"):
            color, lw, dashes = CONSTRUCTION_STYLE
            sketch.line([0j, 9.0 + 0j], color=color, lw=lw, dashes=dashes, gid=f"key-{kind}")
            sketch.bounds.add(0.0, -1.0)
            sketch.bounds.add(0.0, 1.0)
        else:
            raise ValueError(f"no legend sample for {kind!r}: one of {', '.join(KEY_KINDS)}")

    return sketched("fkey", draw, "en", margin=0.6)
