"""Numerical policy in one place: when a position is near a dead centre, when it is refused,
how large a scene's numbers may be, and what error to expect.

Both methods apply these thresholds to the numbers they compute themselves
(the analytic solver to the columns of its 2×2 systems, the graphical
construction to the directions of its construction lines); they share the
policy, not any kinematics.

Conditioning of a group
-----------------------
γ is the angle between the group's two construction lines (the columns of
the analytic 2×2 system).  plans reports

* the **sine** |sin γ|: 1 for perpendicular lines, 0 at a dead centre;
* the **condition number** (1 + |cos γ|)/|sin γ| of the 2×2 matrix with unit
  columns: 1 for perpendicular lines, growing without bound towards a dead
  centre (≈ 2/|sin γ| there).

**Expected relative error.**  For the three kinds whose position is a
quadratic (RRR, RRP, RPR) a dead centre is also where the two assembly
branches meet: the position's discriminant vanishes there, and the rounding
of the data (≈ ε_mach of the mechanism's size) moves the sine by ≈ ε_mach·cond.
Velocities and accelerations are quotients by that sine, so their relative
error grows like ε_mach·cond² (positions like ε_mach·cond).  Measured against
a 50-digit evaluation on a four-bar driven 1e-2 … 1e-9 rad towards its limit
position, the error of v, a, ω, ε is 0.8 … 5 × ε_mach·cond²
(tests/test_stiff_toggle.py); at well-conditioned positions (cond 1 … 3) of
mechanisms from 1e-6 m to 1e3 m and ω from 1e-3 to 1e5 rad/s it is at most
~15 ε_mach (tests/test_extreme_scales.py).  :func:`expected_rel_error` states
:data:`ERROR_FACTOR` × ε_mach·cond², and the tests hold every result within
:data:`ERROR_MARGIN` times that.

**What the figure covers, and a chain of groups.**  The figure is relative
to the scale of each kind of quantity in the group (the largest |v| of its
points for velocities, the largest |a| for accelerations, ω and ε likewise):
a quantity much smaller than that scale (an ω passing through zero, a
component near zero) can have a much larger error relative to itself.  And
it is the group's own: a group solved from the points of earlier groups
inherits their errors, amplified by its own conditioning, so a
well-conditioned group after a stiff one is as uncertain as the stiff one
(measured: a four-bar 1e-8 rad from its limit position, condition 1.8e4,
then an RRP of condition 6: the RRP's own figure says 3e-14, its points
are off by 2e-8).  :func:`chain_rel_error` covers that: for group k, with
E_g the figure of each group g that it takes a known point or guide from,

    E_k = ERROR_FACTOR·ε_mach·cond_k² + cond_k · max_g E_g

(:meth:`plans.analytic.AnalyticSolution.expected_chain_rel_errors`; tested
against a 50-digit reference in tests/test_speed_chain_error.py).

Thresholds
----------
:data:`REFUSE_SINE` = 1e-7
    Below it a group is at a dead centre and both methods refuse
    (SingularPositionError): the expected relative error ε_mach·(2/sin)²
    would exceed 10 %, and a sine of 3e-8 cannot be told from zero (it
    behaves like the square root of a discriminant known to ~1e-15).  A
    four-bar 1e-9 rad of crank angle from its limit position has a sine of
    ~4e-5 and is still solved, with a warning.
:data:`WARN_CONDITION` = 100
    Above it (|sin γ| below ~0.02, about 1.1° from a dead centre) plans warns,
    naming the group, its joint and the driver position, with the expected
    relative error.  Adjustable: ``warn_condition=`` of
    :func:`plans.analytic.solve` and :func:`plans.graphical.construct`, and
    ``--warn-condition`` of the command line.
:data:`MAX_MAGNITUDE` = 1e30
    Every number of a scene (in SI) must be at most this in size, so that the
    squares and products the kinematics forms stay far inside the range of
    double precision (1e±308).  Scale factors must be at least
    :data:`MIN_SCALE` = 1e-30.
:data:`COINCIDENT` = 1e-12
    Two points of one body closer than this fraction of the scene's size are
    one point to double precision (a link of relative length 1e-12 has no
    computable direction); the scene is refused.  Link ratios down to 1e-4
    and beyond are fine.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass

__all__ = [
    "EPS",
    "REFUSE_SINE",
    "WARN_CONDITION",
    "ERROR_FACTOR",
    "ERROR_MARGIN",
    "MAX_MAGNITUDE",
    "MIN_SCALE",
    "COINCIDENT",
    "expected_rel_error",
    "chain_rel_error",
    "NearDeadCentre",
    "position_text",
]

#: Machine epsilon of double precision.
EPS = sys.float_info.epsilon

#: |sin γ| below which a group is at a dead centre and both methods refuse.
REFUSE_SINE = 1e-7

#: Condition number above which plans warns that a group is near a dead centre.
WARN_CONDITION = 100.0

#: The expected relative error is this many times ε_mach·cond² (measured: 0.8 … 5).
ERROR_FACTOR = 4.0

#: Measured errors stay below this many times :func:`expected_rel_error` (tested).
ERROR_MARGIN = 10.0

#: Largest magnitude [SI] a number of a scene may have.
MAX_MAGNITUDE = 1e30

#: Smallest scale factor [SI per mm] a scene's [scales] may give.
MIN_SCALE = 1e-30

#: Two points of one body closer than this fraction of the scene's size coincide.
COINCIDENT = 1e-12


def expected_rel_error(condition):
    """Expected relative error of velocities and accelerations: ERROR_FACTOR · ε_mach · cond².

    Works on floats and numpy arrays alike; NaN where the condition is NaN.

    >>> f"{expected_rel_error(1e3):.1e}"
    '8.9e-10'
    """
    return ERROR_FACTOR * EPS * condition * condition


def chain_rel_error(condition, upstream=0.0):
    """Expected relative error of a group's velocities and accelerations in a chain of groups.

    ``ERROR_FACTOR · ε_mach · cond² + cond · upstream``, *upstream* being the
    largest :func:`chain_rel_error` of the groups this one takes known points
    or guides from (0 for a group on the frame and the driver only: then it
    is :func:`expected_rel_error`).  Floats and numpy arrays alike.

    >>> f"{chain_rel_error(6.0, chain_rel_error(1e3)):.1e}"
    '5.3e-09'
    """
    return expected_rel_error(condition) + condition * upstream


def position_text(crank: bool, position: float, decimals: int | None = None) -> str:
    """A driver position for messages: ``φ = 123.4°`` or ``s = 50.0 mm``.

    With *decimals*, an estimate: rounded to that many decimals of a degree or mm.
    """
    if crank:
        value, text = math.degrees(position), "φ = {}°"
    else:
        value, text = position * 1e3, "s = {} mm"
    if decimals is not None:
        return text.format(f"{value:.{decimals}f}")
    short = f"{value:.1f}"
    return text.format(short if abs(float(short) - value) <= 1e-9 * max(1.0, abs(value)) else f"{value:.9g}")


@dataclass(frozen=True)
class NearDeadCentre:
    """A warning: a group is near a dead centre at a driver position.

    Attributes
    ----------
    group : str
        ``"RRR(3,4)"``.
    joint : str
        The joint whose image the two construction lines place (C of an RRR).
    position : float
        Driver position: crank angle [rad] or linear-driver position [m].
    where : str
        The position as text (``"φ = 123.4°"``).
    condition : float
        Condition number of the group there (see the module docstring).
    sine : float
        |sin| of the angle between the construction lines there.
    method : str
        ``"analytic"`` or ``"graphical"``: whose own numbers these are.
    """

    group: str
    joint: str
    position: float
    where: str
    condition: float
    sine: float
    method: str = "analytic"

    @property
    def expected_rel_error(self) -> float:
        return float(expected_rel_error(self.condition))

    def __str__(self) -> str:
        return (
            f"{self.group} near a dead centre at {self.where}: joint {self.joint}, condition {self.condition:.1e}, "
            f"expected relative error ≈ {self.expected_rel_error:.0e}"
        )

    def as_dict(self) -> dict:
        """JSON-ready (floats are finite: a warning exists only at a solved position)."""
        return {
            "group": self.group,
            "joint": self.joint,
            "where": self.where,
            "condition": float(self.condition),
            "sine": float(self.sine),
            "expected_rel_error": self.expected_rel_error,
            "method": self.method,
            "message": str(self),
        }
