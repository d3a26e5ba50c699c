"""Text tables, JSON and CSV of solved mechanisms.

Formatting only: every number here was computed by the analytic solver or read
off the graphical plans before it arrives.  The JSON schema is documented in
the README ("JSON schema") and kept stable: keys are only ever added.
"""

from __future__ import annotations

import cmath
import io
import json
import math

from ._text import math_name
from .compare import PLAN_QUANTITIES, QUANTITIES, ZERO_FRACTION, Comparison
from .errors import PlansError
from .limits import expected_rel_error
from .scene import Crank, Scene
from .sweep import sweep_csv
from .structure import branches

__all__ = ["driver_summary", "solution_json", "solution_table", "sweep_csv", "format_json", "sheet_table", "guide_direction",
           "drawn_rows", "table_number", "table_error"]

SCHEMA_VERSION = 1


#: A value at most this fraction of its quantity's scale (the largest value of that kind at
#: the same position: lengths, velocities, accelerations, ω, ε) is round-off and reported as 0.
ROUNDOFF = 1e-12


def _clean(x: float, scale: float = 0.0) -> float:
    """Floats for output: -0.0 becomes 0.0, and so does round-off far below *scale* (:data:`ROUNDOFF`)."""
    x = float(x)
    return 0.0 if x == 0 or abs(x) <= ROUNDOFF * scale else x


def _sine(x: float) -> float:
    """|sin| for output: at most 1 (round-off can give 1 + 2e-16)."""
    return min(_clean(x), 1.0)


def _condition(x: float) -> float:
    """A condition number for output: at least 1."""
    return max(_clean(x), 1.0)


def _vec(z: complex, scale: float = 0.0) -> list[float]:
    z = complex(z)
    return [_clean(z.real, scale), _clean(z.imag, scale)]


def _as_given(x: float) -> float:
    """*x* without the round-off of a unit conversion: a value within a few units in the last
    place of a number with 12 significant digits is that number (0.35000000000000003 is 0.35)."""
    short = float(f"{x:.12g}")
    return short if abs(short - x) <= 8 * math.ulp(x) else x


def _deg(phi: float) -> float:
    """An angle [rad] in degrees in [0, 360), as the courses write angles.

    The round-off of the conversion is removed: an angle given as 30° comes
    back as 30, not 29.999999999999996 (a result within a few units in the
    last place of a value with 12 significant digits is that value), and an
    angle within 360·:data:`ROUNDOFF` of a full turn is 0.
    """
    d = _as_given(math.degrees(float(phi)) % 360.0)
    if d <= 360.0 * ROUNDOFF or 360.0 - d <= 360.0 * ROUNDOFF:
        return 0.0
    return d


def _scales(analytic, k: int) -> dict[str, float]:
    """The scale of each kind of quantity at position k: the largest magnitude of that kind (for :func:`_clean`)."""
    def largest(values):
        finite = [abs(complex(v)) for v in values if math.isfinite(abs(complex(v)))]
        return max(finite, default=0.0)

    points = analytic.points.values()
    sliders = analytic.sliders.values()
    links = analytic.links.values()
    acc = analytic.scene.accelerations
    return {
        "length": largest([m.r[k] for m in points] + [m.s[k] for m in sliders]),
        "velocity": largest([m.v[k] for m in points] + [m.v_rel[k] for m in sliders]),
        "acceleration": largest([m.a[k] for m in points] + [m.a_rel[k] for m in sliders] + [m.coriolis[k] for m in sliders]) if acc else 0.0,
        "omega": largest([m.omega[k] for m in links]),
        "epsilon": largest([m.epsilon[k] for m in links]) if acc else 0.0,
    }


#: The kind of each compared quantity, for its scale.
_KIND = {"r": "length", "s": "length", "v": "velocity", "v_rel": "velocity", "a": "acceleration",
         "a_rel": "acceleration", "coriolis": "acceleration", "omega": "omega", "epsilon": "epsilon"}


def check_finite(analytic, graphical=None, comparisons: list[Comparison] | None = None, position: int = 0) -> None:
    """Refuse to report a position with a value that is not a finite number.

    The solvers refuse dead centres and failed assemblies themselves; what is
    left is overflow (numbers beyond ~1e308).  Raises :class:`PlansError`
    naming the first such quantity, so inf or NaN never reaches a table or a
    JSON document.
    """
    k = position
    checks: list[tuple[str, object]] = []
    for name, m in analytic.points.items():
        checks += [(f"point {name}: r", m.r[k]), (f"point {name}: v", m.v[k])]
        if analytic.scene.accelerations:
            checks.append((f"point {name}: a", m.a[k]))
    for name, m in analytic.links.items():
        checks += [(f"link {name}: φ", m.phi[k]), (f"link {name}: ω", m.omega[k])]
        if analytic.scene.accelerations:
            checks.append((f"link {name}: ε", m.epsilon[k]))
    for name, m in analytic.sliders.items():
        checks += [(f"slider {name}: s", m.s[k]), (f"slider {name}: v_rel", m.v_rel[k])]
        if analytic.scene.accelerations:
            checks += [(f"slider {name}: a_rel", m.a_rel[k]), (f"slider {name}: Coriolis", m.coriolis[k])]
    for name, c in analytic.conditions.items():
        checks.append((f"group {name}: condition", c[k]))
    for row in comparisons or ():
        checks.append((f"graphical {row.section[:-1]} {row.name}: {row.quantity}", row.graphical))
        checks.append((f"graphical {row.section[:-1]} {row.name}: {row.quantity} error", row.rel_error))
    if graphical is not None:
        for key, value in graphical.scales.items():
            checks.append((f"scale {key}", value))
    for what, value in checks:
        z = complex(value)
        if not (math.isfinite(z.real) and math.isfinite(z.imag)):
            raise PlansError(
                f"{analytic.scene.source}: {what} is not a finite number at this position ({value}): the scene's "
                "numbers overflow double precision; rescale lengths or rates towards 1 (SI)"
            )


def driver_summary(scene: Scene) -> dict:
    """The driver as JSON-ready data, SI units (angles in degrees)."""
    d = scene.driver
    if isinstance(d, Crank):
        return {
            "type": "crank",
            "link": d.link,
            "pivot": d.pivot,
            "phi_deg": _deg(d.phi),
            "omega": _clean(d.omega),
            "epsilon": _clean(d.epsilon),
        }
    return {
        "type": "linear",
        "link": d.link,
        "point": d.point,
        "guide": f"frame.{d.guide}",
        "s": _clean(d.s),
        "velocity": _clean(d.velocity),
        "acceleration": _clean(d.acceleration),
    }


def _driver_words(scene: Scene) -> str:
    d = scene.driver
    if isinstance(d, Crank):
        return (
            f"crank {d.link} about {d.pivot}: φ = {_deg(d.phi):.3f}°, "
            f"ω = {d.omega:.6g} rad/s, ε = {d.epsilon:.6g} rad/s²"
        )
    return (
        f"slide {d.link} along frame.{d.guide}, point {d.point}: s = {d.s:.6g} m, "
        f"v = {d.velocity:.6g} m/s, a = {d.acceleration:.6g} m/s²"
    )


def _graphical_lookup(comparisons: list[Comparison] | None):
    table: dict[tuple[str, str, str], Comparison] = {}
    for row in comparisons or ():
        table[(row.section, row.name, row.quantity)] = row
    return table


def _graphical_entry(rows: dict, section: str, name: str, accelerations: bool, scales: dict) -> dict:
    """The ``"graphical"`` entry of one point, link or slider: each compared value with its errors."""
    entry: dict = {}
    for quantity, needs_accelerations in QUANTITIES[section]:
        row = rows.get((section, name, quantity))
        if row is None or (needs_accelerations and not accelerations):
            continue
        value = row.graphical
        scale = scales[_KIND[quantity]]
        entry[quantity] = _vec(value, scale) if isinstance(value, complex) else _clean(value, scale)
        entry[f"{quantity}_abs_error"] = _clean(row.abs_error)
        entry[f"{quantity}_rel_error"] = _clean(row.rel_error)
    return entry


def solution_json(analytic, graphical=None, comparisons: list[Comparison] | None = None, position: int = 0) -> dict:
    """The documented JSON document of one position.

    Parameters
    ----------
    analytic : plans.analytic.AnalyticSolution
    graphical : plans.graphical.plan.GraphicalSolution, optional
        When given, each quantity gets a ``"graphical"`` entry beside its
        ``"analytic"`` one, with ``"abs_error"`` and ``"rel_error"``.
    comparisons : list[Comparison], optional
        From :func:`plans.compare.compare`.
    position : int
        Index into the analytic solution's driver positions.
    """
    check_finite(analytic, graphical, comparisons, position)
    scene = analytic.scene
    k = position
    acc = scene.accelerations
    rows = _graphical_lookup(comparisons)
    sc = _scales(analytic, k)
    doc: dict = {
        "schema": SCHEMA_VERSION,
        "title": scene.title,
        "driver": driver_summary(scene),
        "structure": analytic.structure.formula,
        "units": {"length": "m", "angle": "deg", "velocity": "m/s", "acceleration": "m/s^2",
                  "omega": "rad/s", "epsilon": "rad/s^2"},
        "points": {},
        "links": {},
        "sliders": {},
        "groups": {},
    }
    for name in scene.report:
        motion = analytic.points[name]
        entry = {"analytic": {"r": _vec(motion.r[k], sc["length"]), "v": _vec(motion.v[k], sc["velocity"])}}
        if acc:
            entry["analytic"]["a"] = _vec(motion.a[k], sc["acceleration"])
        if graphical is not None:
            entry["graphical"] = _graphical_entry(rows, "points", name, acc, sc)
        doc["points"][name] = entry
    for name in scene.links:
        motion = analytic.links[name]
        entry = {"analytic": {"phi_deg": _deg(motion.phi[k]), "omega": _clean(motion.omega[k], sc["omega"])}}
        if acc:
            entry["analytic"]["epsilon"] = _clean(motion.epsilon[k], sc["epsilon"])
        if graphical is not None and name in graphical.links:
            entry["graphical"] = _graphical_entry(rows, "links", name, acc, sc)
        doc["links"][name] = entry
    for prismatic in scene.prismatics:
        name = prismatic.name
        motion = analytic.sliders[name]
        entry = {"analytic": {"s": _clean(motion.s[k], sc["length"]), "v_rel": _clean(motion.v_rel[k], sc["velocity"])}}
        if acc:
            entry["analytic"]["a_rel"] = _clean(motion.a_rel[k], sc["acceleration"])
            entry["analytic"]["coriolis"] = _vec(motion.coriolis[k], sc["acceleration"])
        if graphical is not None and name in graphical.sliders:
            entry["graphical"] = _graphical_entry(rows, "sliders", name, acc, sc)
        entry["motion"] = {"body": prismatic.slider, "relative_to": prismatic.guide,
                           "guide_deg": _deg(cmath.phase(guide_direction(analytic, prismatic, k)))}
        drawn = getattr(graphical, "relative", {}).get(name) if graphical is not None else None
        if drawn is not None:
            entry["drawn"] = {"body": drawn["moving"], "relative_to": drawn["reference"], "sign": drawn["sign"],
                              **{q: drawn[q] for q in ("v_rel", "a_rel", "coriolis") if q in drawn}}
        doc["sliders"][name] = entry
    branch_of = {b.group: b for b in branches(analytic, k)}
    for group in analytic.structure.groups:
        condition = _condition(analytic.conditions[group.name][k])
        entry = {"kind": group.kind, "links": list(group.links), "joint": group.joint,
                 "condition": condition,
                 "expected_rel_error": _clean(expected_rel_error(condition)),
                 "analytic_sine": _sine(analytic.sines[group.name][k])}
        if graphical is not None and group.name in graphical.sines:
            entry["sine"] = _sine(graphical.sines[group.name])
            if group.name in graphical.conditions:
                entry["graphical_condition"] = _condition(graphical.conditions[group.name])
        else:
            entry["sine"] = entry["analytic_sine"]
        entry["branch"] = branch_of[group.name].as_dict()
        doc["groups"][group.name] = entry
    position_value = float(analytic.driver[k])
    warnings = [w for w in analytic.warnings if w.position == position_value]
    if graphical is not None:
        warnings += list(graphical.warnings)
    doc["warnings"] = [w.as_dict() for w in warnings]
    if graphical is not None:
        doc["scales"] = {key: _clean(value) for key, value in graphical.scales.items()}
        if graphical.precision is not None:
            doc["scales"]["precision_mm"] = _clean(graphical.precision)
    return doc


def guide_direction(analytic, prismatic, position: int = 0) -> complex:
    """The unit direction u_g of a prismatic joint's guide line at a position, from the analytic body angle.

    The JSON's ``v_rel``, ``a_rel`` are along it: the relative velocity vector is ``v_rel·u_g``.
    """
    line = analytic.scene.bodies[prismatic.guide].lines[prismatic.guide_line]
    phi = 0.0 if prismatic.guide not in analytic.links else float(analytic.links[prismatic.guide].phi[position])
    return cmath.exp(1j * (phi + line.angle))


def format_json(doc: dict) -> str:
    """Deterministic JSON text (insertion order, full float precision)."""
    return json.dumps(doc, indent=2, ensure_ascii=False, allow_nan=False) + "\n"


# --- text table --------------------------------------------------------------


def _vector_cells(z: complex, scale: float = 0.0) -> list[str]:
    z = complex(*_vec(z, scale))
    magnitude = abs(z)
    direction = f"{_deg(cmath.phase(z)):9.3f}" if magnitude > 0 else "        —"
    return [f"{z.real:13.6g}", f"{z.imag:13.6g}", f"{magnitude:13.6g}", direction]


def _slider_words(travel: float, v_rel: float, accelerations: tuple | None, sc: dict) -> str:
    """``s = …, v_rel = …[, a_rel = …, Coriolis = (x, y) |magnitude|]`` of one slider."""
    words = f"s = {_clean(travel, sc['length']):.6g}, v_rel = {_clean(v_rel, sc['velocity']):.6g}"
    if accelerations is not None:
        a_rel, coriolis = accelerations
        c = complex(*_vec(complex(coriolis), sc["acceleration"]))
        words += f", a_rel = {_clean(a_rel, sc['acceleration']):.6g}, Coriolis = ({c.real:.6g}, {c.imag:.6g}) |{abs(c):.6g}|"
    return words


def _error_cells(row: Comparison | None) -> list[str]:
    if row is None:
        return []
    return [f"{row.abs_error:10.2e}", f"{row.rel_error:10.2e}"]


def solution_table(analytic, graphical=None, comparisons: list[Comparison] | None = None, position: int = 0) -> str:
    """A readable table of one position; graphical values and errors when given."""
    check_finite(analytic, graphical, comparisons, position)
    scene = analytic.scene
    k = position
    acc = scene.accelerations
    rows = _graphical_lookup(comparisons)
    sc = _scales(analytic, k)
    out = io.StringIO()
    w = out.write
    w(f"{scene.title}\n")
    w(f"structure: {analytic.structure.formula}   (mobility W = {analytic.structure.mobility})\n")
    w(f"driver: {_driver_words(scene)}\n")
    if scene.readings:
        w(f"        bare numbers read as SI and degrees: {'; '.join(scene.readings)}\n")
    if graphical is not None:
        scales = ", ".join(f"{key} = {value:g}" for key, value in graphical.scales.items())
        precision = f", drafting precision {graphical.precision:g} mm" if graphical.precision else ""
        w(f"plan scales: {scales}   (m/mm, (m/s)/mm, (m/s²)/mm){precision}\n")
    w("\nPoints   r [m], v [m/s], a [m/s²]; direction in degrees from +x, counter-clockwise\n")
    header = f"{'point':6} {'':3} {'method':9} {'x':>13} {'y':>13} {'magnitude':>13} {'dir [°]':>9}"
    if graphical is not None:
        header += f" {'abs err':>10} {'rel err':>10}"
    w(header + "\n")
    for name in scene.report:
        motion = analytic.points[name]
        quantities = [("r", motion.r[k]), ("v", motion.v[k])] + ([("a", motion.a[k])] if acc else [])
        for index, (q, value) in enumerate(quantities):
            label = name if index == 0 else ""
            w(f"{label:6} {q:3} {'analytic':9} " + " ".join(_vector_cells(complex(value), sc[_KIND[q]])) + "\n")
            row = rows.get(("points", name, q))
            if row is not None:
                w(f"{'':6} {'':3} {'graphical':9} " + " ".join(_vector_cells(complex(row.graphical), sc[_KIND[q]]))
                  + " " + " ".join(_error_cells(row)) + "\n")
    w("\nLinks   φ [°], ω [rad/s], ε [rad/s²]; counter-clockwise positive\n")
    w(f"{'link':6} {'method':9} {'φ [°]':>11} {'ω':>13} " + (f"{'ε':>13}" if acc else "") + "\n")
    for name in scene.links:
        motion = analytic.links[name]
        line = f"{name:6} {'analytic':9} {_deg(motion.phi[k]):11.4f} {_clean(motion.omega[k], sc['omega']):13.6g} "
        if acc:
            line += f"{_clean(motion.epsilon[k], sc['epsilon']):13.6g}"
        w(line.rstrip() + "\n")
        om, ep = rows.get(("links", name, "omega")), rows.get(("links", name, "epsilon"))
        if om is not None:
            line = f"{'':6} {'graphical':9} {'':11} {_clean(om.graphical, sc['omega']):13.6g} "
            if ep is not None:
                line += f"{_clean(ep.graphical, sc['epsilon']):13.6g}"
            w(line.rstrip() + "\n")
            errors = [f"ω {om.abs_error:.2e} ({om.rel_error:.1e} rel)"]
            if ep is not None:
                errors.append(f"ε {ep.abs_error:.2e} ({ep.rel_error:.1e} rel)")
            w(f"{'':6} {'error':9} " + ", ".join(errors) + "\n")
    if scene.prismatics:
        w("\nSliders   s [m], v_rel [m/s], a_rel [m/s²] along the guide; Coriolis vector [m/s²]\n")
        for prismatic in scene.prismatics:
            name = prismatic.name
            motion = analytic.sliders[name]
            what = f"{prismatic.slider}.{prismatic.slider_line} on {prismatic.guide}.{prismatic.guide_line}"
            w(f"{name} ({what})\n")
            accelerations = (motion.a_rel[k], motion.coriolis[k]) if acc else None
            w(f"  analytic   {_slider_words(motion.s[k], motion.v_rel[k], accelerations, sc)}\n")
            vr = rows.get(("sliders", name, "v_rel"))
            if vr is not None:
                sr, ar, co = (rows.get(("sliders", name, q)) for q in ("s", "a_rel", "coriolis"))
                accelerations = (ar.graphical, co.graphical) if ar is not None else None
                worst = max((r for r in (sr, vr, ar, co) if r is not None), key=lambda r: r.rel_error)
                w(f"  graphical  {_slider_words(sr.graphical, vr.graphical, accelerations, sc)}"
                  f"   (largest rel err {worst.rel_error:.1e})\n")
    branch_of = {b.group: b for b in branches(analytic, k)}
    w("\nGroups   condition number of the analytic 2×2 system; |sin| between the construction lines; "
      "expected relative error of v, a (4·ε_mach·condition²)\n")
    for group in analytic.structure.groups:
        condition = _condition(analytic.conditions[group.name][k])
        sine = _sine(graphical.sines[group.name] if graphical is not None and group.name in graphical.sines else analytic.sines[group.name][k])
        sine_text = f"{sine:.4f}" if sine >= 1e-3 else f"{sine:.3e}"
        line = (f"{group.name:12} joint {group.joint:4} condition {condition:10.4g}   sine {sine_text}"
                f"   expected rel. error {expected_rel_error(condition):.1e}")
        w(line + "\n")
        w(f"{'':12} {_branch_words(branch_of[group.name])}\n")
    if comparisons:
        worst = max(comparisons, key=lambda r: r.rel_error)
        w(f"\nlargest relative difference graphical vs analytic: {worst.rel_error:.2e} "
          f"({worst.section[:-1]} {worst.name}, {worst.quantity})\n")
    return out.getvalue()


def _branch_words(branch) -> str:
    """``branch +1: C to the left of B→D (default (+1); another assembly exists there)``."""
    if branch.sign == 0:
        return "branch: one assembly only"
    other = "another assembly exists there" if branch.other_assembly else "no other assembly there (dead centre)"
    return f"branch {branch.sign:+d}: {branch.words} (chosen by {branch.chosen_by}; {other})"


# --- sweep CSV -----------------------------------------------------------------


# sweep_csv lives with the sweep's analysis (plans/sweep.py) and is imported above.


# --- the sheet's results table -------------------------------------------------

_UNITS = {"v": "m/s", "a": "m/s²", "omega": "rad/s", "epsilon": "rad/s²", "v_rel": "m/s", "a_rel": "m/s²", "coriolis": "m/s²"}
#: the symbols of the sheet table, typeset (``$…$``): v_A, ω₃, the relative velocity vʳ, aʳ and the Coriolis aᵏ
_SYMBOL = {"v": "v", "a": "a", "omega": r"\omega", "epsilon": r"\varepsilon", "v_rel": "v^{r}", "a_rel": "a^{r}", "coriolis": "a^{k}"}
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


#: A table value at most this fraction of the largest of its kind at the same position (velocities,
#: accelerations, ω, ε) is round-off of a zero (a dead centre's v = 0): printed 0, its relative error :data:`NO_ERROR`.
TABLE_ROUNDOFF = 1e-9
#: The relative error of a quantity that is zero: not defined.
NO_ERROR = "—"


def table_number(value: float, digits: int = 4) -> str:
    """*value* to *digits* significant digits as printed in a table: true minus sign, no ``e`` notation.

    Ordinary magnitudes (1e-3 … 1e6) in positional notation (``12160``,
    ``−0.7759``); others as ``2.615·10⁻⁹``.
    """
    if value == 0 or not math.isfinite(value):
        return "0" if value == 0 else str(value)
    text = f"{value:.{digits}g}"
    if "e" in text:
        if 1e-3 <= abs(value) < 1e6:
            text = f"{float(text):.0f}"
        else:
            mantissa, exponent = text.split("e")
            text = f"{mantissa}·10{str(int(exponent)).translate(_SUPERSCRIPT)}"
    return text.replace("-", "−")


def reading_number(value: float, step: float | None) -> str:
    """A graphical reading to the digits its resolution *step* justifies (a 0.1 mm segment at k_a 0.15 ÷ 0.37 m:
    0.04 rad/s², so 2 decimals: ``0.08``, not ``0.08109``); to 4 significant digits without a step."""
    if step is None or step <= 0 or value == 0 or not math.isfinite(value):
        return table_number(value)
    from decimal import ROUND_HALF_UP, Decimal

    decimals = max(0, -math.floor(math.log10(step)))
    # half up, from the value to 12 digits: a reading 6.5 mm × 0.015 = 0.0975 prints 0.098 wherever it is printed, also
    # where it came through a vector's direction as 0.09749999999999999 (the readings table said 0.098, the comparison
    # table 0.097)
    text = str(Decimal(f"{value:.12g}").quantize(Decimal(1).scaleb(-decimals), rounding=ROUND_HALF_UP))
    if float(text) == 0:
        return "0"
    return text.replace("-", "−")


def _magnitude(value, step: float | None = None) -> str:
    if isinstance(value, complex):
        return f"{reading_number(abs(value), step)} ∠ {_deg(cmath.phase(value)):.1f}°".replace("-", "−") if value != 0 else "0"
    return reading_number(value, step)


def _significant(value: float, digits: int = 4) -> str:
    """*value* to *digits* significant digits with its trailing zeros (``14.70``, ``−1.810``; ``12160``):
    :func:`table_number` keeps the zeros a reading gives."""
    if value == 0 or not math.isfinite(value):
        return table_number(value)
    text = f"{value:#.{digits}g}"
    if "e" in text:
        return table_number(value, digits)
    return text.rstrip(".").replace("-", "−")


def _printed_decimals(text: str) -> int | None:
    """The decimals of a printed magnitude (``14.70 ∠ 180.0°`` → 2, ``−10`` → 0); None for ``2.6·10⁻⁹``."""
    magnitude = text.split(" ∠")[0]
    if "·10" in magnitude:
        return None
    return len(magnitude.partition(".")[2])


def _printed_value(text: str) -> complex | float:
    """A printed cell back to its number: ``0.775 ∠ 263.4°`` → the vector, ``−3.35`` → −3.35, ``2.6·10⁻⁹`` → 2.6e-9."""
    def number(t: str) -> float:
        t = t.strip().replace("−", "-")
        if "·10" in t:
            mantissa, exponent = t.split("·10")
            return float(mantissa) * 10 ** int(exponent.translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")))
        return float(t)

    if "∠" in text:
        magnitude, angle = text.split("∠")
        return number(magnitude) * cmath.exp(1j * math.radians(number(angle.replace("°", ""))))
    return number(text)


def _to_decimals(value, decimals: int) -> str:
    """*value* (a number, or a vector as magnitude ∠ direction) to *decimals* places, trailing zeros kept; 0 as ``0``."""
    magnitude = abs(value) if isinstance(value, complex) else value
    text = f"{magnitude:.{decimals}f}"
    if float(text) == 0:
        return "0"
    if isinstance(value, complex):
        text += f" ∠ {_deg(cmath.phase(value)):.1f}°"
    return text.replace("-", "−")


#: the least significant digits of an analytic value in a comparison table (:func:`row_texts`)
ANALYTIC_DIGITS = 4


def row_texts(graphical, analytic, step: float | None = None, given: bool = False) -> tuple[str, str, str]:
    """The three cells of a comparison row: the graphical (or instant-centre) value, the analytic one, the relative error.

    The rule of every comparison table (the sheet's, the handout's, the centres page's): the graphical value to
    the digits its reading justifies (:func:`reading_number` with the resolution *step* [SI]; 4 significant digits,
    trailing zeros kept, when there is no step), the analytic value to the same decimals and to at least
    :data:`ANALYTIC_DIGITS` significant digits, and the relative error of the two numbers as printed, |g − a| / |a|
    (of the vectors, for a magnitude ∠ direction), so that a reader recomputes it from the table.  (Round 21: the
    analytic value rounded to the reading's decimals hid the graphical method's error, "v_K 0,032 | 0,032 | 0"
    against 0,03238.)  A *given* value (the driver's ω, a crank pin's v) is printed as
    given in both columns and has no error (:data:`NO_ERROR`), nor has a quantity printed as 0.
    """
    if given:  # to the reading's decimals where the plan draws it (v_A = 1.500, as the readings print it)
        decimals = max(0, -math.floor(math.log10(step))) if step else None
        if decimals is None:
            return _magnitude(graphical), _magnitude(analytic), NO_ERROR
        text = _to_decimals(analytic, decimals)  # the given value in both columns (a = 2.000, not its drawn 2.001)
        return text, text, NO_ERROR
    if step is None and graphical == analytic:  # the same number by both (exact readings): as given, no difference
        text = _magnitude(analytic)
        return text, text, NO_ERROR if text == "0" else table_error(0.0)
    if step is None:
        g_text = "0" if graphical == 0 else (_significant(abs(graphical)) + f" ∠ {_deg(cmath.phase(graphical)):.1f}°"
                                              if isinstance(graphical, complex) else _significant(graphical))
    else:
        g_text = _magnitude(graphical, step)
    decimals = _printed_decimals(g_text) if g_text != "0" else None
    if decimals is None and step is not None and step > 0:
        decimals = max(0, -math.floor(math.log10(step)))
    magnitude = abs(analytic)
    if decimals is not None and 0 < magnitude and math.isfinite(magnitude):
        decimals = max(decimals, ANALYTIC_DIGITS - 1 - math.floor(math.log10(magnitude)))
    if decimals is None:
        a_text = "0" if analytic == 0 else (_significant(abs(analytic)) + f" ∠ {_deg(cmath.phase(analytic)):.1f}°"
                                             if isinstance(analytic, complex) else _significant(analytic))
    else:
        a_text = _to_decimals(analytic, decimals)
    a = _printed_value(a_text)
    if a == 0:
        return g_text, a_text, NO_ERROR
    return g_text, a_text, table_error(abs(complex(_printed_value(g_text)) - complex(a)) / abs(a))


def table_error(value: float) -> str:
    """A relative error as ``1.0·10⁻⁴`` (``0`` for none, and for one of round-off size, at most :data:`TABLE_ROUNDOFF`:
    two methods that agree to the last bits of a double agree exactly, as far as a table can say)."""
    if value <= TABLE_ROUNDOFF:
        return "0"
    mantissa, exponent = f"{value:.1e}".split("e")
    return f"{mantissa}·10{str(int(exponent)).translate(_SUPERSCRIPT)}".replace("-", "−")


def _drawn_value(plan, label: str) -> complex:
    """The plan vector *label* as measured: its measured magnitude [SI] along its drawn direction (0 when not drawn)."""
    for v in plan.vectors if plan is not None else ():
        if v.label == label:
            d = v.tip - v.tail
            return v.value * d / abs(d) if d else 0j
    return 0j


def drawn_rows(comparisons: list[Comparison], graphical=None, analytic=None, position: int = 0,
               points_of_links: bool = False) -> list[tuple[str, Comparison]]:
    """The compared quantities as the plans draw them: ``(vector label, comparison)``.

    A point's v, a keep their rows (``"v_A"``).  A slider's v_rel, a_rel and
    Coriolis become the vectors drawn in its equation, for the body that moves
    relative to the other in that equation (``graphical.relative``):
    ``v_E5E6``, ``a^r_E5E6``, ``a^k_E5E6``, as vectors: graphical the plan
    vector as measured, analytic ``sign·v_rel·u_g`` (u_g from the analytic
    guide angle), errors of the vector.  ω, ε keep their rows
    (``"omega_3"``).  Without *graphical* and *analytic* the sliders keep the
    JSON's scalars (``"v^r_E"``).  With *points_of_links*, the absolute velocity and acceleration of every
    point of a link the plans draw (``v_A4``, ``a_A4``) gets its row too (:func:`_with_points_of_links`).
    """
    out: list[tuple[str, Comparison]] = []
    prismatics = {p.name: p for p in analytic.scene.prismatics} if analytic is not None else {}
    for row in comparisons:
        if row.section == "points":
            out.append((f"{row.quantity}_{row.name}", _as_read(row, graphical)))
            continue
        if row.section == "links":
            out.append((f"{row.quantity}_{row.name}", row))
            continue
        drawn = graphical.relative.get(row.name) if graphical is not None else None
        if drawn is None or row.quantity not in drawn or row.name not in prismatics:
            out.append((f"{row.quantity}_{row.name}", row))
            continue
        sign = drawn["sign"]
        plan = graphical.velocity_plan if row.quantity == "v_rel" else graphical.acceleration_plan
        label = drawn[row.quantity]
        g = _drawn_value(plan, label)
        if row.quantity == "coriolis":
            a = sign * complex(row.analytic)
        else:
            a = sign * float(row.analytic) * guide_direction(analytic, prismatics[row.name], position)
        error = abs(g - a)
        reference = row.abs_error / row.rel_error if row.rel_error > 0 and row.abs_error > 0 else abs(a)
        out.append((label, Comparison(row.section, row.name, row.quantity, a, g, error, error / reference if reference > 0 else 0.0)))
    if points_of_links and graphical is not None and analytic is not None:
        out = _with_points_of_links(out, graphical, analytic, position)
    return out


def _as_read(row: Comparison, graphical) -> Comparison:
    """A point's row with its graphical value as the plan's readings table reads it: the vector drawn from the pole,
    its measured length × k (:attr:`plans.graphical.plan.PlanVector.value`) along its drawn direction, so that one
    quantity prints one number on a page (a_S3 read 111.1 mm × 15 = 1666.5 m/s², not its image's unrounded 1666.4);
    the row as it is where the plan draws no such vector (or without *graphical*)."""
    if graphical is None or row.quantity not in ("v", "a"):
        return row
    plan = graphical.velocity_plan if row.quantity == "v" else graphical.acceleration_plan
    label = f"{row.quantity}_{row.name}"
    if plan is None or not any(v.label == label for v in plan.vectors):
        return row
    g = _drawn_value(plan, label)
    a = complex(row.analytic)
    error = abs(g - a)
    reference = row.abs_error / row.rel_error if row.rel_error > 0 and row.abs_error > 0 else abs(a)
    return Comparison(row.section, row.name, row.quantity, row.analytic, g, error, error / reference if reference > 0 else 0.0)


def _point_of_link(analytic, point: str, link: str, position: int) -> tuple[complex, complex] | None:
    """(v [m/s], a [m/s²]) of the point of *link* that coincides with *point* at *position* (``A4``: the point of
    rocker 4 under the slider's pin A), from the analytic solution: v = v_R + iω·(r − r_R),
    a = a_R + (iε − ω²)(r − r_R), R a point of the link the analytic solution tracks; None when it tracks none."""
    motion = analytic.links.get(link)
    here = analytic.points.get(point)
    if motion is None or here is None:
        return None
    for name in analytic.scene.bodies[link].points:
        ref = analytic.points.get(name)
        if ref is None or name == point:
            continue
        arm = complex(here.r[position]) - complex(ref.r[position])
        w, e = float(motion.omega[position]), float(motion.epsilon[position])
        return complex(ref.v[position]) + 1j * w * arm, complex(ref.a[position]) + (1j * e - w * w) * arm
    return None


def _with_points_of_links(rows: list, graphical, analytic, position: int) -> list:
    """*rows* with the absolute velocity and acceleration of every point of a link the plans draw and the rows do
    not hold (``v_A4``, ``a_A4``: the point of link 4 under a slider's pin), after the points' rows: graphical
    the plan's vector from the pole as measured, analytic :func:`_point_of_link`."""
    have = {label for label, _ in rows}
    asked = {r.quantity for _, r in rows if r.section == "points"}  # a table of velocities only gets no accelerations
    added = {"v": [], "a": []}
    for quantity, plan in (("v", graphical.velocity_plan), ("a", graphical.acceleration_plan)):
        if plan is None or quantity not in asked:
            continue
        for vector in plan.vectors:
            if vector.kind != "absolute" or vector.label in have or not vector.label.startswith(quantity + "_"):
                continue
            named = vector.label.partition("_")[2]
            match = [(p, link) for p, link in plan.points.values() if link and p + link == named]
            if not match:
                continue
            point, link = match[0]
            values = _point_of_link(analytic, point, link, position)
            if values is None:
                continue
            a = values[0] if quantity == "v" else values[1]
            g = _drawn_value(plan, vector.label)
            error = abs(g - a)
            largest = max([abs(r.analytic) for _, r in rows if r.section == "points" and r.quantity == quantity] + [abs(a)])
            reference = abs(a) if abs(a) >= ZERO_FRACTION * largest else largest
            added[quantity].append((vector.label, Comparison("points", named, quantity, a, g, error, error / reference if reference > 0 else 0.0)))
            have.add(vector.label)
    extra = sorted(added["v"] + added["a"], key=lambda lr: (lr[1].name, lr[1].quantity != "v"))  # v, a of each point
    out = list(rows)
    places = [k for k, (_, r) in enumerate(out) if r.section == "points"]
    at = places[-1] + 1 if places else 0
    out[at:at] = extra
    return out


def _symbol(label: str) -> str:
    """A vector label typeset as the page layer sets equations: ``a^k_E5E6`` → ``$a^{k}_{E5E6}$``, ``omega_3`` → ``$\\omega_{3}$``."""
    head, _, sub = label.partition("_")
    base, _, sup = head.partition("^")
    base = {"omega": r"\omega", "epsilon": r"\varepsilon"}.get(base, base)
    return f"${base}" + (f"^{{{sup}}}" if sup else "") + (f"_{{{math_name(sub)}}}" if sub else "") + "$"


def _link_order(name: str) -> tuple:
    """Links in the order of their numbers (2, 3, 4, …, 10), named links after them in the scene's order."""
    return (0, int(name), "") if name.isdigit() else (1, 0, "")


def _by_link_number(rows: list) -> list:
    """The rows with the links' rows (ω, ε) in the order of the link numbers, where the first of them was:
    a block declared by a ``[[slider]]`` (quick-return 3) comes among the links, not after them."""
    rows = list(rows)
    places = [k for k, (_, row) in enumerate(rows) if row.section == "links"]
    ordered = sorted((rows[k] for k in places), key=lambda lr: _link_order(lr[1].name))  # stable: ω before ε
    for k, item in zip(places, ordered):
        rows[k] = item
    return rows


def sheet_table(comparisons: list[Comparison], graphical=None, analytic=None, position: int = 0,
                points_of_links: bool = False) -> list[list[str]]:
    """Rows of preformatted text for a sheet: header, then one row per quantity.

    Vectors are written as magnitude ∠ direction; ω, ε keep their sign
    (counter-clockwise positive).  With *graphical* and *analytic* (the
    solutions the comparisons came from; *position* into the analytic one)
    every slider row is the vector drawn in its equation, named as drawn
    (``$v_{E5E6}$``, ``$a^{k}_{E5E6}$``, ``$a^{r}_{E5E6}$``, see
    :func:`drawn_rows`), with that vector's magnitude and direction.
    Symbols are typeset; numbers have true minus signs and no ``e`` notation.
    Quantities that both methods give as exactly zero (the Coriolis term of a
    guide that does not turn, ω of a link that only translates, a point at
    rest) are left out, as they are left off the plans.  *points_of_links*: the rows of every point of a link
    the plans draw (``v_A4``, ``a_A4``, the handout's table), see :func:`drawn_rows`.
    """
    rows = [["quantity", "graphical", "analytic", "rel. error"]]
    drawn = drawn_rows(comparisons, graphical, analytic, position, points_of_links)
    # the scale of each kind at this position: the largest analytic value of that kind in the table
    scale: dict[str, float] = {}
    for _, row in drawn:
        kind = _KIND.get(row.quantity, row.quantity)
        if math.isfinite(abs(row.analytic)):
            scale[kind] = max(scale.get(kind, 0.0), abs(row.analytic))

    def noise(value, kind: str) -> bool:
        return abs(value) <= TABLE_ROUNDOFF * scale.get(kind, 0.0)

    for label, row in _by_link_number(drawn):
        if row.quantity not in PLAN_QUANTITIES:  # a sheet tabulates what is read off its plans
            continue
        if row.analytic == 0 and row.graphical == 0:
            continue
        if row.section == "sliders" and label == f"{row.quantity}_{row.name}":  # without the plans: the JSON's scalar
            text = f"${_SYMBOL[row.quantity]}$ slider {row.name} [{_UNITS[row.quantity]}]"
        else:
            text = f"{_symbol(label)} [{_UNITS[row.quantity]}]"
        kind = _KIND.get(row.quantity, row.quantity)
        zero_a, zero_g = noise(row.analytic, kind), noise(row.graphical, kind)
        # both values to the reading's decimals, the error of the two printed numbers; a given value (the driver's ω,
        # v_A: drawn from the data, not read) as given, without error (:func:`row_texts`); round-off of a zero as 0
        g_text, a_text, error = row_texts(0 if zero_g else row.graphical, 0 if zero_a else row.analytic,
                                          reading_step(graphical, row), given(graphical, row))
        rows.append([text, g_text, a_text, error])
    return rows


def given(graphical, row: Comparison) -> bool:
    """Whether a table row is given, not read off a plan: ω, ε of the driver and v, a of the points of the driver's link
    (a crank's pin A: v_A = ω·OA is drawn from the data, as is a linear driver's v)."""
    if graphical is None:
        return False
    driver = graphical.scene.driver.link
    if row.section == "links":
        return row.name == driver
    if row.section == "points":
        return row.name in graphical.scene.bodies[driver].points
    return False


def reading_step(graphical, row: Comparison) -> float | None:
    """The resolution [SI] of a graphical value: one drafting step (``graphical.precision`` [mm]) of its segment × the
    plan's scale factor (÷ the link length a link's ω, ε is read with); None when readings are exact (no precision)."""
    if graphical is None or not getattr(graphical, "precision", None):
        return None
    k = graphical.scales.get("k_v" if _KIND.get(row.quantity) in ("velocity", "omega") else "k_a")
    if k is None:
        return None
    step = graphical.precision * k
    if row.section == "links":
        entry = getattr(graphical, "rotations", {}).get(row.name, {}).get(row.quantity)
        if entry is None:
            return None
        step /= entry[2]
    return step


# --- instant centres (plans.centres) ---------------------------------------------

__all__ += ["row_texts", "given", "reading_step", "reading_number", "centres_json", "add_centres_json", "centres_table", "centres_comparison_table"]


def _centre_where(centre) -> list:
    """``[x, y]`` of a finite centre, or None."""
    return None if centre.point is None else [_as_given(x) for x in _vec(centre.point)]


def _centre_direction(centre) -> float | None:
    """The direction [°] of a centre at infinity, in [0, 180); None for another."""
    d = centre.direction_deg
    return None if d is None else _as_given(_clean(d))


def _found_words(centre) -> str:
    if not centre.determined:
        return f"undetermined: {centre.why}"
    if centre.found_by == "kennedy":
        (a, b), (c, d) = centre.lines
        return f"Kennedy: {a}{b} ∩ {c}{d}"
    return centre.found_by


def centres_json(result) -> dict:
    """The ``"centres"`` entry of the JSON document: body numbers and every centre.

    Each centre: ``bodies`` (names), ``point`` [m] or null, ``direction_deg``
    (of a centre at infinity, in [0, 180)) or null, ``found_by``
    (``"revolute A"``, ``"prismatic NAME"``, ``"kennedy"``, ``"undetermined"``),
    ``lines`` (the two Kennedy lines, as pairs of centre labels) and, for an
    undetermined centre only, ``why``.
    """
    return {
        "body_numbers": dict(result.numbers),
        "list": [
            {"label": c.label, "bodies": list(c.bodies), "point": _centre_where(c), "direction_deg": _centre_direction(c),
             "found_by": c.found_by, "lines": [list(line) for line in c.lines], **({} if c.determined else {"why": c.why})}
            for c in result.centres
        ],
    }


def add_centres_json(doc: dict, result, comparisons: list[Comparison]) -> dict:
    """Add the instant-centre method to a :func:`solution_json` document, in place (and return it).

    Each reported point gets ``"centres": {"v", "v_abs_error", "v_rel_error"}``
    and each link ``"centres": {"omega", "omega_abs_error", "omega_rel_error"}``
    beside ``"analytic"`` (errors against analytic, as for ``"graphical"``),
    and the document gets the ``"centres"`` key of :func:`centres_json`.
    """
    for row in comparisons:
        value = _vec(row.graphical) if isinstance(row.graphical, complex) else _clean(row.graphical)
        entry = {row.quantity: value, f"{row.quantity}_abs_error": _clean(row.abs_error),
                 f"{row.quantity}_rel_error": _clean(row.rel_error)}
        target = doc[row.section].get(row.name)
        if target is not None:
            target["centres"] = entry
    doc["centres"] = centres_json(result)
    return doc


def _check_finite_centres(result) -> None:
    for name, omega in result.links.items():
        if not math.isfinite(omega):
            raise PlansError(f"{result.scene.source}: ω of link {name} from the instant centres is not a finite number")
    for name, v in result.points.items():
        if not (math.isfinite(v.real) and math.isfinite(v.imag)):
            raise PlansError(f"{result.scene.source}: v of point {name} from the instant centres is not a finite number")


def centres_table(result) -> str:
    """Every instant centre (where, or its direction at infinity, and what gave it), then ω and v from the centres."""
    _check_finite_centres(result)
    scene = result.scene
    out = io.StringIO()
    w = out.write
    n = len(result.numbers)
    names = ", ".join(f"{number} = {'frame' if body == 'frame' else 'link ' + body}" for body, number in result.numbers.items())
    w(f"{scene.title}\n")
    w(f"driver: {_driver_words(scene)}\n")
    if scene.readings:
        w(f"        bare numbers read as SI and degrees: {'; '.join(scene.readings)}\n")
    w(f"bodies: {names}\n")
    w(f"\nInstant centres: n = {n} bodies, n(n−1)/2 = {len(result.centres)} centres; x, y [m], or the direction [°] of a centre at infinity\n")
    w(f"{'centre':8} {'bodies':8} {'x':>13} {'y':>13}   found by\n")
    for c in result.centres:
        pair = ",".join(result.numbers[b] for b in c.bodies)
        if c.point is not None:
            # round-off far below the mechanism's size prints as 0 (four-bar P24: y = 1.4e-17 m)
            where = f"{_clean(c.point.real, result.size):13.6g} {_clean(c.point.imag, result.size):13.6g}"
        elif not c.determined:
            where = f"{'—':>13} {'—':>13}"
        else:
            where = f"{'at infinity':>13} {_centre_direction(c):12.3f}°"
        w(f"{c.label:8} {pair:8} {where}   {_found_words(c)}\n")
    omega_scale = max((abs(x) for x in result.links.values()), default=0.0)
    v_scale = max((abs(complex(v)) for v in result.points.values()), default=0.0)
    w("\nVelocities from the centres: ω_j from the ratio theorem, v_M = ω_j × (M − P1j)\n")
    w(f"{'link':6} {'ω [rad/s]':>13}   {'about':6}\n")
    # in the order the links were found, each after the one it was found from; a link that translates with its v
    for name in result.found_order:
        centre = result.centre("frame", name)
        if centre.point is not None:
            about = centre.label
        else:
            magnitude, direction = (cell.strip() for cell in _vector_cells(complex(result.motions[name].v0), v_scale)[2:])
            toward = f", {direction}°" if direction != "—" else ""
            about = f"{centre.label} (translates: v = {magnitude} m/s{toward})"
        w(f"{name:6} {_clean(result.links[name], omega_scale):13.6g}   {about}\n")
    w(f"\n{'point':6} {'vx [m/s]':>13} {'vy [m/s]':>13} {'|v|':>13} {'dir [°]':>9}\n")
    for name in scene.report:
        w(f"{name:6} " + " ".join(_vector_cells(complex(result.points[name]), v_scale)) + "\n")
    return out.getvalue()


def centres_comparison_table(comparisons: list[Comparison]) -> str:
    """The solve table's section for the third method: ω and v from the instant centres, with errors against analytic."""
    out = io.StringIO()
    w = out.write
    w("\nInstant centres (Kennedy), a third method: ω of links, v of points; errors against analytic\n")
    w(f"{'':6} {'':5} {'centres':>13} {'analytic':>13} {'abs err':>10} {'rel err':>10}\n")
    for row in comparisons:
        if row.section == "links":
            w(f"{'link ' + row.name:10} ω {row.graphical:13.6g} {row.analytic:13.6g} {row.abs_error:10.2e} {row.rel_error:10.2e}\n")
        else:
            c, a = complex(row.graphical), complex(row.analytic)
            w(f"{row.name:10} v {abs(c):13.6g} {abs(a):13.6g} {row.abs_error:10.2e} {row.rel_error:10.2e}   (|v|; error of the vector)\n")
    if comparisons:
        worst = max(comparisons, key=lambda r: r.rel_error)
        w(f"largest relative difference centres vs analytic: {worst.rel_error:.2e} ({worst.section[:-1]} {worst.name}, {worst.quantity})\n")
    return out.getvalue()
