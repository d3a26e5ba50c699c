"""Velocities from the instant centres: ω of every link and v of every named point.

Each body's motion at the instant is a rotation about its centre P_1j with
the frame (1 = the frame) or, when P_1j is at infinity, a translation.  A
body j is found from a body k whose motion is known, through their common
centre P_jk, a point of both bodies with one velocity:

* P_jk and P_1j finite — the angular-velocity ratio theorem.  As a point
  of k, P_jk moves with v_k(P_jk); as a point of j, with
  ω_j × (P_jk − P_1j) = i·ω_j·(P_jk − P_1j).  So
  ``ω_j = v_k(P_jk) / (i·(P_jk − P_1j))``; when k turns about P_1k this is
  ``ω_j / ω_k = (P_jk − P_1k) / (P_jk − P_1j)``, a real number because the
  three centres lie on one line (Kennedy): the same sense when P_jk lies
  outside the segment P_1j P_1k.
* P_1j at infinity, P_jk finite — j translates with the velocity of P_jk.
* P_jk at infinity — j turns with k (ω_j = ω_k) about P_1j; if P_1j is at
  infinity too, both translate and j's velocity is k's plus a relative one
  perpendicular to P_jk's direction, perpendicular in all to P_1j's.

A point M of body j then moves with ``v_M = ω_j × (M − P_1j)`` (or the
translation's velocity).  Units SI, ω counter-clockwise positive.

Readings: with a :class:`Reading` (the drawing's k_l and the drafting
precision), every length the rules use (P_1kP_jk, P_1jP_jk, P_1jM) is taken
as a student measures it on the drawing — its millimetres rounded to the
precision (one under SHORT_READ_MM to a tenth of it, as the plans read a short
segment), times k_l — and its direction as it is; without one, exactly.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from ..rounding import SHORT_READ_MM, reading_step
from ..scene import FRAME, Crank, Scene
from .kennedy import JOIN_TOL, Centre, CentreError
from .pose import Pose, point_at

__all__ = ["Motion", "Reading", "body_motions", "point_bodies", "point_velocities", "SHORT_READ_MM"]



@dataclass(frozen=True)
class Reading:
    """Lengths as read off the centres drawing: at *k_l* [m/mm], each rounded to *precision* [mm]."""

    k_l: float
    precision: float
    #: the part of the plane drawn where it is (lower-left, upper-right) [m]; a centre outside (an arrow at the drawing's
    #: edge) gives no length to measure, so a path of centres off it is taken only where none on it gives ω
    room: tuple | None = None

    def on_drawing(self, *centres) -> bool:
        """Whether every finite one of *centres* (points [m] or None) lies on the drawing (always, without a room)."""
        if self.room is None:
            return True
        lo, hi = self.room
        return all(z is None or (lo.real <= z.real <= hi.real and lo.imag <= z.imag <= hi.imag) for z in centres)

    def step(self, mm: float) -> float:
        """The step [mm] a length of *mm* on the drawing is read to: the precision, a tenth of it under SHORT_READ_MM."""
        return reading_step(mm, self.precision)

    def __call__(self, arm: complex) -> complex:
        """*arm* [m] with its length as measured: round(|arm|/k_l to its step)·k_l, its direction kept."""
        length = abs(arm)
        if length == 0.0:
            return arm
        step = self.step(length / self.k_l)
        return arm * (round(length / self.k_l / step) * step * self.k_l / length)


def _exact(arm: complex) -> complex:
    return arm


@dataclass(frozen=True)
class Motion:
    """A body's velocity field: ``v(z) = v0 + i·ω·(z − about)`` [m/s]; ω [rad/s]."""

    omega: float
    about: complex
    v0: complex = 0j
    #: with a reading, the lengths ω was read from: ``(("P12", "P24", 1.1), ("P14", "P24", 25.3))`` — each centre pair's
    #: length [mm of the drawing] as read (P_1kP_jk, then P_1jP_jk); empty where nothing was measured or exactly
    via: tuple = ()
    #: with a reading, the link whose ω this one's was found from ("" for the driver and the frame, or exactly)
    from_link: str = ""
    #: the place of this body in the order the bodies' motions were found: 0 the frame, 1 the driver, then each link
    #: after every link its motion was found from (a table listed by it uses only what rows above it give)
    step: int = 0

    def velocity(self, z: complex, read=_exact) -> complex:
        """The velocity [m/s] of the body's point at z [m] (*read*: the arm z − about as measured, :class:`Reading`)."""
        if self.omega == 0.0:
            return self.v0
        return self.v0 + 1j * self.omega * read(z - self.about)


def _through(known: Motion, p1j: Centre, pjk: Centre, size: float, read=_exact) -> Motion | None:
    """Body j's motion from body k's through P_jk and P_1j; None when these centres do not determine it (*read*: the
    lengths as measured, :class:`Reading`)."""
    if not (p1j.determined and pjk.determined):
        return None
    if pjk.point is not None:
        vk = known.velocity(pjk.point, read)
        if p1j.point is None:
            return Motion(0.0, 0j, vk)
        arm = pjk.point - p1j.point
        if abs(arm) <= JOIN_TOL * size:
            return None
        arm = read(arm)
        if arm == 0:
            return None  # P_jk and P_1j one point on the drawing
        return Motion((vk / (1j * arm)).real, p1j.point)
    if p1j.point is not None:
        return Motion(known.omega, p1j.point)
    if known.omega != 0.0:
        return None
    across_jk, across_1j = 1j * pjk.direction, 1j * p1j.direction
    sine = (across_1j.conjugate() * across_jk).imag
    if abs(sine) <= JOIN_TOL:
        return None
    t = -(across_1j.conjugate() * known.v0).imag / sine
    return Motion(0.0, 0j, known.v0 + t * across_jk)


def _lengths(known: Motion, p1j: Centre, pjk: Centre, k_l: float, size: float) -> list[float]:
    """The lengths [mm of the drawing at *k_l*] that :func:`_through` reads for body j from body k: P_1kP_jk (when k
    turns) and P_1jP_jk (when both are finite); a length that is zero exactly (P_jk on P_1k: ω_j = 0, read as 0) is
    not a reading."""
    if pjk.point is None:
        return []
    arms = [pjk.point - known.about] if known.omega != 0.0 else []
    if p1j.point is not None:
        arms.append(pjk.point - p1j.point)
    return [abs(arm) / k_l for arm in arms if abs(arm) > JOIN_TOL * size]


def _via(known: Motion, p1k: Centre | None, p1j: Centre, pjk: Centre, read: "Reading") -> tuple:
    """The lengths ω_j is read from (see :attr:`Motion.via`): P_1kP_jk when k turns (P_1k finite, also at an instant
    when ω_k = 0: ω_j = 0 · P_1kP_jk / P_1jP_jk), P_1jP_jk when both are finite."""
    if pjk.point is None:
        return ()
    out = []
    for centre, at in ((p1k, None if p1k is None else p1k.point), (p1j, p1j.point)):
        if centre is not None and at is not None:
            out.append((centre.label, pjk.label, abs(read(pjk.point - at)) / read.k_l))
    return tuple(out)


def body_motions(scene: Scene, poses: dict[str, Pose], centres: list[Centre], size: float, read=None) -> dict[str, Motion]:
    """The motion of every body (the frame's is zero), found from the driver through the centres.

    Parameters
    ----------
    size : float
        The mechanism's size [m]; centres closer than ``JOIN_TOL·size`` count as one.
    read : Reading, optional
        The lengths P_1kP_jk, P_1jP_jk as measured on the drawing; exact without.

    Raises
    ------
    CentreError
        A link whose centres with the frame and with every known body
        coincide (a dead centre): names the link and the centres.
    """
    by_pair = {}
    for centre in centres:
        a, b = centre.bodies
        by_pair[(a, b)] = by_pair[(b, a)] = centre
    driver = scene.driver
    if isinstance(driver, Crank):
        pivot = scene.frame.points[driver.pivot]
        start = Motion(driver.omega, pivot)
    else:
        line = scene.frame.lines[driver.guide]
        start = Motion(0.0, 0j, driver.velocity * line.direction)
    motions = {FRAME: Motion(0.0, 0j), driver.link: replace(start, step=1)}
    # with a reading: for the way to each link, (all its centres on the drawing, the shortest length [mm] read on it)
    width = {driver.link: (True, float("inf"))}
    left = [name for name in scene.links if name != driver.link]
    while left:
        best = None  # (width, j, motion)
        for j in left:
            p1j = by_pair[(FRAME, j)]
            # a body that shares a centre at infinity with j first (ω_j = ω_k, nothing measured), then the driver (the
            # rule the page states: ω_j from the driver's), then the others in the order they were found
            for k, known in sorted(motions.items(), key=lambda item: item[0] == FRAME or by_pair[(j, item[0])].point is not None):
                if k == FRAME:
                    continue
                found = _through(known, p1j, by_pair[(j, k)], size, read or _exact)
                if found is None:
                    continue
                if read is None:
                    best = (0.0, j, found)
                    break
                # a student takes the path whose lengths read best: of the links found next, the one whose centres are
                # on the drawing and whose shortest length on its way from the driver is longest (a length that reads 0
                # on the drawing gives no ω)
                pjk = by_pair[(j, k)]
                measured = _lengths(known, p1j, pjk, read.k_l, size)
                on = width[k][0] and (not measured or read.on_drawing(pjk.point, p1j.point, known.about if known.omega else None))
                shortest = (on, min([width[k][1]] + measured))
                if shortest[1] > 0.5 * read.step(0.0) and (best is None or shortest > best[0]):
                    best = (shortest, j, replace(found, via=_via(known, by_pair.get((FRAME, k)), p1j, by_pair[(j, k)], read), from_link=k))
            if best is not None and read is None:
                break
        if best is not None:
            _, j, found = best
            motions[j] = replace(found, step=len(motions))
            width[j] = best[0]
            left.remove(j)
        else:
            j = left[0]
            p1j = by_pair[(FRAME, j)]
            tried = ", ".join(by_pair[(j, k)].label for k in motions if k != FRAME)
            unknown = [c for c in [p1j] + [by_pair[(j, k)] for k in motions if k != FRAME] if not c.determined]
            why = (
                "; ".join(f"{c.label} is {c.describe()}" for c in unknown)
                if unknown
                else f"{p1j.label} coincides with each of them or they all lie at infinity in one direction (a dead centre)"
            )
            raise CentreError(
                f"{scene.source}: the velocity of link {j} is not determined by the instant centres at this "
                f"position: it needs its centre with the frame {p1j.label} and one with a link already known "
                f"({tried}); {why}"
            )
    return {name: motions[name] for name in scene.bodies}


def point_bodies(scene: Scene, centres: list[Centre], read=None) -> dict[str, str]:
    """The body whose motion gives each named point's velocity: the one that defines it (:meth:`Scene.home_of`), or,
    with a reading whose drawing leaves that body's P_1j off it (an arrow at the edge: P_1jM cannot be measured
    there), another body carrying the point (a pin) that translates (v_M = v_j, nothing to measure) or whose P_1j
    is on the drawing — the quick-return's ram pin E read as v₆ where P₁₅ lies 4 m off the page."""
    p1 = {(c.bodies[1] if c.bodies[0] == FRAME else c.bodies[0]): c for c in centres if FRAME in c.bodies}
    out = {}
    for name in scene.point_names:
        home = scene.home_of(name)
        out[name] = home
        if read is None or home == FRAME or read.on_drawing(p1[home].point):
            continue
        others = [b for b in scene.bodies_with(name) if b not in (FRAME, home) and p1[b].determined]
        better = [b for b in others if p1[b].point is None] + [b for b in others if p1[b].point is not None and read.on_drawing(p1[b].point)]
        if better:
            out[name] = better[0]
    return out


def point_velocities(scene: Scene, poses: dict[str, Pose], motions: dict[str, Motion], read=None,
                     bodies: dict[str, str] | None = None) -> dict[str, complex]:
    """v [m/s] of every named point, from the motion of the body it belongs to (*bodies*: point -> the body to read
    it from, :func:`point_bodies`; the body that defines it without) (*read*: P_1jM as measured, :class:`Reading`)."""
    out = {}
    for name in scene.point_names:
        home = (bodies or {}).get(name) or scene.home_of(name)
        out[name] = motions[home].velocity(point_at(poses[home], scene.bodies[home].points[name]), read or _exact)
    return out
