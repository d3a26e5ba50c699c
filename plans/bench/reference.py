"""A 50-digit reference solution, independent of both of plans' methods.

The Cartesian constraint formulation of multibody kinematics: the unknowns are
the pose of every moving body, ``q = (φ, x, y)`` per body (its angle and the
global position of its own point (0, 0)), and the scene becomes a set of
constraint equations ``Φ(q, t) = 0``, one row per scalar condition:

* a **revolute** joint (a point name P shared by bodies 1 and 2)::

      r_O1 + e^{iφ1} z1 − r_O2 − e^{iφ2} z2 = 0          (2 rows: x and y)

* a **prismatic** joint (line s of the slider on line g of the guide, α their
  angles in the bodies' own frames, Q their origins)::

      sin(φ_s + α_s − φ_g − α_g) = 0                      (the lines are parallel)
      Im(conj(u_g)·(Q_s − Q_g)) = 0,  u_g = e^{i(φ_g + α_g)}  (Q_s lies on the guide)

* the **driver**, a crank: ``φ_c − (x₀ + ω t + ε t²/2) = 0`` (its pivot is a
  revolute with the frame); a linear driver with its point P on the frame
  line (Q, u)::

      φ_l − α_u = 0,   Im(conj(u)(P − Q)) = 0,   Re(conj(u)(P − Q)) − (s₀ + v t + a t²/2) = 0

A one-degree-of-freedom scene has as many rows as unknowns.  Positions come
from Newton's method at ``mp.dps = 50`` (:func:`mpmath.lu_solve` on the
Jacobian), seeded from a double-precision guess; velocities and
accelerations from the same Jacobian J = ∂Φ/∂q::

      J q̇ = −Φ_t                    (Φ̇ = J q̇ + Φ_t = 0)
      J q̈ = −(Φ̈ with q̈ = 0)       (Φ̈ = J q̈ + q̇ᵀΦ_qq q̇ + 2Φ_qt q̇ + Φ_tt = 0)

Every row is written with its first and second time derivatives in closed
form, from the motion of a body point ``r = r_O + e^{iφ} z``,
``v = v_O + iφ̇ e^{iφ} z``, ``a = a_O + (iφ̈ − φ̇²) e^{iφ} z``; the Jacobian's
column k is Φ̇ at q̇ = e_k less Φ̇ at q̇ = 0 (Φ̇ is affine in q̇, so this is
exact).  Nothing here uses the Assur groups, the loop-closure formulas of
:mod:`plans.analytic` or the plan geometry of :mod:`plans.graphical`: the
scene model is all that is shared.  The seed only decides which assembly
branch Newton converges to; the digits come from the iteration.

>>> from plans.scene import load, example_path
>>> scene = load(example_path("slider-crank"))
>>> import math
>>> seed = {"2": (math.radians(45), 0j), "3": (-0.083, 0.0707 + 0.0707j), "4": (0.0, 0.32 + 0.05j)}
>>> ref = reference(scene, math.radians(45), seed)
>>> print(mpmath.nstr(ref.links["3"][1], 12))
-59.4427656722
"""

from __future__ import annotations

from dataclasses import dataclass

import mpmath

from ..scene import FRAME, Crank, Scene

__all__ = ["DIGITS", "Reference", "ReferenceError", "reference"]

#: Working precision of the reference [decimal digits].
DIGITS = 50


class ReferenceError(ArithmeticError):
    """Newton's method did not converge, or converged away from the seed's branch."""


@dataclass(frozen=True)
class Reference:
    """The 50-digit motion of a scene at one driver position.

    Attributes
    ----------
    position : float
        The driver position (crank angle [rad] or linear-driver position [m]).
    points : dict[str, tuple[mpc, mpc, mpc]]
        Every named point: r [m], v [m/s], a [m/s²] as mpmath complex numbers.
    links : dict[str, tuple[mpf, mpf, mpf]]
        Every moving body: φ [rad], ω [rad/s], ε [rad/s²].
    iterations : int
        Newton steps taken from the seed.
    residual : float
        max |Φ(q)| at the solution, relative to the scene's size.
    """

    position: float
    points: dict
    links: dict
    iterations: int
    residual: float

    def complex(self, name: str) -> tuple[complex, complex, complex]:
        """r, v, a of a point rounded to double precision."""
        return tuple(complex(z) for z in self.points[name])


class _Body:
    """Motion of one body: pose, and its first and second time derivatives."""

    __slots__ = ("phi", "w", "e", "r", "v", "a", "turn")

    def __init__(self, phi, w, e, r, v, a):
        self.phi, self.w, self.e, self.r, self.v, self.a = phi, w, e, r, v, a
        self.turn = mpmath.expj(phi)

    def point(self, z) -> tuple:
        """r, v, a of the body's own point z: r_O + e^{iφ}z, v_O + iφ̇e^{iφ}z, a_O + (iφ̈ − φ̇²)e^{iφ}z."""
        ez = self.turn * z
        return self.r + ez, self.v + 1j * self.w * ez, self.a + (1j * self.e - self.w**2) * ez


def _cross(a, b):
    """Im(conj(a)·b)."""
    return a.real * b.imag - a.imag * b.real


def _dot(a, b):
    """Re(conj(a)·b)."""
    return a.real * b.real + a.imag * b.imag


class _Model:
    """The constraint rows of a scene, evaluated with their first and second time derivatives."""

    def __init__(self, scene: Scene):
        self.scene = scene
        self.moving = [name for name in scene.bodies if name != FRAME]
        self.index = {name: 3 * k for k, name in enumerate(self.moving)}
        mpf, mpc = mpmath.mpf, mpmath.mpc
        self.local = {
            name: {p: mpc(z.real, z.imag) for p, z in body.points.items()} for name, body in scene.bodies.items()
        }
        self.revolutes = []
        for point in scene.point_names:
            carriers = scene.bodies_with(point)
            for other in carriers[1:]:  # a point shared by k bodies: k − 1 joints
                self.revolutes.append((carriers[0], self.local[carriers[0]][point], other, self.local[other][point]))
        self.prismatics = []
        for pair in scene.prismatics:
            s_line = scene.bodies[pair.slider].lines[pair.slider_line]
            g_line = scene.bodies[pair.guide].lines[pair.guide_line]
            self.prismatics.append(
                (pair.slider, mpf(s_line.angle), mpc(s_line.origin.real, s_line.origin.imag),
                 pair.guide, mpf(g_line.angle), mpc(g_line.origin.real, g_line.origin.imag))
            )
        driver = scene.driver
        self.crank = isinstance(driver, Crank)
        self.rates = (mpf(driver.omega), mpf(driver.epsilon)) if self.crank else (mpf(driver.velocity), mpf(driver.acceleration))
        if not self.crank:
            guide = scene.frame.lines[driver.guide]
            self.guide_angle = mpf(guide.angle)
            self.guide_u = mpmath.expj(self.guide_angle)
            self.guide_q = mpc(guide.origin.real, guide.origin.imag)
            self.driver_point = self.local[driver.link][driver.point]
        self.size = self._size()

    def _size(self) -> mpmath.mpf:
        size = mpmath.mpf(0)
        for points in self.local.values():
            zs = list(points.values())
            for a in zs:
                for b in zs:
                    size = max(size, abs(a - b))
        return size if size > 0 else mpmath.mpf(1)

    def bodies(self, q, qd, qdd) -> dict[str, _Body]:
        zero = mpmath.mpf(0)
        out = {FRAME: _Body(zero, zero, zero, mpmath.mpc(0), mpmath.mpc(0), mpmath.mpc(0))}
        for name, k in self.index.items():
            out[name] = _Body(
                q[k], qd[k], qdd[k],
                mpmath.mpc(q[k + 1], q[k + 2]), mpmath.mpc(qd[k + 1], qd[k + 2]), mpmath.mpc(qdd[k + 1], qdd[k + 2]),
            )
        return out

    def rows(self, q, qd, qdd, x0):
        """(Φ, Φ̇, Φ̈) at time 0 for poses q, rates q̇ and q̈, the driver at x0."""
        b = self.bodies(q, qd, qdd)
        f0, f1, f2 = [], [], []
        for one, z1, two, z2 in self.revolutes:
            r1, v1, a1 = b[one].point(z1)
            r2, v2, a2 = b[two].point(z2)
            d0, d1, d2 = r1 - r2, v1 - v2, a1 - a2
            f0 += [d0.real, d0.imag]
            f1 += [d1.real, d1.imag]
            f2 += [d2.real, d2.imag]
        for slider, a_s, q_s, guide, a_g, q_g in self.prismatics:
            S, G = b[slider], b[guide]
            delta = S.phi + a_s - G.phi - a_g
            dd, ddd = S.w - G.w, S.e - G.e
            f0.append(mpmath.sin(delta))
            f1.append(mpmath.cos(delta) * dd)
            f2.append(mpmath.cos(delta) * ddd - mpmath.sin(delta) * dd**2)
            u = mpmath.expj(G.phi + a_g)
            u1 = 1j * G.w * u
            u2 = (1j * G.e - G.w**2) * u
            Qs, Qg = S.point(q_s), G.point(q_g)
            d0, d1, d2 = Qs[0] - Qg[0], Qs[1] - Qg[1], Qs[2] - Qg[2]
            f0.append(_cross(u, d0))
            f1.append(_cross(u1, d0) + _cross(u, d1))
            f2.append(_cross(u2, d0) + 2 * _cross(u1, d1) + _cross(u, d2))
        rate, rate2 = self.rates
        link = b[self.scene.driver.link]
        if self.crank:
            f0.append(link.phi - x0)
            f1.append(link.w - rate)
            f2.append(link.e - rate2)
        else:
            P = link.point(self.driver_point)
            u, Q = self.guide_u, self.guide_q
            f0 += [link.phi - self.guide_angle, _cross(u, P[0] - Q), _dot(u, P[0] - Q) - x0]
            f1 += [link.w, _cross(u, P[1]), _dot(u, P[1]) - rate]
            f2 += [link.e, _cross(u, P[2]), _dot(u, P[2]) - rate2]
        return f0, f1, f2

    def jacobian(self, q, x0):
        n = len(q)
        zero = [mpmath.mpf(0)] * n
        base = self.rows(q, zero, zero, x0)[1]
        if len(base) != n:
            raise ReferenceError(
                f"{self.scene.source}: {len(base)} constraint rows for {n} unknowns; the reference needs a "
                "one-degree-of-freedom scene"
            )
        J = mpmath.matrix(n, n)
        for k in range(n):
            unit = list(zero)
            unit[k] = mpmath.mpf(1)
            column = self.rows(q, unit, zero, x0)[1]
            for i in range(n):
                J[i, k] = column[i] - base[i]
        return J, base


def reference(
    scene: Scene, position: float, seed: dict, *, digits: int = DIGITS, max_steps: int = 40, max_move: float = 1e-2
) -> Reference:
    """Positions, velocities and accelerations of every point and body at *digits* digits.

    Parameters
    ----------
    scene : Scene
    position : float
        Driver position: crank angle [rad] or linear-driver position [m]; the
        driver's ω, ε (or velocity, acceleration) are the scene's.
    seed : dict[str, tuple[float, complex]]
        A double-precision guess of every moving body's pose, ``(φ, origin)``
        (for example ``AnalyticSolution.poses`` or ``GraphicalSolution.poses``
        at that position).  It chooses the assembly branch.
    digits : int
        Working precision [decimal digits]; Newton stops when a step is below
        10^(3 − digits) relative (lengths relative to the scene's size).
    max_steps : int
        Newton steps allowed.
    max_move : float
        How far the solution may lie from the seed (angles in rad, lengths
        relative to the scene's size) before it counts as another branch.

    Returns
    -------
    Reference

    Raises
    ------
    ReferenceError
        No convergence, or the solution lies far from the seed (another
        branch), or the scene does not have one degree of freedom.
    """
    with mpmath.workdps(digits):
        model = _Model(scene)
        x0 = mpmath.mpf(position)
        q = []
        for name in model.moving:
            phi, origin = seed[name]
            q += [mpmath.mpf(float(phi)), mpmath.mpf(complex(origin).real), mpmath.mpf(complex(origin).imag)]
        scale = [mpmath.mpf(1), model.size, model.size] * len(model.moving)
        start = list(q)
        tiny = mpmath.mpf(10) ** (3 - digits)
        steps = 0
        while True:
            J, _ = model.jacobian(q, x0)
            zero = [mpmath.mpf(0)] * len(q)
            f = model.rows(q, zero, zero, x0)[0]
            if steps >= max_steps:
                raise ReferenceError(f"{scene.source}: Newton's method did not converge in {max_steps} steps at {position!r}")
            try:
                step = mpmath.lu_solve(J, mpmath.matrix(f))
            except ZeroDivisionError:
                raise ReferenceError(
                    f"{scene.source}: the constraint Jacobian is singular at {position!r}: a dead centre"
                ) from None
            q = [qi - step[i] for i, qi in enumerate(q)]
            steps += 1
            if max(abs(step[i]) / scale[i] for i in range(len(q))) < tiny:
                break
        moved = max(abs(q[i] - start[i]) / scale[i] for i in range(len(q)))
        if moved > max_move:
            raise ReferenceError(
                f"{scene.source}: the reference converged {mpmath.nstr(moved, 3)} (relative) away from its seed "
                f"at {position!r}: the seed is on another branch or too rough"
            )
        zero = [mpmath.mpf(0)] * len(q)
        J, phi_t = model.jacobian(q, x0)
        residual = max(abs(r) for r in model.rows(q, zero, zero, x0)[0]) / model.size
        try:
            qd = mpmath.lu_solve(J, -mpmath.matrix(phi_t))
        except ZeroDivisionError:
            raise ReferenceError(f"{scene.source}: the constraint Jacobian is singular at {position!r}: a dead centre") from None
        qd = [qd[i] for i in range(len(q))]
        gamma = model.rows(q, qd, zero, x0)[2]
        qdd = mpmath.lu_solve(J, -mpmath.matrix(gamma))
        qdd = [qdd[i] for i in range(len(q))]
        bodies = model.bodies(q, qd, qdd)
        points = {}
        for name in scene.point_names:
            home = scene.home_of(name)
            points[name] = bodies[home].point(model.local[home][name])
        links = {name: (bodies[name].phi, bodies[name].w, bodies[name].e) for name in model.moving}
        return Reference(float(position), points, links, steps, float(residual))
