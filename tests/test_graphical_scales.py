"""Automatic round scale factors: round values, 60–120 mm, at extreme scales too."""

import math

import pytest

from plans.graphical import construct
from plans.graphical.scales import measure, round_scale
from plans.scene import loads

#: Relative slack on the 60–120 mm window (round-off of a product of floats).
WINDOW_SLACK = 1e-9
ROUND_MANTISSAS = {1.0, 2.0, 2.5, 5.0}


def mantissa(k: float) -> float:
    """k = m × 10ⁿ with 1 ≤ m < 10, m rounded to 12 significant digits."""
    n = math.floor(math.log10(k) + 1e-12)
    return float(f"{k / 10**n:.12g}")


def in_window(drawn: float) -> bool:
    return 60.0 * (1 - WINDOW_SLACK) <= drawn <= 120.0 * (1 + WINDOW_SLACK)


@pytest.mark.parametrize(
    "largest, expected",
    [
        (1.5, 0.02),  # 1.5 / 0.02 = 75 mm (0.0125 would not be round)
        (1.2, 0.01),  # exactly 120 mm
        (1.21, 0.02),
        (2.9, 0.025),
        (3.1, 0.05),
        (6.0, 0.05),
        (6.1, 0.1),
        (3730.28395, 50.0),
        (1e-12, 1e-14),
        (1.2e13, 1e11),
    ],
)
def test_round_scale_table(largest, expected):
    assert round_scale(largest) == expected


@pytest.mark.parametrize("largest", [0.0, -1.0, math.nan, math.inf])
def test_round_scale_nothing_to_draw_gives_fallback(largest):
    assert round_scale(largest, fallback=0.5) == 0.5


@pytest.mark.parametrize("exponent", range(-15, 16))
@pytest.mark.parametrize("digits", [1.0, 1.2, 1.2000001, 1.9999, 2.4, 2.5, 3.3, 5.0, 6.0, 7.77, 9.9999999])
def test_round_scale_is_round_and_fills_the_window(exponent, digits):
    largest = digits * 10.0**exponent
    k = round_scale(largest)
    assert mantissa(k) in ROUND_MANTISSAS
    assert in_window(largest / k)
    assert repr(k) == repr(float(f"{mantissa(k)}e{math.floor(math.log10(k) + 1e-12)}"))


def test_measure_rounds_to_the_precision():
    assert measure(30.26, 0.5) == 30.5
    assert measure(30.24, 0.5) == 30.0
    assert measure(30.24, None) == 30.24


SLIDER_CRANK = """
[frame]
points = {{ O = [0, 0] }}
lines = {{ cylinder = {{ through = [0, {e}], angle = 0 }} }}
[link.2]
points = {{ O = [0, 0], A = [{r}, 0] }}
[link.3]
points = {{ A = [0, 0], B = [{l}, 0] }}
[[slider]]
pin = "B"
on = "frame.cylinder"
[driver]
crank = "2"
angle = "45 deg"
omega = {omega}
epsilon = {epsilon}
[assembly]
B = 1
"""


def scaled_slider_crank(length: float, omega: float):
    """E2's offset slider-crank with every length × *length* and ω = *omega*, ε = ω²/3."""
    return loads(SLIDER_CRANK.format(e=0.05 * length, r=0.1 * length, l=0.25 * length, omega=omega, epsilon=omega**2 / 3))


@pytest.mark.parametrize("length", [1e-6, 1e-3, 1.0, 1e2, 1e3])
@pytest.mark.parametrize("omega", [1e-3, 1.0, 1e5])
def test_auto_scales_at_extremes(length, omega):
    solution = construct(scaled_slider_crank(length, omega))
    for key in ("k_l", "k_v", "k_a"):
        assert mantissa(solution.scales[key]) in ROUND_MANTISSAS, key
    for plan in (solution.velocity_plan, solution.acceleration_plan):
        assert in_window(max(v.length for v in plan.vectors)), plan.kind
    xs = [z.real for z in solution.positions.values()]
    ys = [z.imag for z in solution.positions.values()]
    assert in_window(max(max(xs) - min(xs), max(ys) - min(ys)) / solution.scales["k_l"])
    # the readings do not depend on the unit system: v_A = ω·OA exactly
    assert abs(solution.points["A"]["v"]) == pytest.approx(omega * 0.1 * length, rel=1e-12)


def test_given_scales_override_the_scene_which_overrides_auto():
    scene = loads(SLIDER_CRANK.format(e=0.05, r=0.1, l=0.25, omega=10, epsilon=0) + "[scales]\nk_v = 0.02\nk_l = 0.004\n")
    solution = construct(scene, k_v=0.05)
    assert solution.scales["k_v"] == 0.05
    assert solution.scales["k_l"] == 0.004
    assert mantissa(solution.scales["k_a"]) in ROUND_MANTISSAS


@pytest.mark.parametrize("need, up, down", [(0.0123, 0.02, 0.01), (0.5, 0.5, 0.5), (7.0, 10.0, 5.0), (2.2e-7, 2.5e-7, 2e-7)])
def test_the_textbooks_round_values_by_hand(need, up, down):
    # 1, 2, 2.5, 5 × 10ⁿ, worked by hand; the pages' finer set is the same rule with more mantissas
    from plans.rounding import round_down, round_up

    assert round_up(need) == up and round_down(need) == down
