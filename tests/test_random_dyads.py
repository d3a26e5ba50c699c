"""Graphical against analytic on random mechanisms of every dyad kind (hypothesis).

Each mechanism is generated from an assembled configuration chosen first (so
it always assembles at the scene's position, on the branch the assembly hint
names), with moving and turning guides, offset lines and ε ≠ 0.  The two
methods share no kinematics code, so their agreement to round-off is the
check; configurations near a dead centre (|sin| between the construction
lines below 0.2, computed here from the chosen geometry) are skipped.
"""

import cmath
import math

from hypothesis import assume, given, settings
from hypothesis import strategies as st

from plans.analytic import solve
from plans.graphical import construct
from plans.scene import loads
from plans.structure import find_structure

#: agreement of the two methods, relative to the largest value of each kind
REL = 1e-9
#: configurations closer than this to a dead centre are left out
MIN_SINE = 0.2

lengths = st.floats(0.05, 1.0)
angles = st.floats(-math.pi, math.pi)
params = st.floats(-1.0, 1.0)
omegas = st.floats(0.5, 50.0) | st.floats(-50.0, -0.5)
epsilons = st.floats(-100.0, 100.0)


def _xy(z: complex) -> str:
    return f"[{z.real!r}, {z.imag!r}]"


def _crank(r: float, phi: float, omega: float, epsilon: float, extra_lines: str = "") -> str:
    return f"""
[link.2]
points = {{ O = [0, 0], A = [{r!r}, 0] }}
{extra_lines}
[driver]
crank = "2"
angle = "{math.degrees(phi)!r} deg"
omega = {omega!r}
epsilon = {epsilon!r}
"""


def _sine(u: complex, w: complex) -> float:
    return abs((u.conjugate() * w).imag) / (abs(u) * abs(w))


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
    a = r * cmath.exp(1j * phi)
    assume(abs(c - a) > 0.05 and abs(c - d) > 0.05 and abs(d) > 0.05)
    assume(_sine(c - a, c - d) > MIN_SINE)
    text = f"""
[frame]
points = {{ O = [0, 0], D = {_xy(d)} }}
[link.3]
points = {{ A = [0, 0], C = [{abs(c - a)!r}, 0], M = [{0.3 * abs(c - a)!r}, 0.1] }}
[link.4]
points = {{ D = [0, 0], C = [{abs(c - d)!r}, 0] }}
[assembly]
C = {_xy(c)}
""" + _crank(r, phi, omega, epsilon)
    _agree(text, "RRR")


@settings(max_examples=40, deadline=None)
@given(r=lengths, phi=angles, alpha=angles, offset=params, s=params, b=st.complex_numbers(max_magnitude=1.0),
       omega=omegas, epsilon=epsilons)
def test_rrp_on_a_turning_offset_guide(r, phi, alpha, offset, s, b, omega, epsilon):
    # crank 2 carries a slot at angle alpha, offset from the pivot; block 4 on it pinned at C to link 3 about frame B
    slot_origin = 0.3 * offset * 1j  # own coordinates of the slot's through point
    u = cmath.exp(1j * (phi + alpha))
    c = cmath.exp(1j * phi) * slot_origin + s * u
    assume(abs(c - b) > 0.05 and abs(b) > 0.05)
    assume(_sine(1j * (c - b), u) > MIN_SINE)
    text = f"""
[frame]
points = {{ O = [0, 0], B = {_xy(b)} }}
[link.3]
points = {{ B = [0, 0], C = [{abs(c - b)!r}, 0] }}
[[slider]]
pin = "C"
on = "2.slot"
[assembly]
C = {_xy(c)}
""" + _crank(r, phi, omega, epsilon, f"lines = {{ slot = {{ through = {_xy(slot_origin)}, angle = \"{math.degrees(alpha)!r} deg\" }} }}")
    _agree(text, "RRP")


@settings(max_examples=40, deadline=None)
@given(r=lengths, phi=angles, theta=angles, offset=params, t=params, omega=omegas, epsilon=epsilons)
def test_rpr_with_an_offset_rod(r, phi, theta, offset, t, omega, epsilon):
    # rod 3 pinned at A, its line 0.2·offset from A; it slides through a sleeve pivoting at frame point E
    a = r * cmath.exp(1j * phi)
    u = cmath.exp(1j * theta)
    d = 0.2 * offset
    e = a + d * 1j * u + (0.3 + abs(t)) * u
    assume(abs(e) > 0.05)
    # construction lines: ⊥ AE (rotation about A) and ∥ rod
    assume(_sine(1j * (e - a), u) > MIN_SINE)
    text = f"""
[frame]
points = {{ O = [0, 0], E = {_xy(e)} }}
[link.3]
points = {{ A = [0, 0], M = [1.2, 0] }}
lines = {{ rod = {{ through = [0, {d!r}], angle = 0 }} }}
[[slider]]
pin = "E"
on = "3.rod"
[assembly]
M = {_xy(a + 1.2 * u)}
""" + _crank(r, phi, omega, epsilon)
    _agree(text, "RPR")


@settings(max_examples=40, deadline=None)
@given(r=lengths, phi=angles, alpha=angles, gamma=angles, s=params, t=params, omega=omegas, epsilon=epsilons)
def test_prp_with_one_turning_guide(r, phi, alpha, gamma, s, t, omega, epsilon):
    # block 3 on the crank's slot, block 4 on a frame guide at angle gamma, pinned together at C
    u = cmath.exp(1j * (phi + alpha))
    w = cmath.exp(1j * gamma)
    assume(_sine(u, w) > MIN_SINE)
    c = 0.5 * s * u
    g = c - t * w
    text = f"""
[frame]
points = {{ O = [0, 0] }}
lines = {{ guide = {{ through = {_xy(g)}, angle = "{math.degrees(gamma)!r} deg" }} }}
[[slider]]
pin = "C"
on = "2.slot"
name = "3"
[[slider]]
pin = "C"
on = "frame.guide"
name = "4"
""" + _crank(r, phi, omega, epsilon, f"lines = {{ slot = {{ through = \"O\", angle = \"{math.degrees(alpha)!r} deg\" }} }}")
    _agree(text, "PRP")


@settings(max_examples=40, deadline=None)
@given(r=lengths, phi=angles, alpha=angles, beta=angles, gamma=angles, t=params, omega=omegas, epsilon=epsilons)
def test_rpp_yoke_at_any_angles(r, phi, alpha, beta, gamma, t, omega, epsilon):
    # block 3 on crank pin A slides in yoke 4's slot (angle alpha); the yoke's rail (angle beta) slides on a frame line
    a = r * cmath.exp(1j * phi)
    yoke = gamma - beta
    slot = cmath.exp(1j * (yoke + alpha))
    assume(_sine(slot, cmath.exp(1j * gamma)) > MIN_SINE)
    y = a - 0.5 * t * slot
    text = f"""
[frame]
points = {{ O = [0, 0] }}
lines = {{ rail = {{ through = {_xy(y)}, angle = "{math.degrees(gamma)!r} deg" }} }}
[link.4]
points = {{ Y = [0, 0], R = [0.3, 0.1] }}
lines = {{ slot = {{ through = "Y", angle = "{math.degrees(alpha)!r} deg" }}, rail = {{ through = "Y", angle = "{math.degrees(beta)!r} deg" }} }}
[[slider]]
pin = "A"
on = "4.slot"
name = "3"
[[prismatic]]
line = "4.rail"
on = "frame.rail"
""" + _crank(r, phi, omega, epsilon)
    _agree(text, "RPP")
