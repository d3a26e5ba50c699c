"""Every proportion placing an image by similarity computes from its numbers as printed (issue 20, fourth review).

"π d′ = 4,7 · 550,0 / 370,0 = 6,9 mm" gives 7,0 by hand: the result was the unrounded segments' quotient. A student
redoing the arithmetic, and the teacher marking it, must get the printed last digit.  The check is the arithmetic
itself, done here on the printed numbers (one decimal, half away from zero as a student rounds).
"""

from __future__ import annotations

import re
from decimal import ROUND_HALF_UP, Decimal

import pytest

import plans
from plans.drawing.readings import similarity_lines
from plans.graphical import construct

_EQUATION = re.compile(r"= ([0-9]+\.[0-9]) · ([0-9]+\.[0-9]) / ([0-9]+\.[0-9]) = ([0-9]+\.[0-9]) mm")


def _checked(lines) -> int:
    n = 0
    for line in lines:
        for read, a, b, result in _EQUATION.findall(line):
            exact = Decimal(read) * Decimal(a) / Decimal(b)
            by_hand = exact.quantize(Decimal("0.1"), rounding=ROUND_HALF_UP)
            # (a quotient on the half: either neighbour is a fair rounding)
            on_half = abs(exact - by_hand) == Decimal("0.05")
            assert Decimal(result) == by_hand or on_half, line
            n += 1
    return n


@pytest.mark.parametrize("example", ["six-bar", "quick-return", "four-bar", "linear-arm"])
def test_a_proportions_result_is_its_printed_numbers_arithmetic(example):
    scene = plans.load(plans.example_path(example))
    total = 0
    for k_v, k_a in ((None, None), (0.005, 0.05), (0.013, 0.17)):  # the scene's factors and two others
        g = construct(scene, k_v=k_v, k_a=k_a) if k_v else construct(scene)
        total += sum(_checked(similarity_lines(g, kind)) for kind in ("velocity", "acceleration"))
    assert total >= 3, example  # every one of these examples places images by similarity on both plans
