"""The analytic solver: driver, then the dyads in order, then every point and slider.

One call solves N driver positions with numpy arrays, group after group;
there is no Python loop over the positions.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import AssemblyError, SingularPositionError, StructureError
from ..limits import REFUSE_SINE, WARN_CONDITION, NearDeadCentre, position_text
from ..scene import FRAME, Crank, Line, Scene
from ..structure import Group, Joint, Structure, find_structure
from .dyads import DyadSolution, solve_prp, solve_rpp, solve_rpr, solve_rrp, solve_rrr
from .kinematics import BodyState, PointState, coriolis_acceleration, dot
from .solution import AnalyticSolution, LinkMotion, PointMotion, SliderMotion, _frozen

__all__ = ["solve", "driver_position"]


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
    if structure is None:
        structure = find_structure(scene)
    if not (warn_condition >= 1):
        raise ValueError(f"warn_condition must be a number of at least 1 (a condition number), got {warn_condition!r}")
    base = driver_position(scene)
    driver = _positions(positions, base)
    # index 0 is the scene's own position, where location hints choose the branches
    everywhere = np.concatenate(([base], driver))
    n = len(everywhere)
    with np.errstate(all="ignore"):
        states: dict[str, BodyState] = {FRAME: BodyState.resting(n)}
        states[structure.driver] = _driver_state(scene, everywhere)
        valid = np.ones(n, dtype=bool)
        conditions: dict[str, np.ndarray] = {}
        sines: dict[str, np.ndarray] = {}
        for group in structure.groups:
            sign = _branch_sign(scene, group, states, asked_here=positions is None)
            solution = _solve_group(scene, group, states, sign)
            fails = valid & ~(solution.assembled & ~solution.singular)
            fails[0] = False
            if fails.any() and not allow_partial:
                raise _failure(scene, group, solution, everywhere, fails)
            valid &= solution.assembled & ~solution.singular
            states[group.links[0]] = solution.i
            states[group.links[1]] = solution.j
            conditions[group.name] = np.where(solution.assembled, solution.condition, np.nan)[1:]
            sines[group.name] = np.where(solution.assembled, solution.sine, np.nan)[1:]
        missing = [name for name in scene.bodies if name not in states]
        if missing:
            raise StructureError(f"{scene.source}: the structure does not solve the links {', '.join(missing)}")
        states = {name: state.take(slice(1, None)) for name, state in states.items()}
        warnings = _warnings(scene, structure, driver, conditions, sines, valid[1:], warn_condition)
        return _solution(scene, structure, driver, states, conditions, sines, valid[1:], warnings)


def _warnings(scene, structure, driver, conditions, sines, valid, warn_condition) -> tuple[NearDeadCentre, ...]:
    """One warning per group and run of consecutive solved positions above *warn_condition*, at the worst."""
    out = []
    crank = isinstance(scene.driver, Crank)
    for group in structure.groups:
        condition = conditions[group.name]
        near = valid & (condition > warn_condition)
        k = 0
        n = len(near)
        while k < n:
            if not near[k]:
                k += 1
                continue
            end = k
            while end < n and near[end]:
                end += 1
            worst = k + int(np.argmax(condition[k:end]))
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
            k = end
    return tuple(out)


# --- driver -------------------------------------------------------------------


def _positions(positions, base: float) -> np.ndarray:
    if positions is None:
        return np.array([base], dtype=float)
    try:
        driver = np.asarray(positions, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"driver positions must be numbers (crank angle in rad or position in m), got {positions!r}") from None
    if driver.ndim > 1:
        raise ValueError(f"driver positions must be a number or a 1-D array, got an array of shape {driver.shape}")
    driver = np.atleast_1d(driver)
    bad = ~np.isfinite(driver)
    if bad.any():
        raise ValueError(f"driver position {driver[bad][0]!r} (index {int(np.argmax(bad))}) is not a finite number")
    return driver


def _driver_state(scene: Scene, positions: np.ndarray) -> BodyState:
    """The driver's motion: ω, ε (or velocity, acceleration) held at the scene's values."""
    driver = scene.driver
    n = len(positions)
    body = scene.bodies[driver.link]
    zero = np.zeros(n, dtype=complex)
    if isinstance(driver, Crank):
        # the pivot stays at its frame point; the crank turns about it
        pivot = PointState(np.full(n, scene.frame.points[driver.pivot], dtype=complex), zero, zero)
        return BodyState.from_point(positions, np.full(n, driver.omega), np.full(n, driver.epsilon), pivot, body.points[driver.pivot])
    # LinearDriver: the link's x axis along the guide, its point at Q + s·u
    guide: Line = scene.frame.lines[driver.guide]
    u = complex(math.cos(guide.angle), math.sin(guide.angle))
    point = PointState(guide.origin + positions * u, np.full(n, driver.velocity * u), np.full(n, driver.acceleration * u))
    zeros = np.zeros(n)
    return BodyState.from_point(np.full(n, guide.angle), zeros, zeros, point, body.points[driver.point])


# --- groups -------------------------------------------------------------------


def _known_point(scene: Scene, joint: Joint, states: dict[str, BodyState]) -> PointState:
    """State of the point of an outer revolute joint, from the known body."""
    known = joint.bodies[1]
    return states[known].point(scene.bodies[known].points[joint.point])


def _lines(scene: Scene, joint: Joint) -> tuple[Line, Line]:
    """(line on joint.bodies[0], line on joint.bodies[1]) of a prismatic joint."""
    pair = joint.prismatic
    slider = scene.bodies[pair.slider].lines[pair.slider_line]
    guide = scene.bodies[pair.guide].lines[pair.guide_line]
    return (slider, guide) if joint.bodies[0] == pair.slider else (guide, slider)


def _solve_group(scene: Scene, group: Group, states: dict[str, BodyState], sign: int) -> DyadSolution:
    i, j = group.links
    body_i, body_j = scene.bodies[i], scene.bodies[j]
    o_i, inner, o_j = group.outer_i, group.inner, group.outer_j
    if group.kind == "RRR":
        return solve_rrr(
            _known_point(scene, o_i, states),
            _known_point(scene, o_j, states),
            body_i.points[o_i.point],
            body_i.points[inner.point],
            body_j.points[o_j.point],
            body_j.points[inner.point],
            sign,
        )
    if group.kind == "RRP":
        j_line, guide_line = _lines(scene, o_j)
        return solve_rrp(
            _known_point(scene, o_i, states),
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
        return solve_rpr(
            _known_point(scene, o_i, states),
            _known_point(scene, o_j, states),
            body_i.points[o_i.point],
            i_line,
            body_j.points[o_j.point],
            j_line,
            sign,
        )
    if group.kind == "PRP":
        i_line, gi_line = _lines(scene, o_i)
        j_line, gj_line = _lines(scene, o_j)
        return solve_prp(
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
        return solve_rpp(
            _known_point(scene, o_i, states),
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


def _branch_sign(scene: Scene, group: Group, states: dict[str, BodyState], asked_here: bool = False) -> int:
    """+1 or −1 for the group, from the scene's assembly hints (see :func:`solve`).

    A location hint is resolved at the scene's own position (entry 0 of the
    states); if the group does not assemble there, that is an AssemblyError,
    which says so unless the scene's own position is what was asked for.
    """
    if group.kind in ("PRP", "RPP"):
        return 1
    hints = _hint_points(scene, group)
    if not hints:
        return 1
    name = hints[0]
    hint = scene.assembly[name]
    if isinstance(hint, int):
        return 1 if hint > 0 else -1
    here = {body: state.take(slice(0, 1)) for body, state in states.items()}
    owner = group.links[0] if name in scene.bodies[group.links[0]].points else group.links[1]
    distance = {}
    for sign in (1, -1):
        solution = _solve_group(scene, group, here, sign)
        if solution.assembled[0]:
            link = solution.i if owner == group.links[0] else solution.j
            distance[sign] = abs(link.position(scene.bodies[owner].points[name])[0] - hint)
    if not distance:
        solution = _solve_group(scene, group, here, 1)
        error = _failure(scene, group, solution, np.array([driver_position(scene)]), ~(solution.assembled & ~solution.singular))
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
    m = {key: float(value[k]) for key, value in solution.measures.items()}
    if not solution.assembled[k] and group.kind in ("RRR", "RRP", "RPR"):
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
        sine = float(solution.sine[k])
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


def _solution(
    scene: Scene,
    structure: Structure,
    driver: np.ndarray,
    states: dict[str, BodyState],
    conditions: dict[str, np.ndarray],
    sines: dict[str, np.ndarray],
    valid: np.ndarray,
    warnings: tuple[NearDeadCentre, ...] = (),
) -> AnalyticSolution:
    links = {
        name: LinkMotion(_frozen(state.phi), _frozen(state.omega), _frozen(state.epsilon))
        for name, state in states.items()
        if name != FRAME
    }
    points = {}
    for name in scene.point_names:
        home = scene.home_of(name)
        state = states[home].point(scene.bodies[home].points[name])
        points[name] = PointMotion(_frozen(state.r), _frozen(state.v), _frozen(state.a))
    sliders = {pair.name: _slider_motion(scene, pair, states) for pair in scene.prismatics}
    poses = {name: (_frozen(state.phi), _frozen(state.origin.r)) for name, state in states.items()}
    origins = {
        name: PointMotion(_frozen(state.origin.r), _frozen(state.origin.v), _frozen(state.origin.a))
        for name, state in states.items()
    }
    return AnalyticSolution(
        scene=scene,
        structure=structure,
        driver=_frozen(driver.copy()),
        links=links,
        points=points,
        sliders=sliders,
        poses=poses,
        origins=origins,
        conditions={name: _frozen(c) for name, c in conditions.items()},
        sines={name: _frozen(c) for name, c in sines.items()},
        valid=_frozen(valid),
        warnings=warnings,
    )


def _slider_motion(scene: Scene, pair, states: dict[str, BodyState]) -> SliderMotion:
    """Travel, relative velocity and acceleration, Coriolis of one prismatic pair.

    With Q_s the slider line's origin, Q_g the guide line's origin, u_g the
    guide's direction and G the guide's point under Q_s::

        s = (Q_s − Q_g)·u_g,   v_rel = (v_Qs − v_G)·u_g,   a_rel = (a_Qs − a_G)·u_g,
        aᵏ = 2iω_g·v_rel·u_g
    """
    slider, guide = states[pair.slider], states[pair.guide]
    slider_line = scene.bodies[pair.slider].lines[pair.slider_line]
    guide_line = scene.bodies[pair.guide].lines[pair.guide_line]
    Q_s = slider.point(slider_line.origin)
    u_g = guide.direction(guide_line.angle)
    Q_g = guide.position(guide_line.origin)
    G = guide.point_at(Q_s.r)
    v_rel = dot(u_g, Q_s.v - G.v)
    return SliderMotion(
        s=_frozen(dot(u_g, Q_s.r - Q_g)),
        v_rel=_frozen(v_rel),
        a_rel=_frozen(dot(u_g, Q_s.a - G.a)),
        coriolis=_frozen(coriolis_acceleration(guide.omega, v_rel * u_g)),
    )
