"""The content of the handout's instant-centre page of a position (``plans handout … --centres``).

The page itself is set by :mod:`plans.pages.handout`: the mechanism at that
position with every instant centre marked and labelled (P₁₂ …), the Kennedy
lines thin (:func:`plans.drawing.svgblocks.centres_svg`), the circle diagram,
the two rules and the table made here: ω of every link and v of every
reported point found from the centres (:mod:`plans.centres`, the third
method: its own positions and nothing of the analytic or graphical
kinematics) beside the analytic values of the handout's own analytic
solution, with the relative error (:func:`plans.compare.compare_centres`).
Words from :mod:`plans.i18n`, decimal comma in sr, ru, bg, sl.
"""

from __future__ import annotations


from .._text import decimal_comma, math_name
from ..i18n import term
from ..rounding import SHORT_READ_MM
from ..report import row_texts
from ..scene import LinearDriver
from .centres import centre_text

__all__ = ["centres_page_table", "centres_rules", "centres_order_table", "guide_words", "ROOM_MIN"]

#: the least room [mm] around the mechanism on the page (its near centres widen it; far ones are arrows outside)
ROOM_MIN = 12.0


def _about(result, body: str) -> str:
    """The label of P_1j of *body* (``P₁₃``), ``P₁₄ ∞`` when it is at infinity (the body translates)."""
    if body == "frame":
        return "—"
    centre = result.centre("frame", body)
    return centre_text(centre.label) + ("" if centre.point is not None else " ∞")


def _as_read(mm: float) -> str:
    """A length on the centres drawing [mm] printed as it is read (:class:`plans.centres.Reading`): to 0.1 mm, one
    under :data:`plans.rounding.SHORT_READ_MM` to 0.01 mm."""
    return f"{mm:.2f}" if mm < SHORT_READ_MM else f"{mm:.1f}"


def centres_page_table(result, comparisons, lang: str = "en", k_l: float | None = None) -> list[list[str]]:
    """The page's table: header, then every link's step in the order it was found, then v of every reported point.

    The rows of the links follow :attr:`plans.centres.InstantCentres.found_order` (the driver first, each link after
    the one it was found from), so that every quantity a row uses is given by a row above it: ω of every link and,
    for a link that translates (P_1j at infinity: ω_j = 0), a row of its velocity v_j under its ω (*comparisons*
    from :func:`plans.compare.compare_centres` with ``translations=True`` hold its analytic value; without them
    its analytic value and error are dashes).  Then v of every reported point.

    Columns: quantity, the centre P_1j its body turns about (1: the frame's number,
    :attr:`plans.scene.Scene.frame_number`), the value from the centres, the analytic
    value, the relative error (of the vector for v).  With *k_l* [m/mm] (the drawing's), a column
    more after P_1j, what was read off the drawing [mm] and how it gives the row's value:

    * ω_j from a link k that turns, through P_jk: ``−ω₂ · P₁₂P₂₅ / P₁₅P₂₅ = −ω₂ · 31.5 / 226.1`` (the ratio
      theorem, the sign by where P_jk lies: :func:`centres_rules`); from a link k that translates:
      ``−v₆ / P₁₄P₄₆ = −v₆ / (88.8 · k_l)`` (v₆ its magnitude, the minus where it turns P_jk clockwise about P_1j:
      :func:`centres_rules`); from one it shares a centre at infinity with: ``ω₄ (P₃₄ ∞)``;
    * v_j of a translating link from a link k that turns: ``ω₂ · P₁₂P₂₆ = ω₂ · 29.0 · k_l`` (it moves as its
      centre P_jk, a point of k); from a translating k: ``v₃`` (through a finite P_jk) or
      ``v₃ + v₄₃ (P₁₄ ∞, P₃₄ ∞)`` (the velocity triangle of two directions);
    * v_M of a point: ``P₁₃G = 349.9``, P_1jM [mm] (v_M = |ω_j| · P_1jM × k_l); ``v₆`` on a translating link; a dash on the driver
      of a sliding driver (given); a pin through the body it was read from (:attr:`plans.centres.InstantCentres.carriers`:
      the ram's pin E as ``v₆`` where P₁₅ lies off the drawing);

    the lengths as :attr:`plans.centres.Motion.via` read them; a dash for what is given and where nothing was read
    (a result found exactly, without a reading).
    """
    frame = result.scene.frame_number
    header = [term("quantity", lang), f"$P_{{{frame}j}}$", term("by_centres", lang), term("analytic", lang), term("rel_error", lang)]
    if k_l is not None:
        header.insert(2, term("read_off_drawing", lang))  # P_1jM for v, the path's lengths for ω: both as read
    rows = [header]
    by = {(c.section, c.name, c.quantity): c for c in comparisons}
    driver = result.scene.driver
    linear = isinstance(driver, LinearDriver)
    k_l_text = "$k_l$"

    def omega(name: str) -> str:
        return f"$\\omega_{{{math_name(name)}}}$"

    def velocity(name: str) -> str:
        return f"$v_{{{math_name(name)}}}$"

    def motion_of(name: str) -> str:
        """The symbol of what link *name*'s row gives the links found from it: v for a translating link, else ω."""
        return velocity(name) if result.translates(name) else omega(name)

    def reading(name: str) -> list[str]:
        """P_1jM [mm] of a point (``v_j`` where its link translates, a dash on a sliding driver: given)."""
        if k_l is None:
            return []
        home = result.carriers.get(name) or result.scene.home_of(name)
        centre = result.centre("frame", home)
        if centre.point is None:
            return ["—" if home == driver.link else motion_of(home)]
        mm = abs(result.positions[name] - centre.point) / k_l
        return [f"{centre_text(centre.label)}{name} = {_as_read(mm)}"]  # (the segment measured: round 20's bare "349,9")

    def step(name: str, translation: bool) -> list[str]:
        """How the row of link *name* (its ω, or with *translation* its v) is found from the link found before it."""
        if k_l is None:
            return []
        motion = result.motions[name]
        k = motion.from_link
        if name == driver.link or not k or (result.translates(name) and not translation):
            return ["—"]  # given, found exactly (nothing read), or ω = 0 of a translating link (P_1j ∞)
        known, pjk, via = motion_of(k), result.centre(name, k), motion.via
        if pjk.point is None:  # a centre at infinity: turns with k, or (both translating) the velocity triangle
            if not translation:  # ω_j = ω_k (0 where k translates: its ω row above)
                return [f"{omega(k)} ({centre_text(pjk.label)} ∞)"]
            both = "" if len(name) == len(k) == 1 else ","
            relative = f"$v_{{{math_name(name)}{both}{math_name(k)}}}$"
            p1j = result.centre("frame", name)
            return [f"{known} + {relative} ({centre_text(p1j.label)} ∞, {centre_text(pjk.label)} ∞)"]
        segments = [(centre_text(a) + centre_text(b), _as_read(mm)) for a, b, mm in via]
        if translation:  # moves as its centre P_jk with k: ω_k · P_1kP_jk, or v_k where k translates too
            if not segments:
                return [known]
            (segment, mm), = segments
            return [f"{known} · {segment} = {known} · {mm} · {k_l_text}"]
        if result.translates(k):  # ω_j = ±v_k / P_1jP_jk, v_k its magnitude: − where v_k turns P_jk clockwise about P_1j
            (segment, mm), = segments
            sign = "−" if motion.omega < 0 else ""
            return [f"{sign}{known} / {segment} = {sign}{known} / ({mm} · {k_l_text})"]
        (near, a), (far, b) = segments  # ω_j = ±ω_k · P_1kP_jk / P_1jP_jk: the sign by where P_jk lies
        sign = "−" if motion.omega * result.motions[k].omega < 0 else ""
        return [f"{sign}{known} · {near} / {far} = {sign}{known} · {a} / {b}"]

    def values(key: tuple, centres_value, given: bool) -> list[str]:
        row = by.get(key)
        if row is None:  # no analytic value to compare (compare_centres without translations)
            return [row_texts(centres_value, centres_value, given=given)[0], "—", "—"]
        return list(row_texts(row.graphical, row.analytic, given=given))

    # the values and errors by the rule of every comparison table (plans.report.row_texts): the centres' value to
    # 4 significant digits, the analytic one to its decimals, the error of the two printed numbers; the driver's
    # ω (and a sliding driver's v) is given: "—", as on the plans' pages
    for name in result.found_order:
        if ("links", name, "omega") in by:
            rows.append([f"{omega(name)} [rad/s]", _about(result, name)] + step(name, False)
                        + values(("links", name, "omega"), float(result.links[name]), name == driver.link))
        if result.translates(name):
            rows.append([f"{velocity(name)} [m/s]", _about(result, name)] + step(name, True)
                        + values(("links", name, "v"), complex(result.motions[name].v0), name == driver.link))
    for name in result.scene.report:
        row = by.get(("points", name, "v"))
        if row is not None:
            home = result.carriers.get(name) or result.scene.home_of(name)  # a pin: the body its v was read from
            given = linear and home == driver.link
            rows.append([f"{velocity(name)} [m/s]", _about(result, home)] + reading(name)
                        + list(row_texts(complex(row.graphical), complex(row.analytic), given=given)))
    return [[decimal_comma(cell, lang) for cell in row] for row in rows]


def centres_rules(lang: str, frame: str, driver=None, numbers=None, translating: bool = False) -> list[str]:
    """The rules of the method, each its words and its formula or statement (after ``":  "``): ω from the centres,
    the sense of rotation it gives (the ratio theorem's sign), with *translating* the step through a link that
    translates, and v of a point from its link's centre.

    *frame*: the frame's number (:attr:`plans.scene.Scene.frame_number`), as the centres' labels write it.
    *driver* (:class:`plans.scene.LinearDriver`) with *numbers* (body name -> its number in the labels,
    :attr:`plans.centres.InstantCentres.numbers`): a sliding driver has no ω to start from; the rule then
    starts from its velocity v_A, as the textbook does: the centre P_dk of the driver d and a link k moves
    as a point of d with v_A and as a point of k about P_1k, so ω_k = v_A / P_1kP_dk.
    The sense: ω_j / ω_k = P_1kP_jk / P_1jP_jk is positive (the same sense) when P_jk lies outside the segment
    P_1jP_1k, negative inside (domain.md §8); the tables print the minus.
    *translating* (a link other than a sliding driver translates at some position: P_1j at infinity): such a
    link j moves as its centre P_jk with a link k, v_j = ω_k · P_1kP_jk, and a link l found from it turns with
    ω_l = v_j / P_1lP_jl.
    """
    from ..scene import LinearDriver

    linear = isinstance(driver, LinearDriver)
    if linear:
        d = (numbers or {}).get(driver.link, driver.link)
        point = math_name(driver.point)
        omega = (f"{term('centres_omega_rule_linear', lang)}:  "
                 f"$\\omega_k = \\pm v_{{{point}}} / P_{{{frame}k}}P_{{{d}k}}$")
    else:
        omega = f"{term('centres_omega_rule', lang)}:  $\\omega_j / \\omega_k = P_{{{frame}k}}P_{{jk}} / P_{{{frame}j}}P_{{jk}}$"
    sign = term("centres_sign_rule", lang).format(omega_j="$\\omega_j$", omega_k="$\\omega_k$", pjk="$P_{jk}$",
                                                  segment=f"$P_{{{frame}j}}P_{{{frame}k}}$")
    # through a link that translates the ratio has no ω_k to take the sense from: the sign by the sense in which the
    # link's velocity, at the common centre, turns about the next link's centre (as the tables print it)
    if translating:
        sign += "; " + term("centres_sign_rule_translating", lang).format(
            formula=f"$\\omega_l = \\pm v_j / P_{{{frame}l}}P_{{jl}}$", v="$v_j$", p="$P_{jl}$", p1=f"$P_{{{frame}l}}$")
    elif linear:
        sign += "; " + term("centres_sign_rule_translating", lang).format(
            formula=f"$\\omega_k = \\pm v_{{{point}}} / P_{{{frame}k}}P_{{{d}k}}$", v=f"$v_{{{point}}}$", p=f"$P_{{{d}k}}$",
            p1=f"$P_{{{frame}k}}$")
    rules = [omega, f"{term('centres_sign', lang)}:  {sign}"]
    if translating:
        said = term("centres_translation_rule", lang).format(p1j=f"$P_{{{frame}j}}$", omega_j="$\\omega_j$", k="$k$", l="$l$")
        rules.append(f"{said}:  $v_j = \\omega_k \\cdot P_{{{frame}k}}P_{{jk}}$;\u2003$\\omega_l = \\pm v_j / P_{{{frame}l}}P_{{jl}}$")
    rules.append(f"{term('centres_v_rule', lang)}:  $v_M = \\omega_j \\cdot P_{{{frame}j}}M$")
    return rules


def guide_words(result, centre, lang: str = "en") -> str:
    """Where the centre of a prismatic pair lies, naming its guide: "at infinity, perpendicular to the guide on link 4
    (slot)" (the link that carries the guide, by its number; the frame's guide as the frame's), the guide's own name
    after it where the scene gives it in ``[names]`` (in *lang*, else as written).  Three centres of the linear-arm
    lie on three different guides: each says which."""
    from ..scene import FRAME

    scene = result.scene
    name = centre.found_by.partition(" ")[2]
    guides = {p.name: (p.guide, p.guide_line) for p in scene.prismatics}
    driver = scene.driver
    if getattr(driver, "guide", None) is not None and getattr(driver, "point", None) is not None:
        guides.setdefault(f"{driver.point} on frame.{driver.guide}", (FRAME, driver.guide))
    body, line = guides.get(name, (None, None))
    if body == FRAME:
        words = term("centre_perpendicular_frame_guide", lang)
    elif body is not None:
        words = term("centre_perpendicular_guide", lang).format(link=result.numbers.get(body, body))
    else:
        raise ValueError(f"no guide of the prismatic pair {name!r} in the scene")  # kennedy.py names every guide it uses
    if line in scene.names:
        words += f" ({scene.name_in(line, lang)})"
    return words


def centres_order_table(result, lang: str = "en") -> list[list[str]]:
    """How every centre is found, in the order a student finds them: header, then the centres at the pairs (a
    revolute's at its pin, a prismatic's at infinity perpendicular to the guide), then each of Kennedy's as the
    meeting of its two lines (``P₁₂P₂₃ ∩ P₁₄P₃₄``) once both lines' centres are known.  The same for every
    position of a mechanism (the circle diagram's order), so the centres' pages state it once."""
    def how(centre) -> str:
        if not centre.determined:
            return term("centre_undetermined", lang)
        if centre.found_by.startswith("revolute"):
            return term("centre_at_pin", lang).format(pin=centre.found_by.partition(" ")[2])
        if centre.found_by.startswith("prismatic"):
            return guide_words(result, centre, lang)
        (a, b), (c, d) = centre.lines
        return f"{centre_text(a)}{centre_text(b)} ∩ {centre_text(c)}{centre_text(d)}"

    primary = [c for c in result.centres if c.found_by != "kennedy"]
    known = {c.label for c in primary if c.determined}
    order = list(primary)
    rest = [c for c in result.centres if c.found_by == "kennedy"]
    while rest:
        ready = [c for c in rest if all(x in known for line in c.lines for x in line)] or rest[:1]
        order.append(ready[0])
        known.add(ready[0].label)
        rest.remove(ready[0])
    return [[term("centre_column", lang), term("found_column", lang)]] + [[centre_text(c.label), how(c)] for c in order]
