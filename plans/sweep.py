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
* **Parallel guides.**  The pin of a PRP group is where its two guides
  cross; where the guides turn through parallel between two grid positions
  (the sine of the angle between them changes sign) the pin passes through
  infinity: a loss of assembly between two solved rows, reported as such,
  never as a dead centre crossed.
* **Dead centres crossed.**  A local minimum of a group's sine, with the
  group's condition above the warning threshold and the mechanism solved on
  both sides, is a dead centre the sweep passed through (or close by); its
  driver position is interpolated from the V shape |sin| takes there.
  A dead centre hit exactly on a grid position (refused there) is reported
  as a lost interval of one position whose cause is ``"dead centre"``.

For a crank the sweep is one turn: a gap that runs into the end of the
sweep resumes at its start (one turn later).

It also writes the sweep as CSV (:func:`sweep_csv`), formatted column by
column (:func:`format_column`).
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass

import numpy as np

from .limits import REFUSE_SINE, WARN_CONDITION, expected_rel_error, position_text
from .scene import FRAME, Crank

__all__ = ["LostAssembly", "DeadCentreCrossing", "SweepReport", "analyse_sweep", "line_travel", "sweep_csv", "format_column", "DIGITS"]

#: Significant digits of a CSV column, at the scale of its largest value.
DIGITS = 14


@dataclass(frozen=True)
class LostAssembly:
    """A run of driver positions where the mechanism is not solved.

    Attributes
    ----------
    group : str
        The first group (in solving order) that fails in the run.
    cause : str
        ``"cannot assemble"``, ``"dead centre"``, or ``"guides parallel"``:
        the two guides of a PRP group turn through parallel between two
        solved grid positions, the pin joining its blocks passes through
        infinity (no grid position is unsolved; *first* = *last* is the
        position where the guides are parallel, interpolated, and *stop*,
        *resume* the solved positions on either side).
    first, last : float
        The first and last unsolved grid positions of the run.
    stop, resume : float or None
        The last solved position before the run and the first one after it
        (None at an end of a linear driver's stroke).
    stop_limit, resume_limit : float or None
        Estimated driver positions of the limits between them.
    crank : bool
        Positions are crank angles [rad] (else linear positions [m]).
    between : bool
        The loss lies between two solved grid positions (*stop*, *resume*)
        and no grid position is unsolved (parallel guides only).
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
    between: bool = False

    def __str__(self) -> str:
        where = lambda x, d=None: position_text(self.crank, _wrap(x) if self.crank else x, d)  # noqa: E731
        if self.cause == "guides parallel" and self.between:
            return (f"{self.group} loses assembly at {where(self.first, 2).replace(' = ', ' ≈ ')}: its two guides become "
                    f"parallel there and the pin joining its blocks goes to infinity: the sweep stops after {where(self.stop)} "
                    f"and resumes at {where(self.resume)}; the motion between those rows does not exist "
                    "(not a dead centre that can be crossed)")
        if self.cause == "guides parallel":
            span = where(self.first) if self.first == self.last else f"{where(self.first)} to {where(self.last)}"
            head = f"{self.group} loses assembly at {span}: its two guides are parallel and the pin joining its blocks is at infinity"
        elif self.cause == "dead centre":
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
            branch = "" if self.cause == "guides parallel" else " on the same branch"  # a PRP has one assembly
            parts.append(f"resumes at {where(self.resume)}{limit}{branch}")
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


def _guide_direction(scene, group, joint, phi):
    """The global angle [rad] of the line that link *joint.bodies[0]* has in the prismatic *joint*."""
    pair = joint.prismatic
    link = joint.bodies[0]
    line = scene.bodies[link].lines[pair.slider_line if pair.slider == link else pair.guide_line]
    return phi + line.angle


def _parallel_guides(solution, x: np.ndarray, valid: np.ndarray, crank: bool) -> list[tuple[LostAssembly, tuple[int, int]]]:
    """Where the two guides of a PRP group turn through parallel between two solved grid positions.

    Each block of a PRP turns with its guide; the signed sine of the angle
    from block i's line to block j's, sin(θ_j − θ_i), changes sign there.
    For a crank's full turn the last position and the first (one turn on)
    are neighbours too.  Each with the grid indices on either side.
    """
    scene = solution.scene
    out = []
    n = len(x)
    for group in solution.structure.groups:
        if group.kind != "PRP":
            continue
        i, j = group.links
        theta_i = _guide_direction(scene, group, group.outer_i, np.asarray(solution.links[i].phi, dtype=float))
        theta_j = _guide_direction(scene, group, group.outer_j, np.asarray(solution.links[j].phi, dtype=float))
        signed = np.where(valid, np.sin(theta_j - theta_i), np.nan)
        pairs = [(k, k + 1) for k in range(n - 1)]
        if crank and n > 2 and abs(x[-1] + (x[1] - x[0]) - (x[0] + 2 * math.pi)) <= 1e-9:  # a full turn
            pairs.append((n - 1, 0))
        for a, b in pairs:
            sa, sb = signed[a], signed[b]
            if not (sa * sb < 0):  # NaN (not solved) or no change of sign
                continue
            xa = float(x[a])
            xb = float(x[b]) + (2 * math.pi if b < a else 0.0)
            at = xa + (xb - xa) * sa / (sa - sb)  # linear interpolation to sin = 0
            out.append((LostAssembly(group.name, "guides parallel", at, at, xa, float(x[b]), None, None, crank, True), (a, b)))
    return out


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
                culprit, cause = group.name, "guides parallel" if group.kind == "PRP" else "cannot assemble"
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

    parallel = _parallel_guides(solution, x, valid, crank)
    lost += [item for item, _ in parallel]
    crossed = []
    flips = {(item.group, k) for item, pair in parallel for k in pair}
    for group in groups:
        sine = np.asarray(solution.sines[group.name], dtype=float)
        condition = np.asarray(solution.conditions[group.name], dtype=float)
        for k in range(1, n - 1):
            if not (valid[k - 1] and valid[k] and valid[k + 1]):
                continue
            if not (condition[k] > warn_condition and sine[k] <= sine[k - 1] and sine[k] < sine[k + 1]):
                continue
            if (group.name, k) in flips:
                continue  # a PRP's guides turning through parallel: lost, not crossed
            # |sin| ≈ a·|x − x0| near the dead centre: take the slope of the steeper side
            left = (sine[k - 1] - sine[k]) / abs(x[k] - x[k - 1])
            right = (sine[k + 1] - sine[k]) / abs(x[k + 1] - x[k])
            slope = max(left, right)
            direction = 1.0 if sine[k + 1] < sine[k - 1] else -1.0
            direction *= 1.0 if x[k + 1] > x[k] else -1.0
            position = float(x[k] + direction * sine[k] / slope) if slope > 0 else float(x[k])
            crossed.append(DeadCentreCrossing(group.name, group.joint, position, float(x[k]), float(sine[k]), float(condition[k]), crank))
    return SweepReport(tuple(lost), tuple(crossed))


# --- travel along the lines ------------------------------------------------------------------


def line_travel(solution) -> dict[str, tuple[float, float]]:
    """The stretch of each guide line that what slides on it uses over a solved sweep.

    For every line of a prismatic pair, ``"body.line"`` (``"4.slot"``,
    ``"frame.ram"``), the smallest and largest coordinate [m] along the line,
    from its origin (through point) in its own direction, of the points of the
    body that slides on it (for the guide's line) or, for a slider that is a
    link of its own (a rod sliding through a sleeve), of the guide body (for
    the rod's line only: the sleeve is a collar), over the positions
    where the mechanism is solved.  A line with nothing solved is left out.
    Read from the sweep's positions and poses; nothing is solved here.

    A drawing uses it to draw a slot or a guide over the travel of the cycle
    (:func:`plans.drawing.draw_mechanism`, ``slots``).
    """
    scene = solution.scene
    valid = np.asarray(solution.valid, dtype=bool)
    if not valid.any():
        return {}
    found: dict[str, list[float]] = {}

    def along(body: str, line_name: str, riders) -> None:
        line = scene.bodies[body].lines[line_name]
        phi, origin = solution.poses[body]
        phi = np.broadcast_to(np.asarray(phi, dtype=float), valid.shape)[valid]
        origin = np.broadcast_to(np.asarray(origin, dtype=complex), valid.shape)[valid]
        start = origin + np.exp(1j * phi) * line.origin
        u = np.exp(1j * (phi + line.angle))
        for point in riders:
            r = np.broadcast_to(np.asarray(solution.points[point].r, dtype=complex), valid.shape)[valid]
            t = ((r - start) * u.conjugate()).real
            t = t[np.isfinite(t)]
            if t.size:
                found.setdefault(f"{body}.{line_name}", []).extend((float(t.min()), float(t.max())))

    for pair in scene.prismatics:
        if pair.guide != FRAME and pair.slider != FRAME and len(scene.bodies[pair.slider].points) > 1:
            # a rod through a sleeve: the rod is drawn over where the sleeve rides on it; the sleeve stays a
            # collar (its line over the rod's points would draw the rod again, past its ends)
            along(pair.slider, pair.slider_line, scene.bodies[pair.guide].points)
        else:
            along(pair.guide, pair.guide_line, scene.bodies[pair.slider].points)
    return {key: (min(ts), max(ts)) for key, ts in sorted(found.items())}


# --- the CSV ---------------------------------------------------------------------------------


def format_column(values, shown=None, degrees: bool = False) -> list[str]:
    """The cells of one CSV column: each value to :data:`DIGITS` significant digits of the column's scale.

    The scale is the largest magnitude among the cells shown, 10^e with e
    its decimal exponent; every value is rounded to a multiple of
    10^(e − DIGITS + 1) and written in the shortest form that reads back as
    that number.  So a result that is an input up to round-off comes back as
    given (``29.999999999999996`` in a column of angles up to 350 is ``30``,
    ``57.00000000000001`` is ``57``), and round-off far below the column's
    scale is ``0`` (``-6.8e-18`` beside values of order 1).  With *degrees*
    angles are given in [0, 360) (after rounding, so that 359.99999999999994
    is 0).  A cell not shown (*shown* False), NaN or infinite is empty.

    >>> format_column([57.00000000000001, 411.99999999999994, -6.77126e-18, 0.5])
    ['57', '412', '0', '0.5']
    >>> format_column([-90.0, 29.999999999999996, 359.99999999999994], degrees=True)
    ['270', '30', '0']
    """
    x = np.array(values, dtype=float)
    keep = np.isfinite(x) if shown is None else np.isfinite(x) & np.asarray(shown, dtype=bool)
    cells = [""] * len(x)
    if not keep.any():
        return cells
    if degrees:
        x = np.mod(x, 360.0)
    scale = float(np.abs(x[keep]).max())
    if scale > 0:
        decimals = DIGITS - 1 - math.floor(math.log10(scale))
        if decimals <= 22:  # 10^decimals is exact: numpy's rounding (x·10^d to an integer, / 10^d) is exact too
            x = np.round(x, decimals)
        else:  # a column of tiny values: Python's correctly rounded decimal rounding
            x = np.array([round(value, decimals) for value in x.tolist()])
    if degrees:
        x[x >= 360.0] -= 360.0
    x = x + 0.0  # −0 is 0
    # a rounded value has at most DIGITS significant digits: %g to DIGITS digits writes exactly them,
    # the shortest text that reads back as it (and a third faster than repr)
    texts = list(map(f"%.{DIGITS}g".__mod__, x[keep].tolist()))
    if len(texts) == len(cells):
        return texts
    for k, text in zip(np.flatnonzero(keep).tolist(), texts):
        cells[k] = text
    return cells


def sweep_csv(analytic, t=None, forces=None) -> str:
    """Every quantity over the solved driver positions, one row per position.

    Columns: the driver position (``driver_phi_deg`` for a crank, ``driver_s``
    [m] for a linear driver), with *t* the time ``t`` [s] from the first row
    (a cycle's, :attr:`plans.motion.Cycle.t`: then every rate column is the
    time derivative of the column it rates), ``assembled`` (1 or 0), then per link
    ``phi_deg``, ``omega``, ``epsilon``; per reported point ``x, y, vx, vy,
    ax, ay``; per slider ``s, v_rel, a_rel, coriolis_x, coriolis_y``; per
    group its condition number, the |sin| of the angle between its
    construction lines and the expected relative error of its velocities and
    accelerations (4·ε_mach·condition², :mod:`plans.limits`).  SI units;
    angles in degrees in [0, 360), counter-clockwise from +x.  Acceleration
    columns are left out when the scene asks for velocities only.  Positions
    where the mechanism cannot assemble or sits at a dead centre have empty
    cells and ``assembled = 0``; a cell is never NaN or infinite.  Numbers
    are written to 14 significant digits of their column's scale
    (:func:`format_column`): inputs come back as given, round-off prints as 0.

    With *forces* (:class:`plans.forces.analytic.AnalyticForces` of the same
    positions, for a scene with masses or loads) the kinetostatics follows:
    ``M_b`` [N·m] on a crank (``F_b`` [N] on a linear driver) and, per
    reaction, ``R_ij.magnitude`` [N] (the force of body i on body j, the
    frame 0).
    """
    scene = analytic.scene
    acc = scene.accelerations
    valid = np.asarray(analytic.valid, dtype=bool)
    header: list[str] = []
    cells: list[list[str]] = []

    def add(name: str, values, degrees: bool = False, shown=valid) -> None:
        header.append(name)
        cells.append(format_column(values, shown, degrees))

    crank = isinstance(scene.driver, Crank)
    if crank:
        add("driver_phi_deg", np.degrees(analytic.driver), degrees=True, shown=None)
    else:
        add("driver_s", analytic.driver, shown=None)
    if t is not None:
        add("t", np.asarray(t, dtype=float), shown=None)
    header.append("assembled")
    cells.append(["1" if v else "0" for v in valid.tolist()])
    for name in scene.links:
        m = analytic.links[name]
        add(f"{name}.phi_deg", np.degrees(m.phi), degrees=True)
        add(f"{name}.omega", m.omega)
        if acc:
            add(f"{name}.epsilon", m.epsilon)
    for name in scene.report:
        m = analytic.points[name]
        add(f"{name}.x", m.r.real)
        add(f"{name}.y", m.r.imag)
        add(f"{name}.vx", m.v.real)
        add(f"{name}.vy", m.v.imag)
        if acc:
            add(f"{name}.ax", m.a.real)
            add(f"{name}.ay", m.a.imag)
    for prismatic in scene.prismatics:
        m = analytic.sliders[prismatic.name]
        add(f"{prismatic.name}.s", m.s)
        add(f"{prismatic.name}.v_rel", m.v_rel)
        if acc:
            add(f"{prismatic.name}.a_rel", m.a_rel)
            add(f"{prismatic.name}.coriolis_x", m.coriolis.real)
            add(f"{prismatic.name}.coriolis_y", m.coriolis.imag)
    for group in analytic.structure.groups:
        condition = np.asarray(analytic.conditions[group.name])
        add(f"{group.name}.condition", np.maximum(condition, 1.0))  # at least 1 (round-off can give 1 − 1e-16)
        add(f"{group.name}.sine", np.minimum(np.asarray(analytic.sines[group.name]), 1.0))
        add(f"{group.name}.expected_rel_error", expected_rel_error(condition))
    if forces is not None:
        add("M_b" if forces.balancing_kind == "moment" else "F_b", forces.balancing)
        for label, reaction in forces.reactions.items():
            add(f"{label}.magnitude", reaction.magnitude)
    out = io.StringIO()
    csv.writer(out, lineterminator="\n").writerow(header)  # names from the scene may need quoting; numbers do not
    out.write("\n".join(",".join(row) for row in zip(*cells)))
    if cells and cells[0]:
        out.write("\n")
    return out.getvalue()
