"""The kinetostatics over the driver's cycle: the driving moment M_b(φ) and the crank bearing's reaction.

:func:`forces_over_cycle` solves the analytic kinetostatics at the positions of
one cycle under the driver's law (:func:`plans.motion.driver_cycle`) and at the
project's numbered positions (0, 1, … from the output's extreme position), and
gives what the flywheel chapter starts from:

* M_b [N·m] (counter-clockwise positive, on the crank) — or F_b [N] along a
  linear driver's guide — at every position, and its mean over the cycle, the
  mean driving moment M_b,mean = (1/2π)∮M_b dφ (the work of M_b over a turn
  divided by 2π; trapezoids over the crank angle, so a law that is not constant
  speed is still averaged over the angle);
* the reaction of the frame on the crank (R_12 where the crank is 2) at every
  position: its polar diagram (hodograph) is drawn from one pole.

Only numbers here; :meth:`CycleForces.page` and :meth:`CycleForces.save` draw
through :mod:`plans.display` (filled by :mod:`plans.notebook`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..scene import FRAME, Crank, Scene
from .analytic import AnalyticForces, Reaction, forces_from

__all__ = ["CycleForces", "forces_over_cycle", "cycle_forces", "mean_over_cycle", "is_swing"]


def mean_over_cycle(values, positions, crank: bool = True) -> float:
    """The mean of *values* over the driver's path: (1/Δ)∫values d(position), by trapezoids.

    For a crank (*positions* in rad over one turn, not closed) the turn is closed
    with the first value a turn on, Δ = 2π; for a linear driver the mean runs from
    the first position to the last.  NaN when a value is missing (a position
    where the mechanism does not assemble).
    """
    y = np.asarray(values, dtype=float)
    x = np.asarray(positions, dtype=float)
    if not len(y) or not np.isfinite(y).all():
        return math.nan
    if crank:
        sense = 1.0 if len(x) < 2 or x[-1] >= x[0] else -1.0
        x = np.append(x, x[0] + sense * 2 * math.pi)
        y = np.append(y, y[0])
    span = float(x[-1] - x[0])
    if span == 0:
        return float(y[0])
    return float(np.sum((y[1:] + y[:-1]) * np.diff(x)) / 2 / span)


@dataclass(frozen=True, eq=False)
class CycleForces:
    """The kinetostatics over one cycle and at the numbered positions.

    Attributes
    ----------
    forces : AnalyticForces
        At every position of the sweep (:attr:`cycle`).
    cycle : plans.motion.Cycle
        The sweep's positions (crank angles [rad] in the sense of ω, from position 0).
    marked : AnalyticForces or None
        At the numbered positions 0, 1, … (:attr:`marked_cycle`).
    marked_cycle : plans.motion.Cycle or None
    mean : float
        M_b,mean [N·m] (or F_b,mean [N]); NaN when the mechanism does not assemble over the whole cycle,
        or for a harmonic swing (no turn to average over).
    bearing : str or None
        The label of the frame's reaction on the crank (``"R_12"``); None for a linear driver.
    """

    forces: AnalyticForces
    cycle: object
    marked: AnalyticForces | None
    marked_cycle: object
    mean: float
    bearing: str | None

    @property
    def crank(self) -> bool:
        """The driver is a crank (M_b [N·m]) rather than linear (F_b [N])."""
        return self.forces.balancing_kind == "moment"

    def reaction(self, marked: bool = False) -> Reaction | None:
        """The crank bearing's reaction (the frame on the crank) over the sweep, or at the numbered positions."""
        if self.bearing is None:
            return None
        source = self.marked if marked else self.forces
        return None if source is None else source.reactions[self.bearing]

    def page(self, *, lang: str = "en", title: str = ""):
        """The page of both diagrams as a matplotlib Figure (:func:`plans.drawing.force_diagrams.draw_force_diagrams`)."""
        from ..display import display_function

        return display_function("force_cycle_page")(self, lang=lang, title=title)

    def save(self, path, *, lang: str = "en", title: str = "") -> list:
        """Write the page to *path* by its suffix (``.svg``, ``.pdf``, ``.png``); returns the paths written."""
        from ..display import display_function

        return display_function("save_pages")([("", self.page(lang=lang, title=title))], path)


def is_swing(cycle) -> bool:
    """The cycle is a rocker input's harmonic swing there and back (:mod:`plans.motion`), not a turn or a stroke."""
    return getattr(getattr(cycle, "law", None), "kind", "") == "harmonic"


def _bearing(forces: AnalyticForces) -> str | None:
    driver = forces.scene.driver
    if not isinstance(driver, Crank):
        return None
    for label, reaction in forces.reactions.items():
        if reaction.by == FRAME and reaction.on == driver.link:
            return label
    return None


def cycle_forces(forces: AnalyticForces, cycle, marked: AnalyticForces | None = None, marked_cycle=None) -> CycleForces:
    """:class:`CycleForces` from kinetostatics already solved over *cycle* (and at *marked_cycle*)."""
    crank = forces.balancing_kind == "moment"
    positions = cycle.positions
    # a rocker input's harmonic swing turns back: no turn to average over (the page says so)
    mean = math.nan if is_swing(cycle) else mean_over_cycle(forces.balancing, positions, crank=crank)
    return CycleForces(forces, cycle, marked, marked_cycle, mean, _bearing(forces))


def forces_over_cycle(scene: Scene, steps: int = 360, positions: int = 12, *, law: str | None = None, start: str = "output") -> CycleForces:
    """The analytic kinetostatics over one cycle of *steps* positions and at *positions* numbered ones.

    Parameters
    ----------
    scene : Scene
        With masses or loads (else M_b and every reaction are zero).
    steps : int
        Positions over the cycle (≥ 2), equally spaced in time under the driver's law.
    positions : int
        The numbered positions 0, 1, … (those of ``plans draw --positions N``); 0: none.
    law, start :
        As :func:`plans.motion.driver_cycle`: position 0 is the output's extreme position by default.

    Returns
    -------
    CycleForces
        ``.forces.balancing`` M_b [N·m] (counter-clockwise on the crank) or F_b [N];
        ``.mean`` the mean driving moment [N·m] over the turn; ``.reaction()`` the
        frame's reaction on the crank [N] (complex, x + iy).
    """
    from ..errors import SceneError
    from ..motion import driver_cycle

    if steps < 2:
        raise SceneError("steps: at least 2 positions over the cycle", scene.source, "steps")
    cycle = driver_cycle(scene, steps, law=law, start=start)
    forces = forces_from(cycle.solve(warn_condition=math.inf))
    marked = marked_cycle = None
    if positions:
        marked_cycle = driver_cycle(scene, positions, law=law, start=start)
        marked = forces_from(marked_cycle.solve(warn_condition=math.inf))
    return cycle_forces(forces, cycle, marked, marked_cycle)
