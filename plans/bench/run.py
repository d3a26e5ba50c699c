"""Error against run time, for both methods, on a fixed suite of scenes.

For every case of :func:`plans.bench.cases.suite` and every method setting,
the benchmark measures the run time per driver position and the largest
relative errors of positions, velocities and accelerations against the
50-digit reference of :mod:`plans.bench.reference`.

**Relative error** of a kind X ∈ {r, v, a} at one driver position: the
largest error over the scene's named points, over the largest reference
magnitude of that kind at that position,

    e_X = max_P |X_P − X_P,ref| / max_P |X_P,ref|,

and a row reports the largest e_X over the sample positions it was compared
at.  (The error is relative to the mechanism's scale, not to each point, so
a point at rest does not divide by zero.)  It is computed at 50 digits.

**Time per position**: the best over repeated calls of one call's wall
time (the least disturbed by other work on the machine; the median is kept
in the CSV), divided by the positions it solves; one call solves N positions
(analytic, yardstick) or one (graphical).  The scene's structure is found
once beforehand and passed in.  The cost-of-generality ratio times plans'
solver and the yardstick alternately on the same positions.

Method settings
---------------
* ``analytic`` at N = 1, 360, 3600, 100 000: :func:`plans.analytic.solve`
  over N positions of the case's sweep that include the sample positions;
  the errors are read at those.
* ``yardstick`` (slider-cranks only): :mod:`plans.bench.yardstick`, the
  offset slider-crank in closed numpy form.  At N = 1 it is timed twice
  against plans: a bare call, and a call with every attribute of the
  result read (:data:`READ_ALL`; plans makes the result's dicts and arrays
  when they are first read).
* ``graphical exact``: :func:`plans.graphical.construct` with exact arcs.
* ``graphical arcs``: arcs as shapely polygons with n segments per quarter
  circle; positions, and what is constructed from them, are as good as the
  polygons.
* ``graphical drafting``: readings rounded to a drafting precision of 0.1 mm
  or 0.5 mm at the automatic scales, as a hand construction gives them;
  positions are read off the mechanism drawing at k_l with the same
  precision (each coordinate rounded to the precision).

At a sample position the graphical construction is asked for the branch the
reference follows (the assembly hints are moved to the reference's points).
A position a method refuses (no assembly, a dead centre) counts as failed.
"""

from __future__ import annotations

import csv
import io
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field, replace
from pathlib import Path

import mpmath
import numpy as np

from ..errors import PlansError
from ..scene import Scene
from ..structure import find_structure
from .cases import Case, suite
from .reference import DIGITS, Reference, ReferenceError, reference
from .yardstick import offset_slider_crank

__all__ = [
    "METHODS", "Settings", "DEFAULT", "QUICK", "Row", "Target", "BenchResult", "run_bench", "time_call", "time_pair", "relative_errors",
    "summary", "markdown", "to_csv", "CSV_FIELDS",
]


@dataclass(frozen=True)
class Settings:
    """What the benchmark runs.

    Attributes
    ----------
    ns : tuple[int, ...]
        Numbers of positions per analytic call.
    yardstick_ns : tuple[int, ...]
        Numbers of positions per yardstick call.
    samples : int
        Reference positions per case.
    arc_segments : tuple[int, ...]
        Segments per quarter circle of the polygon arcs.
    precisions : tuple[float, ...]
        Drafting precisions [mm].
    budget : float
        Seconds of timing per setting (at least three timed repeats).
    processes : bool
        Also time ``plans solve`` and ``plans draw`` as whole processes.
    process_runs : int
        Runs of each (the median is reported).
    cold_ns : tuple[int, ...]
        Sizes at which the first call in a fresh process (memory not yet
        touched: page faults) is timed for plans and for the yardstick.
    cases : tuple[str, ...] or None
        Only these cases (None: the whole suite).
    """

    ns: tuple[int, ...] = (1, 360, 3600, 100_000)
    yardstick_ns: tuple[int, ...] = (1, 3600, 100_000)
    samples: int = 8
    arc_segments: tuple[int, ...] = (2, 8, 32, 128)
    precisions: tuple[float, ...] = (0.1, 0.5)
    budget: float = 0.15
    processes: bool = True
    process_runs: int = 5
    cases: tuple[str, ...] | None = None
    cold_ns: tuple[int, ...] = ()


#: ``plans bench``: about 40 s on a 2-CPU virtual machine.
DEFAULT = Settings(cold_ns=(3600, 100_000))
#: ``plans bench --quick``: a smoke run, a few seconds.
QUICK = Settings(
    ns=(1, 360, 3600), yardstick_ns=(1, 3600), samples=3, arc_segments=(4, 32), budget=0.01, processes=False, cold_ns=()
)


@dataclass(frozen=True)
class Row:
    """One case and method setting.

    ``kind`` is the case's (``"example"`` or ``"stiff"``); ``seconds`` is the
    best wall time per position over the timed repeats [s] and ``median`` their
    median; ``err_r``, ``err_v``, ``err_a`` the largest relative errors (NaN
    when no position could be compared); ``compared`` and ``failed`` count the
    sample positions compared and refused.  On a yardstick row, ``versus`` is
    plans' general solver on the same positions, timed alternately with the
    yardstick (best per position [s]), for the cost-of-generality ratio.
    """

    case: str
    kind: str
    method: str
    setting: str
    n: int
    seconds: float
    median: float
    err_r: float
    err_v: float
    err_a: float
    compared: int
    failed: int
    versus: float = math.nan

    @property
    def rate(self) -> float:
        """Positions per second."""
        return 1.0 / self.seconds if self.seconds > 0 else math.inf


@dataclass(frozen=True)
class Target:
    """A performance target (issues 6 and 14) and what this run measured."""

    name: str
    goal: str
    measured: str
    met: bool | None  # None: not measured in this run


@dataclass(frozen=True)
class BenchResult:
    machine: str
    settings: Settings
    rows: list[Row]
    targets: list[Target]
    processes: dict[str, float] = field(default_factory=dict)
    seconds: float = 0.0
    cold: dict[int, tuple[float, float]] = field(default_factory=dict)
    #: Kinetostatics (issue 22): best seconds of the kinematics, of the kinematics and the forces, at 3600 positions.
    forces: dict[str, float] = field(default_factory=dict)


#: The methods, in the order tables list them.
METHODS = ("analytic", "yardstick", "graphical exact", "graphical arcs", "graphical drafting")


# --- timing ------------------------------------------------------------------------------


def _calibrate(function) -> int:
    """How many calls of *function* last about 2 ms (at least one), after one untimed call."""
    function()
    start = time.perf_counter()
    function()
    return max(1, math.ceil(0.002 / max(time.perf_counter() - start, 1e-7)))


def time_call(function, budget: float, repeats: int = 3) -> tuple[float, float]:
    """(median, best) wall time of one call [s], over at least *repeats* timed samples.

    One untimed call first; each sample loops enough calls to last ≥ 2 ms, and
    samples are taken until *budget* seconds are spent (at least *repeats*,
    at most 25).  On a shared machine the best is the number that describes
    the code; the median says how much the machine was disturbed.
    """
    loops = _calibrate(function)
    samples = []
    spent = 0.0
    while len(samples) < repeats or (spent < budget and len(samples) < 25):
        start = time.perf_counter()
        for _ in range(loops):
            function()
        elapsed = time.perf_counter() - start
        spent += elapsed
        samples.append(elapsed / loops)
    return statistics.median(samples), min(samples)


def time_pair(first, second, budget: float, repeats: int = 5) -> tuple[tuple[float, float], tuple[float, float]]:
    """(median, best) of one call of each of two functions, timed in alternating samples.

    Alternating makes a ratio of the two fair on a machine whose load
    changes during the run.
    """
    loops = [_calibrate(function) for function in (first, second)]
    samples: tuple[list[float], list[float]] = ([], [])
    spent = 0.0
    while len(samples[0]) < repeats or (spent < 2 * budget and len(samples[0]) < 25):
        for function, count, out in zip((first, second), loops, samples):
            start = time.perf_counter()
            for _ in range(count):
                function()
            elapsed = time.perf_counter() - start
            spent += elapsed
            out.append(elapsed / count)
    return tuple((statistics.median(out), min(out)) for out in samples)


def machine() -> str:
    """The machine and software the benchmark ran on, in one line."""
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as handle:
            for line in handle:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    import shapely

    return (
        f"{cpu}, {os.cpu_count()} CPUs, {platform.system()} {platform.release()}; "
        f"Python {platform.python_version()} ({platform.python_implementation()}), numpy {np.__version__}, "
        f"shapely {shapely.__version__}, mpmath {mpmath.__version__}"
    )


# --- errors ------------------------------------------------------------------------------


def relative_errors(ref: Reference, values: dict[str, tuple[complex, complex, complex]]) -> tuple[float, float, float]:
    """(e_r, e_v, e_a) of *values* (point → r, v, a) against the reference (module docstring)."""
    out = []
    with mpmath.workdps(DIGITS):
        for kind in range(3):
            scale = max(abs(ref.points[name][kind]) for name in values)
            worst = mpmath.mpf(0)
            for name, triple in values.items():
                got = complex(triple[kind])
                if not (math.isfinite(got.real) and math.isfinite(got.imag)):
                    return (math.nan, math.nan, math.nan)
                worst = max(worst, abs(mpmath.mpc(got.real, got.imag) - ref.points[name][kind]))
            if scale == 0:
                out.append(0.0 if worst == 0 else math.inf)
            else:
                out.append(float(worst / scale))
    return tuple(out)


def _worst(errors: list[tuple[float, float, float]]) -> tuple[float, float, float]:
    if not errors:
        return (math.nan, math.nan, math.nan)
    return tuple(max(e[k] for e in errors) for k in range(3))


# --- the methods ---------------------------------------------------------------------------


def _at(scene: Scene, position: float, ref: Reference) -> Scene:
    """The scene at another driver position, its assembly hints moved to the reference's points."""
    hints = {name: complex(ref.points[name][0]) for name in scene.assembly}
    return replace(scene.at(position), assembly=hints)


def _references(case: Case, structure) -> list[Reference | None]:
    from ..analytic import solve

    seeds = solve(case.scene, np.asarray(case.samples), structure, allow_partial=True)
    out = []
    for k, x in enumerate(case.samples):
        if not seeds.valid[k]:
            out.append(None)
            continue
        seed = {name: (float(phi[k]), complex(origin[k])) for name, (phi, origin) in seeds.poses.items()}
        try:
            out.append(reference(case.scene, x, seed))
        except ReferenceError:
            out.append(None)
    return out


def _analytic_rows(case: Case, structure, refs, settings: Settings) -> list[Row]:
    from ..analytic import solve

    rows = []
    for n in settings.ns:
        positions, index = case.grid(n)
        solution = solve(case.scene, positions, structure, allow_partial=True)
        errors, failed = [], 0
        for j, k in enumerate(index):
            ref = refs[j]
            if ref is None:
                continue
            if not solution.valid[k]:
                failed += 1
                continue
            values = {name: (m.r[k], m.v[k], m.a[k]) for name, m in solution.points.items()}
            errors.append(relative_errors(ref, values))
        median, best = time_call(lambda: solve(case.scene, positions, structure, allow_partial=True), settings.budget)
        rows.append(Row(case.name, case.kind, "analytic", f"N = {n}", n, best / n, median / n, *_worst(errors), len(errors), failed))
    return rows


def _yardstick_rows(case: Case, structure, refs, settings: Settings) -> list[Row]:
    from ..analytic import solve

    p = case.yardstick
    rows = []
    for n in settings.yardstick_ns:
        positions, index = case.grid(n)
        points, _ = offset_slider_crank(positions, p["r"], p["l"], p["e"], p["omega"], p["epsilon"])
        errors = []
        for j, k in enumerate(index):
            if refs[j] is None:
                continue
            values = {name: tuple(points[name][:, k]) for name in ("A", "B")}
            values["O"] = (0j, 0j, 0j)
            errors.append(relative_errors(refs[j], values))
        (median, best), (_, general) = time_pair(
            lambda: offset_slider_crank(positions, p["r"], p["l"], p["e"], p["omega"], p["epsilon"]),
            lambda: solve(case.scene, positions, structure, allow_partial=True),
            settings.budget,
        )
        rows.append(
            Row(case.name, case.kind, "yardstick", f"N = {n}", n, best / n, median / n, *_worst(errors), len(errors), 0, general / n)
        )
        if n == 1:
            # plans makes the result's dicts and arrays when they are first read: time it with all of them read too
            (median, best), (_, general) = time_pair(
                lambda: offset_slider_crank(positions, p["r"], p["l"], p["e"], p["omega"], p["epsilon"]),
                lambda: read_all(solve(case.scene, positions, structure, allow_partial=True)),
                settings.budget,
            )
            rows.append(Row(case.name, case.kind, "yardstick", READ_ALL, n, best, median, *_worst(errors), len(errors), 0, general))
    return rows


#: The yardstick row at one position timed against plans with every attribute of the result read.
READ_ALL = "N = 1, plans' result read in full"


def read_all(solution):
    """Read every attribute of a solution: its dicts of motions and their arrays are made on first reading."""
    for name in ("links", "points", "sliders", "poses", "origins", "conditions", "sines", "valid"):
        getattr(solution, name)
    return solution


def _drafted(z: complex, k_l: float, precision: float) -> complex:
    """A position read off the mechanism drawing at k_l [m/mm], each coordinate to *precision* [mm]."""
    step = k_l * precision
    return complex(round(z.real / step) * step, round(z.imag / step) * step)


def _graphical_rows(case: Case, structure, refs, settings: Settings) -> list[Row]:
    from ..graphical import construct

    scenes = [(_at(case.scene, x, ref), ref) for x, ref in zip(case.samples, refs) if ref is not None]
    variants = [("graphical exact", "exact arcs", {})]
    variants += [("graphical arcs", f"{n} seg/quarter", {"arc_segments": n}) for n in settings.arc_segments]
    variants += [("graphical drafting", f"{p:g} mm", {"precision": p}) for p in settings.precisions]
    rows = []
    for method, setting, options in variants:
        errors, failed, good = [], 0, []
        for scene, ref in scenes:
            try:
                g = construct(scene, structure, **options)
            except (PlansError, ArithmeticError, ValueError):
                failed += 1
                continue
            good.append(scene)
            precision = options.get("precision")
            values = {}
            for name in scene.point_names:
                r = g.positions[name]
                if precision is not None:
                    r = _drafted(r, g.scales["k_l"], precision)
                values[name] = (r, g.points[name]["v"], g.points[name].get("a", 0j))
            errors.append(relative_errors(ref, values))
        if good:

            def run(good=good, options=options):
                for scene in good:
                    construct(scene, structure, **options)

            median, best = time_call(run, settings.budget)
            median, best = median / len(good), best / len(good)
        else:
            median = best = math.nan
        rows.append(Row(case.name, case.kind, method, setting, 1, best, median, *_worst(errors), len(errors), failed))
    return rows


def run_case(case: Case, settings: Settings) -> list[Row]:
    """Every method setting on one case."""
    structure = find_structure(case.scene)
    refs = _references(case, structure)
    rows = _analytic_rows(case, structure, refs, settings)
    if case.yardstick is not None:
        rows += _yardstick_rows(case, structure, refs, settings)
    rows += _graphical_rows(case, structure, refs, settings)
    return rows


# --- whole processes -------------------------------------------------------------------------


def time_processes(runs: int) -> dict[str, float]:
    """Median wall time [s] of whole ``plans`` processes started cold, and of a bare interpreter."""
    root = str(Path(__file__).resolve().parents[2])
    env = dict(os.environ)
    env["PYTHONPATH"] = root + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        commands = {
            "python -c pass": [sys.executable, "-c", "pass"],
            "plans solve --example six-bar": [sys.executable, "-m", "plans", "solve", "--example", "six-bar"],
            "plans draw --example six-bar": [sys.executable, "-m", "plans", "draw", "--example", "six-bar", "-o", tmp],
        }
        for name, command in commands.items():
            times = []
            for _ in range(runs):
                start = time.perf_counter()
                done = subprocess.run(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
                times.append(time.perf_counter() - start)
                if done.returncode != 0:
                    times = [math.nan]
                    break
            out[name] = statistics.median(times)
    return out


_COLD = """
import sys, time
from plans.bench.cases import suite
from plans.bench.yardstick import offset_slider_crank
from plans.analytic import solve
from plans.structure import find_structure
which, n = sys.argv[1], int(sys.argv[2])
case = next(c for c in suite(1) if c.name == "slider-crank")
p = case.yardstick
positions, _ = case.grid(n)
structure = find_structure(case.scene)
if which == "plans":
    run = lambda x: solve(case.scene, x, structure, allow_partial=True)
else:
    run = lambda x: offset_slider_crank(x, p["r"], p["l"], p["e"], p["omega"], p["epsilon"])
run(positions[:2])  # the code is loaded and the scene prepared; the memory for n positions is not yet touched
start = time.perf_counter()
run(positions)
print(time.perf_counter() - start)
"""


def time_cold(ns: tuple[int, ...], runs: int) -> dict[int, tuple[float, float]]:
    """Per size n: median wall time [s] of the first n-position call in a fresh process, (plans, yardstick).

    The offset slider-crank of the suite.  Each process solves two positions
    first, so what is timed is the call itself with memory the process has
    not used yet (page faults), as in a one-shot ``plans sweep``.
    """
    root = str(Path(__file__).resolve().parents[2])
    env = dict(os.environ)
    env["PYTHONPATH"] = root + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    out = {}
    for n in ns:
        times = {}
        for which in ("plans", "yardstick"):
            samples = []
            for _ in range(runs):
                done = subprocess.run([sys.executable, "-c", _COLD, which, str(n)], env=env, capture_output=True, text=True)
                samples.append(float(done.stdout) if done.returncode == 0 else math.nan)
            times[which] = statistics.median(samples)
        out[n] = (times["plans"], times["yardstick"])
    return out


# --- targets -------------------------------------------------------------------------------


def _find(rows: list[Row], case: str, method: str, setting: str) -> Row | None:
    for row in rows:
        if (row.case, row.method, row.setting) == (case, method, setting):
            return row
    return None


#: The scene and the number of positions the kinetostatics is timed at (issue 22).
FORCES_CASE = ("six-bar-loads", 3600)


def time_forces(budget: float) -> dict[str, float]:
    """Best wall times [s] of the kinematics and of the kinematics with the forces, over FORCES_CASE, alternately.

    ``kinematics``: :func:`plans.analytic.solve` with every attribute of the
    result read (:func:`read_all`); ``kinetostatics``: the same solve and
    :func:`plans.forces.analytic.forces_from` (which reads what it needs).
    """
    from ..analytic import solve
    from ..forces.analytic import forces_from
    from ..scene import example_path, load

    name, n = FORCES_CASE
    scene = load(example_path(name))
    structure = find_structure(scene)
    positions = scene.driver.phi + np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    (_, kinematics), (_, both) = time_pair(
        lambda: read_all(solve(scene, positions, structure)), lambda: forces_from(solve(scene, positions, structure)), budget
    )
    return {"kinematics": kinematics, "kinetostatics": both}


def _targets(rows: list[Row], processes: dict[str, float], cold: dict[int, tuple[float, float]] | None = None,
             forces: dict[str, float] | None = None) -> list[Target]:
    targets = []

    def add(name, goal, value, text, limit, below=True):
        if value is None or not math.isfinite(value):
            targets.append(Target(name, goal, "not measured", None))
        else:
            targets.append(Target(name, goal, text(value), value <= limit if below else value >= limit))

    row = _find(rows, "six-bar", "analytic", "N = 3600")
    add("analytic, six-bar, 3600 positions with v and a", "≤ 2 ms", row and row.seconds * 3600,
        lambda v: f"{v * 1e3:.2f} ms", 2e-3)
    row = _find(rows, "slider-crank", "analytic", "N = 100000")
    add("analytic, offset slider-crank, N = 100 000", "≥ 8 M positions/s", row and row.rate,
        lambda v: f"{v / 1e6:.2f} M/s", 8e6, below=False)
    for n in (3600, 100_000):
        yard = _find(rows, "slider-crank", "yardstick", f"N = {n}")
        ratio = yard.versus / yard.seconds if yard else None
        add(f"cost of generality: solve / yardstick at N = {n}", "≤ 2×", ratio, lambda v: f"{v:.1f}×", 2.0)
    row = _find(rows, "six-bar", "graphical exact", "exact arcs")
    add("graphical, six-bar, one position, both plans", "≤ 2 ms", row and row.seconds, lambda v: f"{v * 1e3:.2f} ms", 2e-3)
    # issue 14
    row = _find(rows, "slider-crank", "analytic", "N = 1")
    add("analytic, offset slider-crank, one position", "< 30 µs", row and row.seconds, lambda v: f"{v * 1e6:.1f} µs", 30e-6)
    yard = _find(rows, "slider-crank", "yardstick", "N = 1")
    add("one position: solve / yardstick", "≤ 1.5×", yard.versus / yard.seconds if yard else None, lambda v: f"{v:.2f}×", 1.5)
    row = _find(rows, "six-bar", "analytic", "N = 1")
    add("analytic, six-bar, one position", "< 60 µs", row and row.seconds, lambda v: f"{v * 1e6:.1f} µs", 60e-6)
    for n, (general, yardstick) in sorted((cold or {}).items()):
        add(f"cost of generality, cold (first call in a fresh process) at N = {n}", "≤ 2×", general / yardstick,
            lambda v: f"{v:.1f}×", 2.0)
    row = _find(rows, "six-bar", "graphical exact", "exact arcs")
    add("graphical, six-bar, one position, both plans (issue 14)", "< 250 µs", row and row.seconds,
        lambda v: f"{v * 1e6:.0f} µs", 250e-6)
    add("plans solve --example six-bar, whole process", "≤ 0.5 s", processes.get("plans solve --example six-bar"),
        lambda v: f"{v:.2f} s", 0.5)
    add("plans draw --example six-bar (four SVGs), whole process", "≤ 3 s", processes.get("plans draw --example six-bar"),
        lambda v: f"{v:.2f} s", 3.0)
    if forces:  # issue 22: the forces over 3600 positions against the kinematics they start from
        kinematics, both = forces["kinematics"], forces["kinetostatics"]
        add(f"kinetostatics, {FORCES_CASE[0]}, {FORCES_CASE[1]} positions: forces / kinematics", "≤ 2×",
            (both - kinematics) / kinematics,
            lambda v: f"{v:.1f}× ({kinematics * 1e3:.2f} ms kinematics, {both * 1e3:.2f} ms with the forces)", 2.0)
    return targets


# --- the run -------------------------------------------------------------------------------------


def run_bench(settings: Settings = DEFAULT, progress=None) -> BenchResult:
    """Run the suite; *progress* (a callable taking a line of text) hears of each case."""
    start = time.perf_counter()
    cases = suite(settings.samples)
    if settings.cases is not None:
        known = {case.name for case in cases}
        unknown = [name for name in settings.cases if name not in known]
        if unknown:
            raise ValueError(f"no bench case {', '.join(unknown)}; the cases are: {', '.join(sorted(known))}")
        cases = [case for case in cases if case.name in settings.cases]
    rows = []
    for case in cases:
        if progress:
            progress(f"bench: {case.name}")
        rows += run_case(case, settings)
    processes = {}
    if settings.processes:
        if progress:
            progress("bench: whole processes")
        processes = time_processes(settings.process_runs)
    cold = {}
    if settings.cold_ns and any(case.name == "slider-crank" for case in cases):
        if progress:
            progress("bench: first calls in fresh processes")
        cold = time_cold(settings.cold_ns, max(3, settings.process_runs))
    forces = {}
    if any(case.name == "six-bar" for case in cases):
        if progress:
            progress("bench: kinetostatics")
        forces = time_forces(settings.budget)
    return BenchResult(machine(), settings, rows, _targets(rows, processes, cold, forces), processes, time.perf_counter() - start,
                       cold, forces)


# --- output ------------------------------------------------------------------------------------

CSV_FIELDS = ("case", "kind", "method", "setting", "n", "seconds_per_position", "median_seconds_per_position",
              "positions_per_second", "err_r", "err_v", "err_a", "compared", "failed", "general_seconds_per_position")


def to_csv(result: BenchResult) -> str:
    """The rows as CSV (one header line; times in s, errors relative)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(CSV_FIELDS)
    for r in result.rows:
        writer.writerow([r.case, r.kind, r.method, r.setting, r.n, f"{r.seconds:.6g}", f"{r.median:.6g}", f"{r.rate:.6g}",
                         f"{r.err_r:.3g}", f"{r.err_v:.3g}", f"{r.err_a:.3g}", r.compared, r.failed,
                         "" if math.isnan(r.versus) else f"{r.versus:.6g}"])
    return buffer.getvalue()


def _time(seconds: float) -> str:
    if not math.isfinite(seconds):
        return "—"
    for unit, factor in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6), ("ns", 1e-9)):
        if seconds >= factor:
            return f"{seconds / factor:.3g} {unit}"
    return f"{seconds / 1e-9:.2g} ns"


def _rate(rate: float) -> str:
    if not math.isfinite(rate):
        return "—"
    if rate >= 1e6:
        return f"{rate / 1e6:.3g} M"
    if rate >= 1e3:
        return f"{rate / 1e3:.3g} k"
    return f"{rate:.3g}"


def _error(value: float) -> str:
    return "—" if math.isnan(value) else f"{value:.1e}"


def _errors(rows: list[Row]) -> str:
    if not rows:
        return "—"
    return " / ".join(_error(max((getattr(r, k) for r in rows), default=math.nan)) for k in ("err_r", "err_v", "err_a"))


def summary(result: BenchResult) -> str:
    """One line per method setting: median time per position over the cases, worst errors by kind of case."""
    lines = [
        "| method | setting | time / position (median over cases) | worst err r / v / a, bundled examples | worst err r / v / a, stiff cases |",
        "|---|---|--:|--:|--:|",
    ]
    order = {name: k for k, name in enumerate(METHODS)}
    settings = sorted(dict.fromkeys((r.method, r.setting) for r in result.rows), key=lambda m: order.get(m[0], len(order)))
    for method, setting in settings:
        rows = [r for r in result.rows if (r.method, r.setting) == (method, setting)]
        times = [r.seconds for r in rows if math.isfinite(r.seconds)]
        compared = [r for r in rows if r.compared]
        examples = [r for r in compared if r.kind == "example"]
        stiff = [r for r in compared if r.kind == "stiff"]
        time_text = _time(statistics.median(times)) if times else "—"
        lines.append(f"| {method} | {setting} | {time_text} | {_errors(examples)} | {_errors(stiff)} |")
    return "\n".join(lines) + "\n"


def markdown(result: BenchResult) -> str:
    """The results as Markdown: the machine, the summary, the targets, then every row."""
    settings = result.settings
    lines = [
        f"Ran on: {result.machine}; {result.seconds:.0f} s in all.",
        "",
        f"Errors: the largest over {settings.samples} sample positions per case of max_P |X_P − X_P,ref| / max_P |X_P,ref| "
        "(X = r, v, a; P the scene's points), against a 50-digit mpmath solution of the Cartesian constraint equations. "
        "Times: the best wall time of one call over repeated calls (the least disturbed; medians are in the CSV), "
        "divided by the positions it solves. The cost-of-generality ratio times plans' solver and the yardstick "
        "alternately on the same positions.",
        "",
        summary(result),
        "| target | goal | measured | |",
        "|---|---|--:|---|",
    ]
    for t in result.targets:
        verdict = "not measured" if t.met is None else ("met" if t.met else "**missed**")
        lines.append(f"| {t.name} | {t.goal} | {t.measured} | {verdict} |")
    read = _find(result.rows, "slider-crank", "yardstick", READ_ALL)
    if read:
        lines += ["", f"One position of the offset slider-crank with every attribute of plans' result read (its dicts and "
                  f"arrays are made when first read): plans {read.versus * 1e6:.1f} µs, yardstick {read.seconds * 1e6:.1f} µs, "
                  f"{read.versus / read.seconds:.2f}×."]
    if result.cold:
        lines += ["", "First call in a fresh process (offset slider-crank, median of fresh processes, wall time): "
                  + "; ".join(f"N = {n}: plans {general * 1e3:.2f} ms, yardstick {yardstick * 1e3:.2f} ms"
                              for n, (general, yardstick) in sorted(result.cold.items())) + "."]
    if result.processes:
        lines += ["", f"Whole processes (median of {settings.process_runs} runs, wall time): "
                  + "; ".join(f"`{name}` {seconds:.3f} s" for name, seconds in result.processes.items()) + "."]
    lines += [
        "",
        "| case | method | setting | time / position | positions / s | err r | err v | err a | compared / failed |",
        "|---|---|---|--:|--:|--:|--:|--:|--:|",
    ]
    for r in result.rows:
        lines.append(
            f"| {r.case} | {r.method} | {r.setting} | {_time(r.seconds)} | {_rate(r.rate)} | "
            f"{_error(r.err_r)} | {_error(r.err_v)} | {_error(r.err_a)} | {r.compared} / {r.failed} |"
        )
    return "\n".join(lines) + "\n"
