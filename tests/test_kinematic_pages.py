"""The kinematic-diagram pages of the handout set by Typst (issue 20): each diagram an SVG block placed at
100 % (its width on the page its own physical width), at least 40 mm tall, drawn at the μ its title states
(a point measured in the embedded SVG × μ = the closed form), the words of a Serbian page all Serbian."""

from __future__ import annotations

import base64
import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import plans
from plans.differentiation import kinematic_diagrams
from plans.drawing import kinematic_diagrams as kd
from plans.handout import handout
from review_handouts import built

R, L, E, OMEGA = 0.1, 0.25, 0.05, 2000 * 2 * math.pi / 60  # the offset slider-crank example [m], [rad/s]
PT = 25.4 / 72  # mm per SVG unit (matplotlib's points; Typst's page units are points too)
SVG = "{http://www.w3.org/2000/svg}"


def x_b(phi):
    """Closed form: the offset slider-crank's piston pin B along its guide (y = e), crank OA = r, rod AB = l [m]."""
    return R * np.cos(phi) + np.sqrt(L**2 - (R * np.sin(phi) - E) ** 2)


@pytest.fixture(scope="module")
def plate():
    return built("slider-crank", 12, "en")


@pytest.fixture(scope="module")
def pages(plate):
    return plate.pages("svg")


def _embedded(pages):
    """(width [mm], SVG bytes) of every drawing embedded in the page SVGs."""
    out = []
    for page in pages:
        for m in re.finditer(rb'<image\b[^>]*?xlink:href="data:image/svg\+xml;base64,([^"]+)"[^>]*?width="([0-9.]+)"', page):
            out.append((float(m.group(2)) * PT, base64.b64decode(m.group(1))))
    return out


def _paths(svg: bytes, gid: str) -> list[list[complex]]:
    """The points [mm, y up] of each path in the groups *gid*, *gid*-2, …"""
    root = ET.fromstring(svg)
    out = []
    for g in root.iter(f"{SVG}g"):
        if re.fullmatch(rf"{gid}(-\d+)?", g.get("id", "")):
            for path in g.iter(f"{SVG}path"):
                numbers = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", path.get("d", ""))]
                out.append([complex(numbers[k], -numbers[k + 1]) * PT for k in range(0, len(numbers) - 1, 2)])
    return out


def _stated(source: str, symbol: str) -> float:
    """The value of μ for *symbol* (Typst math, ``s``) as the page's source states it: ``$mu_(s )$#" = 0.004 m/mm"``."""
    m = re.search(rf'\$mu_\({symbol} ?\)\$#" = (?:"[^\n]*?#"\) = )?([0-9.]+) ', source)
    assert m, symbol
    return float(m.group(1))


def test_each_diagram_is_placed_at_its_physical_size(plate, pages):
    from plans.drawing.svg import svg_size_mm

    embedded = _embedded(pages)
    for key in ("s", "v", "a"):
        svg = plate.images[f"kinematic-{key}"]
        widths = [w for w, data in embedded if data == svg]
        assert len(widths) == 1, key  # on the page once
        own = svg_size_mm(svg)[0]
        assert widths[0] == pytest.approx(own, abs=0.02)  # 100 %
        assert own == pytest.approx(plate.drawn[f"kinematic-{key}"][0], abs=0.05)


def test_each_diagram_is_at_least_40_mm_tall(plate):
    for key in ("s", "v", "a"):
        svg = plate.images[f"kinematic-{key}"]
        (curve,) = _paths(svg, f"kd-{key}-curve")
        abscissa = _paths(svg, f"kd-{key}-abscissa")[0][0].imag
        ys = [z.imag for z in curve] + [abscissa]
        assert max(ys) - min(ys) >= 40.0, (key, max(ys) - min(ys))


def test_the_stated_mu_s_is_the_drawn_scale_against_the_closed_form(plate):
    """Each position's point on the s–t diagram, measured from the abscissa in the embedded SVG, × the μ_s the
    page states = the closed form's s(φ) − s(φ₀) at that crank angle."""
    scene = plans.load(plans.example_path("slider-crank"))
    d = kinematic_diagrams(scene, 12)
    mu_s = _stated(plate.source, "s")
    svg = plate.images["kinematic-s"]
    abscissa = _paths(svg, "kd-s-abscissa")[0][0].imag
    root = ET.fromstring(svg)
    centres = []
    for g in root.iter(f"{SVG}g"):
        if re.fullmatch(r"kd-s-point(-\d+)?", g.get("id", "")):
            for use in g.iter(f"{SVG}path"):
                numbers = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?", use.get("d", ""))]
                ys = numbers[1::2]
                centres.append(-(max(ys) + min(ys)) / 2 * PT)
    assert len(centres) == 13  # the 12 positions and position 0 again at the cycle's end
    phi = np.asarray(d.positions)
    expected = x_b(phi) - x_b(phi[0])
    measured = (np.array(centres[:12]) - abscissa) * mu_s
    assert measured == pytest.approx(expected, abs=0.15 * mu_s)  # to 0.15 mm on paper
    assert np.ptp(expected) / mu_s >= 40.0


def test_the_stated_mu_v_and_h1_are_the_rays(plate):
    """A ray's intercept measured in the embedded v–t drawing × the μ_v stated = the chord's mean velocity of the
    closed form; the ray runs H₁ (stated) from the pole."""
    scene = plans.load(plans.example_path("slider-crank"))
    d = kinematic_diagrams(scene, 12)
    mu_v = _stated(plate.source, "v")
    pole = float(re.search(r'\$H_\(1 ?\)\$#" = ([0-9.]+) mm', plate.source).group(1))
    rays = _paths(plate.images["kinematic-v"], "kd-v-ray")
    assert len(rays) == 12
    phi = np.asarray(d.positions)
    s = x_b(np.append(phi, phi[0] + 2 * math.pi))
    chord_v = np.diff(s) / (2 * math.pi / 12 / OMEGA)
    intercepts = sorted(((ray[-1].imag - ray[0].imag), ray[-1].real - ray[0].real) for ray in rays)
    for (rise, run), v in zip(intercepts, sorted(chord_v)):
        assert run == pytest.approx(pole, abs=0.01)
        assert rise * mu_v == pytest.approx(v, abs=0.05 * mu_v)


@pytest.fixture(scope="module")
def serbian():
    return built("quick-return", 12, "sr")


def test_no_english_word_on_the_serbian_kinematic_page(serbian):
    from plans.i18n import TERMS

    doc = serbian
    start = doc.source.index("Кинематски дијаграми излазног члана")
    page = doc.source[start:]
    strings = " ".join(re.findall(r'#"((?:[^"\\]|\\.)*)"', page))
    assert "тетива" in strings and "аналит." in strings and "тангент" not in strings  # (the method of tangents: not drawn, not on the page)
    latin = {w.lower() for w in re.findall(r"[A-Za-z]{3,}", strings)} - {"rad", "max"}  # a unit and max |δ|, as the course writes them
    assert not latin, latin
    english = {w.lower() for key in ("chord", "ray", "displacement", "diagrams_table", "chords_curve", "analytic_curve")
               for w in re.findall(r"[A-Za-z]{4,}", TERMS[key]["en"])}
    assert not english & set(strings.lower().split())
    # the drawings carry no words at all: numbers and symbols only
    for key in ("s", "v", "a"):
        root = ET.fromstring(doc.images[f"kinematic-{key}"])
        words = " ".join("".join(t.itertext()) for t in root.iter(f"{SVG}text"))
        assert not re.search(r"[A-Za-zА-Яа-я]{2,}", words), words


def test_a_constant_rate_is_said_not_drawn():
    """The wedge driven at constant speed: its output moves uniformly, v constant and a = 0, said in lines."""
    doc = handout(plans.load(plans.example_path("wedge")), positions=12, lang="en")
    assert "kinematic-s" in doc.images and "kinematic-v" not in doc.images and "kinematic-a" not in doc.images
    assert "constant over the whole cycle" in doc.source
    assert '#box[#"a = 0"]#" over the whole cycle' in doc.source  # (the formula in one box: never broken after its =)


@pytest.mark.parametrize("name, count", [("quick-return", 12), ("linear-arm", 8), ("six-bar", 12), ("four-bar", 12), ("ladder", 12)])
def test_readable_scales_are_round_and_the_diagrams_tall(name, count):
    from plans.differentiation import PAGE_MANTISSAS

    d = kd.page_diagrams(kinematic_diagrams(plans.load(plans.example_path(name)), count), 175.0)
    sc = d.scales
    for mu in (sc.mu_s, sc.mu_v, sc.mu_a):
        mantissa = mu / 10 ** math.floor(math.log10(mu) + 1e-9)
        assert any(abs(mantissa - m) < 1e-9 for m in PAGE_MANTISSAS), mu
    assert sc.mu_v == pytest.approx(sc.mu_s / (sc.mu_t * sc.pole_v), rel=1e-12)
    assert sc.mu_a == pytest.approx(sc.mu_v / (sc.mu_t * sc.pole_a), rel=1e-12)
    assert sc.mu_t == pytest.approx(d.motion.duration / sc.length, rel=1e-12)
    assert sc.length + max(sc.pole_v, sc.pole_a) <= kd.block_room(175.0) + 1e-9
    blocks = kd.diagram_svgs(d)
    assert set(blocks) == {"s", "v", "a"}
    assert len({round(b.width, 6) for b in blocks.values()}) == 1  # one width: the time axes line up
    for key, block in blocks.items():  # the curve drawn, with its abscissa, at least 40 mm tall
        (curve,) = _paths(block.svg, f"kd-{key}-curve")
        ys = [z.imag for z in curve] + [_paths(block.svg, f"kd-{key}-abscissa")[0][0].imag]
        assert max(ys) - min(ys) >= 40.0, (name, key, max(ys) - min(ys))


def test_the_cycle_page_does_not_repeat_the_output_sliders_speed_unsigned(serbian):
    """quick-return: the kinematic diagrams give the ram E's signed s, v, a; the points page of the cycle diagrams
    keeps D's |v|, |a| and says where E's are, instead of drawing |v_E|, |a_E| beside them."""
    doc = serbian
    root = ET.fromstring(doc.images["diagram-points"])
    texts = ["".join("".join(t.itertext()).split()) for t in root.iter(f"{SVG}text")]
    assert "|v|D" in texts or "|vD|" in texts or any(re.fullmatch(r"\|v\|?D\|?", t) for t in texts), texts
    assert not any("E" in t and t.startswith("|") for t in texts), texts
    # the page's words, set by Typst above the figure (the figure carries none of them)
    assert '#"E: излазни клизач; његове v и a са знаком су у кинематским дијаграмима"' in doc.source
    assert not any("клизач" in t for t in texts)
    assert {"kinematic-s", "kinematic-v", "kinematic-a"} <= set(doc.images)


def test_the_cycle_pages_words_are_set_by_typst_in_the_readers_language():
    doc = handout(plans.load(plans.example_path("four-bar")), positions=8, lang="ru")
    assert doc.source.count('== #"Кинематические диаграммы за цикл"') >= 2  # a heading on each page of them
    assert '#text(size: 9.0pt)[#"Кривошипно-коромысловый механизм с точкой шатуна"]' in doc.source  # the scene's title, as written
    for key in ("diagram-links", "diagram-points"):
        root = ET.fromstring(doc.images[key])
        words = " ".join("".join(t.itertext()) for t in root.iter(f"{SVG}text"))
        assert "Кинематические диаграммы" not in words  # the heading is the page's, not the drawing's
