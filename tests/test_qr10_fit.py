"""What the sheet layout fits: a mechanism's guides over their travel, and a drawing measured at a factor.

Expected values are worked by hand from the example's dimensions and from the page mantissas
(1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8), not taken from the code under test.
"""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

import plans
from plans.drawing.sheet import _Figure, _ladder, _reach
from plans.graphical import construct
from plans.graphical.scales import PAGE_MANTISSAS
from plans.positions import cycle_sweep
from plans.sweep import line_travel


def test_the_slider_crank_s_guide_over_its_stroke_widens_what_scales_with_k_l():
    # E2: OA = 0.1 m at 45°, AB = 0.25 m, B on y = 0.05 m.  B travels from x = √((0.25−0.1)² − 0.05²) = √0.02
    # to √((0.25+0.1)² − 0.05²) = √0.12; at 45° B is at 0.1/√2 + √(0.25² − (0.05 − 0.1/√2)²) ≈ 0.31985.
    scene = plans.load(plans.example_path("slider-crank"))
    graphical = construct(scene)
    travelled = replace(graphical, travel=line_travel(cycle_sweep(scene, plans.solve(scene).structure)))
    a = 0.1 / math.sqrt(2)
    b = a + math.sqrt(0.25**2 - (0.05 - a) ** 2)
    assert _reach(graphical) == pytest.approx((b, a), abs=1e-9)  # no travel attached: the points alone
    assert _reach(travelled) == pytest.approx((math.sqrt(0.12), a), abs=1e-6)  # the stroke's far end, right of B


def test_a_factor_at_which_the_drawing_took_more_is_charged_what_it_took_there():
    ladder = _ladder(PAGE_MANTISSAS)
    plan = _Figure("velocity", (0.1, 0.1), 0.1, (0.0, 0.0), 1.0, False)
    # 0.1 m/s in 100 − 2 mm (FIT_SLACK): need 0.1/98 ≈ 0.00102 → the mantissa 1.2: 0.0012
    assert plan.fit(100.0, 100.0, ladder) == pytest.approx(0.0012)
    # drawn at 0.0012 it took 60 mm more across (an enlarged detail): 0.1/(100 − 60 − 2) ≈ 0.00263 → 0.003
    plan.at = {0.0012: (60.0, 0.0)}
    assert plan.fit(100.0, 100.0, ladder) == pytest.approx(0.003)
    # measured at another factor only: 0.0012 stands
    plan.at = {0.002: (60.0, 0.0)}
    assert plan.fit(100.0, 100.0, ladder) == pytest.approx(0.0012)
    # no room at all with what it took: no fit
    plan.at = {0.0012: (95.0, 0.0)}
    assert plan.fit(100.0, 100.0, ladder) is None
