"""Quantities as people write them in a scene file: ``"300 mm"``, ``"55 deg"``, ``"2000 rpm"``.

A small, tested table rather than a units library: a scene needs ten kinds of
quantity and a dozen unit spellings, and a table keeps ``plans solve`` fast to
start.  Bare numbers are taken in the default unit of their kind (SI, and
degrees for angles).  Everything returned is SI: m, rad, rad/s, rad/s², m/s, m/s², and for the
kinetostatics kg, kg·m², N, N·m.
"""

import math
import re

__all__ = ["KINDS", "UnitError", "parse_quantity"]

_PI = math.pi

#: unit spelling -> factor to SI, per kind of quantity; the first entry of each
#: kind is its default unit for bare numbers.
KINDS: dict[str, dict[str, float]] = {
    "length": {"m": 1.0, "mm": 1e-3, "cm": 1e-2, "dm": 1e-1, "km": 1e3, "um": 1e-6, "µm": 1e-6, "in": 0.0254},
    "angle": {"deg": _PI / 180, "°": _PI / 180, "rad": 1.0},
    "angular velocity": {"rad/s": 1.0, "rpm": 2 * _PI / 60, "1/min": 2 * _PI / 60, "deg/s": _PI / 180, "rps": 2 * _PI},
    "angular acceleration": {"rad/s^2": 1.0, "rad/s2": 1.0, "rad/s²": 1.0, "deg/s^2": _PI / 180, "deg/s²": _PI / 180},
    "velocity": {"m/s": 1.0, "mm/s": 1e-3, "cm/s": 1e-2, "km/h": 1 / 3.6},
    "acceleration": {"m/s^2": 1.0, "m/s2": 1.0, "m/s²": 1.0, "mm/s^2": 1e-3, "mm/s²": 1e-3, "g": 9.80665},
    # kinetostatics (issue 22): masses, moments of inertia, forces and moments of forces
    "mass": {"kg": 1.0, "g": 1e-3, "t": 1e3},
    "moment of inertia": {
        "kg·m²": 1.0, "kg*m^2": 1.0, "kg m^2": 1.0, "kg·m^2": 1.0, "kgm^2": 1.0,
        "kg·mm²": 1e-6, "kg*mm^2": 1e-6, "kg mm^2": 1e-6, "kg·mm^2": 1e-6, "kgmm^2": 1e-6,
        "g·mm²": 1e-9, "g*mm^2": 1e-9,
    },
    "force": {"N": 1.0, "kN": 1e3, "MN": 1e6, "daN": 10.0},
    "moment": {
        "N·m": 1.0, "N*m": 1.0, "N m": 1.0, "Nm": 1.0,
        "N·mm": 1e-3, "N*mm": 1e-3, "N mm": 1e-3, "Nmm": 1e-3,
        "kN·m": 1e3, "kN*m": 1e3, "kN m": 1e3, "kNm": 1e3,
    },
}

_NUMBER = r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?"
_QUANTITY = re.compile(rf"^\s*({_NUMBER})(?:\s*([^\s\d].*?)|\s+(1/\S+))?\s*$")  # "1 1/min": a unit may start with 1/


class UnitError(ValueError):
    """A value that is not a number of the expected kind (raised to the scene loader)."""


def _kind_of(unit: str) -> str | None:
    for kind, table in KINDS.items():
        if unit in table:
            return kind
    return None


def parse_quantity(value: object, kind: str) -> float:
    """Convert a scene value to SI.

    Parameters
    ----------
    value : int, float or str
        A bare number (in the default unit of *kind*) or a string such as
        ``"300 mm"``, ``"-10 rad/s"``, ``"2000 rpm"``.
    kind : str
        One of the keys of :data:`KINDS`.

    Returns
    -------
    float
        The value in SI units (angles in radians).

    Raises
    ------
    UnitError
        For text that is not a number with a unit of this kind, or for NaN or
        infinite values.

    Examples
    --------
    >>> parse_quantity("300 mm", "length")
    0.3
    >>> round(parse_quantity("2000 rpm", "angular velocity"), 6)
    209.43951
    >>> parse_quantity(90, "angle") == math.pi / 2
    True
    """
    table = KINDS[kind]
    default = next(iter(table))
    if isinstance(value, bool):
        raise UnitError(f"expected {_a(kind)} such as 0.3 or \"{_example(kind)}\", got {value!r}")
    if isinstance(value, (int, float)):
        number, unit = float(value), default
    elif isinstance(value, str):
        match = _QUANTITY.match(value)
        if not match:
            raise UnitError(f"expected {_a(kind)} such as \"{_example(kind)}\", got {value!r}")
        number = float(match.group(1))
        unit = (match.group(2) or match.group(3) or default).strip()
        if unit not in table:
            other = _kind_of(unit)
            hint = f" ({unit!r} is a unit of {other})" if other else ""
            raise UnitError(
                f"{value!r} is not {_a(kind)}{hint}; use one of: {', '.join(table)}"
            )
    else:
        raise UnitError(f"expected {_a(kind)} such as \"{_example(kind)}\", got {value!r}")
    if not math.isfinite(number):
        raise UnitError(f"{value!r} is not a finite number")
    return number * table[unit]


def _a(kind: str) -> str:
    """The kind with its article: "a length", "an angle"."""
    return f"an {kind}" if kind[0] in "aeiou" else f"a {kind}"


def _example(kind: str) -> str:
    return {
        "length": "300 mm",
        "angle": "55 deg",
        "angular velocity": "10 rad/s",
        "angular acceleration": "0 rad/s^2",
        "velocity": "1 m/s",
        "acceleration": "0 m/s^2",
        "mass": "2 kg",
        "moment of inertia": "0.004 kg*m^2",
        "force": "1500 N",
        "moment": "20 N*m",
    }[kind]
