"""The graphical method: compass construction of the mechanism, velocity and acceleration plans.

Shares the scene model with :mod:`plans.analytic` and nothing of its
kinematics: everything here is plan geometry (images, construction lines,
intersections, measured lengths × scale factors).  Never imports matplotlib.

>>> from plans.scene import load, example_path
>>> solution = construct(load(example_path("four-bar")))
>>> sorted(solution.scales)
['k_a', 'k_l', 'k_v']
"""

from .construct import construct
from .plan import KINDS, ConstructionLine, GraphicalSolution, Plan, PlanVector, Step
from .scales import round_scale

__all__ = ["construct", "round_scale", "KINDS", "PlanVector", "ConstructionLine", "Step", "Plan", "GraphicalSolution"]
