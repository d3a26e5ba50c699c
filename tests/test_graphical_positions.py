"""Compass construction of positions: hand-computed positions, branches, assembly errors."""

import cmath
import math

import pytest

from plans.errors import AssemblyError, PlansError
from plans.graphical import construct
from plans.scene import example_names, example_path, load, loads

#: Positions computed in closed form in the tests agree to this [m] (round-off).
POSITION_TOL = 1e-12
#: With compass arcs as 64-segment-per-quadrant polygons, positions are within this [mm] of exact.
ARC_64_TOL_MM = 0.05


def printed(value: float, text: str) -> bool:
    """Does *value* round to the printed reference *text* (domain.md), to half its last digit?"""
    decimals = len(text.split(".")[1]) if "." in text else 0
    return abs(value - float(text)) <= 0.5 * 10.0**-decimals * (1 + 1e-9)


def test_e2_offset_slider_crank_position():
    solution = construct(load(example_path("slider-crank")))
    b = solution.positions["B"]
    assert printed(b.real, "0.3198513") and b.imag == pytest.approx(0.05, abs=POSITION_TOL)
    phi3, _ = solution.poses["3"]
    assert printed(math.degrees(phi3), "-4.7519838")


def test_e1_ladder_position():
    solution = construct(load(example_path("ladder")))
    expected = 0.5 * cmath.exp(1j * math.radians(30))
    assert abs(solution.positions["B"] - expected) < POSITION_TOL
    assert abs(solution.positions["A"]) < POSITION_TOL


FOUR_BAR = """
[frame]
points = {{ O = [0, 0], D = [0.4, 0] }}
[link.2]
points = {{ O = [0, 0], A = [0.1, 0] }}
[link.3]
points = {{ A = [0, 0], B = [0.5, 0] }}
[link.4]
points = {{ D = [0, 0], B = [0.4, 0] }}
[driver]
crank = "2"
angle = "90 deg"
omega = 1
{assembly}
"""


def reflect(z: complex, a: complex, d: complex) -> complex:
    """Mirror image of z in the line through a and d."""
    u = (d - a) / abs(d - a)
    return a + u * ((z - a) / u).conjugate()


@pytest.mark.parametrize("assembly", ["", "[assembly]\nB = 1", "[assembly]\nB = [0.5, 0.5]"])
def test_rrr_branch_plus_one_is_left_of_b_to_d(assembly):
    # A = (0, 0.1); B = (0.4, 0.4) is 0.5 from A and 0.4 from D, and left of A → D
    solution = construct(loads(FOUR_BAR.format(assembly=assembly)))
    assert abs(solution.positions["B"] - (0.4 + 0.4j)) < POSITION_TOL


@pytest.mark.parametrize("assembly", ["[assembly]\nB = -1", "[assembly]\nB = [0.3, -0.2]"])
def test_rrr_branch_minus_one_is_the_mirror_image(assembly):
    solution = construct(loads(FOUR_BAR.format(assembly=assembly)))
    assert abs(solution.positions["B"] - reflect(0.4 + 0.4j, 0.1j, 0.4)) < POSITION_TOL
    phi4, origin4 = solution.poses["4"]
    assert origin4 == pytest.approx(0.4)
    assert abs(origin4 + cmath.exp(1j * phi4) * 0.4 - solution.positions["B"]) < POSITION_TOL


def test_rrp_branch_minus_one_is_the_nearer_along_the_guide():
    text = example_path("slider-crank").read_text().replace("B = [0.32, 0.05]", "B = -1")
    solution = construct(loads(text))
    a = 0.1 * cmath.exp(1j * math.radians(45))
    expected_x = a.real - math.sqrt(0.25**2 - (0.05 - a.imag) ** 2)
    assert abs(solution.positions["B"] - complex(expected_x, 0.05)) < POSITION_TOL


def test_rpr_without_offset_lies_along_the_pivots():
    solution = construct(load(example_path("quick-return")))
    a = 0.25j + 0.12 * cmath.exp(1j * math.radians(30))
    u = a / abs(a)  # the slot through C = 0 and the crank pin A
    assert abs(solution.positions["A"] - a) < POSITION_TOL
    assert abs(solution.positions["D"] - 0.55 * u) < POSITION_TOL
    assert abs(solution.poses["4"][0] - cmath.phase(u)) < POSITION_TOL


OFFSET_SLEEVE = """
[frame]
points = {{ O = [0, 0], E = [0.3, 0.1] }}
[link.2]
points = {{ O = [0, 0], B = [0.1, 0] }}
[link.3]                   # rod along its own x axis, offset h3 from B
points = {{ B = [0, 0], M = [0.4, 0] }}
lines = {{ rod = {{ through = [0, {h3}], angle = 0 }} }}
[link.4]                   # sleeve: its line passes h4 to the right of E
points = {{ E = [0, 0] }}
lines = {{ slot = {{ through = [0, {h4}], angle = 0 }} }}
[[prismatic]]
line = "4.slot"
on = "3.rod"
name = "sleeve"
[driver]
crank = "2"
angle = "120 deg"
omega = 2
[assembly]
M = {sign}
"""


@pytest.mark.parametrize("sign", [1, -1])
@pytest.mark.parametrize("h3, h4", [(0.0, 0.0), (0.03, 0.0), (0.0, -0.02), (0.02, 0.05)])
def test_rpr_with_offsets_is_the_tangent_construction(h3, h4, sign):
    solution = construct(loads(OFFSET_SLEEVE.format(h3=h3, h4=h4, sign=sign)))
    b = 0.1 * cmath.exp(1j * math.radians(120))
    e = 0.3 + 0.1j
    # B is −h3 left of the common line, E is −h4 left of it: Im((E − B)·conj u) = h3 − h4
    w = e - b
    delta = h3 - h4
    alpha = math.asin(delta / abs(w))
    u = sign * (w / abs(w)) * cmath.exp(-1j * sign * alpha)
    assert (w * u.conjugate()).imag == pytest.approx(delta, abs=1e-15)
    assert ((w * u.conjugate()).real > 0) == (sign > 0)
    assert abs(cmath.exp(1j * solution.poses["3"][0]) - u) < POSITION_TOL
    assert abs(solution.positions["M"] - (b + 0.4 * u)) < POSITION_TOL


def test_rrr_that_cannot_assemble_names_group_lengths_and_gap():
    text = FOUR_BAR.format(assembly="").replace("D = [0.4, 0]", "D = [1.1, 0]")
    with pytest.raises(AssemblyError) as info:
        construct(loads(text))
    message = str(info.value)
    # |AD| = |(1.1, −0.1)| = 1.10454 m > 0.5 + 0.4 = 0.9 m
    assert message.startswith("RRR(3,4): cannot assemble at φ = 90.0°: joint B: ")
    assert "|AD| = 1.10454 m > AB + BD = 0.9 m (gap 0.205 m)" in message
    assert isinstance(info.value, PlansError) and isinstance(info.value, ArithmeticError)


def test_rrp_that_cannot_assemble_names_the_gap():
    text = example_path("slider-crank").read_text().replace('through = [0, "50 mm"]', 'through = [0, "500 mm"]')
    with pytest.raises(AssemblyError, match=r"RRP\(3,4\): cannot assemble at φ = 45\.0°: joint B: the arc AB = 0\.25 m about A"):
        construct(loads(text))


@pytest.mark.parametrize("name", example_names())
def test_compass_arcs_as_polygons_are_close_to_exact(name):
    scene = load(example_path(name))
    exact = construct(scene)
    approx = construct(scene, arc_segments=64)
    k_l = exact.scales["k_l"]
    for point, z in exact.positions.items():
        assert abs(approx.positions[point] - z) / k_l < ARC_64_TOL_MM, point


@pytest.mark.parametrize(
    "option", [{"arc_segments": 0}, {"k_v": 0.0}, {"k_l": -1.0}, {"k_a": math.nan}, {"precision": 0.0}]
)
def test_bad_options_are_value_errors(option):
    with pytest.raises(ValueError, match=next(iter(option))):
        construct(load(example_path("four-bar")), **option)


@pytest.mark.parametrize("h", [0.25, 0.25 + 1e-16, 0.25 - 1e-16, -0.25, -0.25 - 1e-16])
def test_rpr_with_the_offset_equal_to_the_pivot_distance_is_a_dead_centre_not_a_failed_assembly(h):
    """|BE| = |h| (to rounding): the rod's line is the tangent ⊥ BE through E, a dead centre for both methods."""
    from plans.analytic import solve
    from plans.errors import SingularPositionError

    text = f"""
[frame]
points = {{ O = [0, 0], E = [0.5, 0] }}
[link.2]
points = {{ O = [0, 0], B = [0.25, 0] }}
[link.3]
points = {{ B = [0, 0] }}
lines = {{ rod = {{ through = [0, {h!r}], angle = 0 }} }}
[[slider]]
pin = "E"
on = "3.rod"
name = "4"
[driver]
crank = "2"
angle = "0 deg"
omega = "1 rad/s"
"""
    scene = loads(text)
    with pytest.raises(SingularPositionError, match=r"^RPR\(3,4\): "):
        solve(scene)
    with pytest.raises(SingularPositionError, match=r"^RPR\(3,4\): the construction lines ⊥ BE and ∥ 3\.rod .* dead-centre position"):
        construct(scene)
    # a little further out it does not assemble, a little nearer it does, by both methods
    for factor, outcome in ((1 + 1e-9, AssemblyError), (1 - 1e-9, None)):
        scene = loads(text.replace(repr(h), repr(h * factor)))
        if outcome is None:
            assert abs(construct(scene).positions["E"] - 0.5) < POSITION_TOL and solve(scene).valid.all()
        else:
            with pytest.raises(outcome, match="gap"):
                construct(scene)
            with pytest.raises(outcome, match="gap"):
                solve(scene)
