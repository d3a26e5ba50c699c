"""plans: velocity and acceleration plans of planar linkages.

Two independent methods over one scene model:

* :func:`solve` — the analytic complex-number (loop-closure) solution,
  vectorised over driver positions (numpy only); :func:`prepare` makes a
  scene ready once for many calls (``solver = plans.prepare(scene)``,
  ``solver(phi)``);
* :func:`construct` — the graphical velocity and acceleration plans, built
  group by group with construction lines and read off at scale (shapely);

and :func:`compare` sets one against the other.  :func:`write_drawings`
draws the mechanism and the plans to SVG (matplotlib).  ``construct`` and
``write_drawings`` are imported on first use, so ``import plans`` stays light.

Example
-------
>>> import plans
>>> scene = plans.load(plans.example_path("slider-crank"))
>>> solution = plans.solve(scene)
>>> round(solution.points["B"].v[0].real, 4)            # m/s
-16.0407
"""

from .errors import AssemblyError, PlansError, SceneError, SingularPositionError, StructureError
from .scene import Scene, example_names, example_path, load, loads
from .structure import find_structure
from .compare import compare

__all__ = [
    "load",
    "loads",
    "example_names",
    "example_path",
    "find_structure",
    "solve",
    "prepare",
    "construct",
    "compare",
    "write_drawings",
    "Scene",
    "AnalyticSolution",
    "PlansError",
    "SceneError",
    "StructureError",
    "AssemblyError",
    "SingularPositionError",
]

__version__ = "0.1.0"


def __getattr__(name: str):
    if name in ("solve", "prepare", "AnalyticSolution"):
        from . import analytic

        return getattr(analytic, name)
    if name == "construct":
        from .graphical import construct

        return construct
    if name == "write_drawings":
        from .drawing import write_drawings

        return write_drawings
    raise AttributeError(f"module 'plans' has no attribute {name!r}")
