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
    """The page's table: header, then ω of every link and v of every reported point, from the centres and analytic.

    Columns: quantity, the centre P_1j its body turns about (1: the frame's number,
    :attr:`plans.scene.Scene.frame_number`), the value from the centres, the analytic
    value, the relative error (of the vector for v).  *comparisons* from
    :func:`plans.compare.compare_centres`.  With *k_l* [m/mm] (the drawing's), a column
    more after P_1j: the reading P_1jM [mm] on the drawing, from which
    v_M = |ω_j| · P_1jM × k_l (a dash where P_1j is at infinity: the link translates); for ω,
    the lengths it was read from, P_1kP_jk / P_1jP_jk [mm] (:attr:`plans.centres.Motion.via`: the
    path of centres the reading took), or ω_k (P_jk ∞) for a link that turns with link k (their centre at
    infinity: nothing measured); a dash for the driver.
    """
    frame = result.scene.frame_number
    header = [term("quantity", lang), f"$P_{{{frame}j}}$", term("by_centres", lang), term("analytic", lang), term("rel_error", lang)]
    if k_l is not None:
        header.insert(2, term("read_off_drawing", lang))  # P_1jM for v, the path's lengths for ω: both as read
    rows = [header]
    by = {(c.section, c.name): c for c in comparisons}

    def reading(name: str) -> list[str]:
        if k_l is None:
            return []
        centre = result.centre("frame", result.scene.home_of(name))
        if centre.point is None:
            return ["—"]
        mm = abs(result.positions[name] - centre.point) / k_l
        return [_as_read(mm)]

    def path(name: str) -> list[str]:
        """The lengths ω was read from, as the rule writes them: ``P₁₂P₂₄ / P₁₄P₂₄ = 1.1 / 25.3`` (a dash where none)."""
        if k_l is None:
            return []
        motion = result.motions[name]
        via = motion.via
        if not via and motion.from_link:  # through a centre at infinity: it turns with the other, nothing measured
            return [f"$\\omega_{{{math_name(motion.from_link)}}}$ ({centre_text(result.centre(name, motion.from_link).label)} ∞)"]
        if not via:
            return ["—"]
        segments = " / ".join(centre_text(a) + centre_text(b) for a, b, _ in via)
        return [f"{segments} = {' / '.join(_as_read(mm) for _, _, mm in via)}"]

    # the values and errors by the rule of every comparison table (plans.report.row_texts): the centres' value to
    # 4 significant digits, the analytic one to its decimals, the error of the two printed numbers; the driver's
    # ω (and a sliding driver's v) is given: "—", as on the plans' pages
    driver = result.scene.driver
    linear = isinstance(driver, LinearDriver)
    for name in result.scene.links:
        row = by.get(("links", name))
        if row is not None:
            rows.append([f"$\\omega_{{{math_name(name)}}}$ [rad/s]", _about(result, name)] + path(name)
                        + list(row_texts(float(row.graphical), float(row.analytic), given=name == driver.link)))
    for name in result.scene.report:
        row = by.get(("points", name))
        if row is not None:
            given = linear and result.scene.home_of(name) == driver.link
            rows.append([f"$v_{{{math_name(name)}}}$ [m/s]", _about(result, result.scene.home_of(name))] + reading(name)
                        + list(row_texts(complex(row.graphical), complex(row.analytic), given=given)))
    return [[decimal_comma(cell, lang) for cell in row] for row in rows]


def centres_rules(lang: str, frame: str, driver=None, numbers=None) -> list[str]:
    """The two rules of the method, each with its formula (``$…$``): ω from the centres, v of a point from its link's centre.

    *frame*: the frame's number (:attr:`plans.scene.Scene.frame_number`), as the centres' labels write it.
    *driver* (:class:`plans.scene.LinearDriver`) with *numbers* (body name -> its number in the labels,
    :attr:`plans.centres.InstantCentres.numbers`): a sliding driver has no ω to start from; the rule then
    starts from its velocity v_A, as the textbook does: the centre P_dk of the driver d and a link k moves
    as a point of d with v_A and as a point of k about P_1k, so ω_k = v_A / P_1kP_dk.
    """
    from ..scene import LinearDriver

    if isinstance(driver, LinearDriver):
        d = (numbers or {}).get(driver.link, driver.link)
        point = math_name(driver.point)
        omega = (f"{term('centres_omega_rule_linear', lang)}:  "
                 f"$\\omega_k = v_{{{point}}} / P_{{{frame}k}}P_{{{d}k}}$")
    else:
        omega = f"{term('centres_omega_rule', lang)}:  $\\omega_j / \\omega_k = P_{{{frame}k}}P_{{jk}} / P_{{{frame}j}}P_{{jk}}$"
    return [
        omega,
        f"{term('centres_v_rule', lang)}:  $v_M = \\omega_j \\cdot P_{{{frame}j}}M$",
    ]


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
