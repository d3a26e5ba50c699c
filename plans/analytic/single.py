"""One driver position in plain complex arithmetic: the dyads of :mod:`plans.analytic.dyads` without numpy.

At one (or a few) positions numpy's fixed cost per operation (about a
microsecond for an operation on a one-element array) is most of a solve: a
dyad takes ~30 operations.  Here each dyad is the same loop equation, solved
in the same steps and the same order as its vectorised twin in
:mod:`plans.analytic.dyads` (see the loop equation there), with Python's
``complex`` and ``math``/``cmath``: the same numbers to round-off (tested on
every bundled example and on seeded random mechanisms).

Only the ordinary case is solved here: a position where a group does not
assemble, sits at a dead centre, or gives a number that is not finite raises
:class:`NotHere`, and the solver solves that call by the vectorised path
instead, which reports it (NaN with ``allow_partial``, or the error naming
the group, joint, position and lengths).  So this module has no messages and
no masks.

Each solver takes the known states (:class:`Body`, :class:`Point`) and the
links' own coordinates as its twin does, and returns ``(i, j, sine,
condition, inner)``: the two links as :class:`Body`, the group's |sin| and
condition number (:func:`plans.analytic.dyads` ``_diagnose``), and the inner
joint's :class:`Point` where the dyad finds it directly (RRP, PRP) or None.
"""

from __future__ import annotations

import cmath
import math

from ..limits import REFUSE_SINE
from ..scene import Line
from .kinematics import track_in_guide

__all__ = ["NotHere", "Point", "Body", "resting", "driven", "solve_rrr", "solve_rrp", "solve_rpr", "solve_prp", "solve_rpp", "SOLVERS"]

_PI = math.pi


class NotHere(ArithmeticError):
    """The position is not an ordinary one (no assembly, a dead centre, a number not finite): solve it vectorised."""


class Point:
    """Position r [m], velocity v [m/s], acceleration a [m/s²] of a point at one position (complex numbers)."""

    __slots__ = ("r", "v", "a")

    def __init__(self, r: complex, v: complex, a: complex):
        self.r, self.v, self.a = r, v, a


class Body:
    """Pose and motion of a body at one position: φ, ω, ε, its origin's :class:`Point`, ``turn`` = e^{iφ}.

    The methods are those of :class:`plans.analytic.kinematics.BodyState`
    (the rigid-body theorems ``v = v_O + iω r_OZ``, ``a = a_O + (iε − ω²) r_OZ``).
    """

    __slots__ = ("phi", "omega", "epsilon", "origin", "turn")

    def __init__(self, phi: float, omega: float, epsilon: float, origin: Point, turn: complex):
        self.phi, self.omega, self.epsilon, self.origin, self.turn = phi, omega, epsilon, origin, turn

    def position(self, z: complex) -> complex:
        """Global position of the own point z: ``r_O + e^{iφ} z``."""
        return self.origin.r if z == 0 else self.origin.r + self.turn * z

    def direction(self, angle: float) -> complex:
        """Global unit vector of the own direction at *angle*: ``e^{iφ} e^{iα}``."""
        return self.turn if angle == 0 else self.turn * cmath.exp(1j * angle)

    def point(self, z: complex) -> Point:
        """State of the own point z."""
        origin = self.origin
        if z == 0:
            return origin
        r_OZ = self.turn * z
        return Point(origin.r + r_OZ, origin.v + 1j * self.omega * r_OZ, origin.a + (1j * self.epsilon - self.omega * self.omega) * r_OZ)

    def point_at(self, r: complex) -> Point:
        """State of the body's point that is at global r."""
        origin = self.origin
        r_Or = r - origin.r
        return Point(r, origin.v + 1j * self.omega * r_Or, origin.a + (1j * self.epsilon - self.omega * self.omega) * r_Or)


def resting() -> Body:
    """The frame."""
    return Body(0.0, 0.0, 0.0, Point(0j, 0j, 0j), 1 + 0j)


def from_point(phi: float, omega: float, epsilon: float, P: Point, z: complex, turn: complex) -> Body:
    """The body whose own point z is at P, turned by φ (``turn`` = e^{iφ}): origin ``r_O = r_P − e^{iφ} z``."""
    if z == 0:
        return Body(phi, omega, epsilon, P, turn)
    r_PO = -turn * z
    origin = Point(P.r + r_PO, P.v + 1j * omega * r_PO, P.a + (1j * epsilon - omega * omega) * r_PO)
    return Body(phi, omega, epsilon, origin, turn)


def driven(phi: float, omega: float, epsilon: float, P: Point, z: complex) -> Body:
    """A driver: :func:`from_point` with e^{iφ} formed here."""
    return from_point(phi, omega, epsilon, P, z, complex(math.cos(phi), math.sin(phi)))


# --- the steps every dyad shares (as in plans.analytic.dyads) ----------------------------


def _angle(turn: complex) -> float:
    """φ in (−π, π] of e^{iφ}."""
    phi = math.atan2(turn.imag, turn.real)
    return _PI if phi == -_PI else phi


def _link_turn(r: complex, own: complex) -> tuple[complex, float]:
    """(e^{iφ}, |r|) of a link whose own vector *own* lies along *r*."""
    length = abs(r)
    turn = r * (1.0 / length)
    own = own / abs(own)
    if own != 1:
        turn = turn * own.conjugate()
    return turn, length


def _turned(guide: Body, delta: float) -> tuple[float, complex]:
    """(φ, e^{iφ}) of a body turning with *guide*: φ = φ_g + δ."""
    turn = guide.direction(delta)
    return _angle(turn), turn


def _root(sin2: float) -> float:
    """√sin², a rounding-level negative as 0; :class:`NotHere` where there is no position."""
    if not sin2 >= -REFUSE_SINE**2:
        raise NotHere
    return math.sqrt(sin2) if sin2 > 0 else 0.0


def _cross(a: complex, b: complex) -> float:
    return a.real * b.imag - a.imag * b.real


def _dot(a: complex, b: complex) -> float:
    return a.real * b.real + a.imag * b.imag


def _diagnose(c1: complex, c2: complex, det: float, norms: float | None = None) -> tuple[float, float]:
    """(sine, condition) of the 2×2 matrix; :class:`NotHere` at a dead centre (or where it is not finite)."""
    if norms is None:
        norms = abs(c1) * abs(c2)
    sine = abs(det) / norms
    if not (REFUSE_SINE <= sine < math.inf):
        raise NotHere
    return sine, (1.0 + abs(_dot(c1, c2)) / norms) / sine


# --- the dyads ---------------------------------------------------------------------------


def solve_rrr(B: Point, D: Point, i_B: complex, i_C: complex, j_D: complex, j_C: complex, sign: int = 1):
    """RRR at one position: :func:`plans.analytic.dyads.solve_rrr` (C on the circles (B, BC), (D, DC))."""
    l_i = abs(i_C - i_B)
    l_j = abs(j_C - j_D)
    BD = D.r - B.r
    d = abs(BD)
    if not d > 0:
        raise NotHere
    d2 = d * d
    sin2 = ((l_i + l_j) ** 2 - d2) * (d2 - (l_i - l_j) ** 2) / (4 * l_i**2 * l_j**2)
    x = (l_i**2 - l_j**2 + d2) / (2 * d)
    h = _root(sin2) * l_i * l_j / d
    C = B.r + (x + 1j * sign * h) * BD / d
    r_BC = C - B.r
    r_DC = C - D.r
    turn_i, BC = _link_turn(r_BC, i_C - i_B)
    turn_j, DC = _link_turn(r_DC, j_C - j_D)
    c1, c2 = 1j * r_BC, -1j * r_DC
    det = _cross(c1, c2)
    sine, condition = _diagnose(c1, c2, det, BC * DC)
    rhs = D.v - B.v
    omega_i, omega_j = _cross(rhs, c2) / det, _cross(c1, rhs) / det  # [i(C − B)] ω_i + [−i(C − D)] ω_j = v_D − v_B
    rhs = D.a - B.a + omega_i**2 * r_BC - omega_j**2 * r_DC
    epsilon_i, epsilon_j = _cross(rhs, c2) / det, _cross(c1, rhs) / det
    i = from_point(_angle(turn_i), omega_i, epsilon_i, B, i_B, turn_i)
    j = from_point(_angle(turn_j), omega_j, epsilon_j, D, j_D, turn_j)
    return i, j, sine, condition, None


def solve_rrp(B: Point, i_B: complex, i_C: complex, j_C: complex, j_line: Line, guide: Body, guide_line: Line, sign: int = 1):
    """RRP at one position: :func:`plans.analytic.dyads.solve_rrp` (C where the track meets the circle (B, BC))."""
    l_i = abs(i_C - i_B)
    p0, alpha, delta = track_in_guide(guide_line, j_line, j_C)
    P0 = guide.position(p0)
    u = guide.direction(alpha)
    q = u.conjugate() * (B.r - P0)
    y = abs(q.imag)
    sin2 = (l_i - y) * (l_i + y) / l_i**2
    t = q.real + sign * l_i * _root(sin2)
    C = P0 + t * u
    r_BC = C - B.r
    turn_i, BC = _link_turn(r_BC, i_C - i_B)
    phi_j, turn_j = _turned(guide, delta)

    C_g = guide.point_at(C)
    c1, c2 = 1j * r_BC, -u
    det = _cross(c1, c2)
    sine, condition = _diagnose(c1, c2, det, BC * abs(u))
    rhs = C_g.v - B.v
    omega_i, t_dot = _cross(rhs, c2) / det, _cross(c1, rhs) / det
    v_rel = t_dot * u
    coriolis = 2j * guide.omega * v_rel
    rhs = C_g.a + coriolis - B.a + omega_i**2 * r_BC
    epsilon_i, t_ddot = _cross(rhs, c2) / det, _cross(c1, rhs) / det
    C_state = Point(C, C_g.v + v_rel, C_g.a + coriolis + t_ddot * u)
    i = from_point(_angle(turn_i), omega_i, epsilon_i, B, i_B, turn_i)
    j = from_point(phi_j, guide.omega, guide.epsilon, C_state, j_C, turn_j)
    return i, j, sine, condition, C_state


def solve_rpr(B: Point, E: Point, i_B: complex, i_line: Line, j_E: complex, j_line: Line, sign: int = 1):
    """RPR at one position: :func:`plans.analytic.dyads.solve_rpr` (the line through B's offset tangent to E's)."""
    m_i = cmath.exp(-1j * i_line.angle) * (i_line.origin - i_B)
    m_j = cmath.exp(-1j * j_line.angle) * (j_line.origin - j_E)
    k = (m_i - m_j).imag
    BE = E.r - B.r
    d = abs(BE)
    if not d > 0:
        raise NotHere
    sin2 = (d - abs(k)) * (d + abs(k)) / d**2
    c = d * _root(sin2)
    u = (sign * c - 1j * k) * BE / d**2
    turn_i = u if i_line.angle == 0 else u * cmath.exp(-1j * i_line.angle)
    phi_i = _angle(turn_i)
    if j_line.angle == i_line.angle:
        turn_j, phi_j = turn_i, phi_i
    else:
        turn_j = u * cmath.exp(-1j * j_line.angle)
        phi_j = _angle(turn_j)

    c1, c2 = 1j * BE, u
    det = _cross(c1, c2)
    sine, condition = _diagnose(c1, c2, det, d * abs(u))
    rhs = E.v - B.v
    omega, s_dot = _cross(rhs, c2) / det, _cross(c1, rhs) / det
    rhs = E.a - B.a + omega**2 * BE - 2j * omega * (s_dot * u)
    epsilon = _cross(rhs, c2) / det
    i = from_point(phi_i, omega, epsilon, B, i_B, turn_i)
    j = from_point(phi_j, omega, epsilon, E, j_E, turn_j)
    return i, j, sine, condition, None


def solve_prp(
    guide_i: Body, guide_i_line: Line, i_line: Line, i_C: complex, guide_j: Body, guide_j_line: Line, j_line: Line, j_C: complex
):
    """PRP at one position: :func:`plans.analytic.dyads.solve_prp` (C where the two tracks cross)."""
    p_i, alpha_i, delta_i = track_in_guide(guide_i_line, i_line, i_C)
    p_j, alpha_j, delta_j = track_in_guide(guide_j_line, j_line, j_C)
    P_i, u_i = guide_i.position(p_i), guide_i.direction(alpha_i)
    P_j, u_j = guide_j.position(p_j), guide_j.direction(alpha_j)
    c1, c2 = u_i, -u_j
    det = _cross(c1, c2)
    sine, condition = _diagnose(c1, c2, det)
    t_i = _cross(P_j - P_i, c2) / det
    C = P_i + t_i * u_i

    C_gi, C_gj = guide_i.point_at(C), guide_j.point_at(C)
    rhs = C_gj.v - C_gi.v
    ti_dot, tj_dot = _cross(rhs, c2) / det, _cross(c1, rhs) / det
    rhs = C_gj.a + 2j * guide_j.omega * (tj_dot * u_j) - C_gi.a - 2j * guide_i.omega * (ti_dot * u_i)
    ti_ddot = _cross(rhs, c2) / det
    v_rel, a_rel = ti_dot * u_i, ti_ddot * u_i
    C_state = Point(C, C_gi.v + v_rel, C_gi.a + 2j * guide_i.omega * v_rel + a_rel)
    phi_i, turn_i = _turned(guide_i, delta_i)
    phi_j, turn_j = _turned(guide_j, delta_j)
    i = from_point(phi_i, guide_i.omega, guide_i.epsilon, C_state, i_C, turn_i)
    j = from_point(phi_j, guide_j.omega, guide_j.epsilon, C_state, j_C, turn_j)
    return i, j, sine, condition, C_state


def solve_rpp(B: Point, i_B: complex, i_line: Line, j_inner_line: Line, j_outer_line: Line, guide: Body, guide_line: Line):
    """RPP at one position: :func:`plans.analytic.dyads.solve_rpp` (B's track in j crossing j's track on g)."""
    p_j, alpha_n, delta_n = track_in_guide(j_inner_line, i_line, i_B)
    p_0, alpha_g, delta_o = track_in_guide(guide_line, j_outer_line, p_j)
    P0 = guide.position(p_0)
    u_g = guide.direction(alpha_g)
    u_n = guide.direction(alpha_n + delta_o)
    c1, c2 = u_g, u_n
    det = _cross(c1, c2)
    sine, condition = _diagnose(c1, c2, det)
    t_n = _cross(c1, B.r - P0) / det

    B_g = guide.point_at(B.r)
    rhs = B.v - B_g.v
    to_dot, tn_dot = _cross(rhs, c2) / det, _cross(c1, rhs) / det
    v_rel_o, v_rel_n = to_dot * u_g, tn_dot * u_n
    rhs = B.a - B_g.a - 2j * guide.omega * (v_rel_o + v_rel_n)
    a_rel_n = (_cross(c1, rhs) / det) * u_n

    phi_j, turn_j = _turned(guide, delta_o)
    phi_i, turn_i = _turned(guide, delta_o + delta_n)
    i = from_point(phi_i, guide.omega, guide.epsilon, B, i_B, turn_i)
    B_j = Point(B.r, B.v - v_rel_n, B.a - 2j * guide.omega * v_rel_n - a_rel_n)
    B_in_j = p_j + t_n * cmath.exp(1j * alpha_n)
    j = from_point(phi_j, guide.omega, guide.epsilon, B_j, B_in_j, turn_j)
    return i, j, sine, condition, None


#: The solver of each kind of group.
SOLVERS = {"RRR": solve_rrr, "RRP": solve_rrp, "RPR": solve_rpr, "PRP": solve_prp, "RPP": solve_rpp}
