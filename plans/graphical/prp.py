"""PRP dyad: two sliders, each on its own known guide, pinned to each other at C.

::

       K_i ═══▣(i)            i slides on a line of K_i, j on a line of K_j;
               ╲              i turns with K_i, j with K_j.
                C
               ╱
      K_j ══▣(j)

Position: C lies on K_i's line shifted by C's offset from i's own line, and
on K_j's line shifted likewise; the two ruler lines meet at C (one solution).

Velocity plan (C_Ki, C_Kj: the points of K_i, K_j coinciding with C)::

    v_C = v_CKi + v_CCKi      ∥ u_i      (line ∥ u_i through c_Ki)
    v_C = v_CKj + v_CCKj      ∥ u_j      (line ∥ u_j through c_Kj)

Acceleration plan::

    a_C = a_CKi + aᵏ_CCKi + aʳ_CCKi      aᵏ = 2 ω_Ki × v_CCKi, aʳ ∥ u_i
    a_C = a_CKj + aᵏ_CCKj + aʳ_CCKj
"""

from __future__ import annotations

import cmath

from ..structure import Group
from ._dyad import (
    Chain,
    coincident,
    construct_image,
    coriolis,
    drawn_coriolis,
    name,
    offset_line,
    pair_lines,
    pose_from,
    record_sliding,
    ruler_lines,
    sliding_equation,
    turning_with,
)
from .state import Construction, Motion

__all__ = ["position_prp", "velocity_prp", "acceleration_prp"]


def _sides(ctx: Construction, group: Group):
    """For i and j: (link, known body, own line, known line, prismatic)."""
    out = []
    for link, joint in zip(group.links, (group.outer_i, group.outer_j)):
        own, other = pair_lines(ctx, joint.prismatic, link)
        out.append((link, joint.bodies[1], own, other, joint.prismatic))
    return out


def position_prp(ctx: Construction, group: Group) -> list[dict[str, tuple[float, complex]]]:
    """The one assembly: C where the two shifted guide lines meet."""
    c = group.inner.point
    (i, _, own_i, other_i, _), (j, _, own_j, other_j, _) = _sides(ctx, group)
    p_i, u_i = offset_line(ctx, own_i, other_i, ctx.local(i, c))
    p_j, u_j = offset_line(ctx, own_j, other_j, ctx.local(j, c))
    C = ruler_lines(ctx, group.name, f"the guides {other_i.key} and {other_j.key} of joint {c}", p_i, u_i, p_j, u_j)
    return [{
        i: pose_from(C, ctx.local(i, c), turning_with(own_i, cmath.phase(u_i))),
        j: pose_from(C, ctx.local(j, c), turning_with(own_j, cmath.phase(u_j))),
    }]


def _construct(ctx: Construction, group: Group, plan, motions, accelerations: bool) -> None:
    c = group.inner.point
    C = ctx.point(group.links[0], c)
    chains, equations, slidings = [], [], []
    for link, known, _, other, prismatic in _sides(ctx, group):
        _, u = ctx.line(other)
        ck, ck_vector = coincident(ctx, plan, known, c, C)
        ck_name = name(c, known, ctx.scene.frame_number)
        if accelerations:
            sliding = ctx.sliding[prismatic.name]
            w = ctx.omega(known)
            a_k = coriolis(ctx, w, sliding)  # aᵏ = 2 ω_K × v_rel
            chains.append(Chain(ck, ck_vector, [(a_k, "coriolis", f"a^k_{c}{ck_name}")], u, f"∥ {other.key}", "relative", f"a^r_{c}{ck_name}"))
            equations.append(sliding_equation("a", c, ck_name, known, other.key, w != 0))
        else:
            chains.append(Chain(ck, ck_vector, [], u, f"∥ {other.key}", "relative", f"v_{c}{ck_name}"))
            equations.append(sliding_equation("v", c, ck_name, known, other.key))
            sliding = record_sliding(ctx, prismatic, link, u)
        slidings.append((link, known, sliding))
    pc, found, drawn = construct_image(ctx, plan, group.name, equations, tuple(chains), plan.label(c), c)
    for (link, known, sliding), vec, extra in zip(slidings, found, drawn):
        motions[link] = Motion(C, pc, motions[known].q)
        if accelerations:
            sliding.a_rel = vec
            sliding.coriolis = drawn_coriolis(extra)
        else:
            sliding.v_rel = vec
            ctx.turns_with[link] = known


def velocity_prp(ctx: Construction, group: Group) -> None:
    """Place c: the lines ∥ u_i through c_Ki and ∥ u_j through c_Kj meet."""
    _construct(ctx, group, ctx.velocity, ctx.v_motion, False)


def acceleration_prp(ctx: Construction, group: Group) -> None:
    """Place c′: c_Ki′ + aᵏ then ∥ u_i; c_Kj′ + aᵏ then ∥ u_j."""
    _construct(ctx, group, ctx.acceleration, ctx.a_motion, True)
