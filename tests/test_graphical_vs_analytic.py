"""The project's main correctness claim: the graphical construction agrees with the analytic solution.

The two methods share the scene model and nothing else (plans.graphical never
imports plans.analytic).  Without drafting precision the readings off the
plans equal the complex-number solution to round-off.
"""

import cmath
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from plans.analytic import solve
from plans.errors import PlansError
from plans.graphical import construct
from plans.scene import example_names, example_path, load, loads

#: Agreement, relative to the largest value of the same kind (positions, velocities, ...) in the solution.
REL_TOL = 1e-9


def largest(values) -> float:
    return max([abs(v) for v in values] + [1e-300])


def check(name: str, graphical, analytic):
    g, a = graphical, analytic
    assert set(g.points) == set(a.points), name
    assert set(g.links) == set(a.links), name
    assert set(g.sliders) == set(a.sliders), name
    scale_r = largest(a.points[p].r[0] for p in a.points)
    scale_v = largest(a.points[p].v[0] for p in a.points)
    scale_a = largest(a.points[p].a[0] for p in a.points)
    for p in a.points:
        assert abs(g.positions[p] - a.points[p].r[0]) <= REL_TOL * scale_r, (name, p, "r")
        assert abs(g.points[p]["v"] - a.points[p].v[0]) <= REL_TOL * scale_v, (name, p, "v")
        assert abs(g.points[p]["a"] - a.points[p].a[0]) <= REL_TOL * scale_a, (name, p, "a")
    scale_w = largest(a.links[k].omega[0] for k in a.links)
    scale_e = largest(a.links[k].epsilon[0] for k in a.links)
    for k in a.links:
        assert abs(g.links[k]["omega"] - a.links[k].omega[0]) <= REL_TOL * scale_w, (name, k, "omega")
        assert abs(g.links[k]["epsilon"] - a.links[k].epsilon[0]) <= REL_TOL * scale_e, (name, k, "epsilon")
    for s in a.sliders:
        assert abs(g.sliders[s]["s"] - a.sliders[s].s[0]) <= REL_TOL * scale_r, (name, s, "s")
        assert abs(g.sliders[s]["v_rel"] - a.sliders[s].v_rel[0]) <= REL_TOL * scale_v, (name, s, "v_rel")
        assert abs(g.sliders[s]["a_rel"] - a.sliders[s].a_rel[0]) <= REL_TOL * scale_a, (name, s, "a_rel")
        assert abs(g.sliders[s]["coriolis"] - a.sliders[s].coriolis[0]) <= REL_TOL * scale_a, (name, s, "coriolis")
    for body in g.poses:
        if body in a.links:  # the same angle, modulo a turn
            assert abs(cmath.exp(1j * g.poses[body][0]) - cmath.exp(1j * a.links[body].phi[0])) <= REL_TOL, (name, body, "phi")


@pytest.mark.parametrize("name", example_names())
def test_every_example_agrees(name):
    scene = load(example_path(name))
    check(name, construct(scene), solve(scene))


@pytest.mark.parametrize("name", example_names())
@pytest.mark.parametrize("k", [("k_l", 1e-3), ("k_v", 1e-3), ("k_a", 1e3)])
def test_agreement_does_not_depend_on_the_scale_factors(name, k):
    scene = load(example_path(name))
    check(name, construct(scene, check_scales=False, **{k[0]: k[1]}), solve(scene))  # factors off the sheet on purpose


SIGN_VARIANTS = {
    "four-bar": ["B = 1", "B = -1"],
    "slider-crank": ["B = 1", "B = -1"],
    "ladder": ["B = 1", "B = -1"],
    "six-bar": ["C = 1\nM = 1", "C = -1\nM = 1", "C = 1\nM = -1", "C = -1\nM = -1"],
    "quick-return": ["E = [0.3, 0.52]\nD = 1"],
}


@pytest.mark.parametrize("name, assembly", [(n, a) for n, hints in SIGN_VARIANTS.items() for a in hints])
def test_branch_signs_agree(name, assembly):
    text = example_path(name).read_text().split("[assembly]")[0] + "\n[assembly]\n" + assembly + "\n"
    scene = loads(text)
    check(f"{name} {assembly}", construct(scene), solve(scene))


# Groups whose guides are carried by moving links (Coriolis in RRP, PRP, RPP), and
# an RRP whose link j carries the guide on which a known link slides.
RRP_MOVING_SLIDER = """
[frame]
points = { O = [0, 0], Q = [0.3, 0.2] }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
lines = { peg = { through = "A", angle = "30 deg" } }
[link.3]
points = { Q = [0, 0], C = [0.25, 0] }
[link.4]
points = { C = [0, 0], N = [0.1, 0.05] }
lines = { rod = { through = [0, 0.02], angle = 0 } }
[[prismatic]]
line = "2.peg"
on = "4.rod"
name = "peg"
[driver]
crank = "2"
angle = "40 deg"
omega = 5
epsilon = 2
"""

PRP_MOVING_GUIDE = """
[frame]
points = { O = [0, 0] }
lines = { ground = { through = [0, 0.3], angle = "10 deg" } }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
lines = { arm = { through = "O", angle = 0 } }
[link.3]
points = { C = [0, 0.01] }
lines = { g = { through = [0, 0], angle = 0 } }
[link.4]
points = { C = [0, 0], N = [0.05, 0.02] }
lines = { g = { through = [0, -0.02], angle = "-20 deg" } }
[[prismatic]]
line = "3.g"
on = "2.arm"
name = "on-arm"
[[prismatic]]
line = "4.g"
on = "frame.ground"
name = "on-ground"
[driver]
crank = "2"
angle = "60 deg"
omega = 3
epsilon = -1
"""

RPP_MOVING_GUIDE = """
[frame]
points = { O = [0, 0], D = [0.22, 0] }
[link.2]
points = { O = [0, 0], A = [0.08, 0] }
[link.3]
points = { A = [0, 0], B = [0.25, 0] }
[link.4]
points = { D = [0, 0], B = [0.2, 0] }
lines = { bar = { through = "D", angle = 0 } }
[link.5]
points = { A = [0, 0] }
lines = { s = { through = [0, 0.01], angle = "90 deg" } }
[link.6]
points = { P = [0.05, 0.05] }
lines = { inner = { through = [0, 0], angle = "80 deg" }, outer = { through = [0, 0.03], angle = 0 } }
[[prismatic]]
line = "5.s"
on = "6.inner"
name = "inner"
[[prismatic]]
line = "6.outer"
on = "4.bar"
name = "outer"
[driver]
crank = "2"
angle = "60 deg"
omega = 10
epsilon = 5
[assembly]
B = [0.2, 0.2]
"""

MOVING_GUIDES = {"RRP, known link slides on j": RRP_MOVING_SLIDER, "PRP on a crank": PRP_MOVING_GUIDE, "RPP on a rocker": RPP_MOVING_GUIDE}


@pytest.mark.parametrize("name", list(MOVING_GUIDES))
def test_moving_guides_agree(name):
    scene = loads(MOVING_GUIDES[name])
    graphical = construct(scene)
    check(name, graphical, solve(scene))
    plan = graphical.acceleration_plan
    assert [v for v in plan.vectors if v.kind == "coriolis"]
    size = max(v.length for v in plan.vectors)
    for step in plan.steps[1:]:  # each image on both of its construction lines
        for line in step.lines:
            assert abs(((plan.images[step.image] - line.through) * line.direction.conjugate()).imag) <= 1e-9 * size


@pytest.mark.parametrize("length, omega", [(1e-6, 1e5), (100.0, 1e-3), (1e3, 1.0)])
def test_extreme_scales_agree(length, omega):
    text = f"""
[frame]
points = {{ O = [0, 0], D = [{0.22 * length}, 0] }}
[link.2]
points = {{ O = [0, 0], A = [{0.08 * length}, 0] }}
[link.3]
points = {{ A = [0, 0], B = [{0.25 * length}, 0], M = [{0.1 * length}, {0.06 * length}] }}
[link.4]
points = {{ D = [0, 0], B = [{0.2 * length}, 0] }}
[driver]
crank = "2"
angle = "60 deg"
omega = {omega}
epsilon = {omega ** 2 / 2}
"""
    scene = loads(text)
    check(f"four-bar × {length}", construct(scene), solve(scene))


def test_graphical_imports_neither_analytic_nor_matplotlib():
    code = (
        "import sys; from plans.graphical import construct; from plans.scene import load, example_path; "
        "construct(load(example_path('six-bar'))); "
        "bad = [m for m in sys.modules if m.startswith(('plans.analytic', 'matplotlib'))]; "
        "assert not bad, bad"
    )
    subprocess.run([sys.executable, "-c", code], check=True, cwd=Path(__file__).resolve().parents[1])
    forbidden = re.compile(r"^\s*(from|import)\s+\S*(analytic|matplotlib)", re.MULTILINE)
    for source in (Path(__file__).resolve().parents[1] / "plans" / "graphical").glob("*.py"):
        assert not forbidden.search(source.read_text(encoding="utf-8")), source


RANDOM_FOUR_BAR_WITH_SLEEVE = """
[frame]
points = {{ O = [0, 0], D = [{dx}, {dy}], E = [{ex}, {ey}] }}
[link.2]
points = {{ O = [0, 0], A = [{r}, 0] }}
[link.3]
points = {{ A = [0, 0], B = [{l}, 0], M = [{mx}, {my}] }}
[link.4]
points = {{ D = [0, 0], B = [{k}, 0] }}
[link.5]
points = {{ M = [0, 0], N = [0.3, 0.05] }}
lines = {{ rod = {{ through = [0, {h5}], angle = {a5} }} }}
[link.6]
points = {{ E = [0, 0] }}
lines = {{ slot = {{ through = [0, {h6}], angle = {a6} }} }}
[[prismatic]]
line = "6.slot"
on = "5.rod"
name = "sleeve"
[driver]
crank = "2"
angle = {phi}
omega = {omega}
epsilon = {epsilon}
[assembly]
B = {sign_b}
N = {sign_n}
"""


@pytest.mark.parametrize("seed", range(40))
def test_seeded_random_mechanisms_agree(seed):
    """Four-bar + RPR with offset, welded sleeve: both methods assemble or both refuse, and agree.

    (Bare angles in a scene file are degrees.)
    """
    rng = np.random.default_rng(seed)
    values = dict(
        dx=rng.uniform(0.15, 0.4), dy=rng.uniform(-0.1, 0.1), ex=rng.uniform(-0.3, 0.3), ey=rng.uniform(-0.4, -0.1),
        r=rng.uniform(0.03, 0.1), l=rng.uniform(0.2, 0.4), mx=rng.uniform(0.0, 0.3), my=rng.uniform(-0.1, 0.1),
        k=rng.uniform(0.15, 0.35), h5=rng.uniform(-0.03, 0.03), a5=rng.uniform(-60, 60), h6=rng.uniform(-0.03, 0.03),
        a6=rng.uniform(-60, 60), phi=rng.uniform(0, 360), omega=rng.uniform(-20, 20), epsilon=rng.uniform(-50, 50),
        sign_b=int(rng.choice([-1, 1])), sign_n=int(rng.choice([-1, 1])),
    )
    scene = loads(RANDOM_FOUR_BAR_WITH_SLEEVE.format(**values))
    try:
        analytic = solve(scene)
    except PlansError as exc:
        with pytest.raises(type(exc)):
            construct(scene)
        return
    check(f"seed {seed}", construct(scene), analytic)
