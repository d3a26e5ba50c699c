"""The complex-number loop equations of the analytic check, written out with their numbers.

Formatting only: every number comes from the scene's geometry or from an
:class:`~plans.analytic.AnalyticSolution`; nothing here solves anything.

Each Assur group closes a loop through known points (domain.md §5).  The
loop is written as two paths that meet at the group's inner joint (or, for
an inner prismatic pair, at the origin of the sliding line)::

    z_A + l_AC e^{iφ₃} = z_D + l_DC e^{iφ₄}                       (position)
    v_A + iω₃ l_AC e^{iφ₃} = v_D + iω₄ l_DC e^{iφ₄}                (velocity)
    a_A + (iε₃ − ω₃²) l_AC e^{iφ₃} = a_D + (iε₄ − ω₄²) l_DC e^{iφ₄}   (acceleration)

and a slider travel s along a line turning with angle θ gives
d/dt (s e^{iθ}) = ṡ e^{iθ} + iω s e^{iθ} and
d²/dt² (s e^{iθ}) = s̈ e^{iθ} + 2iωṡ e^{iθ} + (iε − ω²) s e^{iθ} (Coriolis term
2iωṡ e^{iθ}).  At each stage the unknowns stay as symbols (φ and s, then ω
and ṡ, then ε and s̈), the known values are substituted, and the values the
analytic solution found follow the ⇒.  Points that are not joints of a
group (a coupler point M) follow from a rigid vector of their link.

Lines are matplotlib mathtext (``$…$``); :func:`plain` turns one into plain
text.

>>> import plans
>>> from plans.loops import loop_equations
>>> scene = plans.load(plans.example_path("four-bar"))
>>> blocks = loop_equations(plans.solve(scene))
>>> [b.title for b in blocks]
['I(1,2)', 'RRR(3,4)']
"""

from __future__ import annotations

import cmath
import math
import re
from dataclasses import dataclass

from .scene import FRAME, Crank, Scene

__all__ = ["LoopBlock", "loop_equations", "plain"]


@dataclass(frozen=True)
class LoopBlock:
    """The equations of the driver or of one group.

    Attributes
    ----------
    title : str
        ``"I(1,2)"`` or the group's name ``"RRR(3,4)"``.
    lines : tuple of str
        Mathtext lines: for a group, the symbolic loop, then the position,
        velocity and acceleration equations with numbers and results; then
        one line per stage for each further point of its links.
    """

    title: str
    lines: tuple[str, ...]
    #: the pins whose guide point Q (s = 0 there, :func:`_origin`) the first lines place, one line each (a page
    #: says in words what that point is: it is not a load)
    origins: tuple[str, ...] = ()


# --- numbers ------------------------------------------------------------------------


def _num(x: float, digits: int = 4) -> str:
    x = float(x)
    if x == 0 or not math.isfinite(x):
        return "0" if x == 0 else "?"
    text = f"{x:.{digits}g}"
    if "e" in text:
        mantissa, exponent = text.split("e")
        text = rf"{mantissa}\cdot10^{{{int(exponent)}}}"
    return text


def _paren(x: float) -> str:
    text = _num(x)
    return f"({text})" if text.startswith("-") else text


def _power_base(x: float) -> str:
    """*x* as the base of a power: bracketed when negative or in powers of ten (``(5\\cdot10^{4})^2``)."""
    text = _num(x)
    return f"({text})" if text.startswith("-") or "^" in text else text


def _cplx(z: complex, alone: bool = False) -> str:
    z = complex(z)
    re_, im = z.real, z.imag
    scale = max(abs(re_), abs(im))
    if scale == 0:
        return "0"
    if abs(im) < 1e-12 * scale:
        return _num(re_) if alone else _paren(re_)
    if abs(re_) < 1e-12 * scale:
        return f"{_paren(im)}i" if not _num(im).startswith("-") else f"({_num(im)}i)"
    sign = "-" if im < 0 else "+"
    return f"({_num(re_)} {sign} {_num(abs(im))}i)"


def _deg(angle: float) -> str:
    """An angle in degrees, 0 ≤ φ < 360 as the page's headers and the tables' ∠ print it."""
    d = f"{math.degrees(float(angle)) % 360.0:.2f}"
    return rf"{'0.00' if d == '360.00' else d}^\circ"


def _sub(name: str) -> str:
    return name if re.fullmatch(r"[A-Za-z0-9]+", name) else r"\mathrm{" + name.replace("_", r"\_") + "}"


# --- loop terms ----------------------------------------------------------------------


@dataclass
class _Point:
    """A point known before the group: z, v, a."""

    label: str
    r: complex
    v: complex
    a: complex
    sign: int = 1


@dataclass
class _Rigid:
    """A vector fixed in a body: length l, direction φ_body + α."""

    start: str
    end: str
    body: str
    length: float
    alpha: float
    phi: float
    omega: float
    epsilon: float
    unknown: bool
    sign: int = 1


@dataclass
class _Slide:
    """A travel s along a line whose direction is φ_body + α."""

    name: str
    body: str
    alpha: float
    phi: float
    omega: float
    epsilon: float
    s: float
    v_rel: float
    a_rel: float
    angle_unknown: bool
    sign: int = 1


def _phi_symbol(body: str, alpha: float) -> str:
    base = rf"\varphi_{{{_sub(body)}}}"
    if abs(math.remainder(alpha, 2 * math.pi)) < 1e-12:
        return base
    return rf"({base} {'+' if alpha > 0 else '-'} {abs(math.degrees(alpha)):.4g}^\circ)"


def _omega(body: str) -> str:
    return rf"\omega_{{{_sub(body)}}}"


def _eps(body: str) -> str:
    return rf"\varepsilon_{{{_sub(body)}}}"


def _s(name: str) -> str:
    return rf"s_{{{_sub(name)}}}"


def _ds(name: str, order: int) -> str:
    return (r"\dot{s}" if order == 1 else r"\ddot{s}") + rf"_{{{_sub(name)}}}"


def _i_times(factor: str) -> str:
    """``i`` times *factor*: ``i\\omega_{4}`` for a symbol, ``i\\cdot0.2502`` for a number (``i0.2502`` would read as one
    token, and next to ``·0.45`` as ``i0.2502·0.45``)."""
    return rf"i{factor}" if factor.startswith("\\") else rf"i\cdot{factor}"


def _signed(sign: int, text: str, first: bool) -> str:
    if first:
        return text if sign > 0 else f"-{text}"
    return f" + {text}" if sign > 0 else f" - {text}"


def _fixed(term) -> bool:
    """A slide along a frame line: its direction is a number and it does not turn."""
    return isinstance(term, _Slide) and term.body == FRAME


def _symbolic(term, stage: int) -> str:
    if isinstance(term, _Point):
        label = term.label if "_{" in term.label else _sub(term.label)
        return {0: "z", 1: "v", 2: "a"}[stage] + f"_{{{label}}}"
    if isinstance(term, _Rigid):
        e = rf"l_{{{_sub(term.start + term.end)}}}\,e^{{i{_phi_symbol(term.body, term.alpha)}}}"
        if stage == 0:
            return e
        if stage == 1:
            return rf"i{_omega(term.body)}\,{e}"
        return rf"(i{_eps(term.body)} - {_omega(term.body)}^2)\,{e}"
    if _fixed(term):
        e = rf"e^{{i\,{_deg(term.alpha)}}}"
        return rf"{(_s(term.name), _ds(term.name, 1), _ds(term.name, 2))[stage]}\,{e}"
    e = rf"e^{{i{_phi_symbol(term.body, term.alpha)}}}"
    n = term.name
    if stage == 0:
        return rf"{_s(n)}\,{e}"
    if stage == 1:
        return rf"{_ds(n, 1)}\,{e} + i{_omega(term.body)}{_s(n)}\,{e}"
    return rf"{_ds(n, 2)}\,{e} + 2i{_omega(term.body)}{_ds(n, 1)}\,{e} + (i{_eps(term.body)} - {_omega(term.body)}^2){_s(n)}\,{e}"


def _numeric(term, stage: int) -> str:
    if isinstance(term, _Point):
        return _cplx((term.r, term.v, term.a)[stage])
    if isinstance(term, _Rigid):
        angle = _phi_symbol(term.body, term.alpha) if (stage == 0 and term.unknown) else _deg(term.phi + term.alpha)
        e = rf"{_num(term.length)}\,e^{{i\,{angle}}}"
        if stage == 0:
            return e
        if stage == 1:
            w = _omega(term.body) if term.unknown else _paren(term.omega)
            return rf"{_i_times(w)}\cdot{e}"
        eps = _eps(term.body) if term.unknown else _paren(term.epsilon)
        return rf"({_i_times(eps)} - {_power_base(term.omega)}^2)\cdot{e}"
    angle = _phi_symbol(term.body, term.alpha) if (stage == 0 and term.angle_unknown) else _deg(term.phi + term.alpha)
    e = rf"e^{{i\,{angle}}}"
    n = term.name
    if _fixed(term):
        return rf"{(_s(n), _ds(n, 1), _ds(n, 2))[stage]}\,{e}"
    if stage == 0:
        return rf"{_s(n)}\,{e}"
    w = _omega(term.body) if (stage == 1 and term.angle_unknown) else _paren(term.omega)
    if stage == 1:
        return rf"{_ds(n, 1)}\,{e} + {_i_times(w)}\cdot{_paren(term.s)}\,{e}"
    eps = _eps(term.body) if term.angle_unknown else _paren(term.epsilon)
    return (
        rf"{_ds(n, 2)}\,{e} + 2i\cdot{_paren(term.omega)}\cdot{_paren(term.v_rel)}\,{e}"
        rf" + ({_i_times(eps)} - {_power_base(term.omega)}^2)\cdot{_paren(term.s)}\,{e}"
    )


def _still(term, stage: int) -> bool:
    """A known rigid vector of a body that does not turn: its velocity (ω = 0) or acceleration (ω = ε = 0) term is zero."""
    if not isinstance(term, _Rigid) or term.unknown or stage == 0:
        return False
    return term.omega == 0 and (stage == 1 or term.epsilon == 0)


def _side(terms, stage: int, numeric: bool) -> str:
    parts = []
    if numeric and len(terms) > 1:
        kept = [t for t in terms if not (isinstance(t, _Point) and (t.r, t.v, t.a)[stage] == 0) and not _still(t, stage)]
        terms = kept or terms[:1]
    for k, term in enumerate(terms):
        parts.append(_signed(term.sign, (_numeric if numeric else _symbolic)(term, stage), k == 0))
    return "".join(parts) if parts else "0"


# --- building the paths --------------------------------------------------------------


class _Builder:
    def __init__(self, analytic, k: int):
        self.sol = analytic
        self.scene: Scene = analytic.scene
        self.k = k

    def phi(self, body: str) -> float:
        return 0.0 if body == FRAME else float(self.sol.poses[body][0][self.k])

    def omega(self, body: str) -> float:
        return 0.0 if body == FRAME else float(self.sol.links[body].omega[self.k])

    def epsilon(self, body: str) -> float:
        return 0.0 if body == FRAME else float(self.sol.links[body].epsilon[self.k])

    def point_name(self, body: str, z: complex, fallback: str) -> str:
        for name, w in self.scene.bodies[body].points.items():
            if abs(w - z) < 1e-12:
                return name
        return fallback

    def known_point(self, body: str, local: complex, label: str) -> _Point:
        named = self.point_name(body, local, "")
        if named and named in self.sol.points:
            m = self.sol.points[named]
            return _Point(named, complex(m.r[self.k]), complex(m.v[self.k]), complex(m.a[self.k]))
        m = self.sol.motion_of(body, local)
        return _Point(label, complex(m.r[self.k]), complex(m.v[self.k]), complex(m.a[self.k]))

    def rigid(self, body: str, a_local: complex, b_local: complex, a_name: str, b_name: str, unknown: bool):
        d = b_local - a_local
        if abs(d) < 1e-12:
            return None
        return _Rigid(a_name, b_name, body, abs(d), cmath.phase(d), self.phi(body), self.omega(body), self.epsilon(body), unknown)

    def slide(self, pair, guide_body: str, guide_line, unknown_angle: bool, sign: int = 1) -> _Slide:
        m = self.sol.sliders[pair.name]
        return _Slide(
            self.scene.pair_label(pair.name), guide_body, guide_line.angle, self.phi(guide_body), self.omega(guide_body), self.epsilon(guide_body),
            float(m.s[self.k]), float(m.v_rel[self.k]), float(m.a_rel[self.k]), unknown_angle, sign,
        )


def _origin(pin: str) -> str:
    """The point of a guide from which a slider's travel s is measured, when the scene names none there: ``Q_E`` for
    the slider at E (s_E = 0 there), defined on the page by :func:`_origin_lines` (never the guide's program name)."""
    return f"Q_{{{_sub(pin)}}}"


def _origin_lines(b: _Builder, terms) -> list[str]:
    """``z_{Q_E} (s_E = 0) = … m``: where each unnamed guide point of a loop (:func:`_origin`) is."""
    lines = []
    for t in terms:
        if isinstance(t, _Point) and t.label.startswith("Q_{"):
            pin = t.label[3:-1]
            lines.append(rf"$z_{{{t.label}}}\ (s_{{{pin}}} = 0) = {_cplx(t.r, True)}\ \mathrm{{m}}$")
    return lines


def _meeting(scene: Scene, group) -> tuple[str | None, dict[str, complex]]:
    """Where the two paths meet: the inner joint's name and its local coordinates on each link."""
    inner = group.inner
    i, j = group.links
    if inner.kind == "R":
        return inner.point, {i: scene.bodies[i].points[inner.point], j: scene.bodies[j].points[inner.point]}
    pair = inner.prismatic
    slider_line = scene.bodies[pair.slider].lines[pair.slider_line]
    return None, {pair.slider: slider_line.origin}


def _path(b: _Builder, group, link: str, outer, meet_name, meet_local):
    scene = b.scene
    body = scene.bodies[link]
    terms = []
    group_links = set(group.links)
    if outer.kind == "R":
        start_local = body.points[outer.point]
        terms.append(b.known_point(outer.bodies[1], scene.bodies[outer.bodies[1]].points[outer.point], outer.point))
        start_name = outer.point
    else:
        pair = outer.prismatic
        known = outer.bodies[1]
        if pair.slider == link:  # the link slides on a line of the known body
            guide_line = scene.bodies[known].lines[pair.guide_line]
            q_name = b.point_name(known, guide_line.origin, _origin(b.scene.pair_label(pair.name)))
            terms.append(b.known_point(known, guide_line.origin, q_name))
            terms.append(b.slide(pair, known, guide_line, unknown_angle=False))
            own_line = body.lines[pair.slider_line]
        else:  # the known body slides on a line of the link: Q_link = Q_known − s·u_link
            slider_line = scene.bodies[known].lines[pair.slider_line]
            q_name = b.point_name(known, slider_line.origin, _origin(b.scene.pair_label(pair.name)))
            terms.append(b.known_point(known, slider_line.origin, q_name))
            own_line = body.lines[pair.guide_line]
            terms.append(b.slide(pair, link, own_line, unknown_angle=True, sign=-1))
        start_local = own_line.origin
        start_name = b.point_name(link, start_local, f"Q_{{{_sub(link)}}}")
    if meet_name is not None:
        term = b.rigid(link, start_local, meet_local[link], start_name, meet_name, unknown=True)
        if term:
            terms.append(term)
    else:
        pair = group.inner.prismatic
        if link == pair.slider:
            end_local = meet_local[link]
            end_name = b.point_name(link, end_local, f"Q_{{{_sub(link)}}}")
            term = b.rigid(link, start_local, end_local, start_name, end_name, unknown=True)
            if term:
                terms.append(term)
        else:  # the link carries the guide of the inner pair: to its origin, then along it by s
            line = body.lines[pair.guide_line]
            end_name = b.point_name(link, line.origin, f"Q_{{{_sub(link)}}}")
            term = b.rigid(link, start_local, line.origin, start_name, end_name, unknown=True)
            if term:
                terms.append(term)
            terms.append(b.slide(pair, link, line, unknown_angle=link in group_links))
    return terms


def _results(b: _Builder, group, stage: int) -> str:
    parts = []
    pairs = [j.prismatic for j in (group.outer_i, group.inner, group.outer_j) if j.kind == "P"]
    turning = []
    for link in group.links:
        if b.scene.bodies[link].block:
            continue  # a block turns with its guide
        turning.append(link)
    for link in turning:
        if stage == 0:
            parts.append(rf"\varphi_{{{_sub(link)}}} = {_deg(b.phi(link))}")
        elif stage == 1:
            parts.append(rf"{_omega(link)} = {_num(b.omega(link))}\ \mathrm{{rad/s}}")
        else:
            parts.append(rf"{_eps(link)} = {_num(b.epsilon(link))}\ \mathrm{{rad/s^2}}")
    for pair in pairs:
        m = b.sol.sliders[pair.name]
        value = (m.s, m.v_rel, m.a_rel)[stage][b.k]
        label = b.scene.pair_label(pair.name)  # the coincident points (F3F4), not a word
        symbol = _s(label) if stage == 0 else _ds(label, stage)
        parts.append(rf"{symbol} = {_num(value)}\ \mathrm{{{_UNITS[stage]}}}")  # (units as the lines above give them)
    return ",\\ ".join(parts)


_UNITS = ("m", "m/s", "m/s^2")


def _rigid_lines(b: _Builder, name: str, terms_of) -> list[str]:
    """z, v (and a) of point *name* as the sum of known terms: ``terms_of(stage)`` gives the terms of a stage."""
    lines = []
    m = b.sol.points[name]
    for stage, letter in enumerate("zva"):
        if stage == 2 and not b.scene.accelerations:
            break
        value = complex((m.r, m.v, m.a)[stage][b.k])
        terms = terms_of(stage)
        lines.append(
            rf"${letter}_{{{_sub(name)}}} = {_side(terms, stage, False)} = {_side(terms, stage, True)}"
            rf" = {_cplx(value, True)}\ \mathrm{{{_UNITS[stage]}}}$"
        )
    return lines


def _point_lines(b: _Builder, link: str, joints: dict[str, complex], done: set[str]) -> list[str]:
    """z, v, a of the further points of a link, from a joint of the link by a rigid vector."""
    lines = []
    body = b.scene.bodies[link]
    for name, local in body.points.items():
        if name in done or name not in b.scene.report or name in joints:
            continue
        if not joints:
            break
        def cost(n):
            d = local - joints[n]
            along = abs(math.remainder(cmath.phase(d), 2 * math.pi)) < 1e-9 if abs(d) > 0 else False
            return (not along, abs(d))

        base = min(joints, key=cost)
        known = b.sol.points[base]
        start = _Point(base, complex(known.r[b.k]), complex(known.v[b.k]), complex(known.a[b.k]))
        arm = b.rigid(link, joints[base], local, base, name, unknown=False)
        if arm is None:
            continue
        lines += _rigid_lines(b, name, lambda stage: [start, arm])
        done.add(name)
    return lines


def _driver_block(b: _Builder) -> LoopBlock:
    scene = b.scene
    driver = scene.driver
    link = driver.link
    body = scene.bodies[link]
    lines = []
    if isinstance(driver, Crank):
        pivot_local = body.points[driver.pivot]
        pivot = _Point(driver.pivot, complex(scene.frame.points[driver.pivot]), 0j, 0j)
        lines.append(
            rf"$\varphi_{{{_sub(link)}}} = {_deg(b.phi(link))},\ \omega_{{{_sub(link)}}} = {_num(b.omega(link))}\ "
            rf"\mathrm{{rad/s}},\ \varepsilon_{{{_sub(link)}}} = {_num(b.epsilon(link))}\ \mathrm{{rad/s^2}}$"
        )
        for name, local in body.points.items():
            if name == driver.pivot or (name not in scene.report and len(scene.bodies_with(name)) < 2):
                continue
            arm = b.rigid(link, pivot_local, local, driver.pivot, name, unknown=False)
            if arm is None:
                continue
            lines += _rigid_lines(b, name, lambda stage: [pivot, arm] if abs(pivot.r) > 0 or stage == 0 else [arm])
    else:
        guide = scene.frame.lines[driver.guide]
        s = float(b.sol.driver[b.k])  # this position's travel, not the scene's own
        m = b.sol.points[driver.point]
        # this position's rates (the driver's law over the cycle), as its solution used them: ṡ = v·ū, s̈ = a·ū
        unit = cmath.exp(1j * guide.angle)
        s_dot = float((complex(m.v[b.k]) / unit).real)
        s_ddot = float((complex(m.a[b.k]) / unit).real)
        lines.append(
            rf"$s = {_num(s)}\ \mathrm{{m}},\ \dot{{s}} = {_num(s_dot)}\ \mathrm{{m/s}},\ "
            rf"\ddot{{s}} = {_num(s_ddot)}\ \mathrm{{m/s^2}},\ u = e^{{i\,{_deg(guide.angle)}}}$"
        )
        p = _sub(driver.point)
        e = rf"e^{{i\,{_deg(guide.angle)}}}"
        q = complex(guide.origin)
        # the guide's own through point (O for a line through O), named as the scene names it
        q_label = b.point_name(FRAME, q, "")
        q_label = _sub(q_label) if q_label else _origin(driver.point)
        start = f"{_cplx(q)} + " if q != 0 else ""
        lines.append(rf"$z_{{{p}}} = z_{{{q_label}}} + s\,u = {start}{_paren(s)}\,{e} = {_cplx(m.r[b.k], True)}\ \mathrm{{m}}$")
        lines.append(rf"$v_{{{p}}} = \dot{{s}}\,u = {_paren(s_dot)}\,{e} = {_cplx(m.v[b.k], True)}\ \mathrm{{m/s}}$")
        if scene.accelerations:
            lines.append(rf"$a_{{{p}}} = \ddot{{s}}\,u = {_paren(s_ddot)}\,{e} = {_cplx(m.a[b.k], True)}\ \mathrm{{m/s^2}}$")
        # the sliding link translates (no ω, no φ of its own): its other points at a fixed offset, with A's v and a
        at = body.points[driver.point]
        for name, local in body.points.items():
            if name == driver.point or name not in b.sol.points or (name not in scene.report and len(scene.bodies_with(name)) < 2):
                continue
            n = _sub(name)
            arm = complex(local) - complex(at)
            turn = rf"e^{{i\,{_deg(b.phi(link) + cmath.phase(arm))}}}"
            point = b.sol.points[name]
            lines.append(rf"$z_{{{n}}} = z_{{{p}}} + l_{{{p}{n}}}\,{turn} = {_cplx(m.r[b.k])} + {_num(abs(arm))}\,{turn} = {_cplx(point.r[b.k], True)}\ \mathrm{{m}}$")
            lines.append(rf"$v_{{{n}}} = v_{{{p}}} = {_cplx(point.v[b.k], True)}\ \mathrm{{m/s}}$")
            if scene.accelerations:
                lines.append(rf"$a_{{{n}}} = a_{{{p}}} = {_cplx(point.a[b.k], True)}\ \mathrm{{m/s^2}}$")
    return LoopBlock(f"I({scene.frame_number},{link})", tuple(lines))


def _group_block(b: _Builder, group, done: set[str]) -> LoopBlock:
    scene = b.scene
    i, j = group.links
    if group.kind not in ("RRR", "RRP", "RPR", "PRP", "RPP"):
        return LoopBlock(group.name, ())
    meet_name, meet_local = _meeting(scene, group)
    left = _path(b, group, i, group.outer_i, meet_name, meet_local)
    right = _path(b, group, j, group.outer_j, meet_name, meet_local)
    lines = _origin_lines(b, left + right)
    origins = tuple(t.label[3:-1] for t in left + right if isinstance(t, _Point) and t.label.startswith("Q_{"))
    stages = 3 if scene.accelerations else 2
    for stage in range(stages):
        symbolic = f"{_side(left, stage, False)} = {_side(right, stage, False)}"
        numeric = f"{_side(left, stage, True)} = {_side(right, stage, True)}"
        lines.append(f"${symbolic}$")
        lines.append(rf"$\quad {numeric}\ \Rightarrow\ {_results(b, group, stage)}$")
    # further points of the group's links, from the joints now known
    for link in group.links:
        joints = {n: z for n, z in scene.bodies[link].points.items() if n in b.sol.points and (n in group.points or n in done)}
        lines += _point_lines(b, link, joints, done)
    for n in group.points:
        done.add(n)
    return LoopBlock(group.name, tuple(lines), origins)


def loop_equations(analytic, position: int = 0) -> list[LoopBlock]:
    """The driver's equations, then each group's loop, with the numbers of one position.

    Parameters
    ----------
    analytic : plans.analytic.AnalyticSolution
    position : int
        Index into the solution's driver positions.

    Returns
    -------
    list of LoopBlock
        The driver first, then the groups in structural order.
    """
    b = _Builder(analytic, position)
    blocks = [_driver_block(b)]
    done = set(analytic.scene.frame.points) | {analytic.scene.driver.link}
    for name in analytic.scene.bodies[analytic.scene.driver.link].points:
        done.add(name)
    for group in analytic.structure.groups:
        blocks.append(_group_block(b, group, done))
    return blocks


_MATH_PLAIN = [
    (r"\varphi", "φ"), (r"\varepsilon", "ε"), (r"\omega", "ω"), (r"\Rightarrow", "⇒"), (r"\cdot", "·"),
    (r"\circ", "°"), (r"\quad", "  "), (r"\,", ""), (r"\ ", " "), (r"\dot{s}", "ṡ"), (r"\ddot{s}", "s̈"),
]


def plain(line: str) -> str:
    """A mathtext line as plain text (``e^{i\\,55.00^\\circ}`` → ``e^(i 55.00°)``), for tests and text output."""
    text = line.replace("$", "")
    for a, b in _MATH_PLAIN:
        text = text.replace(a, b)
    text = re.sub(r"\\mathrm\{([^}]*)\}", r"\1", text)
    text = text.replace("{", "").replace("}", "").replace("\\_", "_")
    return text
