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

import cmath
import math
from dataclasses import dataclass

from .errors import SceneError, StructureError
from .scene import FRAME, Crank, LinearDriver, Prismatic, Scene, body_words

__all__ = ["Joint", "Group", "Structure", "Branch", "find_structure", "mobility", "branch_points", "branches"]


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
    #: The links in the order a branch sign is stated in (see :attr:`orientation`);
    #: empty: the order of ``links``.
    sign_order: tuple[str, ...] = ()

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

    @property
    def two_assemblies(self) -> bool:
        """True for RRR, RRP and RPR (two assembly branches); PRP and RPP have one."""
        return self.kind in ("RRR", "RRP", "RPR")

    @property
    def orientation(self) -> int:
        """+1 when the solvers' link order (i, j) is :attr:`sign_order`, else −1.

        The branch sign a scene writes (and plans reports) is stated with the
        links in one order that does not depend on the order of the file or
        on whether a sliding pair is written ``[[slider]]`` or ``[[prismatic]]``
        (which decides i and j of an RPR): RRR, the order of the group's name
        (``RRR(3,4)``: from the outer joint of link 3 to that of link 4); RPR,
        the link that is not a slider block first, else the order of the
        name.  The solvers' sign is this sign times the orientation.  RRP,
        PRP, RPP: +1 (their convention does not depend on the order).
        """
        if self.kind in ("RRR", "RPR") and self.sign_order and tuple(self.sign_order) != tuple(self.links):
            return -1
        return 1


@dataclass(frozen=True)
class Structure:
    """The driver and the groups in solving order."""

    driver: str
    groups: tuple[Group, ...]
    mobility: int
    #: The frame's number (:attr:`plans.scene.Scene.frame_number`).
    frame: str = "1"

    @property
    def formula(self) -> str:
        """The structural formula, such as ``I(1,2) → RRR(3,4) → RPR(5,6)`` (the frame's number first)."""
        return " → ".join([f"I({self.frame},{self.driver})"] + [g.name for g in self.groups])

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


def _shared_points(scene: Scene) -> str:
    """The points joining three bodies or more, named with their bodies (each such pin is k − 1 joints)."""
    parts = []
    for point in scene.point_names:
        bodies = scene.bodies_with(point)
        if len(bodies) >= 3:
            names = [body_words(b) for b in bodies]
            parts.append(f"point {point} joins {len(bodies)} bodies ({', '.join(names[:-1])} and {names[-1]}): "
                         f"a pin shared by {len(bodies)} bodies is {len(bodies) - 1} revolute joints")
    if not parts:
        return ""
    return "; " + "; ".join(parts) + " (give each link its own point where it should not be pinned to the others)"


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


def _with_sign_order(scene: Scene, group: Group) -> Group:
    """The group with the link order its branch sign is stated in (:attr:`Group.orientation`)."""
    order = tuple(_sorted_names(group.links))
    if group.kind == "RPR":
        blocks = [link for link in group.links if scene.bodies[link].block]
        if len(blocks) == 1:
            order = tuple(link for link in group.links if link not in blocks) + tuple(blocks)
    return Group(group.kind, group.links, group.outer_i, group.inner, group.outer_j, order)


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
            + (_loose_points(scene) if w > 1 else _shared_points(scene))
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
                groups.append(_with_sign_order(scene, group))
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
    structure = Structure(driver, tuple(groups), w, scene.frame_number)
    check_assembly(scene, structure)
    return structure


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



# --- assembly branches ----------------------------------------------------------


def _outer_points(group: Group) -> set[str]:
    return {o.point for o in (group.outer_i, group.outer_j) if o.kind == "R"}


def branch_points(scene: Scene, group: Group) -> list[str]:
    """The points an ``[assembly]`` key may name to choose the group's branch.

    The points of the group's two links, except its outer joints (they are
    where they are on both branches).  Empty for a group with one assembly.
    """
    if not group.two_assemblies:
        return []
    outer = _outer_points(group)
    names: list[str] = []
    for link in _sorted_names(group.links):
        for name in scene.bodies[link].points:
            if name not in outer and name not in names:
                names.append(name)
    return names


def check_assembly(scene: Scene, structure: "Structure") -> None:
    """Refuse ``[assembly]`` keys that cannot choose a branch, and two keys for one group.

    A key chooses the branch of the first group (in solving order) whose
    :func:`branch_points` include it.  A frame point, a point of the driver,
    an outer joint of a group and a point of a group with one assembly choose
    nothing: the error names the points that do choose each group's branch.
    """
    chosen: dict[str, str] = {}
    for name in scene.assembly:
        group = next((g for g in structure.groups if name in branch_points(scene, g)), None)
        field = _assembly_field(scene, name)
        if group is None:
            raise SceneError(f"{_why_not(scene, structure, name)}; {_who_decides(scene, structure)}", scene.source, field)
        if group.name in chosen:
            raise SceneError(
                f"{chosen[group.name]} and {name} both choose the branch of {group.name}; give one of them",
                scene.source,
                field,
            )
        chosen[group.name] = name


def _assembly_field(scene: Scene, name: str) -> str:
    line = getattr(scene, "key_lines", {}).get(f"assembly.{name}")
    return f"assembly.{name} (line {line})" if line else f"assembly.{name}"


def _why_not(scene: Scene, structure: Structure, name: str) -> str:
    """Why the point *name* cannot choose a branch."""
    owners = scene.bodies_with(name)
    if set(owners) <= {FRAME, structure.driver}:
        if FRAME in owners:
            also = f" (and of the driver, link {structure.driver})" if structure.driver in owners else ""
            return f"{name} is a point of the frame{also}, which does not move: it cannot choose an assembly branch"
    for group in structure.groups:
        if name in _outer_points(group) and any(name in scene.bodies[link].points for link in group.links):
            known = [b for b in owners if b not in group.links]
            return (
                f"{name} joins {group.name} to {' and '.join(body_words(b) for b in known)} (an outer joint): it lies "
                "where it lies on both branches, so it cannot choose one"
            )
        if name in scene.bodies[group.links[0]].points or name in scene.bodies[group.links[1]].points:
            return f"{group.name} has one assembly only: there is no branch for {name} to choose"
    if structure.driver in owners:
        return f"{name} is a point of the driver, link {structure.driver}, whose position is given: it cannot choose an assembly branch"
    return f"{name} is not a point of a group with two assemblies: it cannot choose an assembly branch"


def _who_decides(scene: Scene, structure: Structure) -> str:
    parts = []
    for group in structure.groups:
        if not group.two_assemblies:
            continue
        names = branch_points(scene, group)
        if names:
            parts.append(f"{group.name} by {' or '.join(names)}")
        else:
            links = " or ".join(body_words(link) for link in _sorted_names(group.links))
            parts.append(f"{group.name} by a point of {links} off its joints (add one to choose)")
    if not parts:
        return "no group of this mechanism has two assemblies: leave [assembly] out"
    return "the branch of " + "; of ".join(parts) + " (write NAME = [x, y] near where it lies, or NAME = 1 or -1)"


@dataclass(frozen=True)
class Branch:
    """The assembly branch one group took at one position.

    Attributes
    ----------
    group : str
        The group's name, ``"RRR(3,4)"``.
    sign : int
        +1 or −1 as an ``[assembly]`` sign writes it (see :attr:`Group.orientation`
        and the README's "Assembly branches"); 0 for a group with one assembly.
    words : str
        The branch in words: ``"C to the left of B→D"``.
    other_assembly : bool
        Whether the group could be assembled the other way at this position
        (False for PRP and RPP, which have one assembly, and at a dead
        centre, where the two coincide).
    chosen_by : str
        ``"C near (x, y)"``, ``"C = -1"`` or ``"default (+1)"``: what chose it.
    """

    group: str
    sign: int
    words: str
    other_assembly: bool
    chosen_by: str

    def as_dict(self) -> dict:
        return {"sign": self.sign, "words": self.words, "other_assembly": self.other_assembly, "chosen_by": self.chosen_by}


def branches(solution, position: int = 0) -> tuple[Branch, ...]:
    """The branch each group of an analytic solution took at one of its positions.

    Found from the solved positions themselves (not from the solver's
    choice): RRR, the side of C from the directed line B→D; RRP, whether C
    is the intersection further along the guide's direction u,
    ``(C − B)·u > 0``; RPR, whether the common line's direction points from
    one pivot towards the other, ``u·(E − B) > 0`` — each with the links in
    the order of the group's name.
    """
    scene = solution.scene
    out = []
    for group in solution.structure.groups:
        out.append(_branch(scene, solution, group, position))
    return tuple(out)


def _at(solution, name: str, k: int) -> complex:
    return complex(solution.points[name].r[k])


def _phi(solution, body: str, k: int) -> float:
    return 0.0 if body == FRAME else float(solution.links[body].phi[k])


def _branch(scene: Scene, solution, group: Group, k: int) -> Branch:
    sine = float(solution.sines[group.name][k])
    other = group.two_assemblies and math.isfinite(sine) and sine > 0
    chosen = _chosen_by(scene, group)
    if group.kind == "RRR":
        a, b = _canonical(group)
        B, D, c = a.point, b.point, group.inner.point
        side = (complex(_at(solution, D, k) - _at(solution, B, k)).conjugate() * (_at(solution, c, k) - _at(solution, B, k))).imag
        sign = 1 if side > 0 else -1
        words = f"{c} to the {'left' if sign > 0 else 'right'} of {B}→{D}"
    elif group.kind == "RRP":
        B, c = group.outer_i.point, group.inner.point
        known = group.outer_j.bodies[1]
        p = group.outer_j.prismatic
        line = scene.bodies[known].lines[p.guide_line if p.guide == known else p.slider_line]
        u = cmath.exp(1j * (_phi(solution, known, k) + line.angle))
        along = ((_at(solution, c, k) - _at(solution, B, k)) * u.conjugate()).real
        sign = 1 if along > 0 else -1
        words = f"{c} at the intersection {'further along' if sign > 0 else 'nearer the start of'} {line.key} (of the two the circle about {B} meets)"
    elif group.kind == "RPR":
        a, b = _canonical(group)
        i = group.links[0]  # the solvers' i carries the guide line of the inner pair
        p = group.inner.prismatic
        line = scene.bodies[i].lines[p.guide_line if p.guide == i else p.slider_line]
        u = cmath.exp(1j * (_phi(solution, i, k) + line.angle))
        along = ((_at(solution, b.point, k) - _at(solution, a.point, k)) * u.conjugate()).real
        sign = 1 if along > 0 else -1
        words = f"line {line.key} pointing {'from ' + a.point + ' towards ' + b.point if sign > 0 else 'from ' + b.point + ' towards ' + a.point}"
    else:
        return Branch(group.name, 0, "one assembly only", False, "none needed")
    return Branch(group.name, sign, words, other, chosen)


def _canonical(group: Group) -> tuple[Joint, Joint]:
    """The outer joints in the order of :attr:`Group.sign_order`."""
    if group.orientation > 0:
        return group.outer_i, group.outer_j
    return group.outer_j, group.outer_i


def _chosen_by(scene: Scene, group: Group) -> str:
    for name in branch_points(scene, group):
        if name in scene.assembly:
            hint = scene.assembly[name]
            if isinstance(hint, int):
                return f"{name} = {hint:+d}"
            return f"{name} near ({hint.real:g}, {hint.imag:g}) m"
    return "default (+1)" if group.two_assemblies else "none needed"
