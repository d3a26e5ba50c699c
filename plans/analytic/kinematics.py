"""Kinematic states over N driver positions, and the theorems that relate them.

Everything here is a complex-number statement of plane kinematics, vectorised
over an array of N driver positions.  A point is ``r = x + iy`` [m], its
velocity ``v`` [m/s] and acceleration ``a`` [m/s²] likewise complex.  Angles
are measured from the +x axis, counter-clockwise positive; ω [rad/s] and
ε [rad/s²] are positive counter-clockwise, so the vector product ω × r is the
complex product ``1j * omega * r``.

The theorems, as the code computes them:

* two points A, B of one body (:func:`rigid_velocity`,
  :func:`rigid_acceleration`)::

      v_B = v_A + iω (r_B − r_A)
      a_B = a_A + iε (r_B − r_A) − ω² (r_B − r_A)

* a point C₃ of a body sliding with velocity v_rel along a guide carried by
  body g, C_g the point of g under C₃ (:func:`sliding_velocity`,
  :func:`sliding_acceleration`, :func:`coriolis_acceleration`)::

      v_C3 = v_Cg + v_rel
      a_C3 = a_Cg + 2iω_g v_rel + a_rel
"""

from __future__ import annotations

import cmath
import functools
from dataclasses import dataclass

import numpy as np

from ..scene import Line

__all__ = [
    "PointState",
    "BodyState",
    "rigid_velocity",
    "rigid_acceleration",
    "coriolis_acceleration",
    "coriolis_term",
    "sliding_velocity",
    "sliding_acceleration",
    "cross",
    "dot",
    "solve_real_2x2",
    "track_in_guide",
    "unit_vector",
    "is_number",
    "sum_terms",
]


# --- the theorems ------------------------------------------------------------
#
# A quantity the same at every position may be a plain number (see
# PointState).  Where it is a plain zero (the frame's velocity, the ω of a
# block on a fixed guide) the term it multiplies or the sum it enters is left
# out: ``sum_terms`` and ``_scaled`` spare an operation over all N positions that
# would add or produce zeros.  (Not the Coriolis term: a slider's aᵏ is NaN
# where the slider is not solved, even on a fixed guide.)


def _is_zero(x) -> bool:
    return is_number(x) and x == 0


def sum_terms(*terms):
    """The sum of the terms, leaving out plain zeros (0 if nothing is left)."""
    out = 0j
    for term in terms:
        if not _is_zero(term):
            out = term if _is_zero(out) else out + term
    return out


def _scaled(k, z):
    """k·z, or a plain zero if k is a plain zero."""
    return 0j if _is_zero(k) else k * z



def rigid_velocity(v_A, omega, r_AB):
    """Velocity of B on the body of A: ``v_B = v_A + iω r_AB``.

    Parameters
    ----------
    v_A : complex array [m/s]
    omega : float array [rad/s]
        Angular velocity of the body, counter-clockwise positive.
    r_AB : complex array [m]
        ``r_B − r_A``.
    """
    return sum_terms(v_A, _scaled(1j * omega, r_AB))


def rigid_acceleration(a_A, omega, epsilon, r_AB):
    """Acceleration of B on the body of A: ``a_B = a_A + iε r_AB − ω² r_AB``.

    The term ``iε r_AB`` is the tangential acceleration aᵗ_BA (⊥ AB), the term
    ``−ω² r_AB`` the normal acceleration aⁿ_BA (from B towards A, ω²·AB).
    """
    return sum_terms(a_A, _scaled(1j * epsilon - omega * omega, r_AB))


def coriolis_acceleration(omega_g, v_rel):
    """Coriolis acceleration ``aᵏ = 2 ω_g × v_rel = 2iω_g v_rel``.

    Parameters
    ----------
    omega_g : float array [rad/s]
        Angular velocity of the guide.
    v_rel : complex array [m/s]
        Velocity of the slider relative to the guide (a vector along the guide).
    """
    return 2j * omega_g * v_rel  # zero on a guide that does not turn, but NaN where v_rel is: not left out


def coriolis_term(omega_g, v_rel):
    """Coriolis acceleration ``2iω_g v_rel`` as a term of a sum: a plain zero, which :func:`sum_terms` leaves out, where ω_g is.

    For a sum whose other terms are NaN wherever v_rel is (a dyad's
    acceleration, solved with v_rel): on a guide that does not turn, it
    spares two operations over all positions that add zeros.
    """
    return _scaled(2j * omega_g, v_rel)


def sliding_velocity(v_Cg, v_rel):
    """Velocity of a sliding point: ``v_C3 = v_Cg + v_rel``."""
    return sum_terms(v_Cg, v_rel)


def sliding_acceleration(a_Cg, omega_g, v_rel, a_rel):
    """Acceleration of a sliding point: ``a_C3 = a_Cg + 2iω_g v_rel + a_rel``."""
    return sum_terms(a_Cg, coriolis_acceleration(omega_g, v_rel), a_rel)


# --- plane geometry in complex numbers ----------------------------------------


def cross(a, b):
    """z component of the vector product a × b: ``Im(conj(a)·b)``.

    Of two plain numbers, a numpy float: dividing by it follows numpy's
    rules (∞, NaN), as on arrays, not Python's ZeroDivisionError.
    """
    out = a.real * b.imag - a.imag * b.real
    return np.float64(out) if is_number(out) else out


def dot(a, b):
    """Scalar product a · b: ``Re(conj(a)·b)`` (of two plain numbers, a numpy float, as :func:`cross`)."""
    out = a.real * b.real + a.imag * b.imag
    return np.float64(out) if is_number(out) else out


def solve_real_2x2(c1, c2, rhs, det=None):
    """Real x1, x2 with ``c1·x1 + c2·x2 = rhs`` (Cramer's rule).

    Each complex column is a vector of known direction; this is the 2×2 real
    system ``[[Re c1, Re c2], [Im c1, Im c2]] · [x1, x2] = [Re rhs, Im rhs]``
    that every velocity and acceleration step of a dyad reduces to.

    ``det``, if given, is ``cross(c1, c2)``: a dyad's velocity and
    acceleration systems share the matrix, so it computes it once.
    """
    if det is None:
        det = cross(c1, c2)
    return cross(rhs, c2) / det, cross(c1, rhs) / det


def unit_vector(angle):
    """``e^{iθ}``, the unit vector at angle θ, as ``cos θ + i·sin θ``.

    For an array this fills the real and imaginary parts in place: numpy's
    ``np.exp(1j * θ)`` gives the same numbers but costs up to twice as much
    (it forms the complex argument first; 4.2 ms against 2.4 ms at 100 000
    angles).  A number gives a Python complex.
    """
    if is_number(angle):
        return cmath.exp(1j * angle)
    out = np.empty(np.shape(angle), dtype=complex)
    np.cos(angle, out=out.real)
    np.sin(angle, out=out.imag)
    return out


def track_in_guide(guide_line: Line, own_line: Line, z: complex) -> tuple[complex, float, float]:
    """The line that point z of a sliding body traces on its guide's body.

    A body x whose line ``own_line`` slides on ``guide_line`` of body g (same
    direction, so φ_x = φ_g + δ with δ = α_g − α_x) carries its point z
    (x's own coordinates) along a line fixed in g::

        z_global = Q_g + t·u_g + e^{iφ_x} (z − q_x)        (q_x: own_line's origin)
                 = g's point  q_g + e^{iδ}(z − q_x)  moved by  t·u_g

    Returns
    -------
    p0 : complex
        A point of the track, in g's own coordinates [m].
    angle : float
        The track's direction in g's coordinates [rad] (that of ``guide_line``).
    delta : float
        φ_x − φ_g [rad].
    """
    delta = guide_line.angle - own_line.angle
    p0 = guide_line.origin + cmath.exp(1j * delta) * (z - own_line.origin)
    return p0, guide_line.angle, delta


# --- states -------------------------------------------------------------------


def is_number(x) -> bool:
    """True for a plain number (a quantity the same at every position), False for an array over the positions.

    (``getattr`` rather than numpy's ``ndim`` function, three times as
    fast: the solver asks this of most quantities.)
    """
    return getattr(x, "ndim", 0) == 0


def _all_finite(*values) -> bool:
    """No NaN or ∞ in any of the values (numbers or arrays).

    One sum per array: a NaN or ∞ makes the sum NaN or ∞.  (A sum of finite
    numbers that overflows answers False, which only costs the caller its
    shortcut.)
    """
    return all(np.isfinite(value if is_number(value) else value.sum()) for value in values)


@dataclass(frozen=True, eq=False)
class PointState:
    """Position r [m], velocity v [m/s], acceleration a [m/s²] of a point: complex arrays (N,).

    Any of them may be a plain number where it is the same at every position
    (a frame point, a zero velocity): numpy broadcasts it, and the solver
    spares the arithmetic on arrays of copies.
    """

    r: np.ndarray
    v: np.ndarray
    a: np.ndarray


@dataclass(frozen=True, eq=False)
class BodyState:
    """Pose and motion of a body over N positions.

    Attributes
    ----------
    phi, omega, epsilon : float arrays (N,)
        Angle of the body's own x axis [rad], ω [rad/s], ε [rad/s²]; each
        may be a plain number where it is the same at every position (the
        frame, a driver's ω and ε, a block on a fixed guide).
    origin : PointState
        The body's own point (0, 0): global position, velocity, acceleration.
    """

    phi: np.ndarray
    omega: np.ndarray
    epsilon: np.ndarray
    origin: PointState

    @classmethod
    def resting(cls) -> "BodyState":
        """The frame: φ = 0, origin at 0, nothing moves.

        Every quantity is a plain zero, the same at every position
        (:attr:`at_rest`).
        """
        state = cls(0.0, 0.0, 0.0, PointState(0j, 0j, 0j))
        state.__dict__.update(at_rest=True, turn=1 + 0j)
        return state

    @classmethod
    def from_point(cls, phi, omega, epsilon, point: PointState, z: complex, turn=None) -> "BodyState":
        """The body whose own point z is at ``point``, turned by φ, with ω and ε.

        The origin follows by the rigid-body theorems from the point:
        ``r_O = r_P − e^{iφ} z``, ``v_O = v_P + iω (r_O − r_P)``,
        ``a_O = a_P + (iε − ω²)(r_O − r_P)``.

        ``turn``, if given, is ``e^{iφ}`` already known (a dyad has it as a
        unit vector before it has φ).  Most links are drawn with their
        first point at (0, 0): with z = 0 the origin *is* the point, which
        spares six operations on arrays, unless φ, ω or ε is NaN somewhere
        (a group not assembled, a dead centre): there the formulas make the
        origin NaN too, and they are kept.
        """
        if turn is None:
            turn = unit_vector(phi)
        if is_number(z) and z == 0 and _all_finite(phi, omega, epsilon):  # φ is finite where e^{iφ} is
            origin = point
        else:
            r_PO = -turn * z
            origin = PointState(
                sum_terms(point.r, r_PO),
                rigid_velocity(point.v, omega, r_PO),
                rigid_acceleration(point.a, omega, epsilon, r_PO),
            )
        state = cls(phi, omega, epsilon, origin)
        state.__dict__["turn"] = turn  # the cached e^{iφ}
        return state

    @functools.cached_property
    def turn(self) -> np.ndarray:
        """``e^{iφ}``, the body's rotation as a unit complex number."""
        return unit_vector(self.phi)

    @functools.cached_property
    def at_rest(self) -> bool:
        """True if the body never moves: ω, ε and its origin's v and a are plain zeros (the frame)."""
        return all(is_number(x) and x == 0 for x in (self.omega, self.epsilon, self.origin.v, self.origin.a))

    def position(self, z) -> np.ndarray:
        """Global position of the body's own point z [m]: ``r_O + e^{iφ} z``."""
        if is_number(z) and z == 0:
            return self.origin.r
        return sum_terms(self.origin.r, self.turn * z)

    def direction(self, angle: float) -> np.ndarray:
        """Global unit vector of a direction at ``angle`` in the body's own frame: ``e^{iφ} e^{iα}``."""
        if angle == 0:
            return self.turn
        return self.turn * cmath.exp(1j * angle)

    def point_at(self, r) -> PointState:
        """State of the body's point that is at global r at this instant (rigid-body theorems)."""
        if self.at_rest:
            return PointState(r, 0j, 0j)  # the frame's points do not move: spare two products by zero
        r_Or = r - self.origin.r
        return PointState(
            r,
            rigid_velocity(self.origin.v, self.omega, r_Or),
            rigid_acceleration(self.origin.a, self.omega, self.epsilon, r_Or),
        )

    def point(self, z) -> PointState:
        """State of the body's own point z: from the origin O by the rigid-body theorems with ``r_OZ = e^{iφ} z``.

        (``point_at(position(z))`` gives the same but forms r_OZ again as
        ``r − r_O``, one more operation and a rounding more.)
        """
        if is_number(z) and z == 0:
            return self.origin
        r_OZ = self.turn * z
        return PointState(
            sum_terms(self.origin.r, r_OZ),
            rigid_velocity(self.origin.v, self.omega, r_OZ),
            rigid_acceleration(self.origin.a, self.omega, self.epsilon, r_OZ),
        )
