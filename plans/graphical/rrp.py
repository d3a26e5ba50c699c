"""RRP dyad: a link pinned to a known point B and, at C, to a slider whose line slides on a known line.

::

     B ──(i)── C
               ▣ (j)          j's line slides on the line of the known body K
      ═════════╪══════  K     (the frame, or a moving link: then Coriolis)

Position: C lies on the compass arc (B, BC) and on K's line shifted by the
offset of C from j's own line; branch +1 is the intersection further along
u, the direction of K's line.  j turns with K.

Velocity plan (C_K: the point of K coinciding with C, its image c_K by the
similarity theorem from K's images; at the pole if K is the frame)::

    v_C = v_B + v_CB          v_CB ⊥ BC          (line ⊥ BC through b)
    v_C = v_CK + v_CCK        v_CCK ∥ u          (line ∥ u through c_K)

Acceleration plan::

    a_C = a_B + aⁿ_CB + aᵗ_CB           aⁿ_CB = ω_i²·BC from C towards B
    a_C = a_CK + aᵏ_CCK + aʳ_CCK        aᵏ = 2 ω_K × v_CCK (only if K turns), aʳ ∥ u
"""

from __future__ import annotations

import cmath

from ..structure import Group
from . import geometry
from ._dyad import (
    Chain,
    angle_of,
    coincident,
    construct_image,
    coriolis,
    drawn_coriolis,
    known_point,
    name,
    offset_line,
    pair_lines,
    pose_from,
    record_sliding,
    sliding_equation,
    turning_with,
    unit,
)
from .state import Construction, Motion, Rotation

__all__ = ["position_rrp", "velocity_rrp", "acceleration_rrp"]


def _parts(ctx: Construction, group: Group):
    i, j = group.links
    known = group.outer_j.bodies[1]
    own, other = pair_lines(ctx, group.outer_j.prismatic, j)
    return i, j, known, own, other, group.outer_i.point, group.inner.point


def position_rrp(ctx: Construction, group: Group) -> list[dict[str, tuple[float, complex]]]:
    """Both assemblies, branch +1 (C further along K's line) first."""
    i, j, known, own, other, b, c = _parts(ctx, group)
    B = known_point(ctx, group.outer_i)
    Bi, Ci, Cj = ctx.local(i, b), ctx.local(i, c), ctx.local(j, c)
    bc = abs(Ci - Bi)
    through, u = offset_line(ctx, own, other, Cj)
    phi_j = turning_with(own, cmath.phase(u))
    try:
        further, nearer = geometry.circle_line(ctx.drawn(B), ctx.mm(bc), ctx.drawn(through), u, ctx.arc_segments)
    except geometry.Miss:
        distance = abs(geometry.offset(B, through, u))
        raise ctx.assembly_error(
            group.name,
            f"joint {c}: the arc {b}{c} = {bc:.6g} m about {b} does not reach the line of {c} along {other.key}, "
            f"{distance:.6g} m away (gap {distance - bc:.3g} m)",
        ) from None
    out = []
    for drawn in (further, nearer):
        C = ctx.metres(drawn)
        out.append({i: pose_from(B, Bi, angle_of(C - B, Ci - Bi)), j: pose_from(C, Cj, phi_j)})
    return out


def velocity_rrp(ctx: Construction, group: Group) -> None:
    """Place c: the line ⊥ BC through b meets the line ∥ guide through c_K."""
    plan = ctx.velocity
    i, j, known, own, other, b, c = _parts(ctx, group)
    B, C = ctx.point(i, b), ctx.point(i, c)
    _, u = ctx.line(other)
    pb = plan.images[plan.label(b)]
    ck, ck_vector = coincident(ctx, plan, known, c, C)
    ck_name = name(c, known, ctx.scene.frame_number)
    chains = (
        Chain(pb, plan.absolute(b), [], 1j * unit(C - B), f"⊥ {b}{c}", "relative", f"v_{c}{b}"),
        Chain(ck, ck_vector, [], u, f"∥ {other.key}", "relative", f"v_{c}{ck_name}"),
    )
    equations = [f"v_{c} = v_{b} + v_{c}{b}  (v_{c}{b} ⊥ {b}{c})", sliding_equation("v", c, ck_name, known, other.key)]
    pc, (v_cb, v_rel), _ = construct_image(ctx, plan, group.name, equations, chains, plan.label(c), c)
    ctx.v_motion[i] = Motion(B, pb, (pc - pb) / (C - B))
    ctx.v_motion[j] = Motion(C, pc, ctx.v_motion[known].q)
    ctx.omega_from[i] = Rotation(v_cb, B, C)
    ctx.turns_with[j] = known
    record_sliding(ctx, group.outer_j.prismatic, j, u).v_rel = v_rel


def acceleration_rrp(ctx: Construction, group: Group) -> None:
    """Place c′: b′ + aⁿ_CB then ⊥ BC; c_K′ + aᵏ then ∥ guide."""
    plan = ctx.acceleration
    i, j, known, own, other, b, c = _parts(ctx, group)
    B, C = ctx.point(i, b), ctx.point(i, c)
    _, u = ctx.line(other)
    pb = plan.images[plan.label(b)]
    ck, ck_vector = coincident(ctx, plan, known, c, C)
    ck_name = name(c, known, ctx.scene.frame_number)
    sliding = ctx.sliding[group.outer_j.prismatic.name]
    w_i, w_k = ctx.omega(i), ctx.omega(known)
    n_cb = w_i * w_i * (B - C) / plan.k0
    a_k = coriolis(ctx, w_k, sliding)  # aᵏ = 2 ω_K × v_CCK
    chains = (
        Chain(pb, plan.absolute(b), [(n_cb, "normal", f"a^n_{c}{b}")], 1j * unit(C - B), f"⊥ {b}{c}", "tangential", f"a^t_{c}{b}"),
        Chain(ck, ck_vector, [(a_k, "coriolis", f"a^k_{c}{ck_name}")], u, f"∥ {other.key}", "relative", f"a^r_{c}{ck_name}"),
    )
    equations = [
        f"a_{c} = a_{b} + a^n_{c}{b} + a^t_{c}{b}  (a^n_{c}{b} ∥ {c}{b}, a^t_{c}{b} ⊥ {b}{c})",
        sliding_equation("a", c, ck_name, known, other.key, w_k != 0),
    ]
    pc, (t_cb, a_rel), drawn = construct_image(ctx, plan, group.name, equations, chains, plan.label(c), c)
    ctx.a_motion[i] = Motion(B, pb, (pc - pb) / (C - B))
    ctx.a_motion[j] = Motion(C, pc, ctx.a_motion[known].q)
    ctx.epsilon_from[i] = Rotation(t_cb, B, C)
    sliding.a_rel = a_rel
    sliding.coriolis = drawn_coriolis(drawn[1])
