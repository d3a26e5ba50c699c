"""The analytic kinetostatics (issue 22) against domain.md §11 and checks written here.

* the worked example of domain.md §11, to 1e-9 (or half a unit of the last
  digit printed there, whichever is larger: the angles are printed to 1e-6°);
* Newton–Euler per link, summed here with numpy from the scene's data and
  the reactions the code returns: every moving link in equilibrium under its
  loads (computed here: m·g, −m·a_S, −J·ε, the scene's forces) and the
  reactions acting on it (+R on the body it acts on, −R on the other);
* the virtual-work balance with velocities and accelerations from finite
  differences in time of the solved positions (no velocity or acceleration of
  the solver used): M_b·ω + Σ F·v + Σ M·ω = 0.
"""

import math

import numpy as np
import pytest

import plans
from plans.analytic import solve
from plans.errors import PlansError, SceneError
from plans.forces import solve_forces
from plans.forces.analytic import load_power
from plans.scene import FRAME, Crank, example_names, example_path, load, loads

LOADED = example_names(loads=True)

# domain.md §11, as printed there
M_B = 620.218316
R12 = (9646.41888, 199.942051)
R23 = (8353.55006, 192.098702)
R34 = (5461.32544, 157.194749)
GUIDE = -2077.57014
EPSILON_3 = 6511.74403
A_S3 = complex(-1044.53339, -1299.03811)
A_B = -883.600174


def close(value, printed, decimals):
    """|value − printed| within 1e-9 relative, or half a unit of the printed last digit."""
    return abs(value - printed) <= max(1e-9 * abs(printed), 0.5 * 10.0**-decimals)


def test_the_worked_example_of_domain_md_section_11():
    result = plans.forces(load(example_path("slider-crank-loads")))
    kin = result.kinematics
    assert close(kin.links["3"].epsilon[0], EPSILON_3, 5)
    assert close(kin.motion_of("3", 0.1).a[0].real, A_S3.real, 5) and close(kin.motion_of("3", 0.1).a[0].imag, A_S3.imag, 5)
    assert close(kin.points["B"].a[0].real, A_B, 6)
    assert result.balancing_kind == "moment"
    assert close(result.balancing[0], M_B, 6)
    for label, (magnitude, degrees) in (("R_12", R12), ("R_23", R23), ("R_34", R34)):
        force = complex(result.reactions[label].force[0])
        assert close(abs(force), magnitude, 5), label
        assert close(math.degrees(math.atan2(force.imag, force.real)) % 360, degrees, 6), label
    guide = result.reactions["R_14"]
    assert guide.kind == "P" and guide.by == FRAME and guide.on == "4"
    assert close(guide.normal_force[0], GUIDE, 5)
    assert guide.normal[0] == pytest.approx(1j, abs=1e-15)  # +y
    assert guide.point[0] == pytest.approx(kin.points["B"].r[0], abs=1e-12)  # through B: every load on the block acts at B
    # which body on which, at which point
    assert [(r.by, r.on, r.joint) for r in result.reactions.values()] == [(FRAME, "2", "O"), ("2", "3", "A"), ("3", "4", "B"), (FRAME, "4", "B")]


# --- Newton–Euler per link, summed here ------------------------------------------------


def cross(a, b):
    return a.real * b.imag - a.imag * b.real


def loads_here(scene, kin):
    """Per body: list of (force, point) and list of couples, from the scene's data and the kinematics."""
    forces = {name: [] for name in scene.links}
    couples = {name: [] for name in scene.links}
    g = 0j
    if scene.gravity is not None:
        g = scene.gravity.g * complex(math.cos(scene.gravity.angle), math.sin(scene.gravity.angle))
    for name, mass in scene.masses.items():
        S = kin.motion_of(name, mass.centre)
        forces[name].append((mass.mass * g + 0 * S.r, S.r))
        forces[name].append((-mass.mass * S.a, S.r))
        couples[name].append(-mass.inertia * kin.links[name].epsilon)
    for item in scene.loads:
        if item.kind == "moment":
            couples[item.body].append(item.moment + 0 * kin.driver)
            continue
        P = kin.motion_of(item.body, item.at)
        if item.kind == "force":
            f = item.force + 0 * P.r
        else:
            f = -item.magnitude * P.v / np.abs(P.v)
        if item.working is not None:
            f = np.where((np.conj(item.working) * P.v).real > 0, f, 0)
        forces[item.body].append((f, P.r))
    return forces, couples


def sweep_positions(scene, n):
    if isinstance(scene.driver, Crank):
        return scene.driver.phi + np.linspace(0, 2 * np.pi, n, endpoint=False)
    lo, hi = scene.driver.stroke
    return np.linspace(lo, hi, n)


@pytest.mark.parametrize("name", LOADED)
def test_every_link_is_in_equilibrium_newton_euler_summed_here(name):
    scene = load(example_path(name))
    result = solve_forces(scene, sweep_positions(scene, 24), allow_partial=True)
    kin = result.kinematics
    ok = np.asarray(kin.valid)
    assert ok.sum() >= 6  # rocker-limit: its crank turns through a part of the circle only
    forces, couples = loads_here(scene, kin)
    for reaction in result.reactions.values():
        point = np.where(np.isfinite(reaction.point), reaction.point, 0)  # N = 0: no force, its couple below
        forces[reaction.on].append((reaction.force, point))
        if reaction.by != FRAME:
            forces[reaction.by].append((-reaction.force, point))
        if reaction.kind == "P":  # where N = 0 the pair carries its couple alone
            alone = np.where(np.isfinite(reaction.point), 0.0, reaction.couple)
            couples[reaction.on].append(alone)
            if reaction.by != FRAME:
                couples[reaction.by].append(-alone)
    driver = scene.driver
    if isinstance(driver, Crank):
        couples[driver.link].append(result.balancing)
    else:
        u = np.exp(1j * scene.frame.lines[driver.guide].angle)
        forces[driver.link].append((result.balancing * u, kin.points[driver.point].r))
    scale_f = max(np.nanmax(np.abs(f)) for fs in forces.values() for f, _ in fs)
    size = max(np.nanmax(np.abs(r)) for fs in forces.values() for _, r in fs) + 0.1
    for body in scene.links:
        total_f = sum(f for f, _ in forces[body]) + 0 * kin.driver
        total_m = sum(cross(r, f) for f, r in forces[body]) + sum(couples[body]) + 0 * kin.driver
        assert np.max(np.abs(total_f[ok])) <= 1e-11 * scale_f, (name, body)
        assert np.max(np.abs(total_m[ok])) <= 1e-11 * scale_f * size, (name, body)


# --- virtual work with finite differences in time -------------------------------------------------


def motion_by_differences(scene, h):
    """(r, v, a) of a body point and (ω, ε) of a body by five-point differences in time of solved positions."""
    driver = scene.driver
    if isinstance(driver, Crank):
        x0, x1, x2 = driver.phi, driver.omega, driver.epsilon
    else:
        x0, x1, x2 = driver.s, driver.velocity, driver.acceleration
    times = np.array([-2, -1, 0, 1, 2]) * h
    positions = x0 + x1 * times + 0.5 * x2 * times**2
    sol = solve(scene, positions)
    d1 = np.array([1, -8, 0, 8, -1]) / (12 * h)
    d2 = np.array([-1, 16, -30, 16, -1]) / (12 * h * h)

    def point(body, z):
        phi, origin = sol.poses[body]
        r = origin + np.exp(1j * np.asarray(phi)) * z
        return r[2], d1 @ r, d2 @ r

    def angular(body):
        phi = np.unwrap(np.asarray(sol.poses[body][0], dtype=float) + np.zeros(5))
        return d1 @ phi, d2 @ phi

    return point, angular


@pytest.mark.parametrize("name", LOADED)
def test_the_balancing_moment_does_the_virtual_work_of_the_loads_finite_differences(name):
    scene = load(example_path(name))
    result = plans.forces(scene)
    driver = scene.driver
    natural = 1.0 / abs(driver.omega) if isinstance(driver, Crank) else 0.1 / abs(driver.velocity)
    point, angular = motion_by_differences(scene, 1e-3 * natural)
    g = scene.gravity.g * complex(math.cos(scene.gravity.angle), math.sin(scene.gravity.angle))
    power = 0.0
    scale = 0.0
    for body, mass in scene.masses.items():
        _, v, a = point(body, mass.centre)
        omega, epsilon = angular(body)
        for f in (mass.mass * g, -mass.mass * a):
            power += (np.conj(f) * v).real
            scale += abs(f) * abs(v)
        power += -mass.inertia * epsilon * omega
        scale += abs(mass.inertia * epsilon * omega)
    for item in scene.loads:
        if item.kind == "moment":
            omega, _ = angular(item.body)
            power += item.moment * omega
            scale += abs(item.moment * omega)
            continue
        _, v, _ = point(item.body, item.at)
        f = item.force if item.kind == "force" else -item.magnitude * v / abs(v)
        if item.working is not None and (np.conj(item.working) * v).real <= 0:
            f = 0
        power += (np.conj(f) * v).real
        scale += abs(f) * abs(v)
    speed = driver.omega if isinstance(driver, Crank) else driver.velocity
    expected = -power / speed
    assert result.balancing[0] == pytest.approx(expected, abs=2e-7 * scale / abs(speed)), name


def test_the_power_balance_of_the_result_is_zero_over_a_cycle():
    for name in LOADED:
        scene = load(example_path(name))
        result = solve_forces(scene, sweep_positions(scene, 36), allow_partial=True)
        ok = np.asarray(result.kinematics.valid)
        residual = result.power_residual()[ok]
        assert np.max(np.abs(residual)) <= 1e-12 * np.max(np.abs(result.driving_power()[ok])) + 1e-12, name


def test_the_mean_driving_power_equals_the_mean_resistance_power_over_a_turn():
    """Over one turn at constant ω the inertia and the weights give back what they take (kinetic and potential
    energy return to their values): the mean power of M_b is that of the external loads alone."""
    for name in ("slider-crank-loads", "quick-return-loads", "scotch-yoke-loads"):  # (six-bar's load is a constant force: no mean power)
        scene = load(example_path(name))
        assert isinstance(scene.driver, Crank) and scene.driver.epsilon == 0
        result = solve_forces(scene, sweep_positions(scene, 3600))
        driving = np.mean(result.driving_power())
        external = [item for item in result.loads if item.kind in ("force", "resistance", "moment")]
        inertia = [item for item in result.loads if item.kind not in ("force", "resistance", "moment")]
        resisting = np.mean(load_power(external, result.kinematics))
        assert driving > 0 and resisting < 0
        assert driving == pytest.approx(-resisting, rel=1e-6), name
        # and the inertia loads and weights alone average to nothing (their power is −dE/dt)
        peak = np.max(np.abs(load_power(inertia, result.kinematics)))
        assert abs(np.mean(load_power(inertia, result.kinematics))) <= 1e-6 * peak


# --- hard cases ----------------------------------------------------------------------------------


def test_velocities_only_scene_is_refused_for_forces():
    text = example_path("slider-crank-loads").read_text() + "\n[compute]\naccelerations = false\n"
    with pytest.raises(SceneError, match=r"compute.accelerations.*needs the accelerations"):
        plans.forces(loads(text, source="s.toml"))


def test_an_unassemblable_position_is_refused_as_kinematics_does():
    scene = load(example_path("rocker-limit-loads")).at(math.radians(180))
    with pytest.raises(PlansError):
        plans.forces(scene)


def test_a_scene_without_masses_has_zero_forces():
    result = plans.forces(load(example_path("slider-crank")))
    assert result.loads == ()
    assert np.all(result.balancing == 0) and all(np.all(r.force == 0) for r in result.reactions.values())


def test_a_couple_on_a_block_on_a_moving_guide_passes_to_the_guide_when_the_normal_force_is_zero():
    """A pure couple on the linear-arm's block 5 (on the moving rod 3), no masses: the rod's normal force on the
    block is 0, so the pair carries the couple alone (no line of action) and the rod must feel it: the
    balancing force then does the couple's work, F_b·v = −M·ω₃ (the block turns with the rod)."""
    text = example_path("linear-arm").read_text() + '\n[[load]]\nlink = "5"\nmoment = "5 N*m"\n'
    result = plans.forces(loads(text, source="s.toml"))
    pair = result.reactions["R_35"]
    assert pair.kind == "P" and abs(pair.normal_force[0]) <= 1e-12 and np.isnan(pair.point[0])
    assert pair.couple[0] == pytest.approx(-5.0, rel=1e-12)  # the rod holds the block against its +5 N·m
    kin = result.kinematics
    omega3 = kin.links["3"].omega[0]
    assert abs(omega3) > 0.1
    assert result.balancing[0] * kin.scene.driver.velocity == pytest.approx(-5.0 * omega3, rel=1e-12)


def test_the_frame_goes_by_the_scenes_number_in_every_reaction_label():
    # the §11 example renumbered as the Russian and Bulgarian courses number it: crank 1, rod 2, piston 3, frame 0
    from plans.forces.force_plans import construct_force_plans
    from plans.graphical import construct

    text = example_path("slider-crank-loads").read_text()
    text = text.replace("[link.2]", "[link.1]").replace("[link.3]", "[link.2]").replace('link = "4"', 'link = "3"').replace('crank = "2"', 'crank = "1"')
    scene = loads(text, source="crank-one.toml")
    assert scene.frame_number == "0"
    analytic = solve_forces(scene)
    assert list(analytic.reactions) == ["R_01", "R_12", "R_23", "R_03"]
    assert abs(analytic.reactions["R_01"].force[0]) == pytest.approx(9646.41888, abs=1e-5)  # §11's R12 (frame on crank)
    assert abs(analytic.reactions["R_03"].force[0]) == pytest.approx(2077.57014, abs=1e-5)  # §11's guide on slider
    graphical = construct(scene)
    assert set(construct_force_plans(graphical).reactions) >= {"R_01", "R_12", "R_23", "R_03"}


def test_a_working_stroke_load_acts_on_the_slower_stroke_of_the_output():
    # the shaper's cutting force acts on the working stroke, the slow one, which a cycle's positions start
    # (0 → 0′, plans.motion), and not on the quick return; 48 positions: the return is the last ~120° of the turn
    from plans.forces.analytic import forces_from
    from plans.motion import driver_cycle

    scene = load(example_path("quick-return-loads"))
    cycle = driver_cycle(scene, 48)
    result = forces_from(cycle.solve())
    cutting = next(load for load in result.loads if load.name == "F_c")
    on = np.abs(np.asarray(cutting.force)) > 0
    assert on[1:30].all(), "the cutting force acts over the working stroke"
    assert not on[-12:].any(), "no cutting force on the return stroke"
