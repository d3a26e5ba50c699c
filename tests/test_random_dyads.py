"""Graphical against analytic on random mechanisms of every dyad kind (hypothesis).

Each mechanism is generated from an assembled configuration chosen first (so
it always assembles at the scene's position, on the branch the assembly hint
names), with moving and turning guides, offset lines and ε ≠ 0.  The two
methods share no kinematics code, so their agreement to round-off is the
check; configurations near a dead centre (|sin| between the construction
lines below 0.2, computed here from the chosen geometry) are skipped.
"""

import math

from hypothesis import assume, given, settings
from hypothesis import strategies as st

from plans.analytic import solve
from plans.graphical import construct
from plans.scene import loads
from plans.structure import find_structure

from dyad_scenes import crank, prp, rpp, rpr, rrp, rrr, sine, unit

#: agreement of the two methods, relative to the largest value of each kind
REL = 1e-9
#: configurations closer than this to a dead centre are left out
MIN_SINE = 0.2

lengths = st.floats(0.05, 1.0)
angles = st.floats(-math.pi, math.pi)
params = st.floats(-1.0, 1.0)
omegas = st.floats(0.5, 50.0) | st.floats(-50.0, -0.5)
epsilons = st.floats(-100.0, 100.0)


def _agree(text: str, kind: str) -> None:
    scene = loads(text)
    (group,) = find_structure(scene).groups
    assert group.kind == kind
    analytic = solve(scene)
    graphical = construct(scene)
    pairs = {"v": [], "a": [], "omega": [], "epsilon": []}
    for name, reading in graphical.points.items():
        pairs["v"].append((reading["v"], analytic.points[name].v[0]))
        pairs["a"].append((reading["a"], analytic.points[name].a[0]))
    for name, reading in graphical.links.items():
        pairs["omega"].append((reading["omega"], analytic.links[name].omega[0]))
        pairs["epsilon"].append((reading["epsilon"], analytic.links[name].epsilon[0]))
    for name, reading in graphical.sliders.items():
        motion = analytic.sliders[name]
        pairs["v"].append((reading["v_rel"], motion.v_rel[0]))
        pairs["a"].append((reading["a_rel"], motion.a_rel[0]))
        pairs["a"].append((reading["coriolis"], motion.coriolis[0]))
    scale = {kind_: max(abs(a) for _, a in values) for kind_, values in pairs.items()}
    scale["epsilon"] = max(scale["epsilon"], scale["omega"] ** 2)  # same units; all ε may be exactly 0
    for kind_, values in pairs.items():
        largest = scale[kind_]
        for g, a in values:
            assert abs(g - a) <= REL * largest, (kind_, g, a)


@settings(max_examples=40, deadline=None)
@given(r=lengths, phi=angles, c=st.complex_numbers(max_magnitude=1.0), d=st.complex_numbers(max_magnitude=1.0),
       omega=omegas, epsilon=epsilons)
def test_rrr(r, phi, c, d, omega, epsilon):
    a = r * unit(phi)
    assume(abs(c - a) > 0.05 and abs(c - d) > 0.05 and abs(d) > 0.05)
    assume(sine(c - a, c - d) > MIN_SINE)
    text = rrr(a, c, d) + crank(r, phi, omega, epsilon)
    _agree(text, "RRR")


@settings(max_examples=40, deadline=None)
@given(r=lengths, phi=angles, alpha=angles, offset=params, s=params, b=st.complex_numbers(max_magnitude=1.0),
       omega=omegas, epsilon=epsilons)
def test_rrp_on_a_turning_offset_guide(r, phi, alpha, offset, s, b, omega, epsilon):
    # crank 2 carries a slot at angle alpha, offset from the pivot; block 4 on it pinned at C to link 3 about frame B
    slot_origin = 0.3 * offset * 1j  # own coordinates of the slot's through point
    u = unit(phi + alpha)
    c = unit(phi) * slot_origin + s * u
    assume(abs(c - b) > 0.05 and abs(b) > 0.05)
    assume(sine(1j * (c - b), u) > MIN_SINE)
    text = rrp(b, c, slot_origin, alpha, r, phi, omega, epsilon)
    _agree(text, "RRP")


@settings(max_examples=40, deadline=None)
@given(r=lengths, phi=angles, theta=angles, offset=params, t=params, omega=omegas, epsilon=epsilons)
def test_rpr_with_an_offset_rod(r, phi, theta, offset, t, omega, epsilon):
    # rod 3 pinned at A, its line 0.2·offset from A; it slides through a sleeve pivoting at frame point E
    a = r * unit(phi)
    u = unit(theta)
    d = 0.2 * offset
    e = a + d * 1j * u + (0.3 + abs(t)) * u
    assume(abs(e) > 0.05)
    # construction lines: ⊥ AE (rotation about A) and ∥ rod
    assume(sine(1j * (e - a), u) > MIN_SINE)
    text = rpr(a, e, u, d) + crank(r, phi, omega, epsilon)
    _agree(text, "RPR")


@settings(max_examples=40, deadline=None)
@given(r=lengths, phi=angles, alpha=angles, gamma=angles, s=params, t=params, omega=omegas, epsilon=epsilons)
def test_prp_with_one_turning_guide(r, phi, alpha, gamma, s, t, omega, epsilon):
    # block 3 on the crank's slot, block 4 on a frame guide at angle gamma, pinned together at C
    u = unit(phi + alpha)
    w = unit(gamma)
    assume(sine(u, w) > MIN_SINE)
    c = 0.5 * s * u
    g = c - t * w
    text = prp(g, gamma, alpha, r, phi, omega, epsilon)
    _agree(text, "PRP")


@settings(max_examples=40, deadline=None)
@given(r=lengths, phi=angles, alpha=angles, beta=angles, gamma=angles, t=params, omega=omegas, epsilon=epsilons)
def test_rpp_yoke_at_any_angles(r, phi, alpha, beta, gamma, t, omega, epsilon):
    # block 3 on crank pin A slides in yoke 4's slot (angle alpha); the yoke's rail (angle beta) slides on a frame line
    a = r * unit(phi)
    yoke = gamma - beta
    slot = unit(yoke + alpha)
    assume(sine(slot, unit(gamma)) > MIN_SINE)
    y = a - 0.5 * t * slot
    text = rpp(y, gamma, alpha, beta) + crank(r, phi, omega, epsilon)
    _agree(text, "RPP")
