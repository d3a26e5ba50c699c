"""What the five dyad constructions share: known points, guide lines, coincident images,
and the plan construction "two vector equations, two lines, one intersection".
"""

from __future__ import annotations

import cmath
from dataclasses import dataclass

from ..scene import FRAME, Line, Prismatic
from ..structure import Joint
from . import geometry
from .state import Construction, Sketch, Vec, Sliding, body_label

__all__ = [
    "Chain",
    "known_point",
    "pair_lines",
    "turning_with",
    "coincident",
    "coriolis",
    "drawn_coriolis",
    "construct_image",
    "offset_line",
    "record_sliding",
    "said_line",
    "unit",
    "pose_from",
    "angle_of",
    "name",
    "ruler_lines",
    "sliding_equation",
]


def known_point(ctx: Construction, joint: Joint) -> complex:
    """World position [m] of an outer revolute joint, from the known body it is on."""
    return ctx.point(joint.bodies[1], joint.point)


def pair_lines(ctx: Construction, prismatic: Prismatic, body: str) -> tuple[Line, Line]:
    """(line of *body*, line of the other body) of a prismatic joint."""
    slider = ctx.scene.bodies[prismatic.slider].lines[prismatic.slider_line]
    guide = ctx.scene.bodies[prismatic.guide].lines[prismatic.guide_line]
    return (slider, guide) if prismatic.slider == body else (guide, slider)


def turning_with(own: Line, other_angle_world: float) -> float:
    """Angle φ [rad] of the body carrying *own* when that line lies along a line at the given world angle."""
    return other_angle_world - own.angle


def offset_line(ctx: Construction, own: Line, other: Line, point_local: complex) -> tuple[complex, complex]:
    """The line on which a body's point must lie when its line *own* slides on the known line *other*.

    The point sits at a fixed signed distance h from *own* (its body's
    geometry); the known line shifted by h is its locus.  Returns (a point of
    it [m], unit direction).
    """
    through, direction = ctx.line(other)
    h = geometry.offset(point_local, own.origin, own.direction)
    return through + 1j * direction * h, direction


def coincident(ctx: Construction, plan: Sketch, body: str, point: str, at: complex) -> tuple[complex, Vec | None]:
    """Image of the point of the known *body* that coincides with *point* at *at* [m].

    Placed by the similarity theorem from the body's images; a point of the
    frame is at the pole and gets no label of its own.  Returns (image,
    absolute vector from the pole or None for the frame).
    """
    motion = (ctx.v_motion if plan.kind == "velocity" else ctx.a_motion)[body]
    image = motion.image_of(at)
    if body == FRAME:
        return image, None
    label = plan.label(point, body)
    if label not in plan.images:
        plan.place(label, image)
    return image, plan.absolute(point, body)


def coriolis(ctx: Construction, omega: float, sliding: Sliding) -> complex:
    """The Coriolis acceleration aᵏ = 2 ω_g × v_rel of a sliding point, on the acceleration plan.

    ω_g [rad/s] is the angular velocity of the body carrying the guide (the
    frame of the relative motion), v_rel the sliding velocity measured on
    the velocity plan (``sliding.v_rel``); aᵏ is v_rel turned by +90° in
    the sense of ω_g and 2|ω_g| times as long, zero when the guide does not
    turn.  Returns it in provisional units of the acceleration plan.
    """
    v_rel = sliding.v_rel.delta * ctx.velocity.k0  # [m/s]
    return 2j * omega * v_rel / ctx.acceleration.k0


def drawn_coriolis(drawn: list[Vec]) -> Vec | None:
    """The Coriolis component drawn on a chain whose only known component it is; None if zero (not drawn)."""
    return drawn[0] if drawn else None


@dataclass
class Chain:
    """One vector equation of a construction, from a known image to the unknown one.

    ``start`` is the known image, ``known`` the fully known components
    (complex, provisional plan units, kind, label) drawn from it in order, and
    the unknown component runs along ``direction`` from the end of the last
    one to the unknown image.
    """

    start: complex
    start_vector: Vec | None
    known: list[tuple[complex, str, str]]
    direction: complex
    line_label: str
    found_kind: str
    found_label: str


def construct_image(
    ctx: Construction, plan: Sketch, group: str, equations: list[str], chains: tuple[Chain, Chain], image: str, point: str | None
) -> tuple[complex, list[Vec], list[list[Vec]]]:
    """Draw both chains, intersect their construction lines, and place the image.

    Returns the image (provisional plan units), the two found components
    (in the order of the chains) and the known components drawn for each
    chain (zero ones are not drawn).  The step is recorded on the plan and the
    group's smallest |sin| in ``ctx.sines``.
    """
    known: list[Vec] = []
    ends = []
    drawn: list[list[Vec]] = []
    for chain in chains:
        if chain.start_vector is not None:
            known.append(chain.start_vector)
        tail = chain.start
        drawn.append([])
        for delta, kind, label in chain.known:
            if delta != 0:
                vec = plan.component(tail, tail + delta, kind, label)
                known.append(vec)
                drawn[-1].append(vec)
            tail = tail + delta
        ends.append(tail)
    lines = [(end, chain.direction, chain.line_label) for end, chain in zip(ends, chains)]
    at, sine = plan.intersect(lines[0], lines[1], ctx=ctx, group=group, image=image)
    plan.place(image, at, point)
    found = [plan.component(end, at, chain.found_kind, chain.found_label) for end, chain in zip(ends, chains)]
    plan.step(group, equations, known, lines, found, image, sine)
    ctx.sines[group] = min(ctx.sines.get(group, 1.0), sine)
    # condition number of the intersection, (1 + |cos|)/|sin| of the angle between the two lines
    d1, d2 = chains[0].direction, chains[1].direction
    cosine = abs((d1 * d2.conjugate()).real) / (abs(d1) * abs(d2))
    ctx.conditions[group] = max(ctx.conditions.get(group, 1.0), (1.0 + cosine) / sine)
    return at, found, drawn


def record_sliding(ctx: Construction, prismatic: Prismatic, moving: str, direction: complex) -> Sliding:
    """The readings entry of a prismatic joint whose vectors are drawn for *moving* relative to the other body."""
    entry = ctx.sliding.get(prismatic.name)
    if entry is None:
        entry = Sliding(prismatic, 1 if moving == prismatic.slider else -1, direction)
        ctx.sliding[prismatic.name] = entry
    return entry


def unit(z: complex) -> complex:
    return z / abs(z)


def pose_from(point_world: complex, point_local: complex, phi: float) -> tuple[float, complex]:
    """(φ, origin) of a body at angle φ with its point *point_local* at *point_world*."""
    return phi, point_world - cmath.exp(1j * phi) * point_local


def angle_of(world_segment: complex, local_segment: complex) -> float:
    """The body angle φ that turns the segment *local_segment* (own coordinates) into *world_segment*."""
    return cmath.phase(world_segment) - cmath.phase(local_segment)


def name(point: str, body: str | None = None, frame: str = "0") -> str:
    """A point's name in a vector label, with the body of a coincident point (``E5``; of the frame ``E1`` or ``E0``,
    as *frame*, the scene's number for it)."""
    return point + (body_label(body, frame) if body is not None else "")


def ruler_lines(ctx: Construction, group: str, what: str, p1: complex, d1: complex, p2: complex, d2: complex) -> complex:
    """Intersect two lines of the mechanism drawing (points in m, unit directions); the point in m."""
    from ..errors import SingularPositionError

    try:
        at, _ = geometry.line_line(ctx.drawn(p1), d1, ctx.drawn(p2), d2, ctx.mm(ctx.size))
    except geometry.Parallel as exc:
        raise SingularPositionError(
            f"{group}: {what} are parallel (|sin| = {exc.sine:.2g}) at {ctx.where()}: the group has no definite position"
        ) from None
    return ctx.metres(at)


def said_line(scene, line, prismatic) -> str:
    """The key by which a page names *line* of the sliding pair *prismatic*: a slider block's own line (the implicit
    ``"3.guide"`` of a ``[[slider]]``) by the line the block slides along (``"4.slot"``), parallel to it and named in
    the scene's words (``∥ кулиса``, not the English ``∥ guide``); any other line by its own key."""
    if line.name == "guide" and scene.bodies[line.body].block:
        if prismatic.slider == line.body:
            return f"{prismatic.guide}.{prismatic.guide_line}"
        if prismatic.guide == line.body:
            return f"{prismatic.slider}.{prismatic.slider_line}"
    return line.key


def sliding_equation(symbol: str, moving: str, reference: str, turning: str, guide: str, turns: bool = True, frame: str = "0") -> str:
    """The sliding-point equation as text, ``v_C = v_C4 + v_CC4`` or ``a_C = a_C4 + a^k_CC4 + a^r_CC4``.

    *reference* is the coincident point of body *turning*, which carries the
    relative motion's frame; on the frame it is at rest, and when the body
    does not turn (*turns* False: ω = 0 at this instant) there is no
    Coriolis term.
    """
    rel = f"{moving}{reference}"
    if symbol == "v":
        rest = f"v_{reference} = 0, " if turning == FRAME else ""
        return f"v_{moving} = v_{reference} + v_{rel}  ({rest}v_{rel} ∥ {guide})"
    if turning == FRAME:
        return f"a_{moving} = a_{reference} + a^r_{rel}  (a_{reference} = 0, a^r_{rel} ∥ {guide})"
    if not turns:
        return f"a_{moving} = a_{reference} + a^r_{rel}  (ω{body_label(turning, frame)} = 0 ⇒ a^k_{rel} = 0, a^r_{rel} ∥ {guide})"
    return f"a_{moving} = a_{reference} + a^k_{rel} + a^r_{rel}  (a^k_{rel} = 2 ω{body_label(turning, frame)} × v_{rel}, a^r_{rel} ∥ {guide})"
