"""Joukowski's lever: the balancing moment from the velocity plan turned by 90°.

The construction (domain.md §11), on the graphical solution's own plans:

1. turn the velocity plan by 90° counter-clockwise about its pole p
   (:data:`TURN`): the image x of every point X goes to ``t = i·x`` [mm];
2. apply every load at the turned image of its point, parallel to itself:
   weights, inertia forces (−m·a_S with a_S read off the acceleration plan)
   and external forces; an inertia couple (or a given couple) M on a link
   becomes a pair of forces ±F at two points X₁, X₂ of the link,
   ``F = i·(X₂ − X₁)·M/|X₂ − X₁|²`` at X₂ and −F at X₁ (a block with one
   point only: its couple's moment on the lever, −M·ω/k_v, directly);
3. the lever is in equilibrium about the pole: Σ F·h + F_b·h_b = 0, each arm
   h measured on the drawing (to the drafting precision), with the balancing
   force F_b at the image of the crank pin A, perpendicular to OA (a linear
   driver: along its guide, at the image of its point);
4. M_b = F_b·l_OA.

Why it holds: on the turned plan the moment of F about the pole is
``cross(i·x, F) = −x·F = −F·v/k_v``, so the lever's equilibrium is the power
balance M_b·ω + Σ F·v + Σ M·ω = 0 drawn on paper.

Lengths on the lever are millimetres of the velocity plan, forces newtons,
moments about the pole N·mm; counter-clockwise positive.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import PlansError
from ..graphical.scales import measure
from ..graphical.state import image_label
from ..scene import FRAME, Crank, Scene
from .analytic import cross
from .loads import AppliedLoad, applied_loads
from .readings import PlanReadings

__all__ = ["TURN", "LeverForce", "LeverCouple", "JoukowskiLever", "LeverError", "joukowski_lever"]

#: The velocity plan is turned by +90° (counter-clockwise): t = TURN·x.
TURN = 1j


class LeverError(PlansError, ArithmeticError):
    """The lever cannot give the balancing moment here (the driver at rest: its image at the pole)."""


@dataclass(frozen=True)
class LeverForce:
    """A force on the lever.

    Attributes
    ----------
    name : str
        ``"G_3"``, ``"F_Φ3"``, ``"M_Φ3"`` (one force of the pair that stands
        for the couple), an external load's name, or ``"F_b"``.
    body : str
    kind : str
        The load's kind (:data:`plans.forces.loads.LOAD_KINDS`), or ``"balancing"``.
    image : str
        The label of the turned image it acts at (``"s3"``, ``"b"``).
    point : complex
        Where it acts on the turned plan [mm].
    force : complex
        The force [N] (parallel to the load on the mechanism).
    arm : float
        Its arm about the pole [mm] as measured (to the drafting precision),
        signed: positive when the force turns counter-clockwise about the pole.
    foot : complex
        The foot of the perpendicular from the pole to its line of action [mm].
    moment : float
        Its moment about the pole, |F|·arm [N·mm].
    """

    name: str
    body: str
    kind: str
    image: str
    point: complex
    force: complex
    arm: float
    foot: complex
    moment: float


@dataclass(frozen=True)
class LeverCouple:
    """A couple on the lever: that of a block with one point only, −M·ω/k_v [N·mm]."""

    name: str
    body: str
    kind: str
    couple: float
    moment: float


@dataclass(frozen=True)
class JoukowskiLever:
    """Joukowski's lever at one driver position, with what a drawing needs (it never solves).

    Attributes
    ----------
    scene : plans.scene.Scene
    k_v : float
        The velocity plan's scale [(m/s)/mm].
    precision : float or None
        Drafting precision [mm] of the measured arms (and of the readings of a_S, v).
    images : dict[str, complex]
        The turned images [mm]: every image of the velocity plan turned by
        :data:`TURN` about the pole (at 0), and those added for the loads'
        points (``"s3"``).
    links : dict[str, tuple[str, ...]]
        Link -> labels of its turned images (the velocity plan's figure of the link).
    loads : tuple[plans.forces.loads.AppliedLoad, ...]
        The loads from the graphical kinematics.
    forces : tuple[LeverForce, ...]
        Every force on the lever but the balancing one, the couples' pairs included.
    couples : tuple[LeverCouple, ...]
        Couples applied as such (blocks with one point only).
    balancing_force : LeverForce
        F_b at the image of the crank pin (⟂ OA), or of the linear driver's point (along its guide).
    balancing : float
        M_b [N·m] (= F_b·l_OA) on a crank, or F_b [N] on a linear driver.
    balancing_kind : str
        ``"moment"`` or ``"force"``.
    crank_length : float or None
        l_OA [m], the arm of F_b on the crank.
    """

    scene: Scene
    k_v: float
    precision: float | None
    images: dict[str, complex]
    links: dict[str, tuple[str, ...]]
    loads: tuple[AppliedLoad, ...]
    forces: tuple[LeverForce, ...]
    couples: tuple[LeverCouple, ...]
    balancing_force: LeverForce
    balancing: float
    balancing_kind: str
    crank_length: float | None


def joukowski_lever(graphical, k_v: float | None = None) -> JoukowskiLever:
    """Joukowski's lever on a graphical solution's velocity plan, its loads from its acceleration plan.

    Parameters
    ----------
    graphical : plans.graphical.GraphicalSolution
    k_v : float, optional
        The lever's own scale [(m/s)/mm]: the velocity plan redrawn at it (every image from the pole times
        k_v(plan)/k_v, the arms measured on the lever so drawn); by default the velocity plan's own.

    Raises
    ------
    LeverError
        When the driver's image lies at the pole (ω = 0 or v = 0): the lever
        has no arm for the balancing force.
    """
    scene = graphical.scene
    readings = PlanReadings(graphical)
    precision = graphical.precision
    plan = graphical.velocity_plan
    k_v = readings.k_v if k_v is None else float(k_v)
    if not (math.isfinite(k_v) and k_v > 0):
        raise LeverError(f"{scene.source}: the lever's scale k_v must be a positive number of (m/s)/mm, not {k_v!r}")
    redrawn = readings.k_v / k_v  # mm on the lever per mm of the velocity plan
    images = {label: TURN * z * redrawn for label, z in plan.images.items()}
    links = {link: tuple(labels) for link, labels in plan.links.items()}
    loads = applied_loads(scene, readings)

    def place(body: str, local: complex, point: str | None, fallback: str) -> tuple[str, complex]:
        """(label, turned image) of the body's point; a label added to the images when the plan lacks it."""
        turned = TURN * readings.image(body, local) * redrawn
        if point is not None:
            for label in (image_label(point, body), image_label(point)):
                if label in images and abs(images[label] - turned) <= 1e-9 * (1 + abs(turned)):
                    return label, images[label]
        label = point.lower() if point is not None else fallback
        while label in images and abs(images[label] - turned) > 1e-9 * (1 + abs(turned)):
            label += "′"
        images[label] = turned
        if body in links and label not in links[body]:
            links[body] = links[body] + (label,)
        return label, turned

    def on_lever(name, body, kind, label, point, force) -> LeverForce:
        size = abs(force)
        exact = cross(point, force) / size if size else 0.0
        arm = math.copysign(measure(abs(exact), precision), exact)
        foot = point - (point.real * force.real + point.imag * force.imag) / size**2 * force if size else point
        return LeverForce(name, body, kind, label, point, force, arm, foot, arm * size)

    forces: list[LeverForce] = []
    couples: list[LeverCouple] = []
    for load in loads:
        if not load.is_couple:
            if load.force == 0:
                continue  # a resistance off its working stroke, or at rest
            label, point = place(load.body, load.local, load.point, _centre_label(load))
            forces.append(on_lever(load.name, load.body, load.kind, label, point, complex(load.force)))
            continue
        if load.moment == 0:
            continue
        ends = _pair_points(scene, load.body)
        if ends is None:
            omega = readings.omega(load.body)
            couples.append(LeverCouple(load.name, load.body, load.kind, float(load.moment), -float(load.moment) * omega / k_v))
            continue
        (name1, z1), (name2, z2) = ends
        d = readings.world(load.body, z2) - readings.world(load.body, z1)
        pair = 1j * d * load.moment / abs(d) ** 2
        for name, z, force in ((name1, z1, -pair), (name2, z2, pair)):
            label, point = place(load.body, z, name, name.lower())
            forces.append(on_lever(load.name, load.body, load.kind, label, point, force))

    total = sum(f.moment for f in forces) + sum(c.moment for c in couples)
    driver = scene.driver
    if isinstance(driver, Crank):
        pin = _crank_pin(scene)
        pivot = graphical.positions[driver.pivot]
        crank = graphical.positions[pin] - pivot
        direction = 1j * crank / abs(crank)  # ⟂ OA: a positive F_b turns the crank counter-clockwise
        label, point = place(driver.link, scene.bodies[driver.link].points[pin], pin, pin.lower())
        length = abs(crank)
        kind = "moment"
    else:
        direction = complex(math.cos(scene.frame.lines[driver.guide].angle), math.sin(scene.frame.lines[driver.guide].angle))
        label, point = place(driver.link, scene.bodies[driver.link].points[driver.point], driver.point, driver.point.lower())
        length = None
        kind = "force"
    unit = on_lever("F_b", driver.link, "balancing", label, point, direction)
    if unit.arm == 0:
        raise LeverError(
            f"{scene.source}: Joukowski's lever has no arm for the balancing force: the image {label} of the driver "
            f"lies {'at' if abs(point) == 0 else 'on a line through'} the pole (the driver at rest), so it cannot balance the loads"
        )
    f_b = -total / unit.arm
    balancing_force = on_lever("F_b", driver.link, "balancing", label, point, f_b * direction)
    balancing = f_b * length if length is not None else f_b
    return JoukowskiLever(scene, k_v, precision, images, links, loads, tuple(forces), tuple(couples), balancing_force, balancing, kind, length)


def _centre_label(load: AppliedLoad) -> str:
    """The label of an unnamed point: ``"s3"`` for a centre of mass, the load's name in lower case otherwise."""
    if load.kind in ("weight", "inertia force", "inertia couple"):
        return f"s{'0' if load.body == FRAME else load.body}"
    return load.name.lower()


def _pair_points(scene: Scene, body: str) -> tuple[tuple[str, complex], tuple[str, complex]] | None:
    """The two named points of the body farthest apart, for a couple's pair of forces; None for a body of one point."""
    points = list(scene.bodies[body].points.items())
    best = None
    for k, (a, za) in enumerate(points):
        for b, zb in points[k + 1 :]:
            if best is None or abs(zb - za) > best[0]:
                best = (abs(zb - za), (a, za), (b, zb))
    if best is None or best[0] == 0:
        return None
    return best[1], best[2]


def _crank_pin(scene: Scene) -> str:
    """The crank's point the balancing force acts at: the joint farthest from the pivot (A)."""
    driver = scene.driver
    crank = scene.bodies[driver.link]
    pivot = crank.points[driver.pivot]
    joints = [p for p in crank.points if p != driver.pivot and len(scene.bodies_with(p)) > 1]
    candidates = joints or [p for p in crank.points if p != driver.pivot]
    return max(candidates, key=lambda p: (abs(crank.points[p] - pivot), -candidates.index(p)))
