"""Joukowski's lever (issue 22) against the analytic kinetostatics, and its geometry as a drawing needs it.

The lever takes its velocities and accelerations from the graphical plans only;
with exact readings it must give the analytic M_b to round-off, with a drafting
precision of 0.1 mm within what textbooks accept of a drawing (1 %), and its
geometry (turned images, arms, feet of the perpendiculars) must be what the
construction says, checked here from the plans' own images.
"""

import math

import numpy as np
import pytest

import plans
from plans.cli import main
from plans.forces.lever import TURN, LeverError, joukowski_lever
from plans.graphical import construct
from plans.scene import example_names, example_path, load, loads

LOADED = example_names(loads=True)


@pytest.mark.parametrize("name", LOADED)
def test_with_exact_readings_the_lever_gives_the_analytic_balancing_moment(name):
    scene = load(example_path(name))
    exact = float(plans.forces(scene).balancing[0])
    lever = joukowski_lever(construct(scene, precision=None))
    assert lever.balancing == pytest.approx(exact, rel=1e-9, abs=1e-9)
    assert lever.balancing_kind == ("moment" if name not in ("ladder-loads", "linear-arm-loads", "wedge-loads") else "force")


@pytest.mark.parametrize("name", LOADED)
def test_at_a_drafting_precision_the_lever_is_within_a_drawings_accuracy(name):
    scene = load(example_path(name))
    exact = float(plans.forces(scene).balancing[0])
    lever = joukowski_lever(construct(scene, precision=0.1))
    assert lever.balancing == pytest.approx(exact, rel=1e-2)
    assert lever.balancing != exact  # the arms were measured, not computed
    for force in lever.forces + (lever.balancing_force,):
        assert abs(force.arm / 0.1 - round(force.arm / 0.1)) < 1e-6  # every arm a multiple of the precision
        assert force.moment == pytest.approx(abs(force.force) * force.arm, rel=1e-12, abs=1e-9)
    total = sum(f.moment for f in lever.forces) + sum(c.moment for c in lever.couples) + lever.balancing_force.moment
    assert abs(total) <= 1e-9 * max(abs(f.moment) for f in lever.forces)  # the lever in equilibrium about the pole


def test_the_lever_is_the_velocity_plan_turned_by_90_degrees_with_the_loads_at_their_images():
    scene = load(example_path("slider-crank-loads"))
    graphical = construct(scene, precision=None)
    lever = joukowski_lever(graphical)
    plan = graphical.velocity_plan
    for label, z in plan.images.items():
        assert lever.images[label] == pytest.approx(1j * z, abs=1e-12)  # turned counter-clockwise about p
    assert TURN == 1j
    # S3 is 100 mm along AB (300 mm): its velocity image a third of the way from a to b, turned
    s3 = plan.images["a"] + (plan.images["b"] - plan.images["a"]) / 3
    assert lever.images["s3"] == pytest.approx(1j * s3, abs=1e-9)
    # S2 is on OA, 40 mm from O (OA = 100 mm): its image at 0.4 of pa, and the label is made for it ("s2")
    assert lever.images["s2"] == pytest.approx(1j * 0.4 * plan.images["a"], abs=1e-9)
    for force in lever.forces + (lever.balancing_force,):
        exact = (force.point.real * force.force.imag - force.point.imag * force.force.real) / abs(force.force)
        assert force.arm == pytest.approx(exact, rel=1e-12, abs=1e-12)
        assert abs(force.foot) == pytest.approx(abs(force.arm), rel=1e-9, abs=1e-9)  # the foot is the arm's end
        along = (force.point - force.foot) * np.conj(force.force)
        assert abs(along.imag) <= 1e-9 * abs(force.point) * abs(force.force)  # the foot lies on the line of action
        assert lever.images[force.image] == force.point
    # the balancing force at the image of A, perpendicular to OA, and M_b = F_b·l_OA
    fb = lever.balancing_force
    assert fb.image == "a" and lever.crank_length == pytest.approx(0.1, rel=1e-15)
    A = graphical.positions["A"]
    assert (fb.force * np.conj(A)).real == pytest.approx(0, abs=1e-9 * abs(fb.force))
    assert lever.balancing == pytest.approx(abs(fb.force) * 0.1 * np.sign((np.conj(1j * A) * fb.force).real), rel=1e-12)


def test_the_inertia_loads_of_the_lever_come_from_the_acceleration_plan():
    scene = load(example_path("slider-crank-loads"))
    graphical = construct(scene, precision=None)
    lever = joukowski_lever(graphical)
    plan = graphical.acceleration_plan
    s3 = plan.images["a′"] + (plan.images["b′"] - plan.images["a′"]) / 3  # image of S3 by similarity
    inertia = next(load for load in lever.loads if load.name == "F_Φ3")
    assert inertia.force == pytest.approx(-3.0 * plan.scale * s3, rel=1e-9)
    couple = next(load for load in lever.loads if load.name == "M_Φ3")
    assert couple.moment == pytest.approx(-0.025 * graphical.links["3"]["epsilon"], rel=1e-12)
    # the couple as a pair of forces at A and B (link 3's points farthest apart), ⟂ AB, |M|/AB each
    pair = [f for f in lever.forces if f.name == "M_Φ3"]
    assert sorted(f.image for f in pair) == ["a", "b"]
    A, B = graphical.positions["A"], graphical.positions["B"]
    for f in pair:
        assert abs(f.force) == pytest.approx(abs(couple.moment) / abs(B - A), rel=1e-12)
        assert (f.force * np.conj(B - A)).real == pytest.approx(0, abs=1e-9)
    assert pair[0].force == pytest.approx(-pair[1].force, rel=1e-15)


def test_a_resistance_off_its_working_stroke_is_not_on_the_lever():
    scene = load(example_path("quick-return-loads"))
    ram = plans.solve(scene).points["E"].v[0].real
    lever = joukowski_lever(construct(scene))
    names = [f.name for f in lever.forces]
    assert ("F_c" in names) == (ram < 0)  # the cutting force acts while the ram moves towards −x (the slow working stroke)
    turned = scene.at(scene.driver.phi + math.pi)
    ram_turned = plans.solve(turned).points["E"].v[0].real
    assert (ram > 0) != (ram_turned > 0)
    assert ("F_c" in [f.name for f in joukowski_lever(construct(turned)).forces]) == (ram_turned < 0)


ATREST = example_path("slider-crank-loads").read_text().replace('omega = "150 rad/s"', 'omega = 0')


def test_with_the_driver_at_rest_the_lever_is_refused_and_the_cli_says_why(tmp_path, capsys):
    scene = loads(ATREST, source="rest.toml")
    with pytest.raises(LeverError, match="no arm for the balancing force"):
        joukowski_lever(construct(scene))
    path = tmp_path / "rest.toml"
    path.write_text(ATREST)
    assert main(["forces", str(path)]) == 0  # statics: the analytic method still answers
    out, err = capsys.readouterr()
    assert "Joukowski's lever left out" in err and "Joukowski's lever left out" in out
    # statics: M_b holds the weights, M_b = dV/dφ with V = Σ m·g·y_S (central difference of solved positions)
    h = 1e-6

    def potential(phi):
        solution = plans.solve(scene.at(phi))
        return sum(m.mass * 9.81 * solution.motion_of(body, m.centre).r[0].imag for body, m in scene.masses.items())

    expected = (potential(scene.driver.phi + h) - potential(scene.driver.phi - h)) / (2 * h)
    assert float(plans.forces(scene).balancing[0]) == pytest.approx(expected, rel=1e-7)
    assert f"{expected:16.9g}".strip()[:6] in out


@pytest.mark.parametrize("name", ["slider-crank-loads", "six-bar-loads", "linear-arm-loads"])
def test_at_a_drafting_precision_every_arm_and_reading_is_within_half_of_it(name):
    """What "within drafting precision" means for the lever: each arm measured to ±p/2 of the exact one, each
    inertia force read to ±m·k_a·p/2 of the analytic −m·a_S (its length on the plan rounded to p)."""
    p = 0.1
    scene = load(example_path(name))
    graphical = construct(scene, precision=p)
    lever = joukowski_lever(graphical)
    for force in lever.forces + (lever.balancing_force,):
        exact = (force.point.real * force.force.imag - force.point.imag * force.force.real) / abs(force.force)
        assert abs(force.arm - exact) <= p / 2 + 1e-9, (force.name, force.image)
    analytic = {item.name: item for item in plans.forces(scene).loads}
    k_a = graphical.acceleration_plan.scale
    for item in lever.loads:
        if item.kind == "inertia force":
            mass = scene.masses[item.body].mass
            assert abs(item.force - complex(analytic[item.name].force[0])) <= mass * k_a * p / 2 * (1 + 1e-9), item.name
        if item.kind == "weight":
            assert item.force == analytic[item.name].force
