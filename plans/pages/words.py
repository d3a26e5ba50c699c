"""The words of a page that come from the scene: its title, its names, the assembly of its groups.

A scene may give its title and names per language (``title = { en = "…",
sr = "…" }``, ``[names] slot = { en = "slot", sr = "кулиса" }``); a page
prints them in its language, and where the scene gives only one form,
exactly as written.  The assembly of each group is said in the textbook's
words ("the slider to the right of B", "C to the left of the line BD"),
never as a program token (``RRR(3,4): … (−1)``).
"""

from __future__ import annotations

import cmath
import math
import re

from .._text import course_units as units
from ..i18n import term
from .._text import subscript
from ..scene import FRAME, Crank, Scene

__all__ = ["scene_data_lines", "cycle_lines", "four_bar_kind", "namer", "assembly_lines", "group_words", "block_words", "assembly_text", "units", "formula_words", "KINDS"]


def namer(scene, lang: str, form: str = "name"):
    """A function: a name as the scene writes it → the name on a page in *lang*, in *form* (:data:`plans.scene.NAME_FORMS`:
    ``"parallel"`` for the words of vector equations, where a guide's name follows ∥)."""
    return lambda name: scene.name_in(name, lang, form)


_GROUP = re.compile(r"^[A-Z]{3}\(([^,()]+),([^,()]+)\)$")


def group_words(group: str, lang: str) -> str:
    """``RRR(3,4)`` → ``group 3–4`` (the links it is made of, as the course names a group)."""
    m = _GROUP.match(group)
    if not m:
        return group
    return f"{term('group', lang)} {m.group(1)}–{m.group(2)}"


def block_words(title: str, lang: str) -> str:
    """A loop block's title as the pages name its part: ``RRR(3,4)`` → ``group 3–4`` (:func:`group_words`), the
    driver's ``I(1,2)`` → ``driver 2``, as the vector equations name them; another title as a formula."""
    m = re.fullmatch(r"I\(([^,()]+),([^,()]+)\)", title)
    if m:
        return f"{term('driver', lang)} {m.group(2)}"
    if _GROUP.match(title):
        return group_words(title, lang)
    return formula_words(title)


_NAME = r"[^\W]+"


def _guide_angle(scene, key: str) -> float | None:
    """The frame guide's angle [rad] for a key ``frame.ram``; None for a guide on a moving link."""
    body, _, line = key.partition(".")
    if body != FRAME or line not in scene.bodies[FRAME].lines:
        return None
    return scene.bodies[FRAME].lines[line].angle


def _side(angle: float, sign: int, lang: str) -> str | None:
    """Along a frame guide at *angle*: right/left/above/below when the guide is within 10° of an axis."""
    deg = math.degrees(angle) % 360.0
    for axis, (ahead, back) in ((0.0, ("right_of", "left_of")), (90.0, ("above", "below")), (180.0, ("left_of", "right_of")), (270.0, ("below", "above"))):
        if min(abs(deg - axis), 360 - abs(deg - axis)) <= 10.0:
            return term(ahead if sign > 0 else back, lang)
    return None


def _crosses(p: complex, q: complex, r: complex, s: complex) -> bool:
    """Whether the segments pq and rs cross (touching ends do not count)."""
    def side(a, b, c):
        return ((b - a).conjugate() * (c - a)).imag

    return side(p, q, r) * side(p, q, s) < 0 and side(r, s, p) * side(r, s, q) < 0


def four_bar_kind(scene, b: str, c: str, d: str, positions) -> str | None:
    """``"open_four_bar"`` or ``"crossed_four_bar"`` for an RRR group B–C–D closing a four-bar with the crank
    (O, B on the crank, D on the frame, or the other way round): crossed when the loop O–B–C–D crosses
    itself; None for any other group or without *positions* (point name -> position [m])."""
    driver = scene.driver
    if not positions or not hasattr(driver, "pivot"):
        return None
    crank = scene.bodies[driver.link].points
    frame = scene.bodies[FRAME].points
    if b in crank and d in frame:
        loop = (driver.pivot, b, c, d)
    elif d in crank and b in frame:
        loop = (driver.pivot, d, c, b)
    else:
        return None
    if not all(p in positions for p in loop):
        return None
    o, x, y, z = (complex(positions[p]) for p in loop)
    return "crossed_four_bar" if _crosses(o, x, y, z) or _crosses(x, y, z, o) else "open_four_bar"


def assembly_text(branch, scene, lang: str, positions=None) -> str | None:
    """One group's assembly in words, or None for a group with one assembly (or a form not known here).

    *positions* (point name -> position [m]), when given, lets a group that
    closes a four-bar with the crank be called open or crossed.
    """
    words = branch.words.strip()
    m = re.fullmatch(rf"({_NAME}) to the (left|right) of ({_NAME})→({_NAME})", words)
    if m:
        c, side, b, d = m.groups()
        text = term("assembly_side", lang).format(c=c, side=term(side, lang), b=b, d=d)
        kind = four_bar_kind(scene, b, c, d, positions)
        return f"{term(kind, lang)}, {text}" if kind else text
    m = re.fullmatch(rf"({_NAME}) at the intersection (further along|nearer the start of) ({_NAME}(?:\.{_NAME})?) \(of the two the circle about ({_NAME}) meets\)", words)
    if m:
        c, how, key, b = m.groups()
        sign = 1 if how == "further along" else -1
        angle = _guide_angle(scene, key) if "." in key else _frame_line(scene, key)
        side = _side(angle, sign, lang) if angle is not None else None
        if side is not None:
            return term("assembly_slider_side", lang).format(c=c, where=side, b=b)
        return term("assembly_along", lang).format(c=c, where=term("ahead_of" if sign > 0 else "behind", lang), b=b, key=scene.name_in(key.rpartition(".")[2], lang, "of"))
    m = re.fullmatch(rf"line ({_NAME}(?:\.{_NAME})?) pointing from ({_NAME}) towards ({_NAME})", words)
    if m:
        key, a, b = m.groups()
        g = _GROUP.match(branch.group)
        points = _points_along(scene, key, a, b, positions, g.groups() if g else ())
        if points:
            return term("assembly_directed_points", lang).format(key=scene.name_in(key.rpartition(".")[2], lang, "of"), points=" → ".join(points))
        return term("assembly_directed", lang).format(key=scene.name_in(key.rpartition(".")[2], lang, "of"), a=a, b=b)
    return None


def _points_along(scene, key: str, a: str, b: str, positions, links=()) -> list[str]:
    """The named points of the group's *links* lying on the guide line *key* (through its ``through`` point and the pin *a*), in the
    order of the line's direction u (the branch's words say ``u·(b − a) > 0``): ``["F", "K", "G"]`` for the
    linear-arm's sleeve; empty when the line is not known so (no positions, *a* off the line, under 3 points)."""
    body, _, line_name = key.partition(".")
    line = scene.bodies.get(body).lines.get(line_name) if body in scene.bodies else None
    if not positions or line is None or line.through not in positions or a not in positions or b not in positions:
        return []
    t, pa, pb = complex(positions[line.through]), complex(positions[a]), complex(positions[b])
    if abs(pa - t) == 0:
        return []
    d = (pa - t) / abs(pa - t)
    if ((pb - pa) * d.conjugate()).real < 0:
        d = -d
    size = max(abs(complex(z)) for z in positions.values()) or 1.0
    mine = {n for link in links if link in scene.bodies for n in scene.bodies[link].points}
    on = [(((complex(z) - pa) * d.conjugate()).real, n) for n, z in positions.items()
          if n in mine and abs(((complex(z) - pa) * d.conjugate()).imag) <= 1e-9 * size]
    return [n for _, n in sorted(on)] if len(on) >= 3 else []


def _frame_line(scene, key: str) -> float | None:
    line = scene.bodies[FRAME].lines.get(key)
    return line.angle if line is not None else None


def assembly_lines(branches, scene, lang: str, positions=None) -> list[str]:
    """The assembly of every group that has two, one line each: ``group 3–4: open four-bar, C to the left of …``."""
    out = []
    for b in branches or ():
        if not b.sign:
            continue
        words = assembly_text(b, scene, lang, positions)
        if words:
            out.append(f"{group_words(b.group, lang)}: {words}")
    return out




#: The kind of each class II group as the course numbers them (Artobolevsky): RRR 1, RRP 2, RPR 3, PRP 4, RPP 5.
KINDS = {"RRR": 1, "RRP": 2, "PRR": 2, "RPR": 3, "PRP": 4, "RPP": 5, "PPR": 5}


def formula_words(formula: str) -> str:
    """The structural formula as the course writes it: ``I(1,2) → RRR(3,4)`` → ``I(1,2) → II₁(3,4)`` (``$…$`` math)."""
    return re.sub(r"\b([RP]{3})\(", lambda m: f"$\\mathrm{{II}}_{{{KINDS[m.group(1)]}}}$(" if m.group(1) in KINDS else m.group(0), formula)


# --- the scene's data and its cycle, as lines of a page ---------------------------------------------


def _length_unit(scene: Scene) -> tuple[str, float]:
    sizes = [abs(z) for body in scene.bodies.values() for z in body.points.values()]
    largest = max(sizes, default=1.0)
    if largest < 1e-3:
        return "µm", 1e6
    if largest < 20.0:
        return "mm", 1e3
    return "m", 1.0


def _fmt(x: float) -> str:
    text = f"{x:.4g}"
    if "e" in text:
        text = f"{x:.3e}"
    return text.replace("-", "−")


def _data_guide_angle(scene: Scene, name: str) -> float:
    """The angle [rad] of the frame's line *name* (0 when the frame has no such line)."""
    line = scene.bodies[FRAME].lines.get(name)
    return line.angle if line is not None else 0.0


def scene_data_lines(scene: Scene, lang: str = "en", law=None) -> list[str]:
    """The scene's data as a few lines of text: driver, link lengths, fixed points.

    *law*: the cycle's driver law (:class:`plans.motion.DriverLaw`) when the page states it below; under a
    constant law the driver's line gives its rate only (ω or v): the law's line says ε = 0 (a = 0), and a scene's
    own ε (a) at its instant, which the cycle does not use, is said once beside the law (its ``given_note``)."""
    unit, factor = _length_unit(scene)
    driver = scene.driver
    name_in = scene.name_in
    link = driver.link
    constant = law is not None and law.kind == "constant"
    if isinstance(driver, Crank):
        first = f"{term('driver', lang)} {link} ({driver.pivot}):  ω{subscript(link)} = {_fmt(driver.omega)} rad/s"
        if not constant:
            first += f",  ε{subscript(link)} = {_fmt(driver.epsilon)} rad/s²"
    else:
        first = f"{term('driver', lang)} {link} ({driver.point}, {name_in(driver.guide, lang)} ∥ {_fmt(math.degrees(_data_guide_angle(scene, driver.guide)))}°):  v = {_fmt(driver.velocity)} m/s"
        if not constant:
            first += f",  a = {_fmt(driver.acceleration)} m/s²"
        if driver.stroke:
            first += f",  s ∈ [{_fmt(driver.stroke[0] * factor)}, {_fmt(driver.stroke[1] * factor)}] {unit}"
    lengths = []
    for name, body in scene.bodies.items():
        if name == FRAME or body.block:
            continue
        pts = list(body.points.items())
        pairs = []
        for a in range(len(pts)):
            for b in range(a + 1, len(pts)):
                (na, za), (nb, zb) = pts[a], pts[b]
                pairs.append(f"{na}{nb} = {_fmt(abs(za - zb) * factor)}")
        extra = [term("line_at", lang).format(name=name_in(line.name, lang), angle=_fmt(math.degrees(line.angle))) for line in body.lines.values() if line.angle]
        if pairs or extra:
            lengths.append(f"{name}: " + ", ".join(pairs + extra))
    second = f"{term('lengths', lang)} [{unit}]:  " + ";  ".join(lengths)
    frame = scene.bodies[FRAME]
    fixed = [f"{n} ({_fmt(z.real * factor)}, {_fmt(z.imag * factor)})" for n, z in frame.points.items()]
    pivot = frame.points.get(driver.pivot) if isinstance(driver, Crank) else None
    for line in frame.lines.values():
        text = term("line_at", lang).format(name=name_in(line.name, lang), angle=_fmt(math.degrees(line.angle)))
        if pivot is not None:  # the guide's offset e: its perpendicular distance from the crank's pivot
            offset = abs(((pivot - line.origin) * cmath.exp(-1j * line.angle)).imag)
            text += f", e = {_fmt(offset * factor)} {unit} {term('from_point', lang)} {driver.pivot}"
        fixed.append(text)
    third = f"{term('fixed_points', lang)} [{unit}]:  " + ",  ".join(fixed) if fixed else ""
    return [line for line in (first, second, third) if line]


def cycle_lines(run, lang: str = "en", rate: bool = True) -> list[str]:
    """What the plate states of a cycle (issue 19): the driver's law, the Grashof class of every four-bar loop,
    the output's stroke H (or swing ψ), θ, K and the working stroke (:mod:`plans.motion`).  *rate*: False leaves a
    constant law's rate out (the driver's line above gives it: :func:`scene_data_lines` with the law)."""
    from ..motion import four_bar_loops

    lines = []
    if run.motion is not None:  # a long law in lines a page's width (about 110 characters), the rest indented
        import textwrap

        lines += textwrap.wrap(run.motion.law.describe(lang, run.scene.driver.link, rate=rate), 110, subsequent_indent="    ")
    for loop in four_bar_loops(run.scene, run.structure):
        turning = loop.turning_links()
        turns = f"{', '.join(turning)}: {term('turn_fully', lang)}" if turning else term("none_turns", lang)
        # the loop named by its links, frame first (1–2–3–4), as the course names a four-bar: not by its group's notation
        bars = "–".join((run.scene.frame_number, loop.input, loop.coupler_link, loop.output))
        lines.append(f"{term('grashof_class', lang)} ({term('four_bar_loop', lang)} {bars}): {term(loop.grashof.kind, lang)} ({turns})")
    if run.strokes is not None:
        lines += run.strokes.summary(lang)
    return lines


