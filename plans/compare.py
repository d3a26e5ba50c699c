"""Graphical against analytic: the same quantities from two independent methods.

This module only reads the two solutions; it computes no kinematics.  Vectors
are compared as vectors: the absolute error of v is |v_graphical − v_analytic|
[m/s], and the relative error divides it by |v_analytic|.  Where the analytic
value is (nearly) zero, below 1e-9 of the largest value of its kind in the
scene, the relative error is taken against that largest value instead, so a
point at rest does not give 0/0.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Comparison", "compare", "ZERO_FRACTION", "QUANTITIES", "PLAN_QUANTITIES"]

#: below this fraction of the largest value of its kind, a value counts as zero
ZERO_FRACTION = 1e-9


@dataclass(frozen=True)
class Comparison:
    """One quantity from both methods.

    Attributes
    ----------
    section : str
        ``"points"``, ``"links"`` or ``"sliders"``.
    name : str
        Point, link or prismatic joint name.
    quantity : str
        ``"v"``, ``"a"``, ``"omega"``, ``"epsilon"``, ``"v_rel"``, ``"a_rel"``, ``"coriolis"``.
    analytic, graphical : complex or float
        The two values, SI.
    abs_error : float
        |graphical − analytic|, SI.
    rel_error : float
        abs_error over |analytic| (or over the largest value of the kind, see
        the module docstring).
    """

    section: str
    name: str
    quantity: str
    analytic: complex | float
    graphical: complex | float
    abs_error: float
    rel_error: float


#: quantities measured against one another when a value is near zero
_KIND = {
    "r": "r", "s": "r",
    "v": "v", "v_rel": "v",
    "a": "a", "a_rel": "a", "coriolis": "a",
    "omega": "omega", "epsilon": "epsilon",
}  # fmt: skip

#: what is compared, per section: (quantity, needs accelerations).  r and s
#: come from the compass construction of the mechanism, the rest from the plans.
QUANTITIES = {
    "points": (("r", False), ("v", False), ("a", True)),
    "links": (("omega", False), ("epsilon", True)),
    "sliders": (("s", False), ("v_rel", False), ("a_rel", True), ("coriolis", True)),
}

#: the quantities read off the velocity and acceleration plans (not the mechanism drawing)
PLAN_QUANTITIES = ("v", "a", "omega", "epsilon", "v_rel", "a_rel", "coriolis")


def _analytic_value(analytic, section: str, name: str, quantity: str, k: int):
    record = getattr(analytic, section)[name]
    value = getattr(record, quantity)[k]
    return complex(value) if quantity in ("r", "v", "a", "coriolis") else float(value)


def compare(analytic, graphical, position: int = 0) -> list[Comparison]:
    """Compare every quantity the graphical solution constructed or read off its plans.

    Positions of points (r) and slider travels (s) come from the compass
    construction of the mechanism; velocities, accelerations, ω, ε and the
    sliders' relative motion from the plans.

    Parameters
    ----------
    analytic : plans.analytic.AnalyticSolution
    graphical : plans.graphical.plan.GraphicalSolution
    position : int
        Which of the analytic solution's driver positions the graphical one
        was constructed at.

    Returns
    -------
    list[Comparison]
        Points (in the scene's report order), links, then sliders.
    """
    accelerations = graphical.acceleration_plan is not None
    pairs: list[tuple[str, str, str, object, object]] = []
    for section, quantities in QUANTITIES.items():
        readings = getattr(graphical, section)
        if section == "points":  # the constructed positions beside the plan readings
            readings = {name: {"r": graphical.positions[name], **reading} for name, reading in readings.items()}
        names = [p for p in graphical.scene.report if p in readings] if section == "points" else list(readings)
        for name in names:
            for quantity, needs_a in quantities:
                if needs_a and not accelerations:
                    continue
                if quantity not in readings[name]:
                    continue
                a = _analytic_value(analytic, section, name, quantity, position)
                pairs.append((section, name, quantity, a, readings[name][quantity]))
    largest: dict[str, float] = {}
    for _, _, quantity, a, _ in pairs:
        largest[_KIND[quantity]] = max(largest.get(_KIND[quantity], 0.0), abs(a))
    rows = []
    for section, name, quantity, a, g in pairs:
        error = abs(g - a)
        top = largest[_KIND[quantity]]
        reference = abs(a) if abs(a) >= ZERO_FRACTION * top else top  # (nearly) zero: against the largest of its kind
        rel = error / reference if reference > 0 else 0.0
        rows.append(Comparison(section, name, quantity, a, g, error, rel))
    return rows

__all__ += ["compare_centres", "ROUNDOFF"]


#: A value from the centres or the analytic solution at most this fraction of the largest of its kind at the position
#: is round-off of a zero (as :data:`plans.report.TABLE_ROUNDOFF` for the tables): compared as exactly 0.
ROUNDOFF = 1e-9


def compare_centres(analytic, centres, position: int = 0, translations: bool = False) -> list[Comparison]:
    """Velocities from the instant centres against analytic: ω of every link, v of every reported point.

    Parameters
    ----------
    analytic : plans.analytic.AnalyticSolution
    centres : plans.centres.InstantCentres
        Found at the analytic solution's driver position number *position*.
    translations : bool
        Also v [m/s] of every link that translates at the instant (its centre with the frame at infinity),
        section ``"links"``, quantity ``"v"``: the centres' translation against the analytic velocity of a
        point of the link (every point of it moves alike).

    Returns
    -------
    list[Comparison]
        Points (``"v"``, in the scene's report order), then links
        (``"omega"``, then with *translations* ``"v"``); the ``graphical`` field holds the value from the
        centres.  Errors as in :func:`compare`.
    """
    scene = centres.scene
    pairs = [("points", name, "v", _analytic_value(analytic, "points", name, "v", position), complex(centres.points[name]))
             for name in scene.report]
    pairs += [("links", name, "omega", _analytic_value(analytic, "links", name, "omega", position), float(centres.links[name]))
              for name in scene.links]
    if translations:
        for name in scene.links:
            point = next((p for p in scene.bodies[name].points if p in analytic.points), None)
            if centres.translates(name) and point is not None:
                pairs.append(("links", name, "v", _analytic_value(analytic, "points", point, "v", position),
                              complex(centres.motions[name].v0)))
    largest: dict[str, float] = {}
    for _, _, quantity, a, c in pairs:
        largest[quantity] = max(largest.get(quantity, 0.0), abs(a), abs(c))
    rows = []
    for section, name, quantity, a, c in pairs:
        # round-off of a zero (a dead centre's ω₄ = −2·10⁻¹⁵, v_D = 1·10⁻¹⁵): exactly zero, in both methods
        a, c = (type(x)(0) if abs(x) <= ROUNDOFF * largest[quantity] else x for x in (a, c))
        error = abs(c - a)
        reference = max(abs(a), ZERO_FRACTION * largest[quantity])
        rows.append(Comparison(section, name, quantity, a, c, error, error / reference if reference > 0 else 0.0))
    return rows
