"""Class-II Assur groups (dyads) by the complex-number (loop-closure) method.

Each ``solve_*`` function solves one dyad over N driver positions at once:

* **position** from the loop equation in closed form (circle–circle,
  line–circle, line–line);
* **velocity** from the loop differentiated once, a 2×2 real linear system in
  the two unknown rates;
* **acceleration** from the loop differentiated twice: the same matrix, the
  right-hand side collecting every term that is already known (normal and
  Coriolis components included).

Links are ordered as in :mod:`plans.structure`: link i has the outer joint
``outer_i`` with a known body, link j the outer joint ``outer_j``, and
``inner`` joins i and j.  The inputs are the known motions (a
:class:`~plans.analytic.kinematics.PointState` for a known point, a
:class:`~plans.analytic.kinematics.BodyState` for a known body carrying a
guide) and the own coordinates of the links' points and lines; the result is
the motion of both links.

Prismatic pairs: the two lines coincide and point the same way, so the two
bodies turn together (equal φ + α, equal ω and ε) whichever of them is the
slider.

**Assembly branch** (one convention for all dyads; ``sign`` is +1 or −1):

* RRR: +1 puts the inner joint C to the LEFT of the directed line from B
  (outer joint of i) to D (outer joint of j): ``Im(conj(D − B)·(C − B)) > 0``.
* RRP: +1 takes the intersection further along u, the direction of the known
  body's line in the outer prismatic pair (the larger projection on u).
* RPR: +1 makes the common line direction u point from B (outer joint of i)
  towards E (outer joint of j): ``u·(E − B) > 0``.
* PRP, RPP: one solution, no sign.

A fixed sign follows one branch continuously: it can only change meaning at
a dead centre, where the two solutions meet.

**Dead centres.**  Where the two construction lines of the velocity plan
(the columns of the 2×2 matrix) are parallel to working precision (|sin| of
their angle below :data:`SINGULAR_SINE`) the velocities do not exist: the
result holds NaN in ω, ε, v and a there and ``singular`` is True.  For PRP
and RPP the positions themselves do not exist there (parallel guides).
A discriminant that is negative only by rounding (relative size below
:data:`SINGULAR_SINE` ²) is taken as zero: an exactly stretched or folded dyad
is a dead centre, not a failed assembly.
"""

from __future__ import annotations

import cmath
import functools
from dataclasses import dataclass, field

import numpy as np

from ..limits import REFUSE_SINE
from ..scene import Line
from .kinematics import (
    BodyState,
    PointState,
    sum_terms,
    coriolis_term,
    cross,
    dot,
    is_number,
    sliding_acceleration,
    sliding_velocity,
    coriolis_acceleration,
    solve_real_2x2,
    track_in_guide,
)

__all__ = [
    "SINGULAR_SINE",
    "DyadSolution",
    "solve_rrr",
    "solve_rrp",
    "solve_rpr",
    "solve_prp",
    "solve_rpp",
]

#: |sin| of the angle between the two construction lines below which a
#: position counts as a dead centre: :data:`plans.limits.REFUSE_SINE`, the
#: policy both methods share.  Near a dead centre the sine behaves like
#: the square root of the loop's discriminant, which rounding knows only to
#: about 1e-15 relative: a sine below ~3e-8 cannot be told from zero.
SINGULAR_SINE = REFUSE_SINE


@dataclass(frozen=True, eq=False)
class DyadSolution:
    """Motion of the two links of a dyad over N positions.

    Attributes
    ----------
    i, j : BodyState
        The links in the group's order.  NaN where not ``assembled``; ω, ε and
        the velocities and accelerations are NaN where ``singular``.
    assembled : bool array (N,)
        The position exists.
    singular : bool array (N,)
        At a dead centre (construction lines parallel): the velocities do not
        exist.  RRR, RRP, RPR are assembled there; PRP and RPP, whose
        position is solved with the same matrix, are not assembled either.
    sine : float array (N,)
        |sin| of the angle between the two construction lines.
    condition : float array (N,)
        Condition number of the velocity matrix with unit columns
        (:func:`_diagnose`; see :mod:`plans.limits`).
    measures : dict[str, numpy.ndarray or float]
        The lengths that decide the assembly, for messages [m]; a length of
        the links themselves is a float.
    inner : PointState or None
        The motion of the inner revolute joint C, where the dyad finds it
        directly (RRP, PRP: from the travel along the guide): one point of
        both links.
    """

    i: BodyState
    j: BodyState
    assembled: np.ndarray
    singular: np.ndarray
    sine: np.ndarray
    condition: np.ndarray
    measures: dict[str, np.ndarray | float] = field(default_factory=dict)
    inner: PointState | None = None


def _quiet(function):
    """Run a dyad solver with numpy's floating-point warnings off: failures are reported as masks."""

    @functools.wraps(function)
    def wrapper(*args, **kwargs):
        with np.errstate(all="ignore"):
            return function(*args, **kwargs)

    return wrapper


def _assembles(sin2):
    """Where sin² of the construction angle admits a position: ``sin² ≥ −SINGULAR_SINE²``.

    A negative sin² of rounding size is an exactly stretched or folded dyad
    (a dead centre), not a failed assembly; :func:`_root` takes it as 0.
    """
    return sin2 >= -SINGULAR_SINE**2


def _root(sin2, assembled):
    """√sin² where *assembled* (rounding-level negatives as 0), NaN elsewhere (``np.where`` only if somewhere)."""
    root = np.sqrt(np.maximum(sin2, 0.0))
    return root if assembled.all() else np.where(assembled, root, np.nan)


def _nan_where(mask, *arrays):
    """The arrays with NaN where *mask* holds (the arrays themselves where it holds nowhere)."""
    if not mask.any():
        return arrays
    return tuple(np.where(mask, np.nan, x) for x in arrays)


def _wrap(phi):
    """Angle in (−π, π]."""
    return np.pi - np.remainder(np.pi - phi, 2 * np.pi)


def _angle(turn):
    """The angle φ in (−π, π] of the unit vector ``turn = e^{iφ}``.

    ``np.angle`` already lies in [−π, π] and is the one transcendental call
    a link's angle needs (``_wrap`` of a difference of angles costs twice
    as much, ``np.remainder`` being slow); only an exact −π (Im = −0) is
    moved to π.
    """
    phi = np.angle(turn)
    if is_number(phi):
        return np.pi if phi == -np.pi else phi
    np.putmask(phi, phi == -np.pi, np.pi)
    return phi


def _unit(z: complex) -> complex:
    """z/|z| for a constant of the scene (the own direction of a link's pin-to-pin line)."""
    return z / abs(z)


def _link_turn(r, own):
    """(e^{iφ}, |r|) of a link whose own vector *own* lies along the global vector *r*.

    ``e^{iφ} = (r/|r|) · conj(own/|own|)``: the angle φ = arg r − arg own
    without forming either angle, and |r| for the diagnosis, which needs it
    too.
    """
    length = np.abs(r)
    turn = r * (1.0 / length)  # a complex array divided by a real one costs twice this
    own = _unit(own)
    if own != 1:
        turn = turn * own.conjugate()
    return turn, length


def _turned(guide: BodyState, delta: float):
    """(φ, e^{iφ}) of a body turning with *guide*: φ = φ_g + δ in (−π, π]."""
    turn = guide.direction(delta)
    if is_number(guide.phi):
        return _wrap(guide.phi + delta), turn
    return _angle(turn), turn


def _diagnose(assembled, c1, c2, det, norms=None, positions_need_matrix=False):
    """(assembled, singular, sine, condition) from the two columns of the 2×2 matrix.

    ``det`` is ``cross(c1, c2)`` and ``norms``, if known, ``|c1|·|c2|``
    (each dyad has them already: computing them again cost a fifth of
    the dyad).  The sine of the angle between the columns, and the
    condition number of the 2×2 matrix with its columns scaled to unit
    length (independent of the unit system; see :mod:`plans.limits`)::

        sin γ = |c1 × c2| / (|c1| |c2|),   cond = (1 + |c1 · c2| / (|c1| |c2|)) / sin γ

    1 and 1 for perpendicular columns; 0 and ∞ at a dead centre.

    With ``positions_need_matrix`` (PRP, RPP: the position is solved with the
    same matrix) a singular position is not assembled either.
    """
    if norms is None:
        norms = np.abs(c1) * np.abs(c2)
    sine = np.abs(det) / norms
    cos = np.abs(dot(c1, c2)) / norms
    # (1 + |cos|)/|sin| == sqrt((1 + |cos|)/(1 − |cos|)) without cancellation near 1
    condition = (1.0 + cos) / sine
    singular = assembled & ~(sine >= SINGULAR_SINE)
    if positions_need_matrix:
        assembled = assembled & ~singular
    return assembled, singular, sine, condition


@_quiet
def solve_rrr(B: PointState, D: PointState, i_B: complex, i_C: complex, j_D: complex, j_C: complex, sign: int = 1) -> DyadSolution:
    """RRR: two links pinned to known points B and D and to each other at C.

    ::

                 C
                 o
          (i)  /   \\  (j)
              /     \\
        B  o           o  D          joints in order: B (outer_i), C (inner), D (outer_j)
          known        known

    Loop ``r_B + r_BC e^{iθ_i} = r_D + r_DC e^{iθ_j}`` (θ the directions of BC, DC):

    * position: C is an intersection of the circles (B, BC) and (D, DC)::

          d = |BD|,  e = (D − B)/d,  x = (BC² − DC² + d²) / 2d,
          h² = ((BC + DC)² − d²)(d² − (BC − DC)²) / 4d²,
          C = B + (x + i·sign·h) e

    * velocity, unknowns ω_i, ω_j::

          v_B + iω_i (C − B) = v_D + iω_j (C − D)
          ⇒ [i(C − B)] ω_i + [−i(C − D)] ω_j = v_D − v_B

    * acceleration, unknowns ε_i, ε_j, same matrix::

          a_B + iε_i (C − B) − ω_i²(C − B) = a_D + iε_j (C − D) − ω_j²(C − D)
          ⇒ [i(C − B)] ε_i + [−i(C − D)] ε_j = a_D − a_B + ω_i²(C − B) − ω_j²(C − D)

    Parameters
    ----------
    B, D : PointState
        The known points of the outer joints.
    i_B, i_C : complex
        B and C in link i's own coordinates [m].
    j_D, j_C : complex
        D and C in link j's own coordinates [m].
    sign : {+1, −1}
        +1: C to the left of the directed line B → D.

    Returns
    -------
    DyadSolution
        ``measures``: ``distance`` |BD|, ``sum`` BC + CD, ``difference`` |BC − CD|.
    """
    l_i = abs(i_C - i_B)
    l_j = abs(j_C - j_D)
    BD = D.r - B.r
    d = np.abs(BD)
    d2 = d * d
    # sin² of the angle BCD between the links, in the factored (Heron) form
    sin2 = ((l_i + l_j) ** 2 - d2) * (d2 - (l_i - l_j) ** 2) / (4 * l_i**2 * l_j**2)
    assembled = _assembles(sin2) & (d > 0)
    x = (l_i**2 - l_j**2 + d2) / (2 * d)
    h = _root(sin2, assembled) * l_i * l_j / d
    C = B.r + (x + 1j * sign * h) * BD / d
    r_BC = C - B.r
    r_DC = C - D.r
    # e^{iφ} = (C − B)/|C − B| · conj of the link's own unit vector BC; φ = its angle
    turn_i, BC = _link_turn(r_BC, i_C - i_B)
    turn_j, DC = _link_turn(r_DC, j_C - j_D)
    phi_i, phi_j = _angle(turn_i), _angle(turn_j)

    c1, c2 = 1j * r_BC, -1j * r_DC
    det = cross(c1, c2)
    omega_i, omega_j = solve_real_2x2(c1, c2, D.v - B.v, det)
    rhs = D.a - B.a + omega_i**2 * r_BC - omega_j**2 * r_DC
    epsilon_i, epsilon_j = solve_real_2x2(c1, c2, rhs, det)

    assembled, singular, sine, condition = _diagnose(assembled, c1, c2, det, BC * DC)  # |c1| = BC, |c2| = DC
    measures = {"distance": d, "sum": l_i + l_j, "difference": abs(l_i - l_j)}
    omega_i, omega_j, epsilon_i, epsilon_j = _nan_where(singular, omega_i, omega_j, epsilon_i, epsilon_j)
    i = BodyState.from_point(phi_i, omega_i, epsilon_i, B, i_B, turn_i)
    j = BodyState.from_point(phi_j, omega_j, epsilon_j, D, j_D, turn_j)
    return DyadSolution(i, j, assembled, singular, sine, condition, measures)


@_quiet
def solve_rrp(
    B: PointState,
    i_B: complex,
    i_C: complex,
    j_C: complex,
    j_line: Line,
    guide: BodyState,
    guide_line: Line,
    sign: int = 1,
) -> DyadSolution:
    """RRP: link i pinned at known B and at C to link j, whose line slides on a known body's line.

    ::

        B o
           \\  (i)
            \\
           C o──┐ (j)  block (or link) pinned at C, its line on g's
        ═══════╧══╧══════▶ u      guide line of the known body g (may turn: Coriolis)

        joints in order: B (outer_i, R), C (inner, R), j on g (outer_j, P)

    j turns with g (φ_j = φ_g + α_g − α_j), so its point C runs along a line
    fixed in g: ``C = P₀ + t·u`` (P₀, u carried by g; see
    :func:`~plans.analytic.kinematics.track_in_guide`).  The line may be offset
    from C and from every pivot, and j may be the block or carry the line.

    Loop ``r_B + r_BC e^{iθ_i} = P₀ + t u``:

    * position: the line meets the circle (B, BC)::

          p = B − P₀,  x = p·u = Re(conj(u) p),  y = |Im(conj(u) p)|  (distance of B from the track),
          h² = BC² − y²,  t = x + sign·h,  C = P₀ + t u

    * velocity, unknowns ω_i, ṫ (C_g: the point of g under C)::

          v_B + iω_i (C − B) = v_Cg + ṫ u
          ⇒ [i(C − B)] ω_i + [−u] ṫ = v_Cg − v_B

    * acceleration, unknowns ε_i, ẗ, same matrix (Coriolis 2iω_g ṫ u)::

          a_B + iε_i (C − B) − ω_i²(C − B) = a_Cg + 2iω_g ṫ u + ẗ u
          ⇒ [i(C − B)] ε_i + [−u] ẗ = a_Cg + 2iω_g ṫ u − a_B + ω_i²(C − B)

    Parameters
    ----------
    B : PointState
        The known point of the outer revolute.
    i_B, i_C : complex
        B and C in link i's coordinates [m].
    j_C : complex
        C in link j's coordinates [m].
    j_line : Line
        j's line of the outer prismatic pair (j's coordinates).
    guide : BodyState
        The known body g carrying the other line.
    guide_line : Line
        g's line of the outer prismatic pair (g's coordinates).
    sign : {+1, −1}
        +1: the intersection with the larger t (further along u).

    Returns
    -------
    DyadSolution
        ``measures``: ``distance`` of B from C's track, ``length`` BC.
    """
    l_i = abs(i_C - i_B)
    p0, alpha, delta = track_in_guide(guide_line, j_line, j_C)
    P0 = guide.position(p0)
    u = guide.direction(alpha)
    p = B.r - P0
    q = np.conj(u) * p  # x + iy: p in the track's own axes (one product for the dot and the cross)
    x = q.real
    y = np.abs(q.imag)
    sin2 = (l_i - y) * (l_i + y) / l_i**2
    assembled = _assembles(sin2)
    t = x + sign * l_i * _root(sin2, assembled)
    C = P0 + t * u
    r_BC = C - B.r
    turn_i, BC = _link_turn(r_BC, i_C - i_B)
    phi_i = _angle(turn_i)
    phi_j, turn_j = _turned(guide, delta)

    C_g = guide.point_at(C)
    c1, c2 = 1j * r_BC, -u
    det = cross(c1, c2)
    omega_i, t_dot = solve_real_2x2(c1, c2, C_g.v - B.v, det)
    v_rel = t_dot * u
    coriolis = coriolis_term(guide.omega, v_rel)
    rhs = sum_terms(C_g.a, coriolis) - B.a + omega_i**2 * r_BC
    epsilon_i, t_ddot = solve_real_2x2(c1, c2, rhs, det)

    assembled, singular, sine, condition = _diagnose(assembled, c1, c2, det, BC * np.abs(u))  # |c1| = BC, |c2| = |u|
    measures = {"distance": y, "length": l_i}
    if singular.any():
        omega_i, epsilon_i, t_dot, t_ddot = _nan_where(singular, omega_i, epsilon_i, t_dot, t_ddot)
        v_rel = t_dot * u
        coriolis = coriolis_term(guide.omega, v_rel)
    C_state = PointState(C, sliding_velocity(C_g.v, v_rel), sum_terms(C_g.a, coriolis, t_ddot * u))  # a_Cg + 2iω_g v_rel + a_rel
    i = BodyState.from_point(phi_i, omega_i, epsilon_i, B, i_B, turn_i)
    j = BodyState.from_point(phi_j, guide.omega, guide.epsilon, C_state, j_C, turn_j)
    return DyadSolution(i, j, assembled, singular, sine, condition, measures, C_state)


@_quiet
def solve_rpr(
    B: PointState,
    E: PointState,
    i_B: complex,
    i_line: Line,
    j_E: complex,
    j_line: Line,
    sign: int = 1,
) -> DyadSolution:
    """RPR: link i pinned at known B carries a line on which link j, pinned at known E, slides.

    ::

                          ┌───┐ (j) sleeve / block, pinned at E
        B o═══════════════╪═══╪══════▶ u     i's line (rod, slot), j's line on it
          (i)             └─o─┘
                            E

        joints in order: B (outer_i, R), j on i (inner, P), E (outer_j, R)

    The swinging block, slotted lever and inverted slider-crank.  Both lines
    may be offset from the pins and at any angle to the links (a sleeve welded
    at an angle): with θ the common line angle, i's line origin is
    ``Q_i = B + e^{iθ} m_i`` and j's ``Q_j = E + e^{iθ} m_j``, the constants
    ``m = e^{−iα}(q − pin)`` being the line origins relative to the pins in
    line-aligned coordinates.

    Loop ``r_B + e^{iθ} m_i + s e^{iθ} = r_E + e^{iθ} m_j`` (s: travel of j's
    line origin along i's line, from i's line origin):

    * position: the line lies at the signed distances Im(m_i), Im(m_j) from B
      and E, so with Δ = E − B and k = Im(m_i − m_j)::

          Im(conj(u) Δ) = k,   Re(conj(u) Δ) = sign·c,   c = √(|Δ|² − k²)
          u = e^{iθ} = (sign·c − i k) Δ / |Δ|²,   s = sign·c + Re(m_j − m_i)

    * velocity, unknowns ω (both links), ṡ::

          v_B + iω Δ + ṡ u = v_E        (v of i's point at E, plus the sliding)
          ⇒ [iΔ] ω + [u] ṡ = v_E − v_B

    * acceleration, unknowns ε, s̈, same matrix (Coriolis 2iω ṡ u)::

          a_B + iε Δ − ω² Δ + 2iω ṡ u + s̈ u = a_E
          ⇒ [iΔ] ε + [u] s̈ = a_E − a_B + ω² Δ − 2iω ṡ u

    Parameters
    ----------
    B, E : PointState
        The known points of the outer revolutes of i and j.
    i_B : complex
        B in link i's coordinates [m].
    i_line : Line
        i's line of the inner prismatic pair (i is its guide).
    j_E : complex
        E in link j's coordinates [m].
    j_line : Line
        j's line of the inner pair (j slides).
    sign : {+1, −1}
        +1: u·(E − B) > 0.

    Returns
    -------
    DyadSolution
        ``measures``: ``distance`` |BE|, ``offset`` |k|.
    """
    m_i = cmath.exp(-1j * i_line.angle) * (i_line.origin - i_B)
    m_j = cmath.exp(-1j * j_line.angle) * (j_line.origin - j_E)
    k = (m_i - m_j).imag
    BE = E.r - B.r
    d = np.abs(BE)
    sin2 = (d - abs(k)) * (d + abs(k)) / d**2
    assembled = _assembles(sin2) & (d > 0)
    c = d * _root(sin2, assembled)
    u = (sign * c - 1j * k) * BE / d**2
    # the links' own x axes: e^{iφ} = u e^{−iα} (α the line's own angle); one angle if the α are equal
    turn_i = u if i_line.angle == 0 else u * cmath.exp(-1j * i_line.angle)
    phi_i = _angle(turn_i)
    if j_line.angle == i_line.angle:
        turn_j, phi_j = turn_i, phi_i
    else:
        turn_j = u * cmath.exp(-1j * j_line.angle)
        phi_j = _angle(turn_j)

    c1, c2 = 1j * BE, u
    det = cross(c1, c2)
    omega, s_dot = solve_real_2x2(c1, c2, E.v - B.v, det)
    rhs = E.a - B.a + omega**2 * BE - coriolis_acceleration(omega, s_dot * u)
    epsilon, _s_ddot = solve_real_2x2(c1, c2, rhs, det)

    assembled, singular, sine, condition = _diagnose(assembled, c1, c2, det, d * np.abs(u))  # |c1| = |BE| = d
    measures = {"distance": d, "offset": abs(k)}
    omega, epsilon = _nan_where(singular, omega, epsilon)
    i = BodyState.from_point(phi_i, omega, epsilon, B, i_B, turn_i)
    j = BodyState.from_point(phi_j, omega, epsilon, E, j_E, turn_j)
    return DyadSolution(i, j, assembled, singular, sine, condition, measures)


@_quiet
def solve_prp(
    guide_i: BodyState,
    guide_i_line: Line,
    i_line: Line,
    i_C: complex,
    guide_j: BodyState,
    guide_j_line: Line,
    j_line: Line,
    j_C: complex,
) -> DyadSolution:
    """PRP: two links, each sliding on a known body's line, pinned to each other at C.

    ::

                      C
              (i) ┌───o───┐ (j)
        ══════════╧══▶   ╲ ╲
          guide of i      ╲ ╲  guide of j
                           ╲ ╲▶

        joints in order: i on g_i (outer_i, P), C (inner, R), j on g_j (outer_j, P)

    Each link turns with its guide body, so C runs along a line fixed in g_i,
    ``C = P_i + t_i u_i``, and along one fixed in g_j, ``C = P_j + t_j u_j``
    (either guide may move: Coriolis).

    Loop ``P_i + t_i u_i = P_j + t_j u_j``:

    * position (line–line)::

          [u_i] t_i + [−u_j] t_j = P_j − P_i

    * velocity, unknowns ṫ_i, ṫ_j (C_gi, C_gj: the guides' points under C)::

          v_Cgi + ṫ_i u_i = v_Cgj + ṫ_j u_j
          ⇒ [u_i] ṫ_i + [−u_j] ṫ_j = v_Cgj − v_Cgi

    * acceleration, unknowns ẗ_i, ẗ_j, same matrix::

          a_Cgi + 2iω_gi ṫ_i u_i + ẗ_i u_i = a_Cgj + 2iω_gj ṫ_j u_j + ẗ_j u_j
          ⇒ [u_i] ẗ_i + [−u_j] ẗ_j = a_Cgj + 2iω_gj ṫ_j u_j − a_Cgi − 2iω_gi ṫ_i u_i

    Parameters
    ----------
    guide_i, guide_j : BodyState
        The known bodies of the outer prismatic pairs.
    guide_i_line, guide_j_line : Line
        Their lines in those pairs.
    i_line, j_line : Line
        The links' own lines in those pairs.
    i_C, j_C : complex
        C in the links' coordinates [m].

    Returns
    -------
    DyadSolution
        No sign: one solution, none where the two tracks are parallel.
    """
    p_i, alpha_i, delta_i = track_in_guide(guide_i_line, i_line, i_C)
    p_j, alpha_j, delta_j = track_in_guide(guide_j_line, j_line, j_C)
    P_i, u_i = guide_i.position(p_i), guide_i.direction(alpha_i)
    P_j, u_j = guide_j.position(p_j), guide_j.direction(alpha_j)
    c1, c2 = u_i, -u_j
    det = cross(c1, c2)
    t_i, _t_j = solve_real_2x2(c1, c2, P_j - P_i, det)
    known = np.isfinite(c1) & np.isfinite(c2) & np.isfinite(P_j - P_i)
    assembled, singular, sine, condition = _diagnose(known, c1, c2, det, positions_need_matrix=True)
    measures = {}
    (t_i,) = _nan_where(~assembled, t_i)
    C = P_i + t_i * u_i

    C_gi, C_gj = guide_i.point_at(C), guide_j.point_at(C)
    ti_dot, tj_dot = solve_real_2x2(c1, c2, C_gj.v - C_gi.v, det)
    ti_dot, tj_dot = _nan_where(singular, ti_dot, tj_dot)
    rhs = (
        C_gj.a
        + coriolis_acceleration(guide_j.omega, tj_dot * u_j)
        - C_gi.a
        - coriolis_acceleration(guide_i.omega, ti_dot * u_i)
    )
    ti_ddot, _tj_ddot = solve_real_2x2(c1, c2, rhs, det)
    (ti_ddot,) = _nan_where(singular, ti_ddot)
    v_rel, a_rel = ti_dot * u_i, ti_ddot * u_i
    C_state = PointState(C, sliding_velocity(C_gi.v, v_rel), sliding_acceleration(C_gi.a, guide_i.omega, v_rel, a_rel))
    phi_i, turn_i = _turned(guide_i, delta_i)
    phi_j, turn_j = _turned(guide_j, delta_j)
    i = BodyState.from_point(phi_i, guide_i.omega, guide_i.epsilon, C_state, i_C, turn_i)
    j = BodyState.from_point(phi_j, guide_j.omega, guide_j.epsilon, C_state, j_C, turn_j)
    return DyadSolution(i, j, assembled, singular, sine, condition, measures, C_state)


@_quiet
def solve_rpp(
    B: PointState,
    i_B: complex,
    i_line: Line,
    j_inner_line: Line,
    j_outer_line: Line,
    guide: BodyState,
    guide_line: Line,
) -> DyadSolution:
    """RPP: link i pinned at known B slides in link j, which slides on a known body's line.

    ::

                   ║ (j) yoke
              ┌────╫────┐
        B o═══╪══ (i) ══╪══▶ u_n      i's line slides in j's inner line
              └────╫────┘
                   ║
                   ▼ u_g              j's outer line slides on g's guide

        joints in order: B (outer_i, R), i in j (inner, P), j on g (outer_j, P)

    The Scotch yoke and the sine mechanism.  Both links turn with the guide
    body g (φ_j = φ_g + α_g − α_j,out, φ_i = φ_j + α_j,in − α_i), so B runs
    along a line fixed in j (through its point p_j), and j along g's guide:
    ``B = P₀ + t_o u_g + t_n u_n`` with P₀ fixed in g, t_o the travel of j on
    g, t_n the travel of i in j.

    Loop ``P₀ + t_o u_g + t_n u_n = r_B``:

    * position (line–line)::

          [u_g] t_o + [u_n] t_n = B − P₀

    * velocity, unknowns ṫ_o, ṫ_n (B_g: the point of g under B)::

          v_Bg + ṫ_o u_g + ṫ_n u_n = v_B
          ⇒ [u_g] ṫ_o + [u_n] ṫ_n = v_B − v_Bg

    * acceleration, unknowns ẗ_o, ẗ_n, same matrix (both travels are on
      lines turning with ω_g: Coriolis)::

          a_Bg + 2iω_g (ṫ_o u_g + ṫ_n u_n) + ẗ_o u_g + ẗ_n u_n = a_B
          ⇒ [u_g] ẗ_o + [u_n] ẗ_n = a_B − a_Bg − 2iω_g (ṫ_o u_g + ṫ_n u_n)

    Parameters
    ----------
    B : PointState
        The known point of the outer revolute of i.
    i_B : complex
        B in i's coordinates [m].
    i_line, j_inner_line : Line
        The lines of the inner prismatic pair, on i and on j.
    j_outer_line, guide_line : Line
        The lines of the outer prismatic pair, on j and on the known body g.
    guide : BodyState
        The known body g.

    Returns
    -------
    DyadSolution
        No sign: one solution, none where the two lines are parallel.
    """
    p_j, alpha_n, delta_n = track_in_guide(j_inner_line, i_line, i_B)  # B's track, in j's coordinates
    p_0, alpha_g, delta_o = track_in_guide(guide_line, j_outer_line, p_j)  # its point p_j, in g's coordinates
    P0 = guide.position(p_0)
    u_g = guide.direction(alpha_g)
    u_n = guide.direction(alpha_n + delta_o)
    c1, c2 = u_g, u_n
    det = cross(c1, c2)
    _t_o, t_n = solve_real_2x2(c1, c2, B.r - P0, det)
    known = np.isfinite(c1) & np.isfinite(c2) & np.isfinite(B.r - P0)
    assembled, singular, sine, condition = _diagnose(known, c1, c2, det, positions_need_matrix=True)
    measures = {}
    (t_n,) = _nan_where(~assembled, t_n)

    B_g = guide.point_at(B.r)
    to_dot, tn_dot = solve_real_2x2(c1, c2, B.v - B_g.v, det)
    to_dot, tn_dot = _nan_where(singular, to_dot, tn_dot)
    v_rel_o, v_rel_n = to_dot * u_g, tn_dot * u_n
    rhs = B.a - B_g.a - coriolis_acceleration(guide.omega, v_rel_o + v_rel_n)
    _to_ddot, tn_ddot = solve_real_2x2(c1, c2, rhs, det)
    (tn_ddot,) = _nan_where(singular, tn_ddot)
    a_rel_n = tn_ddot * u_n

    phi_j, turn_j = _turned(guide, delta_o)
    phi_i, turn_i = _turned(guide, delta_o + delta_n)
    i = BodyState.from_point(phi_i, guide.omega, guide.epsilon, B, i_B, turn_i)
    # the point of j under B: B less i's sliding in j (rotating with ω_g)
    B_j = PointState(
        B.r,
        B.v - v_rel_n,
        B.a - coriolis_acceleration(guide.omega, v_rel_n) - a_rel_n,
    )
    B_in_j = p_j + t_n * cmath.exp(1j * alpha_n)  # B in j's own coordinates
    j = BodyState.from_point(phi_j, guide.omega, guide.epsilon, B_j, B_in_j, turn_j)
    return DyadSolution(i, j, assembled, singular, sine, condition, measures)
