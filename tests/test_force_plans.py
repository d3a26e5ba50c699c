"""The force plans (plans.forces.force_plans): the graphical kinetostatics, group by group.

Oracles, none of them the code under test:
* domain.md §11's worked example (exact values, Newton–Euler and the power balance to 1e-39);
* the inertia loads recomputed here from the *analytic* kinematics (−m·a_S, −J·ε);
* the power balance written here: M_b·ω + Σ F·v + Σ M·ω = 0 with the analytic velocities
  (virtual work: it checks M_b, or a linear driver's F_b, without any reaction);
* each link's own equilibrium written here: Σ F = 0 and Σ M = 0 over everything the
  result says acts on it (reactions at their points of action included).
"""

from __future__ import annotations

import cmath
import math
from dataclasses import replace

import pytest

from plans.analytic import solve
from plans.errors import SceneError
from plans.forces.force_plans import construct_force_plans, pair_label
from plans.graphical import construct
from plans.scene import Crank, example_names, example_path, load

#: Exact construction (no drafting precision): agreement with the exact values to round-off.
EXACT = 1e-9
#: Drafting precision of the readings [mm], as the kinematic plans are read on a page.
PRECISION = 0.1

LOADED = example_names(loads=True)

#: domain.md §11: label -> (|R| [N], angle [deg]); R12 of the text is R_02 here (the frame is body 0)
REFERENCE = {
    "R_02": (9646.41888, 199.942051),
    "R_23": (8353.55006, 192.098702),
    "R_34": (5461.32544, 157.194749),
}
M_B = 620.218316
GUIDE_ON_SLIDER = -2077.57014  # N along +y, through B


def _solved(name: str, precision=None):
    scene = load(example_path(name))
    graphical = construct(scene, precision=precision)
    return scene, graphical, construct_force_plans(graphical, precision=precision)


def _angle(z: complex) -> float:
    return math.degrees(cmath.phase(z)) % 360.0


def test_worked_example_exact():
    scene, g, fp = _solved("slider-crank-loads")
    assert fp.balancing_moment == pytest.approx(M_B, rel=1e-8)
    for label, (size, angle) in REFERENCE.items():
        r = fp.reactions[label]
        assert abs(r.force) == pytest.approx(size, rel=1e-8), label
        assert _angle(r.force) == pytest.approx(angle, abs=1e-6), label
    guide = fp.reactions["R_04"]
    assert guide.force.real == pytest.approx(0.0, abs=1e-6)
    assert guide.force.imag == pytest.approx(GUIDE_ON_SLIDER, rel=1e-8)
    assert guide.at == pytest.approx(g.positions["B"], abs=1e-12)  # every load on the piston passes through B
    assert fp.reactions["R_23"].at == g.positions["A"]
    assert fp.balancing_force is None  # a crank's M_b is a couple


def test_worked_example_at_drafting_precision():
    """Read at 0.1 mm, every value within the bound its readings allow.

    A length read is off by at most p/2: a reaction on its plan by p/2·μ_F, an
    acceleration by p/2·k_a (so an inertia force by m·p/2·k_a), an arm by p/2·k_l.
    A reaction carries the errors of its own reading, of the plans before it and
    of the accelerations: bounded here by 2·p·μ_F + Σ m·p·k_a; M_b by that error
    times OA plus Σ |F|·p·k_l over the crank's loads.
    """
    scene, g, fp = _solved("slider-crank-loads", PRECISION)
    p = PRECISION
    mu = max(plan.scale for plan in fp.plans)
    masses = sum(m.mass for m in scene.masses.values())
    bound = 2 * p * mu + masses * p * g.scales["k_a"]
    for label, (size, angle) in REFERENCE.items():
        exact = cmath.rect(size, math.radians(angle))
        assert abs(fp.reactions[label].force - exact) <= bound, label
        assert fp.reactions[label].force != exact  # really read at a precision
    assert abs(fp.reactions["R_04"].force - GUIDE_ON_SLIDER * 1j) <= bound
    on_crank = sum(abs(f.force) for f in fp.on("2")[0])
    assert abs(fp.balancing_moment - M_B) <= bound * 0.1 + on_crank * p * g.scales["k_l"]
    # every reading is a whole number of precision steps times μ_F
    for plan in fp.plans:
        for v in plan.vectors:
            if v.kind == "reaction":
                steps = v.value / plan.scale / p
                assert steps == pytest.approx(round(steps), abs=1e-6), v.label


def test_plans_are_drawn_at_round_scales_and_close():
    _, _, fp = _solved("slider-crank-loads", PRECISION)
    assert [plan.group for plan in fp.plans] == ["RRP(3,4)", "driver"]
    for plan in fp.plans:
        mantissa = plan.scale / 10 ** math.floor(math.log10(plan.scale))
        assert round(mantissa, 9) in (1, 2, 2.5, 5)
        assert 60 <= max(v.length for v in plan.vectors) <= 120
    # the group's polygon: loads and found reactions head to tail back to the start
    group = fp.plans[0]
    labels = [v.label for v in group.vectors]
    assert labels[:7] == ["R^t_23", "G_3", "F_Φ3", "G_4", "F_Φ4", "F_r", "R_04"]
    chain = group.vectors[:8]
    for a, b in zip(chain, chain[1:]):
        assert b.tail == pytest.approx(a.tip, abs=1e-9)
    assert chain[-1].label == "R^n_23" and chain[-1].tip == pytest.approx(chain[0].tail, abs=1e-9)
    # the two closing lines: ⊥ the cylinder (vertical) through the end of the loads, ∥ AB through the start
    assert len(group.lines) == 2
    assert abs(group.lines[0].direction.real) < 1e-12
    ab = fp.graphical.positions["B"] - fp.graphical.positions["A"]
    assert abs((group.lines[1].direction * ab.conjugate()).imag) < 1e-9 * abs(ab)


def _analytic_at(scene):
    a = solve(scene)

    def velocity(body: str, z: complex) -> complex:
        o = a.origins[body]
        return complex(o.v[0]) + 1j * float(a.links[body].omega[0]) * (z - complex(o.r[0]))

    def acceleration(body: str, z: complex) -> complex:
        o = a.origins[body]
        w, e = float(a.links[body].omega[0]), float(a.links[body].epsilon[0])
        return complex(o.a[0]) + (1j * e - w * w) * (z - complex(o.r[0]))

    return a, velocity, acceleration


@pytest.mark.parametrize("name", LOADED)
def test_inertia_loads_from_the_plans_equal_the_analytic(name):
    scene, g, fp = _solved(name)
    a, _, acceleration = _analytic_at(scene)
    gravity = scene.gravity.vector if scene.gravity else 0j
    loads = {f.label: f for f in fp.loads}
    couples = {c.label: c.moment for c in fp.couples}
    for body, m in scene.masses.items():
        label = body if body != "frame" else "0"
        S = fp.centres[body].at
        a_s = acceleration(body, S)
        assert fp.centres[body].acceleration == pytest.approx(a_s, abs=EXACT * (1 + abs(a_s)))
        if m.mass and abs(a_s) > 0:
            assert loads[f"F_Φ{label}"].force == pytest.approx(-m.mass * a_s, abs=EXACT * (1 + m.mass * abs(a_s)))
        if m.mass and gravity:
            assert loads[f"G_{label}"].force == pytest.approx(m.mass * gravity)
        eps = float(a.links[body].epsilon[0])
        if m.inertia and eps:
            assert couples[f"M_Φ{label}"] == pytest.approx(-m.inertia * eps, rel=1e-9)


@pytest.mark.parametrize("name", LOADED)
def test_power_balance(name):
    """M_b·ω + Σ F·v + Σ M·ω = 0 over the loads (velocities analytic): the driving effort is right."""
    scene, g, fp = _solved(name)
    a, velocity, _ = _analytic_at(scene)
    power = 0.0
    scale = 0.0
    for f in fp.loads:
        term = (f.force * velocity(f.body, f.at).conjugate()).real
        power += term
        scale += abs(term)
    for c in fp.couples:
        if c.kind != "balancing":
            term = c.moment * float(a.links[c.body].omega[0])
            power += term
            scale += abs(term)
    driver = scene.driver
    if isinstance(driver, Crank):
        power += fp.balancing_moment * driver.omega
    else:
        power += (fp.balancing_force * velocity(driver.link, fp.balancing_at).conjugate()).real
    assert abs(power) <= 1e-9 * scale


@pytest.mark.parametrize("name", LOADED)
@pytest.mark.parametrize("precision", [None, PRECISION])
def test_every_link_in_equilibrium(name, precision):
    """Σ F = 0 and Σ M = 0 on every moving link (d'Alembert), from what the result says acts on it.

    Exact: to round-off.  Read at a precision: each link still nearly balances (the
    readings differ by drafting errors), within 1 % of the largest force on it.
    """
    scene, g, fp = _solved(name, precision)
    size = 0.2 * g.scales["k_l"] * 200  # a lever of the mechanism's order [m]
    for body in scene.links:
        forces, couples = fp.on(body)
        if not forces and not couples:
            continue
        largest = max([abs(f.force) for f in forces] + [1e-30])
        total = sum(f.force for f in forces)
        about = g.positions[next(iter(scene.bodies[body].points))]
        moment = sum((((f.at - about).conjugate()) * f.force).imag for f in forces) + sum(c.moment for c in couples)
        tol = EXACT if precision is None else 1e-2
        assert abs(total) <= tol * largest, (body, total)
        assert abs(moment) <= tol * largest * size + tol * sum(abs(c.moment) for c in couples), (body, moment)


def test_reaction_labels_name_who_acts_on_whom():
    _, _, fp = _solved("six-bar-loads")
    for label, r in fp.reactions.items():
        assert label == pair_label(r.by, r.on)
    # each inner pair both ways, equal and opposite
    assert fp.reactions["R_34"].force == pytest.approx(-fp.reactions["R_43"].force)
    assert fp.reactions["R_56"].force == pytest.approx(-fp.reactions["R_65"].force)
    # groups from the last to the driver
    assert [plan.group for plan in fp.plans] == ["RPR(5,6)", "RRR(3,4)", "driver"]
    # the later group's reaction on link 3 is a load on 3's plan
    rrr = fp.plans[1]
    assert "R_53" in [v.label for v in rrr.vectors]


def test_resistance_only_over_the_working_stroke():
    """A resistance with ``working`` acts only while its point moves that way: the idle stroke has none."""
    scene = load(example_path("slider-crank-loads"))
    text = example_path("slider-crank-loads").read_text()
    idle = text.replace('force = { magnitude = "1500 N", against = "velocity" }', 'force = { magnitude = "1500 N", against = "velocity" }\nworking = [1, 0]')
    from plans.scene import loads as load_text

    scene_idle = load_text(idle)
    assert scene_idle.loads[0].working is not None
    fp = construct_force_plans(construct(scene_idle, precision=None), precision=None)
    assert "F_r" not in [f.label for f in fp.loads]  # the piston moves in −x at 60°: the idle stroke
    back = construct_force_plans(construct(scene.at(math.radians(240)), precision=None), precision=None)
    assert "F_r" in [f.label for f in back.loads]


def test_velocities_only_is_refused():
    scene = load(example_path("slider-crank-loads"))
    g = construct(replace(scene, accelerations=False))
    with pytest.raises(SceneError, match="acceleration plan"):
        construct_force_plans(g)


def test_given_force_scale():
    _, g, _ = _solved("slider-crank-loads")
    fp = construct_force_plans(g, precision=None, mu_F=50.0)
    assert {plan.scale for plan in fp.plans} == {50.0}
    r = fp.plans[0].vectors[[v.label for v in fp.plans[0].vectors].index("R_23")]
    assert r.length == pytest.approx(REFERENCE["R_23"][0] / 50.0, rel=1e-8)
    with pytest.raises(ValueError, match="mu_F"):
        construct_force_plans(g, mu_F=-1.0)


def _first(x) -> complex:
    import numpy as np

    return complex(np.ravel(x)[0])


@pytest.mark.parametrize("name", LOADED)
def test_against_the_analytic_kinetostatics(name):
    """Exact: every reaction, its line of action and M_b (or F_b) as Newton–Euler gives them, to round-off."""
    from plans.forces import solve_forces

    scene = load(example_path(name))
    analytic = solve_forces(scene)
    fp = construct_force_plans(construct(scene, precision=None), precision=None)
    for label, r in analytic.reactions.items():
        force = _first(r.force)
        assert fp.reactions[label].force == pytest.approx(force, abs=EXACT * (1 + abs(force))), label
        if abs(force) > 0:  # the same line of action (a prismatic pair's point of action)
            u = force / abs(force)
            offset = ((fp.reactions[label].at - _first(r.point)) * u.conjugate()).imag
            assert abs(offset) <= EXACT * (1 + abs(_first(r.point))), label
    balancing = _first(analytic.balancing).real
    mine = fp.balancing_moment if isinstance(scene.driver, Crank) else fp.balancing_force.real
    assert mine == pytest.approx(balancing, rel=EXACT, abs=EXACT)


@pytest.mark.parametrize("name", LOADED)
def test_against_the_analytic_at_drafting_precision(name):
    """Read at 0.1 mm: within the bound the readings allow (see the worked example's test).

    Each plan adds at most p/2·μ_F to a reaction it reads and passes on; the
    accelerations at most m·p/2·k_a per mass: bound (plans + 1)·p·μ_F + Σ m·p·k_a.
    The driving effort adds the arms' p/2·k_l on every force on the driver.
    """
    from plans.forces import solve_forces

    scene = load(example_path(name))
    analytic = solve_forces(scene)
    g = construct(scene, precision=PRECISION)
    fp = construct_force_plans(g)
    p = PRECISION
    mu = max(plan.scale for plan in fp.plans)
    bound = (len(fp.plans) + 1) * p * mu + sum(m.mass for m in scene.masses.values()) * p * g.scales["k_a"]
    for label, r in analytic.reactions.items():
        assert abs(fp.reactions[label].force - _first(r.force)) <= bound, label
    balancing = _first(analytic.balancing).real
    driver = scene.driver.link
    forces, _ = fp.on(driver)
    reach = max(abs(z - w) for z in g.positions.values() for w in g.positions.values())
    if isinstance(scene.driver, Crank):
        allowed = bound * reach + sum(abs(f.force) for f in forces) * p * g.scales["k_l"]
        assert abs(fp.balancing_moment - balancing) <= allowed
    else:
        assert abs(fp.balancing_force.real - balancing) <= bound


@pytest.mark.parametrize("name", ["slider-crank-loads", "wedge-loads"])
def test_balancing_as_the_analytic_states_it(name):
    """``balancing``: M_b on a crank, F_b along a linear driver's guide (signed): as plans.forces gives it."""
    from plans.forces import solve_forces
    from plans.forces.force_plans import force_plans

    scene = load(example_path(name))
    fp = force_plans(construct(scene, precision=None), precision=None)
    assert fp.balancing == pytest.approx(_first(solve_forces(scene).balancing).real, rel=1e-9)
    assert fp.balancing_kind == ("moment" if isinstance(scene.driver, Crank) else "force")
