"""The kinematics of any point of a link, read off the graphical plans (for the graphical force methods).

The graphical methods of the kinetostatics (Joukowski's lever, the force
plans) take their velocities and accelerations from the velocity and
acceleration plans of :func:`plans.graphical.construct`, never from the
analytic solution.  A point S of a link that has no image on the plans (a
centre of mass, a load's point) gets one by the similarity theorem: the
images of a link's points form a figure similar to the link,
``image(X) = image(X₀) + q·(X − X₀)``, with q found from two images of the
link already on the plan (or, for a link with one image only, a block,
from its ω and ε read off the plans: q = iω/k_v, (iε − ω²)/k_a).  A reading
is the measured length of the vector from the pole (rounded to the drafting
precision, if the construction has one) times the scale factor.
"""

from __future__ import annotations

import cmath

from ..errors import PlansError
from ..graphical.scales import measure
from ..graphical.state import image_label
from ..scene import FRAME, body_words

__all__ = ["PlanReadings"]


class PlanReadings:
    """Images and readings of the points of every body on a graphical solution's plans.

    Parameters
    ----------
    graphical : plans.graphical.GraphicalSolution
        With its acceleration plan (the inertia loads need it).
    """

    def __init__(self, graphical):
        self.graphical = graphical
        self.scene = graphical.scene
        if graphical.acceleration_plan is None:
            from ..errors import SceneError

            raise SceneError(
                "the kinetostatics needs the acceleration plan (inertia loads): remove accelerations = false from [compute]",
                self.scene.source,
                "compute.accelerations",
            )
        self.k_v = graphical.velocity_plan.scale
        self.k_a = graphical.acceleration_plan.scale
        self._figures: dict[tuple[str, str], tuple[complex, complex, complex]] = {}

    def world(self, body: str, z: complex) -> complex:
        """The point with own coordinates z [m] of the body, on the mechanism [m]."""
        phi, origin = self.graphical.poses[body]
        return origin + cmath.exp(1j * phi) * z

    def figure(self, body: str, kind: str = "velocity") -> tuple[complex, complex, complex]:
        """``(X₀ [m], image of X₀ [mm], q [mm/m])`` of the body's image figure on the plan of *kind*."""
        key = (body, kind)
        if key not in self._figures:
            self._figures[key] = self._figure(body, kind)
        return self._figures[key]

    def _figure(self, body: str, kind: str) -> tuple[complex, complex, complex]:
        plan = self.graphical.velocity_plan if kind == "velocity" else self.graphical.acceleration_plan
        if body == FRAME:
            return 0j, 0j, 0j
        primed = kind != "velocity"
        pairs: list[tuple[complex, complex]] = []
        for point in self.scene.bodies[body].points:
            own, shared = image_label(point, body, primed), image_label(point, None, primed)
            label = own if own in plan.images else shared if shared in plan.images else None
            if label is not None:
                pairs.append((self.graphical.positions[point] if label == shared else self.world(body, self.scene.bodies[body].points[point]), plan.images[label]))
        for point in self.scene.point_names:  # the body's own points under the pins of blocks it carries (e5)
            label = image_label(point, body, primed)
            if label in plan.images and point not in self.scene.bodies[body].points:
                pairs.append((self.graphical.positions[point], plan.images[label]))
        if not pairs:
            raise PlansError(f"{self.scene.source}: {body_words(body)} has no image on the {kind} plan to read its motion from")
        x0, i0 = pairs[0]
        far = max(pairs, key=lambda pair: abs(pair[0] - x0))
        if abs(far[0] - x0) > 0:
            return x0, i0, (far[1] - i0) / (far[0] - x0)
        reading = self.graphical.links[body]
        if kind == "velocity":
            return x0, i0, 1j * reading["omega"] / self.k_v
        return x0, i0, (1j * reading["epsilon"] - reading["omega"] ** 2) / self.k_a

    def image(self, body: str, z: complex, kind: str = "velocity") -> complex:
        """The image [mm] on the plan of *kind* of the body's point with own coordinates z [m] (similarity)."""
        x0, i0, q = self.figure(body, kind)
        return i0 + q * (self.world(body, z) - x0)

    def reading(self, image: complex, k: float) -> complex:
        """The vector from the pole to an image, measured (to the drafting precision) and times the scale factor."""
        length = abs(image)
        if length == 0:
            return 0j
        return measure(length, self.graphical.precision) * k * image / length

    def position(self, body: str, z: complex) -> complex:
        """r [m] of the body's point with own coordinates z, on the mechanism drawing."""
        return self.world(body, z)

    def velocity(self, body: str, z: complex) -> complex:
        """v [m/s] read off the velocity plan (the point's image by similarity)."""
        return self.reading(self.image(body, z, "velocity"), self.k_v)

    def acceleration(self, body: str, z: complex) -> complex:
        """a [m/s²] read off the acceleration plan (the point's image by similarity)."""
        return self.reading(self.image(body, z, "acceleration"), self.k_a)

    def omega(self, body: str) -> float:
        """ω [rad/s] of the body as read off the plans."""
        return self.graphical.links[body]["omega"]

    def epsilon(self, body: str) -> float:
        """ε [rad/s²] of the body as read off the plans."""
        return self.graphical.links[body]["epsilon"]
