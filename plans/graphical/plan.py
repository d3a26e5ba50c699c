"""What a graphical construction produces, as data: plans, their vectors and steps.

Plan coordinates are millimetres on paper, with the pole at 0 and the
plan's x axis along the frame's x axis (counter-clockwise positive).  A
physical vector is ``k × (tip − tail)``, with k = k_v [(m/s)/mm] on the
velocity plan and k_a [(m/s²)/mm] on the acceleration plan.

Drawings read these objects and never compute kinematics; the construction
(:mod:`plans.graphical`) builds them and never draws.
"""

from __future__ import annotations

from dataclasses import dataclass, field

__all__ = ["KINDS", "PlanVector", "ConstructionLine", "Step", "Plan", "GraphicalSolution"]

#: The kinds of vector a plan can hold, as drawings distinguish them.
#: ``absolute`` runs from the pole to an image (a velocity or acceleration of a
#: point); ``relative`` is v_CB or a sliding velocity / relative acceleration
#: aʳ; ``normal``, ``tangential`` and ``coriolis`` are acceleration components.
KINDS = ("absolute", "relative", "normal", "tangential", "coriolis")

class _Drawable:
    """``.plot(ax=None)`` (returns the Axes) and ``.save(path)`` (one file, in the format of its suffix).

    The drawing functions are those :mod:`plans.notebook` registers in
    :data:`plans.display.DISPLAY`: this module never imports the drawing layer.
    """

    def plot(self, ax=None, *, lang: str = "en"):
        """Draw into *ax* (one data unit = 1 mm), or into a new true-to-scale figure; returns the Axes."""
        from ..display import display_function

        return display_function("plot")(self, ax, lang=lang)

    def save(self, path, *, lang: str = "en"):
        """Write the drawing (a plan, or a solution's sheet) to *path*: ``.svg`` true to scale, ``.pdf`` or ``.png``; returns the path."""
        from ..display import display_function

        return display_function("save")(self, path, lang=lang)


@dataclass(frozen=True)
class PlanVector:
    """A vector drawn on a plan.

    Attributes
    ----------
    tail, tip : complex
        Ends on the plan [mm].
    kind : str
        One of :data:`KINDS`.
    label : str
        The quantity's name as the textbook writes it: ``"v_CB"``, ``"a^n_CB"``,
        ``"a^t_CB"``, ``"a^k_E5E6"``, ``"a^r_E5E6"``, ``"v_C"``.
    value : float
        Its physical magnitude, |tip − tail| × k [m/s or m/s²], as measured
        (after drafting precision, if any).
    """

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
class ConstructionLine:
    """A line of known direction drawn through a known point of the plan [mm].

    ``direction`` is a unit complex number; ``label`` says why it has that
    direction (``"⊥ BC"``, ``"∥ rod"``).
    """

    through: complex
    direction: complex
    label: str


@dataclass(frozen=True)
class Step:
    """One construction: two vector equations solved for one unknown image.

    Attributes
    ----------
    group : str
        The structural group (``"RRR(3,4)"``) or ``"driver"``.
    equations : tuple[str, ...]
        The vector equations, as text (``"v_C = v_B + v_CB"``).
    known : tuple[PlanVector, ...]
        Components known in full, drawn before the intersection.
    lines : tuple[ConstructionLine, ...]
        The construction lines whose intersection is the image (empty for the
        driver's step).
    found : tuple[PlanVector, ...]
        The components read off after the intersection (tangential, relative).
    image : str
        Label of the image the step places (``"c"``, ``"c′"``).
    sine : float
        |sin| of the angle between the two construction lines: 1 is a sharp
        intersection, 0 a dead centre.  1.0 for the driver's step.
    """

    group: str
    equations: tuple[str, ...]
    known: tuple[PlanVector, ...]
    lines: tuple[ConstructionLine, ...]
    found: tuple[PlanVector, ...]
    image: str
    sine: float = 1.0


@dataclass(frozen=True)
class Plan(_Drawable):
    """A velocity or an acceleration plan.

    Attributes
    ----------
    kind : str
        ``"velocity"`` or ``"acceleration"``.
    scale : float
        k_v [(m/s)/mm] or k_a [(m/s²)/mm].
    pole : str
        ``"p"`` or ``"π"``.
    images : dict[str, complex]
        Image label -> position on the plan [mm].  Images of mechanism points
        are their names in lower case (``"a"``), primed on the acceleration
        plan (``"a′"``); the image of the point of link k that coincides with
        a slider's pin E is ``"e5"`` (``"e5′"``).  Points at rest sit at 0.
    steps : tuple[Step, ...]
        In construction order.
    vectors : tuple[PlanVector, ...]
        Everything to draw: absolute vectors from the pole and all components,
        zero-length ones left out.
    links : dict[str, tuple[str, ...]]
        Moving link -> labels of the images of its points on this plan (the
        image of a link's figure, similar to the link: ``"3": ("a", "b", "c")``,
        ``"5": ("b", "e5", "m")``).  Empty when not known.
    points : dict[str, tuple[str, str]]
        Image label -> (the mechanism point's name as the scene writes it, the
        number of the link it is a point of, or ``""``): ``"e5"`` -> ``("E", "5")``,
        ``"o2"`` of a point named O2 -> ``("O2", "")``.  How a drawing letters the
        image (:func:`plans.drawing.plan_drawing.image_text`).  Empty when not known.
    """

    kind: str
    scale: float
    pole: str
    images: dict[str, complex]
    steps: tuple[Step, ...]
    vectors: tuple[PlanVector, ...]
    links: dict[str, tuple[str, ...]] = field(default_factory=dict)
    points: dict[str, tuple[str, str]] = field(default_factory=dict)


@dataclass(frozen=True)
class GraphicalSolution(_Drawable):
    """The graphical method's answer at one driver position.

    Positions come from the compass construction of the mechanism at k_l;
    velocities and accelerations are *read from the plans*: measured length in
    mm (rounded to the drafting precision, if one is set) times the scale
    factor, divided by a link length where needed.

    Attributes
    ----------
    scene : plans.scene.Scene
    scales : dict[str, float]
        ``{"k_l": m/mm, "k_v": (m/s)/mm, "k_a": (m/s²)/mm}`` (k_a absent when
        only velocities are asked for).
    precision : float or None
        Drafting precision [mm] applied to every measured length.
    poses : dict[str, tuple[float, complex]]
        Body name -> (angle φ [rad], global position of its own origin [m]).
        A body point ``z`` (own coordinates) is at ``origin + exp(iφ)·z``.
    positions : dict[str, complex]
        Every named point [m].
    velocity_plan : Plan
    acceleration_plan : Plan or None
    points : dict[str, dict[str, complex]]
        Point name -> ``{"v": ..., "a": ...}`` read from the plans [SI].
    links : dict[str, dict[str, float]]
        Link name -> ``{"omega": rad/s, "epsilon": rad/s²}`` read from the plans.
    sliders : dict[str, dict[str, float | complex]]
        Prismatic joint name -> ``{"v_rel", "a_rel", "coriolis"}``; signs as
        in :class:`plans.scene.Prismatic`; coriolis is a vector (complex).
    sines : dict[str, float]
        Group name -> smallest |sin| between its construction lines.
    conditions : dict[str, float]
        Group name -> largest condition number (1 + |cos|)/|sin| of its
        intersections of construction lines (see :mod:`plans.limits`).
    warnings : tuple[plans.limits.NearDeadCentre, ...]
        Groups whose condition exceeds the construction's ``warn_condition``.
    relative : dict[str, dict]
        Prismatic joint name -> how its relative motion is drawn:
        ``{"moving": body, "reference": body, "sign": ±1, "v_rel": "v_E5E6",
        "a_rel": "a^r_E5E6", "coriolis": "a^k_E5E6"}``: the plan vectors
        (labels) are the motion of ``moving`` relative to ``reference``;
        ``sign`` is +1 when that is the slider relative to its guide (the
        convention of :attr:`sliders`), −1 when it is the guide relative to
        the slider (each drawn vector is then −1 × the slider's).
    rotations : dict[str, dict[str, tuple[str, str, float]]]
        Link name -> ``{"omega": (vector label, segment, length [m]),
        "epsilon": …}``: the plan vector whose length gives ω (ε) of the link,
        ω = |vector| × k_v / length, and the segment of the mechanism it is
        perpendicular to (``"BC"``).  Links that turn with another share its
        entry; a driver's given ω has none.
    turns_with : dict[str, str]
        Link name -> the body it turns with, as the construction took it: a
        block and its guide, a rod sliding in a sleeve (``"3": "4"``: ω₃ = ω₄,
        ε₃ = ε₄); the images of such a link on a plan are drawn with that
        body's ω and ε.  ``"frame"``: the link translates.
    travel : dict[str, tuple[float, float]]
        Drawing data, not part of the construction: ``"4.slot"`` ->
        (s_min, s_max) [m], the stretch of a line that what slides on it uses
        over the cycle (:func:`plans.sweep.line_travel`), given by the caller
        (``dataclasses.replace``) so that the scheme draws a slot or a guide
        over it; empty, they are drawn around the present place.
    cycle_poses : tuple
        Drawing data, not part of the construction: the mechanism over the
        cycle, one ``(positions, poses)`` pair per solved position of a sweep
        (as this solution's own ``positions`` and ``poses``), given by the
        caller (:func:`plans.positions.cycle_poses`) so that the scheme draws
        its frame the same way at every position (the hatched side of each
        guide, the direction of each ground support); empty, each drawing
        chooses for its own position.
    """

    scene: object
    scales: dict[str, float]
    precision: float | None
    poses: dict[str, tuple[float, complex]]
    positions: dict[str, complex]
    velocity_plan: Plan
    acceleration_plan: Plan | None
    points: dict[str, dict[str, complex]]
    links: dict[str, dict[str, float]]
    sliders: dict[str, dict[str, float | complex]]
    sines: dict[str, float] = field(default_factory=dict)
    conditions: dict[str, float] = field(default_factory=dict)
    warnings: tuple = ()
    relative: dict[str, dict] = field(default_factory=dict)
    rotations: dict[str, dict[str, tuple[str, str, float]]] = field(default_factory=dict)
    turns_with: dict[str, str] = field(default_factory=dict)
    travel: dict[str, tuple[float, float]] = field(default_factory=dict)
    cycle_poses: tuple = ()

    def sheet(self, *, lang: str = "en"):
        """The one-page sheet (mechanism, both plans, vector equations) as a matplotlib Figure."""
        from ..display import display_function

        return display_function("sheet")(self, lang=lang)

    def animate(self, positions: int = 36, *, lang: str = "en"):
        """The mechanism and its plans over the cycle from this position (position 0), at one set of scale
        factors for all *positions*: a :class:`plans.lecture.Animation`, which a notebook shows as the lecture
        page (``.save("page.html")``, ``"anim.gif"``, ``"anim.mp4"`` writes it)."""
        from ..display import display_function

        return display_function("animate")(self.scene, positions, lang=lang)
