"""Kinematic diagrams of the output link by graphical differentiation: the method of chords (and of tangents).

The course project's third method, beside the velocity and acceleration plans
and the analytic solution (domain.md §10).  It knows only the displacement s
of the output link at the project's positions and the times t at which the
driver reaches them; it never reads a velocity or an acceleration:

* **The s–t diagram.**  s is the output's signed displacement from its first
  position (a slider: travel along its guide [m], positive along the guide's
  direction; a rocker: its angle [rad], counter-clockwise positive), drawn
  against t at the scales μ_s [m/mm or rad/mm] and μ_t = T / L [s/mm] (T the
  time of one cycle, L the abscissa's length [mm]).
* **Method of chords.**  Neighbouring points of the s–t curve are joined by
  chords.  From a pole P₁ at distance H₁ [mm] to the left of the v–t
  diagram's origin, rays are drawn parallel to the chords; the intercept y
  [mm] a ray cuts on the ordinate axis is the mean velocity over the
  interval, ``v = y · μ_v`` with ``μ_v = μ_s / (μ_t · H₁)``::

      y = H₁ · tan α = H₁ · (Δs / μ_s) / (Δt / μ_t)    ⇒    y · μ_v = Δs / Δt

  and is plotted at the interval's middle in time.  A smooth curve through
  those points is v(t).  The same on the v–t curve (chords between its
  points, pole P₂ at H₂, ``μ_a = μ_v / (μ_t · H₂)``) gives a(t).
* **Reading back at the positions.**  The chord of an interval is exactly
  parallel to the tangent somewhere inside it (the mean value theorem); at
  the interval's middle its slope differs from the true v by
  ``Δt² · s‴ / 24`` (second order).  The a–t points are the chords of the
  v–t points, so where the positions are equally spaced in time they fall on
  the positions themselves, with an error ``Δt² · s⁗ / 12``.  The v–t
  curve is read at the positions through a smooth curve: the cubic through
  the four nearest points (:func:`smooth`), which adds an error of fourth
  order; the reading at a position keeps the chord's ``Δt² · s‴ / 24``.
* **Ends.**  A repeating cycle (a crank at constant speed, a rocker input's
  swing) is closed: the chord from the last position to the first one a
  period later.  An open series has n − 1 chords; a uniformly accelerated
  crank's turn is continued one position past each end (the crank turns on,
  :attr:`OutputMotion.lead`, :attr:`OutputMotion.trail`), a linear driver's
  stroke is not (its end readings lie beyond its last points: the least
  accurate).
* **Method of tangents** (:func:`tangents`): the ray parallel to the tangent
  of the smooth s–t curve at each position; the tangent's slope is that of
  the curve through the five nearest points (fourth order where s is smooth).

Signs: every value is signed (no magnitudes): v = ds/dt, a = dv/dt, with the
sign convention of s.  Units SI; drawn lengths in mm.

>>> import numpy as np
>>> t = np.arange(4) * 0.25                       # four positions of a cycle T = 1 s
>>> s = np.array([0.0, 1.0, 0.0, -1.0])
>>> middles, slopes = chords(t, s, period=1.0)
>>> [float(x) for x in middles], [float(x) for x in slopes]
([0.125, 0.375, 0.625, 0.875], [4.0, -4.0, -4.0, 4.0])
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import rounding
from .errors import PlansError

__all__ = [
    "DiagramsError",
    "chords",
    "smooth",
    "tangents",
    "Differentiation",
    "differentiate",
    "DiagramScales",
    "diagram_scales",
    "OutputMotion",
    "KinematicDiagrams",
    "kinematic_diagrams_of",
    "POLE_DISTANCES",
    "ABSCISSA_MAX",
    "ORDINATE_MAX",
    "TIME_MANTISSAS",
    "relative_errors",
    "round_up",
    "abscissa_length",
    "kinematic_diagrams",
    "rescaled",
    "readable",
    "flat",
    "READABLE_HEIGHT",
    "with_plans",
]

#: Pole distances H [mm] a plate uses: round, short enough to leave the abscissa its room.
POLE_DISTANCES = (10.0, 12.0, 15.0, 20.0, 25.0, 30.0)
#: The longest abscissa L [mm] of one cycle on an A4 page (the poles and the ordinate's labels take the rest).
ABSCISSA_MAX = 125.0
#: The tallest a diagram's ordinate range may be drawn [mm].
ORDINATE_MAX = 40.0
#: Round mantissas of μ_t and μ_s (textbooks' 1, 2, 2.5, 5 × 10ⁿ).
TIME_MANTISSAS = (1, 2, 2.5, 5)


class DiagramsError(PlansError, ValueError):
    """Kinematic diagrams that cannot be made: ``cause`` says why (``"too_few"``, ``"no_output"``,
    ``"unsolved"``), ``positions`` which positions are not solved (for ``"unsolved"``)."""

    def __init__(self, message: str, cause: str, positions: tuple = ()):
        super().__init__(message)
        self.cause = cause
        self.positions = tuple(positions)


def round_up(need: float, mantissas=TIME_MANTISSAS) -> float:
    """The smallest m·10ⁿ (m in *mantissas*, the textbook's by default) not below *need* (:func:`plans.rounding.round_up`)."""
    return rounding.round_up(need, mantissas)


def _extended(t: np.ndarray, y: np.ndarray, period: float | None) -> tuple[np.ndarray, np.ndarray]:
    """The points of a closed cycle with the first one again one period later (open: as given)."""
    if period is None:
        return t, y
    return np.append(t, t[0] + period), np.append(y, y[0])


def chords(t, y, *, period: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The method of chords: the middle of every interval and the chord's slope over it.

    Parameters
    ----------
    t : array (n,)
        Abscissae [s], increasing.
    y : array (n,)
        Ordinates of the curve at *t* (any unit).
    period : float, optional
        The curve repeats after *period* [s]: the last point is joined to the
        first one a period later (n chords); otherwise n − 1 chords.

    Returns
    -------
    middles : array
        ``(t[k] + t[k+1]) / 2`` [s].
    slopes : array
        ``(y[k+1] − y[k]) / (t[k+1] − t[k])`` [unit/s], the mean rate over the interval.
    """
    t, y = _extended(np.asarray(t, dtype=float), np.asarray(y, dtype=float), period)
    return (t[1:] + t[:-1]) / 2, np.diff(y) / np.diff(t)


def _nearest(nodes: np.ndarray, values: np.ndarray, x: float, count: int, period: float | None) -> tuple[np.ndarray, np.ndarray]:
    """The *count* nodes nearest to *x* (a closed cycle: with copies a period before and after)."""
    if period is not None:
        nodes = np.concatenate([nodes - period, nodes, nodes + period])
        values = np.concatenate([values, values, values])
    order = np.argsort(np.abs(nodes - x), kind="stable")[:count]
    order = np.sort(order)
    return nodes[order], values[order]


def _lagrange(xs: np.ndarray, ys: np.ndarray, x: float, derivative: bool = False) -> float:
    """The polynomial through (xs, ys), or its derivative, at *x*."""
    total = 0.0
    for j in range(len(xs)):
        others = np.delete(xs, j)
        denominator = float(np.prod(xs[j] - others))
        if not derivative:
            total += ys[j] * float(np.prod(x - others)) / denominator
        else:
            d = 0.0
            for m in range(len(others)):
                d += float(np.prod(np.delete(x - others, m)))
            total += ys[j] * d / denominator
    return total


def smooth(nodes, values, x, *, period: float | None = None) -> np.ndarray:
    """The smooth curve a draftsman draws through the points (*nodes*, *values*), read at *x*.

    Each reading is the cubic through the four nodes nearest to it (on a
    closed cycle, counted across its ends): exact for a cubic, an error of
    fourth order in the spacing for a smooth curve.
    """
    nodes, values = np.asarray(nodes, dtype=float), np.asarray(values, dtype=float)
    count = min(4, len(nodes))
    out = [_lagrange(*_nearest(nodes, values, float(at), count, period), float(at)) for at in np.atleast_1d(x)]
    return np.asarray(out)


def tangents(t, y, *, period: float | None = None) -> np.ndarray:
    """The method of tangents: the slope of the smooth curve through the points at every point [unit/s].

    The tangent is that of the curve through the five nearest points (fewer
    when there are fewer): ``(y₋₂ − 8y₋₁ + 8y₁ − y₂) / (12Δt)`` on an equal
    spacing, an error of fourth order.
    """
    t, y = np.asarray(t, dtype=float), np.asarray(y, dtype=float)
    count = min(5, len(t))
    return np.asarray([_lagrange(*_nearest(t, y, float(at), count, period), float(at), derivative=True) for at in t])


@dataclass(frozen=True)
class Differentiation:
    """One graphical differentiation by the method of chords: from the curve y(t) to its rate.

    Attributes
    ----------
    t, y : array
        The points of the curve differentiated (times [s], ordinates).
    middles, rates : array
        The chords: each interval's middle [s] and the chord's slope (the
        mean rate over the interval), where the rate curve's points are plotted.
    pole : float
        H [mm]: the pole's distance to the left of the rate diagram's origin.
    scale : float
        μ of the rate diagram: ``scale_of_y / (μ_t · H)`` [unit/s per mm].
    """

    t: np.ndarray
    y: np.ndarray
    middles: np.ndarray
    rates: np.ndarray
    pole: float
    scale: float

    def intercepts(self) -> np.ndarray:
        """The ordinate [mm] each ray cuts on the rate diagram's axis: ``rate / μ``."""
        return self.rates / self.scale


def differentiate(t, y, *, period: float | None, pole: float, scale: float) -> Differentiation:
    """The method of chords on the points (*t*, *y*), drawn with pole distance *pole* [mm] at rate scale *scale*."""
    middles, rates = chords(t, y, period=period)
    return Differentiation(np.asarray(t, dtype=float), np.asarray(y, dtype=float), middles, rates, float(pole), float(scale))


@dataclass(frozen=True)
class DiagramScales:
    """The scales of the s–t, v–t and a–t diagrams.

    Attributes
    ----------
    mu_t : float
        [s/mm], ``T / L``.
    length : float
        L [mm], the abscissa of one cycle (or of the time the positions span).
    mu_s : float
        [m/mm] (a slider) or [rad/mm] (a rocker).
    pole_v, pole_a : float
        H₁, H₂ [mm].
    mu_v, mu_a : float
        ``μ_s / (μ_t·H₁)`` [(m/s)/mm or (rad/s)/mm], ``μ_v / (μ_t·H₂)`` [(m/s²)/mm or (rad/s²)/mm].
    """

    mu_t: float
    length: float
    mu_s: float
    pole_v: float
    mu_v: float
    pole_a: float
    mu_a: float


def _span(values) -> float:
    values = np.asarray(values, dtype=float)
    values = values[np.isfinite(values)]
    return float(values.max() - values.min()) if len(values) else 0.0


def _pole(rate_span_per_h: float, height: float) -> float:
    """The longest round pole distance H [mm] that draws the rate diagram at most *height* mm tall."""
    if rate_span_per_h <= 0:
        return POLE_DISTANCES[-1]
    fitting = [h for h in POLE_DISTANCES if h * rate_span_per_h <= height]
    return fitting[-1] if fitting else POLE_DISTANCES[0]


def abscissa_length(intervals: int, length_max: float = ABSCISSA_MAX) -> float:
    """L [mm]: the longest whole number of millimetres an interval, times *intervals*, within *length_max*
    (12 intervals: 120 mm, 10 mm each), so that the positions fall on whole millimetres."""
    if intervals < 1:
        return float(length_max)
    per = math.floor(length_max / intervals)
    return float(per * intervals) if per >= 1 else float(length_max)


def diagram_scales(duration: float, s, *, length_max: float = ABSCISSA_MAX, height: float = ORDINATE_MAX,
                   t=None, period: float | None = None, intervals: int | None = None) -> DiagramScales:
    """Round scales for the three diagrams of one output.

    L is a whole number of millimetres per interval between positions, at
    most *length_max* (:func:`abscissa_length`), and μ_t = duration / L (as
    the course writes μ_t = T / L); μ_s is the smallest round value (1, 2,
    2.5, 5 × 10ⁿ) that draws s at most *height* mm tall.  H₁ is
    the longest of :data:`POLE_DISTANCES` with which the v–t points (the
    chords' rates) stay within *height*; likewise H₂ for the a–t points;
    μ_v and μ_a follow from them.  *t* (the positions' times) and *period*
    are needed for the chords (default: equally spaced over *duration*);
    *intervals* the intervals between the positions on the abscissa
    (default: those of *s*).
    """
    s = np.asarray(s, dtype=float)
    if t is None:
        t = np.arange(len(s)) * duration / (len(s) if period is not None else len(s) - 1)
    if intervals is None:
        intervals = len(s) if period is not None else len(s) - 1
    length = abscissa_length(intervals, length_max)
    mu_t = duration / length
    span = _span(s)
    mu_s = round_up(span / height, TIME_MANTISSAS) if span > 0 else 1.0
    # drawn slopes: Δ(s/μ_s) / Δ(t/μ_t); a ray's intercept is H × that
    _, v = chords(t, s, period=period)
    drawn_v = _span(v) * mu_t / mu_s
    pole_v = _pole(drawn_v, height)
    mu_v = mu_s / (mu_t * pole_v)
    m, _ = chords(t, s, period=period)
    _, a = chords(m, v, period=period)
    drawn_a = _span(a) * mu_t / mu_v
    pole_a = _pole(drawn_a, height)
    mu_a = mu_v / (mu_t * pole_a)
    return DiagramScales(mu_t, length, mu_s, pole_v, mu_v, pole_a, mu_a)


@dataclass(frozen=True)
class OutputMotion:
    """What the method of chords is given: the output link's displacement at the project's positions.

    Attributes
    ----------
    kind : str
        ``"slider"`` (s in m, along its guide) or ``"rocker"`` (s the angle in rad, counter-clockwise positive).
    name : str
        The prismatic pair's name (a slider) or the link's name (a rocker).
    numbers : tuple of str
        The positions' numbers as the course writes them (``"0"``, ``"1"`` …).
    t : array (n,)
        Time [s] at which the driver reaches each position, from the first.
    s : array (n,)
        Displacement of the output from its place at the first position [m or rad].
    period : float or None
        T [s]: the positions close a cycle (the last is followed by the first
        one period later); None for an open series (a linear driver's stroke).
    lead, trail : (t, s) or None
        On an open series, a point one interval before the first position
        and one after the last (a crank's turn under a uniformly accelerated
        law: the crank turns on, and s repeats over its turn), so that the
        chords reach past the ends and the readings at the end positions
        are interpolated, not extrapolated.  Not drawn; None: the series
        ends at its positions (a linear driver's stroke).
    """

    kind: str
    name: str
    numbers: tuple
    t: np.ndarray
    s: np.ndarray
    period: float | None
    lead: tuple | None = None
    trail: tuple | None = None

    def points(self) -> tuple[np.ndarray, np.ndarray]:
        """(t, s) of the curve differentiated: the positions, with the *lead* and *trail* points on an open series."""
        t, s = np.asarray(self.t, dtype=float), np.asarray(self.s, dtype=float)
        if self.lead is not None:
            t, s = np.insert(t, 0, self.lead[0]), np.insert(s, 0, self.lead[1])
        if self.trail is not None:
            t, s = np.append(t, self.trail[0]), np.append(s, self.trail[1])
        return t, s

    @property
    def intervals(self) -> int:
        """The intervals between the positions over the abscissa: n on a closed cycle, n − 1 on an open series."""
        return len(self.t) if self.period is not None else len(self.t) - 1

    @property
    def unit(self) -> str:
        return "m" if self.kind == "slider" else "rad"

    @property
    def duration(self) -> float:
        return float(self.period if self.period is not None else self.t[-1] - self.t[0])


@dataclass(frozen=True)
class KinematicDiagrams:
    """The output link's s–t, v–t, a–t diagrams by graphical differentiation, and the comparison at every position.

    Attributes
    ----------
    motion : OutputMotion
    scales : DiagramScales
    velocity : Differentiation
        Chords of the s–t curve: v at the interval middles.
    acceleration : Differentiation
        Chords of the v–t points: a at the middles of the middles.
    v, a : array (n,)
        v and a at the positions read off the diagrams (the smooth curve
        through the chords' points) [m/s, m/s² or rad/s, rad/s²].
    v_tangents, a_tangents : array (n,)
        The method of tangents at the positions (a by tangents to the v–t
        curve of tangents).
    v_plans, a_plans : array (n,)
        From the velocity and acceleration plans at each position (NaN where
        a position has no plans).
    v_analytic, a_analytic : array (n,)
        The analytic (complex-number) values at the positions.
    reference : tuple of arrays or None
        ``(t, s, v, a)`` of the analytic solution over the cycle, densely, to
        draw beside the constructed curves for comparison (NaN where the
        mechanism is not assembled); never used by the construction.
    law : plans.motion.DriverLaw or None
        The driver's law over the cycle the times follow.
    plan_scales : dict or None
        ``{"k_l", "k_v", "k_a"}`` of the plans the "plans" column is read from.
    precision : float or None
        Their drafting precision [mm].
    driver : str or None
        The driver link's name (for the law's symbols: ω₂).
    positions : array (n,) or None
        The driver's position at each row: crank angle [rad] (running on in
        the sense of motion, not wrapped) or linear-driver position [m].
    start_phase : float or None
        A swing's phase ψ [rad] at position 0 (t = 0): the law's time origin
        (:meth:`plans.motion.DriverLaw.describe`).
    start : str or None
        Position 0: ``"output"`` (an extreme position of the output link) or
        ``"scene"`` (the scene's own), as :attr:`plans.motion.Cycle.start`.
    v_plans_step, a_plans_step : array (n,) or None
        The resolution of each "plans" value [its unit]: one drafting step of
        the segment read × the plan's scale factor (÷ the link length for a
        rocker's ω, ε), so that a table prints it to the digits its plan's
        readings do (NaN or None: four significant digits).
    """

    motion: OutputMotion
    scales: DiagramScales
    velocity: Differentiation
    acceleration: Differentiation
    v: np.ndarray
    a: np.ndarray
    v_tangents: np.ndarray
    a_tangents: np.ndarray
    v_plans: np.ndarray
    a_plans: np.ndarray
    v_analytic: np.ndarray
    a_analytic: np.ndarray
    reference: tuple | None = None
    law: object = None
    plan_scales: dict | None = None
    precision: float | None = None
    driver: str | None = None
    positions: np.ndarray | None = None
    start_phase: float | None = None
    start: str | None = None
    v_plans_step: np.ndarray | None = None
    a_plans_step: np.ndarray | None = None

    def errors(self) -> dict[str, np.ndarray]:
        """Errors against the analytic values, in % of the largest analytic |v| (|a|) over the positions.

        Keys ``v_diagram``, ``v_plans``, ``a_diagram``, ``a_plans`` (and
        ``v_tangents``, ``a_tangents``).  A per-cent of the value itself
        would be infinite where v passes through zero (an extreme position).
        """
        return {
            "v_diagram": relative_errors(self.v, self.v_analytic),
            "v_plans": relative_errors(self.v_plans, self.v_analytic),
            "v_tangents": relative_errors(self.v_tangents, self.v_analytic),
            "a_diagram": relative_errors(self.a, self.a_analytic),
            "a_plans": relative_errors(self.a_plans, self.a_analytic),
            "a_tangents": relative_errors(self.a_tangents, self.a_analytic),
        }

    def pages(self, *, lang: str = "en", title: str = "") -> list:
        """The diagrams as a one-figure list (a matplotlib Figure true to scale, at the scales an A4 page prints them
        readably, with a short caption; see :func:`plans.drawing.kinematic_diagrams.draw_kinematic_figure`).
        The comparison is :meth:`rows`; the handout sets the page with its table."""
        from .display import display_function

        return display_function("kinematic_pages")(self, lang=lang, title=title)

    def save(self, path, *, lang: str = "en", title: str = "") -> list:
        """Write the drawing of :meth:`pages` to *path* by its suffix (``.pdf``, ``.svg``, ``.png``).  Returns the paths written."""
        from .display import display_function

        return display_function("save_pages")([(str(k + 1), fig) for k, fig in enumerate(self.pages(lang=lang, title=title))], path)

    def _repr_svg_(self) -> str:
        from .display import display_function

        return display_function("svg_of_figure")(self.pages()[0])

    def rows(self) -> list[dict]:
        """One dict per position: number, t [s], s, v and a from the diagrams, the plans and analytic, errors [%]."""
        errors = self.errors()
        out = []
        for k, number in enumerate(self.motion.numbers):
            out.append({
                "position": number, "t": float(self.motion.t[k]), "s": float(self.motion.s[k]),
                "v_diagram": float(self.v[k]), "v_plans": float(self.v_plans[k]), "v_analytic": float(self.v_analytic[k]),
                "a_diagram": float(self.a[k]), "a_plans": float(self.a_plans[k]), "a_analytic": float(self.a_analytic[k]),
                **{f"error_{key}": float(value[k]) for key, value in errors.items()},
            })
        return out


def relative_errors(values, reference) -> np.ndarray:
    """``100 · (values − reference) / max|reference|`` [%] (NaN where either is missing)."""
    values, reference = np.asarray(values, dtype=float), np.asarray(reference, dtype=float)
    finite = reference[np.isfinite(reference)]
    largest = float(np.max(np.abs(finite))) if len(finite) else 0.0
    if largest == 0.0:
        return np.full(len(values), np.nan)
    return 100.0 * (values - reference) / largest


def kinematic_diagrams_of(motion: OutputMotion, *, v_plans=None, a_plans=None, v_analytic=None, a_analytic=None,
                          scales: DiagramScales | None = None, reference: tuple | None = None) -> KinematicDiagrams:
    """Differentiate the output's s(t) graphically and set the result beside the other methods' values.

    Only ``motion.t`` and ``motion.s`` enter the differentiation; the plans'
    and analytic values (arrays over the positions, NaN where missing) are
    carried for the comparison.
    """
    t, period = motion.t, motion.period
    if len(t) < 3:
        raise DiagramsError(f"kinematic diagrams: graphical differentiation needs at least 3 positions, got {len(t)}", "too_few")
    te, se = motion.points()
    if scales is None:
        scales = diagram_scales(motion.duration, se, t=te, period=period, intervals=motion.intervals)
    velocity = differentiate(te, se, period=period, pole=scales.pole_v, scale=scales.mu_v)
    acceleration = differentiate(velocity.middles, velocity.rates, period=period, pole=scales.pole_a, scale=scales.mu_a)
    v = smooth(velocity.middles, velocity.rates, t, period=period)
    a = smooth(acceleration.middles, acceleration.rates, t, period=period)
    inner = slice(1 if motion.lead is not None else 0, len(te) - (1 if motion.trail is not None else 0))
    v_tan_all = tangents(te, se, period=period)
    v_tan = v_tan_all[inner]
    a_tan = tangents(te, v_tan_all, period=period)[inner]
    n = len(t)
    nan = np.full(n, np.nan)

    def array(x):
        return nan.copy() if x is None else np.asarray(x, dtype=float)

    return KinematicDiagrams(motion, scales, velocity, acceleration, v, a, v_tan, a_tan,
                             array(v_plans), array(a_plans), array(v_analytic), array(a_analytic), reference)


# --- from a scene: the project's positions under the driver's law ------------------------


def _hints(scene, analytic, k: int) -> dict:
    """The scene's assembly hints moved to where the analytic solution puts the hinted points at row *k*
    (so that each position's construction follows the branch of the cycle, a swing's way back included)."""
    hints = {}
    for name, hint in scene.assembly.items():
        if isinstance(hint, (complex, float)) and name in analytic.points:
            z = complex(analytic.points[name].r[k])
            hints[name] = z if math.isfinite(z.real) and math.isfinite(z.imag) else hint
        else:
            hints[name] = hint
    return hints


def _output_columns(output, solution) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(s, v, a) of the output over an analytic solution: travel, v_rel, a_rel [m, m/s, m/s²] or angle
    (unwrapped along the rows), ω, ε [rad, rad/s, rad/s²]."""
    values = np.array(output.values(solution), dtype=float)
    rates = np.array(output.rates(solution), dtype=float)
    if output.kind == "slider":
        accelerations = np.array(solution.sliders[output.pair].a_rel, dtype=float)
    else:
        accelerations = np.array(solution.links[output.link].epsilon, dtype=float)
    valid = np.asarray(solution.valid, dtype=bool)
    for column in (values, rates, accelerations):
        column[~valid] = np.nan
    return values, rates, accelerations


def _plans_values(output, graphical) -> tuple[float, float]:
    """v and a of the output read off one position's velocity and acceleration plans."""
    if output.kind == "slider":
        reading = graphical.sliders[output.pair]
        v, a = reading["v_rel"], reading.get("a_rel", math.nan)
    else:
        reading = graphical.links[output.link]
        v, a = reading["omega"], reading.get("epsilon", math.nan)
    return float(v), float(a) if graphical.acceleration_plan is not None else math.nan


def _beyond(cycle, s: np.ndarray) -> tuple[tuple | None, tuple | None]:
    """The points one interval before the first and after the last position of a crank's closed turn
    (positions 0 … n, n one turn after 0) under a uniformly accelerated law: the crank angles one step
    further, s repeating over a turn (s there = s of positions n − 1 and 1), and their times under the law,
    t(φ) = (ω(φ) − ω_first)/ε; None where the driver would not get there (ω² ≤ 0 before the first)."""
    law = cycle.law
    x = np.asarray(cycle.positions, dtype=float)
    step = x[1] - x[0]
    omega = np.asarray(cycle.rate, dtype=float)

    def time(at: float) -> float | None:
        if law.acceleration == 0:
            return float(cycle.t[0] + (at - x[0]) / law.rate0)
        square = law.rate0**2 + 2 * law.acceleration * (at - law.x0)
        if square <= 0:
            return None
        return float(cycle.t[0] + (law.sense * math.sqrt(square) - omega[0]) / law.acceleration)

    before, after = time(x[0] - step), time(x[-1] + step)
    lead = (before, float(s[-2])) if before is not None else None
    trail = (after, float(s[1])) if after is not None else None
    return lead, trail


#: Positions of the dense analytic sweep drawn beside the constructed curves.
REFERENCE_STEPS = 360


def kinematic_diagrams(scene, positions: int = 12, *, law: str | None = None, start: str = "output", precision: float | None = None,
                       k_v: float | None = None, k_a: float | None = None, height: float = ORDINATE_MAX,
                       plans: bool = True) -> KinematicDiagrams:
    """The output link's kinematic diagrams by graphical differentiation, and the comparison at every position.

    Parameters
    ----------
    scene : Scene
    positions : int
        The project's positions over one cycle (8, 12, 24 …), numbered from
        the extreme position of the output link that starts its working
        stroke, in the sense of the driver's motion (:func:`plans.motion.driver_cycle`).
    law : str, optional
        The driver's law over the cycle (``"constant"``, ``"uniform"``,
        ``"harmonic"``); None: the scene's ``[driver] law`` or the default.
    start : {"output", "scene"}
        Position 0: the output's extreme position that starts its working
        stroke (default, as the course numbers them) or the scene's own.
    precision : float, optional
        Drafting precision [mm] of the plans' readings (default: the
        scene's ``[scales] precision``, else 0.1 mm as on a handout; 0: exact).
    k_v, k_a : float, optional
        The plans' scale factors, one for every position (default: the round
        factors that fit the largest of them, as on a plate).
    height : float
        The tallest a diagram is drawn [mm] (sets μ_s, H₁, H₂).
    plans : bool
        Construct the plans at every position for the "plans" column (False:
        that column NaN, for a caller that sets it from the plans it draws,
        :func:`with_plans`).

    Returns
    -------
    KinematicDiagrams
        s [m or rad], v [m/s or rad/s], a [m/s² or rad/s²] of the output (a
        slider along its guide, a rocker's angle counter-clockwise), t [s].

    Raises
    ------
    DiagramsError
        A :class:`plans.errors.PlansError`: no output slider or rocker (name one with ``[output] link``), fewer
        than 3 positions, or a position where the mechanism is not solved
        (graphical differentiation joins neighbouring positions).

    Only the s values at the positions enter the differentiation; the plans
    (:func:`plans.graphical.construct` at each position, the driver's ω and
    ε there under the law) and the analytic solution are its comparison.
    A crank turning at constant speed or a rocker input's swing is a
    repeating cycle (the chord from the last position to the first one a
    period later closes it); a uniformly accelerated crank's turn and a
    linear driver's stroke are not: their positions are an open series (the
    crank's with position 0 again at the end of the turn).
    """
    from dataclasses import replace

    from .graphical import construct
    from .motion import driver_cycle, output_link
    from .positions import common_scales, page_precision
    from .structure import find_structure

    if positions < 3:
        raise DiagramsError(f"{scene.source}: kinematic diagrams: graphical differentiation needs at least 3 positions, got {positions}", "too_few")
    structure = find_structure(scene)
    output = output_link(scene, structure)
    if output is None:
        raise DiagramsError(f"{scene.source}: kinematic diagrams: the mechanism has no output slider (on a frame guide) or rocker "
                            "(turning about a frame point); name one with [output] link = \"…\"", "no_output")
    first = driver_cycle(scene, positions, law=law, start=start, structure=structure)
    repeating = first.law.crank and first.law.kind in ("constant", "harmonic")
    cycle = first if repeating or not first.law.crank else driver_cycle(scene, positions, law=law, start=start, structure=structure, closed=True)
    analytic = cycle.solve(structure)
    unsolved = [k for k in range(len(cycle)) if not bool(analytic.valid[k])]
    if unsolved:
        raise DiagramsError(f"{scene.source}: kinematic diagrams: the mechanism is not solved at positions {', '.join(map(str, unsolved))}; "
                            "graphical differentiation joins neighbouring positions and needs every one", "unsolved", unsolved)
    values, rates, accelerations = _output_columns(output, analytic)
    s = values - values[0]
    t = np.asarray(cycle.t, dtype=float)
    period = float(cycle.period) if repeating else None
    numbers = tuple(str(k % positions) if cycle.law.crank else str(k) for k in range(len(cycle)))
    # the plans at every position, at one scale of each kind
    precision = page_precision(precision, scene)
    if plans:
        scenes = [replace(cycle.scene_at(k), assembly=_hints(scene, analytic, k)) for k in range(len(cycle))]
        scenes = [replace(x, scales=replace(x.scales, precision=precision)) for x in scenes]
        first_pass = [construct(x, structure, k_v=k_v, k_a=k_a, precision=precision, check_scales=False) for x in scenes]
        scales = common_scales(first_pass, given={"k_v": k_v, "k_a": k_a})
        graphicals = [construct(x, structure, k_l=scales["k_l"], k_v=scales["k_v"], k_a=scales.get("k_a"), precision=precision, check_scales=False)
                      for x in scenes]
        plans_v, plans_a = zip(*(_plans_values(output, g) for g in graphicals))
    else:
        scales, plans_v, plans_a = None, None, None
    lead = trail = None
    if not repeating and cycle.law.crank:  # the crank turns on: one position more at each end, s repeating over the turn
        lead, trail = _beyond(cycle, s)
    motion = OutputMotion(output.kind, output.pair if output.kind == "slider" else output.link, numbers, t, s, period, lead, trail)
    dense = driver_cycle(scene, REFERENCE_STEPS, law=law, start=start, structure=structure, closed=True)
    rs, rv, ra = _output_columns(output, dense.solve(structure))
    reference = (np.asarray(dense.t, dtype=float), rs - values[0], rv, ra)
    te, se = motion.points()
    scales_d = diagram_scales(motion.duration, se, t=te, period=period, height=height, intervals=motion.intervals)
    result = kinematic_diagrams_of(motion, v_plans=plans_v, a_plans=plans_a, v_analytic=rates, a_analytic=accelerations,
                                   scales=scales_d, reference=reference)
    return replace(result, law=cycle.law, plan_scales=dict(scales) if scales is not None else None, precision=precision, driver=scene.driver.link,
                   positions=np.asarray(cycle.positions, dtype=float),
                   start_phase=float(cycle.phase[0]) if cycle.law.kind == "harmonic" else None, start=cycle.start)


def with_plans(diagrams: KinematicDiagrams, v, a, *, v_step=None, a_step=None, plan_scales: dict | None = None,
               precision: float | None = None) -> KinematicDiagrams:
    """The same diagrams with the "plans" column taken from plans drawn elsewhere (a plate's, at its scales).

    *v*, *a*: arrays over the positions (the output's v_rel, a_rel along its guide [m/s, m/s²] or ω, ε
    counter-clockwise [rad/s, rad/s²] as read off each position's plans), NaN where a position has no such plan
    drawn; *v_step*, *a_step*: their resolutions (see :attr:`KinematicDiagrams.v_plans_step`).  The errors
    (:meth:`KinematicDiagrams.errors`) follow.
    """
    from dataclasses import replace

    n = len(diagrams.motion.t)

    def array(x):
        out = np.full(n, np.nan) if x is None else np.asarray(x, dtype=float)
        if out.shape != (n,):
            raise ValueError(f"with_plans: {n} values expected, got {out.shape}")
        return out

    return replace(diagrams, v_plans=array(v), a_plans=array(a), v_plans_step=array(v_step), a_plans_step=array(a_step),
                   plan_scales=plan_scales, precision=precision)


def rescaled(diagrams: KinematicDiagrams, height: float) -> KinematicDiagrams:
    """The same diagrams at the scales that draw each at most *height* mm tall (the construction's numbers unchanged)."""
    from dataclasses import replace

    motion = diagrams.motion
    t, s = motion.points()
    scales = diagram_scales(motion.duration, s, t=t, period=motion.period, height=height, intervals=motion.intervals)
    velocity = replace(diagrams.velocity, pole=scales.pole_v, scale=scales.mu_v)
    acceleration = replace(diagrams.acceleration, pole=scales.pole_a, scale=scales.mu_a)
    return replace(diagrams, scales=scales, velocity=velocity, acceleration=acceleration)


#: The height [mm] a page aims each diagram's ordinate range at (its round scale draws it between 3/4 of this and
#: this: at least 40 mm).
READABLE_HEIGHT = 54.0
#: The shortest pole distance [mm] a page draws (a shorter one makes the rays too steep to carry a chord's slope).
POLE_MIN = 10.0
#: Round mantissas of μ_s, μ_v, μ_a on a page (finer than the textbook's, so a diagram fills its height).
PAGE_MANTISSAS = (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8)


def _extent(values) -> float:
    """The drawn range of an ordinate with its abscissa: max(values, 0) − min(values, 0)."""
    values = np.asarray(values, dtype=float)
    values = values[np.isfinite(values)]
    if not len(values):
        return 0.0
    return float(max(values.max(), 0.0) - min(values.min(), 0.0))


def flat(diagrams: KinematicDiagrams, key: str) -> float | None:
    """The constant value of the rate *key* (``"v"`` or ``"a"``) when its chords give the same value over the whole
    series (0 for a quantity identically zero: a uniform motion's acceleration), else None.

    Its diagram would be a line parallel to the t axis: a page says the value instead of drawing it.  A rate is
    constant when its chords' values differ by at most 10⁻⁶ of the largest of them (or of the output's natural
    scale, its span over the cycle time, for a rate that is zero up to round-off).
    """
    motion = diagrams.motion
    if key == "a":
        below = flat(diagrams, "v")
        if below is not None:
            return 0.0  # the rate of a constant
    rates = (diagrams.velocity if key == "v" else diagrams.acceleration).rates
    rates = np.asarray(rates, dtype=float)
    rates = rates[np.isfinite(rates)]
    if not len(rates):
        return None
    duration = motion.duration or 1.0
    natural = _span(motion.s) / duration ** (1 if key == "v" else 2)
    if float(np.ptp(rates)) > 1e-6 * max(float(np.max(np.abs(rates))), natural):
        return None
    value = float(np.mean(rates))
    return 0.0 if abs(value) <= 1e-9 * natural else value


def _rate_scale(extent: float, mu_below: float, mu_t: float, height: float, pole_max: float) -> tuple[float, float, bool]:
    """(μ, H, fits) of a rate diagram: μ the smallest round value that draws *extent* at most *height* mm tall, H
    [mm] the pole distance that gives it (μ = μ_below/(μ_t·H)); H at least :data:`POLE_MIN` (a taller diagram
    then); *fits*: H within *pole_max* (else μ is the smallest round value with H ≤ *pole_max*, a shorter diagram)."""
    if extent <= 0:
        mu = round_up(mu_below / (mu_t * min(20.0, pole_max)), PAGE_MANTISSAS)
        return mu, mu_below / (mu_t * mu), True
    mu = round_up(extent / height, PAGE_MANTISSAS)
    pole = mu_below / (mu_t * mu)
    if pole < POLE_MIN:
        mu = rounding.round_down(mu_below / (mu_t * POLE_MIN), PAGE_MANTISSAS)
        pole = mu_below / (mu_t * mu)
    if pole <= pole_max:
        return mu, pole, True
    mu = round_up(mu_below / (mu_t * pole_max), PAGE_MANTISSAS)
    return mu, mu_below / (mu_t * mu), False


def readable(diagrams: KinematicDiagrams, room: float, *, height: float = READABLE_HEIGHT,
             length_max: float = ABSCISSA_MAX) -> KinematicDiagrams:
    """The same diagrams at the round scales a page prints them readably (the construction's numbers unchanged).

    μ_s (rad/mm or m/mm), μ_v and μ_a are the smallest round values (:data:`PAGE_MANTISSAS`) that draw each
    diagram's ordinate range (its values with the abscissa) at most *height* mm tall — so at least ¾ of it; the
    pole distances follow, H₁ = μ_s/(μ_t·μ_v) and H₂ = μ_v/(μ_t·μ_a) [mm], at least :data:`POLE_MIN`.  *room*
    [mm] is what the page gives the abscissa and the longer pole together (L + max(H₁, H₂)): L is the longest
    whole number of millimetres per interval within *length_max* (as :func:`abscissa_length`) with which both
    poles fit; when no L down to half of it lets them, the longest L with the poles cut to the room (shorter
    rate diagrams).  μ_t = T/L.  A rate constant over the series (:func:`flat`) keeps a pole of 20 mm: it is
    not drawn.
    """
    from dataclasses import replace

    motion = diagrams.motion
    duration = motion.duration
    intervals = max(motion.intervals, 1)
    # each ordinate's values: the points and the smooth curve through them over the abscissa (it reaches past an
    # open series' last chord middles to its ends)
    dense = np.linspace(0.0, duration, 241) + float(motion.t[0])
    t, s = motion.points()
    vel, acc = diagrams.velocity, diagrams.acceleration
    extent_s = _extent(np.concatenate([motion.s, smooth(t, s, dense, period=motion.period)]))
    mu_s = round_up(extent_s / height, PAGE_MANTISSAS) if extent_s > 0 else 1.0
    extent_v = 0.0 if flat(diagrams, "v") is not None else _extent(np.concatenate([vel.rates, smooth(vel.middles, vel.rates, dense, period=motion.period)]))
    extent_a = 0.0 if flat(diagrams, "a") is not None else _extent(np.concatenate([acc.rates, smooth(acc.middles, acc.rates, dense, period=motion.period)]))
    longest = abscissa_length(intervals, length_max)
    per = int(round(longest / intervals))
    choice = None
    for each in range(per, max(1, per // 2) - 1, -1):
        length = float(each * intervals)
        mu_t = duration / length
        mu_v, pole_v, fits_v = _rate_scale(extent_v, mu_s, mu_t, height, room - length)
        mu_a, pole_a, fits_a = _rate_scale(extent_a, mu_v, mu_t, height, room - length)
        if choice is None or (fits_v and fits_a):
            choice = DiagramScales(mu_t, length, mu_s, pole_v, mu_v, pole_a, mu_a)
        if fits_v and fits_a:
            break
    velocity = replace(diagrams.velocity, pole=choice.pole_v, scale=choice.mu_v)
    acceleration = replace(diagrams.acceleration, pole=choice.pole_a, scale=choice.mu_a)
    return replace(diagrams, scales=choice, velocity=velocity, acceleration=acceleration)
