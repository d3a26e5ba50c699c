"""The kinetostatics of one position by every method, side by side, with their differences.

:func:`kinetostatics` solves one driver position analytically
(:mod:`plans.forces.analytic`) and, unless told otherwise, graphically: the
graphical construction (:func:`plans.graphical.construct`), Joukowski's lever
on its velocity plan (:mod:`plans.forces.lever`) and the force plans of the
groups on its acceleration plan, when plans has them (the module
``plans.forces.force_plans`` with a function ``force_plans(graphical)``
returning an object with ``balancing`` — M_b [N·m] or F_b [N] — and
``reactions`` — label (:func:`plans.forces.analytic.reaction_label`) ->
an object whose ``force`` is the complex force [N] — read off the plans).
:func:`compare_forces` sets each against the analytic values.
"""

from __future__ import annotations

import importlib
import importlib.util
from dataclasses import dataclass

from .analytic import AnalyticForces

__all__ = ["ForceComparison", "KinetostaticRun", "compare_forces", "kinetostatics", "METHODS", "force_plans_available"]

#: The methods, as JSON keys and table rows: the analytic one first.
METHODS = ("analytic", "force_plans", "lever")


@dataclass(frozen=True)
class ForceComparison:
    """One quantity by a graphical method against the analytic value.

    Attributes
    ----------
    quantity : str
        ``"M_b"`` / ``"F_b"``, or a reaction's label (``"R_23"``).
    method : str
        ``"force_plans"`` or ``"lever"``.
    analytic, value : float or complex
        The analytic value and the method's (N·m or N; a reaction as a complex force).
    abs_error : float
        |value − analytic|.
    rel_error : float
        abs_error / |analytic| (abs_error itself where the analytic value is 0).
    """

    quantity: str
    method: str
    analytic: complex
    value: complex
    abs_error: float
    rel_error: float


@dataclass(frozen=True)
class KinetostaticRun:
    """One position solved by every method at hand.

    Attributes
    ----------
    scene : plans.scene.Scene
        At the position solved.
    analytic : plans.forces.analytic.AnalyticForces
        At that one position (arrays of length 1).
    graphical : plans.graphical.GraphicalSolution or None
    lever : plans.forces.lever.JoukowskiLever or None
    force_plans : object or None
        The force plans' result (see the module docstring), when plans has them.
    comparisons : tuple[ForceComparison, ...]
    notes : tuple[str, ...]
        Why a method was left out (the lever with the driver at rest), for a warning.
    """

    scene: object
    analytic: AnalyticForces
    graphical: object = None
    lever: object = None
    force_plans: object = None
    comparisons: tuple[ForceComparison, ...] = ()
    notes: tuple[str, ...] = ()


def _error(quantity: str, method: str, analytic: complex, value: complex) -> ForceComparison:
    error = abs(value - analytic)
    size = abs(analytic)
    return ForceComparison(quantity, method, analytic, value, error, error / size if size > 0 else error)


def compare_forces(analytic: AnalyticForces, lever=None, force_plans=None, position: int = 0) -> tuple[ForceComparison, ...]:
    """The balancing moment (force) and every reaction by the graphical methods against analytic.

    Rows: M_b by the force plans and by the lever, then each reaction by the
    force plans (in the analytic's order); methods not given are left out.
    """
    rows: list[ForceComparison] = []
    symbol = "M_b" if analytic.balancing_kind == "moment" else "F_b"
    exact = float(analytic.balancing[position])
    if force_plans is not None:
        rows.append(_error(symbol, "force_plans", exact, float(force_plans.balancing)))
    if lever is not None:
        rows.append(_error(symbol, "lever", exact, float(lever.balancing)))
    if force_plans is not None:
        for label, reaction in analytic.reactions.items():
            theirs = force_plans.reactions.get(label)
            if theirs is not None:
                rows.append(_error(label, "force_plans", complex(reaction.force[position]), complex(getattr(theirs, "force", theirs))))
    return tuple(rows)


def force_plans_available() -> bool:
    """True when plans has the graphical force plans (``plans.forces.force_plans``)."""
    return importlib.util.find_spec(f"{__package__}.force_plans") is not None


def kinetostatics(
    scene,
    *,
    graphical: bool = True,
    k_l: float | None = None,
    k_v: float | None = None,
    k_a: float | None = None,
    precision: float | None = None,
    warn_condition: float | None = None,
) -> KinetostaticRun:
    """The kinetostatics of the scene at its driver position: analytic, and (with *graphical*) lever and force plans.

    Parameters
    ----------
    scene : plans.scene.Scene
    graphical : bool
        Also the graphical construction, Joukowski's lever and the force plans.
    k_l, k_v, k_a, precision : float, optional
        As :func:`plans.graphical.construct` (the scene's ``[scales]`` otherwise).
    warn_condition : float, optional
        As :func:`plans.analytic.solve`.
    """
    from ..analytic import solve
    from .analytic import forces_from

    options = {} if warn_condition is None else {"warn_condition": warn_condition}
    kinematics = solve(scene, **options)
    analytic = forces_from(kinematics)
    if not graphical:
        return KinetostaticRun(scene, analytic)
    from ..graphical import construct
    from .lever import LeverError, joukowski_lever

    solution = construct(scene, kinematics.structure, k_l=k_l, k_v=k_v, k_a=k_a, precision=precision, **options)
    notes = []
    try:
        lever = joukowski_lever(solution)
    except LeverError as exc:
        lever = None
        notes.append(f"Joukowski's lever left out: {exc}")
    plans_result = None
    if force_plans_available():
        module = importlib.import_module(f"{__package__}.force_plans")
        plans_result = module.force_plans(solution)
    comparisons = compare_forces(analytic, lever, plans_result)
    return KinetostaticRun(scene, analytic, solution, lever, plans_result, comparisons, tuple(notes))

