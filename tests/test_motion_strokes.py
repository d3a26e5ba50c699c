"""Limits, Grashof classes, extreme positions, H, θ and K against hand-worked closed forms (issue 19 §2–§3)."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

import plans
from plans.errors import SceneError
from plans.motion import crank_limits, driver_cycle, driver_law, four_bar_limits, four_bar_loops, grashof, output_link, strokes
from plans.scene import loads


def _slider_crank(r: float, l: float, e: float, omega: float = 10.0) -> plans.Scene:
    return loads(f"""
title = "slider-crank"
[frame]
points = {{ O = [0, 0] }}
lines = {{ rail = {{ through = [0, {e}], angle = 0 }} }}
[link.2]
points = {{ O = [0, 0], A = [{r}, 0] }}
[link.3]
points = {{ A = [0, 0], B = [{l}, 0] }}
[[slider]]
pin = "B"
on = "frame.rail"
[driver]
crank = "2"
angle = "45 deg"
omega = "{omega} rad/s"
[assembly]
B = [{r + l}, {e}]
""")


@pytest.mark.parametrize("r,l,e", [(0.1, 0.25, 0.05), (0.1, 0.25, 0.0), (0.05, 0.3, -0.02)])
def test_slider_crank_stroke_theta_K(r, l, e):
    st = strokes(_slider_crank(r, l, e))
    H = math.sqrt((l + r) ** 2 - e**2) - math.sqrt((l - r) ** 2 - e**2)
    theta = abs(math.asin(e / (l - r)) - math.asin(e / (l + r)))
    assert st.output.kind == "slider"
    assert st.travel == pytest.approx(H, rel=1e-9)
    assert st.theta == pytest.approx(theta, abs=1e-8)
    assert st.K == pytest.approx((math.pi + theta) / (math.pi - theta), rel=1e-8)
    # constant ω: the working stroke (the slower) is the longer crank arc, π + θ
    assert st.working_arc == pytest.approx(math.pi + theta, abs=1e-8)
    assert st.working_time == pytest.approx((math.pi + theta) / 10.0, rel=1e-8)
    # extreme positions: the crank along the rod (outer) and against it (inner)
    outer = math.asin(e / (l + r))
    inner = math.pi + math.asin(e / (l - r))
    got = sorted(math.remainder(x, 2 * math.pi) % (2 * math.pi) for x in (st.start_position, st.other_position))
    assert got == pytest.approx(sorted([outer % (2 * math.pi), inner % (2 * math.pi)]), abs=1e-8)


def test_four_bar_crank_rocker_swing_theta():
    """four-bar example: a = 80, b = 250, c = 200, d = 220 mm; B above the frame line in both extremes."""
    a, b, c, d = 0.08, 0.25, 0.2, 0.22
    st = strokes(plans.load(plans.example_path("four-bar")))
    alpha1 = math.acos((d * d + (a + b) ** 2 - c * c) / (2 * d * (a + b)))  # crank along the coupler
    alpha2 = math.acos((d * d + (b - a) ** 2 - c * c) / (2 * d * (b - a)))  # crank against it
    beta1 = math.acos((d * d + c * c - (a + b) ** 2) / (2 * d * c))
    beta2 = math.acos((d * d + c * c - (b - a) ** 2) / (2 * d * c))
    theta = abs(alpha2 - alpha1)
    assert st.output.link == "4" and st.output.kind == "rocker"
    assert st.travel == pytest.approx(abs(beta1 - beta2), abs=1e-9)
    assert st.theta == pytest.approx(theta, abs=1e-8)
    assert st.K == pytest.approx((math.pi + theta) / (math.pi - theta), rel=1e-8)


def test_summary_and_json_words():
    st = strokes(_slider_crank(0.1, 0.25, 0.05))
    text = "\n".join(st.summary("en"))
    assert "H = 205 mm" in text and "θ = 11.3°" in text and "K = (180° + θ)/(180° − θ) = 1.133" in text
    assert "ход H = 205 mm" in "\n".join(st.summary("ru"))
    doc = st.as_dict()
    assert doc["stroke_H_m"] == pytest.approx(0.20498878, rel=1e-6)
    assert doc["theta_deg"] == pytest.approx(11.2580, abs=1e-3)


@pytest.mark.parametrize(
    "lengths,kind,turning",
    [
        ((0.22, 0.08, 0.25, 0.20), "crank-rocker", ("input",)),  # s + l = 0.33 < 0.42, shortest the input
        ((0.05, 0.20, 0.25, 0.22), "double-crank", ("input", "output")),  # shortest the frame
        ((0.20, 0.22, 0.05, 0.25), "double-rocker", ("coupler",)),  # shortest the coupler
        ((0.22, 0.20, 0.25, 0.08), "crank-rocker", ("output",)),  # shortest the output: it is the crank
        ((0.20, 0.10, 0.25, 0.15), "change point", ("input",)),  # 0.1 + 0.25 = 0.2 + 0.15
        ((0.70, 0.10, 0.45, 0.20), "triple-rocker", ()),  # 0.1 + 0.7 = 0.8 > 0.65
    ],
)
def test_grashof_hand_worked(lengths, kind, turning):
    g = grashof(*lengths)
    assert g.kind == kind
    assert g.turning == turning
    assert g.grashof == (kind != "triple-rocker")


def test_examples_loops():
    loops = four_bar_loops(plans.load(plans.example_path("rocker-limit")))
    assert [(x.group, x.grashof.kind, x.turning_links()) for x in loops] == [("RRR(3,4)", "triple-rocker", ())]
    assert (loops[0].ground, loops[0].crank, loops[0].coupler, loops[0].rocker) == pytest.approx((0.7, 0.1, 0.45, 0.2))
    loops = four_bar_loops(plans.load(plans.example_path("four-bar")))
    assert [(x.grashof.kind, x.turning_links()) for x in loops] == [("crank-rocker", ("2",))]
    assert four_bar_loops(plans.load(plans.example_path("slider-crank"))) == []


def test_rocker_limits_closed_form_and_solver():
    scene = plans.load(plans.example_path("rocker-limit"))
    limits = crank_limits(scene)
    # |AD| = AB + BD = 0.65 m: cos φ = (0.1² + 0.7² − 0.65²) / (2·0.1·0.7)
    phi = math.acos((0.01 + 0.49 - 0.65**2) / 0.14)
    assert (limits.lo, limits.hi) == pytest.approx((-phi, phi), abs=1e-12)
    assert four_bar_limits(0.1, 0.7, 0.45, 0.2) == pytest.approx([-phi, phi], abs=1e-12)
    assert limits.closed_form and limits.group == "RRR(3,4)"
    inside = plans.solve(scene, [limits.lo + 1e-6, limits.hi - 1e-6], allow_partial=True).valid
    outside = plans.solve(scene, [limits.lo - 1e-6, limits.hi + 1e-6], allow_partial=True).valid
    assert np.all(inside) and not np.any(outside)
    assert crank_limits(plans.load(plans.example_path("four-bar"))) is None


def test_rocker_input_swings_and_every_row_assembles():
    scene = plans.load(plans.example_path("rocker-limit"))
    cycle = driver_cycle(scene, 12)
    assert cycle.law.kind == "harmonic"
    sweep = cycle.solve()
    assert np.all(sweep.valid), "every position of the swing is assembled"
    limits = crank_limits(scene)
    assert np.all((cycle.positions > limits.lo) & (cycle.positions < limits.hi))
    # over the swing and back: ω changes sign twice over the cycle, and is 0 at the limits
    signs = np.sign(cycle.rate)
    assert np.count_nonzero(signs != np.roll(signs, 1)) == 2
    dense = driver_cycle(scene, 3600)
    near = np.argmin(np.abs(dense.positions - limits.hi))
    assert abs(dense.rate[near]) < 0.02 * np.max(np.abs(dense.rate))
    # |ω| is the scene's at the scene's angle (30°)
    law = cycle.law
    half = 0.5 * (limits.hi - limits.lo)
    assert law.frequency * math.sqrt(half**2 - math.radians(30) ** 2) == pytest.approx(10.0, rel=1e-12)
    # the old sweep over a turn: 9 of 12 positions could not assemble
    old = plans.solve(scene, math.radians(30) + 2 * math.pi * np.arange(12) / 12, allow_partial=True)
    assert np.count_nonzero(~np.asarray(old.valid)) == 9


def test_law_refusals_name_the_key():
    four_bar = plans.load(plans.example_path("four-bar"))
    decelerating = replace(four_bar, driver=replace(four_bar.driver, epsilon=-10.0, law="uniform"))
    with pytest.raises(SceneError, match=r"driver\.law.*|uniform.*cannot cover") as info:
        driver_cycle(decelerating, 12)
    assert "driver.law" in str(info.value) and "reaches 0" in str(info.value)
    with pytest.raises(SceneError, match="harmonic") as info:
        driver_law(four_bar, "harmonic")
    assert "--law" in str(info.value)
    rocker = plans.load(plans.example_path("rocker-limit"))
    with pytest.raises(SceneError, match="cannot turn fully") as info:
        driver_law(replace(rocker, driver=replace(rocker.driver, law="constant")))
    assert "driver.law" in str(info.value)
    with pytest.raises(SceneError, match="does not move"):
        driver_law(replace(four_bar, driver=replace(four_bar.driver, omega=0.0)))


def test_uniform_law_numbers():
    """ω² = ω₀² + 2ε(φ − φ₀) and t = (ω − ω_first)/ε, from the scene's instant (four-bar: ω₀ = 10, ε = 5)."""
    scene = plans.load(plans.example_path("four-bar"))
    cycle = driver_cycle(scene, 8, law="uniform", start="scene")
    phi = cycle.positions
    assert phi[0] == pytest.approx(math.radians(60))
    omega = np.sqrt(100 + 10 * (phi - phi[0]))
    assert cycle.rate == pytest.approx(omega, rel=1e-12)
    assert cycle.acceleration == pytest.approx(np.full(8, 5.0))
    assert cycle.t == pytest.approx((omega - 10) / 5, abs=1e-12)
    constant = driver_cycle(scene, 8, start="scene")
    assert constant.t == pytest.approx((phi - phi[0]) / 10)
    assert constant.period == pytest.approx(2 * math.pi / 10)


def test_output_named_by_the_scene():
    scene = plans.load(plans.example_path("six-bar"))
    assert output_link(scene).link == "6"
    assert output_link(replace(scene, output="4")).link == "4"
    with pytest.raises(SceneError, match="output.link"):
        output_link(replace(scene, output="3"))
    with pytest.raises(SceneError, match="output.link"):
        loads(plans.example_path("six-bar").read_text() + '\n[output]\nlink = "9"\n')


def test_positions_start_at_the_working_strokes_extreme():
    scene = _slider_crank(0.1, 0.25, 0.05)
    cycle = driver_cycle(scene, 12)
    outer = math.asin(0.05 / 0.35)
    inner = math.pi + math.asin(0.05 / 0.15)
    # ω > 0: the longer arc (working) runs from the inner extreme... or the outer; position 0 starts the longer arc
    start = cycle.positions[0] % (2 * math.pi)
    arc = (inner - outer) % (2 * math.pi) if abs(start - outer) < 1e-8 else (outer - inner) % (2 * math.pi)
    assert min(abs(start - outer), abs(start - inner)) < 1e-8
    assert arc > math.pi
    assert driver_cycle(scene, 12, start="scene").positions[0] == pytest.approx(math.radians(45))


def test_quick_return_by_hand():
    """quick-return.toml: crank r = 120 mm about O, 250 mm above the lever's pivot C; lever CD = 550 mm; the ram's
    line 520 mm above C, rod DE = 200 mm.  The lever's extremes: the slot tangent to the crank circle (CA ⊥ OA), the
    crank at ±acos(r/d) from O→C; the short arc 2·acos(r/d) is the return.  The ram's stroke: D at ±CD·r/d either
    side, the rod's offsets equal: H = 2·CD·r/d."""
    r, d, lever = 0.12, 0.25, 0.55
    st = strokes(plans.load(plans.example_path("quick-return")))
    short = 2 * math.acos(r / d)
    assert st.output.link == "6" and st.output.kind == "slider"
    assert st.return_arc == pytest.approx(short, abs=1e-8)
    assert st.theta == pytest.approx(math.pi - short, abs=1e-8)
    assert st.K == pytest.approx((2 * math.pi - short) / short, rel=1e-8)
    assert st.travel == pytest.approx(2 * lever * r / d, rel=1e-9)


def test_solver_rates_and_branches_arguments():
    """plans.solve(..., rates=(ω, ε)) per position: velocities scale with ω, accelerations are ω²·(ε = 0 part) + ε·(ω = 1
    velocity part) — checked against two solves of the scene at its own rates; bad shapes and groups are refused."""
    scene = plans.load(plans.example_path("four-bar"))
    phi = np.radians([10.0, 80.0, 200.0, 300.0, 350.0])
    omega, epsilon = np.array([1.0, -2.0, 3.0, 0.5, 7.0]), np.array([0.0, 4.0, -1.0, 2.0, 0.3])
    got = plans.solve(scene, phi, rates=(omega, epsilon))
    unit = plans.solve(replace(scene, driver=replace(scene.driver, omega=1.0, epsilon=0.0)), phi)
    tangential = plans.solve(replace(scene, driver=replace(scene.driver, omega=0.0, epsilon=1.0)), phi)
    for name in ("B", "M"):
        assert got.points[name].v == pytest.approx(omega * unit.points[name].v, rel=1e-12, abs=1e-15)
        expected = omega**2 * unit.points[name].a + epsilon * tangential.points[name].a
        assert got.points[name].a == pytest.approx(expected, rel=1e-11, abs=1e-13)
    with pytest.raises(ValueError, match="one value per position"):
        plans.solve(scene, phi, rates=(omega[:3], 0.0))
    with pytest.raises(ValueError, match="no group 'RRR\\(4,5\\)'"):
        plans.solve(scene, phi, branches={"RRR(4,5)": -1})
    # the other branch of the four-bar: B mirrored in the line A–D
    other = plans.solve(scene, phi, branches={"RRR(3,4)": np.array([-1, 1, -1, 1, -1])})
    A, B, D = np.asarray(got.points["A"].r), np.asarray(got.points["B"].r), 0.22 + 0j
    mirrored = A + (D - A) * np.conj((B - A) / (D - A))
    assert np.asarray(other.points["B"].r) == pytest.approx(np.where([True, False, True, False, True], mirrored, B), abs=1e-12)


def test_uniform_law_with_no_angular_acceleration_is_the_constant_one():
    """`law = "uniform"` on a scene with ε = 0 (the slider-crank) is constant ω: the stroke times sum to one turn
    at 2000 rpm, 60/2000 s (it divided by ε = 0 before)."""
    from plans.motion import strokes as cycle_strokes
    from plans.scene import example_path, load

    s = cycle_strokes(load(example_path("slider-crank")), law="uniform")
    assert s.working_time + s.return_time == pytest.approx(60 / 2000, rel=1e-12)
