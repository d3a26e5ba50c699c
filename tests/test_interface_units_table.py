"""Every unit spelling of plans/units.py against factors typed here from the standards (issue 9 §4).

Independent values: SI Brochure (BIPM, 9th ed.) for the SI prefixes and the radian; the
international inch (1959) 25.4 mm exactly; standard gravity g_n = 9.80665 m/s² exactly (3rd CGPM,
1901); 1 revolution = 2π rad, 1 min = 60 s, 1 h = 3600 s, 1 degree = π/180 rad.  Written as
fractions of exact numbers so that no factor is copied from the code under test.
"""

import math

import pytest

from plans.units import KINDS, UnitError, parse_quantity

PI = 3.141592653589793  # π to double precision, typed

STANDARD = {
    "length": {"m": 1, "mm": 1 / 1000, "cm": 1 / 100, "dm": 1 / 10, "km": 1000, "um": 1 / 1_000_000,
               "µm": 1 / 1_000_000, "in": 254 / 10_000},
    "angle": {"deg": PI / 180, "°": PI / 180, "rad": 1},
    "angular velocity": {"rad/s": 1, "rpm": 2 * PI / 60, "1/min": 2 * PI / 60, "deg/s": PI / 180, "rps": 2 * PI},
    "angular acceleration": {"rad/s^2": 1, "rad/s2": 1, "rad/s²": 1, "deg/s^2": PI / 180, "deg/s²": PI / 180},
    "velocity": {"m/s": 1, "mm/s": 1 / 1000, "cm/s": 1 / 100, "km/h": 1000 / 3600},
    "acceleration": {"m/s^2": 1, "m/s2": 1, "m/s²": 1, "mm/s^2": 1 / 1000, "mm/s²": 1 / 1000, "g": 9.80665},
    # kinetostatics (issue 22): 1 g = 1/1000 kg, 1 t = 1000 kg, 1 N = 1 kg·m/s², SI prefixes (da = 10)
    "mass": {"kg": 1, "g": 1 / 1000, "t": 1000},
    "moment of inertia": {"kg·m²": 1, "kg*m^2": 1, "kg m^2": 1, "kg·m^2": 1, "kgm^2": 1,
                          "kg·mm²": 1 / 1_000_000, "kg*mm^2": 1 / 1_000_000, "kg mm^2": 1 / 1_000_000,
                          "kg·mm^2": 1 / 1_000_000, "kgmm^2": 1 / 1_000_000,
                          "g·mm²": 1 / 1_000_000_000, "g*mm^2": 1 / 1_000_000_000},
    "force": {"N": 1, "kN": 1000, "MN": 1_000_000, "daN": 10},
    "moment": {"N·m": 1, "N*m": 1, "N m": 1, "Nm": 1, "N·mm": 1 / 1000, "N*mm": 1 / 1000, "N mm": 1 / 1000,
               "Nmm": 1 / 1000, "kN·m": 1000, "kN*m": 1000, "kN m": 1000, "kNm": 1000},
}


def test_the_table_has_exactly_the_spellings_of_the_standard_table():
    assert {kind: set(units) for kind, units in KINDS.items()} == {kind: set(units) for kind, units in STANDARD.items()}


@pytest.mark.parametrize("kind, unit, factor", [(k, u, f) for k, units in STANDARD.items() for u, f in units.items()])
def test_every_spelling_converts_as_the_standard_says(kind, unit, factor):
    for number in (1, 2.5, -7):
        assert parse_quantity(f"{number} {unit}", kind) == pytest.approx(number * factor, rel=1e-15)
        if not unit[0].isdigit():  # "2.5mm" may be written without a space; "2.5 1/min" may not
            assert parse_quantity(f"{number}{unit}", kind) == pytest.approx(number * factor, rel=1e-15)


@pytest.mark.parametrize("kind, bare", [("length", 1), ("angle", PI / 180), ("angular velocity", 1),
                                         ("angular acceleration", 1), ("velocity", 1), ("acceleration", 1)])
def test_bare_numbers_are_si_and_degrees(kind, bare):
    assert parse_quantity(3, kind) == pytest.approx(3 * bare, rel=1e-15)


def test_worked_conversions():
    assert parse_quantity("2000 rpm", "angular velocity") == pytest.approx(209.4395102, rel=1e-9)  # domain.md E2
    assert parse_quantity("1 rps", "angular velocity") == pytest.approx(2 * math.pi, rel=1e-15)
    assert parse_quantity("1 g", "acceleration") == 9.80665
    assert parse_quantity("36 km/h", "velocity") == pytest.approx(10, rel=1e-15)
    assert parse_quantity("1 in", "length") == pytest.approx(0.0254, rel=1e-15)


@pytest.mark.parametrize("text, kind", [("3 mm", "angle"), ("3 rpm", "length"), ("3 furlongs", "length")])
def test_a_unit_of_another_kind_is_refused(text, kind):
    with pytest.raises(UnitError):
        parse_quantity(text, kind)
