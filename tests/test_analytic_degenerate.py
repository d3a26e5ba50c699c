"""Degenerate rows, errors, branches and the shape of the API.

ω = 0 gives an all-zero velocity plan; a dyad that cannot assemble raises
with the group, joint, position, lengths and gap; a dead centre raises
SingularPositionError; allow_partial returns NaN instead; one vectorised call
equals many single calls; the assembly hints pick the documented branch; and
the solver loads neither matplotlib nor shapely.
"""

import cmath
import math
import subprocess
import sys
import time
import warnings

import numpy as np
import pytest

from plans.analytic import AnalyticSolution, solve
from plans.errors import AssemblyError, PlansError, SingularPositionError
from plans.scene import example_path, load, loads
from plans.structure import find_structure
from tolerances import EXACT_REL


def four_bar(D="0.7", coupler="0.45", rocker="0.2", angle="0 deg", assembly="B = 1", omega="10 rad/s", epsilon="0"):
    """Crank OA = 0.1 m about O = (0, 0), coupler AB, rocker DB about D = (x, 0)."""
    return loads(
        f"""
[frame]
points = {{ O = [0, 0], D = [{D}, 0] }}
[link.2]
points = {{ O = [0, 0], A = [0.1, 0] }}
[link.3]
points = {{ A = [0, 0], B = [{coupler}, 0] }}
[link.4]
points = {{ D = [0, 0], B = [{rocker}, 0] }}
[driver]
crank = "2"
angle = "{angle}"
omega = "{omega}"
epsilon = "{epsilon}"
[assembly]
{assembly}
""",
        source="four-bar-test",
    )


def six_bar_text():
    return example_path("six-bar").read_text(encoding="utf-8")


# --- ω = 0 ------------------------------------------------------------------------


def test_a_crank_at_rest_gives_all_zero_velocities_and_accelerations():
    scene = loads(six_bar_text().replace('omega = "-10 rad/s"', "omega = 0"))
    solution = solve(scene, np.linspace(0, 2 * np.pi, 37))
    for motion in solution.points.values():
        assert np.max(np.abs(motion.v)) == 0 and np.max(np.abs(motion.a)) == 0
    for motion in solution.links.values():
        assert np.max(np.abs(motion.omega)) == 0 and np.max(np.abs(motion.epsilon)) == 0
    for motion in solution.sliders.values():
        assert np.max(np.abs(motion.v_rel)) == 0 and np.max(np.abs(motion.coriolis)) == 0


def test_a_crank_starting_from_rest_has_zero_velocities_but_accelerations():
    scene = loads(six_bar_text().replace('omega = "-10 rad/s"', 'omega = 0\nepsilon = "5 rad/s^2"'))
    solution = solve(scene)
    assert all(np.max(np.abs(m.v)) == 0 for m in solution.points.values())
    A = solution.points["A"]
    assert A.a[0] == pytest.approx(5j * A.r[0], rel=EXACT_REL)  # only aᵗ = ε × OA
    assert np.max(np.abs(solution.points["C"].a)) > 0


def test_a_linear_driver_at_rest_gives_zero_velocities():
    text = example_path("linear-arm").read_text(encoding="utf-8")
    scene = loads(text.replace('velocity = "0.5 m/s"', "velocity = 0").replace('acceleration = "2 m/s^2"', "acceleration = 0"))
    solution = solve(scene, np.linspace(-0.05, 0.05, 11))
    assert all(np.max(np.abs(m.v)) == 0 and np.max(np.abs(m.a)) == 0 for m in solution.points.values())


# --- errors ------------------------------------------------------------------------


def test_an_rrr_that_is_too_short_names_group_joint_position_lengths_and_gap():
    scene = four_bar()  # assembles at 0°: |AD| = 0.6 m
    with pytest.raises(AssemblyError) as caught:
        solve(scene, math.pi)  # A = (−0.1, 0): |AD| = 0.8 m
    assert str(caught.value) == "RRR(3,4): joint B cannot assemble at φ = 180.0°: |AD| = 0.800 m > AB + BD = 0.650 m (gap 0.150 m)"
    assert isinstance(caught.value, PlansError) and isinstance(caught.value, ArithmeticError)
    assert caught.value.group == "RRR(3,4)" and caught.value.position == math.pi


def test_an_rrr_that_folds_too_far_names_the_difference_of_the_lengths():
    with pytest.raises(AssemblyError) as caught:
        solve(four_bar(D="0.3"))
    assert str(caught.value) == "RRR(3,4): joint B cannot assemble at φ = 0.0°: |AD| = 0.200 m < |AB − BD| = 0.250 m (gap 0.050 m)"


def test_a_sweep_reports_the_first_failing_position_and_how_many_fail():
    phis = np.radians(np.arange(0, 360, 10.0))
    reach = np.abs(0.7 - 0.1 * np.exp(1j * phis))  # |AD|; B assembles while it is below 0.65 m
    first = int(np.argmax(reach > 0.65))
    with pytest.raises(AssemblyError) as caught:
        solve(four_bar(), phis)
    assert str(caught.value) == (
        f"RRR(3,4): joint B cannot assemble at φ = {10 * first:.1f}°: |AD| = {reach[first]:.3f} m > AB + BD = 0.650 m "
        f"(gap {reach[first] - 0.65:.3f} m) (and at {np.sum(reach > 0.65) - 1} more of the positions asked for; "
        "allow_partial=True returns NaN there)"
    )


def test_an_rrp_out_of_reach_names_the_distance_from_the_guide():
    text = example_path("slider-crank").read_text(encoding="utf-8").replace('through = [0, "50 mm"]', 'through = [0, "400 mm"]')
    with pytest.raises(AssemblyError) as caught:
        solve(loads(text))
    assert str(caught.value) == (
        "RRP(3,4): joint B cannot assemble at φ = 45.0°: the line B runs on (parallel to frame.cylinder) "
        "passes 0.329 m from A, farther than AB = 0.250 m (gap 0.079 m)"
    )


def test_an_rpr_with_an_offset_line_that_cannot_reach_the_sleeve():
    scene = loads(
        """
[frame]
points = { O = [0, 0], E = [0.05, 0.02] }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
[link.5]
points = { A = [0, 0] }
lines = { rod = { through = [0, 0.2], angle = 0 } }
[[slider]]
pin = "E"
on = "5.rod"
name = "6"
[driver]
crank = "2"
angle = "0 deg"
omega = "1 rad/s"
"""
    )
    with pytest.raises(AssemblyError) as caught:
        solve(scene)
    distance = abs(complex(0.05, 0.02) - 0.1)
    assert str(caught.value) == (
        f"RPR(5,6): the line 5.rod cannot pass through E at φ = 0.0°: |AE| = {distance:.3f} m < "
        f"the offset 0.200 m of the line from the pins (gap {0.2 - distance:.3f} m)"
    )


def test_a_linear_driver_position_is_reported_in_mm():
    text = example_path("ladder").read_text(encoding="utf-8")
    with pytest.raises(AssemblyError, match=r"^RRP\(3,4\): joint B cannot assemble at s = 1000\.0 mm: "):
        solve(loads(text), 1.0)  # A 0.567 m from the wall, the ladder 0.5 m long


def test_allow_partial_returns_nan_and_valid_false_where_the_group_fails():
    phis = np.radians(np.arange(0, 360, 10.0))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no numpy warning may leak
        solution = solve(four_bar(), phis, allow_partial=True)
    A = solution.points["A"]
    reach = np.abs(0.7 - A.r)
    assert np.array_equal(solution.valid, reach < 0.65)
    assert 0 < solution.valid.sum() < len(phis)
    bad = ~solution.valid
    assert np.all(np.isnan(solution.points["B"].r[bad])) and np.all(np.isnan(solution.links["3"].omega[bad]))
    assert np.all(np.isfinite(solution.points["B"].a[~bad]))
    assert np.all(np.isfinite(A.v))  # the driver itself is known everywhere
    assert np.all(np.isnan(solution.conditions["RRR(3,4)"][bad]))


def test_a_dead_centre_raises_singular_position_error():
    scene = four_bar(D="0.55", angle="180 deg")  # at 180°: |AD| = 0.65 m = AB + BD, the dyad stretched out
    with pytest.raises(SingularPositionError, match=r"^RRR\(3,4\): dead centre at φ = 180\.0°: A, B and D are in line"):
        solve(scene)
    solution = solve(scene, [math.pi, math.pi - 0.3], allow_partial=True)
    assert solution.valid.tolist() == [False, True]
    assert np.isfinite(solution.points["B"].r[0])  # the position exists …
    assert np.isnan(solution.points["B"].v[0]) and np.isnan(solution.links["4"].omega[0])  # … its velocities do not


def test_parallel_guides_of_a_prp_are_a_singular_position():
    text = example_path("wedge").read_text(encoding="utf-8").replace('angle = "90 deg"', 'angle = "30 deg"')
    with pytest.raises(SingularPositionError, match=r"^PRP\(3,4\): dead centre at s = 0\.0 mm: the guides 2\.incline and frame\.follower are parallel"):
        solve(loads(text))


def test_positions_must_be_finite_numbers_in_at_most_one_dimension():
    scene = load(example_path("four-bar"))
    with pytest.raises(ValueError, match="not a finite number"):
        solve(scene, [0.1, float("nan")])
    with pytest.raises(ValueError, match="1-D"):
        solve(scene, np.zeros((2, 2)))


# --- vectorised ------------------------------------------------------------------------


def test_one_vectorised_call_equals_single_calls():
    # one position is solved in plain complex arithmetic (plans.analytic.single), a sweep with numpy:
    # the same equations, so the same numbers to round-off of each quantity's scale over the turn
    scene = load(example_path("six-bar"))
    phis = np.linspace(0, 2 * np.pi, 3600, endpoint=False)
    turn = solve(scene, phis)
    for k in (0, 457, 1800, 2999, 3599):
        single = solve(scene, phis[k])
        for kind, fields in (("points", ("r", "v", "a")), ("links", ("phi", "omega", "epsilon")), ("sliders", ("s", "v_rel", "a_rel", "coriolis"))):
            for name, motion in getattr(single, kind).items():
                for field in fields:
                    swept = getattr(getattr(turn, kind)[name], field)
                    scale = float(np.abs(swept).max())
                    assert abs(getattr(motion, field)[0] - swept[k]) <= 1e-14 * scale, (kind, name, field)


def test_a_full_turn_of_the_six_bar_is_one_fast_call():
    scene = load(example_path("six-bar"))
    structure = find_structure(scene)
    phis = np.linspace(0, 2 * np.pi, 3600, endpoint=False)
    solve(scene, phis, structure)
    start = time.perf_counter()
    for _ in range(5):
        solution = solve(scene, phis, structure)
    elapsed = (time.perf_counter() - start) / 5
    assert solution.valid.all() and len(solution) == 3600
    assert elapsed < 0.1, f"{elapsed * 1e3:.1f} ms for 3600 positions"  # a few ms on one core; generous for CI


def test_the_result_is_frozen_and_can_be_cut_at_a_position():
    scene = load(example_path("quick-return"))
    solution = solve(scene, np.linspace(0, 1, 5))
    assert isinstance(solution, AnalyticSolution)
    with pytest.raises(ValueError):
        solution.points["A"].r[0] = 0
    third = solution.at(2)
    assert len(third) == 1 and third.driver[0] == solution.driver[2]
    assert third.points["E"].a[0] == solution.points["E"].a[2]
    # a point found from a body's pose and motion equals the named point
    D = solution.motion_of("4", scene.bodies["4"].points["D"])
    assert np.allclose(D.r, solution.points["D"].r, rtol=EXACT_REL) and np.allclose(D.a, solution.points["D"].a, rtol=EXACT_REL)
    phi, origin = solution.poses["4"]
    assert np.allclose(origin, solution.points["C"].r)  # C is link 4's own (0, 0)


def test_the_driver_rates_are_held_at_every_position():
    scene = load(example_path("four-bar"))
    solution = solve(scene, [0.0, 1.0, 2.0])
    assert solution.links["2"].omega.tolist() == [10.0] * 3 and solution.links["2"].epsilon.tolist() == [5.0] * 3
    assert solution.driver.tolist() == [0.0, 1.0, 2.0] and solution.links["2"].phi.tolist() == [0.0, 1.0, 2.0]


def test_the_analytic_solver_loads_neither_matplotlib_nor_shapely():
    code = (
        "import sys, plans.analytic\n"
        "from plans.scene import load, example_path\n"
        "plans.analytic.solve(load(example_path('six-bar')))\n"
        "bad = [m for m in ('matplotlib', 'shapely', 'plans.graphical', 'plans.drawing') if m in sys.modules]\n"
        "assert not bad, bad\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True, cwd=str(example_path("six-bar").parents[2]))


# --- branches ------------------------------------------------------------------------


def circle_intersections(P, p, Q, q):
    """The two points at distances p from P and q from Q, by the law of cosines."""
    d = abs(Q - P)
    angle = math.acos((d * d + p * p - q * q) / (2 * d * p))
    base = cmath.phase(Q - P)
    return [P + p * cmath.exp(1j * (base + s * angle)) for s in (1, -1)]


@pytest.mark.parametrize("which", [0, 1])
def test_a_location_hint_picks_the_open_or_the_crossed_four_bar(which):
    scene = load(example_path("four-bar"))
    A = 0.08 * cmath.exp(1j * math.radians(60))
    candidates = circle_intersections(A, 0.25, 0.22 + 0j, 0.2)
    hint = candidates[which] + 0.02 * (candidates[which] - candidates[1 - which])  # near this one
    text = example_path("four-bar").read_text(encoding="utf-8").replace("B = [0.2, 0.2]", f"B = [{hint.real!r}, {hint.imag!r}]")
    solution = solve(loads(text), np.radians([60.0, 61.0, 120.0]))
    assert abs(solution.points["B"].r[0] - candidates[which]) <= EXACT_REL
    # the branch is kept along the sweep: B stays on the same side of A → D
    A_r, B_r, D_r = (solution.points[p].r for p in "ABD")
    sides = np.sign((np.conj(D_r - A_r) * (B_r - A_r)).imag)
    assert np.all(sides == sides[0])
    assert scene.assembly  # the bundled scene has a hint too


@pytest.mark.parametrize("sign", [1, -1])
def test_the_rrr_sign_puts_the_inner_joint_left_of_b_to_d(sign):
    solution = solve(four_bar(assembly=f"B = {sign}"), np.radians(np.arange(0, 60, 5.0)))
    A, B, D = (solution.points[p].r for p in "ABD")
    assert np.all(np.sign((np.conj(D - A) * (B - A)).imag) == sign)


@pytest.mark.parametrize("sign", [1, -1])
def test_the_rrp_sign_takes_the_intersection_further_along_the_guide(sign):
    text = example_path("slider-crank").read_text(encoding="utf-8").replace("B = [0.32, 0.05]", f"B = {sign}")
    solution = solve(loads(text), np.radians(np.arange(0, 360, 15.0)))
    A, B = solution.points["A"].r, solution.points["B"].r
    foot = A.real  # the guide is horizontal: the two intersections are symmetric about A's foot
    assert np.all(np.sign(B.real - foot) == sign)


@pytest.mark.parametrize("sign", [1, -1])
def test_the_rpr_sign_points_the_line_from_i_to_j(sign):
    text = six_bar_text() + f"M = {sign}\n"  # M rides on rod 5, link i of RPR(5,6)
    solution = solve(loads(text), np.radians(np.arange(0, 360, 15.0)))
    u = np.exp(1j * solution.links["5"].phi)  # the rod's line is along its x axis
    B, E = solution.points["B"].r, solution.points["E"].r
    assert np.all(np.sign((np.conj(u) * (E - B)).real) == sign)


def test_a_hint_at_a_position_where_the_group_does_not_assemble_is_an_error():
    scene = four_bar(angle="180 deg", assembly="B = [0.5, 0.1]")
    with pytest.raises(AssemblyError) as caught:
        solve(scene, [0.0])  # would assemble, but the hint cannot be resolved at 180°
    assert str(caught.value) == (
        "RRR(3,4): joint B cannot assemble at φ = 180.0°: |AD| = 0.800 m > AB + BD = 0.650 m (gap 0.150 m); "
        "the hint B near (0.5, 0.1) m chooses the branch of RRR(3,4) at the scene's own position, "
        "so no branch can be chosen for the positions asked for"
    )


# --- extreme scales ----------------------------------------------------------------------


@pytest.mark.parametrize("length, rate", [(1e-6, 1e5), (1e3 / 4.5, 1e-3), (1.0, 1.0)])
def test_relative_accuracy_does_not_depend_on_the_unit_system(length, rate):
    """The six-bar scaled by `length` and turned `rate` times as fast: r·k, v·k·q, a·k·q², ω·q, ε·q²."""
    import re

    base_text = six_bar_text()
    text = re.sub(r'"(-?[\d.]+) mm"', lambda m: f'"{float(m.group(1)) * length!r} mm"', base_text)
    text = text.replace('omega = "-10 rad/s"', f'omega = "{-10 * rate!r} rad/s"')
    text = text.replace("C = [-0.3, 0.7]", f"C = [{-0.3 * length!r}, {0.7 * length!r}]")
    phis = np.linspace(0, 2 * np.pi, 50)
    base, scaled = solve(loads(base_text), phis), solve(loads(text), phis)
    for name, motion in base.points.items():
        for field, factor in (("r", length), ("v", length * rate), ("a", length * rate**2)):
            want = getattr(motion, field) * factor
            got = getattr(scaled.points[name], field)
            assert np.max(np.abs(got - want)) <= EXACT_REL * (np.max(np.abs(want)) or 1.0), (name, field)
    for name, motion in base.links.items():
        assert np.allclose(scaled.links[name].omega, motion.omega * rate, rtol=EXACT_REL, atol=EXACT_REL * 10 * rate)
        assert np.allclose(scaled.links[name].epsilon, motion.epsilon * rate**2, rtol=EXACT_REL, atol=EXACT_REL * 100 * rate**2)
    assert np.allclose(scaled.conditions["RRR(3,4)"], base.conditions["RRR(3,4)"], rtol=1e-9)


@pytest.mark.parametrize("ratio", [1e-4, 1e-2, 0.5])
def test_a_crank_much_shorter_than_its_coupler(ratio):
    """In-line slider-crank, crank r = ratio·l, against its closed form (r sin φ + l sin θ = 0)."""
    l, w, e = 0.25, 300.0, 40.0
    r = ratio * l
    scene = loads(
        f"""
[frame]
points = {{ O = [0, 0] }}
lines = {{ cylinder = {{ through = "O", angle = 0 }} }}
[link.2]
points = {{ O = [0, 0], A = [{r!r}, 0] }}
[link.3]
points = {{ A = [0, 0], B = [{l!r}, 0] }}
[[slider]]
pin = "B"
on = "frame.cylinder"
[driver]
crank = "2"
angle = "30 deg"
omega = {w!r}
epsilon = {e!r}
[assembly]
B = 1
"""
    )
    phis = np.radians(np.arange(0, 360, 7.5))
    solution = solve(scene, phis)
    theta = np.arcsin(-r * np.sin(phis) / l)
    w3 = -r * w * np.cos(phis) / (l * np.cos(theta))
    e3 = (r * (w**2 * np.sin(phis) - e * np.cos(phis)) + l * w3**2 * np.sin(theta)) / (l * np.cos(theta))
    v_B = -r * w * np.sin(phis) - l * w3 * np.sin(theta)
    a_B = -r * (w**2 * np.cos(phis) + e * np.sin(phis)) - l * e3 * np.sin(theta) - l * w3**2 * np.cos(theta)
    coupler, B = solution.links["3"], solution.points["B"]
    assert np.allclose(coupler.omega, w3, rtol=0, atol=EXACT_REL * np.max(np.abs(w3)))
    assert np.allclose(coupler.epsilon, e3, rtol=0, atol=EXACT_REL * np.max(np.abs(e3)))
    assert np.allclose(B.v.real, v_B, rtol=0, atol=EXACT_REL * np.max(np.abs(v_B)))
    assert np.allclose(B.a.real, a_B, rtol=0, atol=EXACT_REL * np.max(np.abs(a_B)))
    assert np.max(np.abs(B.r - (r * np.cos(phis) + l * np.cos(theta)))) <= EXACT_REL * l


@pytest.mark.parametrize(
    "name, old, new, points",
    [
        ("wedge", 'angle = "90 deg"', 'angle = "30 deg"', ["C"]),  # the follower's guide along the incline
        ("scotch-yoke", 'slot = { through = "Y", angle = "90 deg" }', 'slot = { through = "Y", angle = 0 }', ["Y", "R"]),  # slot ∥ rail
    ],
)
def test_allow_partial_gives_nan_not_infinite_rates_where_a_prp_or_rpp_has_parallel_guides(name, old, new, points):
    """PRP and RPP at a dead centre are not assembled: positions and rates are NaN, none of them ±∞."""
    text = example_path(name).read_text(encoding="utf-8")
    assert old in text
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no numpy warning may leak
        solution = solve(loads(text.replace(old, new)), np.linspace(0.0, 0.05, 3), allow_partial=True)
    assert not solution.valid.any()
    values = {f"{point}.{field}": getattr(solution.points[point], field) for point in points for field in ("r", "v", "a")}
    for slider, motion in solution.sliders.items():
        values.update({f"{slider}.{field}": getattr(motion, field) for field in ("s", "v_rel", "a_rel", "coriolis")})
    values.update({f"{group}.condition": value for group, value in solution.conditions.items()})
    for label, value in values.items():
        value = np.asarray(value)
        assert np.all(np.isnan(value.real)) and (np.isrealobj(value) or np.all(np.isnan(value.imag))), label
    for motion in list(solution.points.values()) + list(solution.origins.values()):
        for value in (motion.r, motion.v, motion.a):
            assert not np.isinf(value.real).any() and not np.isinf(value.imag).any()
    for motion in solution.links.values():
        assert not any(np.isinf(value).any() for value in (motion.phi, motion.omega, motion.epsilon))
