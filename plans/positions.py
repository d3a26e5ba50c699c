"""Many positions of one mechanism: the course project's 8 or 12 crank positions.

Orchestration only: the analytic solution comes from :mod:`plans.analytic`,
the plans from :mod:`plans.graphical`, the differences from
:mod:`plans.compare`.  No drawing happens here (matplotlib is imported only by
the display methods, on demand).

* :func:`parse_positions` turns ``--positions 12`` or ``--at "0,30,55,90 deg"``
  into driver positions.
* :func:`run_positions` solves every position both ways with **one set of
  scale factors** for all of them, so the plans of one run can be compared
  sheet against sheet.  Each scale factor that is not given is chosen by
  first constructing every position at its own automatic scale, then taking
  the round factor (1, 2, 2.5, 5 × 10ⁿ) that draws the largest of them at
  most ``drawn_max`` mm long.
* The graphical construction of each position follows the branch the
  analytic sweep follows (one continuous branch from the scene's own
  position): the scene's location hints are moved, position by position, to
  where the analytic solution puts the hinted points.  The two methods still
  share no kinematics: only the choice of branch.

Positions are numbered as the course does: 0, 1, 2, … in the sense the crank
turns (the sign of ω), starting at the scene's own position.

>>> import plans
>>> from plans.positions import parse_positions, run_positions
>>> scene = plans.load(plans.example_path("four-bar"))
>>> [round(math.degrees(p)) % 360 for p in parse_positions("0, 90 deg", scene)]
[0, 90]
>>> run = run_positions(scene, parse_positions(4, scene))
>>> len(run.runs), sorted(run.scales)
(4, ['k_a', 'k_l', 'k_v'])
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from ._text import subscript
from .errors import AssemblyError, PlansError, SceneError, SingularPositionError
from .scene import Crank, Scene
from .units import UnitError, parse_quantity

__all__ = [
    "parse_positions",
    "cycle_positions",
    "cycle_sweep",
    "cycle_poses",
    "fit_scale",
    "common_scales",
    "PositionRun",
    "PositionsRun",
    "run_positions",
    "page_precision",
    "at_page_precision",
    "PAGE_PRECISION",
    "unsolved_positions",
    "skipped_message",
    "position_text",
    "Diagrams",
    "CYCLE_STEPS",
]

#: Driver positions of the dense sweep behind trajectories and cycle diagrams.
CYCLE_STEPS = 360


# --- which positions ---------------------------------------------------------------


def _is_crank(scene: Scene) -> bool:
    return isinstance(scene.driver, Crank)


def _sense(scene: Scene) -> float:
    """+1 when the crank turns counter-clockwise (or stands still), −1 clockwise."""
    driver = scene.driver
    return -1.0 if isinstance(driver, Crank) and driver.omega < 0 else 1.0


def _stroke(scene: Scene) -> tuple[float, float]:
    driver = scene.driver
    if driver.stroke is None:
        raise SceneError(
            "positions over the cycle of a linear driver need its stroke: add stroke = [start, end] to [driver]",
            scene.source,
            "driver.stroke",
        )
    return driver.stroke


def parse_positions(spec, scene: Scene, *, law: str | None = None, start: str = "output") -> list[float]:
    """Driver positions from a count or from a list written as text.

    Parameters
    ----------
    spec : int, str or sequence
        * a count N (``12`` or ``"12"`` with no unit): N positions of the
          driver's cycle (:func:`cycle_positions`): a crank's full turn in
          the sense of ω, from the extreme position of the output link that
          starts its working stroke (``start="scene"``: from the scene's own
          angle); a rocker input's swing and back; a linear driver's
          ``stroke`` from start to end;
        * a list as text, ``"0,30,55,90 deg"`` or ``"0 deg, 0.5 rad"`` or
          ``"10,20,30 mm"``: a unit written after the last number applies to
          every number without one; bare numbers are degrees for a crank
          and metres for a linear driver (as ``--at``);
        * a sequence of numbers (SI: rad or m) or of such strings.
    scene : Scene
    law, start : see :func:`plans.motion.driver_cycle` (for a count).

    Returns
    -------
    list of float
        Crank angles [rad] or linear-driver positions [m], in order.

    Raises
    ------
    SceneError
        For text that is not a list of positions, a count below 1, or a
        linear driver without a stroke when a count is asked for.
    """
    kind = "angle" if _is_crank(scene) else "length"
    if isinstance(spec, bool):
        raise SceneError(f"positions: expected a count or a list, got {spec!r}", scene.source, "--positions")
    if isinstance(spec, (int, np.integer)):
        return cycle_positions(scene, int(spec), law=law, start=start)
    if isinstance(spec, str):
        text = spec.strip()
        if re.fullmatch(r"\d+", text):
            return cycle_positions(scene, int(text), law=law, start=start)
        items = [t.strip() for t in text.split(",")]
        if not text or any(not t for t in items):
            raise SceneError(f"positions: expected numbers separated by commas, such as \"0,30,55,90 deg\", got {spec!r}", scene.source, "--at")
        last = re.match(r"^\s*[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?\s*(.*)$", items[-1])
        unit = last.group(1).strip() if last else ""
        values = []
        for item in items:
            if unit and re.fullmatch(r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?", item):
                item = f"{item} {unit}"
            else:
                try:
                    item = float(item)
                except ValueError:
                    pass
            try:
                values.append(parse_quantity(item, kind))
            except UnitError as exc:
                raise SceneError(f"positions: {exc}", scene.source, "--at") from None
        return values
    try:
        values = [parse_quantity(v, kind) if isinstance(v, str) else float(v) for v in spec]
    except (TypeError, UnitError) as exc:
        raise SceneError(f"positions: expected numbers (rad or m) or quantities as text: {exc}", scene.source) from None
    if not values or not all(math.isfinite(v) for v in values):
        raise SceneError(f"positions: expected finite numbers, got {spec!r}", scene.source)
    return values


def cycle_positions(scene: Scene, count: int, *, closed: bool = False, law: str | None = None, start: str = "output") -> list[float]:
    """*count* positions of the driver's cycle under its law (:func:`plans.motion.driver_cycle`; see :func:`parse_positions`).

    With ``closed=True`` a crank's (or a swing's) list ends with position 0
    one cycle later (count + 1 entries), so a trajectory drawn through it closes.
    """
    from .motion import driver_cycle

    if count < 1:
        raise SceneError(f"positions: the count must be at least 1, got {count}", scene.source, "--positions")
    if not _is_crank(scene):
        _stroke(scene)
    return driver_cycle(scene, count, closed=closed, law=law, start=start).positions.tolist()


def cycle_sweep(scene: Scene, structure=None, steps: int = CYCLE_STEPS, *, law: str | None = None, start: str = "output"):
    """The analytic solution over the driver's cycle under its law (:func:`plans.motion.driver_cycle`): a crank's
    full turn, a rocker input's swing and back, or a linear driver's stroke, in *steps* positions (the scene's own
    position alone when a linear driver has no stroke)."""
    from .analytic import solve

    if not _is_crank(scene) and scene.driver.stroke is None:
        return solve(scene, np.asarray([scene.driver.s], dtype=float), structure, allow_partial=True)
    count = steps if _is_crank(scene) else steps + 1
    return _geometric_cycle(scene, structure, count, law, start, closed=False)[0].solve(structure)


def _geometric_cycle(scene: Scene, structure, count: int, law, start: str, *, closed: bool):
    """(Cycle, strokes) of the driver's law; for a drawing of the scene's own instant, whose slots, guides and frame
    need only where the mechanism goes, a driver that cannot follow a law over a cycle (at rest, or stopping under a
    uniform law) moves over its cycle at the scene's own rates instead, positions from the scene's own (strokes None)."""
    from .motion import driver_cycle, strokes

    try:
        return driver_cycle(scene, count, law=law, start=start, closed=closed, structure=structure), strokes(scene, law, structure)
    except SceneError:
        if _is_crank(scene):
            n = count + 1 if closed else count
            at = [scene.driver.phi + _sense(scene) * 2 * math.pi * k / count for k in range(n)]
        else:
            a, b = _stroke(scene)
            at = [a + (b - a) * k / (count - 1) for k in range(count)] if count > 1 else [a]
        return _held_cycle(scene, at), None


def _held_cycle(scene: Scene, at: list):
    """A Cycle at positions *at* with the scene's own rates held (geometry only: its t is NaN)."""
    from .motion import Cycle, DriverLaw

    d = scene.driver
    crank = _is_crank(scene)
    rate, acc = (d.omega, d.epsilon) if crank else (d.velocity, d.acceleration)
    x0 = d.phi if crank else d.s
    n = len(at)
    law = DriverLaw("constant", crank, x0, rate, acc, source="scene")
    return Cycle(scene, law, np.asarray(at, dtype=float), np.full(n, np.nan), np.full(n, float(rate)), np.full(n, float(acc)))


#: Positions of a cycle the scheme's frame is chosen over (every 5° of a crank's turn).
CYCLE_POSES = 72


def cycle_poses(sweep, samples: int = CYCLE_POSES) -> tuple:
    """The mechanism over a solved sweep, for drawing: one ``(positions, poses)`` pair per assembled position
    (at most *samples*, evenly spread), as a GraphicalSolution's own ``positions`` [m] and ``poses``
    (φ [rad], origin [m]).  Read from the sweep; nothing is solved here.  The scheme uses it to draw its frame
    (the hatched side of each guide, the direction of each support) the same way at every position."""
    valid = np.asarray(sweep.valid, dtype=bool).reshape(-1)
    if not valid.any():
        return ()
    index = np.flatnonzero(valid)
    if len(index) > samples:
        index = index[np.linspace(0, len(index) - 1, samples).round().astype(int)]
    shape = valid.shape

    def at(values, k):
        return np.broadcast_to(np.asarray(values), shape)[k]

    out = []
    for k in index:
        positions = {name: complex(at(point.r, k)) for name, point in sweep.points.items()}
        poses = {body: (float(at(phi, k)), complex(at(origin, k))) for body, (phi, origin) in sweep.poses.items()}
        if all(np.isfinite(z.real) and np.isfinite(z.imag) for z in positions.values()):
            out.append((positions, poses))
    return tuple(out)


def position_text(scene: Scene, position: float, digits: int = 1) -> str:
    """``"φ₂ = 145.0°"`` (angle in [0, 360)) or ``"s₂ = −120.0 mm"`` (a true minus sign)."""
    driver = scene.driver
    sub = subscript(driver.link)
    if isinstance(driver, Crank):
        degrees = math.degrees(position) % 360.0
        if round(degrees, digits) >= 360.0:
            degrees = 0.0
        return f"φ{sub} = {degrees:.{digits}f}°"
    return f"s{sub} = {position * 1e3:.{digits}f} mm".replace("-", "\u2212")  # a true minus sign


# --- scales ---------------------------------------------------------------------------


def fit_scale(largest: float, drawn_max: float = 120.0, fallback: float = 1.0) -> float:
    """The smallest round scale factor (1, 2, 2.5, 5 × 10ⁿ) drawing *largest* at most *drawn_max* mm long."""
    from .graphical.scales import DRAWN_MAX, round_scale

    if not (math.isfinite(largest) and largest > 0):
        return fallback
    return round_scale(largest * DRAWN_MAX / drawn_max, fallback=fallback)


def _largest(plan) -> float:
    """The largest physical vector of a plan [m/s or m/s²]."""
    return max((abs(v.tip - v.tail) * plan.scale for v in plan.vectors), default=0.0)


def _extent(graphical) -> float:
    """The larger side of the bounding box of the mechanism's points [m]."""
    zs = list(graphical.positions.values())
    if not zs:
        return 0.0
    xs = [z.real for z in zs]
    ys = [z.imag for z in zs]
    return max(max(xs) - min(xs), max(ys) - min(ys))


def common_scales(graphicals, *, drawn_max: dict[str, float] | float = 120.0, given: dict[str, float | None] | None = None) -> dict[str, float]:
    """One round scale factor of each kind that fits every construction.

    Parameters
    ----------
    graphicals : iterable of GraphicalSolution
        Constructions at their own (automatic) scales.
    drawn_max : float or dict
        The longest drawn length allowed [mm], for all kinds or per kind
        (``{"k_l": 90, "k_v": 70, "k_a": 70}``).
    given : dict, optional
        Factors fixed by the user; they are kept as they are.

    Returns
    -------
    dict
        ``{"k_l", "k_v"}`` and ``"k_a"`` when the constructions have
        acceleration plans.
    """
    graphicals = list(graphicals)
    given = {k: v for k, v in (given or {}).items() if v is not None}
    limit = drawn_max if isinstance(drawn_max, dict) else {"k_l": drawn_max, "k_v": drawn_max, "k_a": drawn_max}
    largest = {"k_l": 0.0, "k_v": 0.0, "k_a": 0.0}
    fallback = {}
    has_a = False
    for g in graphicals:
        largest["k_l"] = max(largest["k_l"], _extent(g))
        largest["k_v"] = max(largest["k_v"], _largest(g.velocity_plan))
        fallback.setdefault("k_l", g.scales["k_l"])
        fallback.setdefault("k_v", g.scales["k_v"])
        if g.acceleration_plan is not None:
            has_a = True
            largest["k_a"] = max(largest["k_a"], _largest(g.acceleration_plan))
            fallback.setdefault("k_a", g.scales["k_a"])
    out = {}
    for key in ("k_l", "k_v", "k_a"):
        if key == "k_a" and not has_a:
            continue
        out[key] = given[key] if key in given else fit_scale(largest[key], limit.get(key, 120.0), fallback.get(key, 1.0))
    return out


# --- runs -------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class PositionRun:
    """One numbered position: both solutions and their differences, or why there are none.

    Attributes
    ----------
    index : int
        The course's number of the position: 0, 1, 2, …
    position : float
        Crank angle [rad] or linear-driver position [m].
    scene : Scene
        The scene at this position (driver moved; branch hints following the
        analytic sweep).
    analytic : AnalyticSolution or None
        At this one position (N = 1).
    graphical : GraphicalSolution or None
    comparisons : list of Comparison or None
    error : PlansError or None
        Why the position could not be solved (no assembly, dead centre).
    """

    index: int
    position: float
    scene: Scene
    analytic: object | None = None
    graphical: object | None = None
    comparisons: list | None = None
    error: PlansError | None = None

    @property
    def ok(self) -> bool:
        return self.error is None and self.graphical is not None

    @property
    def label(self) -> str:
        """``"φ₂ = 145.0°"``."""
        return position_text(self.scene, self.position)

    @property
    def reason(self) -> str:
        """Why the position is not solved: the solver's message (empty for a solved position)."""
        return "" if self.ok else str(self.error) if self.error is not None else "no graphical construction"

    def brief(self, lang: str = "en") -> str:
        """The reason in a few words of *lang*, for a listing: ``"RRR(3,4): cannot assemble"`` (empty when solved)."""
        if self.ok:
            return ""
        from .i18n import term

        group = re.match(r"^\s*([A-Z]{3}\([^)]*\))", self.reason)
        return (f"{group.group(1)}: " if group else "") + term(self.cause, lang)

    @property
    def cause(self) -> str:
        """``""`` for a solved position, else ``"dead_centre"`` or ``"no_assembly"`` (keys of :mod:`plans.i18n`)."""
        if self.ok:
            return ""
        return "dead_centre" if isinstance(self.error, SingularPositionError) else "no_assembly"

    # --- notebooks -----------------------------------------------------------

    def sheet(self, *, lang: str = "en"):
        """The position's sheet at the run's factors, titled with the position (:func:`plans.pages.sheet.sheet_at`)."""
        from .pages.sheet import position_heading, sheet_at

        return sheet_at(self.graphical, self.analytic, lang=lang, heading=position_heading(self, lang))

    def _repr_svg_(self) -> str:
        if not self.ok:
            return None
        return self.sheet().pages("svg")[0].decode("utf-8")

    def plot(self, ax=None):
        """Draw the mechanism at this position into *ax* (a new figure when None); returns the Axes."""
        if not self.ok:
            raise self.error
        from .drawing import draw_mechanism

        artists = draw_mechanism(self.graphical, ax)
        return ax if ax is not None else artists[0].axes

    def save(self, path, *, lang: str = "en") -> Path:
        """Write the position's sheet to *path* (``.svg``, ``.pdf`` or ``.png``, by its suffix), atomically."""
        if not self.ok:
            raise self.error
        return self.sheet(lang=lang).save(path)


@dataclass(frozen=True, eq=False)
class PositionsRun:
    """A multi-position run: one scale factor set, one analytic sweep over the cycle.

    Attributes
    ----------
    scene : Scene
    structure : Structure
    runs : tuple of PositionRun
        In the order asked for, numbered 0, 1, 2, …
    scales : dict
        ``{"k_l", "k_v", "k_a"}`` shared by every position.
    precision : float or None
    cycle : AnalyticSolution
        The dense sweep over the driver's cycle (``allow_partial``: ``valid``
        says where the mechanism assembles), for trajectories and diagrams;
        a crank's sweep ends with the starting angle plus a full turn.
    motion : plans.motion.Cycle or None
        The positions of the runs under the driver's law (their times,
        driver rates and branches); None for the scene's own position alone.
    dense : plans.motion.Cycle or None
        The law over the dense sweep (*cycle*).
    strokes : plans.motion.Strokes or None
        The output link's extreme positions, H (or ψ), θ and K.
    """

    scene: Scene
    structure: object
    runs: tuple
    scales: dict
    precision: float | None
    cycle: object
    motion: object = None
    dense: object = None
    strokes: object = None

    @property
    def law(self):
        """The driver's law over the cycle (:class:`plans.motion.DriverLaw`), or None for the scene's own position alone."""
        return self.motion.law if self.motion is not None else None

    def __len__(self) -> int:
        return len(self.runs)

    def other_extreme(self) -> dict:
        """``{"0′": GraphicalSolution}``: the mechanism at the output's other extreme position (the plan of positions
        draws it: its list names it), when the positions start at the output's extreme (a crank's,
        :class:`plans.motion.Strokes`); else empty."""
        st, motion = self.strokes, self.motion
        if st is None or motion is None or motion.start != "output" or not st.law.crank:
            return {}
        try:
            other = run_positions(self.scene, [float(st.other_position)], precision=None, start="scene")
        except PlansError:
            return {}
        solved = [r for r in other.runs if r.ok]
        return {"0′": solved[0].graphical} if solved else {}

    @property
    def positions(self) -> list[float]:
        return [r.position for r in self.runs]

    @property
    def skipped(self) -> list[PositionRun]:
        """The positions that are not solved (no sheet, not drawn), each with its ``reason``."""
        return [r for r in self.runs if not r.ok]

    def skipped_messages(self) -> list[str]:
        """One line per position that is not solved: its number, where it is, and why."""
        return [skipped_message(r.index, r.scene, r.position, r.reason) for r in self.skipped]

    def _repr_svg_(self) -> str:
        from .drawing.positions_plan import draw_positions_plan
        from .drawing.svg import render_svg

        return render_svg(draw_positions_plan(self)[0].figure).decode("utf-8")

    def diagrams(self, *, lang: str = "en", components: bool = False) -> "Diagrams":
        """The kinematic diagrams over the cycle, the positions of the run marked."""
        return Diagrams(self.cycle, marked=self.motion if self.motion is not None else self.positions, lang=lang,
                        components=components, cycle=self.dense, extremes=self.strokes)

    def animate(self, *, lang: str = "en"):
        """The run's positions as a :class:`plans.lecture.Animation` (a lecture page, a GIF, an MP4), at the run's scale factors."""
        from .display import display_function

        return display_function("animate_run")(self, lang=lang)

    def plot(self, ax=None, *, lang: str = "en"):
        """Draw the plan of positions into *ax* (a new figure when None); returns the Axes."""
        from .drawing.positions_plan import draw_positions_plan

        artists = draw_positions_plan(self, ax, lang=lang)
        return ax if ax is not None else artists[0].axes

    def save(self, path, *, lang: str = "en") -> Path:
        """Write the plan of positions to *path* (``.svg``, ``.pdf`` or ``.png``, by its suffix)."""
        from .drawing.positions_plan import draw_positions_plan
        from .drawing.formats import save_figure

        return save_figure(draw_positions_plan(self, lang=lang)[0].figure, path)


class Diagrams:
    """Cycle diagrams of an analytic sweep, for notebooks and scripts.

    Displays itself inline (every page of :func:`plans.drawing.diagrams.draw_cycle_diagrams`);
    ``plot(quantity, ax)`` draws one diagram into an Axes; ``save(path)``
    writes them to one file (or a file a page) in the format of the path's suffix.

    >>> import numpy as np, plans
    >>> scene = plans.load(plans.example_path("four-bar"))
    >>> d = Diagrams(plans.solve(scene, np.linspace(0, 2 * np.pi, 73)))
    >>> d.plot("omega")                                   # doctest: +SKIP
    """

    def __init__(self, analytic, *, marked=None, lang: str = "en", components: bool = False, cycle=None, extremes=None):
        self.analytic = analytic
        self.marked = marked
        self.lang = lang
        self.components = components
        self.cycle = cycle  # the law the sweep was solved under (plans.motion.Cycle), stated on the diagrams
        self.extremes = extremes  # the output's extreme positions (plans.motion.Strokes): 0′ marked

    def figures(self) -> list:
        """(name, Figure) pairs: ``links``, ``points`` and, with prismatic pairs, ``sliders``."""
        from .drawing.diagrams import draw_cycle_diagrams

        return draw_cycle_diagrams(self.analytic, marked=self.marked, lang=self.lang, components=self.components, cycle=self.cycle,
                                   extremes=self.extremes)

    def plot(self, quantity: str = "omega", ax=None):
        """One diagram (``"omega"``, ``"v"``, ``"coriolis"`` …) into *ax* (a new figure when None); returns the Axes."""
        from .drawing.diagrams import plot_cycle

        curves = plot_cycle(self.analytic, quantity, ax, marked=self.marked, lang=self.lang, cycle=self.cycle)
        return ax if ax is not None else curves[0].axes

    def save(self, path) -> list[Path]:
        """Write the diagrams to *path* in the format its suffix names (see :func:`plans.drawing.formats.save_pages`):
        ``diagrams.pdf`` a page each, ``diagrams.svg`` / ``.png`` as ``diagrams-links.svg``, ``diagrams-points.svg`` …"""
        from .drawing.formats import save_pages

        return save_pages(self.figures(), path)

    def _repr_html_(self) -> str:
        from .drawing.svg import render_svg

        return "".join(render_svg(fig).decode("utf-8").split("?>", 1)[-1] for _, fig in self.figures())

    def _repr_svg_(self) -> str:
        from .drawing.svg import render_svg

        return render_svg(self.figures()[0][1]).decode("utf-8")


def skipped_message(index: int, scene: Scene, position: float, reason: str) -> str:
    """``"position 1 (φ₂ = 60.0°) is skipped: RRR(3,4): joint B cannot assemble …"``."""
    return f"position {index} ({position_text(scene, position)}) is skipped: {reason}"


def _position_error(scene: Scene, structure, index: int, value: float) -> PlansError:
    """Why the analytic solver refuses one position: its own message."""
    from .analytic import solve

    try:
        solve(scene, [value], structure)
    except (AssemblyError, SingularPositionError) as exc:
        return exc
    return AssemblyError(f"position {index}: the mechanism cannot be solved at {position_text(scene, value)}")


def unsolved_positions(scene: Scene, positions) -> list[tuple[int, float, PlansError]]:
    """(number, position, error) of each position the mechanism cannot be solved at, by the analytic solver alone.

    The same errors :func:`run_positions` keeps in its runs, found without
    the graphical construction (for a message before a long job).
    """
    from .analytic import solve
    from .structure import find_structure

    structure = find_structure(scene)
    values = parse_positions(positions, scene) if positions is not None else [scene.driver.phi if _is_crank(scene) else scene.driver.s]
    sweep = solve(scene, np.asarray(values, dtype=float), structure, allow_partial=True)
    return [(k, v, _position_error(scene, structure, k, v)) for k, v in enumerate(values) if not bool(sweep.valid[k])]


def _hints_at(scene: Scene, analytic, k: int, every: bool = False) -> dict:
    """The scene's assembly hints moved to where the analytic sweep puts the hinted points.

    With *every*, branch signs too become the places the sweep puts their
    points (a swing's way back runs on the other branch of a group).
    """
    hints = {}
    for name, hint in scene.assembly.items():
        if isinstance(hint, complex) or isinstance(hint, float) or every:
            z = complex(analytic.points[name].r[k])
            hints[name] = z if math.isfinite(z.real) and math.isfinite(z.imag) else hint
        else:
            hints[name] = hint
    return hints


#: Drafting precision [mm] of the readings on sheets and handouts (``plans draw``, ``plans handout``):
#: a length as a student measures and prints it, so the graphical value and its error are those of the method.
PAGE_PRECISION = 0.1


def page_precision(given: float | None, scene) -> float | None:
    """The drafting precision [mm] of a sheet or handout: *given*, else the scene's ``[scales] precision``,
    else :data:`PAGE_PRECISION`; a given 0 means exact readings (None, no rounding)."""
    if given is not None:
        return None if given == 0 else given
    if scene.scales.precision is not None:
        return scene.scales.precision
    return PAGE_PRECISION


def at_page_precision(scene, given: float | None = None):
    """*scene* with its ``[scales] precision`` set to :func:`page_precision` (None: exact), for a sheet or handout."""
    return replace(scene, scales=replace(scene.scales, precision=page_precision(given, scene)))


def run_positions(
    scene: Scene,
    positions=None,
    *,
    k_l: float | None = None,
    k_v: float | None = None,
    k_a: float | None = None,
    precision: float | None = None,
    drawn_max: dict[str, float] | float = 120.0,
    cycle_steps: int = CYCLE_STEPS,
    check_scales: bool = True,
    law: str | None = None,
    start: str = "output",
) -> PositionsRun:
    """Solve the mechanism at every position, analytically and graphically, at one set of scales.

    Parameters
    ----------
    scene : Scene
    positions : None, int, str or sequence
        Anything :func:`parse_positions` takes; None is the scene's own
        position only.
    k_l, k_v, k_a : float, optional
        Scale factors; each one not given (here or in the scene's
        ``[scales]``) is the round factor that fits the largest of all the
        positions (see :func:`common_scales`).
    precision : float, optional
        Drafting precision [mm] (see :func:`plans.graphical.construct`).
    drawn_max : float or dict
        Longest drawn length [mm] the automatic factors allow.
    cycle_steps : int
        Positions of the dense analytic sweep over the cycle.
    check_scales : bool
        Refuse given factors that draw a figure larger than a sheet or
        smaller than 1 mm at some position (see :func:`plans.graphical.construct`).
    law : str, optional
        The driver's law over the cycle (:func:`plans.motion.driver_law`);
        None: the scene's ``[driver] law`` or the default.  Every position
        (but the scene's own alone) is solved with the driver's ω and ε (or
        v and a) under that law there.
    start : {"output", "scene"}
        Where a count of positions starts (:func:`plans.motion.driver_cycle`).

    Returns
    -------
    PositionsRun
        A position that cannot be assembled, or sits at a dead centre, is
        kept with its ``error`` and no solutions.

    Raises
    ------
    StructureError, SceneError
        For a scene that cannot be solved at all.
    """
    from .analytic import solve
    from .compare import compare
    from .graphical import construct
    from .structure import find_structure
    from .sweep import line_travel

    from .motion import cycle_at, driver_cycle, strokes

    structure = find_structure(scene)
    motion = dense = found = None
    if positions is None:
        values = [scene.driver.phi if _is_crank(scene) else scene.driver.s]
    elif isinstance(positions, (int, np.integer)) and not isinstance(positions, bool) or (
        isinstance(positions, str) and re.fullmatch(r"\s*\d+\s*", positions)
    ):
        count = int(positions)
        if count < 1:
            raise SceneError(f"positions: the count must be at least 1, got {count}", scene.source, "--positions")
        if not _is_crank(scene):
            _stroke(scene)
        motion = driver_cycle(scene, count, law=law, start=start, structure=structure)
        values = motion.positions.tolist()
    else:
        values = parse_positions(positions, scene)
        if values:
            motion = cycle_at(scene, values, law=law, structure=structure)
    if not values:
        raise SceneError("positions: no positions asked for", scene.source)

    if motion is None:
        sweep = solve(scene, np.asarray(values, dtype=float), structure, allow_partial=True)
    else:
        sweep = motion.solve(structure)
    if _is_crank(scene) or scene.driver.stroke is not None:
        count = cycle_steps if _is_crank(scene) else cycle_steps + 1
        if motion is not None:  # a cycle of positions: the law must cover it (its errors name the key)
            dense = driver_cycle(scene, count, law=law, start=start, closed=_is_crank(scene), structure=structure)
            found = strokes(scene, law, structure)
        else:  # the scene's own instant: the cycle only for where the mechanism goes (slots, guides, the frame)
            dense, found = _geometric_cycle(scene, structure, count, law, start, closed=_is_crank(scene))
        cycle = dense.solve(structure)
    else:
        cycle = solve(scene, np.asarray(values, dtype=float), structure, allow_partial=True)

    k_l = k_l if k_l is not None else scene.scales.k_l
    k_v = k_v if k_v is not None else scene.scales.k_v
    k_a = k_a if k_a is not None else scene.scales.k_a
    precision = precision if precision is not None else scene.scales.precision

    prepared = []
    for index, value in enumerate(values):
        moved = scene.at(value) if motion is None else motion.scene_at(index)  # the driver's rates under the law
        here = replace(moved, assembly=_hints_at(scene, sweep, index, every=bool(motion is not None and motion.branches)))
        if not bool(sweep.valid[index]):  # the solver's own message for this position
            prepared.append((index, value, here, None, _position_error(scene, structure, index, value)))
            continue
        try:
            first = construct(here, structure, k_l=k_l, k_v=k_v, k_a=k_a, precision=precision, check_scales=check_scales)
        except (AssemblyError, SingularPositionError) as exc:
            prepared.append((index, value, here, None, exc))
            continue
        prepared.append((index, value, here, first, None))

    scales = common_scales(
        [g for *_, g, e in prepared if g is not None],
        drawn_max=drawn_max,
        given={"k_l": k_l, "k_v": k_v, "k_a": k_a},
    )
    travel = line_travel(cycle)
    poses = cycle_poses(cycle)  # the frame drawn the same way at every position
    runs = []
    for index, value, here, first, error in prepared:
        if error is not None:
            runs.append(PositionRun(index, value, here, error=error))
            continue
        graphical = construct(
            here, structure, k_l=scales["k_l"], k_v=scales["k_v"], k_a=scales.get("k_a"), precision=precision,
            check_scales=False,  # given factors were checked above; common ones are plans' own choice
        )
        graphical = replace(graphical, travel=travel, cycle_poses=poses)  # slots and guides over the cycle's travel
        analytic = sweep.at(index)
        runs.append(PositionRun(index, value, here, analytic, graphical, compare(analytic, graphical)))
    return PositionsRun(scene, structure, tuple(runs), scales, precision, cycle, motion, dense, found)
