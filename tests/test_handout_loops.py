"""The complex-number loop equations as the handout prints them: the right terms, the solver's numbers."""

from __future__ import annotations

import re

import pytest
from matplotlib.mathtext import MathTextParser

import plans
from plans.loops import loop_equations, plain

_PARSER = MathTextParser("path")
_COMPLEX = re.compile(r"= \(?(-?[0-9.]+(?:·10\^-?\d+)?)(?: ([+-]) ([0-9.]+(?:·10\^-?\d+)?)i)?\)? (m|m/s|m/s\^2)$")


def _number(text: str) -> float:
    if "·10^" in text:
        mantissa, exponent = text.split("·10^")
        return float(mantissa) * 10.0 ** int(exponent)
    return float(text)


@pytest.fixture(scope="module")
def six_bar():
    scene = plans.load(plans.example_path("six-bar"))
    solution = plans.solve(scene)
    return solution, loop_equations(solution)


def test_one_block_for_the_driver_and_one_per_group(six_bar):
    solution, blocks = six_bar
    assert [b.title for b in blocks] == ["I(1,2)", "RRR(3,4)", "RPR(5,6)"]


def test_the_rrr_loop_and_its_derivatives_with_the_solvers_numbers(six_bar):
    _, blocks = six_bar
    lines = [plain(line) for line in blocks[1].lines]
    assert lines[0] == "z_A + l_ACe^iφ_3 = z_D + l_DCe^iφ_4"
    assert lines[2] == "v_A + iω_3l_ACe^iφ_3 = v_D + iω_4l_DCe^iφ_4"
    assert lines[4] == "a_A + (iε_3 - ω_3^2)l_ACe^iφ_3 = a_D + (iε_4 - ω_4^2)l_DCe^iφ_4"
    # numbers substituted, unknowns left as symbols, results after ⇒
    assert "(0.08604 + 0.1229i) + 0.6e^iφ_3 = (-0.45 + 0.35i) + 0.4e^iφ_4 ⇒ φ_3 = 117.52^°, φ_4 = 49.68^°" in lines[1]
    assert "iω_3·0.6e^i117.52^°" in lines[3] and "ω_3 = 0.2502 rad/s, ω_4 = -3.592 rad/s" in lines[3]  # (with units: round 12)
    assert "(iε_3 - 0.2502^2)·0.6e^i117.52^°" in lines[5] and "ε_3 = -17.61 rad/s^2, ε_4 = -13.53 rad/s^2" in lines[5]


def test_the_coriolis_term_of_the_sliding_rod(six_bar):
    _, blocks = six_bar
    acceleration = plain(blocks[2].lines[5])
    # 2iω₅ṡ e^{iφ₅} with ω₅ = −1.813 rad/s and ṡ = −0.7759 m/s substituted; φ₅ = −96.63° printed as
    # 263.37° (angles 0…360°, as the page's header and the tables' ∠ print them)
    assert "2i·(-1.813)·(-0.7759)e^i263.37^°" in acceleration
    assert "ε_5 = -3.344 rad/s^2, s̈_E = -6.548 m/s^2" in acceleration


@pytest.mark.parametrize("name", plans.example_names())
def test_every_line_is_valid_mathtext_and_every_point_value_is_the_solvers(name):
    scene = plans.load(plans.example_path(name))
    solution = plans.solve(scene)
    blocks = loop_equations(solution)
    assert blocks[0].lines and all(b.lines for b in blocks)
    checked = 0
    for block in blocks:
        for line in block.lines:
            _PARSER.parse(line, dpi=72)
            text = plain(line)
            head = re.match(r"^([zva])_(\w+) = ", text)
            match = _COMPLEX.search(text)
            if head and match and head.group(2) in solution.points:
                letter, point = head.groups()
                re_, sign, im, _ = match.groups()
                value = complex(_number(re_), (_number(im) if im else 0.0) * (-1 if sign == "-" else 1))
                motion = solution.points[point]
                expected = complex({"z": motion.r, "v": motion.v, "a": motion.a}[letter][0])
                scale = max(abs(expected), 1e-300)
                assert abs(value - expected) <= 1e-3 * scale, (name, text)
                checked += 1
    assert checked >= 3  # at least the driver's point, its v and a
