"""The driver's motion over a cycle: one law, the positions of a cycle, its time, strokes and limits.

A scene gives the driver's position, rate and acceleration at one instant
(``plans solve``).  A cycle is a motion in time, and its driver follows one
law (:class:`DriverLaw`), stated on every cycle output:

* ``"constant"`` (the default; the course project's assumption): ω = ω₀,
  ε = 0 (a linear driver: v = v₀, a = 0); t = (φ − φ_first)/ω₀.
* ``"uniform"``: uniformly accelerated from the scene's instant,
  ω² = ω₀² + 2ε(φ − φ₀), ε constant, t = (ω − ω_first)/ε (a linear driver:
  v² = v₀² + 2a(s − s₀)).  A law under which the driver stops (ω² ≤ 0) inside
  the range asked for is refused, naming ``driver.law``.
* ``"harmonic"``: a **rocker input**, a crank that cannot turn fully (a
  non-Grashof four-bar's input), swings between its two limit positions
  φ_lo, φ_hi and reverses there.  φ = φ_c − A·cos ψ with the phase ψ = Ωt,
  φ_c the middle of the swing and A its half; ω = AΩ·sin ψ, ε = AΩ²·cos ψ:
  ω passes through zero at the limits and every curve stays smooth there.
  (A position that would fall exactly on a limit, where the limiting group
  lines up and its rates are 0/0, is taken :data:`LIMIT_STEP` of phase
  after it, its time to match.)
  Ω is chosen so that |ω| at the scene's angle is the scene's |ω|; the sign
  of the scene's ω says which way it swings at its instant.  At a limit the
  group that limits the crank lines up (a dead centre of its own) and the
  smooth motion carries it over to its other assembly branch: the swing
  back runs on the other branch of that group (one closed loop of the
  linkage, as a non-Grashof four-bar moves).  This is the default for a
  crank that cannot turn fully; ``"constant"`` is refused for it (constant
  |ω| reversing sign would need an infinite ε at the limits).

Positions of a cycle (:func:`driver_cycle`) are numbered in the sense of
the driver's motion, starting by default at an extreme position of the
**output link** (the start of its working stroke, the slower of its two
strokes), as the course project numbers them; ``start="scene"`` starts at
the scene's own position instead.  A crank's positions are equally spaced
in angle over its turn, a rocker input's equally spaced in time over its
swing and back, a linear driver's over its ``stroke`` (run in the sense of
its velocity).

:func:`strokes` finds the output's extreme positions: stroke H [m] (a
slider) or swing ψ [rad] (a rocker), the crank angle θ between the extreme
positions and K = (180° + θ)/(180° − θ).  :func:`four_bar_loops` names the
Grashof class of every four-bar loop.

Computation only (numpy and the analytic solver); nothing is drawn here.

>>> import plans
>>> from plans.motion import driver_cycle
>>> scene = plans.load(plans.example_path("four-bar"))
>>> cycle = driver_cycle(scene, 12)
>>> cycle.law.kind, len(cycle), float(cycle.t[0])
('constant', 12, 0.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .errors import PlansError, SceneError
from .scene import FRAME, Crank, Scene

__all__ = [
    "LAWS",
    "DriverLaw",
    "driver_law",
    "Limits",
    "crank_limits",
    "four_bar_limits",
    "Grashof",
    "grashof",
    "FourBarLoop",
    "four_bar_loops",
    "Output",
    "output_link",
    "Cycle",
    "driver_cycle",
    "cycle_at",
    "Strokes",
    "strokes",
    "cycle_summary",
    "cycle_text",
]

#: The laws a driver may follow over a cycle.
LAWS = ("constant", "uniform", "harmonic")

#: Positions of the dense turn on which limits and extremes are first looked for (then refined).
SEARCH_STEPS = 720
#: Bisection steps of a limit or an extreme (2π / 2^60 is far below round-off).
REFINE_STEPS = 60

_TURN = 2 * math.pi


def _is_crank(scene: Scene) -> bool:
    return isinstance(scene.driver, Crank)


def _rates(scene: Scene) -> tuple[float, float, float]:
    """(x₀, rate₀, acceleration) of the scene's driver: φ [rad], ω, ε or s [m], v, a."""
    d = scene.driver
    if isinstance(d, Crank):
        return float(d.phi), float(d.omega), float(d.epsilon)
    return float(d.s), float(d.velocity), float(d.acceleration)


# --- limits of a crank that cannot turn fully ------------------------------------------


@dataclass(frozen=True)
class Limits:
    """The two limit positions of a crank that cannot turn fully (a rocker input).

    Attributes
    ----------
    lo, hi : float
        Crank angles [rad] of the limits, lo < hi < lo + 2π; the scene's
        angle lies between them (as ``lo < φ₀ + 2πk < hi``).
    group : str
        The group that limits the crank (it lines up at both limits).
    closed_form : bool
        Found in closed form (a four-bar loop: crank, coupler, rocker,
        frame), else by bisection on where the solver assembles.
    """

    lo: float
    hi: float
    group: str
    closed_form: bool = False

    @property
    def swing(self) -> float:
        """hi − lo [rad]."""
        return self.hi - self.lo


def four_bar_limits(crank: float, ground: float, coupler: float, rocker: float, ground_angle: float = 0.0) -> list[float]:
    """Limit angles [rad] of the crank of a four-bar in closed form: where coupler and rocker line up.

    The crank OA (length *crank*) turns about O; the rocker turns about D,
    ``|OD|`` = *ground* at angle *ground_angle* from +x.  The coupler AB and
    the rocker DB line up when ``|AD| = coupler + rocker`` (extended) or
    ``|AD| = |coupler − rocker|`` (folded)::

        |AD|² = r² + d² − 2rd·cos(φ − φ_D)   ⇒   cos(φ − φ_D) = (r² + d² − L²) / (2rd)

    Returns the angles φ of OA in [φ_D − π, φ_D + π) where that happens
    (an empty list for a crank that turns fully).

    >>> [round(math.degrees(x), 2) for x in four_bar_limits(0.1, 0.7, 0.45, 0.2)]
    [-56.39, 56.39]
    """
    out = []
    r, d = float(crank), float(ground)
    for length in (coupler + rocker, abs(coupler - rocker)):
        c = (r * r + d * d - length * length) / (2 * r * d)
        if -1 < c < 1:
            a = math.acos(c)
            out += [ground_angle - a, ground_angle + a]
    return sorted(out)


def crank_limits(scene: Scene, structure=None) -> Limits | None:
    """The limit positions of the scene's crank, or None if it turns fully (or the driver is linear).

    A crank turns fully when the mechanism assembles at every angle of a turn
    (dead centres it crosses aside, and the parallel guides of a PRP or RPP
    group, where a pin runs off to infinity: no limit position to turn back
    at).  Otherwise it swings within the interval
    of angles around the scene's own where it assembles; each end is found in
    closed form when the group that fails there closes a four-bar loop with
    the crank and the frame (:func:`four_bar_limits`), else by bisection on
    where the analytic solver assembles.

    >>> import plans
    >>> limits = crank_limits(plans.load(plans.example_path("rocker-limit")))
    >>> round(math.degrees(limits.lo), 2), round(math.degrees(limits.hi), 2), limits.group
    (-56.39, 56.39, 'RRR(3,4)')
    """
    if not _is_crank(scene):
        return None
    from .analytic import solve
    from .structure import find_structure

    structure = structure or find_structure(scene)
    phi0 = float(scene.driver.phi)
    grid = phi0 + np.linspace(0.0, _TURN, SEARCH_STEPS, endpoint=False)
    sweep = solve(scene, grid, structure, allow_partial=True, warn_condition=math.inf)
    # positions where some group does not assemble (its sine is NaN there); a dead centre the crank passes
    # through (refused on a grid position, assembled on both sides) does not stop it
    valid = np.ones(SEARCH_STEPS, dtype=bool)
    for group in structure.groups:
        valid &= np.isfinite(np.asarray(sweep.sines[group.name], dtype=float))
    if valid.all():
        return None
    if not valid[0]:
        return None  # the scene's own position does not assemble: solve reports that
    # the run of assembled positions around the scene's own (index 0), on the cyclic grid
    up = int(np.argmin(valid))  # the first position not assembled going forward
    down = SEARCH_STEPS - 1 - int(np.argmin(valid[::-1]))  # the last one (the first going backward)
    failing = _failing_group(sweep, up)
    if structure.groups and next(g for g in structure.groups if g.name == failing).kind not in ("RRR", "RRP", "RPR"):
        # a PRP or RPP whose guides turn parallel: its pin runs off to infinity, the crank has no limit position to
        # turn back at (a sweep reports the loss of assembly there)
        return None

    def assembles(phi: float) -> bool:
        one = solve(scene, [phi], structure, allow_partial=True, warn_condition=math.inf)
        return bool(one.valid[0])

    def edge(inside: float, outside: float) -> float:
        for _ in range(REFINE_STEPS):
            middle = 0.5 * (inside + outside)
            if assembles(middle):
                inside = middle
            else:
                outside = middle
        return inside

    brackets = ((float(grid[down + 1]) - _TURN if down + 1 < SEARCH_STEPS else phi0, float(grid[down]) - _TURN),
                (float(grid[up - 1]), float(grid[up])))
    closed = _closed_form_limits(scene, structure, failing, brackets)
    if closed is not None:
        return Limits(closed[0], closed[1], failing, True)
    lo, hi = (edge(inside, outside) for inside, outside in brackets)
    return Limits(lo, hi, failing)


def _failing_group(sweep, k: int) -> str:
    """The first group (in solving order) not assembled at grid position k."""
    for group in sweep.structure.groups:
        if not np.isfinite(np.asarray(sweep.sines[group.name])[k]):
            return group.name
    return sweep.structure.groups[0].name if sweep.structure.groups else "?"


def _closed_form_limits(scene: Scene, structure, name: str, brackets) -> tuple[float, float] | None:
    """The closed-form limits (:func:`four_bar_limits`) when group *name* is an RRR closing a four-bar loop with
    the crank, each the one inside its bracket (inside, outside) of grid positions the solver found; else None."""
    for loop in four_bar_loops(scene, structure):
        if loop.group != name or loop.input != scene.driver.link or loop.pivot != scene.driver.pivot:
            continue
        d = scene.driver
        own = scene.bodies[d.link].points
        a = own[loop.input_joint] - own[d.pivot]  # OA in the crank's own coordinates
        O = scene.frame.points[d.pivot]
        D = scene.frame.points[loop.ground_joint]
        angles = four_bar_limits(abs(a), abs(D - O), loop.coupler, loop.rocker, math.atan2((D - O).imag, (D - O).real))
        shift = math.atan2(a.imag, a.real)  # φ of the crank = angle of OA − the own angle of A
        out = []
        for inside, outside in brackets:
            lo, hi = sorted((inside, outside))
            found = [x + _TURN * k for c in angles for k in range(-2, 3) for x in (c - shift,) if lo <= x + _TURN * k <= hi]
            if len(found) != 1:
                return None
            out.append(found[0])
        return out[0], out[1]
    return None


# --- Grashof ---------------------------------------------------------------------------


@dataclass(frozen=True)
class Grashof:
    """The Grashof class of a four-bar loop from its four lengths [m].

    Attributes
    ----------
    kind : str
        ``"crank-rocker"``, ``"double-crank"``, ``"double-rocker"`` (Grashof:
        s + l < p + q), ``"change point"`` (s + l = p + q, to a relative
        1e-9) or ``"triple-rocker"`` (non-Grashof: s + l > p + q).
    grashof : bool
        s + l ≤ p + q.
    turning : tuple[str, ...]
        The roles of the links that can turn fully relative to the frame:
        ``"input"``, ``"output"``, ``"coupler"`` (empty for a triple-rocker).
    s_plus_l, p_plus_q : float
        The shortest plus the longest length, the other two [m].
    """

    kind: str
    grashof: bool
    turning: tuple[str, ...]
    s_plus_l: float
    p_plus_q: float


def grashof(ground: float, input: float, coupler: float, output: float) -> Grashof:
    """The Grashof class of a four-bar: frame, input (driven side link), coupler, output (the other side link) [m].

    With s the shortest and l the longest length, p, q the others: if
    s + l < p + q the shortest link turns fully relative to the others —
    shortest the frame: double-crank (both side links turn fully); a side
    link: crank-rocker (that link is the crank); the coupler: double-rocker
    (the coupler turns fully).  s + l = p + q is a change point (the same
    links turn fully, through a flat position where the branch is not
    defined).  s + l > p + q: triple-rocker, no link turns fully.

    >>> grashof(0.22, 0.08, 0.25, 0.2).kind
    'crank-rocker'
    >>> grashof(0.7, 0.1, 0.45, 0.2).kind, grashof(0.7, 0.1, 0.45, 0.2).turning
    ('triple-rocker', ())
    """
    lengths = {"frame": float(ground), "input": float(input), "coupler": float(coupler), "output": float(output)}
    values = sorted(lengths.values())
    s_l, p_q = values[0] + values[3], values[1] + values[2]
    shortest = min(lengths, key=lambda k: (lengths[k], ("input", "output", "frame", "coupler").index(k)))
    if s_l > p_q * (1 + 1e-9):
        return Grashof("triple-rocker", False, (), s_l, p_q)
    turning = {"frame": ("input", "output"), "input": ("input",), "output": ("output",), "coupler": ("coupler",)}[shortest]
    if abs(s_l - p_q) <= 1e-9 * p_q:
        return Grashof("change point", True, turning, s_l, p_q)
    kind = {"frame": "double-crank", "input": "crank-rocker", "output": "crank-rocker", "coupler": "double-rocker"}[shortest]
    return Grashof(kind, True, turning, s_l, p_q)


@dataclass(frozen=True)
class FourBarLoop:
    """A four-bar loop of the mechanism: an RRR group whose outer joints are on a link pivoted to the frame and on the frame.

    Attributes
    ----------
    group : str
        The RRR group's name.
    input, coupler_link, output : str
        The link pivoted to the frame that carries the group (the crank, or
        a rocker of an earlier group), the group's link joined to it, the
        group's link pivoted to the frame.
    pivot, input_joint, ground_joint : str
        The input's frame pivot, the joint of input and coupler, the
        output's frame pivot.
    ground, crank, coupler, rocker : float
        The four lengths [m]: pivot to pivot, input, coupler, output.
    grashof : Grashof
    """

    group: str
    input: str
    coupler_link: str
    output: str
    pivot: str
    input_joint: str
    ground_joint: str
    ground: float
    crank: float
    coupler: float
    rocker: float
    grashof: Grashof

    def turning_links(self) -> tuple[str, ...]:
        """The names of the links that can turn fully relative to the frame."""
        names = {"input": self.input, "coupler": self.coupler_link, "output": self.output}
        return tuple(names[role] for role in self.grashof.turning)


def _frame_pivots(scene: Scene, structure) -> dict[str, str]:
    """Links pinned to the frame (a revolute pair with it): link → the frame point it turns about."""
    out = {}
    if _is_crank(scene):
        out[scene.driver.link] = scene.driver.pivot
    for group in structure.groups:
        for joint in (group.outer_i, group.outer_j):
            if joint.kind == "R" and joint.bodies[1] == FRAME:
                out[joint.bodies[0]] = joint.point
    return out


def four_bar_loops(scene: Scene, structure=None) -> list[FourBarLoop]:
    """Every four-bar loop of the mechanism (see :class:`FourBarLoop`), in solving order, with its Grashof class.

    >>> import plans
    >>> [(x.group, x.grashof.kind) for x in four_bar_loops(plans.load(plans.example_path("six-bar")))]
    [('RRR(3,4)', 'crank-rocker')]
    """
    from .structure import find_structure

    structure = structure or find_structure(scene)
    pivots = _frame_pivots(scene, structure)
    out = []
    for group in structure.groups:
        if group.kind != "RRR":
            continue
        ends = [(group.outer_i, group.links[0]), (group.outer_j, group.links[1])]
        for (a, link_a), (b, link_b) in (ends, ends[::-1]):
            # a: on a link X pinned to the frame; b: on the frame
            known_a, known_b = a.bodies[1], b.bodies[1]
            if known_b != FRAME or known_a == FRAME or known_a not in pivots:
                continue
            pivot = pivots[known_a]
            X = scene.bodies[known_a].points
            ground = abs(scene.frame.points[b.point] - scene.frame.points[pivot])
            crank = abs(X[a.point] - X[pivot])
            coupler = abs(scene.bodies[link_a].points[group.inner.point] - scene.bodies[link_a].points[a.point])
            rocker = abs(scene.bodies[link_b].points[group.inner.point] - scene.bodies[link_b].points[b.point])
            out.append(
                FourBarLoop(group.name, known_a, link_a, link_b, pivot, a.point, b.point, ground, crank, coupler, rocker,
                            grashof(ground, crank, coupler, rocker))
            )
            break
    return out


# --- the law --------------------------------------------------------------------------


@dataclass(frozen=True)
class DriverLaw:
    """The law the driver follows over a cycle (see the module's docstring).

    Attributes
    ----------
    kind : str
        ``"constant"``, ``"uniform"`` or ``"harmonic"``.
    crank : bool
        A crank (positions φ [rad], rates ω [rad/s], ε [rad/s²]) or a linear
        driver (s [m], v [m/s], a [m/s²]).
    x0, rate0, acceleration : float
        The scene's instant: position, rate and (for ``"uniform"``) the
        constant acceleration; for ``"constant"`` the acceleration is 0.
    limits : Limits or None
        A harmonic swing's limit positions.
    frequency : float
        A harmonic swing's Ω [rad/s] (its period is 2π/Ω); else 0.
    source : str
        Where the law came from: ``"scene"`` (``[driver] law``), ``"option"``
        (a program's or the CLI's ``--law``) or ``"default"``.
    given_acceleration : float
        The scene's ε [rad/s²] (or a [m/s²]) at its instant.  Under
        ``"constant"`` the cycle's acceleration is 0 whatever it is, and a
        non-zero one is stated beside the law as the given instant's only
        (:meth:`given_note`), so that a page never shows both unexplained.
    """

    kind: str
    crank: bool
    x0: float
    rate0: float
    acceleration: float
    limits: Limits | None = None
    frequency: float = 0.0
    source: str = "default"
    given_acceleration: float = 0.0

    @property
    def sense(self) -> float:
        """+1 when the driver moves towards larger φ (or s) from the scene's instant, −1 otherwise."""
        if self.rate0 != 0:
            return 1.0 if self.rate0 > 0 else -1.0
        return -1.0 if self.acceleration < 0 else 1.0

    def rate(self, x) -> np.ndarray:
        """ω(φ) [rad/s] or v(s) [m/s] for the turning/linear laws, in the driver's sense (not for a swing)."""
        x = np.asarray(x, dtype=float)
        if self.kind == "constant":
            return np.full(x.shape, self.rate0)
        if self.kind == "uniform":
            square = self.rate0**2 + 2 * self.acceleration * (x - self.x0)
            return self.sense * np.sqrt(np.maximum(square, 0.0))
        raise ValueError("a harmonic swing's rate depends on the stroke: use Cycle.rate")

    def given_note(self, lang: str = "en", link: str | None = None) -> str:
        """What the scene's own ε (a) is under a law that does not keep it, in *lang*: ``"the given ε₂ = 5 rad/s²
        holds at the given instant only"`` under ``"constant"`` with a given ε ≠ 0; else empty.  Said beside
        :meth:`describe` wherever the scene's data are printed with the law (the handout's data, ``plans sweep``)."""
        if self.kind != "constant" or self.given_acceleration == 0:
            return ""
        from ._text import subscript
        from .i18n import term

        a, unit = ("ε", "rad/s²") if self.crank else ("a", "m/s²")
        value = f"{self.given_acceleration:.4g}".replace("-", "\u2212")
        value = value.replace(".", ",") if lang in ("sr", "ru", "bg", "sl") else value
        return term("law_given_instant_only", lang).format(q=f"{a}{subscript(link) if link else ''} = {value} {unit}")

    def describe(self, lang: str = "en", link: str | None = None, phase: float | None = None, rate: bool = True) -> str:
        """The law in a few words of *lang*, with its numbers: ``"driver law: constant ω₂ = 10 rad/s (ε₂ = 0)"``.

        *rate*: False leaves a constant law's rate out (``"constant angular velocity, ε₂ = 0"``), where the
        driver's line above it gives the rate already (the handout's data, said once).

        *phase*: a swing's phase ψ [rad] at t = 0 of the diagrams it heads (:attr:`Cycle.phase` of their first
        position): the law is then stated with that time origin, φ = φc − A·cos Ω(t + t₀), t₀ = ψ/Ω."""
        from ._text import subscript
        from .i18n import term

        sub = subscript(link) if link else ""
        r, a, x, unit_r, unit_a = ("ω", "ε", "φ", "rad/s", "rad/s²") if self.crank else ("v", "a", "s", "m/s", "m/s²")

        def num(value: float) -> str:
            text = f"{value:.4g}".replace("-", "\u2212")
            return text.replace(".", ",") if lang in ("sr", "ru", "bg", "sl") else text

        def where(value: float) -> str:
            return f"{num(math.degrees(value))}°" if self.crank else f"{num(value * 1e3)} mm"

        head = term("driver_law", lang)
        if self.kind == "constant":
            said = f": {r}{sub} = {num(self.rate0)} {unit_r}," if rate else ","
            body = f"{term('law_constant_angular' if self.crank else 'law_constant', lang)}{said} {a}{sub} = 0"
        elif self.kind == "uniform":
            body = (f"{term('law_uniform', lang)}: {r}{sub}² = {r}₀² + 2{a}{sub}({x}{sub} − {x}₀), "
                    f"{r}₀ = {num(self.rate0)} {unit_r} {term('law_at', lang)} {x}₀ = {where(self.x0)}, {a}{sub} = {num(self.acceleration)} {unit_a}")
        else:
            lim = self.limits
            centre, amplitude = 0.5 * (lim.lo + lim.hi), 0.5 * lim.swing
            centre = 0.0 if abs(centre) < 1e-9 * max(amplitude, 1e-300) else centre  # (a swing about 0: its round-off)
            if phase is None:
                formula = f"{x}{sub} = {x}c − A·cos Ωt"
            else:
                formula = f"{x}{sub} = {x}c − A·cos Ω(t + t₀), t₀ = {num(float(phase) % _TURN / self.frequency)} s"
            body = (f"{term('law_harmonic', lang)} {where(lim.lo)} … {where(lim.hi)}: {formula}, "
                    f"{x}c = {where(centre)}, A = {where(amplitude)}, Ω = {num(self.frequency)} rad/s; "
                    f"{term('scene_instant', lang)}: |{r}{sub}| = {num(abs(self.rate0))} {unit_r} {term('law_at', lang)} "
                    f"{x}₀ = {where(self.x0)}; {r}{sub} = 0 {term('law_at_limits', lang)}")
        return f"{head}: {body}"


def driver_law(scene: Scene, law: str | None = None, structure=None) -> DriverLaw:
    """The law the scene's driver follows over a cycle.

    Parameters
    ----------
    scene : Scene
    law : {"constant", "uniform", "harmonic"} or None
        Overrides the scene's ``[driver] law``; None takes the scene's, else
        the default: constant, or a harmonic swing for a crank that cannot
        turn fully.

    Raises
    ------
    SceneError
        A law this driver cannot follow over a cycle, naming ``driver.law``
        (or ``--law``): a swing for a crank that turns fully or for a linear
        driver; constant or uniform for a crank that cannot turn fully; a
        driver at rest (ω₀ = 0 under the constant law).
    """
    crank = _is_crank(scene)
    given = law if law is not None else scene.driver.law
    source = "option" if law is not None else "scene" if scene.driver.law is not None else "default"
    key = "--law" if source == "option" else "driver.law"
    if given is not None and given not in LAWS:
        raise SceneError(f"unknown driver law {given!r}: expected one of {', '.join(LAWS)}", scene.source, key)
    x0, rate0, acceleration = _rates(scene)
    limits = crank_limits(scene, structure) if crank else None
    if limits is not None:
        if given not in (None, "harmonic"):
            raise SceneError(
                f"law = {given!r}: crank {scene.driver.link} cannot turn fully (it swings between its limit positions "
                f"{math.degrees(limits.lo):.2f}° and {math.degrees(limits.hi):.2f}°, where {limits.group} lines up), "
                "so it must reverse there with ω passing through zero: use law = \"harmonic\" (the default for such a crank)",
                scene.source, key)
        if rate0 == 0:
            raise SceneError("a swinging crank needs ω ≠ 0 at the scene's angle to set the pace of its swing (driver.omega = 0)",
                             scene.source, "driver.omega")
        half, middle = 0.5 * limits.swing, 0.5 * (limits.lo + limits.hi)
        offset = math.remainder(x0 - middle, _TURN)
        frequency = abs(rate0) / math.sqrt(max(half * half - offset * offset, 1e-300))
        return DriverLaw("harmonic", True, middle + offset, rate0, acceleration, limits, frequency, source)
    if given == "harmonic":
        what = "a linear driver has no swing" if not crank else f"crank {scene.driver.link} turns fully"
        raise SceneError(f"law = \"harmonic\" is the swing of a crank that cannot turn fully, but {what}: use \"constant\" or \"uniform\"",
                         scene.source, key)
    kind = given or "constant"
    if kind == "constant":
        if rate0 == 0:
            what = "ω" if crank else "velocity"
            raise SceneError(f"under law = \"constant\" the driver's {what} is the scene's, 0: it does not move and has no cycle; "
                             f"give driver.{'omega' if crank else 'velocity'} ≠ 0, or law = \"uniform\" with an acceleration",
                             scene.source, key)
        return DriverLaw("constant", crank, x0, rate0, 0.0, source=source, given_acceleration=acceleration)
    if rate0 == 0 and acceleration == 0:
        raise SceneError("under law = \"uniform\" a driver with no rate and no acceleration does not move", scene.source, key)
    return DriverLaw("uniform", crank, x0, rate0, acceleration, source=source)


def _check_covers(law: DriverLaw, scene: Scene, xs: np.ndarray, key: str) -> None:
    """Refuse a uniform law under which the driver stops (ω² ≤ 0) inside the range of *xs*."""
    if law.kind != "uniform" or law.acceleration == 0:
        return
    lo, hi = float(np.min(xs)), float(np.max(xs))
    squares = [law.rate0**2 + 2 * law.acceleration * (x - law.x0) for x in (lo, hi)]
    # ω² is linear in x: it is positive over [lo, hi] unless it is not at an end (0 allowed at the end the driver starts from)
    tol = 1e-12 * max(law.rate0**2, abs(law.acceleration) * (hi - lo), 1e-300)
    if min(squares) < -tol or (min(squares) <= tol and not _starts_from_rest(law, xs)):
        stop = law.x0 - law.rate0**2 / (2 * law.acceleration)
        where = f"{math.degrees(stop):.2f}°" if law.crank else f"{stop * 1e3:.2f} mm"
        span = (f"{math.degrees(lo):.2f}° … {math.degrees(hi):.2f}°" if law.crank else f"{lo * 1e3:.2f} … {hi * 1e3:.2f} mm")
        r = "ω" if law.crank else "v"
        raise SceneError(
            f"law = \"uniform\" cannot cover the cycle {span}: {r}² = {r}₀² + 2·({law.acceleration:g})·(x − x₀) reaches 0 at {where} "
            f"(the driver stops there and turns back); use law = \"constant\", or a range the driver covers",
            scene.source, key)


def _starts_from_rest(law: DriverLaw, xs: np.ndarray) -> bool:
    first = float(xs[0])
    return abs(law.rate0**2 + 2 * law.acceleration * (first - law.x0)) <= 1e-12 * max(law.rate0**2, 1e-300) + 1e-300 or (
        law.rate0 == 0 and first == law.x0)


# --- the output link and its extremes -------------------------------------------------------


@dataclass(frozen=True)
class Output:
    """The output link of a cycle and the coordinate whose extremes start it.

    Attributes
    ----------
    link : str
    kind : str
        ``"slider"`` (travel s [m] along a frame guide, of prismatic pair
        *pair*) or ``"rocker"`` (angle φ [rad] about frame point *pivot*).
    pair, pivot : str or None
    named : bool
        The scene names it (``[output] link``), else the default: the last
        group's slider or rocker.
    """

    link: str
    kind: str
    pair: str | None = None
    pivot: str | None = None
    named: bool = False

    def values(self, solution) -> np.ndarray:
        """The output's coordinate over a solution: s [m], or φ [rad] unwrapped along the rows."""
        if self.kind == "slider":
            return np.asarray(solution.sliders[self.pair].s, dtype=float)
        phi = np.asarray(solution.links[self.link].phi, dtype=float)
        ok = np.isfinite(phi)
        out = phi.copy()
        if ok.any():
            out[ok] = np.unwrap(phi[ok])
        return out

    def rates(self, solution) -> np.ndarray:
        """Its rate: v_rel [m/s] or ω [rad/s]."""
        if self.kind == "slider":
            return np.asarray(solution.sliders[self.pair].v_rel, dtype=float)
        return np.asarray(solution.links[self.link].omega, dtype=float)


def _output_of(scene: Scene, structure, link: str, named: bool) -> Output | None:
    for pair in scene.prismatics:
        if pair.slider == link and pair.guide == FRAME:
            return Output(link, "slider", pair=pair.name, named=named)
    pivots = _frame_pivots(scene, structure)
    if link in pivots and link != scene.driver.link:
        return Output(link, "rocker", pivot=pivots[link], named=named)
    return None


def output_link(scene: Scene, structure=None) -> Output | None:
    """The output link: the scene's ``[output] link``, else the last group's slider (on a frame guide) or rocker
    (pinned to the frame), else None (no such link: a cycle then starts at the scene's own position).

    Raises
    ------
    SceneError
        ``[output] link`` names a link that neither slides on a frame guide nor turns about a frame point.
    """
    from .structure import find_structure

    structure = structure or find_structure(scene)
    if scene.output is not None:
        out = _output_of(scene, structure, scene.output, True)
        if out is None:
            raise SceneError(
                f"link {scene.output} neither slides on a guide of the frame nor turns about a frame point (other than the driver): "
                "its extreme positions are not a stroke or a swing; name a slider or a rocker",
                scene.source, "output.link")
        return out
    for group in reversed(structure.groups):
        for link in reversed(group.links):
            out = _output_of(scene, structure, link, False)
            if out is not None:
                return out
    return None


# --- a cycle ---------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class Cycle:
    """Driver positions of a cycle under one law: where, when, how fast, on which branch.

    Attributes
    ----------
    scene : Scene
    law : DriverLaw
    positions : float array (N,)
        Crank angles [rad] (not wrapped: they run on in the sense of
        motion) or linear-driver positions [m].
    t : float array (N,)
        Time from the first position [s].
    rate, acceleration : float array (N,)
        ω [rad/s], ε [rad/s²] (or v [m/s], a [m/s²]) of the driver there.
    branches : dict[str, array]
        Per group, −1 where it runs on the other branch than the scene's
        (a swing's way back), for :func:`plans.analytic.solve`'s *branches*.
    period : float
        The time of one whole cycle [s]: a crank's turn or a swing there and
        back; for a linear driver, the time over its stroke.
    phase : float array (N,)
        A swing's phase ψ = Ωt + ψ_first [rad]; else the path covered from
        the first position [rad or m], in the sense of motion.
    start : str
        ``"output"`` (an extreme position of the output link) or ``"scene"``.
    """

    scene: Scene
    law: DriverLaw
    positions: np.ndarray
    t: np.ndarray
    rate: np.ndarray
    acceleration: np.ndarray
    branches: dict = field(default_factory=dict)
    period: float = math.nan
    phase: np.ndarray | None = None
    start: str = "scene"

    def __len__(self) -> int:
        return len(self.positions)

    def solve(self, structure=None, *, allow_partial: bool = True, warn_condition: float | None = None):
        """The analytic solution at the cycle's positions, the driver following the law (:func:`plans.analytic.solve`)."""
        from .analytic import solve
        from .limits import WARN_CONDITION

        return solve(
            self.scene, self.positions, structure, allow_partial=allow_partial,
            warn_condition=WARN_CONDITION if warn_condition is None else warn_condition,
            rates=(self.rate, self.acceleration), branches=self.branches or None,
        )

    def scene_at(self, k: int) -> Scene:
        """The scene at position k: the driver moved there with its rate and acceleration under the law."""
        from dataclasses import replace

        scene = self.scene.at(float(self.positions[k]))
        if self.law.crank:
            driver = replace(scene.driver, omega=float(self.rate[k]), epsilon=float(self.acceleration[k]))
        else:
            driver = replace(scene.driver, velocity=float(self.rate[k]), acceleration=float(self.acceleration[k]))
        return replace(scene, driver=driver)


def _path_positions(law: DriverLaw, start: float, count: int, closed: bool, span: float) -> np.ndarray:
    n = count + 1 if closed else count
    return start + law.sense * span * np.arange(n) / count


def _turning(scene: Scene, law: DriverLaw, xs: np.ndarray, key: str, period: float | None = None, start: str = "scene") -> Cycle:
    _check_covers(law, scene, xs, key)
    if law.kind == "constant":
        rate = np.full(len(xs), law.rate0)
        acc = np.zeros(len(xs))
        t = (xs - xs[0]) / law.rate0
    else:
        rate = law.rate(xs)
        acc = np.full(len(xs), law.acceleration)
        if law.acceleration != 0:
            t = (rate - rate[0]) / law.acceleration
        else:
            t = (xs - xs[0]) / law.rate0
    t = t + 0.0
    if period is None:
        period = float(t[-1]) if len(t) else math.nan
    return Cycle(scene, law, xs, t, rate, acc, {}, period, law.sense * (xs - xs[0]), start)


#: A swing's position that would fall on a limit position itself (the limiting group lined up, its rates 0/0
#: there) is taken this much phase [rad] after it: 1e-4 rad of phase is A·5e-9 of crank angle.
LIMIT_STEP = 1e-4


def _swing(scene: Scene, law: DriverLaw, phases: np.ndarray, start: str) -> Cycle:
    phases = np.asarray(phases, dtype=float).copy()
    on_limit = np.abs(np.sin(phases)) < 0.5 * LIMIT_STEP
    phases[on_limit] = np.round(phases[on_limit] / math.pi) * math.pi + LIMIT_STEP
    lim = law.limits
    half, middle = 0.5 * lim.swing, 0.5 * (lim.lo + lim.hi)
    omega = law.frequency
    xs = middle - half * np.cos(phases)
    rate = half * omega * np.sin(phases)
    acc = half * omega * omega * np.cos(phases)
    # the scene's own stroke: up (ψ in (0, π)) if its ω > 0; the other stroke on the other branch
    own_up = law.rate0 > 0
    up = np.mod(phases, _TURN) < math.pi
    flips = np.where(up == own_up, 1.0, -1.0)
    t = (phases - phases[0]) / omega
    return Cycle(scene, law, xs, t + 0.0, rate, acc, {lim.group: flips}, _TURN / omega, phases, start)


def _scene_phase(law: DriverLaw) -> float:
    """The swing's phase ψ₀ at the scene's instant."""
    half = 0.5 * law.limits.swing
    middle = 0.5 * (law.limits.lo + law.limits.hi)
    c = max(-1.0, min(1.0, (middle - law.x0) / half))
    psi = math.acos(c)
    return psi if law.rate0 > 0 else _TURN - psi


def driver_cycle(
    scene: Scene,
    count: int,
    *,
    law: str | None = None,
    start: str = "output",
    closed: bool = False,
    structure=None,
    limits: bool = False,
) -> Cycle:
    """*count* driver positions over one cycle under the driver's law (see the module's docstring).

    Parameters
    ----------
    scene : Scene
    count : int
        Positions over the cycle (at least 1).
    law : str, optional
        ``"constant"``, ``"uniform"`` or ``"harmonic"``; None: the scene's
        ``[driver] law`` or the default (:func:`driver_law`).
    start : {"output", "scene"}
        Position 0: the extreme position of the output link that starts its
        working stroke (:func:`strokes`; the scene's own position when the
        mechanism has no output slider or rocker, or for a linear driver),
        or the scene's own position.
    closed : bool
        A crank's or a swing's list ends with position 0 one cycle later
        (count + 1 entries), so that a curve drawn through it closes.
    limits : bool
        A swing's list also holds its two limit positions, at the times the
        law reaches them (a curve drawn through the positions then reaches
        the input's ω = 0 there); the others stay equally spaced in time.

    Raises
    ------
    SceneError
        A law the driver cannot follow over the cycle (:func:`driver_law`,
        a uniform law under which it stops), a count below 1, an unknown
        *start*, a linear driver without a stroke.
    """
    from .structure import find_structure

    if count < 1:
        raise SceneError(f"positions: the count must be at least 1, got {count}", scene.source, "--positions")
    if start not in ("output", "scene"):
        raise SceneError(f"start: expected \"output\" or \"scene\", got {start!r}", scene.source, "--start")
    structure = structure or find_structure(scene)
    the_law = driver_law(scene, law, structure)
    key = "--law" if law is not None else "driver.law"
    if not the_law.crank:
        stroke = scene.driver.stroke
        if stroke is None:
            raise SceneError("positions over the cycle of a linear driver need its stroke: add stroke = [start, end] to [driver]",
                             scene.source, "driver.stroke")
        a, b = stroke
        if (b - a) * the_law.sense < 0:
            a, b = b, a
        xs = np.array([a]) if count == 1 else a + (b - a) * np.arange(count) / (count - 1)
        return _turning(scene, the_law, xs, key)
    first = None
    if start == "output":
        found = strokes(scene, law, structure, _law=the_law)
        if found is not None:
            first = found
    if the_law.kind == "harmonic":
        psi0 = _scene_phase(the_law) if first is None else first.start_phase
        n = count + 1 if closed else count
        phases = psi0 + _TURN * np.arange(n) / count
        if limits:  # the limit positions: ψ = kπ, within the cycle
            ends = math.pi * np.arange(math.ceil(psi0 / math.pi), math.floor((psi0 + _TURN) / math.pi) + 1)
            ends = ends[(ends > psi0) & (ends < psi0 + _TURN)]
            ends = ends[np.min(np.abs(phases[:, None] - ends[None, :]), axis=0) > 1e-9]  # not one of the positions already
            phases = np.sort(np.concatenate([phases, ends]))
        return _swing(scene, the_law, phases, "output" if first is not None else "scene")
    x_start = the_law.x0 if first is None else first.start_position
    xs = _path_positions(the_law, x_start, count, closed, _TURN)
    period = None
    if the_law.kind == "constant":
        period = _TURN / abs(the_law.rate0)
    cycle = _turning(scene, the_law, xs, key, period, "output" if first is not None else "scene")
    if the_law.kind == "uniform" and not closed and count > 0:
        # the time of the whole turn, to the first position one turn later
        whole = _turning(scene, the_law, np.append(xs, x_start + the_law.sense * _TURN), key)
        cycle = Cycle(cycle.scene, cycle.law, cycle.positions, cycle.t, cycle.rate, cycle.acceleration, {}, float(whole.t[-1]),
                      cycle.phase, cycle.start)
    return cycle


def cycle_at(scene: Scene, positions, *, law: str | None = None, structure=None) -> Cycle:
    """Given driver positions (rad or m, in the order given) under the driver's law: a :class:`Cycle` of them.

    A turning crank or a linear driver takes the law's rate at each position
    (t from the first one, along the path in the sense of motion).  A swing
    (a rocker input) takes the positions on the scene's own stroke and
    branch, with the harmonic law's rate there; a position outside the
    swing (where the mechanism does not assemble) keeps the scene's rate and
    has no time (NaN).

    >>> import plans
    >>> c = cycle_at(plans.load(plans.example_path("four-bar")), [0.0, 1.0], law="uniform")
    >>> [round(float(w), 4) for w in c.rate]
    [9.4619, 9.9764]
    """
    from .structure import find_structure

    structure = structure or find_structure(scene)
    the_law = driver_law(scene, law, structure)
    key = "--law" if law is not None else "driver.law"
    xs = np.asarray(positions, dtype=float).reshape(-1)
    if the_law.kind == "harmonic":
        lim = the_law.limits
        half, middle = 0.5 * lim.swing, 0.5 * (lim.lo + lim.hi)
        offsets = np.array([math.remainder(x - middle, _TURN) for x in xs])
        outside = np.abs(offsets) >= half  # where the mechanism does not assemble: the solver says so there
        psi = np.arccos(np.clip(-offsets / half, -1.0, 1.0))
        if the_law.rate0 < 0:
            psi = _TURN - psi
        cycle = _swing(scene, the_law, psi, "scene")
        if outside.any():
            positions = np.where(outside, xs, cycle.positions)
            rate = np.where(outside, the_law.rate0, cycle.rate)
            acc = np.where(outside, 0.0, cycle.acceleration)
            t = np.where(outside, np.nan, cycle.t)
            cycle = Cycle(scene, the_law, positions, t, rate, acc, cycle.branches, cycle.period, cycle.phase, "scene")
        return cycle
    return _turning(scene, the_law, xs, key)


# --- strokes -------------------------------------------------------------------------------


@dataclass(frozen=True)
class Strokes:
    """The output link's extreme positions over the cycle and what the course project states of them.

    Attributes
    ----------
    output : Output
    law : DriverLaw
    start_position, other_position : float
        Driver positions [rad or m] of the extreme position that starts the
        working stroke (position 0) and of the other one (0′).
    start_phase, other_phase : float
        Their phases along a swing (ψ [rad]); for a crank, the path turned
        from the scene's angle in the sense of motion [rad].
    start_value, other_value : float
        The output's coordinate there: s [m] or φ [rad].
    travel : float
        The stroke H [m] (a slider) or swing ψ [rad] (a rocker): |difference|.
    working_arc, return_arc : float
        The driver's path over the working and the return stroke: crank
        angles [rad] (their sum a turn, or twice the swing for a rocker
        input), or for a linear driver its travel [m] (return_arc NaN).
    theta : float or None
        The crank angle between the extreme positions, θ = |working arc −
        180°| [rad] (a crank that turns fully only).
    K : float or None
        Coefficient of the average speed increase (180° + θ)/(180° − θ) for a
        crank that turns fully; for a rocker input the ratio of the times of
        the working and the return stroke; None for a linear driver.
    working_time, return_time : float
        Times of the two strokes under the law [s] (return NaN for a linear driver).
    working : str
        Which stroke is the working one, named by the output's motion:
        ``"out"`` (s or φ increasing) or ``"back"``.
    """

    output: Output
    law: DriverLaw
    start_position: float
    other_position: float
    start_phase: float
    other_phase: float
    start_value: float
    other_value: float
    travel: float
    working_arc: float
    return_arc: float
    theta: float | None
    K: float | None
    working_time: float
    return_time: float
    working: str

    def summary(self, lang: str = "en") -> list[str]:
        """A few lines of *lang* stating H (or ψ), θ, K and the working stroke."""
        from ._text import subscript
        from .i18n import term

        def num(value: float, digits: int = 4) -> str:
            value = 0.0 if abs(value) < 1e-9 else value
            text = f"{value:.{digits}g}".replace("-", "\u2212")
            return text.replace(".", ",") if lang in ("sr", "ru", "bg", "sl") else text

        sub = subscript(self.output.link)
        lines = []
        if not self.law.crank:  # a sliding driver: its stroke, one way; its ends are not the output's rest
            return self._linear_summary(lang, num, sub)
        if self.output.kind == "slider":
            lines.append(f"{term('output_link', lang)} {self.output.link}: {term('stroke_H', lang)} H = {num(self.travel * 1e3)} mm")
        else:
            lines.append(f"{term('output_link', lang)} {self.output.link}: {term('swing_psi', lang)} ψ{sub} = {num(math.degrees(self.travel))}°")
        def deg(value: float) -> str:  # every angle of the cycle to 0.1° (one rounding on a page)
            text = f"{0.0 if abs(value) < 0.05 else value:.1f}".replace("-", "\u2212")
            return text.replace(".", ",") if lang in ("sr", "ru", "bg", "sl") else text

        where = (lambda x: f"{deg(_degrees_0_360(x))}°") if self.law.crank else (lambda x: f"{num(x * 1e3)} mm")
        lines.append(f"{term('extreme_positions', lang)}: 0 — {where(self.start_position)}, 0′ — {where(self.other_position)}")
        if self.theta is not None:
            lines.append(f"θ = {deg(math.degrees(self.theta))}°, K = (180° + θ)/(180° − θ) = {num(self.K)}")
        elif self.K is not None:
            lines.append(f"K = t_w / t_r = {num(self.K)}")
        arc = f"{deg(math.degrees(self.working_arc))}°" if self.law.crank else f"{num(self.working_arc * 1e3)} mm"
        lines.append(f"{term('working_stroke', lang)}: 0 → 0′, {arc}, t = {num(self.working_time)} s")
        return lines

    def _linear_summary(self, lang: str, num, sub: str) -> list[str]:
        """A linear driver's cycle is its stroke, one way (domain.md §10): the output's travel over it, the stroke's
        ends (the driver's, not the output's extreme positions: the output is not at rest there), the stroke's
        length and time; no return stroke, no θ, no K."""
        from .i18n import term

        if self.output.kind == "slider":
            travel = f"{term('stroke_H', lang)} H = {num(self.travel * 1e3)} mm"
        else:
            travel = f"{term('swing_psi', lang)} ψ{sub} = {num(math.degrees(self.travel))}°"
        return [
            f"{term('output_link', lang)} {self.output.link}: {travel} ({term('over_driver_stroke', lang)})",
            f"{term('driver_stroke_ends', lang)}: {num(self.start_position * 1e3)} mm, {num(self.other_position * 1e3)} mm",
            f"{term('driver_stroke', lang)}: {num(self.working_arc * 1e3)} mm, t = {num(self.working_time)} s "
            f"({term('one_way_stroke', lang)})",
        ]

    def as_dict(self) -> dict:
        """For JSON: each key names its unit (``_deg`` in [0, 360) for crank angles, ``_m``, ``_s``)."""
        kind = self.output.kind
        crank = self.law.crank

        def where(x: float) -> float:
            return _degrees_0_360(x) if crank else x

        arc = (lambda x: math.degrees(x)) if crank else (lambda x: x)
        unit = "deg" if crank else "m"
        finite = math.isfinite
        return {
            "output_link": self.output.link,
            "output_kind": kind,
            "law": self.law.kind,
            f"start_{unit}": where(self.start_position),
            f"other_{unit}": where(self.other_position),
            "stroke_H_m" if kind == "slider" else "swing_psi_deg": self.travel if kind == "slider" else math.degrees(self.travel),
            "theta_deg": None if self.theta is None else math.degrees(self.theta),
            "K": self.K,
            f"working_arc_{unit}": arc(self.working_arc),
            f"return_arc_{unit}": arc(self.return_arc) if finite(self.return_arc) else None,
            "working_time_s": self.working_time,
            "return_time_s": self.return_time if finite(self.return_time) else None,
            "working_stroke": self.working,
        }


def _degrees_0_360(x: float) -> float:
    """An angle [rad] in degrees in [0, 360), round-off at 360 as 0."""
    deg = math.degrees(x) % 360.0
    return 0.0 if deg > 360.0 - 1e-9 else deg + 0.0


def strokes(scene: Scene, law: str | None = None, structure=None, *, _law: DriverLaw | None = None) -> Strokes | None:
    """The output link's extreme positions over the driver's cycle, H (or ψ), θ and K (see :class:`Strokes`).

    None when the mechanism has no output slider or rocker (:func:`output_link`),
    or the output has no two extreme positions over the cycle (it turns fully).

    The extremes are where the output's rate changes sign: found on a dense
    cycle, then refined by bisection on the sign of the output's rate at
    single positions.  The working stroke is the slower of the two (under
    the law); position 0 starts it.

    >>> import plans
    >>> st = strokes(plans.load(plans.example_path("slider-crank")))
    >>> round(st.travel * 1e3, 3), round(math.degrees(st.theta), 3)
    (204.989, 11.258)
    """
    from .analytic import solve
    from .structure import find_structure

    structure = structure or find_structure(scene)
    the_law = _law or driver_law(scene, law, structure)
    output = output_link(scene, structure)
    if output is None:
        return None
    if not the_law.crank:
        return _linear_strokes(scene, the_law, output, structure)
    if the_law.kind == "harmonic":
        psi0 = _scene_phase(the_law)
        phases = psi0 + _TURN * np.arange(SEARCH_STEPS) / SEARCH_STEPS
        base = _swing(scene, the_law, phases, "scene")
    else:
        xs = the_law.x0 + the_law.sense * _TURN * np.arange(SEARCH_STEPS) / SEARCH_STEPS
        phases = the_law.sense * (xs - xs[0])
        base = Cycle(scene, the_law, xs, np.zeros(len(xs)), np.full(len(xs), the_law.sense), np.zeros(len(xs)), {}, math.nan, phases)
    sweep = solve(scene, base.positions, structure, allow_partial=True, warn_condition=math.inf,
                  rates=(np.sign(base.rate) + (base.rate == 0), np.zeros(len(base.rate))), branches=base.branches or None)
    valid = np.asarray(sweep.valid, dtype=bool)
    if not valid.all():
        return None
    rate = output.rates(sweep)  # per unit driver rate, in the sense of motion: its sign is that of dy/d(path)
    sign = np.sign(rate)
    n = len(sign)
    changes = [k for k in range(n) if sign[k] != 0 and sign[(k + 1) % n] != 0 and sign[k] != sign[(k + 1) % n]]
    if len(changes) != 2:
        return None

    def position(phase: float) -> tuple[float, dict]:
        if the_law.kind == "harmonic":
            one = _swing(scene, the_law, np.array([phase]), "scene")
            return float(one.positions[0]), {g: f for g, f in one.branches.items()}
        return the_law.x0 + the_law.sense * phase, {}

    def rate_at(phase: float) -> float:
        x, flips = position(phase)
        sense = 1.0
        if the_law.kind == "harmonic":
            sense = 1.0 if math.sin(phase) >= 0 else -1.0
        else:
            sense = the_law.sense
        one = solve(scene, [x], structure, allow_partial=True, warn_condition=math.inf, rates=(sense, 0.0), branches=flips or None)
        return float(output.rates(one)[0])

    dense = output.values(sweep)
    found = []
    for k in changes:
        a, b = float(phases[k]), float(phases[(k + 1) % n]) + (_TURN if k + 1 == n else 0.0)
        a, b = _root(rate_at, a, b)
        phase = 0.5 * (a + b)
        x, flips = position(phase)
        one = solve(scene, [x], structure, allow_partial=True, warn_condition=math.inf, branches=flips or None)
        y = float(output.values(one)[0])
        if output.kind == "rocker":  # on the dense curve's turn (angles are wrapped at single positions)
            y = float(dense[k]) + math.remainder(y - float(dense[k]), _TURN)
        found.append((phase, x, y))
    (p1, x1, y1), (p2, x2, y2) = found
    # times under the law of the two strokes: 1 → 2 and 2 → 1 (one cycle on)
    span = _TURN  # phase or path of one whole cycle
    arc12 = (p2 - p1) % span
    arc21 = span - arc12
    t12, t21 = _duration(the_law, p1, arc12, scene), _duration(the_law, p2, arc21, scene)
    if t12 >= t21:
        (ps, xs_, ys), (po, xo, yo), tw, tr, aw, ar = (p1, x1, y1), (p2, x2, y2), t12, t21, arc12, arc21
    else:
        (ps, xs_, ys), (po, xo, yo), tw, tr, aw, ar = (p2, x2, y2), (p1, x1, y1), t21, t12, arc21, arc12
    if the_law.kind == "harmonic":
        lim = the_law.limits
        # the driver's path along the swing over each stroke [rad]
        aw_path = _swing_path(lim, ps, aw)
        ar_path = _swing_path(lim, po, ar)
        theta, K = None, tw / tr
        working_arc, return_arc = aw_path, ar_path
    else:
        theta = abs(aw - math.pi)
        K = (math.pi + theta) / (math.pi - theta)
        working_arc, return_arc = aw, ar
    return Strokes(output, the_law, xs_, xo, ps, po, ys, yo, abs(yo - ys), working_arc, return_arc, theta, K, tw, tr,
                   "out" if yo > ys else "back")


def _root(f, a: float, b: float) -> tuple[float, float]:
    """A bracket [a, b] of a sign change of f, narrowed to round-off by the Illinois method (regula falsi that halves
    the weight of an end kept twice): some ten evaluations against bisection's sixty."""
    fa, fb = f(a), f(b)
    side = 0
    c = 0.5 * (a + b)
    for _ in range(REFINE_STEPS):
        if fa == 0:
            return a, a
        if fb == 0:
            return b, b
        if abs(b - a) <= 1e-14 * max(1.0, abs(a)):
            break
        c = b - fb * (b - a) / (fb - fa)
        if not (min(a, b) < c < max(a, b)):
            c = 0.5 * (a + b)
        fc = f(c)
        if (fc > 0) == (fb > 0):
            b, fb = c, fc
            if side == -1:
                fa *= 0.5
            side = -1
        else:
            a, fa = c, fc
            if side == 1:
                fb *= 0.5
            side = 1
        if abs(fc) <= 1e-15 * (abs(fa) + abs(fb)):
            return c, c
    return (c, c) if abs(b - a) > 1e-9 else (a, b)  # the last estimate, should the bracket not have closed


def _swing_path(limits: Limits, phase: float, span: float) -> float:
    """The crank angle travelled [rad] along a swing φ = φ_c − A cos ψ from *phase* over *span* of phase."""
    half = 0.5 * limits.swing
    psi = np.linspace(phase, phase + span, 2049)
    return float(np.sum(np.abs(np.diff(-half * np.cos(psi)))))


def _duration(law: DriverLaw, phase: float, span: float, scene: Scene) -> float:
    """Time [s] over *span* of path (or phase) from *phase* (path from the scene's position) under the law."""
    if law.kind == "harmonic":
        return span / law.frequency
    if law.kind == "constant" or law.acceleration == 0:  # uniform with ε = 0 (a = 0) is the constant law
        return span / abs(law.rate0)
    x1 = law.x0 + law.sense * phase
    x2 = x1 + law.sense * span
    xs = np.array([x1, x2])
    _check_covers(law, scene, xs, "driver.law")
    rate = law.rate(xs)
    return abs(float(rate[1] - rate[0]) / law.acceleration)


def _linear_strokes(scene: Scene, law: DriverLaw, output: Output, structure) -> Strokes | None:
    """A linear driver's stroke: the output's travel from the stroke's start to its end (no return stroke)."""
    from .analytic import solve

    stroke = scene.driver.stroke
    if stroke is None:
        return None
    a, b = stroke
    if (b - a) * law.sense < 0:
        a, b = b, a
    one = solve(scene, [a, b], structure, allow_partial=True, warn_condition=math.inf)
    if not np.asarray(one.valid).all():
        return None
    ya, yb = (float(v) for v in output.values(one))
    xs = np.array([a, b])
    _check_covers(law, scene, xs, "driver.law")
    if law.kind == "constant":
        time = abs(b - a) / abs(law.rate0)
    else:
        rate = law.rate(xs)
        time = abs(float(rate[1] - rate[0]) / law.acceleration) if law.acceleration else abs(b - a) / abs(law.rate0)
    return Strokes(output, law, a, b, 0.0, abs(b - a), ya, yb, abs(yb - ya), abs(b - a), math.nan, None, None, time, math.nan,
                   "out" if yb > ya else "back")


# --- what plans solve states of the cycle ------------------------------------------------------


def cycle_summary(scene: Scene, law: str | None = None, structure=None) -> dict:
    """What ``plans solve --json`` states of the scene's cycle (key ``"cycle"``), SI units with the unit in the key.

    ``law``: the kind, where it came from and its words (None with ``law_error``,
    the reason, when the driver cannot follow one: a driver at rest; ``strokes_error``
    likewise when the strokes cannot be timed under it);
    ``limits_deg``: a rocker input's limit angles, else None;
    ``four_bar_loops``: per loop its group, links, lengths [m], Grashof class
    and the links that turn fully; ``strokes``: :meth:`Strokes.as_dict` or None.
    """
    from .structure import find_structure

    structure = structure or find_structure(scene)
    out: dict = {"law": None}
    the_law = None
    try:
        the_law = driver_law(scene, law, structure)
        out["law"] = {"kind": the_law.kind, "source": the_law.source, "words": the_law.describe("en", scene.driver.link)}
    except PlansError as exc:  # a driver at rest has no cycle; the instant is still solved
        out["law_error"] = str(exc)
    limits = the_law.limits if the_law is not None else None
    out["limits_deg"] = None if limits is None else [math.degrees(limits.lo), math.degrees(limits.hi)]
    out["four_bar_loops"] = [
        {
            "group": loop.group,
            "links": {"input": loop.input, "coupler": loop.coupler_link, "output": loop.output},
            "lengths_m": {"frame": loop.ground, "input": loop.crank, "coupler": loop.coupler, "output": loop.rocker},
            "grashof_class": loop.grashof.kind,
            "grashof": loop.grashof.grashof,
            "turning_links": list(loop.turning_links()),
        }
        for loop in four_bar_loops(scene, structure)
    ]
    found = None
    if the_law is not None:
        try:
            found = strokes(scene, law, structure, _law=the_law)
        except PlansError as exc:  # (a uniform law that cannot cover a stroke): said, not silently left out
            out["strokes_error"] = str(exc)
    out["strokes"] = None if found is None else found.as_dict()
    return out


def cycle_text(summary: dict) -> str:
    """The lines of ``plans solve``'s table about the cycle, from :func:`cycle_summary`."""
    lines = ["", "cycle"]
    law = summary.get("law")
    lines.append(f"  {law['words']}" if law else f"  driver law: none ({summary.get('law_error', '')})")
    if summary.get("strokes_error"):
        lines.append(f"  strokes not stated: {summary['strokes_error']}")
    if summary["limits_deg"] is not None:
        lo, hi = summary["limits_deg"]
        lines.append(f"  the input link cannot turn fully: it swings between its limit positions {lo:.2f}° and {hi:.2f}°".replace("-", "−"))
    for loop in summary["four_bar_loops"]:
        turning = ", ".join(loop["turning_links"])
        turns = f"turning fully: {turning}" if turning else "no link turns fully"
        n = loop["lengths_m"]
        lines.append(
            f"  four-bar loop {loop['group']} (frame {n['frame']:.6g} m, input {loop['links']['input']} {n['input']:.6g} m, "
            f"coupler {loop['links']['coupler']} {n['coupler']:.6g} m, output {loop['links']['output']} {n['output']:.6g} m): "
            f"{loop['grashof_class']}{'' if loop['grashof'] else ' (non-Grashof)'}; {turns}"
        )
    st = summary["strokes"]
    if st is not None:
        if st["output_kind"] == "slider":
            lines.append(f"  output link {st['output_link']}: stroke H = {st['stroke_H_m'] * 1e3:.6g} mm")
        else:
            lines.append(f"  output link {st['output_link']}: swing ψ = {st['swing_psi_deg']:.6g}°")
        if st["theta_deg"] is not None:
            lines.append(f"  θ = {st['theta_deg']:.6g}° between the extreme positions, K = (180° + θ)/(180° − θ) = {st['K']:.6g}")
        elif st["K"] is not None:
            lines.append(f"  K = t_working / t_return = {st['K']:.6g}")
        lines.append(f"  working stroke (the slower): {st['working_time_s']:.6g} s"
                     + (f", return {st['return_time_s']:.6g} s" if st["return_time_s"] is not None else ""))
    return "\n".join(lines) + "\n"
