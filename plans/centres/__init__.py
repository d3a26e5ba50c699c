"""Instant centres (Kennedy–Aronhold): a third, independent method for the velocities.

For a scene at its driver position: the bodies are placed by this method's
own position step (:mod:`plans.centres.pose`), every instant centre P_ij of
the n bodies — n(n−1)/2 of them — is found, the primary ones from the pairs
and the rest by Kennedy's theorem (:mod:`plans.centres.kennedy`), and ω of
every link and v of every named point follow from the centres
(:mod:`plans.centres.velocities`).  It shares the scene model and the
structure with :mod:`plans.analytic` and :mod:`plans.graphical` and nothing of
their kinematics; it never imports matplotlib.

Body numbers: the links keep the scene's names, the frame is 1 (the
workbooks' crank 2, coupler 3, …), or 0 when a link is already called 1.

>>> from plans.scene import load, example_path
>>> result = instant_centres(load(example_path("slider-crank")))
>>> [c.label for c in result.centres]
['P12', 'P13', 'P14', 'P23', 'P24', 'P34']
>>> result.centre("3", "frame").describe()
'(0.319851, 0.319851) m'
>>> round(result.points["B"].real, 4)
-16.0407
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..scene import Scene
from ..structure import Structure, find_structure
from .kennedy import Centre, CentreError, body_numbers, find_centres
from .pose import Pose, place_bodies, point_at
from .velocities import Motion, Reading, body_motions, point_bodies, point_velocities

__all__ = ["instant_centres", "InstantCentres", "Centre", "CentreError", "Motion", "Reading", "body_numbers"]


@dataclass(frozen=True)
class InstantCentres:
    """The instant centres of a scene at its position and the velocities they give.

    Attributes
    ----------
    scene : plans.scene.Scene
    numbers : dict[str, str]
        Body name → its number in the labels (frame first).
    poses : dict[str, tuple[float, complex]]
        Each body's (φ [rad], origin [m]) from this method's position step.
    positions : dict[str, complex]
        Every named point [m].
    centres : list[Centre]
        All n(n−1)/2 centres, P12, P13, …, lower number first.
    size : float
        The mechanism's size [m] (larger side of its bounding box).
    motions : dict[str, Motion]
        Each body's rotation about P_1j, or translation.
    links : dict[str, float]
        ω [rad/s] of every link, counter-clockwise positive.
    points : dict[str, complex]
        v [m/s] of every named point.
    carriers : dict[str, str]
        The body each point's v was found from (:func:`plans.centres.velocities.point_bodies`): the one that
        defines it, or with a reading a pin's other body where that one's P_1j lies off the drawing.
    """

    scene: Scene
    numbers: dict
    poses: dict
    positions: dict
    centres: list
    size: float
    motions: dict
    links: dict
    points: dict
    carriers: dict = field(default_factory=dict)

    @property
    def found_order(self) -> list[str]:
        """The links in the order their motions were found, the driver first: each after every link it was found
        from (:attr:`plans.centres.velocities.Motion.step`), the order a table of the steps lists them in."""
        return sorted(self.scene.links, key=lambda name: self.motions[name].step)

    def translates(self, body: str) -> bool:
        """Whether *body* translates at this instant: its centre with the frame P_1j lies at infinity (ω = 0)."""
        return body != "frame" and self.centre("frame", body).point is None

    def centre(self, a: str, b: str) -> Centre:
        """P_ab by the bodies' names (either order; ``"frame"`` for the frame)."""
        for centre in self.centres:
            if set(centre.bodies) == {a, b}:
                return centre
        raise KeyError(f"no centre of bodies {a!r} and {b!r}")


def _size(positions: dict[str, complex]) -> float:
    xs = [z.real for z in positions.values()]
    ys = [z.imag for z in positions.values()]
    size = max(max(xs) - min(xs), max(ys) - min(ys))
    return size if size > 0 else 1.0


def instant_centres(scene: Scene, structure: Structure | None = None, *, k_l: float | None = None,
                    precision: float | None = None, room: tuple[complex, complex] | None = None) -> InstantCentres:
    """Place the bodies, find every instant centre, and the velocities from them.

    Parameters
    ----------
    scene : plans.scene.Scene
        At its own driver position (``scene.at(position)`` for another).
    structure : plans.structure.Structure, optional
    k_l, precision : float, optional
        The drawing's scale [m/mm] and the drafting precision [mm]: with both, ω and v are what a student
        reads off the drawing — every length the rules use (P_1kP_jk, P_1jP_jk, P_1jM) measured in mm,
        rounded to *precision*, times k_l (:class:`plans.centres.velocities.Reading`); exact when either is
        None (``plans solve``, ``plans centres``; a handout asked for exact readings), as the graphical
        plans are exact without a precision.  ω of each link is read along the path of centres whose shortest
        length is longest (:func:`plans.centres.velocities.body_motions`).
    room : (complex, complex), optional
        With a reading, the part of the plane [m] (lower-left, upper-right) the drawing shows where it is: a path
        through a centre outside it (an arrow at the drawing's edge) is taken only where no other gives ω.

    Raises
    ------
    plans.errors.AssemblyError, plans.errors.SingularPositionError
        The mechanism cannot be placed at this position.
    CentreError
        A centre or a link's ω the construction cannot determine (a dead
        centre, coincident joints): names the centre or the link.
    """
    if structure is None:
        structure = find_structure(scene)
    poses: dict[str, Pose] = place_bodies(scene, structure)
    positions = {name: point_at(poses[scene.home_of(name)], scene.bodies[scene.home_of(name)].points[name]) for name in scene.point_names}
    size = _size(positions)
    centres = find_centres(scene, poses)
    read = Reading(k_l, precision, room) if k_l is not None and precision is not None else None
    motions = body_motions(scene, poses, centres, size, read)
    carriers = point_bodies(scene, centres, read)
    return InstantCentres(
        scene=scene,
        numbers=body_numbers(scene),
        poses=poses,
        positions=positions,
        centres=centres,
        size=size,
        motions=motions,
        links={name: motions[name].omega for name in scene.links},
        points=point_velocities(scene, poses, motions, read, carriers),
        carriers=carriers,
    )
