"""RPR dyad: a rod i pinned to a known point B slides through a sleeve j pivoting at a known point E.

::

     B ──(i)══════▣══════       i carries the guide line of the inner P,
                  │ (j)         j (the sleeve or block) the sliding line;
                  E             both turn together.

Position: the common line of i and j passes at fixed signed distances h_i
from B and h_j from E (the bodies' geometry; zero when the line passes
through the pivots).  Its direction u is a tangent from E to the compass
circle about B of radius |h_j − h_i|, constructed with the Thales circle on
BE; with no offset, u lies along BE.  Branch +1: u·(E − B) > 0.

Velocity plan (E_i: the point of the rod i coinciding with E; image e_i)::

    v_Ei = v_B + v_EiB          v_EiB ⊥ BE        (line ⊥ BE through b)
    v_Ei = v_Ej + v_EiEj        v_EiEj ∥ u        (line ∥ u through e)

Acceleration plan::

    a_Ei = a_B + aⁿ_EiB + aᵗ_EiB          aⁿ = ω²·BE from E towards B
    a_Ei = a_Ej + aᵏ_EiEj + aʳ_EiEj       aᵏ = 2 ω × v_EiEj, aʳ ∥ u

ω = |v_EiB| / BE, ε = |aᵗ_EiB| / BE, common to i and j.
"""

from __future__ import annotations

import cmath

from ..errors import SingularPositionError
from ..structure import Group
from . import geometry
from ._dyad import (
    Chain,
    construct_image,
    coriolis,
    drawn_coriolis,
    known_point,
    name,
    pair_lines,
    pose_from,
    record_sliding,
    sliding_equation,
    unit,
)
from .state import Construction, Motion, Rotation

__all__ = ["position_rpr", "velocity_rpr", "acceleration_rpr"]

#: An offset below this fraction of |BE| is taken as a line through both pivots.
NO_OFFSET = 1e-12


def _parts(ctx: Construction, group: Group):
    i, j = group.links
    line_i, line_j = pair_lines(ctx, group.inner.prismatic, i)
    return i, j, line_i, line_j, group.outer_i.point, group.outer_j.point


def _too_close(b: str, e: str, be: complex, delta: float) -> str:
    return (
        f"the pivots {b} and {e} are |{b}{e}| = {abs(be):.6g} m apart, less than the offset "
        f"|h| = {abs(delta):.6g} m of the line from them (gap {abs(delta) - abs(be):.3g} m)"
    )


def _along(foot: complex, drawn_b: complex, drawn_e: complex, delta: float, sign: int) -> complex:
    """The line's direction u of branch *sign*, from its foot P (drawing units).

    The line runs through P and E, and P − B = iδ·u (B's perpendicular), so
    u is ±unit(E − P) and also −i·unit(P − B)·sign δ: taken from the longer
    of the tangent PE and the radius BP, the better-drawn direction.  At a
    tangent position (|BE| = |δ|: P = E, a dead centre) only BP has one.
    """
    tangent, radius = drawn_e - foot, foot - drawn_b
    if abs(tangent) >= abs(radius):
        return sign * unit(tangent)
    return (-1j if delta > 0 else 1j) * unit(radius)


def position_rpr(ctx: Construction, group: Group) -> list[dict[str, tuple[float, complex]]]:
    """Both assemblies, branch +1 (u·(E − B) > 0) first."""
    i, j, line_i, line_j, b, e = _parts(ctx, group)
    B, E = known_point(ctx, group.outer_i), known_point(ctx, group.outer_j)
    Bi, Ej = ctx.local(i, b), ctx.local(j, e)
    h_i = geometry.offset(Bi, line_i.origin, line_i.direction)
    h_j = geometry.offset(Ej, line_j.origin, line_j.direction)
    delta = h_j - h_i  # signed distance of E from the line through B, left of u
    be = E - B
    if be == 0:
        raise ctx.assembly_error(group.name, _too_close(b, e, be, delta))
    if abs(delta) <= NO_OFFSET * abs(be):
        directions = [unit(be), -unit(be)]
    else:
        # foot of the perpendicular from B on the line: on the circle (B, |δ|) and on the Thales circle on BE
        # (the two touch, to rounding, when |BE| = |δ|: the line ⊥ BE through E, a dead centre)
        drawn_b = ctx.drawn(B)
        try:
            left, right = geometry.circle_circle(
                drawn_b, ctx.mm(abs(delta)), ctx.drawn((B + E) / 2), ctx.mm(abs(be) / 2), ctx.arc_segments
            )
        except geometry.Miss:
            if abs(be) < abs(delta):
                raise ctx.assembly_error(group.name, _too_close(b, e, be, delta)) from None
            raise ctx.assembly_error(group.name, f"the tangent from {e} to the circle of radius {abs(delta):.6g} m about {b} does not exist") from None
        plus, minus = (left, right) if delta > 0 else (right, left)
        drawn_e = ctx.drawn(E)
        directions = [_along(plus, drawn_b, drawn_e, delta, 1), _along(minus, drawn_b, drawn_e, delta, -1)]
    out = []
    for u in directions:
        angle = cmath.phase(u)
        out.append({i: pose_from(B, Bi, angle - line_i.angle), j: pose_from(E, Ej, angle - line_j.angle)})
    return out


def velocity_rpr(ctx: Construction, group: Group) -> None:
    """Place e_i: the line ⊥ BE through b meets the line ∥ u through e."""
    plan = ctx.velocity
    i, j, line_i, line_j, b, e = _parts(ctx, group)
    B, E = ctx.point(i, b), ctx.point(j, e)
    if B == E:
        raise SingularPositionError(f"{group.name}: the rod's pivot {b} is at the sleeve's pivot {e} at {ctx.where()}")
    _, u = ctx.line(line_i)
    pb, pe = plan.images[plan.label(b)], plan.images[plan.label(e)]
    ei, ej = name(e, i, ctx.scene.frame_number), name(e, j, ctx.scene.frame_number)
    chains = (
        Chain(pb, plan.absolute(b), [], 1j * unit(E - B), f"⊥ {b}{e}", "relative", f"v_{ei}{b}"),
        Chain(pe, plan.absolute(e), [], u, f"∥ {line_i.key}", "relative", f"v_{ei}{ej}"),
    )
    equations = [f"v_{ei} = v_{b} + v_{ei}{b}  (v_{ei}{b} ⊥ {b}{e})", sliding_equation("v", ei, ej, j, line_i.key)]
    image = plan.label(e, i)
    p_ei, (v_rot, v_rel), _ = construct_image(ctx, plan, group.name, equations, chains, image, None)
    q = (p_ei - pb) / (E - B)
    ctx.v_motion[i] = Motion(B, pb, q)
    ctx.v_motion[j] = Motion(E, pe, q)
    ctx.omega_from[i] = Rotation(v_rot, B, E)
    ctx.turns_with[j] = i
    record_sliding(ctx, group.inner.prismatic, i, u).v_rel = v_rel


def acceleration_rpr(ctx: Construction, group: Group) -> None:
    """Place e_i′: b′ + aⁿ then ⊥ BE; e′ + aᵏ then ∥ u."""
    plan = ctx.acceleration
    i, j, line_i, line_j, b, e = _parts(ctx, group)
    B, E = ctx.point(i, b), ctx.point(j, e)
    _, u = ctx.line(line_i)
    pb, pe = plan.images[plan.label(b)], plan.images[plan.label(e)]
    ei, ej = name(e, i, ctx.scene.frame_number), name(e, j, ctx.scene.frame_number)
    sliding = ctx.sliding[group.inner.prismatic.name]
    w = ctx.omega(i)
    normal = w * w * (B - E) / plan.k0
    a_k = coriolis(ctx, w, sliding)  # aᵏ = 2 ω × v_EiEj
    chains = (
        Chain(pb, plan.absolute(b), [(normal, "normal", f"a^n_{ei}{b}")], 1j * unit(E - B), f"⊥ {b}{e}", "tangential", f"a^t_{ei}{b}"),
        Chain(pe, plan.absolute(e), [(a_k, "coriolis", f"a^k_{ei}{ej}")], u, f"∥ {line_i.key}", "relative", f"a^r_{ei}{ej}"),
    )
    equations = [
        f"a_{ei} = a_{b} + a^n_{ei}{b} + a^t_{ei}{b}  (a^n_{ei}{b} ∥ {e}{b}, a^t_{ei}{b} ⊥ {b}{e})",
        sliding_equation("a", ei, ej, j, line_i.key, w != 0),
    ]
    image = plan.label(e, i)
    p_ei, (tangential, a_rel), drawn = construct_image(ctx, plan, group.name, equations, chains, image, None)
    q = (p_ei - pb) / (E - B)
    ctx.a_motion[i] = Motion(B, pb, q)
    ctx.a_motion[j] = Motion(E, pe, q)
    ctx.epsilon_from[i] = Rotation(tangential, B, E)
    sliding.a_rel = a_rel
    sliding.coriolis = drawn_coriolis(drawn[1])
