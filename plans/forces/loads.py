"""The loads on the moving links at one or many driver positions, from a method's own kinematics.

By d'Alembert's principle the moving mechanism is in equilibrium at each
instant under its given loads and its inertia loads (domain.md §11):

* the weight ``G_k = m_k·g`` at the centre of mass S_k;
* the inertia force ``F_Φk = −m_k·a_Sk`` at S_k;
* the inertia couple ``M_Φk = −J_Sk·ε_k`` (J_Sk about S_k);
* the scene's external loads: a given force at a point, a resistance of given
  magnitude against the velocity of its point (zero where that velocity is
  zero; over the working stroke only, if the scene says so), a couple.

The kinematics comes from the caller, so that each method uses its own: the
analytic solution (:mod:`plans.forces.analytic`) or the readings of the
graphical plans (:mod:`plans.forces.lever`, the force plans).  Everything is
SI: N, N·m, m; forces are complex numbers ``Fx + iFy`` in the frame's axes,
couples counter-clockwise positive.  Arrays broadcast: one position (plain
numbers) or N positions (arrays of shape (N,)).
"""

from __future__ import annotations

from dataclasses import dataclass
import numpy as np

from ..scene import Scene

__all__ = ["LOAD_KINDS", "AppliedLoad", "applied_loads", "inertia_symbol", "weight_symbol"]

#: The kinds of :class:`AppliedLoad`, in the order they are listed per link.
LOAD_KINDS = ("weight", "inertia force", "inertia couple", "force", "resistance", "moment")


@dataclass(frozen=True, eq=False)
class AppliedLoad:
    """One load on a moving body.

    Attributes
    ----------
    name : str
        Its symbol: ``"G_2"`` (weight), ``"F_Φ2"`` (inertia force),
        ``"M_Φ2"`` (inertia couple), or the scene's name of an external load.
    body : str
        The body it acts on.
    kind : str
        One of :data:`LOAD_KINDS`.
    local : complex
        Point of application in the body's own coordinates [m] (a couple: the
        centre of mass, or 0 for an external couple; it has no point).
    point : str or None
        The named point it acts at, if any (``"S3"``, ``"B"``).
    r : complex array or complex
        Point of application [m] (a couple: where a drawing shows it).
    force : complex array or complex
        The force [N]; 0 for a couple.  A plain number where it is the same
        at every position (a weight, a given force).
    moment : float array or float
        The couple [N·m], counter-clockwise positive; 0 for a force.
    """

    name: str
    body: str
    kind: str
    local: complex
    point: str | None
    r: np.ndarray
    force: np.ndarray
    moment: np.ndarray

    @property
    def is_couple(self) -> bool:
        return self.kind in ("inertia couple", "moment")


def weight_symbol(body: str) -> str:
    """``"G_2"``."""
    return f"G_{body}"


def inertia_symbol(body: str, couple: bool = False) -> str:
    """``"F_Φ2"`` or, for the couple, ``"M_Φ2"``."""
    return f"{'M' if couple else 'F'}_Φ{body}"


def applied_loads(scene: Scene, kinematics) -> tuple[AppliedLoad, ...]:
    """Every load on the moving bodies, from the kinematics given.

    Parameters
    ----------
    scene : plans.scene.Scene
    kinematics : object
        A method's kinematics, with methods ``position(body, z)`` [m],
        ``velocity(body, z)`` [m/s] and ``acceleration(body, z)`` [m/s²] of
        the point with own coordinates *z* [m] of the body (complex numbers or
        arrays), and ``epsilon(body)`` [rad/s²]
        (:class:`plans.forces.analytic.SolutionKinematics`,
        :class:`plans.forces.readings.PlanReadings`).

    Returns
    -------
    tuple of AppliedLoad
        Per body in scene order: weight, inertia force, inertia couple (those
        that are not identically zero: a body without mass has none), then the
        external loads in file order.
    """
    out: list[AppliedLoad] = []
    g = scene.gravity.vector if scene.gravity is not None else 0j
    for body, mass in scene.masses.items():
        r = kinematics.position(body, mass.centre)
        if mass.mass > 0 and g != 0:
            out.append(AppliedLoad(weight_symbol(body), body, "weight", mass.centre, mass.point, r, mass.mass * g, 0.0))
        if mass.mass > 0:
            a = kinematics.acceleration(body, mass.centre)
            out.append(AppliedLoad(inertia_symbol(body), body, "inertia force", mass.centre, mass.point, r, -mass.mass * a, 0.0))
        if mass.inertia > 0:
            epsilon = kinematics.epsilon(body)
            out.append(AppliedLoad(inertia_symbol(body, True), body, "inertia couple", mass.centre, mass.point, r, 0j, -mass.inertia * epsilon))
    for load in scene.loads:
        r = kinematics.position(load.body, load.at)
        if load.kind == "moment":
            out.append(AppliedLoad(load.name, load.body, "moment", load.at, None, r, 0j, load.moment))
            continue
        if load.kind == "force" and load.working is None:
            out.append(AppliedLoad(load.name, load.body, load.kind, load.at, load.point, r, load.force, 0.0))
            continue
        v = kinematics.velocity(load.body, load.at)
        if load.kind == "force":
            force = load.force
        else:  # against the velocity of its point: −|F|·v/|v|, zero where v = 0
            speed = np.abs(v)
            force = np.where(speed > 0, -load.magnitude * v / np.where(speed > 0, speed, 1.0), 0j)
        if load.working is not None:  # over the working stroke only: while the point moves along `working`
            force = np.where(np.real(np.conj(load.working) * v) > 0, force, 0j)
        if np.ndim(force) == 0:
            force = complex(force)
        out.append(AppliedLoad(load.name, load.body, load.kind, load.at, load.point, r, force, 0.0))
    return tuple(out)
