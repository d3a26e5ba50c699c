"""Force plans: the kinetostatics of a mechanism constructed graphically, group by group.

This is the textbook's construction (domain.md §11), done as a draftsman does
it, from the graphical solution of the kinematics (never from the analytic
one; the two methods share only the scene):

1. **Loads.**  For every link with a mass: the image s′ of its centre S on
   the *acceleration plan*, by the similarity theorem from two images of the
   link (or, for a block with one image, from ε and ω read off the plans),
   and a_S = |πs′| × k_a measured; the weight G = m·g and the inertia force
   F_Φ = −m·a_S at S, the inertia couple M_Φ = −J_S·ε with ε read off the
   plan.  Given forces and couples as the scene states them; a resistance
   "against the velocity" of a point opposes the velocity read off the
   *velocity plan*.
2. **Groups, from the last to the driver.**  Each class-II group is drawn on
   its own force plan at a round scale μ_F [N/mm]:

   * RRR (``B ─(i)─ C ─(j)─ D``): each outer reaction split into Rⁿ (∥ the
     link's joints) and Rᵗ (⊥); Rᵗ_B from Σ M_C = 0 over link i, Rᵗ_D over
     link j, with the arms measured on the mechanism drawing; the polygon
     Rᵗ_B + loads(i) + loads(j) + Rᵗ_D + Rⁿ_D + Rⁿ_B = 0 closed by the lines
     ∥ DC and ∥ BC: their intersection.  The inner reaction from link i's
     polygon.
   * RRP: Rᵗ_B as above; the polygon Rᵗ_B + loads(i) + loads(j) + N + Rⁿ_B
     closed by the line ⊥ the guide and the line ∥ BC; the guide's force N
     acts ⊥ the guide through the point that Σ M_C = 0 over link j gives.
   * PRP: loads(i) + loads(j) closed by the two lines ⊥ the two guides; each
     normal force's point of action from its link's Σ M_C = 0.
   * RPP: link j's polygon loads(j) + N_ij + N_j closed by the lines ⊥ the
     inner and ⊥ the outer guide; the pin's reaction closes link i's polygon.
   * RPR: the sleeve's force N ⊥ the guide from Σ M_B over link i and Σ M_E
     over link j (two equations in its magnitude and its point of action);
     then each link's polygon closes with its pin's reaction.

   A group's reactions on the links it is attached to are loads on those
   links, applied where they act, when their own group's plan is drawn.
3. **The driver.**  A crank: the balancing moment M_b (a couple) from
   Σ M_O = 0 over the crank (arms measured), and the frame's reaction R_12
   closing the polygon of the crank's loads and the first group's reaction.  A linear driver: the polygon closed by the line ∥
   its guide (the balancing force) and the line ⊥ it (the guide's reaction).

Every reaction is *read off its plan*: its drawn length rounded to the
drafting precision (as the kinematic plans are read, see
:func:`plans.graphical.scales.measure`) times μ_F, its direction as drawn;
the value read is what the next group's plan uses.  With no precision the
construction is exact and the readings equal the analytic reactions to
round-off.

Sign conventions: SI units, forces as complex numbers Fx + i·Fy [N],
moments counter-clockwise positive [N·m].  R_xy is the force of body x on
body y (the frame is body 0 in labels); a prismatic pair's reaction is
perpendicular to its guide.

No matplotlib here: :mod:`plans.drawing.force_drawing` draws these objects.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass, field

from ..errors import SceneError, SingularPositionError
from ..graphical.plan import ConstructionLine
from ..graphical.scales import measure, round_scale
from ..limits import REFUSE_SINE, position_text
from ..scene import FRAME, Crank
from ..structure import Group, find_structure

__all__ = [
    "FORCE_KINDS",
    "PLAN_KINDS",
    "AppliedForce",
    "Couple",
    "PlanForce",
    "ForcePlan",
    "Reaction",
    "Centre",
    "ForcePlans",
    "construct_force_plans",
    "force_plans",
    "body_number",
    "pair_label",
]

#: The kinds of force acting on a link, as drawings distinguish them.
FORCE_KINDS = ("weight", "inertia", "external", "reaction", "balancing")
#: The kinds of vector on a force plan: a load (weight, inertia or given
#: force), a reaction read off the plan, its normal and tangential components,
#: the balancing force.
PLAN_KINDS = ("weight", "inertia", "external", "reaction", "normal", "tangential", "balancing")


# --- results ----------------------------------------------------------------------------


@dataclass(frozen=True)
class AppliedForce:
    """A force acting on a link.

    Attributes
    ----------
    label : str
        ``"G_3"``, ``"F_Φ3"``, ``"F_c"``, ``"R_23"``, ``"F_b"``.
    kind : str
        One of :data:`FORCE_KINDS`.
    body : str
        The link it acts on.
    at : complex
        A point of its line of action on the mechanism [m] (the point of
        application: S, a pin, a prismatic pair's point of action).
    force : complex
        Fx + i·Fy [N].
    """

    label: str
    kind: str
    body: str
    at: complex
    force: complex


@dataclass(frozen=True)
class Couple:
    """A couple on a link [N·m], counter-clockwise positive: ``"M_Φ3"`` (inertia), a given one, or ``"M_b"``."""

    label: str
    kind: str
    body: str
    moment: float


@dataclass(frozen=True)
class PlanForce:
    """A vector drawn on a force plan: ends [mm], kind (:data:`PLAN_KINDS`), label, magnitude [N] as read."""

    tail: complex
    tip: complex
    kind: str
    label: str
    value: float

    @property
    def length(self) -> float:
        """Drawn length [mm]."""
        return abs(self.tip - self.tail)


@dataclass(frozen=True)
class ForcePlan:
    """One group's (or the driver's) force plan.

    Attributes
    ----------
    group : str
        ``"RRP(3,4)"`` or ``"driver"``.
    links : tuple[str, ...]
    scale : float
        μ_F [N/mm].
    vectors : tuple[PlanForce, ...]
        In drawing order: the polygon's loads and found reactions (head to
        tail, the polygon closes), then the components and the inner reaction.
    lines : tuple[ConstructionLine, ...]
        The two lines of known direction whose intersection closes the
        polygon (empty where the polygon closes by itself).
    equations : tuple[str, ...]
        The vector equation of the polygon, then the moment equations used,
        as text.
    points : dict[str, complex]
        The lettered vertices of the polygon [mm] (``"a"``, ``"b"``, …).
    sine : float
        |sin| of the angle between the two closing lines (1.0 without them).
    found : tuple[str, ...]
        The labels of the reactions (and a linear driver's balancing force)
        read off this plan; the plan's other reactions are loads known before
        it (a later group's reactions on these links).
    precision : float or None
        The drafting precision [mm] its lengths are read to.
    """

    group: str
    links: tuple[str, ...]
    scale: float
    vectors: tuple[PlanForce, ...]
    lines: tuple[ConstructionLine, ...]
    equations: tuple[str, ...]
    points: dict[str, complex] = field(default_factory=dict)
    sine: float = 1.0
    found: tuple[str, ...] = ()
    precision: float | None = None


@dataclass(frozen=True)
class Reaction:
    """A joint's reaction as read off a force plan.

    ``label`` ``"R_23"`` is the force of body ``by`` on body ``on`` [N] at
    ``at`` [m] (a pin's centre, or a prismatic pair's point of action);
    ``joint`` is the pin's point name or the prismatic joint's name; ``kind``
    ``"R"`` or ``"P"``.
    """

    label: str
    joint: str
    kind: str
    by: str
    on: str
    at: complex
    force: complex


@dataclass(frozen=True)
class Centre:
    """A link's centre of mass: S [m], its image s′ on the acceleration plan [mm], a_S as read [m/s²]."""

    body: str
    at: complex
    image: complex
    acceleration: complex


@dataclass(frozen=True)
class ForcePlans:
    """The kinetostatics of one position, constructed graphically.

    Attributes
    ----------
    graphical : plans.graphical.GraphicalSolution
        The kinematics the construction read.
    precision : float or None
        Drafting precision [mm] of every length read (plans and arms).
    centres : dict[str, Centre]
    loads : tuple[AppliedForce, ...]
        Weights, inertia forces and given forces, per link.
    couples : tuple[Couple, ...]
        Inertia couples and given couples (and ``M_b`` on a crank).
    plans : tuple[ForcePlan, ...]
        In construction order: the last group first, the driver's plan last.
    reactions : dict[str, Reaction]
        Label -> reaction, as read.
    balancing_moment : float or None
        M_b [N·m] on a crank (counter-clockwise positive).
    balancing_force : complex or None
        F_b [N] along the guide of a linear driver; None for a crank (its M_b is a couple).
    balancing_at : complex or None
        Where F_b acts [m].
    """

    graphical: object
    precision: float | None
    centres: dict[str, Centre]
    loads: tuple[AppliedForce, ...]
    couples: tuple[Couple, ...]
    plans: tuple[ForcePlan, ...]
    reactions: dict[str, Reaction]
    balancing_moment: float | None
    balancing_force: complex | None
    balancing_at: complex | None

    @property
    def balancing(self) -> float:
        """M_b [N·m] on a crank, or F_b [N] along a linear driver's guide (as :class:`plans.forces.AnalyticForces` gives it)."""
        if self.balancing_moment is not None:
            return self.balancing_moment
        scene = self.graphical.scene
        u = scene.frame.lines[scene.driver.guide].direction
        return (self.balancing_force * u.conjugate()).real

    @property
    def balancing_kind(self) -> str:
        """``"moment"`` (a crank) or ``"force"`` (a linear driver)."""
        return "moment" if self.balancing_moment is not None else "force"

    def on(self, body: str) -> tuple[list[AppliedForce], list[Couple]]:
        """Everything acting on *body*: its loads, the reactions on it, F_b; and its couples."""
        forces = [f for f in self.loads if f.body == body]
        for r in self.reactions.values():
            if r.on == body:
                forces.append(AppliedForce(r.label, "reaction", body, r.at, r.force))
            elif r.by == body and pair_label(r.on, r.by, self.graphical.scene.frame_number) not in self.reactions:  # its other half, when not listed
                forces.append(AppliedForce(pair_label(r.on, r.by, self.graphical.scene.frame_number), "reaction", body, r.at, -r.force))
        if self.balancing_force is not None and self.graphical.scene.driver.link == body:
            forces.append(AppliedForce("F_b", "balancing", body, self.balancing_at, self.balancing_force))
        return forces, [c for c in self.couples if c.body == body]


def body_number(body: str, frame: str) -> str:
    """A body as labels write it: the frame by *frame*, the scene's :attr:`~plans.scene.Scene.frame_number`."""
    return frame if body == FRAME else body


def pair_label(by: str, on: str, frame: str) -> str:
    """``"R_23"``: the reaction of body *by* on body *on* (``"R_{rod,slider}"``-like with a comma for longer names)."""
    a, b = body_number(by, frame), body_number(on, frame)
    return f"R_{a}{b}" if len(a) == 1 and len(b) == 1 else f"R_{a},{b}"


def _sub(body: str) -> str:
    """A moving link's number as a subscript (the frame carries no loads of its own)."""
    return body


def _cross(a: complex, b: complex) -> float:
    """a × b (the z component) [units of a·b]."""
    return (a.conjugate() * b).imag


def _unit(z: complex) -> complex:
    r = abs(z)
    return z / r if r > 0 else 0j


# --- the construction ------------------------------------------------------------------------


class _Drafting:
    """The construction's measurements: arms on the mechanism drawing, lengths on the force plans."""

    def __init__(self, graphical, precision: float | None, mu_F: float | None):
        self.g = graphical
        self.k_l = graphical.scales["k_l"]
        self.precision = precision
        self.mu_F = mu_F

    def world(self, body: str, local: complex) -> complex:
        phi, origin = self.g.poses[body]
        return origin + cmath.exp(1j * phi) * local

    def length(self, metres: float) -> float:
        """A length on the mechanism drawing, measured [m]."""
        return measure(metres / self.k_l, self.precision) * self.k_l

    def moment(self, force: complex, at: complex, about: complex) -> float:
        """Moment of *force* acting at *at* about *about* [N·m]: ±|F|·h, the arm h measured on the drawing."""
        size = abs(force)
        if size == 0.0:
            return 0.0
        lever = _cross(at - about, force / size)
        return math.copysign(self.length(abs(lever)), lever) * size

    def read(self, vector: complex, mu: float) -> complex:
        """A vector of a force plan [N] read: its length rounded to the precision, times μ_F."""
        size = abs(vector)
        if size == 0.0:
            return 0j
        return measure(size / mu, self.precision) * mu * (vector / size)


def _images_of(plan, scene, body: str, positions) -> list[tuple[complex, complex]]:
    """(point [m], its image [mm]) for the body's named points that have images on *plan*."""
    out = []
    primed = plan.kind == "acceleration"
    for name in scene.bodies[body].points:
        own = name.lower() + body_number(body, scene.frame_number) + ("′" if primed else "")
        shared = name.lower() + ("′" if primed else "")
        label = own if own in plan.images else shared
        if label in plan.images:
            out.append((positions[name], plan.images[label]))
    return out


def _image(plan, scene, graphical, body: str, point: complex, key: str) -> complex:
    """The image [mm] of a point of *body* on *plan*, by the similarity theorem.

    From the two images of the body's points farthest apart; a body with one
    image (a block) moves with the ω (ε) read off the plans:
    image = image(P) + (iω)/k·(X − P) on the velocity plan, (iε − ω²)/k·(X − P)
    on the acceleration plan.
    """
    known = _images_of(plan, scene, body, graphical.positions)
    if not known:
        raise ValueError(f"link {body} has no image on the {plan.kind} plan")
    if len(known) >= 2:
        (p, pi), (q, qi) = max(((a, b) for a in known for b in known), key=lambda ab: abs(ab[0][0] - ab[1][0]))
        if abs(q - p) > 0:
            return pi + (qi - pi) * (point - p) / (q - p)
    p, pi = known[0]
    rates = graphical.links[body]
    omega = rates["omega"]
    ratio = 1j * omega if key == "v" else 1j * rates["epsilon"] - omega * omega
    return pi + ratio / plan.scale * (point - p)


def _read_image(image: complex, k: float, precision: float | None) -> complex:
    """The vector from the pole to an image, measured [SI]."""
    size = abs(image)
    if size == 0.0:
        return 0j
    return measure(size, precision) * k * (image / size)


def _applied(graphical, d: _Drafting):
    """Weights, inertia forces and couples, given loads (the scene's), read from the graphical solution."""
    scene = graphical.scene
    acc = graphical.acceleration_plan
    vel = graphical.velocity_plan
    k_a = graphical.scales.get("k_a")
    gravity = scene.gravity.vector if scene.gravity is not None else 0j
    loads: list[AppliedForce] = []
    couples: list[Couple] = []
    centres: dict[str, Centre] = {}
    for m in scene.masses.values():
        if m.mass == 0 and m.inertia == 0:
            continue
        s = _sub(m.body)
        at = d.world(m.body, m.centre)
        image = _image(acc, scene, graphical, m.body, at, "a")
        a_s = _read_image(image, k_a, d.precision)
        centres[m.body] = Centre(m.body, at, image, a_s)
        if m.mass and gravity:
            loads.append(AppliedForce(f"G_{s}", "weight", m.body, at, m.mass * gravity))
        if m.mass and a_s:
            loads.append(AppliedForce(f"F_Φ{s}", "inertia", m.body, at, -m.mass * a_s))
        epsilon = graphical.links[m.body]["epsilon"]
        if m.inertia and epsilon:
            couples.append(Couple(f"M_Φ{s}", "inertia", m.body, -m.inertia * epsilon))
    for load in scene.loads:
        if load.kind == "moment":
            if load.moment:
                couples.append(Couple(load.name, "external", load.body, load.moment))
            continue
        at = d.world(load.body, load.at)
        if load.kind == "force":
            force = load.force
        else:  # a resistance: against the velocity of its point read off the velocity plan
            v = _read_image(_image(vel, scene, graphical, load.body, at, "v"), graphical.scales["k_v"], d.precision)
            working = load.working is None or (v * load.working.conjugate()).real > 0
            force = -load.magnitude * _unit(v) if working else 0j
        if force:
            loads.append(AppliedForce(load.name, "external", load.body, at, force))
    return loads, couples, centres


class _Polygon:
    """A force polygon being drawn, in newtons (scaled to mm at the end)."""

    def __init__(self):
        self.vectors: list[tuple[complex, complex, str, str]] = []  # tail, tip [N], kind, label
        self.lines: list[tuple[complex, complex, str]] = []
        self.end = 0j

    def add(self, force: complex, kind: str, label: str) -> None:
        if force:
            self.vectors.append((self.end, self.end + force, kind, label))
            self.end += force

    def draw(self, tail: complex, tip: complex, kind: str, label: str) -> None:
        if abs(tip - tail) > 0:
            self.vectors.append((tail, tip, kind, label))


def _intersect(p1: complex, d1: complex, p2: complex, d2: complex, size: float, what: str) -> tuple[complex, float]:
    """Where the line (p1, d1) meets the line (p2, d2); |sin| of their angle."""
    sine = abs(_cross(d1, d2))
    if sine < REFUSE_SINE:
        raise SingularPositionError(what + f" (|sin| = {sine:.2g}): a dead-centre position, the reactions are unbounded")
    t = _cross(p2 - p1, d2) / _cross(d1, d2)
    return p1 + t * d1, sine


class _Builder:
    """Group by group, from the last to the driver."""

    def __init__(self, graphical, structure, d: _Drafting):
        self.g = graphical
        self.scene = graphical.scene
        self.structure = structure
        self.d = d
        self.loads, self.couples, self.centres = _applied(graphical, d)
        self.passed: dict[str, list[AppliedForce]] = {}  # reactions of later groups on a known link
        self.reactions: dict[str, Reaction] = {}
        self.plans: list[ForcePlan] = []
        self.current: tuple[str, ...] = ()
        crank = isinstance(self.scene.driver, Crank)
        self.where = position_text(crank, self.scene.driver.phi if crank else self.scene.driver.s)

    def label(self, by: str, on: str) -> str:
        """The reaction's label, the frame by the scene's number."""
        return pair_label(by, on, self.scene.frame_number)

    # -- what acts on a link -------------------------------------------------------------

    def forces_on(self, body: str) -> list[AppliedForce]:
        return [f for f in self.loads if f.body == body] + self.passed.get(body, [])

    def couple_on(self, body: str) -> float:
        return sum(c.moment for c in self.couples if c.body == body)

    def moment_about(self, body: str, about: complex) -> float:
        """Σ M about *about* of the link's loads and couples [N·m] (arms measured)."""
        return sum(self.d.moment(f.force, f.at, about) for f in self.forces_on(body)) + self.couple_on(body)

    def point(self, name: str) -> complex:
        return self.g.positions[name]

    def guide(self, prismatic) -> tuple[complex, complex]:
        """A prismatic pair's guide line on the mechanism: (a point of it [m], unit direction)."""
        line = self.scene.line(f"{prismatic.guide}.{prismatic.guide_line}")
        phi, _ = self.g.poses[prismatic.guide]
        return self.d.world(prismatic.guide, line.origin), cmath.exp(1j * (phi + line.angle))

    def react(self, label: str, joint: str, kind: str, by: str, on: str, at: complex, force: complex) -> None:
        self.reactions[label] = Reaction(label, joint, kind, by, on, at, force)
        if by != FRAME and by not in self.current:
            # a reaction on a link already known: a load on it when its own plan is drawn
            self.passed.setdefault(by, []).append(AppliedForce(self.label(on, by), "reaction", by, at, -force))

    def on_line(self, force: complex, origin: complex, u: complex, about: complex, moment: float) -> complex:
        """The point of action of a force ⊥ a guide line (origin, u) whose moment about *about* must be *moment*.

        The point is ``foot + e·u`` (foot: *about*'s foot on the line), with
        e·(u × F) = moment − (foot − about) × F; a zero force acts at the foot.
        """
        foot = origin + ((about - origin) * u.conjugate()).real * u
        size = abs(force)
        if size == 0.0:
            return foot
        e = (moment - _cross(foot - about, force)) / _cross(u, force)
        return foot + e * u

    # -- the plan ------------------------------------------------------------------------

    def finish(self, group: str, links, poly: _Polygon, equations, sine: float = 1.0) -> float:
        largest = max((abs(tip - tail) for tail, tip, *_ in poly.vectors), default=0.0)
        given = self.d.mu_F.get(group) if isinstance(self.d.mu_F, dict) else self.d.mu_F
        mu = given if given is not None else round_scale(largest)
        carried = {f.label for body in links for f in self.passed.get(body, [])}
        # a reaction carried from a plan before is the force read there (its value as found, not read again here)
        vectors = tuple(
            PlanForce(tail / mu, tip / mu, kind, label, abs(tip - tail) if label in carried else abs(self.d.read(tip - tail, mu)))
            for tail, tip, kind, label in poly.vectors
        )
        lines = tuple(ConstructionLine(through / mu, direction, label) for through, direction, label in poly.lines)
        points: dict[str, complex] = {}
        for v in vectors:
            for z in (v.tail, v.tip):
                if not any(abs(z - w) <= 1e-9 * max(1.0, abs(w)) for w in points.values()):
                    points[chr(ord("a") + len(points))] = z
        found = tuple(v.label for v in vectors if v.kind in ("reaction", "balancing") and v.label not in carried)
        self.plans.append(ForcePlan(group, tuple(links), mu, vectors, lines, tuple(equations), points, sine, found, self.d.precision))
        return mu

    def load_vectors(self, poly: _Polygon, body: str) -> list[str]:
        names = []
        for f in self.forces_on(body):
            poly.add(f.force, f.kind if f.kind in PLAN_KINDS else "reaction", f.label)
            if f.force:
                names.append(f.label)
        return names

    def size(self, poly: _Polygon) -> float:
        return max([abs(poly.end)] + [abs(t) for _, t, *_ in poly.vectors] + [1e-30])

    def singular(self, group: Group, lines: str) -> str:
        return f"{group.name}: the force plan's closing lines {lines} are parallel at {self.where}"

    # -- the groups --------------------------------------------------------------------------

    def group(self, group: Group) -> None:
        self.current = group.links
        getattr(self, "group_" + group.kind.lower())(group)

    def tangential(self, link: str, outer: str, inner: str) -> tuple[complex, float, str]:
        """Rᵗ on *link* at its outer pin, ⊥ the link's pins, from Σ M_inner = 0 over the link [N]; and the equation."""
        B, C = self.point(outer), self.point(inner)
        u = _unit(C - B)
        l_bc = self.d.length(abs(C - B))
        m = self.moment_about(link, C)
        # Rᵗ = t·(i·u) at B has moment about C: (B − C) × t·iu = −t·|BC|
        t = m / l_bc
        return t * 1j * u, l_bc, f"ΣM_{inner}({_sub(link)}) = 0: R^t·{outer}{inner} = Σ F·h"

    def group_rrr(self, group: Group) -> None:
        i, j = group.links
        ki, kj = group.outer_i.bodies[1], group.outer_j.bodies[1]
        b, c, dd = group.outer_i.point, group.inner.point, group.outer_j.point
        B, C, D = self.point(b), self.point(c), self.point(dd)
        rt_b, _, eq_b = self.tangential(i, b, c)
        rt_d, _, eq_d = self.tangential(j, dd, c)
        name_b, name_d, name_c = self.label(ki, i), self.label(kj, j), self.label(j, i)
        poly = _Polygon()
        poly.add(rt_b, "tangential", _sup(name_b, "t"))
        start_i = poly.end
        self.load_vectors(poly, i)
        end_i = poly.end
        self.load_vectors(poly, j)
        before_d = poly.end
        poly.add(rt_d, "tangential", _sup(name_d, "t"))
        u_bc, u_dc = _unit(C - B), _unit(C - D)
        x, sine = _intersect(poly.end, u_dc, 0j, u_bc, self.size(poly), self.singular(group, f"∥ {dd}{c} and ∥ {b}{c}"))
        poly.lines += [(poly.end, u_dc, f"∥ {dd}{c}"), (0j, u_bc, f"∥ {b}{c}")]
        poly.draw(poly.end, x, "normal", _sup(name_d, "n"))
        poly.draw(x, 0j, "normal", _sup(name_b, "n"))
        poly.draw(x, start_i, "reaction", name_b)
        poly.draw(before_d, x, "reaction", name_d)
        poly.draw(end_i, x, "reaction", name_c)
        mu = self.finish(group.name, group.links, poly, (
            f"{_sup(name_b, 't')} + Σ F({_sub(i)}) + Σ F({_sub(j)}) + {_sup(name_d, 't')} + {_sup(name_d, 'n')} + {_sup(name_b, 'n')} = 0",
            eq_b, eq_d, f"{name_c}: {name_b} + Σ F({_sub(i)}) + {name_c} = 0"), sine)
        self.react(name_b, b, "R", ki, i, B, self.d.read(start_i - x, mu))
        self.react(name_d, dd, "R", kj, j, D, self.d.read(x - before_d, mu))
        self.react(name_c, c, "R", j, i, C, self.d.read(x - end_i, mu))
        self.reactions[self.label(i, j)] = Reaction(self.label(i, j), c, "R", i, j, C, -self.reactions[name_c].force)

    def group_rrp(self, group: Group) -> None:
        i, j = group.links
        ki, kj = group.outer_i.bodies[1], group.outer_j.bodies[1]
        b, c = group.outer_i.point, group.inner.point
        B, C = self.point(b), self.point(c)
        origin, u = self.guide(group.outer_j.prismatic)
        rt_b, _, eq_b = self.tangential(i, b, c)
        name_b, name_n, name_c = self.label(ki, i), self.label(kj, j), self.label(i, j)
        poly = _Polygon()
        poly.add(rt_b, "tangential", _sup(name_b, "t"))
        start_i = poly.end
        self.load_vectors(poly, i)
        end_i = poly.end
        self.load_vectors(poly, j)
        end_j = poly.end
        u_bc, n = _unit(C - B), 1j * u
        x, sine = _intersect(end_j, n, 0j, u_bc, self.size(poly), self.singular(group, f"⊥ guide and ∥ {b}{c}"))
        poly.lines += [(end_j, n, "⊥ " + _guide_words(group.outer_j.prismatic)), (0j, u_bc, f"∥ {b}{c}")]
        poly.draw(end_j, x, "reaction", name_n)
        poly.draw(x, 0j, "normal", _sup(name_b, "n"))
        poly.draw(x, start_i, "reaction", name_b)
        poly.draw(x, end_i, "reaction", name_c)
        mu = self.finish(group.name, group.links, poly, (
            f"{_sup(name_b, 't')} + Σ F({_sub(i)}) + Σ F({_sub(j)}) + {name_n} + {_sup(name_b, 'n')} = 0",
            eq_b, f"ΣM_{c}({_sub(j)}) = 0: {name_n}·h = Σ F·h", f"{name_c}: {name_c} + Σ F({_sub(j)}) + {name_n} = 0"), sine)
        normal = self.d.read(x - end_j, mu)
        # link j about C: its loads, and N at its point of action (R_ij passes through C)
        at = self.on_line(normal, origin, u, C, -self.moment_about(j, C))
        self.react(name_b, b, "R", ki, i, B, self.d.read(start_i - x, mu))
        self.react(name_c, c, "R", i, j, C, self.d.read(end_i - x, mu))
        self.reactions[self.label(j, i)] = Reaction(self.label(j, i), c, "R", j, i, C, -self.reactions[name_c].force)
        self.react(name_n, group.outer_j.prismatic.name, "P", kj, j, at, normal)

    def group_prp(self, group: Group) -> None:
        i, j = group.links
        ki, kj = group.outer_i.bodies[1], group.outer_j.bodies[1]
        c = group.inner.point
        C = self.point(c)
        o_i, u_i = self.guide(group.outer_i.prismatic)
        o_j, u_j = self.guide(group.outer_j.prismatic)
        name_i, name_j, name_c = self.label(ki, i), self.label(kj, j), self.label(j, i)
        poly = _Polygon()
        self.load_vectors(poly, i)
        end_i = poly.end
        self.load_vectors(poly, j)
        end_j = poly.end
        x, sine = _intersect(end_j, 1j * u_j, 0j, 1j * u_i, self.size(poly), self.singular(group, "⊥ both guides"))
        poly.lines += [(end_j, 1j * u_j, "⊥ " + _guide_words(group.outer_j.prismatic)), (0j, 1j * u_i, "⊥ " + _guide_words(group.outer_i.prismatic))]
        poly.draw(end_j, x, "reaction", name_j)
        poly.draw(x, 0j, "reaction", name_i)
        poly.draw(end_i, x, "reaction", name_c)
        mu = self.finish(group.name, group.links, poly, (
            f"{name_i} + Σ F({_sub(i)}) + Σ F({_sub(j)}) + {name_j} = 0",
            f"ΣM_{c}({_sub(i)}) = 0, ΣM_{c}({_sub(j)}) = 0: the normal forces' points of action",
            f"{name_c}: {name_i} + Σ F({_sub(i)}) + {name_c} = 0"), sine)
        n_i, n_j = self.d.read(-x, mu), self.d.read(x - end_j, mu)
        at_i = self.on_line(n_i, o_i, u_i, C, -self.moment_about(i, C))
        at_j = self.on_line(n_j, o_j, u_j, C, -self.moment_about(j, C))
        self.react(name_i, group.outer_i.prismatic.name, "P", ki, i, at_i, n_i)
        self.react(name_j, group.outer_j.prismatic.name, "P", kj, j, at_j, n_j)
        self.react(name_c, c, "R", j, i, C, self.d.read(x - end_i, mu))
        self.reactions[self.label(i, j)] = Reaction(self.label(i, j), c, "R", i, j, C, -self.reactions[name_c].force)

    def group_rpp(self, group: Group) -> None:
        i, j = group.links
        ki, kj = group.outer_i.bodies[1], group.outer_j.bodies[1]
        b = group.outer_i.point
        B = self.point(b)
        inner, outer = group.inner.prismatic, group.outer_j.prismatic
        o_in, u_in = self.guide(inner)
        o_out, u_out = self.guide(outer)
        name_b, name_in, name_out = self.label(ki, i), self.label(i, j), self.label(kj, j)
        poly = _Polygon()
        self.load_vectors(poly, i)
        end_i = poly.end
        self.load_vectors(poly, j)
        end_j = poly.end
        x, sine = _intersect(end_j, 1j * u_out, end_i, 1j * u_in, self.size(poly), self.singular(group, "⊥ both guides"))
        poly.lines += [(end_j, 1j * u_out, "⊥ " + _guide_words(outer)), (end_i, 1j * u_in, "⊥ " + _guide_words(inner))]
        poly.draw(end_j, x, "reaction", name_out)
        poly.draw(x, end_i, "reaction", name_in)
        poly.draw(x, 0j, "reaction", name_b)
        mu = self.finish(group.name, group.links, poly, (
            f"{name_in} + Σ F({_sub(j)}) + {name_out} = 0",
            f"{name_b}: {name_b} + Σ F({_sub(i)}) + {self.label(j, i)} = 0",
            f"ΣM_{b}({_sub(i)}) = 0, ΣM({_sub(j)}) = 0: the normal forces' points of action"), sine)
        n_in = self.d.read(end_i - x, mu)  # on j
        n_out = self.d.read(x - end_j, mu)
        r_b = self.d.read(-x, mu)
        # link i about B: its loads and −n_in at the inner point of action
        at_in = self.on_line(-n_in, o_in, u_in, B, -self.moment_about(i, B))
        # link j about the inner point of action: its loads and n_out
        at_out = self.on_line(n_out, o_out, u_out, at_in, -self.moment_about(j, at_in))
        self.react(name_b, b, "R", ki, i, B, r_b)
        self.react(name_in, inner.name, "P", i, j, at_in, n_in)
        self.reactions[self.label(j, i)] = Reaction(self.label(j, i), inner.name, "P", j, i, at_in, -n_in)
        self.react(name_out, outer.name, "P", kj, j, at_out, n_out)

    def group_rpr(self, group: Group) -> None:
        i, j = group.links
        ki, kj = group.outer_i.bodies[1], group.outer_j.bodies[1]
        b, e = group.outer_i.point, group.outer_j.point
        B, E = self.point(b), self.point(e)
        p = group.inner.prismatic
        origin, u = self.guide(p)
        nu = 1j * u
        name_b, name_e, name_n = self.label(ki, i), self.label(kj, j), self.label(i, j)
        # N = n·ν on j at origin + s·u:  j: n·(a_E + s) = −M_j;  i: −n·(a_B + s) = −M_i
        m_i, m_j = self.moment_about(i, B), self.moment_about(j, E)
        a_b = _signed_foot(self.d, origin, u, B)
        a_e = _signed_foot(self.d, origin, u, E)
        if abs(a_e - a_b) < REFUSE_SINE * max(abs(a_b), abs(a_e), 1e-30):
            raise SingularPositionError(f"{group.name}: {b} and {e} have the same foot on the guide at {self.where}: the sleeve's force is unbounded")
        n = -(m_i + m_j) / (a_e - a_b)
        poly = _Polygon()
        self.load_vectors(poly, i)
        end_i = poly.end
        self.load_vectors(poly, j)
        end_j = poly.end
        x = end_i - n * nu  # N_ji = −N on i, drawn from the end of i's loads
        poly.draw(end_j, x, "reaction", name_e)
        poly.draw(x, 0j, "reaction", name_b)
        poly.draw(end_i, x, "reaction", self.label(j, i))
        mu = self.finish(group.name, group.links, poly, (
            f"{name_b} + Σ F({_sub(i)}) + Σ F({_sub(j)}) + {name_e} = 0",
            f"ΣM_{b}({_sub(i)}) = 0, ΣM_{e}({_sub(j)}) = 0: {name_n} ⊥ guide and its point of action",
            f"{name_b} + Σ F({_sub(i)}) + {self.label(j, i)} = 0"))
        normal = -self.d.read(x - end_i, mu)  # on j
        at = self.on_line(normal, origin, u, E, -m_j)
        self.react(name_b, b, "R", ki, i, B, self.d.read(-x, mu))
        self.react(name_e, e, "R", kj, j, E, self.d.read(x - end_j, mu))
        self.reactions[name_n] = Reaction(name_n, p.name, "P", i, j, at, normal)
        self.reactions[self.label(j, i)] = Reaction(self.label(j, i), p.name, "P", j, i, at, -normal)

    # -- the driver --------------------------------------------------------------------------

    def driver(self) -> tuple[float | None, complex | None, complex | None]:
        drv = self.scene.driver
        link = drv.link
        self.current = (link,)
        poly = _Polygon()
        names = self.load_vectors(poly, link)
        end = poly.end
        if isinstance(drv, Crank):
            # the balancing moment is a couple: it does not enter the polygon, the frame's reaction closes it
            O = self.point(drv.pivot)
            m_b = -self.moment_about(link, O)  # Σ M_O of everything on the crank, M_b included, is zero
            label = self.label(FRAME, link)
            poly.draw(poly.end, 0j, "reaction", label)
            self.finish("driver", (link,), poly, (
                " + ".join(names + [label]) + " = 0",
                f"ΣM_{drv.pivot}({_sub(link)}) = 0: M_b = −Σ M_{drv.pivot}(F)"))
            mu = self.plans[-1].scale
            self.react(label, drv.pivot, "R", FRAME, link, O, self.d.read(-end, mu))
            self.couples.append(Couple("M_b", "balancing", link, m_b))
            return m_b, None, None
        origin, u = self._linear_guide(drv)
        P = self.point(drv.point)
        x, sine = _intersect(end, u, 0j, 1j * u, self.size(poly), f"driver: the force plan's closing lines ∥ and ⊥ the guide are parallel at {self.where}")
        poly.lines += [(end, u, "∥ " + drv.guide), (0j, 1j * u, "⊥ " + drv.guide)]
        label = self.label(FRAME, link)
        poly.draw(end, x, "balancing", "F_b")
        poly.draw(x, 0j, "reaction", label)
        mu = self.finish("driver", (link,), poly, (" + ".join(names + ["F_b", label]) + " = 0",), sine)
        f_b = self.d.read(x - end, mu)
        normal = self.d.read(-x, mu)
        at = self.on_line(normal, origin, u, P, -self.moment_about(link, P))
        self.react(label, drv.guide, "P", FRAME, link, at, normal)
        return None, f_b, P

    def _linear_guide(self, drv) -> tuple[complex, complex]:
        line = self.scene.frame.lines[drv.guide]
        return line.origin, line.direction


def _signed_foot(d: _Drafting, origin: complex, u: complex, point: complex) -> float:
    """(origin − point) × ν with ν = i·u: where the foot of *point* lies along the line, measured [m]."""
    along = _cross(origin - point, 1j * u)
    return math.copysign(d.length(abs(along)), along)


def _sup(label: str, sup: str) -> str:
    """``"R_23"`` → ``"R^t_23"``."""
    head, _, sub = label.partition("_")
    return f"{head}^{sup}_{sub}"


def _guide_words(prismatic) -> str:
    return f"{prismatic.guide_line}"


def construct_force_plans(graphical, *, structure=None, precision: float | None = ..., mu_F: float | dict[str, float] | None = None) -> ForcePlans:
    """Construct the force plans of every group and of the driver at the graphical solution's position.

    Parameters
    ----------
    graphical : plans.graphical.GraphicalSolution
        With its acceleration plan: the accelerations are read off it.  Its
        scene's masses, gravity and loads are the loads.
    structure : plans.structure.Structure, optional
    precision : float or None, optional
        Drafting precision [mm] of every length read (the force plans and the
        arms on the mechanism drawing); by default the graphical solution's.
        None: exact.
    mu_F : float or dict, optional
        One force scale [N/mm] for every plan, or one per plan (group name, or
        ``"driver"`` -> N/mm); a plan without one gets the round value (1, 2,
        2.5 or 5 × 10ⁿ) that draws its largest vector 60–120 mm long.

    Returns
    -------
    ForcePlans

    Raises
    ------
    plans.errors.SingularPositionError
        Two closing lines are parallel (a dead centre: the reactions are unbounded).
    """
    if precision is ...:
        precision = graphical.precision
    for value in (mu_F.values() if isinstance(mu_F, dict) else [mu_F]):
        if value is not None and not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
            raise ValueError(f"mu_F must be a positive number of N/mm, got {value!r}")
    if structure is None:
        structure = find_structure(graphical.scene)
    d = _Drafting(graphical, precision, mu_F)
    if graphical.acceleration_plan is None:
        scene = graphical.scene
        raise SceneError("force plans need the acceleration plan, and the scene asks for velocities only", scene.source, "compute")
    builder = _Builder(graphical, structure, d)
    for group in reversed(structure.groups):
        builder.group(group)
    m_b, f_b, at = builder.driver()
    return ForcePlans(
        graphical=graphical,
        precision=precision,
        centres=builder.centres,
        loads=tuple(builder.loads),
        couples=tuple(builder.couples),
        plans=tuple(builder.plans),
        reactions=dict(builder.reactions),
        balancing_moment=m_b,
        balancing_force=f_b,
        balancing_at=at,
    )


def force_plans(graphical, *, precision: float | None = ..., mu_F: float | dict[str, float] | None = None) -> ForcePlans:
    """:func:`construct_force_plans` (the name :mod:`plans.forces.compare` calls)."""
    return construct_force_plans(graphical, precision=precision, mu_F=mu_F)
