"""Kinetostatics by Newton–Euler, group by group: every joint reaction and the balancing moment.

The loads (weights, inertia loads from the analytic accelerations, the
scene's external loads; :mod:`plans.forces.loads`) hold each moving link in
equilibrium together with the joint reactions (d'Alembert).  Each class-II
group is statically determinate on its own (6 equations, 6 unknowns), so the
groups are solved from the last one back to the driver, each passing the
reactions on its outer joints to the links it is attached to; the driver's
equilibrium then gives the balancing moment M_b on a crank (or the balancing
force F_b on a linear driver) and the reaction of the frame on it.

Conventions (SI, frame axes, counter-clockwise positive):

* forces are complex numbers ``Fx + iFy`` [N]; ``cross(a, b) = Im(ā·b)`` is
  the z component of a × b, so a force f at r has the moment ``cross(r, f)``
  about the origin [N·m];
* an ideal revolute joint transmits a force through its centre (2 unknowns);
* an ideal prismatic pair transmits a force ``N·n`` along the normal
  ``n = i·u`` of its common line (u: the line's unit direction) whose line of
  action is unknown: the unknowns are N and the couple C of that force about
  a reference point Q of the pair, and the force acts through
  ``Q + (C/N)·u`` (2 unknowns; no friction);
* ``R_ij`` is the force of body i on body j (the frame is 0): the reaction
  of the known body on a group's link at an outer joint, of the group's
  first link on its second at the inner joint.

Every array has one entry per driver position (the kinematics' N), with no
Python loop over the positions.  Singular positions of the kinetostatics are
those of the kinematics (the same pairs of directions meet), which the
analytic solver already refuses or warns of.

>>> import plans
>>> forces = plans.forces(plans.load(plans.example_path("slider-crank-loads")))
>>> round(float(forces.balancing[0]), 6)        # M_b [N·m], domain.md §11
620.218316
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import SceneError
from ..scene import FRAME, Crank, LinearDriver, Prismatic, Scene
from ..structure import Group, Joint, Structure
from .loads import AppliedLoad, applied_loads

__all__ = ["Reaction", "AnalyticForces", "SolutionKinematics", "solve_forces", "forces_from", "load_power", "reaction_label", "cross"]


def cross(a, b):
    """The z component of a × b for plane vectors as complex numbers: ``Im(ā·b) = a_x·b_y − a_y·b_x``."""
    return (a.conjugate() * b).imag


def _dot(a, b):
    """a · b for plane vectors as complex numbers."""
    return a.real * b.real + a.imag * b.imag


def reaction_label(by: str, on: str) -> str:
    """``"R_23"``: the force of body *by* on body *on* (the frame is 0); ``"R_3,rod"`` for longer names."""
    names = ["0" if b == FRAME else b for b in (by, on)]
    joiner = "" if all(len(n) == 1 for n in names) else ","
    return f"R_{joiner.join(names)}"


@dataclass(frozen=True, eq=False)
class Reaction:
    """The force one body exerts on another in a joint, at N positions.

    Attributes
    ----------
    label : str
        ``"R_23"`` (:func:`reaction_label`).
    joint : str
        The joint: a point name for a revolute, the prismatic pair's name.
    kind : str
        ``"R"`` or ``"P"``.
    by, on : str
        The body exerting the force and the body it acts on.
    group : str
        The group whose equations gave it (``"RRP(3,4)"``), or ``"driver"``.
    force : complex array (N,)
        The force of *by* on *on* [N].
    point : complex array (N,)
        Its point of application [m]: the joint's centre for a revolute; for
        a prismatic pair, the point of its line of action on the common line
        (NaN where N = 0: no force, no line).
    normal : complex array (N,) or None
        A prismatic pair's unit normal n = i·u (u the common line's
        direction); None for a revolute.
    normal_force : float array (N,) or None
        A prismatic pair's N, signed along n: ``force = N·n``.
    reference : complex array (N,) or None
        A prismatic pair's reference point Q [m] (a joint point of the group).
    couple : float array (N,) or None
        A prismatic pair's moment of its force about Q [N·m]: the force acts
        through ``Q + (couple/N)·u``; where N = 0 the pair transmits this
        couple alone.
    """

    label: str
    joint: str
    kind: str
    by: str
    on: str
    group: str
    force: np.ndarray
    point: np.ndarray
    normal: np.ndarray | None = None
    normal_force: np.ndarray | None = None
    reference: np.ndarray | None = None
    couple: np.ndarray | None = None

    @property
    def magnitude(self) -> np.ndarray:
        """|R| [N]."""
        return np.abs(self.force)

    @property
    def angle(self) -> np.ndarray:
        """Direction of the force [rad], from +x counter-clockwise, in (−π, π]."""
        return np.angle(self.force)


@dataclass(frozen=True, eq=False)
class AnalyticForces:
    """The kinetostatics at N driver positions, from the analytic kinematics.

    Attributes
    ----------
    scene : plans.scene.Scene
    structure : plans.structure.Structure
    kinematics : plans.analytic.AnalyticSolution
        The solution whose accelerations gave the inertia loads.
    loads : tuple[plans.forces.loads.AppliedLoad, ...]
        Every load on the moving bodies (weights, inertia loads, external).
    reactions : dict[str, Reaction]
        By label, the driver's first, then each group's in structural order
        (outer joint of its first link, inner joint, outer joint of its second).
    balancing : float array (N,)
        M_b [N·m], counter-clockwise on the crank; or F_b [N] on a linear
        driver, along its guide's direction.
    balancing_kind : str
        ``"moment"`` (crank) or ``"force"`` (linear driver).
    """

    scene: Scene
    structure: Structure
    kinematics: object
    loads: tuple[AppliedLoad, ...]
    reactions: dict[str, Reaction]
    balancing: np.ndarray
    balancing_kind: str

    def __len__(self) -> int:
        return len(self.balancing)

    @property
    def driver(self) -> np.ndarray:
        """The driver positions: crank angle [rad] or linear-driver position [m]."""
        return self.kinematics.driver

    def driving_power(self) -> np.ndarray:
        """Power of the balancing moment (force): M_b·ω (F_b·v) [W], per position."""
        driver = self.scene.driver
        if isinstance(driver, Crank):
            return self.balancing * self.kinematics.links[driver.link].omega
        return self.balancing * driver.velocity

    def load_power(self) -> np.ndarray:
        """Σ F·v + Σ M·ω over every load [W], with the analytic velocities, per position."""
        return load_power(self.loads, self.kinematics)

    def power_residual(self) -> np.ndarray:
        """M_b·ω + Σ F·v + Σ M·ω [W]: zero by the principle of virtual power (a check independent of the reactions)."""
        return self.driving_power() + self.load_power()


def load_power(loads, kinematics) -> np.ndarray:
    """Σ F·v_P + Σ M·ω over the loads [W], with the velocities of a solution's bodies."""
    total = 0.0
    for load in loads:
        if load.is_couple:
            total = total + load.moment * kinematics.links[load.body].omega
        else:
            v = kinematics.motion_of(load.body, load.local).v
            total = total + _dot(load.force, v)
    return total + np.zeros(len(kinematics))


def solve_forces(scene: Scene, positions=None, structure: Structure | None = None, *, allow_partial: bool = False, warn_condition: float | None = None) -> AnalyticForces:
    """The kinetostatics of the scene at its driver position, or at *positions* (an array: a sweep).

    Solves the kinematics (:func:`plans.analytic.solve`, which refuses dead
    centres and unassemblable positions as it always does), then the forces
    (:func:`forces_from`).

    Parameters
    ----------
    scene : plans.scene.Scene
    positions : float or array, optional
        Driver positions (crank angles [rad] or linear-driver positions [m]).
    structure : plans.structure.Structure, optional
    allow_partial : bool
        As :func:`plans.analytic.solve`: NaN where the mechanism is not solved.
    warn_condition : float, optional
        As :func:`plans.analytic.solve`.
    """
    from ..analytic import solve

    options = {} if warn_condition is None else {"warn_condition": warn_condition}
    kinematics = solve(scene, positions, structure, allow_partial=allow_partial, **options)
    return forces_from(kinematics)


class _Sums:
    """Per body, the sum of the forces on it [N] and of their moments about the origin [N·m]."""

    def __init__(self):
        self.force: dict[str, object] = {}
        self.moment: dict[str, object] = {}

    def add_force(self, body: str, force, r) -> None:
        self.force[body] = self.force.get(body, 0j) + force
        self.moment[body] = self.moment.get(body, 0.0) + cross(r, force)

    def add_couple(self, body: str, moment) -> None:
        self.moment[body] = self.moment.get(body, 0.0) + moment

    def of(self, body: str):
        """(ΣF, ΣM about the origin) on the body."""
        return self.force.get(body, 0j), self.moment.get(body, 0.0)

    def about(self, body: str, point):
        """(ΣF, ΣM about *point*) on the body: M_P = M_O − cross(P, F)."""
        force, moment = self.of(body)
        return force, moment - cross(point, force)


def forces_from(kinematics) -> AnalyticForces:
    """The kinetostatics from an analytic solution (its accelerations give the inertia loads).

    Parameters
    ----------
    kinematics : plans.analytic.AnalyticSolution
        With accelerations (a scene with ``accelerations = false`` has no
        inertia loads to find: refused).
    """
    scene, structure = kinematics.scene, kinematics.structure
    if not scene.accelerations:
        raise SceneError(
            "the kinetostatics needs the accelerations (inertia loads): remove accelerations = false from [compute]",
            scene.source,
            "compute.accelerations",
        )

    loads = applied_loads(scene, SolutionKinematics(kinematics))
    sums = _Sums()
    at_points: dict[tuple[str, int], list] = {}  # forces at one point (a weight and an inertia force at S) summed first
    for load in loads:
        if load.is_couple:
            sums.add_couple(load.body, load.moment)
        else:
            entry = at_points.setdefault((load.body, id(load.r)), [load.r, 0j])
            entry[1] = entry[1] + load.force
    for (body, _), (r, force) in at_points.items():
        sums.add_force(body, force, r)
    n = len(kinematics)
    solved: list[list[Reaction]] = []
    with np.errstate(divide="ignore", invalid="ignore"):  # NaN where a position is not solved
        for group in reversed(structure.groups):
            reactions = _GROUPS[group.kind](kinematics, group, sums)
            for reaction in reactions:
                if reaction.on in group.links and reaction.by not in group.links:  # passed on to the known body
                    _pass_on(sums, reaction)
            solved.append(reactions)
        balancing, driver_reaction = _driver(kinematics, sums)
    ordered = [driver_reaction] + [r for reactions in reversed(solved) for r in reactions]
    out: dict[str, Reaction] = {}
    for reaction in ordered:
        reaction = _full(reaction, n)
        label = reaction.label if reaction.label not in out else f"{reaction.label}:{reaction.joint}"
        out[label] = reaction if label == reaction.label else _relabel(reaction, label)
    return AnalyticForces(scene, structure, kinematics, loads, out, _frozen(np.real(balancing) + np.zeros(n)), "moment" if isinstance(scene.driver, Crank) else "force")


class SolutionKinematics:
    """The kinematics of any point of a body from an analytic solution (for :func:`plans.forces.loads.applied_loads`).

    A named point's own motion where the point is one (no arithmetic); else,
    for a body with two named points A, B, the similarity of its figure,
    ``X = X_A + (z − z_A)·(X_B − X_A)/(z_B − z_A)`` for X = r, v, a (the
    points of a rigid body move as a figure similar to it); for a body of one
    point, ``r = r_O + e^{iφ}z``, ``v = v_O + iω(r − r_O)``, ``a = a_O + (iε − ω²)(r − r_O)``.

    Parameters
    ----------
    solution : plans.analytic.AnalyticSolution
    """

    def __init__(self, solution):
        self.solution = solution
        self.scene = solution.scene

    def _named(self, body: str, z: complex) -> str | None:
        for name, local in self.scene.bodies[body].points.items():
            if local == z:
                return name
        return None

    def _pair(self, body: str):
        points = list(self.scene.bodies[body].points.items())
        if len(points) < 2:
            return None
        (a, za), (b, zb) = points[0], max(points[1:], key=lambda item: abs(item[1] - points[0][1]))
        return (a, za, b, zb) if zb != za else None

    def _motion(self, body: str, z: complex, quantity: str):
        solution = self.solution
        name = self._named(body, z)
        if name is not None:
            return getattr(solution.points[name], quantity)
        pair = self._pair(body)
        if pair is not None:
            a, za, b, zb = pair
            xa, xb = getattr(solution.points[a], quantity), getattr(solution.points[b], quantity)
            return xa + (xb - xa) * ((z - za) / (zb - za))
        motion = solution.motion_of(body, z)
        return getattr(motion, quantity)

    def position(self, body: str, z: complex):
        """r [m] of the body's point with own coordinates z, per position."""
        return self._motion(body, z, "r")

    def velocity(self, body: str, z: complex):
        """v [m/s]."""
        return self._motion(body, z, "v")

    def acceleration(self, body: str, z: complex):
        """a [m/s²]."""
        return self._motion(body, z, "a")

    def omega(self, body: str):
        """ω [rad/s] of the body."""
        return self.solution.links[body].omega

    def epsilon(self, body: str):
        """ε [rad/s²] of the body."""
        return self.solution.links[body].epsilon


def _frozen(array) -> np.ndarray:
    array = np.asarray(array)
    array.setflags(write=False)
    return array


def _full(reaction: Reaction, n: int) -> Reaction:
    """Every array of the reaction of shape (N,), read-only (an array of that shape is kept, not copied)."""
    def full(x, dtype):
        if x is None:
            return None
        x = np.asarray(x)
        if x.shape != (n,) or x.dtype != dtype:
            x = np.asarray(x, dtype=dtype) + np.zeros(n, dtype=dtype)
        return _frozen(x)

    return Reaction(reaction.label, reaction.joint, reaction.kind, reaction.by, reaction.on, reaction.group,
                    full(reaction.force, complex), full(reaction.point, complex), full(reaction.normal, complex),
                    full(reaction.normal_force, float), full(reaction.reference, complex), full(reaction.couple, float))


def _relabel(reaction: Reaction, label: str) -> Reaction:
    fields = ("joint", "kind", "by", "on", "group", "force", "point", "normal", "normal_force", "reference", "couple")
    return Reaction(label, *[getattr(reaction, f) for f in fields])


def _pass_on(sums: _Sums, reaction: Reaction) -> None:
    """The known body feels the opposite of the reaction it exerts on the group (Newton's third law)."""
    if reaction.kind == "P":  # −N·n at Q and the couple −C about Q (a couple alone where N = 0)
        sums.add_force(reaction.by, -reaction.force, reaction.reference)
        sums.add_couple(reaction.by, -reaction.couple)
    else:
        sums.add_force(reaction.by, -reaction.force, reaction.point)


# --- the joints ------------------------------------------------------------------


def _r(kinematics, joint: Joint):
    """Centre of a revolute joint [m]."""
    return kinematics.points[joint.point].r


def _u(kinematics, joint: Joint):
    """Unit direction u of a prismatic pair's common line (frame axes)."""
    p = joint.prismatic
    scene = kinematics.scene
    line = scene.bodies[p.guide].lines[p.guide_line]
    phi = 0.0 if p.guide == FRAME else kinematics.poses[p.guide][0]
    return np.exp(1j * (phi + line.angle))


def _revolute(label_by: str, on: str, joint: Joint, group: str, force, kinematics) -> Reaction:
    return Reaction(reaction_label(label_by, on), joint.point, "R", label_by, on, group, force, _r(kinematics, joint))


def _prismatic(by: str, on: str, joint: Joint, group: str, normal_force, couple, reference, u) -> Reaction:
    """The reaction N·n of a prismatic pair whose couple about *reference* is C: it acts through Q + (C/N)·u."""
    n = 1j * u
    offset = np.where(normal_force != 0, couple / np.where(normal_force != 0, normal_force, 1.0), np.nan)
    point = reference + offset * u
    return Reaction(reaction_label(by, on), joint.prismatic.name, "P", by, on, group, normal_force * n, point, n, normal_force, reference, couple)


def _divide(a, b):
    """a / b, NaN or infinite where b = 0 (a dead centre; :func:`forces_from` silences numpy's warnings)."""
    return a / b


# --- the groups --------------------------------------------------------------------
#
# In each, i and j are the group's links as plans.structure orders them, F = ΣF on i and j
# together, M_X the moment of a link's loads (reactions of later groups included) about X.


def solve_rrr(kinematics, group: Group, sums: _Sums) -> list[Reaction]:
    """RRR: links i (B–C) and j (C–D); outer revolutes B, D, inner C.

    ::

        B ──(i)── C ──(j)── D

    Moments of each link about C (the inner reaction has no moment there)::

        cross(B − C, R_B) + M_i,C = 0            (link i)
        cross(D − C, R_D) + M_j,C = 0            (link j)
        R_B + R_D + F_i + F_j = 0                (the group)

    With b = B − C, d = D − C: cross(b, R_B) = −M_i,C and
    cross(d, R_B) = M_j,C − cross(d, F), so R_B = (p·d − q·b)/cross(b, d)
    with p, q those right-hand sides.  Then R_D = −F − R_B and the inner
    reaction of i on j, R_ij = −R_D − F_j.
    """
    i, j = group.links
    B, C, D = _r(kinematics, group.outer_i), _r(kinematics, group.inner), _r(kinematics, group.outer_j)
    F_i, M_i = sums.about(i, C)
    F_j, M_j = sums.about(j, C)
    b, d = B - C, D - C
    F = F_i + F_j
    p, q = -M_i, M_j - cross(d, F)
    R_B = _divide(p * d - q * b, cross(b, d))
    R_D = -F - R_B
    R_C = -R_D - F_j
    name = group.name
    return [
        _revolute(group.outer_i.bodies[1], i, group.outer_i, name, R_B, kinematics),
        _revolute(i, j, group.inner, name, R_C, kinematics),
        _revolute(group.outer_j.bodies[1], j, group.outer_j, name, R_D, kinematics),
    ]


def solve_rrp(kinematics, group: Group, sums: _Sums) -> list[Reaction]:
    """RRP: link i pinned at B (outer) and C (inner) to j, which slides on a known body (outer P).

    ::

        B ──(i)── C ──(j)══ guide

    The pair's force N·n on j and its couple C_P about C; moments about C::

        cross(B − C, R_B) + M_i,C = 0            (link i)
        C_P + M_j,C = 0                          (link j)
        R_B + N·n + F_i + F_j = 0                (the group)

    so N = (M_i,C − cross(b, F))/cross(b, n) with b = B − C, R_B = −F − N·n,
    and the inner reaction of i on j R_ij = −N·n − F_j.
    """
    i, j = group.links
    B, C = _r(kinematics, group.outer_i), _r(kinematics, group.inner)
    u = _u(kinematics, group.outer_j)
    n = 1j * u
    F_i, M_i = sums.about(i, C)
    F_j, M_j = sums.about(j, C)
    b = B - C
    F = F_i + F_j
    N = _divide(M_i - cross(b, F), cross(b, n))
    R_B = -F - N * n
    R_C = -N * n - F_j
    name = group.name
    return [
        _revolute(group.outer_i.bodies[1], i, group.outer_i, name, R_B, kinematics),
        _revolute(i, j, group.inner, name, R_C, kinematics),
        _prismatic(group.outer_j.bodies[1], j, group.outer_j, name, N, -M_j, C, u),
    ]


def solve_rpr(kinematics, group: Group, sums: _Sums) -> list[Reaction]:
    """RPR: link i pinned at B carries the line on which j slides; j pinned at E (sleeve, swinging block).

    ::

        B ──(i)══(j)── E

    The inner pair's force N·n on j and its couple C_P about E; moments about E::

        C_P + M_j,E = 0                          (link j)
        cross(B − E, R_B) − C_P + M_i,E = 0      (link i)
        R_B − N·n + F_i = 0                      (link i)

    so cross(B − E, R_B) = −(M_i,E + M_j,E) = −M_E with R_B = N·n − F_i:
    N = (cross(B − E, F_i) − M_E)/cross(B − E, n); R_E = −F_j − N·n.
    """
    i, j = group.links
    B, E = _r(kinematics, group.outer_i), _r(kinematics, group.outer_j)
    u = _u(kinematics, group.inner)
    n = 1j * u
    F_i, M_i = sums.about(i, E)
    F_j, M_j = sums.about(j, E)
    be = B - E
    N = _divide(cross(be, F_i) - (M_i + M_j), cross(be, n))
    R_B = N * n - F_i
    R_E = -F_j - N * n
    name = group.name
    return [
        _revolute(group.outer_i.bodies[1], i, group.outer_i, name, R_B, kinematics),
        _prismatic(i, j, group.inner, name, N, -M_j, E, u),
        _revolute(group.outer_j.bodies[1], j, group.outer_j, name, R_E, kinematics),
    ]


def solve_prp(kinematics, group: Group, sums: _Sums) -> list[Reaction]:
    """PRP: links i and j, each sliding on a known body, pinned to each other at C.

    ::

        guide ══(i)── C ──(j)══ guide

    Forces N₁·n₁ on i, N₂·n₂ on j, couples about C: C₁ = −M_i,C, C₂ = −M_j,C;
    the group's forces N₁·n₁ + N₂·n₂ = −F give
    N₁ = −cross(n₂, F)/cross(n₂, n₁), N₂ = −cross(n₁, F)/cross(n₁, n₂);
    the inner reaction of i on j R_ij = −N₂·n₂ − F_j.
    """
    i, j = group.links
    C = _r(kinematics, group.inner)
    u1, u2 = _u(kinematics, group.outer_i), _u(kinematics, group.outer_j)
    n1, n2 = 1j * u1, 1j * u2
    F_i, M_i = sums.about(i, C)
    F_j, M_j = sums.about(j, C)
    F = F_i + F_j
    N1 = _divide(-cross(n2, F), cross(n2, n1))
    N2 = _divide(-cross(n1, F), cross(n1, n2))
    R_C = -N2 * n2 - F_j
    name = group.name
    return [
        _prismatic(group.outer_i.bodies[1], i, group.outer_i, name, N1, -M_i, C, u1),
        _revolute(i, j, group.inner, name, R_C, kinematics),
        _prismatic(group.outer_j.bodies[1], j, group.outer_j, name, N2, -M_j, C, u2),
    ]


def solve_rpp(kinematics, group: Group, sums: _Sums) -> list[Reaction]:
    """RPP: link i pinned at B slides in j (inner P), which slides on a known body (outer P).

    ::

        B ──(i)══(j)══ guide

    Inner force N₁·n₁ of i on j, outer N₂·n₂ on j; moments about B::

        −C₁ + M_i,B = 0                          (link i)
        C₁ + C₂ + M_j,B = 0                      (link j)
        N₁·n₁ + N₂·n₂ + F_j = 0                  (link j)

    so N₁ = −cross(n₂, F_j)/cross(n₂, n₁), N₂ = −cross(n₁, F_j)/cross(n₁, n₂),
    C₁ = M_i,B, C₂ = −M_i,B − M_j,B, and R_B = N₁·n₁ − F_i.
    """
    i, j = group.links
    B = _r(kinematics, group.outer_i)
    u1, u2 = _u(kinematics, group.inner), _u(kinematics, group.outer_j)
    n1, n2 = 1j * u1, 1j * u2
    F_i, M_i = sums.about(i, B)
    F_j, M_j = sums.about(j, B)
    N1 = _divide(-cross(n2, F_j), cross(n2, n1))
    N2 = _divide(-cross(n1, F_j), cross(n1, n2))
    R_B = N1 * n1 - F_i
    name = group.name
    return [
        _revolute(group.outer_i.bodies[1], i, group.outer_i, name, R_B, kinematics),
        _prismatic(i, j, group.inner, name, N1, M_i, B, u1),
        _prismatic(group.outer_j.bodies[1], j, group.outer_j, name, N2, -M_i - M_j, B, u2),
    ]


_GROUPS = {"RRR": solve_rrr, "RRP": solve_rrp, "RPR": solve_rpr, "PRP": solve_prp, "RPP": solve_rpp}


def _driver(kinematics, sums: _Sums):
    """(M_b or F_b, the frame's reaction on the driver).

    Crank about O: R_0d = −ΣF, M_b = −ΣM_O (the moment of the driver's loads
    about its pivot).  Linear driver on a frame line of direction u through
    its point P: F_b = −ΣF·u along the line, N = −ΣF·n, and the couple about
    P is −ΣM_P: the guide's force acts through P + (C/N)·u.
    """
    scene = kinematics.scene
    driver = scene.driver
    link = driver.link
    if isinstance(driver, Crank):
        O = kinematics.points[driver.pivot].r
        F, M = sums.about(link, O)
        joint = Joint("R", (link, FRAME), point=driver.pivot)
        return -M, _revolute(FRAME, link, joint, "driver", -F, kinematics)
    assert isinstance(driver, LinearDriver)
    P = kinematics.points[driver.point].r
    u = complex(np.exp(1j * scene.frame.lines[driver.guide].angle))
    F, M = sums.about(link, P)
    joint = Joint("P", (link, FRAME), prismatic=Prismatic(f"{driver.point}:{FRAME}.{driver.guide}", link, "", FRAME, driver.guide))
    balancing = -_dot(F, u)
    N = -_dot(F, 1j * u)
    return balancing, _prismatic(FRAME, link, joint, "driver", N, -M, P, u)
