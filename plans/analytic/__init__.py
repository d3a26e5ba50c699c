"""The analytic solution by the complex-number (loop-closure) method.

Positions in closed form, velocities and accelerations from the loop
equations differentiated once and twice (2×2 real linear systems), for the
driver and every class-II Assur group, vectorised over N driver positions.

This package needs only numpy and the scene model: it imports neither
matplotlib nor shapely, nor the graphical construction.

>>> from plans.scene import load, example_path
>>> from plans.analytic import solve
>>> solution = solve(load(example_path("slider-crank")))
>>> round(float(solution.links["3"].omega[0]), 4)
-59.4428
"""

from .dyads import SINGULAR_SINE, DyadSolution, solve_prp, solve_rpp, solve_rpr, solve_rrp, solve_rrr
from .solution import AnalyticSolution, LinkMotion, PointMotion, SliderMotion
from .solver import PreparedSolver, driver_position, prepare, solve

__all__ = [
    "solve",
    "prepare",
    "PreparedSolver",
    "driver_position",
    "AnalyticSolution",
    "LinkMotion",
    "PointMotion",
    "SliderMotion",
    "DyadSolution",
    "SINGULAR_SINE",
    "solve_rrr",
    "solve_rrp",
    "solve_rpr",
    "solve_prp",
    "solve_rpp",
]
