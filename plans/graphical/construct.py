"""The graphical method, orchestrated: mechanism drawing, velocity plan, acceleration plan.

The order is the textbook's: the driver first, then each Assur group in
structural order — first all positions (compass construction), then the
velocity plan group by group, then the acceleration plan group by group —
and finally the readings, measured off the finished plans.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import replace

from ..limits import WARN_CONDITION, NearDeadCentre, position_text
from ..scene import Crank, Scales, Scene, diameter
from ..structure import Group, Structure, find_structure
from . import prp, rpp, rpr, rrp, rrr
from .driver import driver_acceleration, driver_velocity, place_driver
from .plan import GraphicalSolution
from .scales import DRAWN_LARGEST, check_scale, extent, measure, read_segment, round_scale
from .state import Construction, Sketch

__all__ = ["construct"]

_KINDS = {
    "RRR": (rrr.position_rrr, rrr.velocity_rrr, rrr.acceleration_rrr),
    "RRP": (rrp.position_rrp, rrp.velocity_rrp, rrp.acceleration_rrp),
    "RPR": (rpr.position_rpr, rpr.velocity_rpr, rpr.acceleration_rpr),
    "PRP": (prp.position_prp, prp.velocity_prp, prp.acceleration_prp),
    "RPP": (rpp.position_rpp, rpp.velocity_rpp, rpp.acceleration_rpp),
}


def construct(
    scene: Scene,
    structure: Structure | None = None,
    *,
    k_l: float | None = None,
    k_v: float | None = None,
    k_a: float | None = None,
    precision: float | None = None,
    arc_segments: int | None = None,
    warn_condition: float = WARN_CONDITION,
    check_scales: bool = True,
) -> GraphicalSolution:
    """Solve the mechanism graphically at the scene's driver position.

    The mechanism is constructed with compass and ruler, then the velocity
    plan and (unless ``scene.accelerations`` is False) the acceleration plan,
    group by group, and every result is read off the plans: a measured
    length [mm] times the scale factor (and divided by a link length for ω
    and ε), its direction or sense taken from the plan.

    Parameters
    ----------
    scene : plans.scene.Scene
    structure : plans.structure.Structure, optional
        The result of :func:`plans.structure.find_structure`, if at hand.
    k_l, k_v, k_a : float, optional
        Scale factors [m/mm, (m/s)/mm, (m/s²)/mm].  Each overrides the
        scene's ``[scales]``, which overrides the automatic choice: the round
        value (1, 2, 2.5 or 5 × 10ⁿ) that draws the larger side of the
        mechanism's bounding box, or the plan's largest vector, 60–120 mm long.
    precision : float, optional
        Drafting precision [mm], overriding the scene's: every measured length
        is rounded to a multiple of it before it is multiplied by the scale
        factor, so a reading differs from the exact one by at most
        precision/2 × k (divided by the link length for ω, ε).  The
        construction itself stays exact.  None: no rounding, and the readings
        equal the analytic solution to round-off.
    arc_segments : int, optional
        None: compass arcs are intersected exactly.  An integer: each arc is a
        shapely polygon with that many segments per quarter circle (faster to
        be wrong: the positions are only as good as the polygon).
    warn_condition : float
        A group whose construction lines meet with a condition number above
        this (|sin| of their angle below ~2/warn_condition) is near a dead
        centre: the solution carries a :class:`~plans.limits.NearDeadCentre`
        warning.  Default :data:`plans.limits.WARN_CONDITION`.
    check_scales : bool
        Refuse a given scale factor (here or in the scene's ``[scales]``)
        that draws the mechanism or a plan larger than a sheet or smaller
        than a millimetre (:func:`plans.graphical.scales.check_scale`).
        False for factors plans chose itself (common to several positions).

    Returns
    -------
    GraphicalSolution

    Raises
    ------
    plans.errors.SceneError
        A given scale factor draws a figure larger than a sheet or smaller
        than 1 mm; the message gives the range that fits.
    plans.errors.AssemblyError
        A group cannot be assembled (names the group, the lengths and the gap).
    plans.errors.SingularPositionError
        Two construction lines are parallel: |sin| of their angle is below
        :data:`plans.limits.REFUSE_SINE`, a dead-centre position.

    Examples
    --------
    >>> from plans.scene import load, example_path
    >>> solution = construct(load(example_path("slider-crank")), k_v=0.25)
    >>> round(solution.points["A"]["v"].imag, 4)
    14.8096
    >>> round(solution.velocity_plan.images["a"].imag, 2)   # mm on the plan
    59.24
    """
    if structure is None:
        structure = find_structure(scene)
    # where each factor came from, for messages: the scene's [scales] (also when a caller passes its value on)
    given = {
        key: f"scales.{key}" if value is None or value == getattr(scene.scales, key) else None
        for key, value in (("k_l", k_l), ("k_v", k_v), ("k_a", k_a))
    }
    k_l = k_l if k_l is not None else scene.scales.k_l
    k_v = k_v if k_v is not None else scene.scales.k_v
    k_a = k_a if k_a is not None else scene.scales.k_a
    precision = precision if precision is not None else scene.scales.precision
    if not (warn_condition >= 1):
        raise ValueError(f"warn_condition must be a number of at least 1 (a condition number), got {warn_condition!r}")
    if arc_segments is not None and int(arc_segments) < 1:
        raise ValueError(f"arc_segments must be a positive number of segments per quarter circle, got {arc_segments!r}")
    for key, value in (("k_l", k_l), ("k_v", k_v), ("k_a", k_a), ("precision", precision)):
        if value is not None and not (math.isfinite(value) and value > 0):
            raise ValueError(f"{key} must be a positive number, got {value!r}")

    given = {key: field for key, field in given.items() if {"k_l": k_l, "k_v": k_v, "k_a": k_a}[key] is not None}
    if check_scales and given:
        _refuse_unfit_early(scene, structure, {"k_l": k_l, "k_v": k_v, "k_a": k_a}, given, precision, arc_segments)

    size = _extent(scene)
    ctx = Construction(scene, arc_segments, k_l if k_l is not None else round_scale(size))
    ctx.size = size

    # --- the mechanism, drawn at k_l (or, when k_l is automatic, at a provisional
    # round k_l from the bodies' sizes: the construction is a similarity, so the
    # figure is the same; the final k_l is chosen from its bounding box) ---------
    place_driver(ctx)
    for group in structure.groups:
        candidates = _KINDS[group.kind][0](ctx, group)
        ctx.poses.update(_branch(scene, structure, group, candidates, ctx))
    positions = {name: ctx.point(scene.home_of(name), name) for name in scene.point_names}
    if k_l is None:
        xs = [z.real for z in positions.values()]
        ys = [z.imag for z in positions.values()]
        k_l = round_scale(max(max(xs) - min(xs), max(ys) - min(ys)), fallback=ctx.k_l0)

    # --- velocity plan -------------------------------------------------------------
    ctx.velocity = Sketch("velocity", k_v if k_v is not None else _provisional_v(ctx), ctx.scene.frame_number)
    _rest(ctx, ctx.velocity)
    driver_velocity(ctx)
    for group in structure.groups:
        _KINDS[group.kind][1](ctx, group)
        _images(ctx, ctx.velocity, ctx.v_motion, group.links)
    if k_v is None:
        k_v = round_scale(ctx.velocity.largest(), fallback=ctx.velocity.k0)

    # --- acceleration plan -----------------------------------------------------------
    if scene.accelerations:
        ctx.acceleration = Sketch("acceleration", k_a if k_a is not None else _provisional_a(ctx), ctx.scene.frame_number)
        _rest(ctx, ctx.acceleration)
        driver_acceleration(ctx)
        for group in structure.groups:
            _KINDS[group.kind][2](ctx, group)
            _images(ctx, ctx.acceleration, ctx.a_motion, group.links)
        if k_a is None:
            k_a = round_scale(ctx.acceleration.largest(), fallback=ctx.acceleration.k0)
    else:
        k_a = None

    # --- the finished plans and what is read off them ---------------------------------
    velocity_plan = ctx.velocity.finish(k_v, precision, ctx.velocity.link_images(scene))
    acceleration_plan = ctx.acceleration.finish(k_a, precision, ctx.acceleration.link_images(scene)) if k_a is not None else None
    v_label = {point: label for label, point in ctx.velocity.named.items()}
    a_label = {point: label for label, point in ctx.acceleration.named.items()} if acceleration_plan else {}
    points = {}
    for name in scene.point_names:
        entry = {"v": _read(velocity_plan.images.get(v_label.get(name), 0j), k_v, precision)}
        if acceleration_plan is not None:
            entry["a"] = _read(acceleration_plan.images.get(a_label.get(name), 0j), k_a, precision)
        points[name] = entry
    links, sliders = ctx.readings(k_l, k_v, k_a, precision)
    relative, rotations = ctx.read_from()
    crank = isinstance(scene.driver, Crank)
    position = scene.driver.phi if crank else scene.driver.s
    warnings = tuple(
        NearDeadCentre(group.name, group.joint, position, position_text(crank, position), ctx.conditions[group.name], ctx.sines[group.name], "graphical")
        for group in structure.groups
        if ctx.conditions.get(group.name, 1.0) > warn_condition
    )
    scales = {"k_l": k_l, "k_v": k_v}
    if k_a is not None:
        scales["k_a"] = k_a
    solution = GraphicalSolution(
        scene=scene,
        scales=scales,
        precision=precision,
        poses={body: ctx.poses[body] for body in scene.bodies},
        positions=positions,
        velocity_plan=velocity_plan,
        acceleration_plan=acceleration_plan,
        points=points,
        links=links,
        sliders=sliders,
        sines=dict(ctx.sines),
        conditions=dict(ctx.conditions),
        warnings=warnings,
        relative=relative,
        rotations=rotations,
        turns_with=dict(ctx.turns_with),
    )
    if check_scales and given:
        sizes = figure_sizes(solution)
        for key, field in given.items():
            if key in scales:
                check_scale(key, scales[key], sizes[key], what=_FIGURES[key], where=_where(scene), source=scene.source, field=field)
    return solution


_FIGURES = {"k_l": "the mechanism", "k_v": "the velocity plan", "k_a": "the acceleration plan"}


def figure_sizes(solution: GraphicalSolution) -> dict[str, float]:
    """Physical size of each figure [m, m/s, m/s²]: the larger side of its bounding box.

    The mechanism's points; a plan's pole, images and vector ends (times its scale).
    """
    sizes = {"k_l": extent(solution.positions.values())}
    for key, plan in (("k_v", solution.velocity_plan), ("k_a", solution.acceleration_plan)):
        if plan is not None:
            ends = [0j, *plan.images.values(), *(v.tail for v in plan.vectors), *(v.tip for v in plan.vectors)]
            sizes[key] = extent(ends) * plan.scale
    return sizes


def _where(scene: Scene) -> str:
    crank = isinstance(scene.driver, Crank)
    return "at " + position_text(crank, scene.driver.phi if crank else scene.driver.s)


def _refuse_unfit_early(scene: Scene, structure: Structure, ks: dict, given: dict, precision, arc_segments) -> None:
    """Refuse, before drawing, a given factor that certainly draws a figure larger than a sheet.

    Each figure is at least as large as something known before the
    construction (a bounding box's larger side is at least 1/√2 of the
    distance of two of its points): the mechanism as any one body, the
    velocity plan as the driver's velocity vector, the acceleration plan as
    the driver's acceleration vector.  Drawing at such a factor would
    overflow, so the range that fits comes from a construction at
    automatic scale factors.
    """
    bounds = {"k_l": max(diameter(list(body.points.values())) for body in scene.bodies.values())}
    driver = scene.driver
    if isinstance(driver, Crank):
        reach = _crank_reach(scene)
        bounds["k_v"] = abs(driver.omega) * reach
        bounds["k_a"] = math.hypot(driver.omega**2, driver.epsilon) * reach
    else:
        bounds["k_v"], bounds["k_a"] = abs(driver.velocity), abs(driver.acceleration)
    if not any(bounds[key] / math.sqrt(2) / ks[key] > DRAWN_LARGEST for key in given):
        return
    automatic = construct(
        replace(scene, scales=Scales(precision=precision)),
        structure,
        precision=precision,
        arc_segments=arc_segments,
        warn_condition=math.inf,
        check_scales=False,
    )
    sizes = figure_sizes(automatic)
    for key, field in given.items():
        if key in sizes:
            check_scale(key, ks[key], sizes[key], what=_FIGURES[key], where=_where(scene), source=scene.source, field=field)


def _read(image: complex, k: float, precision: float | None) -> complex:
    """The vector from the pole to *image* [mm], measured and scaled [SI]."""
    length = abs(image)
    if length == 0.0:
        return 0j
    return read_segment(length, precision) * k * (image / length)


def _extent(scene: Scene) -> float:
    """A size of the mechanism [m] before it is drawn: the largest extent of a body's points and lines."""
    size = 0.0
    for body in scene.bodies.values():
        zs = list(body.points.values()) + [line.origin for line in body.lines.values()]
        if body.is_frame:
            zs = zs + [0j]
        size = max(size, diameter(zs))  # O(n log n): a frame may carry thousands of points
    driver = scene.driver
    if not isinstance(driver, Crank):
        size = max(size, abs(driver.s))
    return size if size > 0 and math.isfinite(size) else 1.0


def _crank_reach(scene: Scene) -> float:
    """The crank's largest distance from its pivot to a point of it [m]."""
    body = scene.bodies[scene.driver.link]
    pivot = body.points[scene.driver.pivot]
    return max((abs(z - pivot) for z in body.points.values()), default=0.0)


def _provisional_v(ctx: Construction) -> float:
    """A provisional k_v from the driver's data (the plan is redrawn at the final k_v)."""
    driver = ctx.scene.driver
    if isinstance(driver, Crank):
        return round_scale(abs(driver.omega) * _crank_reach(ctx.scene))
    return round_scale(abs(driver.velocity))


def _provisional_a(ctx: Construction) -> float:
    """A provisional k_a from the driver's data and the velocity plan."""
    driver = ctx.scene.driver
    v = ctx.velocity.largest()
    estimate = v * v / ctx.size
    if isinstance(driver, Crank):
        estimate = max(estimate, math.hypot(driver.omega**2, driver.epsilon) * _crank_reach(ctx.scene))
    else:
        estimate = max(estimate, abs(driver.acceleration))
    return round_scale(estimate)


def _rest(ctx: Construction, plan: Sketch) -> None:
    """Frame points where moving links are pinned: their images are at the pole."""
    for name in ctx.scene.frame.points:
        if len(ctx.scene.bodies_with(name)) > 1:
            plan.place(plan.label(name), 0j, name)


def _images(ctx: Construction, plan: Sketch, motions, bodies) -> None:
    """Images of the bodies' other named points, by the similarity theorem."""
    for body in bodies:
        motion = motions[body]
        for name in ctx.scene.bodies[body].points:
            label = plan.label(name)
            if label not in plan.images:
                plan.place(label, motion.image_of(ctx.point(body, name)), name)


def _branch(scene: Scene, structure: Structure, group: Group, candidates, ctx: Construction):
    """The assembly the scene asks for: a sign ±1 or the candidate putting a point nearer a location."""
    if len(candidates) == 1:
        return candidates[0]
    hint = _hint(scene, structure, group)
    if hint is None:  # +1 in the order of the group's name (Group.orientation)
        return candidates[0] if group.orientation > 0 else candidates[1]
    name, value = hint
    if isinstance(value, int):
        return candidates[0] if value * group.orientation > 0 else candidates[1]
    body = next(b for b in scene.bodies_with(name) if b in group.links)
    local = scene.bodies[body].points[name]

    def distance(candidate):
        phi, origin = candidate[body]
        return abs(origin + cmath.exp(1j * phi) * local - value)

    return min(candidates, key=distance)


def _hint(scene: Scene, structure: Structure, group: Group):
    """The assembly entry that applies to *group*: the first that names a point of its links.

    The group's outer joints are excepted: a point the group's links share
    with a known body does not choose the group's branch.
    """
    outer = {joint.point for joint in (group.outer_i, group.outer_j) if joint.kind == "R"}
    for name, value in scene.assembly.items():
        if name in outer:
            continue
        if any(name in scene.bodies[link].points for link in group.links):
            return name, value
    return None
