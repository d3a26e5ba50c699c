"""The kinetostatics of one position as a table (in the reader's language) and as JSON.

Both read a :class:`plans.forces.compare.KinetostaticRun`; neither computes.
Units: N, N·m, m, W (the table writes them as the course does: Н, Н·м, м, Вт,
рад/с in ru and bg; the JSON's keys and values do not change); angles in
degrees from +x, counter-clockwise; on the lever, mm of the velocity plan and
N·mm.
"""

from __future__ import annotations

import io
import math

from .._text import course_units
from ..i18n import term
from ..scene import FRAME, Crank
from .compare import KinetostaticRun
from .notation import course_label

__all__ = ["FORCES_SCHEMA", "forces_json", "forces_table", "LOAD_TERMS", "method_name", "course_formula", "COURSE_KINDS", "unit"]

#: Version of the JSON document of ``plans forces --json``.
FORCES_SCHEMA = 1

#: The i18n key of each kind of load.
LOAD_TERMS = {
    "weight": "weight",
    "inertia force": "inertia_force",
    "inertia couple": "inertia_couple",
    "force": "external_force",
    "resistance": "resistance",
    "moment": "couple",
}


def method_name(method: str, lang: str = "en") -> str:
    """``"analytic"``, ``"force plans"``, ``"Joukowski's lever"`` in *lang*."""
    return term({"analytic": "analytic", "force_plans": "force_plans", "lever": "joukowski_lever"}[method], lang)


def _body(name: str, frame: str) -> str:
    return frame if name == FRAME else name


def _vec(z: complex) -> list[float] | None:
    z = complex(z)
    if not (math.isfinite(z.real) and math.isfinite(z.imag)):
        return None
    return [z.real + 0.0, z.imag + 0.0]


def _num(x: float) -> float | None:
    x = float(x)
    return x + 0.0 if math.isfinite(x) else None


def _deg(z: complex) -> float | None:
    return math.degrees(math.atan2(z.imag, z.real)) % 360.0 if abs(z) > 0 else None


def _rows(run: KinetostaticRun) -> dict[tuple[str, str], object]:
    return {(row.quantity, row.method): row for row in run.comparisons}


def forces_json(run: KinetostaticRun) -> dict:
    """The JSON document of one position (see the README, "plans forces")."""
    from ..report import driver_summary

    analytic = run.analytic
    scene = run.scene
    rows = _rows(run)
    symbol = "M_b" if analytic.balancing_kind == "moment" else "F_b"
    doc: dict = {
        "schema": FORCES_SCHEMA,
        "title": scene.title,
        "driver": driver_summary(scene),
        "structure": analytic.structure.formula,
        "units": {"force": "N", "moment": "N*m", "length": "m", "angle": "deg", "power": "W",
                  "lever_length": "mm", "lever_moment": "N*mm"},
        "loads": [],
        "reactions": {},
        "balancing": {"kind": analytic.balancing_kind, "symbol": symbol, "analytic": _num(analytic.balancing[0])},
        "power": {
            "driving": _num(analytic.driving_power()[0]),
            "loads": _num(analytic.load_power()[0]),
            "residual": _num(analytic.power_residual()[0]),
        },
        "lever": None,
        "scales": dict(run.graphical.scales) if run.graphical is not None else None,
        "warnings": [str(warning) for warning in analytic.kinematics.warnings] + list(run.notes),
    }
    for load in analytic.loads:
        doc["loads"].append({
            "name": load.name,
            "link": load.body,
            "kind": load.kind,
            "point": load.point,
            "r": _vec(_first(load.r)),
            "force": _vec(_first(load.force)),
            "moment": _num(_first(load.moment)),
        })
    for label, reaction in analytic.reactions.items():
        force = complex(reaction.force[0])
        entry = {
            "joint": reaction.joint,
            "kind": reaction.kind,
            "by": _body(reaction.by, analytic.scene.frame_number),
            "on": _body(reaction.on, analytic.scene.frame_number),
            "group": reaction.group,
            "analytic": {"force": _vec(force), "magnitude": _num(abs(force)), "angle_deg": _deg(force), "point": _vec(reaction.point[0])},
        }
        if reaction.kind == "P":
            entry["analytic"]["normal"] = _vec(reaction.normal[0])
            entry["analytic"]["normal_force"] = _num(reaction.normal_force[0])
        row = rows.get((label, "force_plans"))
        if row is not None:
            entry["force_plans"] = {"force": _vec(row.value), "magnitude": _num(abs(row.value)), "angle_deg": _deg(row.value),
                                    "abs_error": _num(row.abs_error), "rel_error": _num(row.rel_error)}
        doc["reactions"][label] = entry
    for method in ("force_plans", "lever"):
        row = rows.get((symbol, method))
        if row is not None:
            doc["balancing"][method] = {"value": _num(row.value.real), "abs_error": _num(row.abs_error), "rel_error": _num(row.rel_error)}
    lever = run.lever
    if lever is not None:
        doc["lever"] = {
            "k_v": lever.k_v,
            "precision": lever.precision,
            "turn_deg": 90,
            "images": {label: _vec(z) for label, z in lever.images.items()},
            "forces": [_lever_force(f) for f in lever.forces],
            "couples": [{"name": c.name, "link": c.body, "kind": c.kind, "couple": c.couple, "moment_Nmm": c.moment} for c in lever.couples],
            "balancing_force": _lever_force(lever.balancing_force),
            "crank_length": lever.crank_length,
        }
    return doc


def _first(x):
    """The value at the first position of an array, or the plain number."""
    try:
        return x[0]
    except (TypeError, IndexError):
        return x


def _lever_force(f) -> dict:
    return {"name": f.name, "link": f.body, "kind": f.kind, "image": f.image, "point": _vec(f.point), "force": _vec(f.force),
            "arm_mm": _num(f.arm), "foot": _vec(f.foot), "moment_Nmm": _num(f.moment)}


#: A component smaller than this fraction of its vector's magnitude is round-off, printed as 0.
_ROUND_OFF = 1e-12


def _clean(z: complex) -> complex:
    """The vector with components that are round-off beside its magnitude (cos 90° = 6e-17) set to 0, and −0 as 0."""
    z = complex(z)
    size = abs(z)
    x = 0.0 if abs(z.real) <= _ROUND_OFF * size else z.real
    y = 0.0 if abs(z.imag) <= _ROUND_OFF * size else z.imag
    return complex(x + 0.0, y + 0.0)


#: the units the kinetostatics adds to the kinematics', as the Russian and Bulgarian courses write them
_FORCE_UNITS = {"N": "Н", "W": "Вт"}


def unit(symbol: str, lang: str = "en") -> str:
    """A unit *symbol* (``"N·m"``, ``"rad/s"``, ``"W"``) as the course in *lang* writes it: ``Н·м``, ``рад/с``, ``Вт`` in
    ru and bg (:func:`plans._text.course_units`), the international symbol elsewhere."""
    if lang not in ("ru", "bg"):
        return symbol
    return "·".join(_FORCE_UNITS.get(part, course_units(part, lang)) for part in symbol.split("·"))


def _cells(z: complex) -> str:
    z = _clean(z)
    direction = f"{_deg(z):9.3f}" if abs(z) > 0 and math.isfinite(abs(z)) else "        —"
    return f"{z.real:13.6g} {z.imag:13.6g} {abs(z):13.6g} {direction}"


def _errors(row) -> str:
    return f" {row.abs_error:10.3g} {row.rel_error:10.2e}"


#: a class-II Assur group's kind -> its number in the course's notation (II₁ … II₅), as the kinematic pages write it
COURSE_KINDS = {"RRR": "₁", "RRP": "₂", "PRR": "₂", "RPR": "₃", "PRP": "₄", "RPP": "₅", "PPR": "₅"}


def course_formula(formula: str) -> str:
    """The structural formula as the course writes it: ``I(1,2) → RRR(3,4)`` → ``I(1,2) → II₁(3,4)`` (plain text)."""
    import re

    return re.sub(r"\b([RP]{3})\(", lambda m: f"II{COURSE_KINDS[m.group(1)]}(" if m.group(1) in COURSE_KINDS else m.group(0), formula)


def forces_table(run: KinetostaticRun, lang: str = "en") -> str:
    """A readable table of one position in *lang*: loads, reactions, the balancing moment by each method, the power balance."""
    analytic = run.analytic
    scene = run.scene
    rows = _rows(run)
    out = io.StringIO()
    w = out.write

    def u(symbol: str) -> str:
        return unit(symbol, lang)

    w(f"{scene.title_in(lang)}\n")
    w(f"{term('kinetostatics', lang)}: {course_formula(analytic.structure.formula)}\n")
    driver = scene.driver
    if isinstance(driver, Crank):
        w(f"{term('driver', lang)} {driver.link}: φ = {math.degrees(driver.phi):.3f}°, ω = {driver.omega:.6g} {u('rad/s')}, ε = {driver.epsilon:.6g} {u('rad/s²')}\n")
    else:
        w(f"{term('driver', lang)} {driver.link}: s = {driver.s:.6g} {u('m')}, v = {driver.velocity:.6g} {u('m/s')}, a = {driver.acceleration:.6g} {u('m/s²')}\n")
    if run.graphical is not None:
        scales = ", ".join(f"{key} = {value:g}" for key, value in run.graphical.scales.items())
        precision = f", {run.graphical.precision:g} {u('mm')}" if run.graphical.precision else ""
        w(f"{term('scale_factors', lang)}: {scales}{precision}\n")

    w(f"\n{term('loads', lang)} [{u('N')}, {u('N·m')}]\n")
    x, y = (f"{axis} [{u('m')}]" for axis in "xy")
    w(f"{'':8} {term('link', lang)[:6]:6} {term('kind', lang)[:24]:24} {x:>11} {y:>11} {'Fx':>13} {'Fy':>13} {'|F|':>13} {'∠ [°]':>9} {'M':>13}\n")
    for load in analytic.loads:
        r = complex(_first(load.r))
        kind = term(LOAD_TERMS[load.kind], lang)
        if load.is_couple:
            w(f"{course_label(load.name, lang):8} {load.body:6} {kind[:24]:24} {'':11} {'':11} {'':13} {'':13} {'':13} {'':9} {float(_first(load.moment)) + 0.0:13.6g}\n")
        else:
            w(f"{course_label(load.name, lang):8} {load.body:6} {kind[:24]:24} {r.real:11.5g} {r.imag:11.5g} {_cells(_first(load.force))}\n")

    w(f"\n{term('reactions', lang)} [{u('N')}]; {term('reaction_convention', lang).format(frame=scene.frame_number)}\n")
    w(f"{'':8} {'':6} {'':20} {'Rx':>13} {'Ry':>13} {'|R|':>13} {'∠ [°]':>9} {'Δ':>10} {'δ':>10}\n")
    for label, reaction in analytic.reactions.items():
        w(f"{label:8} {reaction.joint:6} {method_name('analytic', lang)[:20]:20} {_cells(reaction.force[0])}\n")
        if reaction.kind == "P":
            point = complex(reaction.point[0])
            where = f"({point.real:.6g}, {point.imag:.6g}) {u('m')}" if math.isfinite(abs(point)) else "—"
            n = _clean(reaction.normal[0])
            w(f"{'':8} {'':6} {'':20} N = {float(reaction.normal_force[0]):.6g} {u('N')} ∥ n = ({n.real:.6g}, {n.imag:.6g}); {term('point_of_action', lang)} {where}\n")
        row = rows.get((label, "force_plans"))
        if row is not None:
            w(f"{'':8} {'':6} {method_name('force_plans', lang)[:20]:20} {_cells(row.value)}{_errors(row)}\n")

    key = "M_b" if analytic.balancing_kind == "moment" else "F_b"
    symbol = course_label(key, lang)
    if analytic.balancing_kind == "moment":
        w(f"\n{term('balancing_moment', lang)} {symbol} [{u('N·m')}], {term('ccw_positive', lang)}\n")
    else:
        w(f"\n{term('balancing_force', lang)} {symbol} [{u('N')}], {term('along_guide', lang)}\n")
    w(f"{method_name('analytic', lang)[:24]:24} {float(analytic.balancing[0]):16.9g}\n")
    for method in ("force_plans", "lever"):
        row = rows.get((key, method))
        if row is not None:
            w(f"{method_name(method, lang)[:24]:24} {row.value.real:16.9g}   Δ = {row.abs_error:.3g}, δ = {row.rel_error:.2e}\n")
    if run.graphical is not None and run.lever is None:
        w(f"{term('lever_left_out', lang)}\n")

    driving, loads, residual = (float(x[0]) for x in (analytic.driving_power(), analytic.load_power(), analytic.power_residual()))
    product = f"{symbol}·ω" if analytic.balancing_kind == "moment" else f"{symbol}·v"
    w(f"\n{term('power_balance', lang)} [{u('W')}]: {product} = {driving:.9g}; Σ F·v + Σ M·ω = {loads:.9g}; {term('residual', lang)} {residual:.3g}\n")
    return out.getvalue()
