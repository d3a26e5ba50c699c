"""All instant centres of a mechanism at its position: primary ones from the pairs, the rest by Kennedy's theorem.

Kennedy's theorem: the three instant centres P_ij, P_jk, P_ik of any three
bodies lie on one straight line.  A centre P_ik not given by a pair is found
where two such lines cross: the line P_ij P_jk and the line P_il P_lk.  The
order is the circle diagram's: bodies on a circle, known centres as drawn
sides, and the next centre found is the first (lowest numbers) diagonal that
closes two triangles of drawn sides.

Centres are handled in homogeneous coordinates (x, y, w), in the
mechanism's own coordinates shifted to its middle and divided by its size:
a finite centre is (x, y, 1), a centre at infinity the unit direction
(dx, dy, 0) it lies in.  The line through two centres p, q is the cross
product p × q and the point where two lines meet is their cross product, so
a prismatic pair (its centre at infinity perpendicular to the guide), two
parallel Kennedy lines (a centre at infinity) and the line through two
centres at infinity (the line at infinity) all need no special case, and no
centre is ever a huge number.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import PlansError
from ..scene import FRAME, LinearDriver, Scene
from .pose import Pose, point_at

__all__ = ["CentreError", "Centre", "body_numbers", "find_centres", "JOIN_TOL", "MEET_TOL", "INFINITY_TOL"]

#: two centres closer than this (a fraction of the mechanism's size) give no line
JOIN_TOL = 1e-9
#: two Kennedy lines this close to one line (|l1 × l2| of unit lines) give no point
MEET_TOL = 1e-9
#: a centre farther than 1/INFINITY_TOL mechanism sizes is at infinity: the lines were parallel to round-off
INFINITY_TOL = 1e-13


class CentreError(PlansError, ArithmeticError):
    """An instant centre, or a velocity from the centres, that the construction cannot determine."""


@dataclass(frozen=True)
class Centre:
    """The instant centre P_ij of two bodies.

    Attributes
    ----------
    bodies : tuple[str, str]
        The two bodies' names (``"frame"`` for the frame), lower number first.
    label : str
        ``"P13"`` with the bodies' numbers (see :func:`body_numbers`).
    point : complex or None
        Where it is [m]; None when it is at infinity.
    direction : complex or None
        For a centre at infinity, the unit direction it lies in (sense
        immaterial: the angle is taken in [0°, 180°)); None for a finite one.
    found_by : str
        ``"revolute B"``, ``"prismatic NAME"``, ``"kennedy"``, or
        ``"undetermined"`` when no two distinct Kennedy lines give it at this
        position (then ``point`` and ``direction`` are None and ``why`` says
        which lines were tried).
    lines : tuple
        For a Kennedy centre, the two lines that gave it, as label pairs
        ``(("P12", "P23"), ("P14", "P34"))``; empty for a primary centre.
    why : str
        For an undetermined centre, the reason.
    """

    bodies: tuple[str, str]
    label: str
    point: complex | None
    direction: complex | None
    found_by: str
    lines: tuple = ()
    why: str = ""

    @property
    def determined(self) -> bool:
        return self.found_by != "undetermined"

    @property
    def at_infinity(self) -> bool:
        return self.point is None and self.direction is not None

    def describe(self) -> str:
        """``(x, y) m``, ``at infinity, 90.000°`` or ``undetermined: …`` for tables and messages."""
        if not self.determined:
            return f"undetermined: {self.why}"
        if self.point is not None:
            return f"({self.point.real:.6g}, {self.point.imag:.6g}) m"
        return f"at infinity, direction {self.direction_deg:.3f}°"

    @property
    def direction_deg(self) -> float | None:
        """The direction [°] of a centre at infinity, in [0, 180) (0 for a direction along x to round-off); else None."""
        if self.direction is None:
            return None
        d = math.degrees(math.atan2(self.direction.imag, self.direction.real)) % 180.0
        return 0.0 if min(d, 180.0 - d) < 1e-9 else d


def _number_key(name: str):
    return (0, int(name), "") if name.isdigit() else (1, 0, name)


def body_numbers(scene: Scene) -> dict[str, str]:
    """The number each body goes by in a centre's label, in order.

    The links keep the scene's names (``"2"``, ``"3"``, … or words); the
    frame is ``"1"``, as in the workbooks where the crank is 2, unless a
    link is already called 1 (the crank-1 convention), then ``"0"``.
    """
    links = sorted(scene.links, key=_number_key)
    return {FRAME: scene.frame_number, **{name: name for name in links}}


def centre_label(numbers: dict[str, str], a: str, b: str) -> str:
    """``P13``; with a name of more than one character, ``P1,coupler``."""
    x, y = numbers[a], numbers[b]
    sep = "" if len(x) == 1 and len(y) == 1 else ","
    return f"P{x}{sep}{y}"


# --- homogeneous geometry, in units of the mechanism's size ----------------------


def _cross(p, q):
    return (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0])


def _join(p, q):
    """The unit line through two centres, the line at infinity (0, 0, ±1), or None when they coincide."""
    line = _cross(p, q)
    ab = math.hypot(line[0], line[1])
    if ab > JOIN_TOL:
        return (line[0] / ab, line[1] / ab, line[2] / ab)
    if abs(line[2]) > JOIN_TOL:  # two distinct directions at infinity
        return (0.0, 0.0, math.copysign(1.0, line[2]))
    return None


def _meet(l1, l2):
    """Where two unit lines cross, normalised; None when they are one line. Also returns |l1 × l2|."""
    x = _cross(l1, l2)
    size = math.sqrt(x[0] ** 2 + x[1] ** 2 + x[2] ** 2)
    if size <= MEET_TOL:
        return None, size
    return _normal(x), size


def _normal(x):
    """A homogeneous point as (x, y, 1) or (dx, dy, 0) with dx² + dy² = 1 and the direction's angle in [0, π)
    (a direction within 1e-12 of the x axis points along +x)."""
    ab = math.hypot(x[0], x[1])
    if abs(x[2]) <= INFINITY_TOL * ab:
        dx, dy = x[0] / ab, x[1] / ab
        if (dy < 0 and abs(dy) > 1e-12) or (abs(dy) <= 1e-12 and dx < 0):  # the angle in [0°, 180°)
            dx, dy = -dx, -dy
        return (dx + 0.0, dy + 0.0, 0.0)
    return (x[0] / x[2], x[1] / x[2], 1.0)


def _size(scene: Scene, poses: dict[str, Pose]) -> tuple[complex, float]:
    zs = [point_at(poses[name], z) for name, body in scene.bodies.items() for z in body.points.values()]
    xs, ys = [z.real for z in zs], [z.imag for z in zs]
    middle = complex((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2)
    size = max(max(xs) - min(xs), max(ys) - min(ys))
    return middle, size if size > 0 else 1.0


# --- the construction ---------------------------------------------------------------


def _primary(scene: Scene, poses: dict[str, Pose]):
    """Centres given by the pairs: {pair: (global point or None, direction or None, found_by)}."""
    found: dict[tuple[str, str], tuple] = {}
    for name in scene.point_names:
        owners = scene.bodies_with(name)
        at = point_at(poses[owners[0]], scene.bodies[owners[0]].points[name])
        for k, a in enumerate(owners):
            for b in owners[k + 1 :]:
                found.setdefault(frozenset((a, b)), (at, None, f"revolute {name}"))
    guides = [(p.name, p.guide, p.guide_line, p.slider) for p in scene.prismatics]
    driver = scene.driver
    if isinstance(driver, LinearDriver):
        guides.append((f"{driver.point} on frame.{driver.guide}", FRAME, driver.guide, driver.link))
    for name, guide, line, slider in guides:
        u = _direction(scene, poses, guide, line)
        found.setdefault(frozenset((guide, slider)), (None, 1j * u, f"prismatic {name}"))
    return found


def _direction(scene: Scene, poses: dict[str, Pose], body: str, line: str) -> complex:
    phi = poses[body][0]
    angle = scene.bodies[body].lines[line].angle
    return complex(math.cos(phi + angle), math.sin(phi + angle))


def find_centres(scene: Scene, poses: dict[str, Pose]) -> list[Centre]:
    """Every instant centre of the bodies at their poses, in label order (P12, P13, …, P23, …).

    A centre that no pair gives and no two distinct Kennedy lines determine
    (every line through it coincides with the others, or passes through two
    coincident centres: a special position, not a wrong number) is returned
    as ``found_by = "undetermined"`` with the reason; the construction goes
    on with the others.
    """
    numbers = body_numbers(scene)
    order = list(numbers)
    middle, size = _size(scene, poses)
    known: dict[tuple[str, str], tuple] = {}
    records: dict[tuple[str, str], Centre] = {}

    def pair(a, b):
        return (a, b) if order.index(a) < order.index(b) else (b, a)

    def label(a, b):
        return centre_label(numbers, *pair(a, b))

    for bodies, (at, u, how) in _primary(scene, poses).items():
        a, b = pair(*bodies)
        if at is not None:
            z = (at - middle) / size
            known[(a, b)] = (z.real, z.imag, 1.0)
        else:
            known[(a, b)] = _normal((u.real, u.imag, 0.0))
        records[(a, b)] = _record(known[(a, b)], (a, b), label(a, b), how, (), middle, size)

    wanted = [(a, b) for k, a in enumerate(order) for b in order[k + 1 :]]
    while len(known) < len(wanted):
        for a, c in wanted:
            if (a, c) in known:
                continue
            lines = []
            for b in order:
                if b in (a, c) or pair(a, b) not in known or pair(b, c) not in known:
                    continue
                line = _join(known[pair(a, b)], known[pair(b, c)])
                lines.append((b, line))
            best = None
            for k, (b, l1) in enumerate(lines):
                for d, l2 in lines[k + 1 :]:
                    if l1 is None or l2 is None:
                        continue
                    point, quality = _meet(l1, l2)
                    if point is not None and (best is None or quality > best[0]):
                        best = (quality, point, b, d)
            if best is not None:
                _, point, b, d = best
                known[(a, c)] = point
                used = ((label(a, b), label(b, c)), (label(a, d), label(d, c)))
                records[(a, c)] = _record(point, (a, c), label(a, c), "kennedy", used, middle, size)
                break
        else:
            break
    for a, c in wanted:
        if (a, c) not in records:
            records[(a, c)] = Centre((a, c), label(a, c), None, None, "undetermined", (), _why(known, order, label, a, c))
    return [records[p] for p in wanted]


def _record(h, bodies, label, how, lines, middle, size) -> Centre:
    if h[2] == 0.0:
        return Centre(bodies, label, None, complex(h[0], h[1]), how, lines)
    return Centre(bodies, label, middle + size * complex(h[0], h[1]), None, how, lines)


def _why(known, order, label, a, c) -> str:
    """Why the centre of bodies a, c is not determined: the Kennedy lines available for it."""
    tried = []
    for b in order:
        if b in (a, c):
            continue
        ab, bc = tuple(sorted((a, b), key=order.index)), tuple(sorted((b, c), key=order.index))
        if ab in known and bc in known:
            line = _join(known[ab], known[bc])
            tried.append(f"{label(a, b)}{label(b, c)}" + (" (its two centres coincide)" if line is None else ""))
    if not tried:
        return "no centre of its two bodies with a third body is known"
    if len(tried) == 1:
        return f"Kennedy's theorem gives only the line {tried[0]}"
    return f"the Kennedy lines {', '.join(tried)} are one line at this position"
