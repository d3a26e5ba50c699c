"""Unit strings as people write them, against hand-converted values."""

import math

import pytest

from plans.units import UnitError, parse_quantity


@pytest.mark.parametrize(
    "text, kind, expected",
    [
        ("300 mm", "length", 0.3),
        ("0.3 m", "length", 0.3),
        ("30cm", "length", 0.3),
        (0.3, "length", 0.3),
        ("55 deg", "angle", 55 * math.pi / 180),
        (90, "angle", math.pi / 2),  # bare angles are degrees
        ("1.5 rad", "angle", 1.5),
        ("2000 rpm", "angular velocity", 2000 * 2 * math.pi / 60),
        ("-10 rad/s", "angular velocity", -10.0),
        ("1e3 rad/s", "angular velocity", 1000.0),
        ("5 rad/s^2", "angular acceleration", 5.0),
        ("1 m/s", "velocity", 1.0),
        ("36 km/h", "velocity", 10.0),
        ("2 m/s^2", "acceleration", 2.0),
        ("-0.5 mm/s^2", "acceleration", -0.5e-3),
    ],
)
def test_quantities_convert_to_si(text, kind, expected):
    assert parse_quantity(text, kind) == pytest.approx(expected, rel=1e-15)


@pytest.mark.parametrize(
    "text, kind, words",
    [
        ("3 kg", "length", "'3 kg' is not a length"),
        ("3 m/s", "length", "'m/s' is a unit of velocity"),
        ("fast", "angular velocity", "expected an angular velocity"),
        (float("nan"), "length", "not a finite number"),
        (float("inf"), "angle", "not a finite number"),
        (True, "length", "expected a length"),
        ([1], "length", "expected a length"),
    ],
)
def test_bad_quantities_name_the_problem(text, kind, words):
    with pytest.raises(UnitError) as info:
        parse_quantity(text, kind)
    assert words in str(info.value)
