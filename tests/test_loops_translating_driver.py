"""A sliding driver's link translates: its other points are at a fixed offset and move with the driver's point
(v_F = v_A, a_F = a_A); the loop block writes no ω₂ or φ₂ for it (a review found "v_F = v_A + iω₂ l_AF e^{i(φ₂+56,31°)}")."""

import math
import tomllib

import plans
from plans.loops import loop_equations


def test_the_driver_link_of_a_linear_arm_translates():
    raw = tomllib.loads(open(plans.example_path("linear-arm"), encoding="utf-8").read())
    v = float(str(raw["driver"]["velocity"]).split()[0])  # the scene's driver speed, as typed
    block = loop_equations(plans.solve(plans.load(plans.example_path("linear-arm"))))[0]
    text = "\n".join(block.lines)
    assert r"\omega_{2}" not in text and r"\varphi_{2}" not in text, text
    assert rf"v_{{F}} = v_{{A}} = {v:g}\ \mathrm{{m/s}}" in text, text
    # F at 56.31° from A at l_AF = 0.1803 m: the arm from the scene's local coordinates (0.1, 0.15) m
    assert f"{math.degrees(math.atan2(0.15, 0.1)):.2f}" == "56.31" and r"l_{AF}\,e^{i\,56.31^\circ}" in text, text
