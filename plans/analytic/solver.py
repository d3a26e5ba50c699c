"""The analytic solver: driver, then the dyads in order, then every point and slider.

One call solves N driver positions with numpy arrays, group after group;
there is no Python loop over the positions.

What does not depend on the positions is found once per scene and kept
(:class:`_Plan`): the branch sign of each group, which a location hint
chooses by solving the group twice at the scene's own position, and the
bodies, points and sliders of the result.  A long sweep is solved in pieces
of :data:`CHUNK` positions, so that the temporaries of each numpy step stay
in the processor's cache.  Quantities that are the same at every position
(the frame's, a driver's ω and ε, a block's angle on a fixed guide) are
carried as plain numbers and made arrays only in the result.  The result's
dicts of motions and their arrays are made when first read (see
:mod:`plans.analytic.solution`); the warnings are looked for only if some
group's condition exceeds the limit.
"""

from __future__ import annotations

import cmath
import math
import operator
from dataclasses import dataclass

import numpy as np

from ..errors import AssemblyError, SingularPositionError, StructureError
from ..limits import REFUSE_SINE, WARN_CONDITION, NearDeadCentre, position_text
from ..scene import FRAME, Crank, Line, Scene
from ..structure import Group, Joint, Structure, find_structure
from . import single
from .dyads import DyadSolution, solve_prp, solve_rpp, solve_rpr, solve_rrp, solve_rrr
from .kinematics import BodyState, PointState, sum_terms, coriolis_acceleration, dot, is_number
from .solution import AnalyticSolution, LinkMotion, PointMotion, SliderMotion, frozen

__all__ = ["solve", "prepare", "PreparedSolver", "driver_position", "CHUNK", "FEW"]

#: A sweep of more driver positions than this is solved in pieces of this
#: many.  At 100 000 positions each numpy step would stream its operands
#: (1.6 MB per complex array) through main memory; pieces keep them in the
#: processor's cache.  Measured on the offset slider-crank at N = 100 000:
#: 2048 → 6.6 M positions/s, 4096 → 8.5 M/s, 8192 → 9.8 M/s, 16384 →
#: 9.1–10.3 M/s (the fixed cost per piece against the cache).  The results
#: are the same: every step is elementwise.
CHUNK = 8192

#: Up to this many driver positions are solved one at a time in plain
#: complex arithmetic (:mod:`plans.analytic.single`).  Measured (CPU time,
#: loaded 2-CPU machine): one position of the slider-crank 66 µs that way
#: against 148 µs vectorised, of the six-bar 94 against 271 µs; the two
#: cost the same at about 5 (slider-crank) to 8 (six-bar) positions.
FEW = 4


def driver_position(scene: Scene) -> float:
    """The scene's own driver position: crank angle φ [rad] or linear-driver position s [m]."""
    driver = scene.driver
    return driver.phi if isinstance(driver, Crank) else driver.s


def solve(
    scene: Scene,
    positions=None,
    structure: Structure | None = None,
    *,
    allow_partial: bool = False,
    warn_condition: float = WARN_CONDITION,
    rates=None,
    branches: dict | None = None,
) -> AnalyticSolution:
    """Positions, velocities and accelerations of every link, point and slider.

    The complex-number (loop-closure) method: the driver's motion is given,
    then each Assur group is solved in closed form for its position and by a
    2×2 real linear system for its velocities and accelerations (see
    :mod:`plans.analytic.dyads`), in the order :func:`plans.structure.find_structure`
    gives.  Every array of the result has one entry per driver position.

    Parameters
    ----------
    scene : Scene
    positions : None, float or array_like of shape (N,)
        Driver positions: the crank angle φ [rad] of a :class:`~plans.scene.Crank`
        (the angle of its own x axis) or the position s [m] of a
        :class:`~plans.scene.LinearDriver` along its guide.  None solves the
        scene's own position (N = 1).  The driver's ω and ε (or velocity and
        acceleration) are held at the scene's values at every position: a sweep
        is a set of instants with the same driver rates, not one motion in time.
    structure : Structure, optional
        The scene's structure, if already found.
    allow_partial : bool
        If True, positions where a group cannot be assembled or sits at a dead
        centre do not raise: ``valid`` is False there and what depends on that
        group is NaN.
    warn_condition : float
        A group whose condition number exceeds this at a solved position is
        near a dead centre: the solution carries a
        :class:`~plans.limits.NearDeadCentre` warning (one per group and run
        of consecutive positions, at the worst of them).  Default
        :data:`plans.limits.WARN_CONDITION`; ``math.inf`` never warns.

    rates : None or pair (rate, acceleration), each a number or array_like (N,)
        The driver's rates at each position, a motion's law along the
        positions: a crank's ω [rad/s] and ε [rad/s²], counter-clockwise
        positive; a linear driver's velocity [m/s] and acceleration [m/s²]
        along its guide.  None: the scene's own at every position.
    branches : None or dict[str, number or array_like (N,)]
        For a group (by name, ``"RRR(3,4)"``), +1 keeps at each position the
        branch the scene's hints choose, −1 takes the other one there (a
        rocker input passing its limit position goes over to the other
        branch of the group that limits it).  Groups not named keep theirs.

    Returns
    -------
    AnalyticSolution

    Raises
    ------
    AssemblyError
        A group cannot be assembled at some position (naming the group, the
        joint, the position and the lengths with the gap).
    SingularPositionError
        A group sits at a dead centre at some position: |sin| of the angle
        between its construction lines is below
        :data:`plans.limits.REFUSE_SINE` (its 2×2 velocity system is
        singular to working precision).
    StructureError
        The scene is not a driver followed by dyads.
    ValueError
        Positions that are not finite numbers, or not a 1-D array.

    Notes
    -----
    **Assembly branches.**  A hint in ``scene.assembly`` names a point; it
    applies to the group whose links carry that point (a point the group's
    links share with a known body does not choose a branch).  A location hint
    [m] is resolved at the scene's own driver position: both branches are
    computed there and the one that puts the point nearer the location is
    kept.  A sign ±1 is taken as it is; no hint means +1.  The sign so found
    is kept at every position of the sweep (one branch, continuous away from
    dead centres).  What +1 means for each kind:

    * RRR: the inner joint C lies to the left of the directed line from the
      outer joint B of link i to the outer joint D of link j,
      ``Im(conj(D − B)·(C − B)) > 0``;
    * RRP: of the two intersections, the one further along u (larger
      projection on u), u the direction of the known body's line in the outer
      prismatic pair;
    * RPR: the common line direction u points from the outer joint of i
      towards that of j, ``u·(P_j − P_i) > 0``;
    * PRP, RPP: one solution.

    Examples
    --------
    >>> import numpy as np
    >>> from plans.scene import load, example_path
    >>> scene = load(example_path("slider-crank"))
    >>> solution = solve(scene)
    >>> round(float(solution.points["B"].v[0].real), 4)
    -16.0407
    >>> turn = solve(scene, np.linspace(0, 2 * np.pi, 3600))
    >>> turn.points["B"].r.shape
    (3600,)
    """
    return prepare(scene, structure)(positions, allow_partial=allow_partial, warn_condition=warn_condition, rates=rates, branches=branches)


class PreparedSolver:
    """A scene made ready to solve, the way FFT libraries plan a transform: call it with driver positions.

    Made by :func:`prepare`.  What does not depend on the positions is found
    once: the structure, each group's assembly branch (resolved at the
    scene's own position), the order in which bodies, points and sliders are
    solved and the layout of the result.  Each call then solves only the
    positions asked for, as :func:`solve` does (same arguments, same result,
    same errors).

    One position, or a few (up to :data:`FEW`), is solved in plain complex
    arithmetic (:mod:`plans.analytic.single`), which spares numpy's fixed
    cost per operation; a position that is not an ordinary one (a group that
    does not assemble, a dead centre) is solved by the vectorised path,
    which reports it.  More positions are solved vectorised, in pieces of
    :data:`CHUNK`.

    Examples
    --------
    >>> import numpy as np
    >>> from plans.scene import load, example_path
    >>> solver = prepare(load(example_path("slider-crank")))
    >>> round(float(solver(np.radians(45)).points["B"].v[0].real), 4)
    -16.0407
    >>> solver(np.linspace(0, 2 * np.pi, 360)).points["B"].r.shape
    (360,)
    """

    def __init__(self, plan: "_Plan"):
        self._plan = plan
        self.scene = plan.scene
        self.structure = plan.structure

    def __call__(
        self, positions=None, *, allow_partial: bool = False, warn_condition: float = WARN_CONDITION, rates=None, branches: dict | None = None
    ) -> AnalyticSolution:
        """The solution at *positions* (see :func:`solve` for the arguments)."""
        if not (warn_condition >= 1):
            raise ValueError(f"warn_condition must be a number of at least 1 (a condition number), got {warn_condition!r}")
        plan = self._plan
        driver = _positions(positions, plan.base)
        n = len(driver)
        if rates is not None or branches:
            law = _Law(plan, n, rates, branches)
            return _solve_vectorised(plan, driver, positions is None, allow_partial, warn_condition, law)
        if n <= FEW and plan.resolved and not plan.missing:
            few = _solve_few(plan, driver, warn_condition) if n else None
            if few is not None:
                columns, calm = few
                return _solution(plan, driver, columns, warn_condition, calm)
        return _solve_vectorised(plan, driver, positions is None, allow_partial, warn_condition)


def prepare(scene: Scene, structure: Structure | None = None) -> PreparedSolver:
    """The scene made ready to solve at any driver positions (see :class:`PreparedSolver`).

    >>> from plans.scene import load, example_path
    >>> solver = prepare(load(example_path("six-bar")))
    >>> len(solver([0.1, 0.2, 0.3]))
    3
    """
    return PreparedSolver(_prepared(scene, structure))


def _solve_vectorised(
    plan: "_Plan", driver: np.ndarray, asked_here: bool, allow_partial: bool, warn_condition: float, law: "_Law | None" = None
) -> AnalyticSolution:
    """Every position with numpy arrays, in pieces of :data:`CHUNK` (*law*: the driver's rates and branches per position)."""
    scene = plan.scene
    n = len(driver)
    with np.errstate(all="ignore"):
        if n <= CHUNK or not plan.resolved or plan.missing:
            piece = _solve_piece(plan, driver, allow_partial, asked_here, law)
            if plan.missing:
                raise StructureError(f"{scene.source}: the structure does not solve the links {', '.join(plan.missing)}")
            columns = _Columns(plan.dtypes, n)
            columns.put(0, _columns(plan, piece))
            calm = _calm(piece, warn_condition)
        else:
            columns = _Columns(plan.dtypes, n)
            calm = True
            for start in range(0, n, CHUNK):
                part = law.part(start, start + CHUNK) if law is not None else None
                piece = _solve_piece(plan, driver[start : start + CHUNK], True, asked_here, part)
                if not allow_partial and not piece.valid.all():
                    # the error names the first failing position of the first group that fails: one piece finds it
                    _solve_piece(plan, driver, False, asked_here, law)
                columns.put(start, _columns(plan, piece))
                calm = calm and _calm(piece, warn_condition)

    def make() -> list[np.ndarray]:
        arrays = columns.arrays()
        return [frozen(arrays[k]) for k in plan.order]  # ordered by kind of number (see _part)

    return _solution(plan, driver, _Once(make), warn_condition, calm)


def _calm(piece: "_Piece", warn_condition: float) -> bool:
    """No group's condition exceeds *warn_condition* anywhere in the piece (NaN, not assembled, does not): nothing to warn of."""
    return not any((condition > warn_condition).any() for condition in piece.conditions.values())


def _solve_few(plan: "_Plan", driver: np.ndarray, warn_condition: float) -> "tuple[_Once, bool] | None":
    """The columns of the result (:func:`_columns`) at a few positions, one at a time in plain complex arithmetic.

    With them, whether every group's condition is at most *warn_condition*
    everywhere (then there is nothing to warn of).  None if some position is not an ordinary one (:class:`single.NotHere`):
    the caller then solves them all vectorised, which reports it.  The
    columns are rows of one read-only block per kind of number, made when
    the first of them is asked for.
    """
    rows = []
    calm = True
    try:
        for x in driver.tolist():
            piece = _solve_one(plan, x)
            for condition in piece.conditions.values():
                calm = calm and condition <= warn_condition
            rows.append(_columns(plan, piece))
    except (single.NotHere, ArithmeticError, ValueError):
        return None

    def make() -> list[np.ndarray]:
        out: list[np.ndarray] = []
        for dtype, _, pick in plan.kinds:
            block = np.array([pick(values) for values in rows], dtype).T  # (columns, positions)
            block.setflags(write=False)  # its rows, views of it, are read-only too
            out.extend(block)
        return out  # ordered by kind of number (plan.order)

    return _Once(make), calm


class _Once:
    """The columns of the result, made by ``make()`` when first asked for (``columns()``), then kept."""

    __slots__ = ("make", "made")

    def __init__(self, make):
        self.make = make
        self.made: list[np.ndarray] | None = None

    def __call__(self) -> list[np.ndarray]:
        if self.made is None:
            self.made = self.make()
        return self.made


def _solve_one(plan: "_Plan", x: float) -> "_Piece":
    """The driver, then each group in order, at one ordinary position *x* (see :mod:`plans.analytic.single`)."""
    scene = plan.scene
    states = {FRAME: single.resting(), plan.structure.driver: plan.driver_at(x)}
    points: dict = {}
    conditions, sines = {}, {}
    for group, name, sign in zip(plan.structure.groups, plan.names, plan.signs):
        i, j, sine, condition, inner = _solve_group(scene, group, states, sign, points, single.SOLVERS)
        states[group.links[0]] = i
        states[group.links[1]] = j
        if inner is not None:
            for link in group.links:
                points[(link, scene.bodies[link].points[group.inner.point])] = inner
        conditions[name] = condition
        sines[name] = sine
    return _Piece(states, points, conditions, sines, True)


def _warnings(scene, structure, driver, conditions, sines, valid, warn_condition) -> tuple[NearDeadCentre, ...]:
    """One warning per group and run of consecutive solved positions above *warn_condition*, at the worst."""
    out = []
    crank = isinstance(scene.driver, Crank)
    for group in structure.groups:
        condition = conditions[group.name]
        near = valid & (condition > warn_condition)
        if not near.any():
            continue
        # the runs [start, end) of consecutive near positions: where `near` changes
        edges = np.flatnonzero(np.diff(near, prepend=False, append=False))
        for start, end in zip(edges[::2].tolist(), edges[1::2].tolist()):
            worst = start + int(np.argmax(condition[start:end]))
            out.append(
                NearDeadCentre(
                    group.name,
                    group.joint,
                    float(driver[worst]),
                    position_text(crank, float(driver[worst])),
                    float(condition[worst]),
                    float(sines[group.name][worst]),
                    "analytic",
                )
            )
    return tuple(out)


# --- what is found once per scene ----------------------------------------------


class _Plan:
    """What :func:`solve` needs of a scene and structure besides the positions.

    Attributes
    ----------
    base : float
        The scene's own driver position.
    signs : tuple
        The branch sign of each group, resolved at the scene's own position
        by :func:`_branch_sign` (a location hint solves the group twice
        there: 40 % of a call at N = 1 before it was kept).  It ends with
        None at a group whose sign cannot be found there (an unresolvable
        hint, or a group that cannot be solved at all): :func:`solve` raises
        that error when it reaches the group, after the errors of the groups
        before it.
    here : dict[str, BodyState]
        The states at the scene's own position, as far as they were solved.
    resolved : bool
        Every group has its sign.
    names : list[str]
        The groups' names (``Group.name`` sorts the links' names each time).
    bodies : list[str]
        The bodies in solving order: frame, driver, the links of each group.
    missing : list[str]
        Bodies of the scene that no group solves.
    points : list[tuple[str, str, complex]]
        Each named point, the body whose motion defines it and the point's
        own coordinates there.
    dtypes : list[type]
        The kind of number of each column of the result (:func:`_columns`).
    """

    def __init__(self, scene: Scene, structure: Structure):
        self.scene = scene
        self.structure = structure
        self.base = driver_position(scene)
        self.here: dict[str, BodyState] = {
            FRAME: BodyState.resting(),
            structure.driver: _driver_state(scene, np.array([self.base])),
        }
        signs = []
        with np.errstate(all="ignore"):
            for group in structure.groups:
                try:
                    sign = _branch_sign(scene, group, self.here)
                    solution = _solve_group(scene, group, self.here, sign)
                except Exception:  # noqa: BLE001 - solve meets the error again, in its place
                    signs.append(None)
                    break
                signs.append(sign)
                self.here[group.links[0]] = solution.i
                self.here[group.links[1]] = solution.j
        self.signs = tuple(signs)
        self.resolved = len(signs) == len(structure.groups) and None not in signs
        self.names = [group.name for group in structure.groups]
        self.bodies = [FRAME, structure.driver] + [link for group in structure.groups for link in group.links]
        self.missing = [name for name in scene.bodies if name not in self.bodies]
        self.points = []
        for name in scene.point_names:
            home = scene.home_of(name)
            self.points.append((name, home, scene.bodies[home].points[name]))
        self.dtypes = (
            [float, float, float, complex, complex, complex] * len(self.bodies)
            + [complex, complex, complex] * len(self.points)
            + [float, float, float, complex] * len(scene.prismatics)
            + [float, float] * len(structure.groups)
            + [bool]
        )
        #: each kind of number, its columns and a function that picks them from a list of all: the blocks of :func:`_solve_few`
        self.kinds = []
        for dtype in (float, complex, bool):
            ks = [k for k, d in enumerate(self.dtypes) if d is dtype]
            self.kinds.append((dtype, ks, operator.itemgetter(*ks) if len(ks) > 1 else lambda row, k=ks[0]: (row[k],)))
        #: the columns ordered by kind of number, as the result's list of columns holds them (:func:`_part`)
        self.order = [k for _, ks, _ in self.kinds for k in ks]
        at = {k: place for place, k in enumerate(self.order)}  # where column k is in that list

        def places(start: int, count: int) -> tuple[int, ...]:
            return tuple(at[k] for k in range(start, start + count))

        #: where each body's, point's and slider's columns are in the result's list, and the groups'
        self.body_columns = [(name, places(6 * m, 6)) for m, name in enumerate(self.bodies)]
        start = 6 * len(self.bodies)
        self.point_columns = [(name, places(start + 3 * m, 3)) for m, (name, _, _) in enumerate(self.points)]
        start += 3 * len(self.points)
        self.slider_columns = [(pair.name, places(start + 4 * m, 4)) for m, pair in enumerate(scene.prismatics)]
        start += 4 * len(scene.prismatics)
        self.condition_columns = [(name, at[start + m]) for m, name in enumerate(self.names)]
        self.sine_columns = [(name, at[start + len(self.names) + m]) for m, name in enumerate(self.names)]
        self.valid_column = at[start + 2 * len(self.names)]
        driver = scene.driver
        if isinstance(driver, Crank):
            pivot = single.Point(scene.frame.points[driver.pivot], 0j, 0j)
            z, omega, epsilon = scene.bodies[driver.link].points[driver.pivot], float(driver.omega), float(driver.epsilon)
            self.driver_at = lambda phi: single.driven(phi, omega, epsilon, pivot, z)
        else:
            guide: Line = scene.frame.lines[driver.guide]
            u = complex(math.cos(guide.angle), math.sin(guide.angle))
            z, angle, turn = scene.bodies[driver.link].points[driver.point], float(guide.angle), cmath.exp(1j * guide.angle)
            v, a = driver.velocity * u, driver.acceleration * u
            self.driver_at = lambda s: single.from_point(angle, 0.0, 0.0, single.Point(guide.origin + s * u, v, a), z, turn)


#: The plans of the scenes solved last, by id(scene) (a Scene is frozen; the
#: plan holds the scene, so its id is not reused while the plan is kept).
_PLANS: dict[int, _Plan] = {}
#: How many plans are kept.
_PLANS_KEPT = 32


def _prepared(scene: Scene, structure: Structure | None) -> _Plan:
    """The plan of a scene and structure, kept from an earlier call if there was one.

    Without a structure, the one found for the scene before (a scene's
    structure is found the same way every time).
    """
    plan = _PLANS.get(id(scene))
    if plan is not None and plan.scene is scene and structure in (None, plan.structure):
        return plan
    if structure is None:
        structure = find_structure(scene)
    plan = _Plan(scene, structure)
    if len(_PLANS) >= _PLANS_KEPT:
        del _PLANS[next(iter(_PLANS))]  # the oldest
    _PLANS[id(scene)] = plan
    return plan


# --- one piece of the positions ---------------------------------------------------


@dataclass
class _Piece:
    """The states of every body over some driver positions, the points computed, each group's conditioning."""

    states: dict[str, BodyState]
    points: dict[tuple[str, complex], PointState]
    conditions: dict[str, np.ndarray]
    sines: dict[str, np.ndarray]
    valid: np.ndarray


def _solve_piece(plan: _Plan, driver: np.ndarray, allow_partial: bool, asked_here: bool, law: "_Law | None" = None) -> _Piece:
    """The driver, then each group in order, at the positions *driver* (see :func:`solve`)."""
    scene, groups = plan.scene, plan.structure.groups
    rates = law.rates if law is not None else None
    states: dict[str, BodyState] = {FRAME: BodyState.resting(), plan.structure.driver: _driver_state(scene, driver, rates)}
    points: dict[tuple[str, complex], PointState] = {}
    valid = np.ones(len(driver), dtype=bool)
    conditions: dict[str, np.ndarray] = {}
    sines: dict[str, np.ndarray] = {}
    for k, group in enumerate(groups):
        sign = plan.signs[k] if k < len(plan.signs) else None
        if sign is None:
            sign = _branch_sign(scene, group, plan.here, asked_here)  # raises the error the plan met
        if law is not None and plan.names[k] in law.flips:
            sign = sign * law.flips[plan.names[k]]  # the other branch where the law says so
        solution = _solve_group(scene, group, states, sign, points)
        solved = solution.assembled & ~solution.singular
        fails = valid & ~solved
        if not allow_partial and fails.any():
            raise _failure(scene, group, solution, driver, fails)
        valid &= solved
        states[group.links[0]] = solution.i
        states[group.links[1]] = solution.j
        if solution.inner is not None:  # the inner joint's motion, as the dyad found it, for both links
            for link in group.links:
                points[(link, scene.bodies[link].points[group.inner.point])] = solution.inner
        conditions[plan.names[k]] = _nan_unless(solution.assembled, solution.condition)
        sines[plan.names[k]] = _nan_unless(solution.assembled, solution.sine)
    return _Piece(states, points, conditions, sines, valid)


def _nan_unless(assembled, values):
    """The values, NaN where the group is not assembled (as they are if it is everywhere: no ``np.where``)."""
    if is_number(values) or not assembled.all():
        return np.where(assembled, values, np.nan)
    return values


# --- driver -------------------------------------------------------------------


def _positions(positions, base: float) -> np.ndarray:
    """The driver positions as a new 1-D float array (the solution keeps it)."""
    if positions is None:
        return np.array([base], dtype=float)
    try:
        driver = np.array(positions, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"driver positions must be numbers (crank angle in rad or position in m), got {positions!r}") from None
    if driver.ndim > 1:
        raise ValueError(f"driver positions must be a number or a 1-D array, got an array of shape {driver.shape}")
    driver = np.atleast_1d(driver)
    if len(driver) <= FEW and all(map(math.isfinite, driver.tolist())):
        return driver  # a few positions: checked without numpy's fixed cost per call
    bad = ~np.isfinite(driver)
    if bad.any():
        raise ValueError(f"driver position {driver[bad][0]!r} (index {int(np.argmax(bad))}) is not a finite number")
    return driver


def _driver_state(scene: Scene, positions: np.ndarray, rates=None) -> BodyState:
    """The driver's motion: ω, ε (or velocity, acceleration) at each position.

    Without *rates* they are the scene's values, plain numbers the same at
    every position; *rates* = (rate, acceleration) gives them per position
    (arrays over the positions, or numbers).
    """
    driver = scene.driver
    body = scene.bodies[driver.link]
    crank = isinstance(driver, Crank)
    if rates is None:
        rate, acceleration = (float(driver.omega), float(driver.epsilon)) if crank else (driver.velocity, driver.acceleration)
    else:
        rate, acceleration = rates
    if crank:
        # the pivot stays at its frame point; the crank turns about it
        pivot = PointState(scene.frame.points[driver.pivot], 0j, 0j)
        return BodyState.from_point(positions, rate, acceleration, pivot, body.points[driver.pivot])
    # LinearDriver: the link's x axis along the guide, its point at Q + s·u
    guide: Line = scene.frame.lines[driver.guide]
    u = complex(math.cos(guide.angle), math.sin(guide.angle))
    point = PointState(guide.origin + positions * u, rate * u, acceleration * u)
    return BodyState.from_point(float(guide.angle), 0.0, 0.0, point, body.points[driver.point])


class _Law:
    """The driver's rates and the groups' branch flips at each position asked for (see :func:`solve`, *rates*, *branches*)."""

    def __init__(self, plan: _Plan, n: int, rates, branches):
        self.rates = None
        if rates is not None:
            try:
                rate, acceleration = rates
            except (TypeError, ValueError):
                raise ValueError(f"rates must be a pair (rate, acceleration), got {rates!r}") from None
            self.rates = (_per_position(rate, n, "rates[0]"), _per_position(acceleration, n, "rates[1]"))
        self.flips = {}
        for name, flip in (branches or {}).items():
            if name not in plan.names:
                raise ValueError(f"branches: there is no group {name!r} (groups: {', '.join(plan.names)})")
            flip = _per_position(flip, n, f"branches[{name!r}]")
            if not np.all(np.abs(flip) == 1):
                raise ValueError(f"branches[{name!r}]: expected +1 (the scene's branch) or −1 (the other) at each position")
            self.flips[name] = flip

    def part(self, start: int, stop: int) -> "_Law":
        """The same over the positions [start, stop)."""
        out = object.__new__(_Law)
        cut = lambda x: x if is_number(x) else x[start:stop]  # noqa: E731
        out.rates = None if self.rates is None else tuple(cut(x) for x in self.rates)
        out.flips = {name: cut(flip) for name, flip in self.flips.items()}
        return out


def _per_position(value, n: int, what: str):
    """A number, or a float array of shape (n,), finite."""
    array = np.asarray(value, dtype=float)
    if array.ndim == 0:
        if not math.isfinite(float(array)):
            raise ValueError(f"{what} must be finite, got {value!r}")
        return float(array)
    if array.shape != (n,):
        raise ValueError(f"{what} must be a number or an array of one value per position ({n}), got shape {array.shape}")
    if not np.isfinite(array).all():
        raise ValueError(f"{what} must be finite at every position")
    return array


# --- groups -------------------------------------------------------------------


def _point_of(states: dict[str, BodyState], points: dict | None, body: str, z: complex) -> PointState:
    """State of the own point z of a body; *points* keeps it for the next who asks (groups, the result)."""
    if points is None:
        return states[body].point(z)
    key = (body, z)
    point = points.get(key)
    if point is None:
        point = points[key] = states[body].point(z)
    return point


def _known_point(scene: Scene, joint: Joint, states: dict[str, BodyState], points: dict | None = None) -> PointState:
    """State of the point of an outer revolute joint, from the known body."""
    known = joint.bodies[1]
    return _point_of(states, points, known, scene.bodies[known].points[joint.point])


def _lines(scene: Scene, joint: Joint) -> tuple[Line, Line]:
    """(line on joint.bodies[0], line on joint.bodies[1]) of a prismatic joint."""
    pair = joint.prismatic
    slider = scene.bodies[pair.slider].lines[pair.slider_line]
    guide = scene.bodies[pair.guide].lines[pair.guide_line]
    return (slider, guide) if joint.bodies[0] == pair.slider else (guide, slider)


#: The vectorised solver of each kind of group.
VECTORISED = {"RRR": solve_rrr, "RRP": solve_rrp, "RPR": solve_rpr, "PRP": solve_prp, "RPP": solve_rpp}


def _solve_group(scene: Scene, group: Group, states: dict, sign: int, points: dict | None = None, solvers: dict = VECTORISED):
    """Solve one group from the known states; *points* keeps the known points it computes (see :func:`_point_of`).

    *solvers* gives the function for each kind: :data:`VECTORISED` (numpy
    arrays over the positions, a :class:`DyadSolution`) or
    :data:`plans.analytic.single.SOLVERS` (one position).
    """
    i, j = group.links
    body_i, body_j = scene.bodies[i], scene.bodies[j]
    o_i, inner, o_j = group.outer_i, group.inner, group.outer_j
    if group.kind == "RRR":
        return solvers["RRR"](
            _known_point(scene, o_i, states, points),
            _known_point(scene, o_j, states, points),
            body_i.points[o_i.point],
            body_i.points[inner.point],
            body_j.points[o_j.point],
            body_j.points[inner.point],
            sign,
        )
    if group.kind == "RRP":
        j_line, guide_line = _lines(scene, o_j)
        return solvers["RRP"](
            _known_point(scene, o_i, states, points),
            body_i.points[o_i.point],
            body_i.points[inner.point],
            body_j.points[inner.point],
            j_line,
            states[o_j.bodies[1]],
            guide_line,
            sign,
        )
    if group.kind == "RPR":
        if inner.prismatic.guide != i:
            raise StructureError(f"{group.name}: link {i} should carry the guide line of the inner prismatic pair")
        i_line, j_line = _lines(scene, inner)
        return solvers["RPR"](
            _known_point(scene, o_i, states, points),
            _known_point(scene, o_j, states, points),
            body_i.points[o_i.point],
            i_line,
            body_j.points[o_j.point],
            j_line,
            sign,
        )
    if group.kind == "PRP":
        i_line, gi_line = _lines(scene, o_i)
        j_line, gj_line = _lines(scene, o_j)
        return solvers["PRP"](
            states[o_i.bodies[1]],
            gi_line,
            i_line,
            body_i.points[inner.point],
            states[o_j.bodies[1]],
            gj_line,
            j_line,
            body_j.points[inner.point],
        )
    if group.kind == "RPP":
        i_line, j_inner = _lines(scene, inner)
        j_outer, g_line = _lines(scene, o_j)
        return solvers["RPP"](
            _known_point(scene, o_i, states, points),
            body_i.points[o_i.point],
            i_line,
            j_inner,
            j_outer,
            states[o_j.bodies[1]],
            g_line,
        )
    raise StructureError(f"{group.name}: no analytic solution for a group of kind {group.kind}")


def _hint_points(scene: Scene, group: Group) -> list[str]:
    """The assembly hints that apply to a group: points of its links, outer joints excepted."""
    i, j = group.links
    outer = {o.point for o in (group.outer_i, group.outer_j) if o.kind == "R"}
    return [
        name
        for name in scene.assembly
        if (name in scene.bodies[i].points or name in scene.bodies[j].points) and name not in outer
    ]


def _branch_sign(scene: Scene, group: Group, here: dict[str, BodyState], asked_here: bool = False) -> int:
    """+1 or −1 for the group, from the scene's assembly hints (see :func:`solve`).

    *here* holds the states at the scene's own position (one position),
    where a location hint is resolved; if the group does not assemble there,
    that is an AssemblyError, which says so unless the scene's own position
    is what was asked for.
    """
    if group.kind in ("PRP", "RPP"):
        return 1
    hints = _hint_points(scene, group)
    if not hints:
        return group.orientation  # +1 in the order of the group's name (Group.orientation)
    name = hints[0]
    hint = scene.assembly[name]
    if isinstance(hint, int):
        return (1 if hint > 0 else -1) * group.orientation
    owner = group.links[0] if name in scene.bodies[group.links[0]].points else group.links[1]
    distance = {}
    for sign in (1, -1):
        solution = _solve_group(scene, group, here, sign)
        if np.broadcast_to(solution.assembled, (1,))[0]:
            link = solution.i if owner == group.links[0] else solution.j
            distance[sign] = abs(np.broadcast_to(link.position(scene.bodies[owner].points[name]), (1,))[0] - hint)
    if not distance:
        solution = _solve_group(scene, group, here, 1)
        error = _failure(scene, group, solution, np.array([driver_position(scene)]), np.broadcast_to(~(solution.assembled & ~solution.singular), (1,)))
        if not asked_here:
            error = AssemblyError(
                f"{error}; the hint {name} near ({hint.real:g}, {hint.imag:g}) m chooses the branch of {group.name} "
                "at the scene's own position, so no branch can be chosen for the positions asked for"
            )
            error.group, error.position = group.name, driver_position(scene)
        raise error
    return -1 if distance.get(-1, math.inf) < distance.get(1, math.inf) else 1


# --- messages -----------------------------------------------------------------


def _length(x: float, gap: float | None = None) -> str:
    """A length for messages; with *gap*, enough digits to show a difference of that size."""
    x = float(x)
    if gap is not None and x != 0 and 0 < abs(gap) < 1e-3 * abs(x):
        digits = min(16, 2 + math.ceil(math.log10(abs(x) / abs(gap))))
        return f"{x:.{digits}g} m"
    if x == 0 or 1e-3 <= abs(x) < 1e4:
        return f"{x:.3f} m"
    return f"{x:.3g} m"


def _where(scene: Scene, position: float) -> str:
    return position_text(isinstance(scene.driver, Crank), position)


def _failure(scene: Scene, group: Group, solution: DyadSolution, positions: np.ndarray, fails: np.ndarray) -> Exception:
    """The error for the first failing position of a group.

    ``positions`` and ``fails`` run over the solution's entries; ``fails``
    marks the failing positions the caller asked for.
    """
    k = int(np.argmax(fails))
    where = _where(scene, positions[k])
    i, j = group.links
    count = int(fails.sum())
    more = f" (and at {count - 1} more of the positions asked for; allow_partial=True returns NaN there)" if count > 1 else ""
    o_i, inner, o_j = group.outer_i, group.inner, group.outer_j
    def at(values):  # a group's quantity at position k (a number if it is the same everywhere)
        return np.broadcast_to(values, np.shape(positions))[k]

    m = {key: float(at(value)) for key, value in solution.measures.items()}
    if not at(solution.assembled) and group.kind in ("RRR", "RRP", "RPR"):
        if group.kind == "RRR":
            B, C, D = o_i.point, inner.point, o_j.point
            d = m["distance"]
            if d > m["sum"]:
                gap = d - m["sum"]
                detail = f"|{B}{D}| = {_length(d, gap)} > {B}{C} + {C}{D} = {_length(m['sum'], gap)} (gap {_length(gap)})"
            elif d < m["difference"]:
                gap = m["difference"] - d
                detail = f"|{B}{D}| = {_length(d, gap)} < |{B}{C} − {C}{D}| = {_length(m['difference'], gap)} (gap {_length(gap)})"
            else:
                detail = f"{B} and {D} coincide, or a point before them is not known"
            message = f"{group.name}: joint {C} cannot assemble at {where}: {detail}"
        elif group.kind == "RRP":
            B, C = o_i.point, inner.point
            _, guide_line = _lines(scene, o_j)
            y, length = m["distance"], m["length"]
            if y > length:
                detail = (
                    f"the line {C} runs on (parallel to {guide_line.key}) passes {_length(y, y - length)} from {B}, "
                    f"farther than {B}{C} = {_length(length, y - length)} (gap {_length(y - length)})"
                )
            else:
                detail = f"a point before {B} or the guide {guide_line.key} is not known"
            message = f"{group.name}: joint {C} cannot assemble at {where}: {detail}"
        else:
            B, E = o_i.point, o_j.point
            i_line, _ = _lines(scene, inner)
            d, offset = m["distance"], m["offset"]
            if d < offset:
                detail = f"|{B}{E}| = {_length(d, offset - d)} < the offset {_length(offset, offset - d)} of the line from the pins (gap {_length(offset - d)})"
            elif d == 0:
                detail = f"{B} and {E} coincide: the line has no direction"
            else:
                detail = f"a point before {B} or {E} is not known"
            message = f"{group.name}: the line {i_line.key} cannot pass through {E} at {where}: {detail}"
        error: Exception = AssemblyError(message + more)
    else:
        sine = float(at(solution.sine))
        if group.kind == "RRR":
            what = f"{o_i.point}, {inner.point} and {o_j.point} are in line"
        elif group.kind == "RRP":
            what = f"{o_i.point}{inner.point} is perpendicular to the guide {_lines(scene, o_j)[1].key}"
        elif group.kind == "RPR":
            what = f"the line {_lines(scene, inner)[0].key} is perpendicular to {o_i.point}{o_j.point}"
        elif group.kind == "PRP":
            what = f"the guides {_lines(scene, o_i)[1].key} and {_lines(scene, o_j)[1].key} are parallel: {inner.point} has no definite position"
        else:
            what = f"the lines {_lines(scene, inner)[1].key} and {_lines(scene, o_j)[1].key} are parallel: the position is not definite"
        sine_text = (
            f" (|sin| of the angle between the construction lines = {sine:.1e}, below the dead-centre threshold {REFUSE_SINE:g})"
            if math.isfinite(sine)
            else ""
        )
        error = SingularPositionError(
            f"{group.name}: dead centre at {where}: {what}{sine_text}; the 2×2 velocity system of links {i} and {j} "
            f"is singular and their velocities do not exist there{more}"
        )
    error.group = group.name
    error.position = float(positions[k])
    return error


# --- the result -----------------------------------------------------------------


def _columns(plan: _Plan, piece: _Piece) -> list:
    """Every array of the result over one piece, in the order of ``plan.dtypes``.

    For each body (``plan.bodies``) φ, ω, ε and its origin's r, v, a; for
    each point r, v, a; for each prismatic pair s, v_rel, a_rel, aᵏ; each
    group's condition numbers, then its sines; ``valid``.  A number stands
    for a quantity that is the same at every position.  A point that a group
    has already computed (an outer joint) is taken as it is.
    """
    states = piece.states
    out = []
    for name in plan.bodies:
        state = states[name]
        out += (state.phi, state.omega, state.epsilon, state.origin.r, state.origin.v, state.origin.a)
    for _, home, z in plan.points:
        point = _point_of(states, piece.points, home, z)
        out += (point.r, point.v, point.a)
    for pair in plan.scene.prismatics:
        out += _slider_motion(plan.scene, pair, states, piece.points)
    out += piece.conditions.values()
    out += piece.sines.values()
    out.append(piece.valid)
    return out


class _Columns:
    """The columns of the result (:func:`_columns`) over all N positions, filled piece by piece.

    A column that is a number in every piece becomes an array of that number
    (one array per distinct number, the result's arrays being read-only).
    A single piece gives its arrays as they are.  Pieces are copied into
    rows of one 2-D array per kind of number, allocated at the first piece:
    at 100 000 positions, forty fresh arrays of 0.8–1.6 MB each cost
    ~15 ms of page faults, one block of the same size under 1 ms (it is
    large enough for numpy to ask for huge pages).
    """

    def __init__(self, dtypes: list[type], n: int):
        self.dtypes = dtypes
        self.n = n
        self.values: list = []  # per column: the number it is so far, or its array over all positions

    def put(self, start: int, parts: list) -> None:
        """Add one piece's columns, for the positions from *start* on."""
        if not self.values:
            # every array of a piece runs over its positions (numpy broadcasts numbers to them), as `valid` does
            if start == 0 and len(parts[-1]) == self.n:
                self.values = list(parts)  # the piece is everything
                return
            self._allocate(parts)
        stop = start + len(parts[-1])  # `valid` is an array over the piece
        for k, part in enumerate(parts):
            value = self.values[k]
            if is_number(value):
                if is_number(part) and part == value:
                    continue
                # a number so far, not in this piece: an array after all
                value = self.values[k] = np.empty(self.n, self.dtypes[k])
                value[:start] = self.values_before[k]
            value[start:stop] = part

    def _allocate(self, parts: list) -> None:
        varying = [k for k, part in enumerate(parts) if not is_number(part)]
        self.values = list(parts)
        self.values_before = list(parts)
        for dtype in {self.dtypes[k] for k in varying}:
            mine = [k for k in varying if self.dtypes[k] is dtype]
            block = np.empty((len(mine), self.n), dtype)
            for row, k in zip(block, mine):
                self.values[k] = row

    def arrays(self) -> list[np.ndarray]:
        """Every column as an array over the N positions."""
        constants: dict = {}
        out = []
        for value, dtype in zip(self.values, self.dtypes):
            if is_number(value):
                value = np.asarray(value).item()  # a Python number (a 0-d array is not hashable)
                key = (dtype, value)
                if key not in constants:
                    constants[key] = np.zeros(self.n, dtype) if value == 0 else np.full(self.n, value, dtype)
                value = constants[key]
            out.append(value)
        return out


def _solution(plan: _Plan, driver: np.ndarray, columns: _Once, warn_condition: float, calm: bool = False) -> AnalyticSolution:
    """The result from the columns of :func:`_columns` (``columns()``: each as a read-only array over the positions).

    Its dicts of motions are made when first read (:func:`_part`); the
    warnings now, unless *calm*: no group's condition exceeds
    *warn_condition* (known already), so there is nothing to look for.
    """
    known = {}
    warnings: tuple = ()
    if not calm:
        known = {name: _part(plan, columns(), name) for name in ("conditions", "sines", "valid")}
        warnings = _warnings(plan.scene, plan.structure, driver, known["conditions"], known["sines"], known["valid"], warn_condition)
    return AnalyticSolution._deferred(
        plan.scene, plan.structure, frozen(driver), warnings, lambda name: _part(plan, columns(), name), known
    )


def _part(plan: _Plan, columns: list[np.ndarray], name: str):
    """One attribute of the result (``links``, ``points``, …, ``valid``) from the list of the columns of :func:`_columns`.

    The list holds them ordered by kind of number (``plan.order``); the
    plan knows where each body's, point's, … columns are in it.
    """
    c = columns
    if name == "links":
        return {body: LinkMotion(c[phi], c[omega], c[epsilon]) for body, (phi, omega, epsilon, *_) in plan.body_columns if body != FRAME}
    if name == "poses":
        return {body: (c[phi], c[r]) for body, (phi, _, _, r, _, _) in plan.body_columns}
    if name == "origins":
        return {body: PointMotion(c[r], c[v], c[a]) for body, (*_, r, v, a) in plan.body_columns}
    if name == "points":
        return {point: PointMotion(c[r], c[v], c[a]) for point, (r, v, a) in plan.point_columns}
    if name == "sliders":
        return {pair: SliderMotion(c[s], c[v], c[a], c[k]) for pair, (s, v, a, k) in plan.slider_columns}
    if name == "conditions":
        return {group: c[k] for group, k in plan.condition_columns}
    if name == "sines":
        return {group: c[k] for group, k in plan.sine_columns}
    if name == "valid":
        return c[plan.valid_column]
    raise AttributeError(name)


def _slider_motion(scene: Scene, pair, states: dict[str, BodyState], points: dict | None = None) -> tuple:
    """(s, v_rel, a_rel, aᵏ): travel, relative velocity and acceleration, Coriolis of one prismatic pair.

    With Q_s the slider line's origin, Q_g the guide line's origin, u_g the
    guide's direction and G the guide's point under Q_s::

        s = (Q_s − Q_g)·u_g,   v_rel = (v_Qs − v_G)·u_g,   a_rel = (a_Qs − a_G)·u_g,
        aᵏ = 2iω_g·u_g·v_rel

    (On a guide that does not move, v_G and a_G are plain zeros, left out;
    ``2iω_g·u_g`` is then one number times v_rel.)
    """
    guide = states[pair.guide]
    slider_line = scene.bodies[pair.slider].lines[pair.slider_line]
    guide_line = scene.bodies[pair.guide].lines[pair.guide_line]
    Q_s = _point_of(states, points, pair.slider, slider_line.origin)
    u_g = guide.direction(guide_line.angle)
    Q_g = guide.position(guide_line.origin)
    G = guide.point_at(Q_s.r)
    v_rel = dot(u_g, sum_terms(Q_s.v, -G.v))
    return (
        dot(u_g, Q_s.r - Q_g),
        v_rel,
        dot(u_g, sum_terms(Q_s.a, -G.a)),
        coriolis_acceleration(guide.omega, u_g) * v_rel,
    )
