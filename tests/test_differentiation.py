"""Kinematic diagrams of the output link by graphical differentiation (issue 19 §4).

Expected values are independent of the code under test: the centric
slider-crank's displacement in closed form, s(φ) = r cos φ + √(l² − r² sin² φ),
its derivatives by hand, and the method of chords as a hand formula
(s(t_{k+1}) − s(t_k)) / Δt.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import plans
from plans.differentiation import (
    DiagramScales,
    OutputMotion,
    chords,
    kinematic_diagrams,
    kinematic_diagrams_of,
    smooth,
    tangents,
)

R, L, OMEGA = 0.1, 0.3, 10.0  # crank [m], rod [m], ω [rad/s] (constant, counter-clockwise)
PT = 25.4 / 72  # mm per SVG unit (matplotlib writes points)

CENTRIC = f"""
title = "Centric slider-crank"

[frame]
points = {{ O = [0, 0] }}
lines = {{ guide = {{ through = [0, 0], angle = 0 }} }}

[link.2]
points = {{ O = [0, 0], A = [{R}, 0] }}

[link.3]
points = {{ A = [0, 0], B = [{L}, 0] }}

[[slider]]
pin = "B"
on = "frame.guide"

[driver]
crank = "2"
angle = "30 deg"
omega = "{OMEGA} rad/s"

[assembly]
B = [0.38, 0]
"""


def x_b(phi):
    """Closed form: the piston pin's x [m]."""
    return R * np.cos(phi) + np.sqrt(L**2 - (R * np.sin(phi)) ** 2)


def dx_dphi(phi):
    return -R * np.sin(phi) - R**2 * np.sin(phi) * np.cos(phi) / np.sqrt(L**2 - (R * np.sin(phi)) ** 2)


def d2x_dphi2(phi):
    root = np.sqrt(L**2 - (R * np.sin(phi)) ** 2)
    return -R * np.cos(phi) - R**2 * np.cos(2 * phi) / root - R**4 * np.sin(phi) ** 2 * np.cos(phi) ** 2 / root**3


@pytest.fixture(scope="module")
def scene():
    return plans.loads(CENTRIC)


@pytest.fixture(scope="module")
def twelve(scene):
    return kinematic_diagrams(scene, 12, precision=0.1)


# --- the method itself, by hand ----------------------------------------------------------------


def test_chords_are_mean_rates_at_interval_middles():
    t = np.array([0.0, 0.1, 0.3, 0.6])
    y = np.array([1.0, 2.0, 0.0, 3.0])
    middles, slopes = chords(t, y)
    assert middles.tolist() == pytest.approx([0.05, 0.2, 0.45])
    assert slopes.tolist() == pytest.approx([10.0, -10.0, 10.0])
    # a closed cycle: the last point joined to the first one a period later
    middles, slopes = chords(t, y, period=1.0)
    assert middles[-1] == pytest.approx(0.8)
    assert slopes[-1] == pytest.approx((1.0 - 3.0) / 0.4)


def test_smooth_curve_and_tangents_are_exact_for_a_cubic():
    t = np.linspace(0.0, 1.0, 7)
    cubic = lambda x: 2 * x**3 - x**2 + 0.5 * x - 1  # noqa: E731
    x = np.array([0.03, 0.41, 0.97])
    assert smooth(t, cubic(t), x) == pytest.approx(cubic(x), abs=1e-12)
    assert tangents(t, cubic(t)) == pytest.approx(6 * t**2 - 2 * t + 0.5, abs=1e-12)


def test_chord_error_is_second_order_at_interval_middles():
    """(s(t_{k+1}) − s(t_k))/Δt against v at the middle: the error falls as Δt² (ratio 4 when Δt halves)."""
    errors = []
    for n in (12, 24, 48, 96):
        phi = 2 * np.pi * np.arange(n) / n
        t = phi / OMEGA
        middles, slopes = chords(t, x_b(phi), period=2 * np.pi / OMEGA)
        exact = OMEGA * dx_dphi(OMEGA * middles)
        errors.append(float(np.max(np.abs(slopes - exact))))
    orders = [math.log2(a / b) for a, b in zip(errors, errors[1:])]
    assert all(1.9 < p < 2.1 for p in orders), orders
    # and the constant is the textbook's: Δt² s‴/24 at the middle
    n = 96
    h = 2 * np.pi / n / OMEGA
    s3 = OMEGA**3 * np.gradient(d2x_dphi2(np.linspace(0, 2 * np.pi, 20001)), 2 * np.pi / 20000).max()
    assert errors[-1] <= 1.05 * h**2 * s3 / 24


# --- from the scene ----------------------------------------------------------------------------------


def test_positions_start_at_an_extreme_and_s_is_the_closed_form(scene, twelve):
    d = twelve
    assert d.motion.kind == "slider" and len(d.motion.t) == 12
    phi = d.positions
    # position 0 is an extreme position of the piston (φ = 0 or π, modulo a turn)
    assert min(abs(math.sin(phi[0])), 1.0) == pytest.approx(0.0, abs=1e-9)
    assert d.motion.s == pytest.approx(x_b(phi) - x_b(phi[0]), abs=1e-12)
    # equally spaced in time under the constant-speed law, over one turn T = 2π/ω
    assert d.motion.t == pytest.approx((phi - phi[0]) / OMEGA, abs=1e-12)
    assert d.motion.period == pytest.approx(2 * math.pi / OMEGA)


def test_chord_rates_are_the_hand_formula(twelve):
    d = twelve
    phi = d.positions
    s = x_b(np.append(phi, phi[0] + 2 * math.pi))
    dt = 2 * math.pi / 12 / OMEGA
    assert d.velocity.rates == pytest.approx(np.diff(s) / dt, rel=1e-12, abs=1e-12)
    assert d.velocity.middles == pytest.approx((phi - phi[0]) / OMEGA + dt / 2, abs=1e-12)
    # a–t points: chords of the v–t points, at the positions themselves (equal spacing)
    second = (np.roll(np.diff(s), -1) - np.diff(s)) / dt**2
    assert d.acceleration.rates == pytest.approx(second, rel=1e-9, abs=1e-9)
    assert d.acceleration.middles == pytest.approx(d.velocity.middles + dt / 2, abs=1e-12)


def test_table_analytic_column_is_the_closed_form_and_plans_agree(twelve):
    d = twelve
    phi = d.positions
    assert d.v_analytic == pytest.approx(OMEGA * dx_dphi(phi), abs=1e-9)
    assert d.a_analytic == pytest.approx(OMEGA**2 * d2x_dphi2(phi), abs=1e-6)
    # the plans, read to 0.1 mm, within a few tenths of a per cent of the largest value
    assert np.max(np.abs(d.v_plans - d.v_analytic)) < 0.005 * np.max(np.abs(d.v_analytic))
    assert np.max(np.abs(d.a_plans - d.a_analytic)) < 0.005 * np.max(np.abs(d.a_analytic))
    rows = d.rows()
    k = 5
    assert rows[k]["v_analytic"] == pytest.approx(OMEGA * dx_dphi(phi[k]), abs=1e-9)
    largest = np.max(np.abs(OMEGA * dx_dphi(phi)))
    assert rows[k]["error_v_diagram"] == pytest.approx(100 * (d.v[k] - OMEGA * dx_dphi(phi[k])) / largest, abs=1e-9)


def test_errors_several_per_cent_at_12_falling_as_dt_squared(scene, twelve):
    """The honest numbers: the chords' error at 12 positions is of per cents; 24 and 48 quarter it each time."""
    largest = {}
    for n in (12, 24, 48):
        d = twelve if n == 12 else kinematic_diagrams(scene, n, precision=0)
        phi = d.positions
        v_exact, a_exact = OMEGA * dx_dphi(phi), OMEGA**2 * d2x_dphi2(phi)
        largest[n] = (np.max(np.abs(d.v - v_exact)) / np.max(np.abs(v_exact)), np.max(np.abs(d.a - a_exact)) / np.max(np.abs(a_exact)))
    assert 0.005 < largest[12][0] < 0.05 and 0.01 < largest[12][1] < 0.10
    # observed order log2(e(n) / e(2n)): 2 in the limit; at 12 → 24 the cubic read-back at the positions (fourth
    # order) still adds to the chords' second-order error (v: 2.3)
    for q in (0, 1):
        assert 1.8 < math.log2(largest[12][q] / largest[24][q]) < 2.6, (q, largest)
        assert 1.85 < math.log2(largest[24][q] / largest[48][q]) < 2.25, (q, largest)


def test_scales_follow_the_formulas(twelve):
    sc = twelve.scales
    assert sc.length == 120.0  # 12 intervals of 10 mm
    assert sc.mu_t == pytest.approx((2 * math.pi / OMEGA) / 120.0)
    mantissa = sc.mu_s / 10 ** math.floor(math.log10(sc.mu_s))
    assert round(mantissa, 9) in (1, 2, 2.5, 5)
    assert sc.pole_v == round(sc.pole_v) and sc.pole_a == round(sc.pole_a)
    assert sc.mu_v == pytest.approx(sc.mu_s / (sc.mu_t * sc.pole_v))
    assert sc.mu_a == pytest.approx(sc.mu_v / (sc.mu_t * sc.pole_a))
    # every diagram within its height
    assert np.ptp(twelve.motion.s) / sc.mu_s <= 40.0 + 1e-9
    assert np.ptp(twelve.velocity.rates) / sc.mu_v <= 40.0 + 1e-9
    assert np.ptp(twelve.acceleration.rates) / sc.mu_a <= 40.0 + 1e-9


def test_rocker_output_is_its_angle(scene):
    four = plans.load(plans.example_path("four-bar"))
    d = kinematic_diagrams(four, 8, precision=0)
    assert d.motion.kind == "rocker" and d.motion.name == "4"
    solution = plans.solve(four, d.positions)
    phi4 = np.unwrap(np.asarray(solution.links["4"].phi))
    assert d.motion.s == pytest.approx(phi4 - phi4[0], abs=1e-12)
    # constant speed: ε of the driver is 0 over the cycle whatever the scene's own ε (5 rad/s²) says
    exact = plans.solve(four, d.positions, rates=(np.full(8, 10.0), np.zeros(8)))
    assert d.a_analytic == pytest.approx(np.asarray(exact.links["4"].epsilon), abs=1e-9)


def test_too_few_positions_refused(scene):
    with pytest.raises(plans.PlansError, match="at least 3 positions"):
        kinematic_diagrams(scene, 2)


def test_open_series_reads_its_ends():
    """A linear driver's stroke is not a cycle: n − 1 chords, the ends read off the curve through the points."""
    t = np.linspace(0.0, 1.0, 9)
    s = np.sin(t)
    d = kinematic_diagrams_of(OutputMotion("slider", "x", tuple(map(str, range(9))), t, s, None),
                              scales=DiagramScales(0.01, 100.0, 0.01, 20.0, 0.05, 20.0, 0.25))
    assert len(d.velocity.rates) == 8 and len(d.acceleration.rates) == 7
    assert d.v == pytest.approx(np.cos(t), abs=2e-3)
    assert d.a == pytest.approx(-np.sin(t), abs=2e-2)


# --- the drawing, measured in its SVG ---------------------------------------------------------


def _groups(svg: bytes, prefix: str) -> list:
    root = ET.fromstring(svg)
    ns = "{http://www.w3.org/2000/svg}"
    found = [g for g in root.iter(f"{ns}g") if re.fullmatch(rf"{prefix}(-\d+)?", g.get("id", ""))]
    return sorted(found, key=lambda g: int(g.get("id").rsplit("-", 1)[1]) if g.get("id")[-1].isdigit() and g.get("id") != prefix else 1)


def _ends(group) -> tuple[complex, complex]:
    path = next(group.iter("{http://www.w3.org/2000/svg}path"))
    numbers = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?", path.get("d"))]
    return complex(numbers[0], -numbers[1]) * PT, complex(numbers[-2], -numbers[-1]) * PT  # mm, y up


def _text_of(svg: bytes, gid: str) -> str:
    root = ET.fromstring(svg)
    return "".join("".join(t.itertext()) for g in root.iter("{http://www.w3.org/2000/svg}g") if g.get("id") == gid
                   for t in g.iter("{http://www.w3.org/2000/svg}text"))


def test_ray_intercepts_measured_in_the_svg_give_the_chord_velocities(twelve):
    """In the drawings a page places at 100 %: H₁ and μ_v as their title states, an intercept measured in mm × μ_v
    = the chord's velocity."""
    from plans.drawing.kinematic_diagrams import diagram_svgs, diagram_title, page_diagrams

    d = page_diagrams(twelve, 175.0)
    blocks = diagram_svgs(d, "en")
    stated = diagram_title(d, "v", "en")
    m = re.search(r"\$\\mu_\{v\}\$ = \$\\mu_\{s\}\$/\(\$\\mu_\{t\}\$·\$H_\{1\}\$\) = ([0-9.]+) \(m/s\)/mm,\s+\$H_\{1\}\$ = ([0-9.]+) mm", stated)
    assert m, stated
    mu_v, pole = float(m.group(1)), float(m.group(2))
    mu_s = float(re.search(r"\$\\mu_\{s\}\$ = ([0-9.]+) m/mm", diagram_title(d, "s", "en")).group(1))
    from plans.drawing.kinematic_diagrams import header_lines

    mu_t = float(re.search(r"\$\\mu_\{t\}\$ = T/L = ([0-9.]+) s/mm", " ".join(header_lines(d, "en"))).group(1))
    assert mu_v == pytest.approx(mu_s / (mu_t * pole), rel=2e-3)  # the formula, with the page's own numbers
    rays = _groups(blocks["v"].svg, "kd-v-ray")
    assert len(rays) == 12
    phi = d.positions
    s = x_b(np.append(phi, phi[0] + 2 * math.pi))
    chord_v = np.diff(s) / (2 * math.pi / 12 / OMEGA)  # the hand formula
    for k, ray in enumerate(rays):
        start, end = _ends(ray)
        assert end.real - start.real == pytest.approx(pole, abs=0.01)  # H₁ at true scale
        assert (end.imag - start.imag) * mu_v == pytest.approx(chord_v[k], rel=3e-3, abs=0.01 * mu_v)
    # each ray is parallel to its chord of the s–t curve
    chords_drawn = _groups(blocks["s"].svg, "kd-s-chord")
    assert len(chords_drawn) == 12
    for chord, ray in zip(chords_drawn, rays):
        a, b = _ends(chord)
        p, q = _ends(ray)
        assert math.atan2((b - a).imag, (b - a).real) == pytest.approx(math.atan2((q - p).imag, (q - p).real), abs=1e-3)
    # the abscissa of one cycle: L = T / μ_t at true scale, between the first and the closing position's lines
    lines = _groups(blocks["s"].svg, "kd-s-position")
    assert len(lines) == 13
    first, last = _ends(lines[0])[0], _ends(lines[-1])[0]
    assert last.real - first.real == pytest.approx((2 * math.pi / OMEGA) / mu_t, abs=0.05)
    # the three drawings as wide, their origins (the ordinates) at the same distance from their left edges
    origins = {key: _ends(_groups(block.svg, f"kd-{key}-ordinate")[0])[0].real for key, block in blocks.items()}
    assert max(origins.values()) - min(origins.values()) < 0.01


def test_handout_has_the_page_in_serbian(scene):
    from plans.handout import handout
    from plans.i18n import TERMS

    doc = handout(scene, positions=8, lang="sr")
    assert {"kinematic-s", "kinematic-v", "kinematic-a"} <= set(doc.images)  # the drawings, placed at 100 %
    start = doc.source.index("Кинематски дијаграми излазног члана")  # the words, set by Typst
    texts = re.findall(r'#"((?:[^"\\]|\\.)*)"', doc.source[start:])
    for name in ("kinematic-s", "kinematic-v", "kinematic-a"):  # the drawings' own texts: numbers and symbols
        root = ET.fromstring(doc.images[name])
        texts += ["".join(t.itertext()) for t in root.iter("{http://www.w3.org/2000/svg}text")]
    page = " ".join(texts)
    assert "тангент" not in page and "аналит." in page and "тетив" in page  # (the method of tangents: not drawn, not on the page)
    # no English words: none of the block's English terms, and no Latin word beyond units, symbols and the user's title
    english = {w.lower() for key in ("kinematic_diagrams", "chord", "ray", "displacement", "diagrams_table", "diagram_error_note",
                                     "chords_curve", "analytic_curve", "method_of_tangents", "cycle_time", "abscissa_length", "velocity",
                                     "acceleration", "output_slider", "positions", "driver_law", "law_constant", "law_constant_angular")
               for w in re.findall(r"[A-Za-z]{4,}", TERMS[key]["en"])}
    latin = {w.lower() for w in re.findall(r"[A-Za-z]{4,}", page)} - {w.lower() for w in re.findall(r"[A-Za-z]+", scene.title)}
    assert not (latin & english), latin & english
    assert not latin, latin


def test_cli_sweep_plot_writes_the_kinematic_diagrams(tmp_path, capsys):
    from plans.cli import main

    out = tmp_path / "plots"
    assert main(["sweep", "--example", "slider-crank", "--steps", "24", "-o", str(tmp_path / "s.csv"), "--plot", str(out),
                 "--positions", "8", "--format", "svg"]) == 0
    written = sorted(p.name for p in out.iterdir())
    assert any(name.startswith("kinematic") for name in written), written
    svg = "".join((out / n).read_text() for n in written if n.startswith("kinematic"))
    assert "method of chords" in svg and "8" in svg


def test_a_linear_drivers_stroke_is_an_open_series():
    """linear-arm: the driver runs its stroke once at constant speed; n − 1 chords, times from the law."""
    scene = plans.load(plans.example_path("linear-arm"))
    d = kinematic_diagrams(scene, 12, precision=0)
    assert d.motion.period is None and len(d.velocity.rates) == 11 and len(d.acceleration.rates) == 10
    v0 = scene.driver.velocity
    assert d.motion.t == pytest.approx(np.abs(d.positions - d.positions[0]) / abs(v0), abs=1e-12)
    # the chords are the hand formula on the output's own angles, solved independently here
    phi = np.unwrap(np.asarray(plans.solve(scene, d.positions).links[d.motion.name].phi))
    assert d.velocity.rates == pytest.approx(np.diff(phi) / np.diff(d.motion.t), rel=1e-9)
    errors = d.errors()
    assert np.nanmax(np.abs(errors["v_diagram"])) < 1.0 and np.nanmax(np.abs(errors["a_diagram"])) < 2.0


def test_why_the_diagrams_are_not_drawn_is_said_in_the_readers_language():
    from plans.differentiation import DiagramsError
    from plans.drawing.kinematic_diagrams import unavailable_reason

    error = DiagramsError("x.toml: kinematic diagrams: the mechanism is not solved at positions 3, 4; …", "unsolved", (3, 4))
    assert isinstance(error, plans.PlansError)
    text = unavailable_reason(error, "ru")
    assert "в положениях 3, 4" in text
    assert "not solved" not in text


def test_a_uniformly_accelerated_turn_is_open_and_continued_past_its_ends():
    """Four-bar, ω² = ω₀² + 2ε(φ − φ₀): not a repeating cycle; the crank turns on, so the chords reach one
    position past each end (s repeats over a turn, t from the law), and the errors fall as Δt² to the ends."""
    scene = plans.load(plans.example_path("four-bar"))
    omega0, eps, phi0 = scene.driver.omega, scene.driver.epsilon, scene.driver.phi

    def time(phi, first):
        return (math.sqrt(omega0**2 + 2 * eps * (phi - phi0)) - math.sqrt(omega0**2 + 2 * eps * (first - phi0))) / eps

    largest = {}
    for n in (12, 24, 48):
        d = kinematic_diagrams(scene, n, law="uniform", precision=0)
        phi = d.positions
        assert d.motion.period is None and len(phi) == n + 1 and phi[-1] - phi[0] == pytest.approx(2 * math.pi)
        assert d.motion.t == pytest.approx([time(p, phi[0]) for p in phi], abs=1e-12)
        step = phi[1] - phi[0]
        assert d.motion.lead[0] == pytest.approx(time(phi[0] - step, phi[0]), abs=1e-12)
        assert d.motion.trail[0] == pytest.approx(time(phi[-1] + step, phi[0]), abs=1e-12)
        assert (d.motion.lead[1], d.motion.trail[1]) == pytest.approx((d.motion.s[-2], d.motion.s[1]), abs=1e-12)
        assert d.scales.length == n * (125 // n)  # a whole number of mm for each of the n intervals of the turn
        e = d.errors()
        largest[n] = (np.nanmax(np.abs(e["v_diagram"])), np.nanmax(np.abs(e["a_diagram"])))
    assert largest[12][0] < 10 and largest[12][1] < 20
    for q in (0, 1):
        assert 1.6 < math.log2(largest[24][q] / largest[48][q]) < 2.6, largest
