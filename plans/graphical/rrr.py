"""RRR dyad: two links pinned to known points B and D and to each other at C.

::

            C
           ╱ ╲
     (i)  ╱   ╲  (j)
         ╱     ╲
        B       D         B on a known body (outer_i), D on a known body (outer_j)

Position: C is an intersection of the compass arcs (B, BC) and (D, DC);
branch +1 puts C to the left of the directed line B → D.

Velocity plan::

    v_C = v_B + v_CB      v_CB ⊥ BC      (line ⊥ BC through b)
    v_C = v_D + v_CD      v_CD ⊥ DC      (line ⊥ DC through d)

Acceleration plan::

    a_C = a_B + aⁿ_CB + aᵗ_CB     aⁿ_CB = ω_i²·BC from C towards B; aᵗ_CB ⊥ BC
    a_C = a_D + aⁿ_CD + aᵗ_CD     aⁿ_CD = ω_j²·DC from C towards D; aᵗ_CD ⊥ DC

ω = |v_CB| / BC and ε = |aᵗ_CB| / BC, with the sense read off the plan.
"""

from __future__ import annotations

from ..structure import Group
from . import geometry
from ._dyad import Chain, angle_of, construct_image, known_point, pose_from, unit
from .state import Construction, Motion, Rotation

__all__ = ["position_rrr", "velocity_rrr", "acceleration_rrr"]


def _names(group: Group) -> tuple[str, str, str]:
    return group.outer_i.point, group.inner.point, group.outer_j.point


def position_rrr(ctx: Construction, group: Group) -> list[dict[str, tuple[float, complex]]]:
    """Both assemblies of the dyad, branch +1 first: poses of links i and j."""
    i, j = group.links
    b, c, d = _names(group)
    B, D = known_point(ctx, group.outer_i), known_point(ctx, group.outer_j)
    Bi, Ci = ctx.local(i, b), ctx.local(i, c)
    Cj, Dj = ctx.local(j, c), ctx.local(j, d)
    bc, dc = abs(Ci - Bi), abs(Cj - Dj)
    try:
        left, right = geometry.circle_circle(ctx.drawn(B), ctx.mm(bc), ctx.drawn(D), ctx.mm(dc), ctx.arc_segments)
    except geometry.Miss:
        bd = abs(D - B)
        if bd > bc + dc:
            detail = f"|{b}{d}| = {bd:.6g} m > {b}{c} + {c}{d} = {bc + dc:.6g} m (gap {bd - bc - dc:.3g} m)"
        else:
            detail = f"|{b}{d}| = {bd:.6g} m < |{b}{c} − {c}{d}| = {abs(bc - dc):.6g} m (gap {abs(bc - dc) - bd:.3g} m)"
        raise ctx.assembly_error(group.name, f"joint {c}: {detail}") from None
    out = []
    for drawn in (left, right):
        C = ctx.metres(drawn)
        out.append({
            i: pose_from(B, Bi, angle_of(C - B, Ci - Bi)),
            j: pose_from(D, Dj, angle_of(C - D, Cj - Dj)),
        })
    return out


def velocity_rrr(ctx: Construction, group: Group) -> None:
    """Place c: the line ⊥ BC through b meets the line ⊥ DC through d."""
    plan = ctx.velocity
    i, j = group.links
    b, c, d = _names(group)
    B, C, D = ctx.point(i, b), ctx.point(i, c), ctx.point(j, d)
    pb, pd = plan.images[plan.label(b)], plan.images[plan.label(d)]
    chains = (
        Chain(pb, plan.absolute(b), [], 1j * unit(C - B), f"⊥ {b}{c}", "relative", f"v_{c}{b}"),
        Chain(pd, plan.absolute(d), [], 1j * unit(C - D), f"⊥ {d}{c}", "relative", f"v_{c}{d}"),
    )
    equations = [f"v_{c} = v_{b} + v_{c}{b}  (v_{c}{b} ⊥ {b}{c})", f"v_{c} = v_{d} + v_{c}{d}  (v_{c}{d} ⊥ {d}{c})"]
    pc, (v_cb, v_cd), _ = construct_image(ctx, plan, group.name, equations, chains, plan.label(c), c)
    ctx.v_motion[i] = Motion(B, pb, (pc - pb) / (C - B))
    ctx.v_motion[j] = Motion(D, pd, (pc - pd) / (C - D))
    ctx.omega_from[i] = Rotation(v_cb, B, C)
    ctx.omega_from[j] = Rotation(v_cd, D, C)


def acceleration_rrr(ctx: Construction, group: Group) -> None:
    """Place c′: from b′ the normal aⁿ_CB, then ⊥ BC; from d′ the normal aⁿ_CD, then ⊥ DC."""
    plan = ctx.acceleration
    i, j = group.links
    b, c, d = _names(group)
    B, C, D = ctx.point(i, b), ctx.point(i, c), ctx.point(j, d)
    pb, pd = plan.images[plan.label(b)], plan.images[plan.label(d)]
    w_i, w_j = ctx.omega(i), ctx.omega(j)
    # aⁿ = ω²·l, from the moving point C towards the reference point
    n_cb = w_i * w_i * (B - C) / plan.k0
    n_cd = w_j * w_j * (D - C) / plan.k0
    chains = (
        Chain(pb, plan.absolute(b), [(n_cb, "normal", f"a^n_{c}{b}")], 1j * unit(C - B), f"⊥ {b}{c}", "tangential", f"a^t_{c}{b}"),
        Chain(pd, plan.absolute(d), [(n_cd, "normal", f"a^n_{c}{d}")], 1j * unit(C - D), f"⊥ {d}{c}", "tangential", f"a^t_{c}{d}"),
    )
    equations = [
        f"a_{c} = a_{b} + a^n_{c}{b} + a^t_{c}{b}  (a^n_{c}{b} ∥ {c}{b}, a^t_{c}{b} ⊥ {b}{c})",
        f"a_{c} = a_{d} + a^n_{c}{d} + a^t_{c}{d}  (a^n_{c}{d} ∥ {c}{d}, a^t_{c}{d} ⊥ {d}{c})",
    ]
    pc, (t_cb, t_cd), _ = construct_image(ctx, plan, group.name, equations, chains, plan.label(c), c)
    ctx.a_motion[i] = Motion(B, pb, (pc - pb) / (C - B))
    ctx.a_motion[j] = Motion(D, pd, (pc - pd) / (C - D))
    ctx.epsilon_from[i] = Rotation(t_cb, B, C)
    ctx.epsilon_from[j] = Rotation(t_cd, D, C)
