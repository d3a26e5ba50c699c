"""Velocities and accelerations equal finite differences of the position solution.

For every dyad kind, on fixed and on moving guides, the driver is moved along
its path in time, φ(t) = φ₀ + ωt + ½εt² (or s(t) = s₀ + vt + ½at²), the
POSITIONS are solved at t = ±h, ±2h, and the five-point central differences

    ẋ ≈ (x(−2h) − 8x(−h) + 8x(h) − x(2h)) / 12h
    ẍ ≈ (−x(−2h) + 16x(−h) − 30x(0) + 16x(h) − x(2h)) / 12h²

are compared with the solver's v, a, ω, ε, v_rel and a_rel at many positions
(those away from dead centres, condition number below FD_MAX_CONDITION).
See tests/tolerances.py for why the tolerances are what they are.
"""

import numpy as np
import pytest

from plans.analytic import solve
from plans.scene import Crank, example_path, load, loads
from tolerances import FD_MAX_CONDITION, FD_REL_ACCELERATION, FD_REL_VELOCITY

#: Scenes made for this test, one per dyad kind and guide situation.  Lines are
#: offset from the pins and at angles to the links wherever the kind allows.
CASES = {}
# RRP: block 4 (its own offset line) slides on an offset line of the turning crank
CASES["rrp-turning-guide"] = """
[frame]
points = { O = [0, 0], B = [0.3, 0.25] }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
lines = { rod = { through = [0.02, 0.03], angle = "25 deg" } }
[link.3]
points = { B = [0, 0], C = [0.48, 0.1] }
[link.4]
points = { C = [0, 0] }
lines = { shoe = { through = [0.01, -0.02], angle = "-15 deg" } }
[[prismatic]]
line = "4.shoe"
on = "2.rod"
[driver]
crank = "2"
angle = "40 deg"
omega = "7 rad/s"
epsilon = "3 rad/s^2"
"""
# RRP with the roles swapped: the crank's line slides in a slot of link 4
CASES["rrp-slot-on-link"] = """
[frame]
points = { O = [0, 0], B = [0.3, 0.25] }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
lines = { pin = { through = [0.02, 0.03], angle = "25 deg" } }
[link.3]
points = { B = [0, 0], C = [0.48, 0.1] }
[link.4]
points = { C = [0, 0] }
lines = { slot = { through = [0.01, -0.02], angle = "-15 deg" } }
[[prismatic]]
line = "2.pin"
on = "4.slot"
[driver]
crank = "2"
angle = "40 deg"
omega = "-7 rad/s"
epsilon = "3 rad/s^2"
[assembly]
C = -1
"""
# RPR: rod 5 on the crank pin carries an offset line; sleeve 6, swinging about E,
# slides on it with its own line offset and at 35° to its x axis
CASES["rpr-welded-offset-sleeve"] = """
[frame]
points = { O = [0, 0], E = [-0.25, -0.1] }
[link.2]
points = { O = [0, 0], A = [0.12, 0] }
[link.5]
points = { A = [0, 0], M = [0.5, 0.05] }
lines = { rod = { through = [0.03, 0.02], angle = "10 deg" } }
[link.6]
points = { E = [0, 0] }
lines = { sleeve = { through = [0.02, 0.04], angle = "35 deg" } }
[[prismatic]]
line = "6.sleeve"
on = "5.rod"
[driver]
crank = "2"
angle = "70 deg"
omega = "12 rad/s"
epsilon = "-4 rad/s^2"
"""
# RPR the other way round: the sleeve carries the guide line, the rod slides
CASES["rpr-rod-in-welded-sleeve"] = """
[frame]
points = { O = [0, 0], E = [-0.25, -0.1] }
[link.2]
points = { O = [0, 0], A = [0.12, 0] }
[link.5]
points = { A = [0, 0], M = [0.5, 0.05] }
lines = { rod = { through = [0.03, 0.02], angle = "10 deg" } }
[link.6]
points = { E = [0, 0], F = [0.05, 0.1] }
lines = { sleeve = { through = [0.02, 0.04], angle = "35 deg" } }
[[prismatic]]
line = "5.rod"
on = "6.sleeve"
[driver]
crank = "2"
angle = "70 deg"
omega = "12 rad/s"
epsilon = "-4 rad/s^2"
[assembly]
M = [-0.6, -0.2]
"""
# PRP: link 3 slides on a line of the turning crank, link 4 on a frame rail
CASES["prp-moving-guide"] = """
[frame]
points = { O = [0, 0] }
lines = { rail = { through = [0.1, 0.3], angle = "-20 deg" } }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
lines = { rod = { through = [0.0, 0.02], angle = "10 deg" } }
[link.3]
points = { C = [0, 0], K = [0.03, 0.01] }
lines = { bore = { through = [0.01, 0.0], angle = "5 deg" } }
[link.4]
points = { C = [0, 0] }
lines = { foot = { through = [0.0, -0.02], angle = "0 deg" } }
[[prismatic]]
line = "3.bore"
on = "2.rod"
[[prismatic]]
line = "4.foot"
on = "frame.rail"
[driver]
crank = "2"
angle = "60 deg"
omega = "5 rad/s"
epsilon = "2 rad/s^2"
"""
# RPP: the Scotch yoke with an offset rail
CASES["rpp-scotch-yoke"] = """
[frame]
points = { O = [0, 0] }
lines = { x = { through = [0, -0.05], angle = 0 } }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
[link.4]
points = { Y = [0.2, 0] }
lines = { slot = { through = "Y", angle = "90 deg" }, rail = { through = [0.2, -0.05], angle = 0 } }
[[slider]]
pin = "A"
on = "4.slot"
name = "3"
[[prismatic]]
line = "4.rail"
on = "frame.x"
[driver]
crank = "2"
angle = "30 deg"
omega = "10 rad/s"
epsilon = "6 rad/s^2"
"""
# RPP on a turning guide: yoke 4 slides on the crank's arm, link 3 pinned at
# the frame point B slides in the yoke
CASES["rpp-turning-guide"] = """
[frame]
points = { O = [0, 0], B = [0.25, 0.15] }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
lines = { arm = { through = [0.0, 0.03], angle = "15 deg" } }
[link.3]
points = { B = [0, 0] }
lines = { tongue = { through = [0.01, 0.01], angle = "80 deg" } }
[link.4]
points = { Y = [0.05, 0.05] }
lines = { slot = { through = [0.02, 0.0], angle = "100 deg" }, rail = { through = [0.0, -0.01], angle = "-5 deg" } }
[[prismatic]]
line = "3.tongue"
on = "4.slot"
[[prismatic]]
line = "4.rail"
on = "2.arm"
[driver]
crank = "2"
angle = "20 deg"
omega = "-6 rad/s"
epsilon = "9 rad/s^2"
"""
# a linear driver with an arm at an angle and a non-zero acceleration, then RRR
CASES["linear-driver-arm-rrr"] = """
[frame]
points = { D = [0.35, 0.3] }
lines = { track = { through = [0, 0.05], angle = "20 deg" } }
[link.2]
points = { P = [0, 0], A = [0.1, 0.08] }
[link.3]
points = { A = [0, 0], B = [0.3, 0], M = [0.1, -0.05] }
[link.4]
points = { D = [0, 0], B = [0.25, 0] }
[driver]
slider = "2"
on = "frame.track"
point = "P"
position = "20 mm"
velocity = "0.8 m/s"
acceleration = "-3 m/s^2"
[assembly]
B = [0.3, 0.0]
"""

#: Bundled examples, each covering a situation too.
EXAMPLES = ["ladder", "slider-crank", "four-bar", "six-bar", "quick-return", "linear-arm", "wedge", "scotch-yoke"]

#: Five-point stencils for the first and second derivative (offsets in steps of h).
OFFSETS = (-2, -1, 1, 2)
FIRST = {-2: 1 / 12, -1: -8 / 12, 1: 8 / 12, 2: -1 / 12}
SECOND = {-2: -1 / 12, -1: 16 / 12, 1: 16 / 12, 2: -1 / 12}  # and −30/12 at 0, which the differences x(t) − x(0) absorb


def wrapped(angle):
    return np.angle(np.exp(1j * angle))


def sweep_and_step(scene):
    """Positions to test, the driver's rate and acceleration, and the time step h."""
    driver = scene.driver
    if isinstance(driver, Crank):
        rate, acceleration = driver.omega, driver.epsilon
        positions = driver.phi + np.linspace(-np.pi, np.pi, 61)
        h = 1e-3 / abs(rate)  # the crank turns 1e-3 rad per step
    else:
        rate, acceleration = driver.velocity, driver.acceleration
        positions = driver.s + np.linspace(-0.05, 0.05, 41)
        h = 1e-3 * 0.1 / abs(rate)  # the slide moves 0.1 mm per step
    return positions, rate, acceleration, h


def scene_of(name):
    return loads(CASES[name], source=name) if name in CASES else load(example_path(name))


def differences(scene):
    """(solution at the positions, solutions at t = k·h for k in OFFSETS, h)."""
    positions, rate, acceleration, h = sweep_and_step(scene)
    probe = solve(scene, positions, allow_partial=True)
    calm = probe.valid.copy()
    for condition in probe.conditions.values():
        calm &= condition < FD_MAX_CONDITION
    positions = positions[calm]
    assert len(positions) >= 10, "too few positions away from dead centres to test"
    here = solve(scene, positions)
    moved = {k: solve(scene, positions + rate * k * h + 0.5 * acceleration * (k * h) ** 2) for k in OFFSETS}
    return here, moved, h


def assert_close(got, want, scale, rel, what):
    error = np.max(np.abs(got - want)) / scale
    assert error <= rel, f"{what}: {error:.2e} > {rel:.0e}"


@pytest.mark.parametrize("name", list(CASES) + EXAMPLES)
def test_velocities_and_accelerations_are_derivatives_of_positions(name):
    scene = scene_of(name)
    here, moved, h = differences(scene)

    for point, motion in here.points.items():
        step = {k: moved[k].points[point].r - motion.r for k in OFFSETS}
        v = sum(FIRST[k] * step[k] for k in OFFSETS) / h
        a = sum(SECOND[k] * step[k] for k in OFFSETS) / h**2
        assert_close(v, motion.v, np.max(np.abs(motion.v)) or 1.0, FD_REL_VELOCITY, f"v_{point}")
        assert_close(a, motion.a, np.max(np.abs(motion.a)) or 1.0, FD_REL_ACCELERATION, f"a_{point}")

    omega_scale = max(np.max(np.abs(m.omega)) for m in here.links.values()) or 1.0
    for link, motion in here.links.items():
        step = {k: wrapped(moved[k].links[link].phi - motion.phi) for k in OFFSETS}
        omega = sum(FIRST[k] * step[k] for k in OFFSETS) / h
        epsilon = sum(SECOND[k] * step[k] for k in OFFSETS) / h**2
        epsilon_scale = np.max(np.abs(motion.epsilon)) + omega_scale**2
        assert_close(omega, motion.omega, omega_scale, FD_REL_VELOCITY, f"ω{link}")
        assert_close(epsilon, motion.epsilon, epsilon_scale, FD_REL_ACCELERATION, f"ε{link}")

    for pair, motion in here.sliders.items():
        step = {k: moved[k].sliders[pair].s - motion.s for k in OFFSETS}
        v_rel = sum(FIRST[k] * step[k] for k in OFFSETS) / h
        a_rel = sum(SECOND[k] * step[k] for k in OFFSETS) / h**2
        assert_close(v_rel, motion.v_rel, np.max(np.abs(motion.v_rel)) or 1.0, FD_REL_VELOCITY, f"v_rel {pair}")
        assert_close(a_rel, motion.a_rel, np.max(np.abs(motion.a_rel)) or 1.0, FD_REL_ACCELERATION, f"a_rel {pair}")


@pytest.mark.parametrize("name", ["rrp-turning-guide", "rpr-welded-offset-sleeve", "prp-moving-guide", "rpp-turning-guide", "quick-return"])
def test_coriolis_appears_on_turning_guides_and_is_2_omega_v_rel_turned(name):
    """aᵏ = 2ω_g × v_rel: perpendicular to the guide, magnitude 2|ω_g||v_rel|, non-zero here."""
    scene = scene_of(name)
    solution = solve(scene, sweep_and_step(scene)[0], allow_partial=True)
    turning = [p for p in scene.prismatics if scene.bodies[p.guide].name != "frame"]
    assert turning
    for pair in turning:
        motion = solution.sliders[pair.name]
        guide = solution.links[pair.guide]
        ok = solution.valid
        u_g = np.exp(1j * (guide.phi + scene.bodies[pair.guide].lines[pair.guide_line].angle))[ok]
        coriolis = motion.coriolis[ok]
        scale = np.max(np.abs(coriolis))
        assert scale > 0
        assert np.max(np.abs((np.conj(u_g) * coriolis).real)) <= 1e-12 * scale  # ⟂ guide
        assert np.allclose(np.abs(coriolis), 2 * np.abs(guide.omega[ok] * motion.v_rel[ok]), rtol=1e-12, atol=1e-12 * scale)
        # turned by +90° in the sense of ω_g: coriolis / (v_rel·u_g) = 2iω_g
        moving = np.abs(motion.v_rel[ok]) > 1e-9
        ratio = coriolis[moving] / (motion.v_rel[ok][moving] * u_g[moving])
        assert np.allclose(ratio, 2j * guide.omega[ok][moving], rtol=1e-12)
