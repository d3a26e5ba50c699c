"""The handout's plate pages in the course's words (issue 20, the teacher's leftover findings).

Expected values from independent sources: finite differences of the analytic
positions, the scene's own data (the driver's stroke), the i18n tables only for
words a test plants a bug in.
"""

import numpy as np
import pytest

from plans.analytic import solve
from plans.centres import instant_centres
from plans.drawing.centres_page import centres_rules
from plans.scene import example_path, load


# --- 1. the centres page's ω rule for a sliding driver ------------------------------------------------------


def test_centres_rule_of_a_sliding_driver_starts_from_its_velocity():
    scene = load(example_path("linear-arm"))
    result = instant_centres(scene)
    for lang in ("en", "sr", "ru", "bg", "sl"):
        omega_rule = centres_rules(lang, scene.frame_number, scene.driver, result.numbers)[0]
        assert "v_{A}" in omega_rule and r"\omega_j / \omega_k" not in omega_rule, omega_rule
        assert "P_{1k}P_{2k}" in omega_rule, omega_rule  # through P_1k and the centre of the driver (2) and k
    crank = load(example_path("quick-return"))
    rule = centres_rules("en", crank.frame_number, crank.driver, instant_centres(crank).numbers)[0]
    assert r"\omega_j / \omega_k" in rule


def test_sliding_driver_rule_gives_each_links_omega():
    """ω_k = v_A / P_1kP_2k (the rule the page states) equals dφ_k/dt by finite differences of the analytic positions."""
    scene = load(example_path("linear-arm"))
    d = scene.driver
    result = instant_centres(scene)
    h = 1e-6
    positions = solve(scene, [d.s - h, d.s + h])
    checked = 0
    for k in scene.links:
        if k == d.link:
            continue
        p1k, pdk = result.centre("frame", k), result.centre(d.link, k)
        if p1k.point is None or pdk.point is None:
            continue
        by_rule = abs(d.velocity) / abs(p1k.point - pdk.point)
        phi = np.unwrap(positions.links[k].phi)
        by_differences = abs((phi[1] - phi[0]) / (2 * h) * d.velocity)
        assert by_rule == pytest.approx(by_differences, rel=1e-5), k
        assert abs(result.links[k]) == pytest.approx(by_differences, rel=1e-5), k  # the value the page's table states
        checked += 1
    assert checked >= 3
