"""RPP dyad: a link i pinned to a known point B slides in j, which slides on a known guide.

::

     B ●(i)                   i pinned at B (a block on a crank pin, say)
       ║  j's inner line      i's line slides on j's inner line,
     ══╬══════ j ══           j's outer line slides on the line of K;
       ║                      i, j and K all turn together (Scotch yoke: K = frame)
     ══════════ K ══

Position: i's angle follows from K's through both prismatic joints, so its
line is known through B; j's two lines then lie on i's line and on K's
line, and the point where j's lines cross is where those two lines meet
(one solution).

Velocity plan (B_j: the point of j coinciding with B; B_K likewise)::

    v_Bj = v_B + v_BjB         ∥ i's line       (line through b)
    v_Bj = v_BK + v_BjBK       ∥ K's line       (line through b_K)

Acceleration plan::

    a_Bj = a_B + aᵏ_BjB + aʳ_BjB            aᵏ = 2 ω × v_BjB
    a_Bj = a_BK + aᵏ_BjBK + aʳ_BjBK         aᵏ = 2 ω_K × v_BjBK
"""

from __future__ import annotations

import cmath

from ..errors import SingularPositionError
from ..structure import Group
from . import geometry
from ._dyad import (
    Chain,
    coincident,
    construct_image,
    coriolis,
    drawn_coriolis,
    known_point,
    name,
    pair_lines,
    pose_from,
    record_sliding,
    ruler_lines,
    said_line,
    sliding_equation,
    turning_with,
)
from .state import Construction, Motion

__all__ = ["position_rpp", "velocity_rpp", "acceleration_rpp"]


def _parts(ctx: Construction, group: Group):
    i, j = group.links
    known = group.outer_j.bodies[1]
    inner_i, inner_j = pair_lines(ctx, group.inner.prismatic, i)
    outer_j, outer_k = pair_lines(ctx, group.outer_j.prismatic, j)
    return i, j, known, inner_i, inner_j, outer_j, outer_k, group.outer_i.point


def position_rpp(ctx: Construction, group: Group) -> list[dict[str, tuple[float, complex]]]:
    """The one assembly: j placed where its two lines cross."""
    i, j, known, inner_i, inner_j, outer_j, outer_k, b = _parts(ctx, group)
    B = known_point(ctx, group.outer_i)
    k_point, u_k = ctx.line(outer_k)
    phi_j = turning_with(outer_j, cmath.phase(u_k))
    phi_i = phi_j + inner_j.angle - inner_i.angle
    pose_i = pose_from(B, ctx.local(i, b), phi_i)
    i_point = pose_i[1] + cmath.exp(1j * phi_i) * inner_i.origin  # i's line on the mechanism
    u_i = cmath.exp(1j * (phi_i + inner_i.angle))
    # where j's own two lines cross, in j's coordinates (a drawing of link j)
    try:
        cross_local, _ = geometry.line_line(inner_j.origin, inner_j.direction, outer_j.origin, outer_j.direction, max(abs(inner_j.origin), abs(outer_j.origin), ctx.size))
    except geometry.Parallel:
        raise SingularPositionError(f"{group.name}: the two lines {inner_j.key} and {outer_j.key} of link {j} are parallel: its position along them is not defined") from None
    cross = ruler_lines(ctx, group.name, f"the lines {inner_i.key} and {outer_k.key}", i_point, u_i, k_point, u_k)
    return [{i: pose_i, j: pose_from(cross, cross_local, phi_j)}]


def _construct(ctx: Construction, group: Group, plan, motions, accelerations: bool) -> None:
    i, j, known, inner_i, inner_j, outer_j, outer_k, b = _parts(ctx, group)
    B = ctx.point(i, b)
    pb = plan.images[plan.label(b)]
    bk, bk_vector = coincident(ctx, plan, known, b, B)
    bj, bk_name = name(b, j, ctx.scene.frame_number), name(b, known, ctx.scene.frame_number)
    _, u_i = ctx.line(inner_i)
    _, u_k = ctx.line(outer_k)
    inner, outer = group.inner.prismatic, group.outer_j.prismatic
    said_i, said_k = said_line(ctx.scene, inner_i, inner), said_line(ctx.scene, outer_k, outer)  # (the pages' words)
    if accelerations:
        w = ctx.omega(known)  # i, j and K turn together
        s_in, s_out = ctx.sliding[inner.name], ctx.sliding[outer.name]
        cor_in, cor_out = coriolis(ctx, w, s_in), coriolis(ctx, w, s_out)  # aᵏ = 2 ω × v_rel
        chains = (
            Chain(pb, plan.absolute(b), [(cor_in, "coriolis", f"a^k_{bj}{b}")], u_i, f"∥ {said_i}", "relative", f"a^r_{bj}{b}"),
            Chain(bk, bk_vector, [(cor_out, "coriolis", f"a^k_{bj}{bk_name}")], u_k, f"∥ {said_k}", "relative", f"a^r_{bj}{bk_name}"),
        )
        equations = [
            sliding_equation("a", bj, b, i, said_i, w != 0),
            sliding_equation("a", bj, bk_name, known, said_k, w != 0),
        ]
    else:
        chains = (
            Chain(pb, plan.absolute(b), [], u_i, f"∥ {said_i}", "relative", f"v_{bj}{b}"),
            Chain(bk, bk_vector, [], u_k, f"∥ {said_k}", "relative", f"v_{bj}{bk_name}"),
        )
        equations = [sliding_equation("v", bj, b, i, said_i), sliding_equation("v", bj, bk_name, known, said_k)]
    p_bj, (rel_in, rel_out), drawn = construct_image(ctx, plan, group.name, equations, chains, plan.label(b, j), None)
    q = motions[known].q
    motions[i] = Motion(B, pb, q)
    motions[j] = Motion(B, p_bj, q)
    if accelerations:
        s_in.a_rel, s_in.coriolis = rel_in, drawn_coriolis(drawn[0])
        s_out.a_rel, s_out.coriolis = rel_out, drawn_coriolis(drawn[1])
    else:
        ctx.turns_with[i] = known
        ctx.turns_with[j] = known
        record_sliding(ctx, inner, j, u_i).v_rel = rel_in
        record_sliding(ctx, outer, j, u_k).v_rel = rel_out


def velocity_rpp(ctx: Construction, group: Group) -> None:
    """Place b_j: the line ∥ i's line through b meets the line ∥ K's line through b_K."""
    _construct(ctx, group, ctx.velocity, ctx.v_motion, False)


def acceleration_rpp(ctx: Construction, group: Group) -> None:
    """Place b_j′: b′ + aᵏ then ∥ i's line; b_K′ + aᵏ then ∥ K's line."""
    _construct(ctx, group, ctx.acceleration, ctx.a_motion, True)
