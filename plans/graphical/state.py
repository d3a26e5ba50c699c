"""The construction in progress: the mechanism drawing and the two plans being drawn.

:class:`Construction` holds what is known so far (body poses, the images of
every known body on each plan) and what was measured (which plan vector
gives which ω, ε or sliding velocity), and turns it into the frozen
:class:`~plans.graphical.plan.Plan` and
:class:`~plans.graphical.plan.GraphicalSolution` at the end.

Plans are drawn first at a provisional scale k₀ (plan coordinate =
physical / k₀), chosen from the driver's data, because the automatic round
scale factor depends on the largest vector, which is only known once the plan
is finished; at the end the whole figure is redrawn at the final round k
(every coordinate × k₀ / k: a similarity, so every construction stays exact).

Body motion on a plan (the similarity theorem): the images of a link's
points form a figure similar to the link, so a link's images are fixed by one
image and the complex ratio ``q`` of the figure: image(X) = image(X₀) +
q·(X − X₀), X in metres.  On the velocity plan q = (b − a)/(B − A) for two
points A, B of the link with images a, b (= iω / k); on the acceleration plan
likewise (= (iε − ω²)/k).  Links that turn together (a block and its guide,
links joined by a welded sleeve) share q.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

from ..errors import AssemblyError, SingularPositionError
from ..limits import position_text
from ..scene import FRAME, Crank, Line, Prismatic, Scene
from . import geometry
from .plan import ConstructionLine, Plan, PlanVector, Step
from .scales import measure, read_segment

__all__ = ["Motion", "Vec", "Sketch", "Construction", "body_label", "image_label", "ZERO"]

#: A vector shorter than this fraction of the plan's largest vector is not drawn.
ZERO = 1e-9


def body_label(body: str, frame: str = "0") -> str:
    """A body's number in labels: the frame goes by *frame*, the scene's number for it
    (:attr:`plans.scene.Scene.frame_number`: 1 where the crank is 2, 0 where it is 1)."""
    return frame if body == FRAME else body


def image_label(point: str, body: str | None = None, primed: bool = False, frame: str = "0") -> str:
    """``"c"``, ``"c′"``, or the image of the point of *body* coinciding with it: ``"e5"``, ``"e5′"``
    (a point of the frame: ``"e1"`` or ``"e0"``, as *frame* numbers it)."""
    label = point.lower() + (body_label(body, frame) if body is not None else "")
    return label + ("′" if primed else "")


@dataclass
class Motion:
    """A body's images on one plan: image(X) = image + q·(X − anchor), X in m."""

    anchor: complex
    image: complex
    q: complex

    def image_of(self, point: complex) -> complex:
        return self.image + self.q * (point - self.anchor)


@dataclass
class Vec:
    """A vector being drawn on a plan (provisional units)."""

    tail: complex
    tip: complex
    kind: str
    label: str

    @property
    def delta(self) -> complex:
        return self.tip - self.tail


@dataclass
class _Step:
    group: str
    equations: tuple[str, ...]
    known: list[Vec]
    lines: list[tuple[complex, complex, str]]
    found: list[Vec]
    image: str
    sine: float = 1.0


class Sketch:
    """One plan being drawn at the provisional scale ``k0``.

    Parameters
    ----------
    kind : str
        ``"velocity"`` or ``"acceleration"``.
    k0 : float
        Provisional scale [(m/s)/unit or (m/s²)/unit].
    frame : str
        The frame's number in labels (``v_EE1`` or ``v_EE0``).
    """

    def __init__(self, kind: str, k0: float, frame: str = "0"):
        self.kind = kind
        self.k0 = k0
        #: the frame's number in labels (the scene's :attr:`~plans.scene.Scene.frame_number`)
        self.frame = frame
        self.pole = "p" if kind == "velocity" else "π"
        self.primed = kind == "acceleration"
        self.images: dict[str, complex] = {}
        self.named: dict[str, str] = {}  # image label -> named point it is the image of
        self.points: dict[str, tuple[str, str]] = {}  # image label -> (point, body number or "")
        self.components: list[Vec] = []
        self.steps: list[_Step] = []

    # -- drawing -------------------------------------------------------------

    def label(self, point: str, body: str | None = None) -> str:
        label = image_label(point, body, self.primed, self.frame)
        self.points.setdefault(label, (point, body_label(body, self.frame) if body is not None else ""))
        return label

    def place(self, label: str, at: complex, point: str | None = None) -> None:
        """Mark an image on the plan (``point``: the named mechanism point it belongs to)."""
        self.images[label] = at
        if point is not None:
            self.named[label] = point

    def component(self, tail: complex, tip: complex, kind: str, label: str) -> Vec:
        vec = Vec(tail, tip, kind, label)
        self.components.append(vec)
        return vec

    def absolute(self, point: str, body: str | None = None) -> Vec:
        """The vector from the pole to an image (not stored among the components)."""
        symbol = "v" if self.kind == "velocity" else "a"
        name = point + (body_label(body, self.frame) if body is not None else "")
        return Vec(0j, self.images[self.label(point, body)], "absolute", f"{symbol}_{name}")

    def size(self) -> float:
        """The plan's extent so far (provisional units): its largest coordinate or vector."""
        extent = max((abs(z) for z in self.images.values()), default=0.0)
        return max([extent] + [abs(v.delta) for v in self.components])

    def intersect(self, line1: tuple[complex, complex, str], line2: tuple[complex, complex, str], *, ctx: "Construction", group: str, image: str) -> tuple[complex, float]:
        """Intersect two construction lines (through, unit direction, label) of the plan."""
        try:
            return geometry.line_line(line1[0], line1[1], line2[0], line2[1], self.size())
        except geometry.Parallel as exc:
            raise SingularPositionError(
                f"{group}: the construction lines {line1[2]} and {line2[2]} of image {image} on the "
                f"{self.kind} plan are parallel (|sin| = {exc.sine:.2g}) at {ctx.where()}: a dead-centre position"
            ) from None

    def step(self, group: str, equations, known, lines, found, image: str, sine: float = 1.0) -> None:
        self.steps.append(_Step(group, tuple(equations), list(known), list(lines), list(found), image, sine))

    # -- the finished plan ------------------------------------------------------

    def link_images(self, scene: Scene) -> dict[str, tuple[str, ...]]:
        """Moving link -> the labels of its points' images on this plan (a point's own image
        where the link has one of its own at a slider, ``"e5"``, else the shared one, ``"b"``)."""
        out = {}
        for body in scene.links:
            labels = []
            for point in scene.bodies[body].points:
                own, shared = self.label(point, body), self.label(point)
                label = own if own in self.images else shared
                if label in self.images and label not in labels:
                    labels.append(label)
            # the link's own points at the sliders it carries (e5: the point of 5 under E)
            for point in scene.point_names:
                label = self.label(point, body)
                if label in self.images and label not in labels:
                    labels.append(label)
            if len(labels) >= 2:
                out[body] = tuple(labels)
        return out

    def finish(self, k: float, precision: float | None, links: dict[str, tuple[str, ...]] | None = None) -> Plan:
        """The plan redrawn at scale *k*, absolute vectors added, zero vectors left out.

        Every image has its absolute vector from the pole: a named point's (``v_D``) and
        that of a point of a link coinciding with a slider's pin (``v_A4``, ``a_E5``), which the
        construction reaches through components (v_A4 = v_C + v_A4C).
        """
        f = self.k0 / k
        absolute = []
        symbol = "v" if self.kind == "velocity" else "a"
        for label, point in self.named.items():
            absolute.append(Vec(0j, self.images[label], "absolute", f"{symbol}_{point}"))
        for label, z in self.images.items():
            if label not in self.named and label in self.points:
                point, body = self.points[label]
                absolute.append(Vec(0j, z, "absolute", f"{symbol}_{point}{body}"))
        everything = absolute + self.components
        largest = max((abs(v.delta) for v in everything), default=0.0)
        tiny = ZERO * largest

        drawn: dict[int, PlanVector | None] = {}  # each vector once: a component is in its step and in the list

        def frozen(vs):
            out = []
            for v in vs:
                key = id(v)
                if key not in drawn:
                    length = abs(v.tip - v.tail)
                    drawn[key] = PlanVector(v.tail * f, v.tip * f, v.kind, v.label, read_segment(length * f, precision) * k) if length > tiny else None
                if drawn[key] is not None:
                    out.append(drawn[key])
            return tuple(out)

        steps = tuple(
            Step(
                s.group,
                s.equations,
                frozen(s.known),
                tuple(ConstructionLine(t * f, d, lab) for t, d, lab in s.lines),
                frozen(s.found),
                s.image,
                s.sine,
            )
            for s in self.steps
        )
        images = {label: z * f for label, z in self.images.items()}
        points = {label: self.points[label] for label in images if label in self.points}
        return Plan(self.kind, k, self.pole, images, steps, frozen(absolute + self.components), dict(links or {}), points)

    def largest(self) -> float:
        """The largest vector the finished plan draws [physical units]: an image's absolute vector or a component."""
        everything = [abs(z) for z in self.images.values()] + [abs(v.delta) for v in self.components]
        return max(everything, default=0.0) * self.k0


@dataclass
class Rotation:
    """Where a link's ω (or ε) is read: a vector ⊥ segment tail→tip of the link."""

    vec: Vec
    tail: complex  # m
    tip: complex  # m


@dataclass
class Sliding:
    """Where a prismatic joint's readings are: vectors of body ``moving`` relative to ``reference``."""

    prismatic: Prismatic
    sign: int  # +1: moving is the slider, −1: moving is the guide
    direction: complex  # world unit vector of the guide
    v_rel: Vec | None = None
    a_rel: Vec | None = None
    coriolis: Vec | None = None


class Construction:
    """All that is known about the mechanism so far, and the two plans in progress."""

    def __init__(self, scene: Scene, arc_segments: int | None, k_l0: float):
        self.scene = scene
        self.arc_segments = arc_segments
        self.k_l0 = k_l0  # m/mm of the mechanism drawing
        self.poses: dict[str, tuple[float, complex]] = {FRAME: (0.0, 0j)}
        self.velocity: Sketch | None = None
        self.acceleration: Sketch | None = None
        self.v_motion: dict[str, Motion] = {FRAME: Motion(0j, 0j, 0j)}
        self.a_motion: dict[str, Motion] = {FRAME: Motion(0j, 0j, 0j)}
        # readings
        self.given: dict[str, tuple[float, float]] = {FRAME: (0.0, 0.0)}
        self.omega_from: dict[str, Rotation] = {}
        self.epsilon_from: dict[str, Rotation] = {}
        self.turns_with: dict[str, str] = {}
        self.sliding: dict[str, Sliding] = {}
        self.sines: dict[str, float] = {}
        self.conditions: dict[str, float] = {}
        self.size = 0.0  # the mechanism's extent [m], for the reach of ruler lines

    # -- the mechanism drawing ----------------------------------------------------

    def where(self) -> str:
        """The driver position, for messages."""
        driver = self.scene.driver
        crank = isinstance(driver, Crank)
        return position_text(crank, driver.phi if crank else driver.s)

    def world(self, body: str, local: complex) -> complex:
        """A point given in the body's own coordinates, on the mechanism [m]."""
        phi, origin = self.poses[body]
        return origin + cmath.exp(1j * phi) * local

    def point(self, body: str, name: str) -> complex:
        return self.world(body, self.scene.bodies[body].points[name])

    def line(self, line: Line) -> tuple[complex, complex]:
        """A body's line on the mechanism: (a point of it [m], unit direction)."""
        phi, _ = self.poses[line.body]
        return self.world(line.body, line.origin), cmath.exp(1j * (phi + line.angle))

    def local(self, body: str, name: str) -> complex:
        return self.scene.bodies[body].points[name]

    def drawn(self, z: complex) -> complex:
        """A point [m] on the mechanism drawing [mm] at the provisional k_l."""
        return z / self.k_l0

    def mm(self, length: float) -> float:
        return length / self.k_l0

    def metres(self, z):
        return z * self.k_l0

    def assembly_error(self, group: str, detail: str) -> AssemblyError:
        return AssemblyError(f"{group}: cannot assemble at {self.where()}: {detail}")

    # -- rotation shared by links ------------------------------------------------

    def omega(self, body: str) -> float:
        """ω of a known body [rad/s], from its velocity image figure (q·k = iω)."""
        return (self.v_motion[body].q * self.velocity.k0).imag

    # -- readings ---------------------------------------------------------------

    def readings(self, k_l: float, k_v: float, k_a: float | None, precision: float | None):
        """Links' ω, ε and sliders' v_rel, a_rel, Coriolis as measured on the finished plans."""
        fv = self.velocity.k0 / k_v
        fa = self.acceleration.k0 / k_a if self.acceleration is not None else None

        def along(vec: Vec | None, f: float, k: float, direction: complex) -> float:
            if vec is None:
                return 0.0
            length = read_segment(abs(vec.delta) * f, precision) * k
            return math.copysign(length, (vec.delta * direction.conjugate()).real)

        def rotation(source: Rotation, f: float, k: float) -> float:
            segment = source.tip - source.tail
            length = read_segment(abs(source.vec.delta) * f, precision) * k / abs(segment)
            return math.copysign(length, (source.vec.delta * segment.conjugate()).imag)

        links: dict[str, dict[str, float]] = {}
        for body in self.scene.links:
            root = body
            while root in self.turns_with:
                root = self.turns_with[root]
            if root in self.given:
                omega, epsilon = self.given[root]
            else:
                omega = rotation(self.omega_from[root], fv, k_v)
                epsilon = rotation(self.epsilon_from[root], fa, k_a) if fa is not None else None
            links[body] = {"omega": omega} if fa is None else {"omega": omega, "epsilon": epsilon}

        sliders: dict[str, dict[str, float | complex]] = {}
        for name, sl in self.sliding.items():
            entry: dict[str, float | complex] = {
                "s": self.travel(sl.prismatic, k_l, precision),
                "v_rel": sl.sign * along(sl.v_rel, fv, k_v, sl.direction),
            }
            if fa is not None:
                entry["a_rel"] = sl.sign * along(sl.a_rel, fa, k_a, sl.direction)
                if sl.coriolis is None:
                    entry["coriolis"] = 0j
                else:
                    c = sl.coriolis.delta
                    entry["coriolis"] = sl.sign * read_segment(abs(c) * fa, precision) * k_a * (c / abs(c) if c else 0j)
            sliders[name] = entry
        return links, sliders

    def read_from(self) -> tuple[dict[str, dict], dict[str, dict[str, tuple[str, str, float]]]]:
        """How each prismatic joint's relative motion is drawn, and which plan vector gives each link's ω, ε.

        Returns ``(relative, rotations)`` as :class:`~plans.graphical.plan.GraphicalSolution` documents them.
        """
        relative: dict[str, dict] = {}
        for name, sl in self.sliding.items():
            p = sl.prismatic
            moving, reference = (p.slider, p.guide) if sl.sign > 0 else (p.guide, p.slider)
            entry: dict = {"moving": moving, "reference": reference, "sign": sl.sign}
            if sl.v_rel is not None:
                relative_name = sl.v_rel.label.partition("_")[2]
                entry["v_rel"] = sl.v_rel.label
                if self.acceleration is not None:
                    entry["a_rel"] = f"a^r_{relative_name}"
                    entry["coriolis"] = f"a^k_{relative_name}"
            relative[name] = entry
        rotations: dict[str, dict[str, tuple[str, str, float]]] = {}
        for body in self.scene.links:
            root = body
            while root in self.turns_with:
                root = self.turns_with[root]
            if root in self.given:
                continue
            entry = {}
            for quantity, source in (("omega", self.omega_from.get(root)), ("epsilon", self.epsilon_from.get(root))):
                if source is not None and (quantity == "omega" or self.acceleration is not None):
                    entry[quantity] = (source.vec.label, source.vec.label.partition("_")[2], abs(source.tip - source.tail))
            if entry:
                rotations[body] = entry
        return relative, rotations

    def travel(self, prismatic: Prismatic, k_l: float, precision: float | None) -> float:
        """Relative travel s = (Q_s − Q_g)·u_g [m], measured on the mechanism drawing at *k_l*."""
        q_s, _ = self.line(self.scene.line(f"{prismatic.slider}.{prismatic.slider_line}"))
        q_g, u_g = self.line(self.scene.line(f"{prismatic.guide}.{prismatic.guide_line}"))
        s_mm = ((q_s - q_g) * u_g.conjugate()).real / k_l
        return measure(s_mm, precision) * k_l
