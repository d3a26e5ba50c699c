"""The equations a force plan is drawn from, as a course writes them beside the plan (domain.md §11).

For each group: the moment equation of a link about the group's inner joint that gives the tangential
component Rᵗ of an outer reaction first,

    ΣM_B(3) = 0:  −Rᵗ_23·l_AB + G_3·h_1 − F_Φ3·h_2 + M_Φ3 = 0   ⇒   Rᵗ_23 = Σ/l_AB,

each term a load's magnitude times its arm about the joint [m] (or a couple), signed counter-clockwise
positive, the Rᵗ term with the sign its moment has (so that Rᵗ is its magnitude); then the vector equation
of the polygon, its terms in drawing order with what is known of each: ``"full"`` (magnitude and direction:
a load, a reaction carried from a plan before, an Rᵗ found from its moment equation), ``"direction"`` (a
closing line's direction: Rⁿ along its link, a prismatic pair's normal force ⊥ the guide) or ``"none"`` (the
sought vector); and the equation of one link that gives the inner reaction.

Read from :class:`plans.forces.force_plans.ForcePlans` (the loads and reactions the plans were constructed
with) and the graphical positions: nothing is solved here but the one-unknown moment equations written out.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from ..graphical.scales import measure

__all__ = ["MomentTerm", "TangentialEquation", "PlanEquations", "plan_equations"]

#: a vector shorter than this on the plan [N] and with a zero value is left out of an equation (a resistance off its stroke)
_ZERO = 1e-9


@dataclass(frozen=True)
class MomentTerm:
    """One term of a moment equation about a joint: a force's magnitude [N] times its arm [m], or a couple [N·m].

    ``moment`` is the signed moment [N·m], counter-clockwise positive; ``arm`` None for a couple.  A force's
    ``number`` is k of its arm's name h_k, numbered in order over the moment equations of the plans of a position
    (the free bodies drawn together name each arm once); ``through`` [m] and ``direction`` (unit) its line of action.
    """

    label: str
    size: float
    arm: float | None
    moment: float
    number: int | None = None
    through: complex | None = None
    direction: complex | None = None


@dataclass(frozen=True)
class TangentialEquation:
    """ΣM_about(link) = 0, which gives the tangential component *label* (``"R^t_23"``) of the reaction acting at
    *joint* on *link*: its arm *length* [m] = l(joint, about), *sign* the sign of its moment (±1), *terms* the
    other loads on the link, *value* = |Σ moments of the terms| / length [N]."""

    label: str
    link: str
    joint: str
    about: str
    length: float
    sign: int
    terms: tuple[MomentTerm, ...]
    value: float


@dataclass(frozen=True)
class PlanEquations:
    """The equations of one force plan: its moment equations (Rᵗ first), the polygon's vector equation as
    (label, known) in drawing order (known: ``"full"``, ``"direction"`` or ``"none"``), and the inner reaction's
    equation over one link as (label, known) (empty where the plan finds none)."""

    group: str
    moments: tuple[TangentialEquation, ...]
    polygon: tuple[tuple[str, str], ...]
    inner: tuple[tuple[str, str], ...]
    #: the driver's ΣM_O(crank) = 0 that gives M_b: the pivot, the crank, the loads' terms (empty for a group or
    #: a linear driver); M_b = −Σ of their moments
    pivot: str | None = None
    crank: str | None = None
    balancing: tuple[MomentTerm, ...] = ()


def _cross(a: complex, b: complex) -> float:
    return (a.conjugate() * b).imag


def _chain(plan) -> list:
    """The polygon's vectors: head to tail from the plan's start until it closes (the rest are components' sums and
    the inner reaction)."""
    out, at = [], 0j
    scale = max((abs(v.tip) for v in plan.vectors), default=1.0) or 1.0
    for v in plan.vectors:
        if abs(v.tail - at) > 1e-6 * scale:
            break
        out.append(v)
        at = v.tip
    return out


def _inner_joint(scene, links) -> str | None:
    if len(links) < 2:
        return None
    shared = [n for n in scene.bodies[links[0]].points if n in scene.bodies[links[1]].points]
    return shared[0] if shared else None


def _measured(plans, metres: float) -> float:
    """A length on the mechanism drawing as the construction measures it [m]: to its drafting precision at k_l."""
    k_l = plans.graphical.scales["k_l"]
    return measure(metres / k_l, plans.precision) * k_l


def _terms(plans, body: str, centre: complex, skip) -> tuple[MomentTerm, ...]:
    """The moments about *centre* [m] of everything on *body* but the forces in *skip*, a reaction in the joint
    itself (no arm) and the balancing couple; each arm measured on the drawing (:func:`_measured`)."""
    forces, couples = plans.on(body)
    terms = []
    for f in forces:
        if f.label in skip or abs(f.force) <= _ZERO or abs(f.at - centre) <= 1e-12:
            continue
        arm = _cross(f.at - centre, f.force / abs(f.force))
        h = _measured(plans, abs(arm))
        terms.append(MomentTerm(f.label, abs(f.force), h, math.copysign(h, arm) * abs(f.force), None, f.at, f.force / abs(f.force)))
    for c in couples:
        if c.moment and c.kind != "balancing":
            terms.append(MomentTerm(c.label, abs(c.moment), None, c.moment))
    return tuple(terms)


def _moment_equation(plans, plan, v) -> TangentialEquation | None:
    g = plans.graphical
    reaction = plans.reactions.get(v.label.replace("^t", ""))
    about = _inner_joint(g.scene, plan.links)
    if reaction is None or about is None:
        return None
    centre = g.positions[about]
    terms = _terms(plans, reaction.on, centre, skip=(reaction.label,))
    total = sum(t.moment for t in terms)
    length = _measured(plans, abs(reaction.at - centre))
    joint = reaction.joint
    return TangentialEquation(v.label, reaction.on, joint, about, length, -1 if total > 0 else 1, tuple(terms), abs(total) / length)


def plan_equations(plans) -> list[PlanEquations]:
    """The equations of every plan of *plans* (:class:`plans.forces.force_plans.ForcePlans`), in their order."""
    out = []
    g = plans.graphical
    count = 0  # the arms h_k named so far
    for plan in plans.plans:
        chain = _chain(plan)
        directions = [complex(line.direction) for line in plan.lines]
        moments = tuple(e for v in chain if v.kind == "tangential" for e in [_moment_equation(plans, plan, v)] if e is not None)
        polygon = []
        for v in chain:
            if v.value <= _ZERO and v.length <= _ZERO and v.kind not in ("normal", "tangential", "reaction"):
                continue
            if v.kind == "normal":
                known = "direction"
            elif v.label in plan.found:
                d = v.tip - v.tail
                along = abs(d) > 0 and any(abs(_cross(u, d)) <= 1e-6 * abs(u) * abs(d) for u in directions if abs(u))
                known = "direction" if along else "none"
            else:
                known = "full"
            polygon.append((v.label, known))
        inner: list[tuple[str, str]] = []
        rest = [v for v in plan.vectors[len(chain):] if v.kind == "reaction" and v.label in plan.found]
        components = {v.label.replace("^t", "").replace("^n", "") for v in chain if v.kind in ("normal", "tangential")}
        for v in rest:
            if v.label in components:
                continue  # Rᵗ + Rⁿ read as one reaction
            reaction = plans.reactions.get(v.label)
            if reaction is None:
                continue
            on_link = {f.label for f in plans.on(reaction.on)[0]}
            # the link's loads and the reactions on it found on this plan before: all known now
            inner = [(v.label, "none")] + [(label, "full") for label, known in polygon
                                           if label.replace("^t", "").replace("^n", "") in on_link and label != v.label]
            break
        pivot, crank, balancing = None, None, ()
        if plan.group == "driver" and plans.balancing_moment is not None:
            pivot, crank = g.scene.driver.pivot, g.scene.driver.link
            balancing = _terms(plans, crank, g.positions[pivot], skip=())
        moments, balancing, count = _numbered(moments, balancing, count)
        out.append(PlanEquations(plan.group, moments, tuple(polygon), tuple(inner), pivot, crank, balancing))
    return out


def _numbered(moments, balancing, count: int):
    """The equations of one plan with their forces' arms numbered h_{count+1}, h_{count+2}, … in order (a couple has
    no arm), and the last number given: numbered on over the plans of a position, one name for one arm on a page
    that draws the free bodies of all of them together."""

    def number(terms):
        nonlocal count
        out = []
        for t in terms:
            if t.arm is not None:
                count += 1
                t = replace(t, number=count)
            out.append(t)
        return tuple(out)

    moments = tuple(replace(m, terms=number(m.terms)) for m in moments)
    return moments, number(balancing), count
