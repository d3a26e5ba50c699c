"""Kinetostatics: the joint reactions and the balancing moment, by three independent methods.

* :mod:`plans.forces.analytic` — Newton–Euler group by group from the analytic
  kinematics (numpy, vectorised over driver positions);
* :mod:`plans.forces.lever` — Joukowski's lever: the graphical velocity plan
  turned by 90°, the loads (their inertia loads from the graphical plans) at
  the images of their points, M_b from the moments about the pole;
* the force plans of each group from the graphical plans (a module of their own);
* over the cycle, :mod:`plans.forces.cycle` — M_b(φ), its mean and the crank
  bearing's reaction at every position (``forces_over_cycle``; drawn by
  :mod:`plans.drawing.force_diagrams`);

sharing the scene model and :mod:`plans.forces.loads` (what loads act where,
from each method's own kinematics) and nothing else.  The power balance
M_b·ω + Σ F·v + Σ M·ω = 0 is a fourth check.

The module is callable: ``plans.forces(scene, positions=None, ...)`` is
:func:`plans.forces.analytic.solve_forces`.

>>> import plans
>>> result = plans.forces(plans.load(plans.example_path("slider-crank-loads")))
>>> round(float(abs(result.reactions["R_23"].force[0])), 5)
8353.55006
"""

import sys
import types

from .analytic import AnalyticForces, Reaction, forces_from, solve_forces
from .cycle import CycleForces, forces_over_cycle, mean_over_cycle
from .loads import AppliedLoad, applied_loads

__all__ = ["solve_forces", "forces_from", "AnalyticForces", "Reaction", "AppliedLoad", "applied_loads", "CycleForces", "forces_over_cycle",
           "mean_over_cycle"]


class _CallableModule(types.ModuleType):
    """``plans.forces(...)`` calls :func:`solve_forces` (the package is also the function)."""

    def __call__(self, scene, positions=None, **options) -> AnalyticForces:
        return solve_forces(scene, positions, **options)


sys.modules[__name__].__class__ = _CallableModule
