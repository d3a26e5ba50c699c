"""The driver's loop equations print the position's own rates (the driver's law), not the scene's instant.

Expected values from the law's closed form (plans/motion.py docstring):
constant: ṡ = v₀, s̈ = 0; uniform: ṡ² = v₀² + 2a(s − s₀), s̈ = a.  The
printed product s̈·u must equal the value printed after it.
"""

import math
import re
from dataclasses import replace

import pytest

from plans.loops import loop_equations
from plans.positions import run_positions

from accelerating_scenes import linear_arm_accelerating

NUM = r"\(?(-?[0-9.eE+-]+)\)?"


def _driver_numbers(block):
    head, z, v, a = block.lines[:4]
    s, s_dot, s_ddot = (float(x) for x in re.findall(r"= (-?[0-9.eE+-]+)\\ \\mathrm", head))
    v_factor, v_value = (float(x) for x in re.search(rf"\\dot{{s}}\\,u = {NUM}\\,e\^.*? = {NUM}\\ ", v).groups())
    a_factor, a_value = (float(x) for x in re.search(rf"\\ddot{{s}}\\,u = {NUM}\\,e\^.*? = {NUM}\\ ", a).groups())
    return s, s_dot, s_ddot, (v_factor, v_value), (a_factor, a_value)


@pytest.mark.parametrize("law", [None, "uniform"])
def test_linear_arm_driver_rates_at_every_position(law):
    scene = linear_arm_accelerating()  # a = 2 m/s² at its instant (the bundled example runs at a = 0)
    if law == "uniform":  # fast enough not to stop inside the stroke: v² = 1 + 4(s − 0) > 0 on ±0.1 m
        scene = replace(scene, driver=replace(scene.driver, velocity=1.0))
    d = scene.driver
    assert d.acceleration != 0  # the scene's instant differs from the constant law
    run = run_positions(scene, 8, law=law)
    assert run.runs
    for r in run.runs:
        s, s_dot, s_ddot, (vf, vv), (af, av) = _driver_numbers(loop_equations(r.analytic, 0)[0])
        if law is None:
            assert s_ddot == 0 and s_dot == pytest.approx(d.velocity, rel=1e-3)
        else:
            assert s_ddot == pytest.approx(d.acceleration, rel=1e-3)
            assert s_dot == pytest.approx(math.copysign(math.sqrt(d.velocity ** 2 + 2 * d.acceleration * (s - d.s)), d.velocity), rel=2e-3)
        # the guide is horizontal (u = e^{i0°}): the product printed is the value printed
        assert vf == s_dot and vv == pytest.approx(vf, rel=1e-3, abs=1e-9)
        assert af == s_ddot and av == pytest.approx(af, rel=1e-3, abs=1e-9)
