"""Instant centres (plans.centres) against independent references.

* Every centre against its definition from the ANALYTIC solution's velocities:
  P_ij = r_A + i (v_A,i − v_A,j) / (ω_i − ω_j), at infinity in the direction
  i (v_A,i − v_A,j) when ω_i = ω_j (domain.md §8).  The analytic solver shares
  no kinematics with plans.centres, so agreement is a check of both.
* Kennedy's theorem as a property: any three centres of three bodies are
  collinear, over seeded random mechanisms of every dyad kind.
* Hand cases: the slider-crank's six centres typed from domain.md §8, the
  four-bar's P13 and P24 at the intersections of the opposite links' lines
  (computed here by Cramer's rule), the six-bar's fifteen, the scotch yoke's
  centres at infinity.
* Velocities from the centres against analytic to 1e-12 on every example.
"""

import cmath
import itertools
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from plans.analytic import solve
from plans.centres import CentreError, instant_centres
from plans.errors import PlansError
from plans.scene import FRAME, example_names, example_path, load, loads

from dyad_scenes import crank, prp, rpp, rpr, rrp, rrr, sine, unit, xy

#: agreement of centres (unit homogeneous vectors in units of the mechanism's size)
CENTRE_TOL = 1e-9
#: agreement of velocities from the centres with the analytic ones, relative
VELOCITY_REL = 1e-12
#: random mechanisms closer than this to a dead centre are skipped
MIN_SINE = 0.2


def _analytic_fields(scene, analytic):
    """Each body's velocity field from the analytic solution: ω and one point's (r, v)."""
    fields = {FRAME: (0.0, 0j, 0j)}
    for name in scene.links:
        point = next(iter(scene.bodies[name].points))
        motion = analytic.points[point]
        fields[name] = (float(analytic.links[name].omega[0]), complex(motion.r[0]), complex(motion.v[0]))
    return fields


def _velocity(field, z):
    omega, r, v = field
    return v + 1j * omega * (z - r)


def _homogeneous(point, direction, middle, size):
    """A centre as a unit vector (x, y, w) in units of the size, sign fixed."""
    if point is None:
        h = np.array([direction.real, direction.imag, 0.0])
    else:
        z = (point - middle) / size
        h = np.array([z.real, z.imag, 1.0])
    h = h / np.linalg.norm(h)
    return h


def _same(h1, h2):
    return min(np.linalg.norm(h1 - h2), np.linalg.norm(h1 + h2))


def _check_against_analytic(scene):
    analytic = solve(scene)
    result = instant_centres(scene)
    fields = _analytic_fields(scene, analytic)
    omegas = [abs(f[0]) for f in fields.values()]
    speeds = [abs(complex(analytic.points[p].v[0])) for p in scene.point_names]
    zs = [complex(analytic.points[p].r[0]) for p in scene.point_names]
    middle = complex((max(z.real for z in zs) + min(z.real for z in zs)) / 2, (max(z.imag for z in zs) + min(z.imag for z in zs)) / 2)
    size = max(max(z.real for z in zs) - min(z.real for z in zs), max(z.imag for z in zs) - min(z.imag for z in zs))
    omega_scale = max(max(omegas), max(speeds) / size)
    n = len(scene.bodies)
    assert len(result.centres) == n * (n - 1) // 2
    for centre in result.centres:
        i, j = centre.bodies
        a = middle  # any point A: the definition does not depend on it
        dv = _velocity(fields[i], a) - _velocity(fields[j], a)
        domega = fields[i][0] - fields[j][0]
        if abs(domega) <= 1e-11 * omega_scale:
            if abs(dv) <= 1e-11 * omega_scale * size:
                continue  # no relative motion (two blocks pinned together, both translating): any point is a centre
            expected = _homogeneous(None, 1j * dv / abs(dv), middle, size)
        else:
            expected = _homogeneous(a + 1j * dv / domega, None, middle, size)
        got = _homogeneous(centre.point, centre.direction, middle, size)
        assert _same(got, expected) <= CENTRE_TOL, (scene.title, centre.label, centre.describe(), expected)
    return result


@pytest.mark.parametrize("name", example_names())
def test_every_centre_is_where_the_analytic_relative_velocity_vanishes(name):
    _check_against_analytic(load(example_path(name)))


@pytest.mark.parametrize("name", example_names())
def test_velocities_from_centres_agree_with_analytic(name):
    scene = load(example_path(name))
    analytic = solve(scene)
    result = instant_centres(scene)
    omegas = {n: float(analytic.links[n].omega[0]) for n in scene.links}
    largest = max(abs(w) for w in omegas.values())
    for link, omega in omegas.items():
        assert abs(result.links[link] - omega) <= VELOCITY_REL * max(abs(omega), largest), (link, result.links[link], omega)
    speeds = {p: complex(analytic.points[p].v[0]) for p in scene.point_names}
    fastest = max(abs(v) for v in speeds.values())
    for point, v in speeds.items():
        assert abs(result.points[point] - v) <= VELOCITY_REL * max(abs(v), fastest * 1e-3), (point, result.points[point], v)


def test_slider_crank_six_centres_from_domain_section_8():
    result = instant_centres(load(example_path("slider-crank")))
    assert [c.label for c in result.centres] == ["P12", "P13", "P14", "P23", "P24", "P34"]
    finite = {"P12": (0, 0), "P23": (0.0707107, 0.0707107), "P34": (0.3198513, 0.05),
              "P13": (0.3198513, 0.3198513), "P24": (0, 0.0765887)}
    for centre in result.centres:
        if centre.label == "P14":
            assert centre.point is None
            assert abs(centre.direction.real) < 1e-15 and abs(centre.direction.imag) == pytest.approx(1.0)
            assert centre.found_by.startswith("prismatic")
        else:
            x, y = finite[centre.label]
            assert abs(centre.point - complex(x, y)) < 1e-7, centre.label
    kennedy = {c.label: c.lines for c in result.centres if c.found_by == "kennedy"}
    assert kennedy == {"P13": (("P12", "P23"), ("P14", "P34")), "P24": (("P12", "P14"), ("P23", "P34"))}
    # the slider's velocity is that of P24 as a point of the crank: −16.0407 m/s along x (domain.md §6)
    assert result.points["B"] == pytest.approx(complex(-16.0407098, 0), abs=1e-6)
    assert result.links["3"] == pytest.approx(-59.4427657, abs=1e-6)


def _cross_lines(p1, p2, q1, q2):
    """Where line p1p2 meets line q1q2, by Cramer's rule on p1 + t(p2 − p1) = q1 + s(q2 − q1)."""
    a, b = p2 - p1, q1 - q2
    rhs = q1 - p1
    det = a.real * b.imag - a.imag * b.real
    t = (rhs.real * b.imag - rhs.imag * b.real) / det
    return p1 + t * a


def test_four_bar_p13_p24_where_opposite_links_lines_cross():
    scene = load(example_path("four-bar"))
    analytic = solve(scene)
    r = {p: complex(analytic.points[p].r[0]) for p in scene.point_names}
    result = instant_centres(scene)
    crank, coupler, rocker = scene.driver.link, *[n for n in scene.links if n != scene.driver.link]
    o = r[scene.driver.pivot]
    (a,) = [p for p in scene.bodies[crank].points if p != scene.driver.pivot]
    (b,) = [p for p in scene.bodies[rocker].points if p in scene.bodies[coupler].points]
    (d,) = [p for p in scene.bodies[rocker].points if p in scene.frame.points]
    p13 = _cross_lines(o, r[a], r[d], r[b])  # crank's line × rocker's line
    p24 = _cross_lines(r[a], r[b], o, r[d])  # coupler's line × the frame's line
    assert abs(result.centre(FRAME, coupler).point - p13) < 1e-12
    assert abs(result.centre(crank, rocker).point - p24) < 1e-12


def test_six_bar_has_fifteen_centres_and_its_hand_ones():
    scene = load(example_path("six-bar"))
    result = _check_against_analytic(scene)
    labels = [c.label for c in result.centres]
    assert labels == ["P12", "P13", "P14", "P15", "P16", "P23", "P24", "P25", "P26", "P34", "P35", "P36", "P45", "P46", "P56"]
    primary = {c.label: c.found_by for c in result.centres if c.found_by != "kennedy"}
    assert primary == {"P12": "revolute O", "P14": "revolute D", "P16": "revolute E", "P23": "revolute A",
                       "P34": "revolute C", "P35": "revolute B", "P56": "prismatic E"}
    # P56 lies at infinity perpendicular to the rod BM
    rod = result.positions["M"] - result.positions["B"]
    assert result.centre("5", "6").point is None
    assert abs((result.centre("5", "6").direction.conjugate() * rod).real) < 1e-12 * abs(rod)


def test_scotch_yoke_centres_at_infinity():
    scene = load(example_path("scotch-yoke"))
    result = _check_against_analytic(scene)
    a = 0.1 * cmath.exp(1j * math.radians(30))
    assert result.centre("frame", "4").direction == pytest.approx(1j)  # ⊥ the rail
    assert result.centre("3", "4").direction == pytest.approx(1 + 0j)  # ⊥ the vertical slot
    assert result.centre("frame", "3").direction == pytest.approx(a / abs(a))  # the block translates ⊥ OA... along v_A's normal
    assert result.centre("2", "4").point == pytest.approx(complex(0, a.imag))
    assert result.points["R"] == pytest.approx(complex(-20 * a.imag, 0))  # the yoke moves with P24 as a point of the crank
    assert result.links["3"] == 0 and result.links["4"] == 0


def test_a_pure_translation_wedge_has_every_link_translating():
    result = _check_against_analytic(load(example_path("wedge")))
    assert all(result.centre("frame", link).point is None for link in ("2", "3", "4"))
    assert all(omega == 0 for omega in result.links.values())


PARALLELOGRAM = """
[frame]
points = { O = [0, 0], D = [0.4, 0] }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
[link.3]
points = { A = [0, 0], B = [0.4, 0] }
[link.4]
points = { D = [0, 0], B = [0.1, 0] }
[driver]
crank = "2"
angle = "60 deg"
omega = 10
[assembly]
B = [0.45, 0.09]
"""


def test_parallelogram_coupler_translates_its_centres_at_infinity():
    # crank and rocker parallel: the lines P12P23 and P14P34 never meet, so P13 lies at infinity along
    # the crank (60°), and P24 along the frame line OD (0°); ω3 = 0, ω4 = ω2, v_B = v_A
    result = instant_centres(loads(PARALLELOGRAM))
    p13, p24 = result.centre("frame", "3"), result.centre("2", "4")
    assert p13.point is None and p13.direction_deg == pytest.approx(60.0, abs=1e-9)
    assert p24.point is None and p24.direction_deg == 0.0
    assert p13.describe() == "at infinity, direction 60.000°" and p24.describe() == "at infinity, direction 0.000°"
    assert result.links["3"] == 0.0 and result.links["4"] == pytest.approx(10.0, rel=1e-14)
    v_a = 10 * 0.1 * 1j * cmath.exp(1j * math.pi / 3)
    assert abs(result.points["B"] - v_a) < 1e-14 and abs(result.points["A"] - v_a) < 1e-15


FLAT_FOUR_BAR = """
[frame]
points = { O = [0, 0], D = [4, 0] }
[link.2]
points = { O = [0, 0], A = [1, 0] }
[link.3]
points = { A = [0, 0], B = [2, 0] }
[link.4]
points = { D = [0, 0], B = [1, 0] }
[driver]
crank = "2"
angle = 0
omega = 1
"""


def test_undetermined_centre_is_named_not_computed():
    # O, A, B, D on one line: the Kennedy lines for P13 (OA and DB) are one line, and ω3 needs P13
    with pytest.raises(CentreError) as caught:
        instant_centres(loads(FLAT_FOUR_BAR, source="flat.toml"))
    assert isinstance(caught.value, PlansError) and isinstance(caught.value, ArithmeticError)
    assert str(caught.value) == (
        "flat.toml: the velocity of link 3 is not determined by the instant centres at this position: it needs its "
        "centre with the frame P13 and one with a link already known (P23); P13 is undetermined: the Kennedy lines "
        "P12P23, P14P34 are one line at this position"
    )


def test_quick_return_at_90_deg_has_two_undetermined_centres_and_right_velocities():
    # φ = 90°: O, A, C, D on the vertical through C, so every Kennedy line for P25 and P26 is that
    # vertical; the velocities do not need them (link 5 translates: P15 at infinity, vertical)
    scene = load(example_path("quick-return")).at(math.pi / 2)
    result = instant_centres(scene)
    undetermined = {c.label: c.why for c in result.centres if not c.determined}
    assert undetermined == {
        "P25": "the Kennedy lines P12P15, P23P35, P24P45 are one line at this position",
        "P26": "the Kennedy lines P12P16, P23P36, P24P46 are one line at this position",
    }
    assert all(c.point is None and c.direction is None for c in result.centres if not c.determined)
    p15 = result.centre("frame", "5")
    assert p15.point is None and abs(p15.direction.real) < 1e-12
    analytic = solve(scene)
    for link in scene.links:
        assert result.links[link] == pytest.approx(float(analytic.links[link].omega[0]), abs=1e-12 * 6)
    for point in scene.point_names:
        assert abs(result.points[point] - complex(analytic.points[point].v[0])) <= 1e-12


def test_centres_import_neither_analytic_nor_graphical_nor_matplotlib():
    code = (
        "import sys; from plans.centres import instant_centres; from plans.scene import load, example_path; "
        "instant_centres(load(example_path('six-bar'))); "
        "bad = [m for m in sys.modules if m.startswith(('plans.analytic', 'plans.graphical', 'matplotlib', 'shapely'))]; "
        "assert not bad, bad"
    )
    subprocess.run([sys.executable, "-c", code], check=True, cwd=Path(__file__).resolve().parents[1])
    forbidden = re.compile(r"^\s*(from|import)\s+\S*(analytic|graphical|matplotlib)", re.MULTILINE)
    for source in (Path(__file__).resolve().parents[1] / "plans" / "centres").glob("*.py"):
        assert not forbidden.search(source.read_text(encoding="utf-8")), source


# --- Kennedy's theorem over seeded random mechanisms of every dyad kind -------------------


def _random_rrr(rng):
    r, phi = rng.uniform(0.05, 1), rng.uniform(-math.pi, math.pi)
    a = r * unit(phi)
    c, d = complex(*rng.uniform(-1, 1, 2)), complex(*rng.uniform(-1, 1, 2))
    if min(abs(c - a), abs(c - d), abs(d)) < 0.05 or sine(c - a, c - d) < MIN_SINE:
        return None
    return rrr(a, c, d) + crank(r, phi, rng.uniform(0.5, 50))


def _random_rrp(rng):
    r, phi, alpha = rng.uniform(0.05, 1), rng.uniform(-math.pi, math.pi), rng.uniform(-math.pi, math.pi)
    slot_origin = 0.3 * rng.uniform(-1, 1) * 1j
    u = unit(phi + alpha)
    c = unit(phi) * slot_origin + rng.uniform(-1, 1) * u
    b = complex(*rng.uniform(-1, 1, 2))
    if abs(c - b) < 0.05 or abs(b) < 0.05 or sine(1j * (c - b), u) < MIN_SINE:
        return None
    return rrp(b, c, slot_origin, alpha, r, phi, -rng.uniform(0.5, 50))


def _random_rpr(rng):
    r, phi, theta = rng.uniform(0.05, 1), rng.uniform(-math.pi, math.pi), rng.uniform(-math.pi, math.pi)
    a, u = r * unit(phi), unit(theta)
    d = 0.2 * rng.uniform(-1, 1)
    e = a + d * 1j * u + (0.3 + rng.uniform(0, 1)) * u
    if abs(e) < 0.05 or sine(1j * (e - a), u) < MIN_SINE:
        return None
    return rpr(a, e, u, d) + crank(r, phi, rng.uniform(0.5, 50))


def _random_prp(rng):
    r, phi, alpha, gamma = rng.uniform(0.05, 1), *rng.uniform(-math.pi, math.pi, 3)
    u, w = unit(phi + alpha), unit(gamma)
    if sine(u, w) < MIN_SINE:
        return None
    c = 0.5 * rng.uniform(-1, 1) * u
    g = c - rng.uniform(-1, 1) * w
    return prp(g, gamma, alpha, r, phi, rng.uniform(0.5, 50))


def _random_rpp(rng):
    r, phi, alpha, beta, gamma = rng.uniform(0.05, 1), *rng.uniform(-math.pi, math.pi, 4)
    a = r * unit(phi)
    slot = unit(gamma - beta + alpha)
    if sine(slot, unit(gamma)) < MIN_SINE:
        return None
    y = a - 0.5 * rng.uniform(-1, 1) * slot
    return rpp(y, gamma, alpha, beta) + crank(r, phi, rng.uniform(0.5, 50))


def _random_six_bar(rng):
    """A four-bar whose coupler drives an RPR: two groups, fifteen centres."""
    base = _random_rrr(rng)
    if base is None:
        return None
    e = complex(*rng.uniform(-1, 1, 2))
    return base.replace("[link.4]", """[link.5]
points = { M = [0, 0], N = [0.7, 0] }
lines = { rod = { through = "M", angle = 0 } }
[[slider]]
pin = "E"
on = "5.rod"
[link.4]""").replace("points = { O = [0, 0], D", f"points = {{ O = [0, 0], E = {xy(e)}, D")


@pytest.mark.parametrize("kind, make", [("RRR", _random_rrr), ("RRP", _random_rrp), ("RPR", _random_rpr),
                                        ("PRP", _random_prp), ("RPP", _random_rpp), ("RRR+RPR", _random_six_bar)])
def test_kennedy_any_three_centres_collinear_on_random_mechanisms(kind, make):
    rng = np.random.default_rng(1300 + len(kind))
    checked = 0
    while checked < 15:
        text = make(rng)
        if text is None:
            continue
        try:
            scene = loads(text)
            analytic = solve(scene)
        except PlansError:
            continue  # does not assemble, or too near a dead centre
        if analytic.warnings:
            continue
        result = _check_against_analytic(scene)
        middle = complex(np.mean([z.real for z in result.positions.values()]), np.mean([z.imag for z in result.positions.values()]))
        h = {c.bodies: _homogeneous(c.point, c.direction, middle, result.size) for c in result.centres}
        h.update({(b, a): v for (a, b), v in list(h.items())})
        for i, j, k in itertools.combinations(list(scene.bodies), 3):
            det = np.linalg.det(np.array([h[(i, j)], h[(j, k)], h[(i, k)]]))
            assert abs(det) <= 1e-9, (kind, i, j, k, det)
        checked += 1


@pytest.mark.parametrize("name", example_names())
def test_velocities_from_centres_over_the_cycle(name):
    # twelve crank positions (from the scene's angle, so 90° and 270° of the quick-return too), or five
    # along a linear driver's stroke; against analytic, relative to the largest value of each kind
    scene = load(example_path(name))
    driver = scene.driver
    if hasattr(driver, "phi"):
        positions = [driver.phi + k * math.pi / 6 for k in range(12)]
    else:
        positions = list(np.linspace(*driver.stroke, 5))
    checked = 0
    for position in positions:
        at = scene.at(position)
        try:
            analytic = solve(at)
        except PlansError:
            continue  # rocker-limit: the crank cannot reach every angle
        result = instant_centres(at)
        omega_scale = max(abs(float(analytic.links[n].omega[0])) for n in at.links)
        v_scale = max(abs(complex(analytic.points[p].v[0])) for p in at.point_names)
        for link in at.links:
            assert abs(result.links[link] - float(analytic.links[link].omega[0])) <= 1e-11 * omega_scale, (position, link)
        for point in at.point_names:
            assert abs(result.points[point] - complex(analytic.points[point].v[0])) <= 1e-11 * v_scale, (position, point)
        checked += 1
    assert checked >= 3


# --- the method's own position step --------------------------------------------------------


def _branch_scenes():
    """Every bundled example with each group's branch forced to +1 and to −1 (README "Assembly branches")."""
    from dataclasses import replace

    from plans.structure import find_structure

    for name in example_names():
        scene = load(example_path(name))
        for group in find_structure(scene).groups:
            outer = {j.point for j in (group.outer_i, group.outer_j) if j.kind == "R"}
            hint = next((p for link in group.links for p in scene.bodies[link].points if p not in outer), None)
            if hint is None:
                continue
            for sign in (1, -1):
                yield pytest.param(replace(scene, assembly={hint: sign}), id=f"{name}-{group.name}-{hint}{sign:+d}")


@pytest.mark.parametrize("scene", list(_branch_scenes()))
def test_own_positions_follow_the_branch_convention_like_analytic(scene):
    try:
        analytic = solve(scene)
    except PlansError as refused:  # quick-return, lever on branch −1: the ram's group cannot reach its guide
        with pytest.raises(type(refused)):
            instant_centres(scene)
        return
    result = instant_centres(scene)
    size = result.size
    for name in scene.point_names:
        assert abs(result.positions[name] - complex(analytic.points[name].r[0])) <= 1e-12 * size, name


def test_own_position_step_refuses_what_cannot_assemble():
    from plans.errors import AssemblyError

    text = FLAT_FOUR_BAR.replace("D = [4, 0]", "D = [4.5, 0]")  # |AD| = 3.5 > AB + BD = 3
    with pytest.raises(AssemblyError) as caught:
        instant_centres(loads(text, source="far.toml"))
    assert str(caught.value) == (
        "far.toml: RRR(3,4): joint B cannot assemble: |AD| = 3.5 m with links 2 m and 1 m (gap 0.5 m) "
        "(at φ = 0.0°, instant-centre method)"
    )
