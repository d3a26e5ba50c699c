"""Where every body is at the instant: the position step of the instant-centre method.

The instant centres are drawn on the mechanism at its position, so the
method needs the poses of the bodies.  They are found here, by the method's
own geometry (a circle through a pin, a line a slider block runs on), group
by group in the structural order, with nothing taken from
:mod:`plans.analytic` or :mod:`plans.graphical`.  The assembly branch
follows the convention in the README ("Assembly branches"), which both other
methods follow too.

A pose is ``(φ, origin)``: a body's point with own coordinates ``z`` is at
``origin + exp(iφ)·z`` [m]; φ [rad] counter-clockwise from +x.
"""

from __future__ import annotations

import cmath
import math

from ..errors import AssemblyError, SingularPositionError
from ..limits import position_text
from ..scene import FRAME, Crank, Prismatic, Scene
from ..structure import Group, Joint, Structure

__all__ = ["Pose", "place_bodies", "point_at"]

#: (φ [rad], origin [m] as a complex number)
Pose = tuple[float, complex]


def point_at(pose: Pose, local: complex) -> complex:
    """The global position [m] of a body's point given in its own coordinates."""
    phi, origin = pose
    return origin + cmath.exp(1j * phi) * local


def _line_of(scene: Scene, poses: dict[str, Pose], body: str, line: str) -> tuple[complex, complex]:
    """A body's line at its pose: (a point of it [m], unit direction)."""
    spec = scene.bodies[body].lines[line]
    phi = poses[body][0]
    return point_at(poses[body], spec.origin), cmath.exp(1j * (phi + spec.angle))


def _own_line(prismatic: Prismatic, body: str) -> str:
    return prismatic.slider_line if body == prismatic.slider else prismatic.guide_line


def _turned_with(scene: Scene, poses: dict[str, Pose], prismatic: Prismatic, body: str) -> float:
    """φ of *body* from the prismatic joint with a body already placed: the two lines point the same way."""
    other = prismatic.guide if body == prismatic.slider else prismatic.slider
    alpha_other = scene.bodies[other].lines[_own_line(prismatic, other)].angle
    alpha_own = scene.bodies[body].lines[_own_line(prismatic, body)].angle
    return poses[other][0] + alpha_other - alpha_own


def _track(scene: Scene, poses: dict[str, Pose], prismatic: Prismatic, body: str, phi: float, local: complex):
    """The line a point of *body* (own coordinates *local*) runs on, when *body* slides with angle φ.

    The body's line lies on the placed partner's line, so the point lies on
    that line shifted by exp(iφ)·(local − Q), Q the own line's through point.
    Returns (a point of the track [m], unit direction).
    """
    other = prismatic.guide if body == prismatic.slider else prismatic.slider
    at, u = _line_of(scene, poses, other, _own_line(prismatic, other))
    own = scene.bodies[body].lines[_own_line(prismatic, body)]
    return at + cmath.exp(1j * phi) * (local - own.origin), u


def _local(scene: Scene, body: str, point: str) -> complex:
    return scene.bodies[body].points[point]


def _known_point(scene: Scene, poses: dict[str, Pose], joint: Joint) -> complex:
    """The global position of an outer revolute joint, from the placed body."""
    return point_at(poses[joint.bodies[1]], _local(scene, joint.bodies[1], joint.point))


def _pin_pose(scene: Scene, body: str, a: str, za: complex, b: str, zb: complex) -> Pose:
    """The pose that puts the body's points a, b at za, zb (a rigid body through two of its points)."""
    la, lb = _local(scene, body, a), _local(scene, body, b)
    phi = cmath.phase(zb - za) - cmath.phase(lb - la)
    return phi, za - cmath.exp(1j * phi) * la


def _circle_circle(group: Group, b: complex, r1: float, d: complex, r2: float) -> list[complex]:
    """RRR: the two intersections of circles (B, r1), (D, r2); branch +1 (left of B→D) first."""
    span = abs(d - b)
    if span == 0:
        raise AssemblyError(f"{group.name}: joints {group.outer_i.point} and {group.outer_j.point} coincide; the group has no definite position")
    along = (r1 * r1 - r2 * r2 + span * span) / (2 * span)
    h2 = r1 * r1 - along * along
    if h2 < 0:
        gap = max(span - (r1 + r2), abs(r1 - r2) - span)
        raise AssemblyError(
            f"{group.name}: joint {group.inner.point} cannot assemble: |{group.outer_i.point}{group.outer_j.point}| = "
            f"{span:.6g} m with links {r1:.6g} m and {r2:.6g} m (gap {gap:.3g} m)"
        )
    h = math.sqrt(h2)
    u = (d - b) / span
    return [b + (along + 1j * h) * u, b + (along - 1j * h) * u]


def _circle_line(group: Group, b: complex, r: float, at: complex, u: complex) -> list[float]:
    """RRP: parameters t of the points at + t·u at distance r from B; branch +1 (further along u) first."""
    w = (at - b) * u.conjugate()
    h2 = r * r - w.imag * w.imag
    if h2 < 0:
        raise AssemblyError(
            f"{group.name}: joint {group.inner.point} cannot assemble: the guide passes {abs(w.imag):.6g} m from "
            f"{group.outer_i.point}, farther than the link's {r:.6g} m (gap {abs(w.imag) - r:.3g} m)"
        )
    h = math.sqrt(h2)
    return [-w.real + h, -w.real - h]


def _meet(group: Group, tracks: list[tuple[complex, complex]]) -> complex:
    """The point where two tracks (point, unit direction) cross."""
    (p1, u1), (p2, u2) = tracks
    sine = (u1.conjugate() * u2).imag
    if abs(sine) < 1e-12:
        raise SingularPositionError(f"{group.name}: its two guides are parallel, so joint {group.joint} has no definite position")
    t = ((p2 - p1) * u2.conjugate()).imag / (u1 * u2.conjugate()).imag
    return p1 + t * u1


def _place_rrr(scene, poses, group):
    i, j = group.links
    b, d = _known_point(scene, poses, group.outer_i), _known_point(scene, poses, group.outer_j)
    c_name = group.inner.point
    r1 = abs(_local(scene, i, c_name) - _local(scene, i, group.outer_i.point))
    r2 = abs(_local(scene, j, c_name) - _local(scene, j, group.outer_j.point))
    out = []
    for c in _circle_circle(group, b, r1, d, r2):
        out.append({i: _pin_pose(scene, i, group.outer_i.point, b, c_name, c), j: _pin_pose(scene, j, group.outer_j.point, d, c_name, c)})
    return out


def _place_rrp(scene, poses, group):
    i, j = group.links
    b = _known_point(scene, poses, group.outer_i)
    c_name = group.inner.point
    r = abs(_local(scene, i, c_name) - _local(scene, i, group.outer_i.point))
    prismatic = group.outer_j.prismatic
    phi_j = _turned_with(scene, poses, prismatic, j)
    at, u = _track(scene, poses, prismatic, j, phi_j, _local(scene, j, c_name))
    out = []
    for t in _circle_line(group, b, r, at, u):
        c = at + t * u
        pose_j = (phi_j, c - cmath.exp(1j * phi_j) * _local(scene, j, c_name))
        out.append({i: _pin_pose(scene, i, group.outer_i.point, b, c_name, c), j: pose_j})
    return out


def _place_rpr(scene, poses, group):
    i, j = group.links  # i carries the guide line, j the sliding line
    b, e = _known_point(scene, poses, group.outer_i), _known_point(scene, poses, group.outer_j)
    prismatic = group.inner.prismatic
    guide = scene.bodies[i].lines[prismatic.guide_line]
    slide = scene.bodies[j].lines[prismatic.slider_line]
    # offsets of the lines from the pivots, measured across the common line
    h_g = ((guide.origin - _local(scene, i, group.outer_i.point)) * cmath.exp(-1j * guide.angle)).imag
    h_s = ((slide.origin - _local(scene, j, group.outer_j.point)) * cmath.exp(-1j * slide.angle)).imag
    h = h_g - h_s
    rho, beta = abs(e - b), cmath.phase(e - b)
    if abs(h) > rho:
        raise AssemblyError(
            f"{group.name}: the sleeve cannot assemble: the common line must pass {abs(h):.6g} m from "
            f"{group.outer_i.point} and {group.outer_j.point}, which are only {rho:.6g} m apart (gap {abs(h) - rho:.3g} m)"
        )
    tilt = math.asin(h / rho) if rho > 0 else 0.0
    out = []
    for theta in (beta - tilt, beta - math.pi + tilt):  # +1: the line points from B towards E
        phi_i, phi_j = theta - guide.angle, theta - slide.angle
        out.append({
            i: (phi_i, b - cmath.exp(1j * phi_i) * _local(scene, i, group.outer_i.point)),
            j: (phi_j, e - cmath.exp(1j * phi_j) * _local(scene, j, group.outer_j.point)),
        })
    return out


def _place_prp(scene, poses, group):
    i, j = group.links
    c_name = group.inner.point
    phi_i = _turned_with(scene, poses, group.outer_i.prismatic, i)
    phi_j = _turned_with(scene, poses, group.outer_j.prismatic, j)
    c = _meet(group, [
        _track(scene, poses, group.outer_i.prismatic, i, phi_i, _local(scene, i, c_name)),
        _track(scene, poses, group.outer_j.prismatic, j, phi_j, _local(scene, j, c_name)),
    ])
    return [{
        i: (phi_i, c - cmath.exp(1j * phi_i) * _local(scene, i, c_name)),
        j: (phi_j, c - cmath.exp(1j * phi_j) * _local(scene, j, c_name)),
    }]


def _place_rpp(scene, poses, group):
    i, j = group.links  # i: pinned at B; j: slides on i and on a placed guide
    b = _known_point(scene, poses, group.outer_i)
    phi_j = _turned_with(scene, poses, group.outer_j.prismatic, j)
    placed = dict(poses)
    placed[j] = (phi_j, 0j)
    phi_i = _turned_with(scene, placed, group.inner.prismatic, i)
    placed[i] = (phi_i, b - cmath.exp(1j * phi_i) * _local(scene, i, group.outer_i.point))
    origin = _meet(group, [
        _track(scene, placed, group.outer_j.prismatic, j, phi_j, 0j),
        _track(scene, placed, group.inner.prismatic, j, phi_j, 0j),
    ])
    return [{i: placed[i], j: (phi_j, origin)}]


_PLACE = {"RRR": _place_rrr, "RRP": _place_rrp, "RPR": _place_rpr, "PRP": _place_prp, "RPP": _place_rpp}


def _choose(scene: Scene, group: Group, candidates: list[dict[str, Pose]]) -> dict[str, Pose]:
    """The branch the scene's [assembly] asks for: the first entry naming a point of the group's links
    (not an outer joint), a sign ±1 (stated in the order of :attr:`Group.sign_order`) or a location
    the point lies nearest; +1 without one."""
    if len(candidates) == 1:
        return candidates[0]
    outer = {joint.point for joint in (group.outer_i, group.outer_j) if joint.kind == "R"}
    for name, value in scene.assembly.items():
        if name in outer:
            continue
        owners = [link for link in group.links if name in scene.bodies[link].points]
        if not owners:
            continue
        if isinstance(value, int):  # a sign is stated in the order of Group.sign_order
            return candidates[0] if value * group.orientation > 0 else candidates[1]
        local = _local(scene, owners[0], name)
        return min(candidates, key=lambda c: abs(point_at(c[owners[0]], local) - value))
    return candidates[0] if group.orientation > 0 else candidates[1]  # +1 in the order of Group.sign_order


def place_bodies(scene: Scene, structure: Structure) -> dict[str, Pose]:
    """The pose of every body at the scene's driver position.

    Raises
    ------
    plans.errors.AssemblyError
        A group cannot be assembled (names the group and the lengths).
    plans.errors.SingularPositionError
        A PRP or RPP group whose two guides are parallel.
    """
    poses: dict[str, Pose] = {FRAME: (0.0, 0j)}
    driver = scene.driver
    body = scene.bodies[driver.link]
    if isinstance(driver, Crank):
        pivot = scene.frame.points[driver.pivot]
        poses[driver.link] = (driver.phi, pivot - cmath.exp(1j * driver.phi) * body.points[driver.pivot])
    else:
        line = scene.frame.lines[driver.guide]
        at = line.origin + driver.s * line.direction
        poses[driver.link] = (line.angle, at - cmath.exp(1j * line.angle) * body.points[driver.point])
    for group in structure.groups:
        try:
            candidates = _PLACE[group.kind](scene, poses, group)
        except (AssemblyError, SingularPositionError) as exc:
            position = position_text(isinstance(driver, Crank), driver.phi if isinstance(driver, Crank) else driver.s)
            raise type(exc)(f"{scene.source}: {exc} (at {position}, instant-centre method)") from None
        poses.update(_choose(scene, group, candidates))
    return poses
