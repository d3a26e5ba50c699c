"""What happened along a solved sweep: where assembly was lost, and which dead centres were crossed.

This module reads an :class:`~plans.analytic.AnalyticSolution` solved with
``allow_partial=True`` over an ordered set of driver positions; it computes no
kinematics, only where the solver's own masks and conditioning change.

* **Lost assembly.**  A run of positions where the mechanism is not solved
  (``valid`` False) is reported with the group that fails first in the
  structure's order, the last solved position before it (*stop*) and the
  first after it (*resume*), and an estimate of where between the grid
  positions the limit lies: near a limit position a group's sin² falls
  linearly with the driver position, so the two solved positions nearest
  the gap are extrapolated to sin² = 0.  The solver keeps the branch sign
  found at the scene's own position everywhere, so a sweep resumes on the
  same branch after a gap; it never switches branch silently.
* **Dead centres crossed.**  A local minimum of a group's sine, with the
  group's condition above the warning threshold and the mechanism solved on
  both sides, is a dead centre the sweep passed through (or close by); its
  driver position is interpolated from the V shape |sin| takes there.
  A dead centre hit exactly on a grid position (refused there) is reported
  as a lost interval of one position whose cause is ``"dead centre"``.

For a crank the sweep is one turn: a gap that runs into the end of the
sweep resumes at its start (one turn later).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .limits import REFUSE_SINE, WARN_CONDITION, position_text
from .scene import Crank

__all__ = ["LostAssembly", "DeadCentreCrossing", "SweepReport", "analyse_sweep"]


@dataclass(frozen=True)
class LostAssembly:
    """A run of driver positions where the mechanism is not solved.

    Attributes
    ----------
    group : str
        The first group (in solving order) that fails in the run.
    cause : str
        ``"cannot assemble"`` or ``"dead centre"``.
    first, last : float
        The first and last unsolved grid positions of the run.
    stop, resume : float or None
        The last solved position before the run and the first one after it
        (None at an end of a linear driver's stroke).
    stop_limit, resume_limit : float or None
        Estimated driver positions of the limits between them.
    crank : bool
        Positions are crank angles [rad] (else linear positions [m]).
    """

    group: str
    cause: str
    first: float
    last: float
    stop: float | None
    resume: float | None
    stop_limit: float | None
    resume_limit: float | None
    crank: bool

    def __str__(self) -> str:
        where = lambda x, d=None: position_text(self.crank, _wrap(x) if self.crank else x, d)  # noqa: E731
        if self.cause == "dead centre":
            head = f"{self.group} is at a dead centre at {where(self.first)}" if self.first == self.last else (
                f"{self.group} is at a dead centre from {where(self.first)} to {where(self.last)}")
        else:
            head = f"{self.group} cannot assemble from {where(self.first)} to {where(self.last)}"
        parts = []
        if self.stop is not None:
            limit = f" (limit ≈ {where(self.stop_limit, 2)})" if self.stop_limit is not None else ""
            parts.append(f"the sweep stops after {where(self.stop)}{limit}")
        else:
            parts.append("the sweep starts there")
        if self.resume is not None:
            limit = f" (limit ≈ {where(self.resume_limit, 2)})" if self.resume_limit is not None else ""
            parts.append(f"resumes at {where(self.resume)}{limit} on the same branch")
        else:
            parts.append("does not resume before the end")
        return f"{head}: {' and '.join(parts)}; those rows have assembled = 0 and empty cells"


@dataclass(frozen=True)
class DeadCentreCrossing:
    """A dead centre the sweep passed while staying assembled.

    Attributes
    ----------
    group, joint : str
    position : float
        Interpolated driver position of the dead centre.
    nearest : float
        The grid position closest to it.
    sine, condition : float
        At that grid position.
    crank : bool
    """

    group: str
    joint: str
    position: float
    nearest: float
    sine: float
    condition: float
    crank: bool

    def __str__(self) -> str:
        where = lambda x, d=None: position_text(self.crank, _wrap(x) if self.crank else x, d)  # noqa: E731
        return (
            f"{self.group} passes a dead centre at {where(self.position, 2).replace(' = ', ' ≈ ')}: joint {self.joint}, "
            f"|sin| {self.sine:.1e} and condition {self.condition:.1e} at {where(self.nearest)}"
        )


@dataclass(frozen=True)
class SweepReport:
    lost: tuple[LostAssembly, ...]
    crossed: tuple[DeadCentreCrossing, ...]

    def messages(self) -> list[str]:
        return [str(x) for x in self.lost] + [str(x) for x in self.crossed]


def _wrap(phi: float) -> float:
    """An angle in [0, 2π)."""
    return math.fmod(math.fmod(phi, 2 * math.pi) + 2 * math.pi, 2 * math.pi)


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """(start, end) index ranges, end exclusive, of the True runs of a mask."""
    out = []
    k, n = 0, len(mask)
    while k < n:
        if mask[k]:
            end = k
            while end < n and mask[end]:
                end += 1
            out.append((k, end))
            k = end
        else:
            k += 1
    return out


def _limit(x_far: float, s_far: float, x_near: float, s_near: float, x_gap: float) -> float | None:
    """Where sin² reaches 0 past x_near, extrapolated linearly from two solved positions; within [x_near, x_gap]."""
    if not (math.isfinite(s_far) and math.isfinite(s_near)) or s_far <= s_near:
        return None
    t = s_near**2 / (s_far**2 - s_near**2)
    x = x_near + t * (x_near - x_far)
    lo, hi = sorted((x_near, x_gap))
    return min(max(x, lo), hi)


def analyse_sweep(solution, warn_condition: float = WARN_CONDITION) -> SweepReport:
    """Lost-assembly intervals and dead centres crossed along a solved sweep.

    Parameters
    ----------
    solution : plans.analytic.AnalyticSolution
        Solved with ``allow_partial=True`` over driver positions in the order
        the sweep runs through them.
    warn_condition : float
        A local minimum of a group's sine counts as a dead centre crossed
        when the group's condition number there exceeds this.

    Returns
    -------
    SweepReport
    """
    scene = solution.scene
    crank = isinstance(scene.driver, Crank)
    x = np.asarray(solution.driver, dtype=float)
    valid = np.asarray(solution.valid, dtype=bool)
    n = len(x)
    groups = solution.structure.groups
    lost = []
    runs = _runs(~valid)
    wrap = crank and n > 1 and runs and runs[-1][1] == n and not (runs[0][0] == 0)
    # one turn on, in the sense the sweep runs (that of ω for plans sweep)
    step = (2 * math.pi if n < 2 or x[-1] >= x[0] else -2 * math.pi) if crank else 0.0
    for start, end in runs:
        culprit, cause = groups[0].name if groups else "?", "cannot assemble"
        for group in groups:
            sine = np.asarray(solution.sines[group.name])[start:end]
            if np.any(np.isnan(sine)):
                culprit, cause = group.name, "cannot assemble"
                break
            if np.any(sine < REFUSE_SINE):
                culprit, cause = group.name, "dead centre"
                break
        sines = np.asarray(solution.sines[culprit])
        stop = resume = stop_limit = resume_limit = None
        if start > 0:
            stop = float(x[start - 1])
            if start > 1 and cause == "cannot assemble":
                stop_limit = _limit(x[start - 2], sines[start - 2], x[start - 1], sines[start - 1], x[start])
        if end < n:
            resume = float(x[end])
            if end + 1 < n and valid[end + 1] and cause == "cannot assemble":
                resume_limit = _limit(x[end + 1], sines[end + 1], x[end], sines[end], x[end - 1])
        elif wrap:
            resume = float(x[0] + step)
            if n > 1 and valid[1] and cause == "cannot assemble":
                resume_limit = _limit(x[1] + step, sines[1], x[0] + step, sines[0], x[-1])
        lost.append(LostAssembly(culprit, cause, float(x[start]), float(x[end - 1]), stop, resume, stop_limit, resume_limit, crank))

    crossed = []
    for group in groups:
        sine = np.asarray(solution.sines[group.name], dtype=float)
        condition = np.asarray(solution.conditions[group.name], dtype=float)
        for k in range(1, n - 1):
            if not (valid[k - 1] and valid[k] and valid[k + 1]):
                continue
            if not (condition[k] > warn_condition and sine[k] <= sine[k - 1] and sine[k] < sine[k + 1]):
                continue
            # |sin| ≈ a·|x − x0| near the dead centre: take the slope of the steeper side
            left = (sine[k - 1] - sine[k]) / abs(x[k] - x[k - 1])
            right = (sine[k + 1] - sine[k]) / abs(x[k + 1] - x[k])
            slope = max(left, right)
            direction = 1.0 if sine[k + 1] < sine[k - 1] else -1.0
            direction *= 1.0 if x[k + 1] > x[k] else -1.0
            position = float(x[k] + direction * sine[k] / slope) if slope > 0 else float(x[k])
            crossed.append(DeadCentreCrossing(group.name, group.joint, position, float(x[k]), float(sine[k]), float(condition[k]), crank))
    return SweepReport(tuple(lost), tuple(crossed))
