"""plans: velocity and acceleration plans of planar linkages.

Two independent methods over one scene model:

* :func:`solve` — the analytic complex-number (loop-closure) solution,
  vectorised over driver positions (numpy only); :func:`prepare` makes a
  scene ready once for many calls (``solver = plans.prepare(scene)``,
  ``solver(phi)``);
* :func:`construct` — the graphical velocity and acceleration plans, built
  group by group with construction lines and read off at scale (shapely);

and :func:`compare` sets one against the other.  :func:`forces` finds the
joint reactions and the balancing moment of a scene with masses and loads
(kinetostatics: Newton–Euler group by group; :mod:`plans.forces` has
Joukowski's lever and the comparison of the methods).  Over a cycle the driver
follows one law (:mod:`plans.motion`): :func:`driver_cycle` gives the
positions, times [s] and driver rates of a cycle (``cycle.solve()`` the
solution that is a motion), :func:`strokes` the output's stroke H [m] or
swing ψ [rad], θ and K, :func:`four_bar_loops` the Grashof class of every
four-bar loop; :func:`kinematic_diagrams` the output link's s, v, a
diagrams by graphical differentiation (method of chords) against the plans
and the analytic values.  :func:`write_drawings`
draws the mechanism and the plans (matplotlib) and sets the sheet (Typst).  ``construct`` and
``write_drawings`` are imported on first use, so ``import plans`` stays light.

Example
-------
>>> import plans
>>> scene = plans.load(plans.example_path("slider-crank"))
>>> solution = plans.solve(scene)
>>> float(round(solution.points["B"].v[0].real, 4))     # m/s
-16.0407
"""

from .errors import AssemblyError, PlansError, SceneError, SingularPositionError, StructureError
from .scene import Scene, example_names, example_path, from_mapping, load, loads
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
    "forces",
    "write_drawings",
    "write_position_sheets",
    "run_positions",
    "write_handout",
    "driver_cycle",
    "cycle_at",
    "driver_law",
    "strokes",
    "crank_limits",
    "four_bar_loops",
    "grashof",
    "kinematic_diagrams",
    "from_mapping",
    "Scene",
    "AnalyticSolution",
    "PlansError",
    "SceneError",
    "StructureError",
    "AssemblyError",
    "SingularPositionError",
]

__version__ = "0.1.0"


def __dir__() -> list[str]:
    """The public names, those loaded on first use included (``dir(plans)`` in a notebook)."""
    return sorted(set(__all__) | {"__version__"})


def __getattr__(name: str):
    if name in ("solve", "prepare", "AnalyticSolution"):
        from . import analytic

        return getattr(analytic, name)
    if name == "forces":  # the package, callable: plans.forces(scene, positions=None, ...)
        import importlib

        return importlib.import_module(f"{__name__}.forces")
    if name == "construct":
        from .graphical import construct

        return construct
    if name in ("write_drawings", "write_position_sheets"):  # the sheets: pages set by Typst
        from .pages import sheet

        return getattr(sheet, name)
    if name == "run_positions":
        from .positions import run_positions

        return run_positions
    if name in ("driver_cycle", "cycle_at", "driver_law", "strokes", "crank_limits", "four_bar_loops", "grashof"):
        from . import motion

        return getattr(motion, name)
    if name == "kinematic_diagrams":
        from .differentiation import kinematic_diagrams

        return kinematic_diagrams
    if name == "write_handout":
        from .handout import write_handout

        return write_handout
    raise AttributeError(f"module 'plans' has no attribute {name!r}")


# notebook display of graphical results (plans.notebook); nothing happens outside IPython
from .notebook import register as _register_notebook_display  # noqa: E402

_register_notebook_display()
