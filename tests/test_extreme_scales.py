"""Extreme scales: relative accuracy does not depend on the unit system.

The same mechanisms at lengths from 1e-6 m to 1e3 m, driven at ω from 1e-3 to
1e5 rad/s (ε = ω²/2, so that tangential and normal accelerations are of one
size), with crank-to-coupler ratios from 1e-4 to 0.3, against independent
50-digit mpmath closed forms:

* an offset slider-crank (RRP): sin θ₃ = (e − r sin φ)/l, x_B = r cos φ + l cos θ₃
  and its derivatives worked by hand;
* a four-bar (RRR): the rocker angle from the law of cosines in triangle ADB,
  the rates from the differentiated loop solved by mpmath's linear solver.

Every velocity, acceleration, ω and ε, analytic and read off the graphical
plans, agrees within ERROR_MARGIN × the expected relative error the program
states (4·ε_mach·cond², plans.limits) — here cond is 1 … 3, so the bound is
1e-14 … 8e-14; measured at most 3.3e-15.  The automatic scale factors still
draw the mechanism and both plans 60–120 mm large at both extremes.
"""

import math

import mpmath as mp
import numpy as np
import pytest

from plans.analytic import solve
from plans.graphical import construct
from plans.limits import ERROR_MARGIN, expected_rel_error
from plans.scene import loads

LENGTHS = [1e-6, 1e-3, 1.0, 1e3]
OMEGAS = [1e-3, 1.0, 1e5]
RATIOS = [1e-4, 1e-2, 0.3]
ANGLES_DEG = [40.0, 135.0, 250.0]
#: the drawn size of the largest figure of a plan, mm (plans.graphical.scales), with round-off slack
WINDOW = (60.0 * (1 - 1e-9), 120.0 * (1 + 1e-9))


def slider_crank(L, w, ratio, angle_deg=135.0):
    r, e = ratio * L, 0.2 * ratio * L
    text = f"""
[frame]
points = {{ O = [0, 0] }}
lines = {{ cylinder = {{ through = [0, {e!r}], angle = 0 }} }}
[link.2]
points = {{ O = [0, 0], A = [{r!r}, 0] }}
[link.3]
points = {{ A = [0, 0], B = [{L!r}, 0] }}
[[slider]]
pin = "B"
on = "frame.cylinder"
[driver]
crank = "2"
angle = "{angle_deg!r} deg"
omega = {w!r}
epsilon = {0.5 * w * w!r}
[assembly]
B = 1
"""
    return loads(text), (r, L, e)


def slider_crank_reference(r, l, e, w, phi):
    """B, v_B, a_B, ω₃, ε₃ of the offset slider-crank, 50 digits; phi a double taken exactly."""
    mp.mp.dps = 50
    r, l, e, w, phi = (mp.mpf(x) for x in (r, l, e, w, phi))
    eps = w * w / 2
    th = mp.asin((e - r * mp.sin(phi)) / l)
    xB = r * mp.cos(phi) + l * mp.cos(th)
    w3 = -r * w * mp.cos(phi) / (l * mp.cos(th))
    e3 = (r * w**2 * mp.sin(phi) - r * eps * mp.cos(phi) + l * w3**2 * mp.sin(th)) / (l * mp.cos(th))
    vB = -r * w * mp.sin(phi) - l * w3 * mp.sin(th)
    aB = -r * eps * mp.sin(phi) - r * w**2 * mp.cos(phi) - l * e3 * mp.sin(th) - l * w3**2 * mp.cos(th)
    return {"B.r": mp.mpc(xB, e), "B.v": mp.mpc(vB, 0), "B.a": mp.mpc(aB, 0), "3.omega": w3, "3.epsilon": e3}


def four_bar(L, w, ratio, angle_deg=135.0):
    r, d = ratio * L, 1.2 * L
    text = f"""
[frame]
points = {{ O = [0, 0], D = [{d!r}, 0] }}
[link.2]
points = {{ O = [0, 0], A = [{r!r}, 0] }}
[link.3]
points = {{ A = [0, 0], B = [{L!r}, 0] }}
[link.4]
points = {{ D = [0, 0], B = [{L!r}, 0] }}
[driver]
crank = "2"
angle = "{angle_deg!r} deg"
omega = {w!r}
epsilon = {0.5 * w * w!r}
[assembly]
B = 1
"""
    return loads(text), (r, L, L, d)


def four_bar_reference(r2, l3, l4, xd, w2, phi):
    """B, v_B, a_B, ω₃, ω₄, ε₃, ε₄ of the four-bar O–A–B–D, branch B left of A → D, 50 digits."""
    mp.mp.dps = 50
    r2, l3, l4, xd, w2, phi = (mp.mpf(x) for x in (r2, l3, l4, xd, w2, phi))
    e2 = w2 * w2 / 2
    A, D = r2 * mp.expj(phi), mp.mpc(xd, 0)
    d = abs(A - D)
    gamma = mp.acos((l4**2 + d**2 - l3**2) / (2 * l4 * d))
    for theta4 in (mp.arg(A - D) + gamma, mp.arg(A - D) - gamma):
        B = D + l4 * mp.expj(theta4)
        if mp.im(mp.conj(D - A) * (B - A)) > 0:
            break
    theta3 = mp.arg(B - A)
    M = mp.matrix([[-l3 * mp.sin(theta3), l4 * mp.sin(theta4)], [l3 * mp.cos(theta3), -l4 * mp.cos(theta4)]])
    w3, w4 = mp.lu_solve(M, r2 * w2 * mp.matrix([mp.sin(phi), -mp.cos(phi)]))
    known = 1j * r2 * e2 * mp.expj(phi) - r2 * w2**2 * mp.expj(phi) - l3 * w3**2 * mp.expj(theta3) + l4 * w4**2 * mp.expj(theta4)
    e3, e4 = mp.lu_solve(M, mp.matrix([-mp.re(known), -mp.im(known)]))
    vB = 1j * w2 * A + 1j * w3 * (B - A)
    aB = (1j * e2 - w2**2) * A + (1j * e3 - w3**2) * (B - A)
    return {"B.r": B, "B.v": vB, "B.a": aB, "3.omega": w3, "4.omega": w4, "3.epsilon": e3, "4.epsilon": e4}


def rel_error(got, want) -> float:
    return float(abs(mp.mpc(complex(got)) - want) / abs(want))


def analytic_values(solution, k):
    out = {f"B.{q}": getattr(solution.points["B"], q)[k] for q in "rva"}
    for link in solution.links:
        if link in ("3", "4"):
            out[f"{link}.omega"] = solution.links[link].omega[k]
            out[f"{link}.epsilon"] = solution.links[link].epsilon[k]
    return out


def graphical_values(g):
    out = {"B.r": g.positions["B"], "B.v": g.points["B"]["v"], "B.a": g.points["B"]["a"]}
    for link in ("3", "4"):
        if link in g.links and not g.scene.bodies[link].block:
            out[f"{link}.omega"] = g.links[link]["omega"]
            out[f"{link}.epsilon"] = g.links[link]["epsilon"]
    return out


CASES = [(L, w, ratio) for L in LENGTHS for w in OMEGAS for ratio in RATIOS]


def _check(values, ref, condition, what):
    bound = ERROR_MARGIN * expected_rel_error(condition)
    for key, want in ref.items():
        error = rel_error(values[key], want)
        assert error <= bound, (what, key, error, bound)


@pytest.mark.parametrize("L, w, ratio", CASES)
def test_slider_crank_agrees_with_mpmath_at_any_scale(L, w, ratio):
    scene, (r, l, e) = slider_crank(L, w, ratio)
    phis = np.radians(ANGLES_DEG)
    solution = solve(scene, phis)
    for k, phi in enumerate(phis):
        ref = slider_crank_reference(r, l, e, w, phi)
        _check(analytic_values(solution, k), ref, float(solution.conditions["RRP(3,4)"][k]), ("analytic", phi))
    g = construct(scene)
    ref = slider_crank_reference(r, l, e, w, scene.driver.phi)
    _check(graphical_values(g), ref, g.conditions["RRP(3,4)"], "graphical")


@pytest.mark.parametrize("L, w, ratio", CASES)
def test_four_bar_agrees_with_mpmath_at_any_scale(L, w, ratio):
    scene, (r, l3, l4, d) = four_bar(L, w, ratio)
    phis = np.radians(ANGLES_DEG)
    solution = solve(scene, phis)
    for k, phi in enumerate(phis):
        ref = four_bar_reference(r, l3, l4, d, w, phi)
        _check(analytic_values(solution, k), ref, float(solution.conditions["RRR(3,4)"][k]), ("analytic", phi))
    g = construct(scene)
    ref = four_bar_reference(r, l3, l4, d, w, scene.driver.phi)
    _check(graphical_values(g), ref, g.conditions["RRR(3,4)"], "graphical")


@pytest.mark.parametrize("L, w", [(1e-6, 1e5), (1e3, 1e-3), (1e-6, 1e-3), (1e3, 1e5)])
@pytest.mark.parametrize("make", [slider_crank, four_bar])
def test_automatic_scales_give_readable_plans_at_both_extremes(make, L, w):
    scene, _ = make(L, w, 0.3)
    g = construct(scene)
    xs = [z.real for z in g.positions.values()]
    ys = [z.imag for z in g.positions.values()]
    drawn = max(max(xs) - min(xs), max(ys) - min(ys)) / g.scales["k_l"]
    assert WINDOW[0] <= drawn <= WINDOW[1]
    for plan in (g.velocity_plan, g.acceleration_plan):
        largest = max(v.length for v in plan.vectors)
        assert WINDOW[0] <= largest <= WINDOW[1], (plan.kind, largest, plan.scale)
        assert math.isfinite(plan.scale) and plan.scale > 0
    # the plans scale with the mechanism: k_v ∝ L·ω, k_a ∝ L·ω², up to the choice of a round value
    assert 0.5 * L * w / g.scales["k_v"] > 1 and L * w / g.scales["k_v"] < 1e3
