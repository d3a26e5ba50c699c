"""Structure of a linkage: the driver, then Assur dyads in an order where each
attaches to links already known.

A dyad is two links i and j and three joints: an outer joint of i with a known
body, an inner joint between i and j, and an outer joint of j with a known
body.  R is a revolute, P a prismatic joint.  The five kinds and how plans
orders their links (the order every solver and construction relies on)::

    RRR   B ──(i)── C ──(j)── D        outer R at B, inner R at C, outer R at D
    RRP   B ──(i)── C ──(j)══ guide    i: outer R; j: outer P (j is a block or carries a line)
    RPR   B ──(i)══(j)── E             i carries the guide line of the inner P, j the sliding line
    PRP   guide ══(i)── C ──(j)══ guide
    RPP   B ──(i)══(j)══ guide         i: outer R; j: inner P with i and outer P

The mobility follows Chebychev–Grübler for planar chains with lower pairs,
W = 3n − 2p, where n counts the moving links and p the joints.
"""

from __future__ import annotations

from dataclasses import dataclass

from .errors import StructureError
from .scene import FRAME, Crank, LinearDriver, Prismatic, Scene, body_words

__all__ = ["Joint", "Group", "Structure", "find_structure", "mobility"]


@dataclass(frozen=True)
class Joint:
    """One kinematic pair between two bodies.

    Attributes
    ----------
    kind : str
        ``"R"`` (revolute) or ``"P"`` (prismatic).
    bodies : tuple[str, str]
        The two bodies it joins.  For an outer joint of a group, the first is
        the group's link and the second the known body.
    point : str or None
        For R, the shared point name.
    prismatic : Prismatic or None
        For P, the joint as declared in the scene (slider and guide lines).
    """

    kind: str
    bodies: tuple[str, str]
    point: str | None = None
    prismatic: Prismatic | None = None

    def other(self, body: str) -> str:
        a, b = self.bodies
        return b if body == a else a

    def label(self) -> str:
        if self.kind == "R":
            return self.point
        return self.prismatic.name


@dataclass(frozen=True)
class Group:
    """A class-II Assur group (dyad), links ordered as in the module docstring.

    Attributes
    ----------
    kind : str
        ``"RRR"``, ``"RRP"``, ``"RPR"``, ``"PRP"`` or ``"RPP"``.
    links : tuple[str, str]
        (i, j).
    outer_i, inner, outer_j : Joint
        ``outer_i.bodies == (i, known)``, ``inner.bodies == (i, j)``,
        ``outer_j.bodies == (j, known)``.
    """

    kind: str
    links: tuple[str, str]
    outer_i: Joint
    inner: Joint
    outer_j: Joint

    @property
    def name(self) -> str:
        """``"RRR(3,4)"``, links in ascending order as textbooks write them."""
        return f"{self.kind}({','.join(_sorted_names(self.links))})"

    @property
    def joint(self) -> str:
        """The joint whose image the group's two construction lines place on the plans.

        RRR, RRP, PRP: the inner joint C; RPR: the sleeve's pivot E (outer
        joint of j); RPP: the pin B (outer joint of i).
        """
        if self.kind == "RPR":
            return self.outer_j.point
        if self.kind == "RPP":
            return self.outer_i.point
        return self.inner.point

    @property
    def points(self) -> list[str]:
        """The joint point names of the group (R joints only)."""
        return [j.point for j in (self.outer_i, self.inner, self.outer_j) if j.kind == "R"]


@dataclass(frozen=True)
class Structure:
    """The driver and the groups in solving order."""

    driver: str
    groups: tuple[Group, ...]
    mobility: int

    @property
    def formula(self) -> str:
        """The structural formula, such as ``I(0,2) → RRR(3,4) → RPR(5,6)``."""
        return " → ".join([f"I(0,{self.driver})"] + [g.name for g in self.groups])

    def group_of(self, link: str) -> Group | None:
        for group in self.groups:
            if link in group.links:
                return group
        return None


def _sorted_names(names) -> list[str]:
    return sorted(names, key=lambda n: (0, int(n), "") if n.isdigit() else (1, 0, n))


def _joints(scene: Scene) -> list[Joint]:
    """All pairs of the scene, the driver's included, in a stable order."""
    joints: list[Joint] = []
    for point in scene.point_names:
        bodies = scene.bodies_with(point)
        # a point shared by k bodies is k − 1 revolute joints, all to the first body
        for other in bodies[1:]:
            joints.append(Joint("R", (bodies[0], other), point=point))
    for prismatic in scene.prismatics:
        joints.append(Joint("P", (prismatic.slider, prismatic.guide), prismatic=prismatic))
    driver = scene.driver
    if isinstance(driver, LinearDriver):
        joints.append(
            Joint("P", (driver.link, FRAME), prismatic=Prismatic(f"{driver.point}:{FRAME}.{driver.guide}", driver.link, "", FRAME, driver.guide))
        )
    return joints


def mobility(scene: Scene) -> tuple[int, int, int]:
    """Chebychev–Grübler count ``(W, n, p)`` with W = 3n − 2p."""
    n = len(scene.links)
    p = len(_joints(scene))
    return 3 * n - 2 * p, n, p


def _between(joints: list[Joint], a: str, b: str) -> list[Joint]:
    return [j for j in joints if set(j.bodies) == {a, b}]


def _outer(joints: list[Joint], link: str, known: set[str]) -> list[Joint]:
    """Joints of *link* with known bodies, one per shared point (oriented link → known)."""
    found: dict[object, Joint] = {}
    for j in joints:
        if link in j.bodies and j.other(link) in known:
            key = ("R", j.point) if j.kind == "R" else ("P", j.prismatic.name)
            found.setdefault(key, Joint(j.kind, (link, j.other(link)), j.point, j.prismatic))
    return list(found.values())


_KINDS = {
    ("R", "R", "R"): "RRR",
    ("R", "R", "P"): "RRP",
    ("R", "P", "R"): "RPR",
    ("P", "R", "P"): "PRP",
    ("R", "P", "P"): "RPP",
}


def _make_group(i: str, j: str, outer_i: Joint, inner: Joint, outer_j: Joint) -> Group | None:
    pattern = (outer_i.kind, inner.kind, outer_j.kind)
    if pattern not in _KINDS:
        pattern = pattern[::-1]
        i, j, outer_i, outer_j = j, i, outer_j, outer_i
    kind = _KINDS.get(pattern)
    if kind is None:
        return None
    if kind == "RPR" and inner.prismatic.guide != i:
        i, j, outer_i, outer_j = j, i, outer_j, outer_i
    inner = Joint(inner.kind, (i, j), inner.point, inner.prismatic)
    return Group(kind, (i, j), outer_i, inner, outer_j)


def find_structure(scene: Scene) -> Structure:
    """Find the driver and the dyads in an order where each attaches to known links.

    Raises
    ------
    StructureError
        When the mobility is not 1, or the links left over do not form dyads
        (a class III group or higher), naming the links involved.
    """
    w, n, p = mobility(scene)
    driver = scene.driver.link
    if w != 1:
        advice = (
            "a link or joint is missing: the mechanism can move without the driver"
            if w > 1
            else "there are too many joints: the mechanism is locked or over-constrained"
        )
        raise StructureError(
            f"{scene.source}: mobility W = 3n − 2p = 3·{n} − 2·{p} = {w}, but a mechanism with one driver needs W = 1; {advice}"
            + (_loose_points(scene) if w > 1 else "")
        )
    joints = _joints(scene)
    if isinstance(scene.driver, Crank):
        crank_frame = [j for j in _between(joints, driver, FRAME)]
        if len(crank_frame) != 1:
            raise StructureError(f"{scene.source}: crank {driver} must be joined to the frame by its pivot only")
    known = {FRAME, driver}
    order = [name for name in scene.links if name != driver]
    groups: list[Group] = []
    progress = True
    while progress:
        progress = False
        unknown = [name for name in order if name not in known]
        for a_index, a in enumerate(unknown):
            for b in unknown[a_index + 1 :]:
                inner = _between(joints, a, b)
                if len(inner) != 1:
                    continue
                outer_a = _outer(joints, a, known)
                outer_b = _outer(joints, b, known)
                if len(outer_a) != 1 or len(outer_b) != 1:
                    continue
                group = _make_group(a, b, outer_a[0], inner[0], outer_b[0])
                if group is None:
                    raise StructureError(
                        f"{scene.source}: links {a} and {b} form a PPP group, which has no definite position; "
                        "replace one prismatic joint by a revolute"
                    )
                groups.append(group)
                known |= {a, b}
                progress = True
                break
            if progress:
                break
    left = [name for name in order if name not in known]
    if left:
        for name in left:
            outer = _outer(joints, name, known)
            if len(outer) >= 2:
                raise StructureError(
                    f"{scene.source}: link {name} is joined to known links at {', '.join(j.label() for j in outer)}: "
                    "a single link held by two joints cannot move (it is part of a structure, not a dyad)"
                )
        solved = ", ".join(["the frame"] + _sorted_names([k for k in known if k != FRAME]))
        detail = "; ".join(_joins(joints, name, known) for name in _sorted_names(left))
        raise StructureError(
            f"{scene.source}: links {', '.join(_sorted_names(left))} do not form class-II Assur groups (dyads) "
            f"attached to links solved before them ({solved}): {detail}; each dyad needs one joint from each of its "
            "two links to a solved link; plans solves dyads only (a class III group or higher needs an iterative solution)"
        )
    return Structure(driver, tuple(groups), w)


def _joins(joints: list[Joint], link: str, known: set[str]) -> str:
    """``link 5: E with 6, G with 7 (not solved)`` for a message."""
    parts = []
    for j in joints:
        if link in j.bodies:
            other = j.other(link)
            state = "" if other in known else " (not solved)"
            parts.append(f"{j.label()} with {'the frame' if other == FRAME else other}{state}")
    return f"link {link} joins " + (", ".join(parts) if parts else "nothing")


def _loose_points(scene: Scene) -> str:
    """Points of moving links that no other body has, with close names that may have been meant."""
    import difflib

    names = scene.point_names
    loose = []
    for name in names:
        bodies = scene.bodies_with(name)
        if len(bodies) == 1 and bodies[0] != FRAME and not scene.bodies[bodies[0]].block:
            close = [n for n in names if n != name and (n.lower() == name.lower() or n in difflib.get_close_matches(name, names, n=3, cutoff=0.8))]
            if close:
                owners = " and ".join(body_words(b) for b in scene.bodies_with(close[0]))
                loose.append(f"{name} of link {bodies[0]} (did you mean {close[0]!r}, of {owners}?)")
    if not loose:
        return ""
    return "; a joint is where two bodies name the same point, and only one link has " + ", ".join(loose)

