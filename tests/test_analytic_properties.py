"""Invariants of the solution on random mechanisms (hypothesis).

Random four-bars, offset slider-cranks and crank + slotted-lever linkages, at
random sizes from micro to large (a common scale factor) and random driver
rates, at positions away from dead centres.  Whatever the mechanism, the
solution must satisfy the loop equations and the theorems of plane kinematics:

* every loop closes (joint points at link lengths, sliders on their guides);
* v_BA ⟂ AB and |v_BA| = |ω|·AB; aⁿ_BA points from B to A with ω²·AB and
  aᵗ_BA = ε × AB;
* a block on a turning guide: v_A = v_A4 + v_rel (∥ guide), and
  a_A = a_A4 + aᵏ + aʳ with aᵏ = 2ω_g × v_rel ⟂ guide.
"""

import math

import numpy as np
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from plans.analytic import solve
from plans.scene import loads
from tolerances import INVARIANT_REL

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])

#: Positions closer to a dead centre than this (|sin| of the angle between the
#: construction lines) are not drawn: the invariants hold there too, but the
#: checks' own rounding grows like 1/sin.
MIN_SINE = 0.05

unit = st.floats(0.2, 1.0)
scale = st.sampled_from([1e-6, 1e-3, 1.0, 100.0])
angle = st.floats(-math.pi, math.pi)
rate = st.floats(0.1, 50.0).flatmap(lambda w: st.sampled_from([w, -w]))
sign = st.sampled_from([1, -1])


def perpendicular(a, b, scale):
    """|a · b| small beside the scale |a||b| of the product."""
    return abs((np.conj(a) * b).real) <= INVARIANT_REL * scale


def equal(a, b, scale):
    return abs(a - b) <= INVARIANT_REL * scale


def check_rigid_link(P, Q, link, length):
    """The theorems for two points P, Q of one link of length |PQ|."""
    r = Q.r[0] - P.r[0]
    w, e = link.omega[0], link.epsilon[0]
    v_rel = Q.v[0] - P.v[0]
    a_rel = Q.a[0] - P.a[0]
    v_scale = (abs(w) + 1) * length + abs(P.v[0]) + abs(Q.v[0])
    a_scale = (w * w + abs(e) + 1) * length + abs(P.a[0]) + abs(Q.a[0])
    assert equal(abs(r), length, length)  # the loop closes
    assert perpendicular(v_rel, r, v_scale * length)  # v_QP ⟂ PQ
    assert equal(abs(v_rel), abs(w) * length, v_scale)  # |v_QP| = |ω|·PQ
    towards_P = -r / length
    assert equal((np.conj(towards_P) * a_rel).real, w * w * length, a_scale)  # aⁿ: ω²·PQ, from Q to P
    assert equal((np.conj(1j * r / length) * a_rel).real, e * length, a_scale)  # aᵗ = ε × PQ


@st.composite
def four_bars(draw):
    k = draw(scale)
    crank, coupler, rocker, ground = (draw(unit) * k for _ in range(4))
    ground_angle, phi = draw(angle), draw(angle)
    O = 0j
    D = ground * complex(math.cos(ground_angle), math.sin(ground_angle))
    A = crank * complex(math.cos(phi), math.sin(phi))
    d = abs(D - A)
    assume(abs(coupler - rocker) < d < coupler + rocker)
    # |sin| of the angle at B between the coupler and the rocker (Heron)
    sine = math.sqrt(((coupler + rocker) ** 2 - d * d) * (d * d - (coupler - rocker) ** 2)) / (2 * coupler * rocker)
    assume(sine > MIN_SINE)
    branch = draw(sign)
    w, e = draw(rate), draw(rate)
    text = f"""
[frame]
points = {{ O = [{O.real!r}, {O.imag!r}], D = [{D.real!r}, {D.imag!r}] }}
[link.2]
points = {{ O = [0, 0], A = [{crank!r}, 0] }}
[link.3]
points = {{ A = [0, 0], B = [{coupler!r}, 0] }}
[link.4]
points = {{ D = [0, 0], B = [{rocker!r}, 0] }}
[driver]
crank = "2"
angle = "{phi!r} rad"
omega = {w!r}
epsilon = {e!r}
[assembly]
B = {branch}
"""
    return loads(text), (crank, coupler, rocker), branch


@SETTINGS
@given(four_bars())
def test_random_four_bars_close_their_loop_and_obey_the_rigid_body_theorems(case):
    scene, (crank, coupler, rocker), branch = case
    solution = solve(scene)
    O, A, B, D = (solution.points[p] for p in "OABD")
    check_rigid_link(O, A, solution.links["2"], crank)
    check_rigid_link(A, B, solution.links["3"], coupler)
    check_rigid_link(D, B, solution.links["4"], rocker)
    # the branch convention: +1 puts B to the left of A → D
    side = (np.conj(D.r[0] - A.r[0]) * (B.r[0] - A.r[0])).imag
    assert np.sign(side) == branch


@st.composite
def slider_cranks(draw):
    k = draw(scale)
    crank, coupler = draw(unit) * k, draw(unit) * k
    offset = draw(st.floats(-0.5, 0.5)) * k
    guide_angle, phi = draw(angle), draw(angle)
    u = complex(math.cos(guide_angle), math.sin(guide_angle))
    through = offset * 1j * u  # the guide passes at `offset` from O
    A = crank * complex(math.cos(phi), math.sin(phi))
    distance = abs((np.conj(u) * (A - through)).imag)
    assume(distance < coupler * math.sqrt(1 - MIN_SINE**2))
    w, e, branch = draw(rate), draw(rate), draw(sign)
    text = f"""
[frame]
points = {{ O = [0, 0] }}
lines = {{ cylinder = {{ through = [{through.real!r}, {through.imag!r}], angle = "{guide_angle!r} rad" }} }}
[link.2]
points = {{ O = [0, 0], A = [{crank!r}, 0] }}
[link.3]
points = {{ A = [0, 0], B = [{coupler!r}, 0] }}
[[slider]]
pin = "B"
on = "frame.cylinder"
[driver]
crank = "2"
angle = "{phi!r} rad"
omega = {w!r}
epsilon = {e!r}
[assembly]
B = {branch}
"""
    return loads(text), (crank, coupler), through, u, branch


@SETTINGS
@given(slider_cranks())
def test_random_slider_cranks_keep_the_pin_on_the_guide(case):
    scene, (crank, coupler), through, u, branch = case
    solution = solve(scene)
    O, A, B = (solution.points[p] for p in "OAB")
    check_rigid_link(O, A, solution.links["2"], crank)
    check_rigid_link(A, B, solution.links["3"], coupler)
    k = crank + coupler
    v_scale = abs(A.v[0]) + abs(B.v[0])
    a_scale = abs(A.a[0]) + abs(B.a[0])
    assert abs((np.conj(u) * (B.r[0] - through)).imag) <= INVARIANT_REL * k  # B on the guide line
    assert abs((np.conj(u) * B.v[0]).imag) <= INVARIANT_REL * v_scale  # v_B ∥ guide
    assert abs((np.conj(u) * B.a[0]).imag) <= INVARIANT_REL * a_scale  # a_B ∥ guide
    slider = solution.sliders["B"]
    assert equal(slider.v_rel[0] * u, B.v[0], v_scale)
    assert equal(slider.a_rel[0] * u, B.a[0], a_scale)
    assert slider.coriolis[0] == 0  # the frame does not turn
    # the branch convention: +1 takes the intersection further along u
    other = 2 * (np.conj(u) * (A.r[0] - through)).real - (np.conj(u) * (B.r[0] - through)).real
    assert branch * ((np.conj(u) * (B.r[0] - through)).real - other) >= -INVARIANT_REL * k


@st.composite
def slotted_levers(draw):
    k = draw(scale)
    crank, ground, lever = draw(unit) * k, draw(unit) * k, 2.5 * k
    assume(abs(crank - ground) > 0.1 * k)  # the block never passes through the lever's pivot
    ground_angle, phi = draw(angle), draw(angle)
    C = ground * complex(math.cos(ground_angle), math.sin(ground_angle))
    w, e, branch = draw(rate), draw(rate), draw(sign)
    text = f"""
[frame]
points = {{ O = [0, 0], C = [{C.real!r}, {C.imag!r}] }}
[link.2]
points = {{ O = [0, 0], A = [{crank!r}, 0] }}
[link.4]
points = {{ C = [0, 0], D = [{lever!r}, 0] }}
lines = {{ slot = {{ through = "C", angle = 0 }} }}
[[slider]]
pin = "A"
on = "4.slot"
name = "3"
[driver]
crank = "2"
angle = "{phi!r} rad"
omega = {w!r}
epsilon = {e!r}
[assembly]
D = {branch}
"""
    return loads(text), crank, branch


@SETTINGS
@given(slotted_levers())
def test_random_slotted_levers_obey_the_sliding_point_theorems(case):
    scene, crank, branch = case
    solution = solve(scene)
    A, C = solution.points["A"], solution.points["C"]
    lever, block = solution.links["4"], solution.links["3"]
    slider = solution.sliders["A"]
    u = np.exp(1j * lever.phi[0])  # the slot lies along the lever's x axis
    CA = A.r[0] - C.r[0]
    length = abs(CA) + crank
    v_scale = abs(A.v[0]) + abs(lever.omega[0]) * length
    a_scale = abs(A.a[0]) + (lever.omega[0] ** 2 + abs(lever.epsilon[0])) * length + abs(slider.coriolis[0])
    check_rigid_link(solution.points["O"], A, solution.links["2"], crank)
    assert abs((np.conj(u) * CA).imag) <= INVARIANT_REL * length  # A lies on the slot
    assert block.omega[0] == lever.omega[0] and block.epsilon[0] == lever.epsilon[0]
    # v_A = v_A4 + v_rel, the point A4 of the lever under A
    v_A4 = 1j * lever.omega[0] * CA
    assert equal(A.v[0], v_A4 + slider.v_rel[0] * u, v_scale)
    # a_A = a_A4 + aᵏ + aʳ, aᵏ = 2ω₄ × v_rel ⟂ slot
    a_A4 = (1j * lever.epsilon[0] - lever.omega[0] ** 2) * CA
    coriolis = 2j * lever.omega[0] * slider.v_rel[0] * u
    assert equal(slider.coriolis[0], coriolis, a_scale)
    assert perpendicular(slider.coriolis[0], u, a_scale)
    assert equal(A.a[0], a_A4 + coriolis + slider.a_rel[0] * u, a_scale)
    # the branch convention: +1 makes the slot point from C towards A
    assert np.sign((np.conj(u) * CA).real) == branch
