"""What the analytic solver returns: motions over N driver positions, as frozen data.

All arrays have shape (N,), one entry per driver position, in SI units
(m, rad, s); angles counter-clockwise from +x, ω and ε counter-clockwise
positive.  Points and vectors are complex numbers ``x + iy``.  The arrays are
read-only.

The solver computes every number before it returns, but it makes the
result's dicts of motions (``links``, ``points``, ``sliders``, ``poses``,
``origins``, ``conditions``, ``sines``) and ``valid``, and their arrays,
only when each is first read (:meth:`AnalyticSolution._deferred`): at one
position, building some forty arrays and a dozen objects that a caller may
not look at cost as much as the mechanics itself.  Reading gives the same
values, kept for the next read.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..limits import NearDeadCentre, chain_rel_error, expected_rel_error
from ..scene import Scene
from ..structure import Structure

__all__ = ["LinkMotion", "PointMotion", "SliderMotion", "AnalyticSolution", "frozen"]


@dataclass(frozen=True, eq=False)
class LinkMotion:
    """Angle and angular motion of a body.

    Attributes
    ----------
    phi : float array (N,)
        Angle of the body's own x axis [rad].  The crank's is the driver
        position as given; every other body's is wrapped to (−π, π].
    omega : float array (N,)
        Angular velocity [rad/s].
    epsilon : float array (N,)
        Angular acceleration [rad/s²].
    """

    phi: np.ndarray
    omega: np.ndarray
    epsilon: np.ndarray


@dataclass(frozen=True, eq=False)
class PointMotion:
    """Position r [m], velocity v [m/s] and acceleration a [m/s²] of a point, complex arrays (N,)."""

    r: np.ndarray
    v: np.ndarray
    a: np.ndarray


@dataclass(frozen=True, eq=False)
class SliderMotion:
    """Motion in a prismatic pair, relative to its guide.

    Attributes
    ----------
    s : float array (N,)
        Travel ``(Q_s − Q_g)·u_g`` [m]: Q_s, Q_g the origins (through points)
        of the slider's and the guide's lines, u_g the guide's unit direction.
    v_rel : float array (N,)
        ds/dt [m/s]; the relative velocity vector is ``v_rel·u_g``.
    a_rel : float array (N,)
        d²s/dt² [m/s²]; the relative acceleration aʳ is ``a_rel·u_g``.
    coriolis : complex array (N,)
        Coriolis acceleration ``aᵏ = 2iω_g·v_rel·u_g`` [m/s²] (zero on a guide
        that does not turn).
    """

    s: np.ndarray
    v_rel: np.ndarray
    a_rel: np.ndarray
    coriolis: np.ndarray


@dataclass(frozen=True, eq=False)
class AnalyticSolution:
    """Kinematics of a linkage at N driver positions, by the complex-number method.

    Attributes
    ----------
    scene : Scene
    structure : Structure
    driver : float array (N,)
        The driver positions: crank angle φ [rad] or linear-driver position s [m].
    links : dict[str, LinkMotion]
        Every moving body (driver, links, slider blocks), by name.
    points : dict[str, PointMotion]
        Every named point, frame points included (fixed r, zero v and a).
    sliders : dict[str, SliderMotion]
        Every prismatic pair of ``scene.prismatics``, by its name.
    poses : dict[str, tuple[numpy.ndarray, numpy.ndarray]]
        Every body (frame included) as ``(phi, origin)``: its angle [rad] and
        the global position of its own point (0, 0) [m].
    origins : dict[str, PointMotion]
        Motion of every body's own origin; with ``links`` it gives the
        motion of any point of the body (:meth:`motion_of`).
    conditions : dict[str, numpy.ndarray]
        Per group (``group.name``), the 2-norm condition number of its 2×2
        velocity matrix with unit columns (1 for perpendicular construction
        lines, growing without bound towards a dead centre; NaN where the
        group is not assembled).
    sines : dict[str, numpy.ndarray]
        Per group, |sin| of the angle between the two construction lines.
    valid : bool array (N,)
        False where some group cannot be assembled or sits at a dead centre
        (only with ``allow_partial=True``; the unknown values are NaN there).
    warnings : tuple[plans.limits.NearDeadCentre, ...]
        Groups near a dead centre (condition above the solver's
        ``warn_condition``): one per group and run of consecutive positions.
    """

    scene: Scene
    structure: Structure
    driver: np.ndarray
    links: dict[str, LinkMotion]
    points: dict[str, PointMotion]
    sliders: dict[str, SliderMotion]
    poses: dict[str, tuple[np.ndarray, np.ndarray]]
    origins: dict[str, PointMotion]
    conditions: dict[str, np.ndarray]
    sines: dict[str, np.ndarray]
    valid: np.ndarray
    warnings: tuple[NearDeadCentre, ...] = ()

    @classmethod
    def _deferred(cls, scene: Scene, structure: Structure, driver: np.ndarray, warnings: tuple, build, known: dict | None = None) -> "AnalyticSolution":
        """A solution whose other attributes are made when first read, by ``build(name)`` (once each).

        *known*: attributes made already.  Reading gives the same values as
        a solution made with all of them; the solver uses this (see the
        module docstring).
        """
        self = object.__new__(cls)
        vars(self).update(known or {}, scene=scene, structure=structure, driver=driver, warnings=warnings, _build=build)
        return self

    def __getstate__(self) -> dict:
        """Every attribute made (for copy and pickle)."""
        state = {name: getattr(self, name) for name in _ALL}
        return state

    def expected_rel_errors(self, group: str) -> np.ndarray:
        """Expected relative error of the group's velocities and accelerations, 4·ε_mach·cond², per position.

        See :mod:`plans.limits`; NaN where the group is not assembled.
        """
        return expected_rel_error(np.asarray(self.conditions[group]))

    def expected_chain_rel_errors(self, group: str) -> np.ndarray:
        """Expected relative error of the group's velocities and accelerations with the errors it inherits, per position.

        A group solved from points or guides of earlier groups inherits their
        errors, amplified by its own condition (see :mod:`plans.limits`)::

            E_k = 4·ε_mach·cond_k² + cond_k · max E_g   over the groups g it takes a known point or guide from

        Relative to the scale of each kind of quantity (the largest |v|, |a|
        of the group's points), not to each quantity itself.  NaN where a
        group it depends on is not assembled.
        """
        groups = {g.name: g for g in self.structure.groups}
        solved_by = {link: g.name for g in self.structure.groups for link in g.links}
        figures: dict[str, np.ndarray] = {}

        def figure(name: str) -> np.ndarray:
            if name not in figures:
                g = groups[name]
                upstream = [solved_by[joint.bodies[1]] for joint in (g.outer_i, g.outer_j) if joint.bodies[1] in solved_by]
                inherited = np.zeros(len(self)) if not upstream else np.maximum.reduce([figure(u) for u in upstream] + [np.zeros(len(self))])
                figures[name] = chain_rel_error(np.asarray(self.conditions[name], dtype=float), inherited)
            return figures[name]

        return figure(group)

    def animate(self, positions: int = 36, *, lang: str = "en"):
        """The mechanism and its plans over the cycle from the scene's position, at one set of scale factors for
        all *positions*: a :class:`plans.lecture.Animation`, which a notebook shows as the lecture page
        (``.save("page.html")``, ``"anim.gif"``, ``"anim.mp4"`` writes it).  Drawn by :mod:`plans.notebook`."""
        from ..display import display_function

        return display_function("animate")(self.scene, positions, lang=lang)

    def __len__(self) -> int:
        return len(self.driver)

    @property
    def branches(self):
        """The assembly branch of each group at the first position, as :class:`plans.structure.Branch`
        records (sign, words such as ``"C to the left of B→D"``, whether another assembly exists);
        ``solution.at(k).branches`` for position k.  See :func:`plans.structure.branches`."""
        from ..structure import branches

        return branches(self)

    def motion_of(self, body: str, z: complex) -> PointMotion:
        """Motion of the point with own coordinates z [m] of a body.

        ``r = r_O + e^{iφ} z``, ``v = v_O + iω (r − r_O)``,
        ``a = a_O + (iε − ω²)(r − r_O)``.
        """
        phi, _ = self.poses[body]
        origin = self.origins[body]
        if body in self.links:
            omega, epsilon = self.links[body].omega, self.links[body].epsilon
        else:
            omega = epsilon = np.zeros_like(phi)
        r_Or = np.exp(1j * phi) * z
        return PointMotion(
            origin.r + r_Or,
            origin.v + 1j * omega * r_Or,
            origin.a + (1j * epsilon - omega**2) * r_Or,
        )

    def at(self, k) -> "AnalyticSolution":
        """The solution at position(s) k (an index, slice or index array), as a new solution."""
        index = np.atleast_1d(np.arange(len(self))[k])

        def cut(x):
            return frozen(np.asarray(x)[index])  # fancy indexing copies

        return AnalyticSolution(
            scene=self.scene,
            structure=self.structure,
            driver=cut(self.driver),
            links={n: LinkMotion(cut(m.phi), cut(m.omega), cut(m.epsilon)) for n, m in self.links.items()},
            points={n: PointMotion(cut(m.r), cut(m.v), cut(m.a)) for n, m in self.points.items()},
            sliders={n: SliderMotion(cut(m.s), cut(m.v_rel), cut(m.a_rel), cut(m.coriolis)) for n, m in self.sliders.items()},
            poses={n: (cut(phi), cut(origin)) for n, (phi, origin) in self.poses.items()},
            origins={n: PointMotion(cut(m.r), cut(m.v), cut(m.a)) for n, m in self.origins.items()},
            conditions={n: cut(c) for n, c in self.conditions.items()},
            sines={n: cut(c) for n, c in self.sines.items()},
            valid=cut(self.valid),
            warnings=tuple(w for w in self.warnings if np.any(np.asarray(self.driver)[index] == w.position)),
        )


#: The attributes of a solution, and those a deferred one makes when first read.
_ALL = ("scene", "structure", "driver", "links", "points", "sliders", "poses", "origins", "conditions", "sines", "valid", "warnings")
_DEFERRED = ("links", "points", "sliders", "poses", "origins", "conditions", "sines", "valid")


class _MadeOnFirstRead:
    """An attribute of a deferred :class:`AnalyticSolution`, made by its ``_build`` when first read, then kept.

    It is kept in the instance's ``__dict__``, which Python reads before this
    (a descriptor without ``__set__``): so a solution made with every
    attribute, and a deferred one after its first read, never come here.
    """

    def __init__(self, name: str):
        self.name = name

    def __get__(self, solution, owner=None):
        if solution is None:
            return self
        made = vars(solution)
        build = made.get("_build")
        if build is None:
            raise AttributeError(f"{owner.__name__!r} object has no attribute {self.name!r}")
        value = made[self.name] = build(self.name)
        return value


# set after the dataclass is made, so that they are not taken for default values of its fields
for _name in _DEFERRED:
    setattr(AnalyticSolution, _name, _MadeOnFirstRead(_name))


def frozen(array: np.ndarray) -> np.ndarray:
    """A read-only view of an array the solver owns."""
    view = np.asarray(array).view()
    view.setflags(write=False)
    return view
